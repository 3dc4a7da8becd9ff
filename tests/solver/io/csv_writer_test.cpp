#include "solver/io/csv_writer.h"

#include "tests/solver/temp_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <locale>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace solver {
namespace {

namespace fs = std::filesystem;

std::string readAll(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// Names of the files in a folder.
std::vector<std::string> listing(const fs::path& dir)
{
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::vector<std::string> names(std::initializer_list<const char*> list)
{
    return std::vector<std::string>(list.begin(), list.end());
}

/// A locale whose decimal point is ',' (as de_DE), whether or not the system has one.
struct CommaDecimal : std::numpunct<char> {
    char do_decimal_point() const override { return ','; }
    char do_thousands_sep() const override { return '.'; }
    std::string do_grouping() const override { return "\3"; }
};

TEST(CsvWriter, WritesHeaderAndRows)
{
    test::TempDir dir("csv_writer");
    const std::string path = dir.path("out.csv");
    {
        CsvWriter w(path);
        ASSERT_TRUE(w.ok()) << w.errorString();
        EXPECT_FALSE(w.toStdout());
        w.writeHeader(names({"t", "q1", "qd1"}));
        const double row1[] = {0, 0.1, -2};
        const double row2[] = {0.001, 1.0 / 3.0, 1e-5};
        w.writeRow(row1);
        w.writeRow(row2);
        w.add(0.002);
        w.add(1234567.5);
        w.add(-0.0);
        w.endRow();
        EXPECT_EQ(w.rowCount(), 3);
        EXPECT_FALSE(fs::exists(path));  // nothing at the target before commit
        ASSERT_TRUE(w.commit()) << w.errorString();
        EXPECT_TRUE(w.temporaryPath().empty());
    }
    EXPECT_EQ(readAll(path), "t,q1,qd1\n"
                             "0,0.1,-2\n"
                             "0.001,0.3333333333333333,1e-05\n"
                             "0.002,1234567.5,-0\n");
    EXPECT_EQ(listing(dir.dir()), names({"out.csv"}));  // no temporary left
}

TEST(CsvWriter, NumbersRoundTrip)
{
    test::TempDir dir("csv_writer_rt");
    const std::string path = dir.path("out.csv");
    const std::vector<double> values{0.1,
                                     1.0 / 3.0,
                                     std::numbers::pi,
                                     -2.5e10,
                                     1e-300,
                                     5e-324,  // the smallest subnormal
                                     std::numeric_limits<double>::max(),
                                     -std::numeric_limits<double>::min(),
                                     0.1 + 0.2,
                                     123456789.123456789,
                                     9.81,
                                     -0.0};
    {
        CsvWriter w(path);
        std::vector<std::string> header;
        for (std::size_t k = 0; k < values.size(); ++k) header.push_back("c" + std::to_string(k));
        w.writeHeader(header);
        w.writeRow(values);
        ASSERT_TRUE(w.commit());
    }
    const std::string text = readAll(path);
    const std::string row = text.substr(text.find('\n') + 1);
    ASSERT_EQ(row.back(), '\n');
    std::vector<double> back;
    std::size_t at = 0;
    while (at < row.size() - 1) {
        std::size_t end = row.find_first_of(",\n", at);
        double v = 0;
        auto [ptr, ec] = std::from_chars(row.data() + at, row.data() + end, v);
        EXPECT_EQ(ec, std::errc()) << row.substr(at, end - at);
        EXPECT_EQ(ptr, row.data() + end) << row.substr(at, end - at);
        back.push_back(v);
        at = end + 1;
    }
    ASSERT_EQ(back.size(), values.size());
    for (std::size_t k = 0; k < values.size(); ++k) {
        EXPECT_EQ(back[k], values[k]) << k;
        EXPECT_EQ(std::signbit(back[k]), std::signbit(values[k])) << k;
    }
}

TEST(CsvWriter, CLocaleWhateverTheProcessLocale)
{
    test::TempDir dir("csv_writer_locale");
    const std::string path = dir.path("out.csv");
    const std::locale previous =
        std::locale::global(std::locale(std::locale::classic(), new CommaDecimal));
    {
        CsvWriter w(path);
        w.writeHeader(names({"t", "x1"}));
        const double row[] = {0.5, 12345.25};
        w.writeRow(row);
        EXPECT_TRUE(w.commit());
    }
    std::locale::global(previous);
    EXPECT_EQ(readAll(path), "t,x1\n0.5,12345.25\n");
}

TEST(CsvWriter, QuotesNamesThatNeedIt)
{
    test::TempDir dir("csv_writer_quote");
    const std::string path = dir.path("out.csv");
    CsvWriter w(path);
    w.writeHeader(names({"t", "a,b", "say \"hi\""}));
    ASSERT_TRUE(w.commit());
    EXPECT_EQ(readAll(path), "t,\"a,b\",\"say \"\"hi\"\"\"\n");
}

TEST(CsvWriter, UncommittedWriterLeavesNoFile)
{
    test::TempDir dir("csv_writer_abandon");
    const std::string path = dir.path("out.csv");
    {
        CsvWriter w(path);
        ASSERT_TRUE(w.ok());
        if (w.temporaryPath().empty()) {
            EXPECT_TRUE(listing(dir.dir()).empty());  // an unnamed file (O_TMPFILE): nothing to leave behind
        } else {
            EXPECT_TRUE(fs::exists(w.temporaryPath()));  // (a file system without O_TMPFILE)
            EXPECT_EQ(fs::path(w.temporaryPath()).parent_path(), dir.dir());  // next to the target
        }
        w.writeHeader(names({"t"}));
        const double row[] = {1.0};
        w.writeRow(row);
        // the simulation fails here: no commit
    }
    EXPECT_TRUE(listing(dir.dir()).empty());
}

TEST(CsvWriter, UncommittedWriterKeepsTheOldFile)
{
    test::TempDir dir("csv_writer_keep");
    const std::string path = dir.write("out.csv", "old contents\n");
    {
        CsvWriter w(path);
        w.writeHeader(names({"t"}));
        w.abandon();
        EXPECT_TRUE(w.temporaryPath().empty());
        EXPECT_FALSE(w.commit());
    }
    EXPECT_EQ(readAll(path), "old contents\n");
    EXPECT_EQ(listing(dir.dir()), names({"out.csv"}));
}

TEST(CsvWriter, CommitReplacesTheOldFile)
{
    test::TempDir dir("csv_writer_replace");
    const std::string path = dir.write("out.csv", "old contents\n");
    CsvWriter w(path);
    w.writeHeader(names({"t"}));
    ASSERT_TRUE(w.commit());
    EXPECT_EQ(readAll(path), "t\n");
    EXPECT_EQ(listing(dir.dir()), names({"out.csv"}));
}

TEST(CsvWriter, CannotCreate)
{
    test::TempDir dir("csv_writer_nodir");
    const std::string path = dir.path("no/such/folder/out.csv");
    CsvWriter w(path);
    EXPECT_FALSE(w.ok());
    EXPECT_EQ(w.errorString(), "cannot create " + path + ": No such file or directory");
    w.writeHeader(names({"t"}));  // does nothing
    EXPECT_FALSE(w.commit());
    EXPECT_TRUE(listing(dir.dir()).empty());
}

TEST(CsvWriter, TargetIsAFolder)
{
    test::TempDir dir("csv_writer_folder");
    fs::create_directory(dir.dir() / "out.csv");
    const std::string path = dir.path("out.csv");
    CsvWriter w(path);
    EXPECT_FALSE(w.ok());
    EXPECT_EQ(w.errorString(), "cannot write " + path + ": it is a folder");
    EXPECT_FALSE(w.commit());
    EXPECT_EQ(listing(dir.dir()), names({"out.csv"}));
}

TEST(CsvWriter, RowOfTheWrongLengthFails)
{
    test::TempDir dir("csv_writer_len");
    const std::string path = dir.path("out.csv");
    CsvWriter w(path);
    w.writeHeader(names({"t", "q1"}));
    const double row[] = {0.0, 1.0, 2.0};
    w.writeRow(row);
    EXPECT_FALSE(w.ok());
    EXPECT_EQ(w.errorString(), "a row has 3 values; the header has 2 columns");
    EXPECT_FALSE(w.commit());
    EXPECT_TRUE(listing(dir.dir()).empty());
}

TEST(CsvWriter, UnfinishedRowIsNotCommitted)
{
    test::TempDir dir("csv_writer_unfinished");
    CsvWriter w(dir.path("out.csv"));
    w.writeHeader(names({"t", "q1"}));
    w.add(1.0);
    EXPECT_FALSE(w.commit());
    EXPECT_EQ(w.errorString(), "the last row is not finished");
    EXPECT_TRUE(listing(dir.dir()).empty());
}

TEST(CsvWriter, WritesToStandardOutput)
{
    testing::internal::CaptureStdout();
    {
        CsvWriter w;
        EXPECT_TRUE(w.toStdout());
        EXPECT_TRUE(w.ok());
        w.writeHeader(names({"t", "E"}));
        const double row[] = {0.25, -1.5e-7};
        w.writeRow(row);
        EXPECT_TRUE(w.commit());
    }
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "t,E\n0.25,-1.5e-07\n");
}

}  // namespace
}  // namespace solver
