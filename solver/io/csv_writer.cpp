#include "solver/io/csv_writer.h"

#include <cerrno>
#include <charconv>
#include <cstdint>
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

CsvWriter::CsvWriter(std::string path, const std::vector<std::string>& inputs) : m_path(std::move(path))
{
    if (m_path.empty()) {
        fail(trText("Diagnostics", "no output file given"));
        return;
    }
    if (!m_out.open(m_path, inputs)) {
        fail(m_out.error());
        return;
    }
    m_file = m_out.stream();
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
    if (m_file == stdout) std::fflush(stdout);
    m_file = nullptr;
    m_out.abandon();
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
    m_file = nullptr;
    if (!m_out.commit()) {
        fail(m_out.error());
        return false;
    }
    m_committed = true;
    return true;
}

}  // namespace solver
