#include "solver/io/input_table.h"

#include "solver/core/text_file.h"
#include "solver/parse/lexer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <system_error>

namespace solver {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isBlank(char c) { return c == ' ' || c == '\t'; }

/// Shortest round-trip text of a number.
std::string fmt(double v)
{
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

enum class NumberStatus { Ok, Empty, NotANumber, DecimalComma, NotFinite, OutOfRange };

/// Reads a field as a number (C locale, '.' decimal point).
NumberStatus readNumber(std::string_view w, double& out)
{
    if (w.empty()) return NumberStatus::Empty;
    if (!parse::looksLikeNumber(w)) {
        std::string_view body = w;
        if (body[0] == '+' || body[0] == '-') body.remove_prefix(1);
        const std::string u = parse::upper(body);
        if (u == "NAN" || u == "INF" || u == "INFINITY") return NumberStatus::NotFinite;
        const std::size_t comma = w.find(',');
        if (comma != std::string_view::npos && comma > 0 && isDigit(w[comma - 1]) &&
            w.find(',', comma + 1) == std::string_view::npos) {
            std::string dotted(w);
            dotted[comma] = '.';
            if (parse::looksLikeNumber(dotted)) return NumberStatus::DecimalComma;
        }
        return NumberStatus::NotANumber;
    }
    std::string_view s = w;
    if (s[0] == '+') s.remove_prefix(1);
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    if (ec == std::errc::result_out_of_range) {
        // from_chars reports underflow as out of range too: a tiny number is 0
        const std::size_t e = s.find_first_of("eE");
        const bool negativeExponent =
            e != std::string_view::npos && e + 1 < s.size() && s[e + 1] == '-';
        std::string_view mant = s.substr(0, e);
        if (!mant.empty() && mant[0] == '-') mant.remove_prefix(1);
        const bool fraction =
            !mant.empty() &&
            (mant[0] == '.' || (mant[0] == '0' && mant.size() > 1 && mant[1] == '.'));
        if (negativeExponent || (e == std::string_view::npos && fraction)) {
            out = 0.0;
            return NumberStatus::Ok;
        }
        return NumberStatus::OutOfRange;
    }
    if (ec != std::errc() || ptr != s.data() + s.size()) return NumberStatus::NotANumber;
    return std::isfinite(out) ? NumberStatus::Ok : NumberStatus::OutOfRange;
}

/// One field of a CSV line.
struct Field {
    std::string text;       ///< contents, blanks around it removed, quotes resolved
    int column = 1;         ///< 1-based character column of its first non-blank character
    bool unterminated = false;  ///< an opening quote without its closing quote
};

/// Splits one line (no line end) into fields; columns count code points.
void splitFields(std::string_view line, char sep, std::vector<Field>& fields)
{
    fields.clear();
    std::size_t i = 0;
    int col = 1;  // column of line[i]
    auto advance = [&]() {
        ++i;
        while (i < line.size() && (static_cast<unsigned char>(line[i]) & 0xC0) == 0x80) ++i;
        ++col;
    };
    while (true) {
        Field f;
        while (i < line.size() && isBlank(line[i])) advance();
        f.column = col;
        if (i < line.size() && line[i] == '"') {
            advance();
            bool closed = false;
            while (i < line.size()) {
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') {
                        f.text += '"';
                        advance();
                        advance();
                        continue;
                    }
                    advance();
                    closed = true;
                    break;
                }
                const std::size_t start = i;
                advance();
                f.text.append(line.substr(start, i - start));
            }
            f.unterminated = !closed;
            // anything between the closing quote and the separator is kept (and so
            // makes the field wrong) rather than silently dropped
            while (i < line.size() && line[i] != sep) {
                const std::size_t start = i;
                advance();
                f.text.append(line.substr(start, i - start));
            }
        } else {
            const std::size_t start = i;
            while (i < line.size() && line[i] != sep) advance();
            f.text.assign(line.substr(start, i - start));
        }
        while (!f.text.empty() && isBlank(f.text.back())) f.text.pop_back();
        fields.push_back(std::move(f));
        if (i >= line.size()) break;
        advance();  // the separator
    }
}

bool isBlankLine(std::string_view line)
{
    return std::all_of(line.begin(), line.end(), [](char c) { return isBlank(c); });
}

/// Reads a field as a number; reports why not (with `label` naming the column).
bool readValue(const Field& f, const Text& label, SourcePos pos, Diagnostics& diags, double& v)
{
    if (f.unterminated) {
        diags.error("unterminated-quote", pos,
                    trText("Diagnostics", "%1: the value has no closing quote").with(label),
                    trText("Diagnostics", "close the quote, or write the number without quotes"));
        return false;
    }
    switch (readNumber(f.text, v)) {
    case NumberStatus::Ok:
        return true;
    case NumberStatus::Empty:
        diags.error("empty-value", pos, trText("Diagnostics", "%1: no value").with(label),
                    trText("Diagnostics", "write a number (0 for a closed valve)"));
        return false;
    case NumberStatus::DecimalComma: {
        std::string dotted = f.text;
        dotted[dotted.find(',')] = '.';
        diags.error("decimal-comma", pos,
                    trText("Diagnostics", "%1: '%2' is not a number").with(label).with(f.text),
                    trText("Diagnostics", "use '.' as the decimal separator: %1").with(dotted));
        return false;
    }
    case NumberStatus::NotFinite:
        diags.error("not-finite", pos,
                    trText("Diagnostics", "%1: '%2' is not a finite number").with(label).with(f.text),
                    trText("Diagnostics", "write a finite value; NaN and infinity are not allowed"));
        return false;
    case NumberStatus::OutOfRange:
        diags.error("out-of-range", pos,
                    trText("Diagnostics", "%1: '%2' is too large").with(label).with(f.text),
                    trText("Diagnostics", "write a value that fits a double (below 1.8e308)"));
        return false;
    case NumberStatus::NotANumber:
        diags.error("not-a-number", pos,
                    trText("Diagnostics", "%1: '%2' is not a number").with(label).with(f.text),
                    trText("Diagnostics", "write a number in the C locale: '.' as the decimal point, "
                                          "e.g. -0.25 or 1e-3"));
        return false;
    }
    return false;
}

/// Number of characters (code points) in a line, plus one: the column after its end.
int columnAfter(std::string_view line)
{
    int column = 1;
    for (char c : line) {
        if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++column;
    }
    return column;
}

/// What a header name means.
struct ColumnName {
    enum class Kind { Time, Command, Bad } kind = Kind::Bad;
    int joint = -1;
};

ColumnName classify(std::string_view name)
{
    if (name == "t" || name == "T") return {ColumnName::Kind::Time, -1};
    if (name.size() >= 2 && (name[0] == 'u' || name[0] == 'U') &&
        std::all_of(name.begin() + 1, name.end(), isDigit)) {
        int id = 0;
        auto [ptr, ec] = std::from_chars(name.data() + 1, name.data() + name.size(), id);
        if (ec == std::errc() && ptr == name.data() + name.size())
            return {ColumnName::Kind::Command, id};
    }
    return {};
}

}  // namespace

std::optional<InputTable> InputTable::parse(std::string_view text, Diagnostics& diags)
{
    const std::size_t errorsBefore = diags.errorCount();
    InputTable table;

    // a UTF-8 byte order mark (spreadsheets write one) is not part of the header
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);

    std::size_t at = 0;
    int lineNo = 0;
    auto nextLine = [&](std::string_view& line) {
        if (at >= text.size()) return false;
        std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        line = text.substr(at, end - at);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        at = end + 1;
        ++lineNo;
        return true;
    };

    // header: the first line that is not blank
    std::string_view line;
    bool haveHeader = false;
    while (nextLine(line)) {
        if (!isBlankLine(line)) { haveHeader = true; break; }
    }
    if (!haveHeader) {
        diags.error("empty-file", {1, 1}, trText("Diagnostics", "the input file is empty"),
                    trText("Diagnostics", "write a header naming the columns, then one row per time, "
                                          "e.g. t,u2 then 0,0.5"));
        return std::nullopt;
    }
    const SourcePos headerPos{lineNo, 1};
    // ';' separates the fields of files from decimal-comma spreadsheets
    const bool semicolons =
        line.find(',') == std::string_view::npos && line.find(';') != std::string_view::npos;
    const char sep = semicolons ? ';' : ',';
    const std::string sepName = sep == ',' ? "','" : "';'";

    std::vector<Field> fields;
    splitFields(line, sep, fields);
    const std::size_t nFields = fields.size();
    // per header field: −1 = the time column, k ≥ 0 = command column k, −2 = unusable
    std::vector<int> role(nFields, -2);
    int timeField = -1;
    SourcePos timePos;
    for (std::size_t k = 0; k < nFields; ++k) {
        const Field& f = fields[k];
        const SourcePos pos{lineNo, f.column};
        if (f.unterminated) {
            diags.error("unterminated-quote", pos, trText("Diagnostics", "the column name has no closing quote"),
                        trText("Diagnostics", "close the quote, or write the name without quotes"));
            continue;
        }
        if (f.text.empty()) {
            diags.error("empty-column-name", pos,
                        trText("Diagnostics", "column %1 has no name").with(std::to_string(k + 1)),
                        trText("Diagnostics", "name every column: t for the time, u<joint id> for a "
                                              "command (e.g. u2)"));
            continue;
        }
        const ColumnName c = classify(f.text);
        if (c.kind == ColumnName::Kind::Time) {
            if (timeField >= 0) {
                diags.error("duplicate-column", pos,
                            trText("Diagnostics", "column 't' appears twice (first at column %1)")
                                .with(std::to_string(timePos.column)),
                            trText("Diagnostics", "remove one of them"));
                continue;
            }
            timeField = static_cast<int>(k);
            timePos = pos;
            role[k] = -1;
        } else if (c.kind == ColumnName::Kind::Command) {
            const auto dup = std::find(table.m_jointIds.begin(), table.m_jointIds.end(), c.joint);
            if (dup != table.m_jointIds.end()) {
                const auto d = static_cast<std::size_t>(dup - table.m_jointIds.begin());
                diags.error("duplicate-column", pos,
                            trText("Diagnostics", "column '%1' is joint %2's command again ('%3' at column %4)")
                                .with(f.text)
                                .with(std::to_string(c.joint))
                                .with(table.m_names[d])
                                .with(std::to_string(table.m_namePos[d].column)),
                            trText("Diagnostics", "remove one of them"));
                continue;
            }
            role[k] = static_cast<int>(table.m_jointIds.size());
            table.m_jointIds.push_back(c.joint);
            table.m_names.push_back(f.text);
            table.m_namePos.push_back(pos);
        } else {
            diags.error("bad-column", pos, trText("Diagnostics", "'%1' is not an input column name").with(f.text),
                        trText("Diagnostics", "name the time column t and each command column u<joint id>, "
                                              "e.g. u2"));
        }
    }
    if (timeField < 0) {
        diags.error("missing-time-column", headerPos, trText("Diagnostics", "the header has no 't' column"),
                    trText("Diagnostics", "the first line names the columns: t, then u<joint id> for each "
                                          "command, e.g. t,u2"));
    }
    table.m_headerPos = headerPos;

    // rows
    const std::size_t nCols = table.m_jointIds.size();
    std::vector<double> rowValues(nCols, 0.0);
    bool havePrevious = false;
    double previousTime = 0;
    int previousLine = 0;
    std::size_t rows = 0;
    while (nextLine(line)) {
        if (isBlankLine(line)) continue;
        ++rows;
        splitFields(line, sep, fields);
        if (fields.size() < nFields) {
            // at the end of the line, where the missing values would go
            Text message = fields.size() == 1
                               ? trText("Diagnostics", "this row has %1 value; the header names %2 columns")
                               : trText("Diagnostics", "this row has %1 values; the header names %2 columns");
            diags.error("too-few-fields", {lineNo, columnAfter(line)},
                        message.arg(std::to_string(fields.size())).arg(std::to_string(nFields)),
                        trText("Diagnostics", "give a value for every column (0 for a closed valve)"));
        } else if (fields.size() > nFields) {
            Text message = nFields == 1
                               ? trText("Diagnostics", "this row has %1 values; the header names %2 column")
                               : trText("Diagnostics", "this row has %1 values; the header names %2 columns");
            diags.error("too-many-fields", {lineNo, fields[nFields].column},
                        message.arg(std::to_string(fields.size())).arg(std::to_string(nFields)),
                        sep == ','
                            ? trText("Diagnostics", "one value per column; if ',' is a decimal separator here, "
                                                    "write '.' instead (0.5, not 0,5)")
                            : trText("Diagnostics", "one value per column, separated by %1").with(sepName));
        }
        bool timeOk = false;
        double time = 0;
        const std::size_t n = std::min(fields.size(), nFields);
        for (std::size_t k = 0; k < n; ++k) {
            const Field& f = fields[k];
            const SourcePos pos{lineNo, f.column};
            const Text label =
                role[k] == -1  ? trText("Diagnostics", "time")
                : role[k] >= 0 ? trText("Diagnostics", "column '%1'").with(table.m_names[role[k]])
                               : trText("Diagnostics", "column %1").with(std::to_string(k + 1));
            double v = 0;
            if (!readValue(f, label, pos, diags, v)) continue;
            if (role[k] == -1) {
                time = v;
                timeOk = true;
                if (havePrevious && !(v > previousTime)) {
                    const std::string line0 = std::to_string(previousLine);
                    diags.error("time-not-increasing", pos,
                                v == previousTime
                                    ? trText("Diagnostics", "time %1 repeats the time of line %2")
                                          .with(f.text)
                                          .with(line0)
                                    : trText("Diagnostics", "time %1 comes after time %2 (line %3); "
                                                            "times must increase")
                                          .with(f.text)
                                          .with(fmt(previousTime))
                                          .with(line0),
                                trText("Diagnostics", "sort the rows by time, each time once"));
                }
            } else if (role[k] >= 0) {
                if (v < -1.0 || v > 1.0) {
                    diags.error("command-out-of-range", pos,
                                trText("Diagnostics", "%1: %2 is outside [-1, 1]").with(label).with(f.text),
                                trText("Diagnostics", "a command is a valve spool position (or joystick "
                                                      "axis) from -1 to 1"));
                }
                rowValues[static_cast<std::size_t>(role[k])] = v;
            }
        }
        if (timeOk) {
            // the order is checked against the last readable time, so that one bad
            // row gives one error, not two
            if (!havePrevious || time > previousTime) {
                previousTime = time;
                previousLine = lineNo;
            }
            havePrevious = true;
        }
        table.m_times.push_back(time);
        table.m_values.insert(table.m_values.end(), rowValues.begin(), rowValues.end());
        std::fill(rowValues.begin(), rowValues.end(), 0.0);
    }
    if (rows == 0) {
        diags.error("no-rows", headerPos, trText("Diagnostics", "the input file has a header but no rows"),
                    trText("Diagnostics", "add one row per time under the header, e.g. 0,0.5"));
    }
    if (diags.errorCount() > errorsBefore) return std::nullopt;
    return table;
}

std::optional<InputTable> InputTable::readFile(const std::string& path, Diagnostics& diags)
{
    namespace fs = std::filesystem;
    if (diags.file().empty()) diags.setFile(path);
    std::optional<std::string> text =
        readTextFile(path, kMaxInputFileBytes, trText("Diagnostics", "an input file"), ".csv",
                     trText("Diagnostics", "split the session, or record the commands less often"), diags);
    if (!text) return std::nullopt;
    return parse(*text, diags);
}

std::optional<std::size_t> InputTable::column(int jointId) const
{
    const auto it = std::find(m_jointIds.begin(), m_jointIds.end(), jointId);
    if (it == m_jointIds.end()) return std::nullopt;
    return static_cast<std::size_t>(it - m_jointIds.begin());
}

std::optional<std::size_t> InputTable::rowAt(double t) const
{
    // first row after t; the one before it is in force
    const auto it = std::upper_bound(m_times.begin(), m_times.end(), t);
    if (it == m_times.begin()) return std::nullopt;
    return static_cast<std::size_t>(it - m_times.begin()) - 1;
}

double InputTable::value(std::size_t column, double t) const
{
    const auto row = rowAt(t);
    return row ? at(*row, column) : 0.0;
}

void InputTable::Cursor::seek(double t)
{
    const std::vector<double>& times = m_table->m_times;
    const auto n = static_cast<std::ptrdiff_t>(times.size());
    if (m_row < 0 || times[static_cast<std::size_t>(m_row)] <= t) {
        // forward: a few rows by steps (the usual case), then by bisection
        for (int k = 0; k < 8; ++k) {
            if (m_row + 1 >= n || !(times[static_cast<std::size_t>(m_row + 1)] <= t)) return;
            ++m_row;
        }
        if (m_row + 1 >= n || !(times[static_cast<std::size_t>(m_row + 1)] <= t)) return;
    }
    const auto row = m_table->rowAt(t);
    m_row = row ? static_cast<std::ptrdiff_t>(*row) : -1;
}

bool checkInputColumns(const InputTable& table, std::span<const int> drivenJoints,
                       std::span<const int> jointIds, Diagnostics& diags)
{
    auto contains = [](std::span<const int> ids, int id) {
        return std::find(ids.begin(), ids.end(), id) != ids.end();
    };
    std::vector<int> driven(drivenJoints.begin(), drivenJoints.end());
    std::sort(driven.begin(), driven.end());
    std::string drivenList;
    for (int id : driven) drivenList += (drivenList.empty() ? "" : ", ") + std::to_string(id);

    bool ok = true;
    for (std::size_t c = 0; c < table.columnCount(); ++c) {
        const int id = table.jointId(c);
        const std::string& name = table.columnName(c);
        if (!contains(jointIds, id)) {
            ok = false;
            diags.error("unknown-joint", table.columnPos(c),
                        trText("Diagnostics", "column '%1': the model has no joint %2")
                            .with(name)
                            .with(std::to_string(id)),
                        driven.empty()
                            ? trText("Diagnostics", "the model has no drives; remove the column")
                            : trText("Diagnostics", "the joints with a drive are %1").with(drivenList));
        } else if (!contains(drivenJoints, id)) {
            ok = false;
            diags.error("no-drive", table.columnPos(c),
                        trText("Diagnostics", "column '%1': joint %2 has no drive").with(name).with(std::to_string(id)),
                        trText("Diagnostics", "a command moves a drive: remove the column, or give the "
                                              "joint a drive (D %1 …)")
                            .with(std::to_string(id)));
        }
    }
    // the format has one column per drive (issue 3): a missing one is an error, so
    // that a typo in a column name does not silently leave a valve closed
    std::string missing;
    int nMissing = 0;
    for (int id : driven) {
        if (table.column(id)) continue;
        missing += (missing.empty() ? "" : ", ") + std::to_string(id);
        ++nMissing;
    }
    if (nMissing > 0) {
        ok = false;
        diags.error("missing-column", table.headerPos(),
                    nMissing == 1 ? trText("Diagnostics", "no column for joint %1's drive").with(missing)
                                  : trText("Diagnostics", "no columns for the drives of joints %1").with(missing),
                    trText("Diagnostics", "the table has one column u<joint id> per drive; write 0 in a "
                                          "column to keep that valve closed"));
    }
    return ok;
}

}  // namespace solver
