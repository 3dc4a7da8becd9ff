#pragma once
// A tiny streaming JSON writer: keys keep the order they are written in, so the
// `padrob info --json` output is stable (docs/cli.md).

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace ide::cli {

class JsonWriter {
public:
    explicit JsonWriter(bool pretty = true) : m_pretty(pretty) {}

    JsonWriter& beginObject() { value(); m_out += '{'; m_stack.push_back({true, true}); return *this; }
    JsonWriter& endObject() { close('}'); return *this; }
    JsonWriter& beginArray() { value(); m_out += '['; m_stack.push_back({false, true}); return *this; }
    JsonWriter& endArray() { close(']'); return *this; }

    JsonWriter& key(std::string_view k)
    {
        separator();
        string(k);
        m_out += m_pretty ? ": " : ":";
        m_afterKey = true;
        return *this;
    }
    JsonWriter& str(std::string_view s) { value(); string(s); return *this; }
    JsonWriter& num(double v)
    {
        value();
        if (!std::isfinite(v)) { m_out += "null"; return *this; }
        if (v == 0) { m_out += '0'; return *this; }
        char buf[64];
        auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
        m_out.append(buf, p);
        return *this;
    }
    JsonWriter& integer(long long v) { value(); m_out += std::to_string(v); return *this; }
    JsonWriter& boolean(bool b) { value(); m_out += b ? "true" : "false"; return *this; }
    JsonWriter& null() { value(); m_out += "null"; return *this; }

    const std::string& text() const { return m_out; }

private:
    struct Level { bool object; bool first; };
    std::string m_out;
    std::vector<Level> m_stack;
    bool m_pretty;
    bool m_afterKey = false;

    void newline()
    {
        if (!m_pretty) return;
        m_out += '\n';
        m_out.append(2 * m_stack.size(), ' ');
    }
    void separator()
    {
        if (m_stack.empty()) return;
        if (!m_stack.back().first) m_out += ',';
        m_stack.back().first = false;
        newline();
    }
    void value()
    {
        if (m_afterKey) { m_afterKey = false; return; }
        separator();
    }
    void close(char c)
    {
        bool empty = m_stack.back().first;
        m_stack.pop_back();
        if (!empty) newline();
        m_out += c;
    }
    void string(std::string_view s)
    {
        m_out += '"';
        for (char ch : s) {
            const auto c = static_cast<unsigned char>(ch);
            switch (ch) {
            case '"': m_out += "\\\""; break;
            case '\\': m_out += "\\\\"; break;
            case '\n': m_out += "\\n"; break;
            case '\t': m_out += "\\t"; break;
            case '\r': m_out += "\\r"; break;
            default:
                if (c < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    m_out += buf;
                } else {
                    m_out += ch;
                }
            }
        }
        m_out += '"';
    }
};

}  // namespace ide::cli
