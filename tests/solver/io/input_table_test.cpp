#include "solver/io/input_table.h"

#include "tests/solver/temp_dir.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace solver {
namespace {

/// Parses `text` as "in.csv"; the diagnostics, formatted, in `out`.
std::optional<InputTable> parseCsv(const std::string& text, std::vector<std::string>& out)
{
    Diagnostics diags("in.csv");
    auto table = InputTable::parse(text, diags);
    out.clear();
    for (const Diagnostic& d : diags) out.push_back(d.code + " " + d.format());
    return table;
}

/// The diagnostics of a text that must fail.
std::vector<std::string> errorsOf(const std::string& text)
{
    std::vector<std::string> out;
    const auto table = parseCsv(text, out);
    EXPECT_FALSE(table.has_value()) << text;
    return out;
}

InputTable good(const std::string& text)
{
    std::vector<std::string> out;
    auto table = parseCsv(text, out);
    EXPECT_TRUE(table.has_value());
    EXPECT_TRUE(out.empty()) << (out.empty() ? "" : out.front());
    return table ? *table : InputTable();
}

using Lines = std::vector<std::string>;

// ---- reading -----------------------------------------------------------------

TEST(InputTable, ReadsColumnsAndRows)
{
    const InputTable t = good("t,u2,u5\n0,0.5,-1\n1.5,1,0\n2,-.25,1e-1\n");
    ASSERT_EQ(t.columnCount(), 2u);
    EXPECT_EQ(t.jointId(0), 2);
    EXPECT_EQ(t.jointId(1), 5);
    EXPECT_EQ(t.columnName(1), "u5");
    EXPECT_EQ(t.columnPos(1), (SourcePos{1, 6}));
    EXPECT_EQ(t.column(5), 1u);
    EXPECT_FALSE(t.column(3).has_value());
    ASSERT_EQ(t.rowCount(), 3u);
    EXPECT_EQ(t.time(2), 2.0);
    EXPECT_EQ(t.at(0, 0), 0.5);
    EXPECT_EQ(t.at(0, 1), -1.0);
    EXPECT_EQ(t.at(2, 0), -0.25);
    EXPECT_EQ(t.at(2, 1), 0.1);
}

TEST(InputTable, ColumnsInAnyOrderAndCase)
{
    const InputTable t = good("U7, T ,u02\n0,1,-1\n");
    ASSERT_EQ(t.columnCount(), 2u);
    EXPECT_EQ(t.jointId(0), 7);
    EXPECT_EQ(t.jointId(1), 2);  // u02 is joint 2
    EXPECT_EQ(t.time(0), 1.0);
    EXPECT_EQ(t.at(0, 0), 0.0);
    EXPECT_EQ(t.at(0, 1), -1.0);
}

TEST(InputTable, AcceptsSpreadsheetExports)
{
    // byte order mark, CRLF line ends, quoted names, blanks around fields, blank lines
    const InputTable t =
        good("\xEF\xBB\xBF\"t\",\"u1\"\r\n\r\n 0 , 0.5 \r\n\"1\",\"-0.5\"\r\n\r\n");
    ASSERT_EQ(t.rowCount(), 2u);
    EXPECT_EQ(t.jointId(0), 1);
    EXPECT_EQ(t.at(0, 0), 0.5);
    EXPECT_EQ(t.time(1), 1.0);
    EXPECT_EQ(t.at(1, 0), -0.5);
    EXPECT_EQ(t.columnPos(0), (SourcePos{1, 5}));  // the BOM is not a character of the line
}

TEST(InputTable, SemicolonSeparatedFiles)
{
    const InputTable t = good("t;u3\n0;1\n0.5;-1\n");
    ASSERT_EQ(t.rowCount(), 2u);
    EXPECT_EQ(t.at(1, 0), -1.0);
}

TEST(InputTable, OnlyATimeColumn)
{
    const InputTable t = good("t\n0\n1\n");
    EXPECT_EQ(t.columnCount(), 0u);
    EXPECT_EQ(t.rowCount(), 2u);
}

// ---- lookup --------------------------------------------------------------------

TEST(InputTable, ZeroOrderHold)
{
    const InputTable t = good("t,u1\n0.5,0.25\n1,1\n2,-0.5\n");
    EXPECT_EQ(t.value(0, 0.0), 0.0);   // before the first row: valve closed
    EXPECT_EQ(t.value(0, 0.49), 0.0);
    EXPECT_EQ(t.value(0, 0.5), 0.25);  // at a row: its value
    EXPECT_EQ(t.value(0, 0.75), 0.25);  // between rows: held, not interpolated
    EXPECT_EQ(t.value(0, 0.999999), 0.25);
    EXPECT_EQ(t.value(0, 1.0), 1.0);
    EXPECT_EQ(t.value(0, 1.5), 1.0);
    EXPECT_EQ(t.value(0, 2.0), -0.5);
    EXPECT_EQ(t.value(0, 1e9), -0.5);  // after the last row: held
    EXPECT_FALSE(t.rowAt(0.1).has_value());
    EXPECT_EQ(t.rowAt(1.2), 1u);
}

TEST(InputTable, CursorFollowsTimeForwardAndBack)
{
    std::string text = "t,u1,u2\n";
    for (int k = 0; k < 100; ++k) {
        text += std::to_string(0.1 * k + 0.05) + "," + std::to_string(k / 100.0) + "," +
                std::to_string(-k / 100.0) + "\n";
    }
    const InputTable t = good(text);
    InputTable::Cursor c = t.cursor();
    EXPECT_EQ(c.row(), -1);
    EXPECT_EQ(c.value(0), 0.0);
    // small steps, as an integrator takes them
    for (int k = 0; k <= 11000; ++k) {
        const double time = k * 1e-3;
        c.seek(time);
        ASSERT_EQ(c.value(0), t.value(0, time)) << time;
        ASSERT_EQ(c.value(1), t.value(1, time)) << time;
    }
    EXPECT_EQ(c.row(), 99);
    // back in time, a jump forward, before the start
    c.seek(3.07);
    EXPECT_EQ(c.row(), 30);
    EXPECT_EQ(c.value(0), 0.30);
    c.seek(9.0);
    EXPECT_EQ(c.row(), 89);
    c.seek(9.0);
    EXPECT_EQ(c.row(), 89);
    c.seek(0.0);
    EXPECT_EQ(c.row(), -1);
    EXPECT_EQ(c.value(1), 0.0);
    c.seek(0.05);
    EXPECT_EQ(c.row(), 0);
}

// ---- bad input -------------------------------------------------------------------

TEST(InputTable, EmptyFile)
{
    EXPECT_EQ(
        errorsOf(""),
        (Lines{"empty-file in.csv:1:1: error: the input file is empty [write a header naming the "
               "columns, then one row per time, e.g. t,u2 then 0,0.5]"}));
    EXPECT_EQ(errorsOf(" \n\n\t\n"), errorsOf(""));
    EXPECT_EQ(errorsOf("\xEF\xBB\xBF"), errorsOf(""));
}

TEST(InputTable, HeaderWithoutRows)
{
    EXPECT_EQ(errorsOf("t,u1\n\n"),
              (Lines{"no-rows in.csv:1:1: error: the input file has a header but no rows [add "
                     "one row per time under the header, e.g. 0,0.5]"}));
}

TEST(InputTable, MissingTimeColumn)
{
    EXPECT_EQ(
        errorsOf("u1,u2\n0,0\n"),
        (Lines{
            "missing-time-column in.csv:1:1: error: the header has no 't' column [the first line names the "
            "columns: t, then u<joint id> for each command, e.g. t,u2]"}));
    // after blank lines, the header's own line
    EXPECT_EQ(
        errorsOf("\n\nu1\n0\n"),
        (Lines{
            "missing-time-column in.csv:3:1: error: the header has no 't' column [the first line names the "
            "columns: t, then u<joint id> for each command, e.g. t,u2]"}));
}

TEST(InputTable, BadColumnNames)
{
    EXPECT_EQ(
        errorsOf("t,u2,speed,u,u-1,u1.5,q3\n0,0,0,0,0,0,0\n"),
        (Lines{
            "bad-column in.csv:1:6: error: 'speed' is not an input column name [name the time column t and "
            "each command column u<joint id>, e.g. u2]",
            "bad-column in.csv:1:12: error: 'u' is not an input column name [name the time column t and "
            "each command column u<joint id>, e.g. u2]",
            "bad-column in.csv:1:14: error: 'u-1' is not an input column name [name the time column t and "
            "each command column u<joint id>, e.g. u2]",
            "bad-column in.csv:1:18: error: 'u1.5' is not an input column name [name the time column t and "
            "each command column u<joint id>, e.g. u2]",
            "bad-column in.csv:1:23: error: 'q3' is not an input column name [name the time column t and "
            "each command column u<joint id>, e.g. u2]",
        }));
    EXPECT_EQ(
        errorsOf("t,u99999999999\n0,0\n"),
        (Lines{
            "bad-column in.csv:1:3: error: 'u99999999999' is not an input column name [name the time "
            "column t and each command column u<joint id>, e.g. u2]"}));
    EXPECT_EQ(
        errorsOf("t,,u1\n0,0,0\n"),
        (Lines{
            "empty-column-name in.csv:1:3: error: column 2 has no name [name every column: t for the time, "
            "u<joint id> for a command (e.g. u2)]"}));
}

TEST(InputTable, DuplicateColumns)
{
    EXPECT_EQ(
        errorsOf("t,u2,u3,u02\n0,0,0,0\n"),
        (Lines{
            "duplicate-column in.csv:1:9: error: column 'u02' is joint 2's command again ('u2' at column 3) "
            "[remove one of them]"}));
    EXPECT_EQ(
        errorsOf("t,u1,T\n0,0,0\n"),
        (Lines{
            "duplicate-column in.csv:1:6: error: column 't' appears twice (first at column 1) [remove one "
            "of them]"}));
}

TEST(InputTable, RowsWithTooFewOrTooManyFields)
{
    EXPECT_EQ(
        errorsOf("t,u1,u2\n0,0.5,0\n1,0.5\n"),
        (Lines{
            "too-few-fields in.csv:3:6: error: this row has 2 values; the header names 3 columns [give a "
            "value for every column (0 for a closed valve)]"}));
    EXPECT_EQ(
        errorsOf("t,u1\n0,0,1\n"),
        (Lines{
            "too-many-fields in.csv:2:5: error: this row has 3 values; the header names 2 columns [one "
            "value per column; if ',' is a decimal separator here, write '.' instead (0.5, not 0,5)]"}));
    EXPECT_EQ(
        errorsOf("t;u1\n0;0;1\n"),
        (Lines{
            "too-many-fields in.csv:2:5: error: this row has 3 values; the header names 2 columns [one "
            "value per column, separated by ';']"}));
    EXPECT_EQ(
        errorsOf("t,u1\n0,\n"),
        (Lines{
            "empty-value in.csv:2:3: error: column 'u1': no value [write a number (0 for a closed valve)]"}));
}

TEST(InputTable, TextInANumber)
{
    EXPECT_EQ(
        errorsOf("t,u1\n0,0\n1,half\n2x,0\n"),
        (Lines{
            "not-a-number in.csv:3:3: error: column 'u1': 'half' is not a number [write a number in the C "
            "locale: '.' as the decimal point, e.g. -0.25 or 1e-3]",
            "not-a-number in.csv:4:1: error: time: '2x' is not a number [write a number in the C locale: '.' "
            "as the decimal point, e.g. -0.25 or 1e-3]",
        }));
}

TEST(InputTable, DecimalComma)
{
    // a semicolon-separated export from a spreadsheet in a decimal-comma locale
    EXPECT_EQ(
        errorsOf("t;u1\n0;0\n0,5;-0,25\n"),
        (Lines{
            "decimal-comma in.csv:3:1: error: time: '0,5' is not a number [use '.' as the decimal separator: "
            "0.5]",
            "decimal-comma in.csv:3:5: error: column 'u1': '-0,25' is not a number [use '.' as the decimal "
            "separator: -0.25]",
        }));
    // a quoted field in a comma-separated file
    EXPECT_EQ(
        errorsOf("t,u1\n0,\"0,5\"\n"),
        (Lines{
            "decimal-comma in.csv:2:3: error: column 'u1': '0,5' is not a number [use '.' as the decimal "
            "separator: 0.5]"}));
}

TEST(InputTable, NotFiniteAndTooLarge)
{
    EXPECT_EQ(
        errorsOf("t,u1\n0,NaN\ninf,0\n2,-Infinity\n1e999,0\n"),
        (Lines{
            "not-finite in.csv:2:3: error: column 'u1': 'NaN' is not a finite number [write a finite value; "
            "NaN and infinity are not allowed]",
            "not-finite in.csv:3:1: error: time: 'inf' is not a finite number [write a finite value; NaN and "
            "infinity are not allowed]",
            "not-finite in.csv:4:3: error: column 'u1': '-Infinity' is not a finite number [write a finite "
            "value; NaN and infinity are not allowed]",
            "out-of-range in.csv:5:1: error: time: '1e999' is too large [write a value that fits a double "
            "(below 1.8e308)]",
        }));
    // a number too small for a double is 0
    const InputTable t = good("t,u1\n0,1e-400\n");
    EXPECT_EQ(t.at(0, 0), 0.0);
}

TEST(InputTable, TimesMustIncrease)
{
    EXPECT_EQ(
        errorsOf("t,u1\n0,0\n1,0\n1,0.5\n0.5,0\n2,0\n"),
        (Lines{
            "time-not-increasing in.csv:4:1: error: time 1 repeats the time of line 3 [sort the rows by time, "
            "each time once]",
            "time-not-increasing in.csv:5:1: error: time 0.5 comes after time 1 (line 3); times must increase "
            "[sort the rows by time, each time once]",
        }));
}

TEST(InputTable, CommandsOutsideMinusOneToOne)
{
    EXPECT_EQ(
        errorsOf("t,u1,u2\n0,1,-1\n1,1.5,-1.0001\n"),
        (Lines{
            "command-out-of-range in.csv:3:3: error: column 'u1': 1.5 is outside [-1, 1] [a command is a "
            "valve spool position (or joystick axis) from -1 to 1]",
            "command-out-of-range in.csv:3:7: error: column 'u2': -1.0001 is outside [-1, 1] [a command is a "
            "valve spool position (or joystick axis) from -1 to 1]",
        }));
}

TEST(InputTable, UnterminatedQuote)
{
    EXPECT_EQ(
        errorsOf("t,u1\n0,\"0.5\n"),
        (Lines{
            "unterminated-quote in.csv:2:3: error: column 'u1': the value has no closing quote [close the "
            "quote, or write the number without quotes]"}));
}

TEST(InputTable, ColumnsCountCharactersNotBytes)
{
    EXPECT_EQ(
        errorsOf("t,u1\n0,\"é\"\n"),
        (Lines{
            "not-a-number in.csv:2:3: error: column 'u1': 'é' is not a number [write a number in the C "
            "locale: '.' as the decimal point, e.g. -0.25 or 1e-3]"}));
    EXPECT_EQ(
        errorsOf("t,u1\n0,éé,x\n"),
        (Lines{
            "too-many-fields in.csv:2:6: error: this row has 3 values; the header names 2 columns [one "
            "value per column; if ',' is a decimal separator here, write '.' instead (0.5, not 0,5)]",
            "not-a-number in.csv:2:3: error: column 'u1': 'éé' is not a number [write a number in the C "
            "locale: '.' as the decimal point, e.g. -0.25 or 1e-3]"}));
}

TEST(InputTable, EveryProblemIsReported)
{
    const auto errors = errorsOf("t,u1,bad\n0,2,0\n0,x,0\n");
    ASSERT_EQ(errors.size(), 4u);
    EXPECT_EQ(errors[0].substr(0, errors[0].find(' ')), "bad-column");
    EXPECT_EQ(errors[1].substr(0, errors[1].find(' ')), "command-out-of-range");
    EXPECT_EQ(errors[2].substr(0, errors[2].find(' ')), "time-not-increasing");
    EXPECT_EQ(errors[3].substr(0, errors[3].find(' ')), "not-a-number");
}

// ---- files -----------------------------------------------------------------------------

TEST(InputTable, ReadsAFile)
{
    test::TempDir dir("input_table");
    const std::string path = dir.write("in.csv", "t,u1\n0,0.5\n");
    Diagnostics diags;
    const auto t = InputTable::readFile(path, diags);
    ASSERT_TRUE(t.has_value());
    EXPECT_EQ(t->value(0, 3.0), 0.5);
    EXPECT_EQ(diags.file(), path);

    const std::string bad = dir.write("bad.csv", "t,u1\n0,x\n");
    Diagnostics badDiags;
    EXPECT_FALSE(InputTable::readFile(bad, badDiags).has_value());
    ASSERT_EQ(badDiags.size(), 1u);
    EXPECT_EQ(badDiags.items()[0].format().substr(0, bad.size() + 5), bad + ":2:3:");
}

TEST(InputTable, FileProblems)
{
    test::TempDir dir("input_table_io");
    Diagnostics missing;
    EXPECT_FALSE(InputTable::readFile(dir.path("none.csv"), missing).has_value());
    ASSERT_EQ(missing.size(), 1u);
    EXPECT_EQ(missing.items()[0].code, "io-error");
    EXPECT_EQ(missing.items()[0].format(),
              dir.path("none.csv") + ": error: no such file [check the path]");

    Diagnostics folder;
    EXPECT_FALSE(InputTable::readFile(dir.dir().string(), folder).has_value());
    ASSERT_EQ(folder.size(), 1u);
    EXPECT_EQ(folder.items()[0].format(),
              dir.dir().string() +
                  ": error: this is a folder, not an input file [give the path of a .csv file]");
}

// ---- against the model ---------------------------------------------------------------

TEST(InputColumns, MatchTheDrivenJoints)
{
    const InputTable t = good("t,u2,u5\n0,0,0\n");
    Diagnostics diags("in.csv");
    const std::vector<int> driven{5, 2}, joints{1, 2, 3, 5};
    EXPECT_TRUE(checkInputColumns(t, driven, joints, diags));
    EXPECT_TRUE(diags.empty());
}

TEST(InputColumns, MissingColumnsAreOneError)
{
    const InputTable t = good("t,u2\n0,0.5\n");
    Diagnostics diags("in.csv");
    const std::vector<int> driven{5, 2, 1, 3}, joints{1, 2, 3, 5};
    EXPECT_FALSE(checkInputColumns(t, driven, joints, diags));
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(diags.items()[0].format(),
              "in.csv:1:1: error: no columns for the drives of joints 1, 3, 5 [the table has one column "
              "u<joint id> per drive; write 0 in a column to keep that valve closed]");
}

TEST(InputColumns, UnknownJointNoDriveAndMissingColumn)
{
    const InputTable t = good("t,u7,u3,u2\n0,0,0,0\n");
    Diagnostics diags("in.csv");
    const std::vector<int> driven{5, 2}, joints{1, 2, 3, 5};
    EXPECT_FALSE(checkInputColumns(t, driven, joints, diags));
    Lines out;
    for (const Diagnostic& d : diags) out.push_back(d.code + " " + d.format());
    EXPECT_EQ(
        out,
        (Lines{
            "unknown-joint in.csv:1:3: error: column 'u7': the model has no joint 7 [the joints with a "
            "drive are 2, 5]",
            "no-drive in.csv:1:6: error: column 'u3': joint 3 has no drive [a command moves a drive: "
            "remove the column, or give the joint a drive (D 3 …)]",
            "missing-column in.csv:1:1: error: no column for joint 5's drive [the table has one column "
            "u<joint id> per drive; write 0 in a column to keep that valve closed]",
        }));
}

TEST(InputColumns, ModelWithoutDrives)
{
    const InputTable t = good("t,u1\n0,0\n");
    Diagnostics diags("in.csv");
    const std::vector<int> joints{1};
    EXPECT_FALSE(checkInputColumns(t, {}, joints, diags));
    ASSERT_EQ(diags.size(), 1u);
    EXPECT_EQ(
        diags.items()[0].format(),
        "in.csv:1:3: error: column 'u1': joint 1 has no drive [a command moves a drive: remove the column, or "
        "give the joint a drive (D 1 …)]");
    Diagnostics none("in.csv");
    EXPECT_FALSE(checkInputColumns(good("t,u4\n0,0\n"), {}, joints, none));
    EXPECT_EQ(none.items()[0].hint, "the model has no drives; remove the column");
}

}  // namespace
}  // namespace solver
