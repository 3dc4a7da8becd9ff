#include "solver/core/diagnostic.h"

#include <algorithm>

namespace solver {

const char* severityName(Severity s)
{
    switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
    }
    return "error";
}

std::string Diagnostic::format() const
{
    std::string out = file.empty() ? std::string("<model>") : file;
    if (pos.valid()) {
        out += ':' + std::to_string(pos.line) + ':' + std::to_string(pos.column);
    }
    out += ": ";
    out += severityName(severity);
    out += ": ";
    out += message;
    if (!hint.empty()) {
        out += " [";
        out += hint;
        out += ']';
    }
    return out;
}

Diagnostic& Diagnostics::error(std::string code, SourcePos pos, std::string message, std::string hint)
{
    return add(Severity::Error, std::move(code), pos, std::move(message), std::move(hint));
}

Diagnostic& Diagnostics::warning(std::string code, SourcePos pos, std::string message,
                                 std::string hint)
{
    return add(Severity::Warning, std::move(code), pos, std::move(message), std::move(hint));
}

Diagnostic& Diagnostics::add(Severity s, std::string code, SourcePos pos, std::string message,
                             std::string hint)
{
    if (s == Severity::Error) ++m_errors;
    if (s == Severity::Warning) ++m_warnings;
    if (m_items.size() >= m_limit) {
        if (m_dropped++ == 0) {
            m_items.push_back({Severity::Note, "too-many-diagnostics", m_file, pos,
                               "too many problems; the rest are not listed",
                               "fix the ones above first", {}});
        }
        m_sink = {};
        return m_sink;
    }
    m_items.push_back({s, std::move(code), m_file, pos, std::move(message), std::move(hint), {}});
    return m_items.back();
}

void Diagnostics::sortByPosition()
{
    std::stable_sort(m_items.begin(), m_items.end(), [](const Diagnostic& a, const Diagnostic& b) {
        if (a.file != b.file) return a.file < b.file;
        if (a.pos.line != b.pos.line) return a.pos.line < b.pos.line;
        return a.pos.column < b.pos.column;
    });
}

void Diagnostics::append(const Diagnostics& other)
{
    for (const Diagnostic& d : other) {
        Diagnostic& n = add(d.severity, d.code, d.pos, d.message, d.hint);
        n.file = d.file;
        n.args = d.args;
    }
}

}  // namespace solver
