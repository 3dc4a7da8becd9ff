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

std::string escapeControls(std::string_view value)
{
    std::string out;
    out.reserve(value.size());
    for (const char c : value) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u != 0x7f) {
            out += c;
        } else if (c == '\n') {
            out += c;  // (a message's own line break, e.g. in a list)
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else {
            static constexpr char kHex[] = "0123456789abcdef";
            out += "\\x";
            out += kHex[u >> 4];
            out += kHex[u & 15];
        }
    }
    return out;
}

Text& Text::arg(std::string value)
{
    // a value from a file or the command line may hold control characters (an escape
    // sequence, a NUL): shown escaped, never sent raw to a terminal or a log
    m_args.push_back(plainText(escapeControls(value)));
    return *this;
}

Text& Text::arg(Text phrase)
{
    m_args.push_back(std::move(phrase));
    return *this;
}

Text plainText(std::string value)
{
    Text t;
    t.m_value = std::move(value);
    return t;
}

std::string Text::english() const
{
    return render([](const char*, const char* tmpl) { return std::string(tmpl); });
}

std::string Text::fill(const std::string& tmpl, const std::vector<std::string>& args)
{
    std::string out;
    out.reserve(tmpl.size() + 16 * args.size());
    for (std::size_t i = 0; i < tmpl.size(); ++i) {
        const char c = tmpl[i];
        if (c == '%' && i + 1 < tmpl.size()) {
            const char n = tmpl[i + 1];
            if (n >= '1' && n <= '9' && static_cast<std::size_t>(n - '1') < args.size()) {
                out += args[static_cast<std::size_t>(n - '1')];
                ++i;
                continue;
            }
        }
        out += c;
    }
    return out;
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

Diagnostic& Diagnostics::error(std::string code, SourcePos pos, Text message, Text hint)
{
    return add(Severity::Error, std::move(code), pos, std::move(message), std::move(hint));
}

Diagnostic& Diagnostics::warning(std::string code, SourcePos pos, Text message, Text hint)
{
    return add(Severity::Warning, std::move(code), pos, std::move(message), std::move(hint));
}

Diagnostic& Diagnostics::add(Severity s, std::string code, SourcePos pos, Text message, Text hint)
{
    Diagnostic& d = add(s, std::move(code), pos, message.english(), hint.english());
    if (&d != &m_sink) {
        d.messageText = std::move(message);
        d.hintText = std::move(hint);
    }
    return d;
}

Diagnostic& Diagnostics::add(Severity s, std::string code, SourcePos pos, std::string message,
                             std::string hint)
{
    if (s == Severity::Error) ++m_errors;
    if (s == Severity::Warning) ++m_warnings;
    if (m_items.size() >= m_limit) {
        if (m_dropped++ == 0) {
            Text message = trText("Diagnostics", "too many problems; the rest are not listed");
            Text hint = trText("Diagnostics", "fix the ones above first");
            m_items.push_back({Severity::Note, "too-many-diagnostics", m_file, pos, message.english(), hint.english(),
                               message, hint});
        }
        m_sink = {};
        return m_sink;
    }
    m_items.push_back({s, std::move(code), m_file, pos, std::move(message), std::move(hint), {}, {}});
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
        Diagnostic& n = add(d.severity, d.code, d.pos, std::string(d.message), std::string(d.hint));
        n.file = d.file;
        n.messageText = d.messageText;
        n.hintText = d.hintText;
    }
}

}  // namespace solver
