#include "solver/io/csv_writer.h"

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <random>
#include <system_error>

namespace solver {

namespace {

std::string errnoText(int err) { return std::generic_category().message(err); }

/// Appends a header name, quoted when it holds a separator, a quote or a line end.
void appendName(std::string& line, std::string_view name)
{
    if (name.find_first_of(",\"\r\n") == std::string_view::npos) {
        line += name;
        return;
    }
    line += '"';
    for (char c : name) {
        if (c == '"') line += '"';
        line += c;
    }
    line += '"';
}

}  // namespace

CsvWriter::CsvWriter() : m_file(stdout) {}

CsvWriter::CsvWriter(std::string path) : m_path(std::move(path))
{
    namespace fs = std::filesystem;
    if (m_path.empty()) {
        fail(trText("Diagnostics", "no output file given"));
        return;
    }
    std::error_code ec;
    const fs::path target(m_path);
    if (fs::is_directory(target, ec)) {
        fail(trText("Diagnostics", "cannot write %1: it is a folder").with(m_path));
        return;
    }
    // a fresh temporary file in the target's folder (a rename within one file system
    // replaces the target in one step)
    std::random_device rd;
    std::mt19937_64 gen((static_cast<std::uint64_t>(rd()) << 32) ^ rd());
    int err = 0;
    for (int attempt = 0; attempt < 16; ++attempt) {
        char suffix[24];
        auto [end, ec2] =
            std::to_chars(suffix, suffix + sizeof suffix, gen() & 0xFFFFFFFFFFFFull, 16);
        (void)ec2;
        const fs::path tmp = target.parent_path() / ("." + target.filename().string() + "." +
                                                     std::string(suffix, end) + ".tmp");
        errno = 0;
        m_file = std::fopen(tmp.string().c_str(), "wbx");
        if (m_file) {
            m_tmpPath = tmp.string();
            return;
        }
        err = errno;
        if (err != EEXIST) break;
    }
    fail(trText("Diagnostics", "cannot create %1: %2").with(m_path).with(errnoText(err)));
}

CsvWriter::~CsvWriter()
{
    if (!m_committed) abandon();
}

void CsvWriter::fail(Text message)
{
    if (m_error.empty()) {
        m_error = message.english();
        m_errorText = std::move(message);
    }
    abandon();
}

void CsvWriter::abandon()
{
    if (m_file && m_file != stdout) std::fclose(m_file);
    if (m_file == stdout) std::fflush(stdout);
    m_file = nullptr;
    if (!m_tmpPath.empty()) {
        std::error_code ec;
        std::filesystem::remove(m_tmpPath, ec);
        m_tmpPath.clear();
    }
    m_line.clear();
    m_inRow = 0;
}

void CsvWriter::flushLine()
{
    m_line += '\n';
    if (m_file && std::fwrite(m_line.data(), 1, m_line.size(), m_file) != m_line.size()) {
        const int err = errno;
        fail(toStdout() ? trText("Diagnostics", "cannot write to standard output: %1").with(errnoText(err))
                        : trText("Diagnostics", "cannot write %1: %2").with(m_path).with(errnoText(err)));
    }
    m_line.clear();
}

void CsvWriter::writeHeader(std::span<const std::string> names)
{
    if (!m_file || m_inRow != 0) {
        if (m_inRow != 0) fail(trText("Diagnostics", "the header was written in the middle of a row"));
        return;
    }
    m_line.clear();
    for (std::size_t k = 0; k < names.size(); ++k) {
        if (k > 0) m_line += ',';
        appendName(m_line, names[k]);
    }
    m_columns = names.size();
    flushLine();
}

void CsvWriter::appendNumber(double value)
{
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    (void)ec;  // 32 characters hold any double
    m_line.append(buf, end);
}

void CsvWriter::add(double value)
{
    if (!m_file) return;
    if (m_inRow > 0) m_line += ',';
    appendNumber(value);
    ++m_inRow;
}

void CsvWriter::endRow()
{
    if (!m_file) return;
    if (m_columns == 0) m_columns = m_inRow;
    if (m_inRow != m_columns) {
        fail(trText("Diagnostics", "a row has %1 values; the header has %2 columns")
                 .with(std::to_string(m_inRow))
                 .with(std::to_string(m_columns)));
        return;
    }
    m_inRow = 0;
    ++m_rows;
    flushLine();
}

void CsvWriter::writeRow(std::span<const double> values)
{
    if (!m_file) return;
    for (double v : values) add(v);
    endRow();
}

bool CsvWriter::commit()
{
    if (m_committed) return ok();
    if (!m_file) {
        if (ok()) fail(trText("Diagnostics", "the output was already closed"));
        return false;
    }
    if (m_inRow != 0) {
        fail(trText("Diagnostics", "the last row is not finished"));
        return false;
    }
    if (toStdout()) {
        if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
            fail(trText("Diagnostics", "cannot write to standard output: %1").with(errnoText(errno)));
            return false;
        }
        m_file = nullptr;
        m_committed = true;
        return true;
    }
    const bool written = std::fflush(m_file) == 0 && !std::ferror(m_file);
    const int err = errno;
    std::FILE* f = m_file;
    m_file = nullptr;
    const bool closed = std::fclose(f) == 0;
    if (!written || !closed) {
        fail(trText("Diagnostics", "cannot write %1: %2").with(m_path).with(errnoText(written ? errno : err)));
        return false;
    }
    std::error_code ec;
    std::filesystem::rename(m_tmpPath, m_path, ec);
    if (ec) {
        fail(trText("Diagnostics", "cannot write %1: %2").with(m_path).with(ec.message()));
        return false;
    }
    m_tmpPath.clear();
    m_committed = true;
    return true;
}

}  // namespace solver
