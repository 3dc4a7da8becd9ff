#include "solver/parse/lexer.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace solver::parse {

std::string upper(std::string_view s)
{
    std::string out(s);
    for (char& c : out) {
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    }
    return out;
}

bool Token::is(std::string_view kw) const
{
    return kind == Kind::Word && upper(text) == kw;
}

int columnOf(std::string_view s, std::size_t bytes)
{
    int col = 0;
    for (std::size_t i = 0; i < bytes && i < s.size(); ++i) {
        // count every byte that is not a UTF-8 continuation byte
        if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) ++col;
    }
    return col;
}

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

bool looksLikeNumber(std::string_view w)
{
    std::size_t i = 0;
    if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
    std::size_t digits = 0;
    while (i < w.size() && isDigit(w[i])) { ++i; ++digits; }
    if (i < w.size() && w[i] == '.') {
        ++i;
        while (i < w.size() && isDigit(w[i])) { ++i; ++digits; }
    }
    if (digits == 0) return false;
    if (i < w.size() && (w[i] == 'e' || w[i] == 'E')) {
        ++i;
        if (i < w.size() && (w[i] == '+' || w[i] == '-')) ++i;
        std::size_t expDigits = 0;
        while (i < w.size() && isDigit(w[i])) { ++i; ++expDigits; }
        if (expDigits == 0) return false;
    }
    return i == w.size();
}

namespace {

/// Parses a word that looksLikeNumber; false when out of the range of a double.
bool toDouble(std::string_view w, double& out)
{
    if (!w.empty() && w[0] == '+') w.remove_prefix(1);
    auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), out);
    if (ec == std::errc::result_out_of_range) {
        // from_chars reports underflow as out of range too; a tiny number is 0
        double mantissaOnly = 0;
        std::size_t e = w.find_first_of("eE");
        std::string_view mant = w.substr(0, e);
        std::from_chars(mant.data(), mant.data() + mant.size(), mantissaOnly);
        std::string_view ex = w.substr(e + 1);
        if (!ex.empty() && ex[0] == '+') ex.remove_prefix(1);
        if (e != std::string_view::npos && !ex.empty() && ex[0] == '-') {
            out = 0.0;
            return true;
        }
        if (mantissaOnly == 0.0) {
            out = 0.0;
            return true;
        }
        return false;
    }
    return ec == std::errc() && ptr == w.data() + w.size() && std::isfinite(out);
}

}  // namespace

std::string numberProblem(std::string_view w)
{
    std::string u = upper(w);
    std::string_view body = u;
    if (!body.empty() && (body[0] == '+' || body[0] == '-')) body.remove_prefix(1);
    if (body == "NAN" || body == "INF" || body == "INFINITY") return "not-finite";
    if (looksLikeNumber(w)) {
        double v = 0;
        return toDouble(w, v) ? std::string() : std::string("out-of-range");
    }
    // a decimal comma: digits on both sides of exactly one ','
    std::size_t comma = w.find(',');
    if (comma != std::string_view::npos && w.find(',', comma + 1) == std::string_view::npos) {
        std::string dotted(w);
        dotted[comma] = '.';
        if (looksLikeNumber(dotted) && comma > 0 && isDigit(w[comma - 1])) return "decimal-comma";
    }
    return {};
}

std::vector<Token> tokenizeLine(std::string_view line, int lineNo, Diagnostics& diags)
{
    std::vector<Token> tokens;
    tokenizeLine(line, lineNo, diags, tokens);
    return tokens;
}

void tokenizeLine(std::string_view line, int lineNo, Diagnostics& diags, std::vector<Token>& tokens)
{
    tokens.clear();
    std::size_t i = 0;
    const std::size_t n = line.size();
    // columns are counted incrementally (positions are asked for left to right), so
    // that a line of a million tokens takes linear, not quadratic, time
    std::size_t colByte = 0;
    int col = 0;
    auto posAt = [&](std::size_t byte) {
        if (byte < colByte) { colByte = 0; col = 0; }
        col += columnOf(line.substr(colByte), byte - colByte);
        colByte = byte;
        return SourcePos{lineNo, col + 1};
    };
    auto isBlank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
    auto isControl = [](char c) {
        auto u = static_cast<unsigned char>(c);
        return (u < 0x20 && c != '\t' && c != '\r' && c != '\v' && c != '\f') || u == 0x7F;
    };
    auto controlError = [&](std::size_t at) {
        diags.error("control-character", posAt(at),
                    trText("Diagnostics", "unexpected control character (code %1)")
                        .with(std::to_string(static_cast<unsigned char>(line[at]))),
                    trText("Diagnostics", "delete it; a model file is plain text"));
    };

    while (i < n) {
        char c = line[i];
        if (isBlank(c)) { ++i; continue; }
        if (isControl(c)) {
            controlError(i);
            ++i;
            continue;
        }
        if (c == '#' || (c == '/' && i + 1 < n && line[i + 1] == '/')) break;  // comment
        if (c == '"') {
            Token t;
            t.kind = Token::Kind::String;
            t.pos = posAt(i);
            ++i;
            bool closed = false;
            while (i < n) {
                char d = line[i];
                if (d == '\\' && i + 1 < n && (line[i + 1] == '"' || line[i + 1] == '\\')) {
                    t.text += line[i + 1];
                    i += 2;
                    continue;
                }
                if (d == '"') { closed = true; ++i; break; }
                if (isControl(d)) {  // not even inside a string (a name with a bell in it)
                    controlError(i);
                    ++i;
                    continue;
                }
                t.text += d;
                ++i;
            }
            if (!closed) {
                diags.error("unterminated-string", t.pos, trText("Diagnostics", "the string has no closing quote"),
                            trText("Diagnostics", "add '\"' at the end of the text"));
            }
            tokens.push_back(std::move(t));
            continue;
        }
        // a word or number runs to a blank, a quote, a control character or a comment
        std::size_t start = i;
        while (i < n && !isBlank(line[i]) && !isControl(line[i]) && line[i] != '"' && line[i] != '#' &&
               !(line[i] == '/' && i + 1 < n && line[i + 1] == '/')) {
            ++i;
        }
        Token& t = tokens.emplace_back();
        t.text.assign(line.data() + start, i - start);
        t.pos = posAt(start);
        double v = 0;
        if (looksLikeNumber(t.text) && toDouble(t.text, v)) {
            t.kind = Token::Kind::Number;
            t.number = v;
        }
    }
}

}  // namespace solver::parse
