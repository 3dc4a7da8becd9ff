#pragma once
// A deterministic mutation fuzzer for text formats, shared by the model loader's fuzz
// test (tests/solver/fuzz_test.cpp) and the trainer's file readers' (tests/trainer_fuzz):
// from a seed text and a fixed seed, mutants made of byte flips, token deletion,
// duplication and swaps, inserted tokens from the format's vocabulary, cut, deleted,
// duplicated and joined lines, random bytes (invalid UTF-8, NUL, control characters).
// Also the checks' arithmetic: UTF-8 validity, line lengths in characters, escaping.

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace test::fuzz {

inline bool validUtf8(std::string_view s)
{
    for (std::size_t i = 0; i < s.size();) {
        const auto b0 = static_cast<unsigned char>(s[i]);
        const std::size_t len = b0 < 0x80 ? 1
                                : (b0 & 0xE0) == 0xC0 ? 2
                                : (b0 & 0xF0) == 0xE0 ? 3
                                : (b0 & 0xF8) == 0xF0 ? 4
                                                      : 0;
        if (len == 0 || i + len > s.size()) return false;
        unsigned cp = b0 & (0x7F >> len);
        for (std::size_t k = 1; k < len; ++k) {
            const auto b = static_cast<unsigned char>(s[i + k]);
            if ((b & 0xC0) != 0x80) return false;
            cp = (cp << 6) | (b & 0x3F);
        }
        static constexpr std::array<unsigned, 5> kMin = {0, 0, 0x80, 0x800, 0x10000};
        if (cp < kMin[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
        i += len;
    }
    return true;
}

/// The length in characters of each line, as the loader reads the text: UTF-8 (a
/// BOM is not part of line 1), or, when the text is not UTF-8, Latin-1 (one byte,
/// one character). A line's final CR is not counted.
inline std::vector<int> lineLengths(std::string_view text)
{
    const bool utf8 = validUtf8(text);
    if (utf8 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::vector<int> lengths;
    std::size_t start = 0;
    while (true) {
        std::size_t nl = text.find('\n', start);
        std::string_view line = text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        int n = 0;
        for (char c : line) {
            if (!utf8 || (static_cast<unsigned char>(c) & 0xC0) != 0x80) ++n;
        }
        lengths.push_back(n);
        if (nl == std::string_view::npos) break;
        start = nl + 1;
    }
    return lengths;
}

inline std::string escaped(std::string_view s)
{
    std::string out;
    for (char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') out += "\\n\n";
        else if (c == '\\') out += "\\\\";
        else if (u < 0x20 || u >= 0x7F) {
            char b[8];
            std::snprintf(b, sizeof b, "\\x%02X", u);
            out += b;
        } else {
            out += c;
        }
    }
    return out;
}

class Mutator {
public:
    /// `vocabulary`: the tokens inserted and substituted (the format's keywords, odd
    /// numbers, quotes…); not empty.
    Mutator(std::uint32_t seed, std::vector<std::string> vocabulary) : m_rng(seed), m_vocabulary(std::move(vocabulary)) {}

    std::string mutate(std::string s)
    {
        const int n = 1 + pick(4);
        for (int k = 0; k < n; ++k) s = mutateOnce(std::move(s));
        return s;
    }

private:
    std::mt19937 m_rng;
    std::vector<std::string> m_vocabulary;

    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_rng); }
    std::size_t pos(const std::string& s) { return std::uniform_int_distribution<std::size_t>(0, s.size())(m_rng); }

    /// Byte ranges of the blank-separated tokens.
    static std::vector<std::pair<std::size_t, std::size_t>> tokens(const std::string& s)
    {
        std::vector<std::pair<std::size_t, std::size_t>> t;
        std::size_t i = 0;
        while (i < s.size()) {
            while (i < s.size() && (s[i] == ' ' || s[i] == '\n' || s[i] == '\t' || s[i] == '\r')) ++i;
            std::size_t b = i;
            while (i < s.size() && !(s[i] == ' ' || s[i] == '\n' || s[i] == '\t' || s[i] == '\r')) ++i;
            if (i > b) t.emplace_back(b, i - b);
        }
        return t;
    }

    /// Byte ranges of the lines, each with its newline.
    static std::vector<std::pair<std::size_t, std::size_t>> lines(const std::string& s)
    {
        std::vector<std::pair<std::size_t, std::size_t>> l;
        std::size_t b = 0;
        while (b < s.size()) {
            std::size_t nl = s.find('\n', b);
            std::size_t e = nl == std::string::npos ? s.size() : nl + 1;
            l.emplace_back(b, e - b);
            b = e;
        }
        return l;
    }

    std::string randomToken()
    {
        return m_vocabulary[static_cast<std::size_t>(pick(static_cast<int>(m_vocabulary.size())))];
    }

    std::string randomBytes()
    {
        static const std::vector<std::string> kSpecial = {
            std::string(1, '\0'), "\x01", "\x07", "\x1B[0m", "\x7F", "\x80", "\xBF", "\xC0\x80", "\xC3", "\xE2\x82",
            "\xED\xA0\x80", "\xF4\x90\x80\x80", "\xF8\x88\x80\x80\x80", "\xFE", "\xFF", "\xF3", "\xF1",
        };
        if (pick(2) == 0) return kSpecial[static_cast<std::size_t>(pick(static_cast<int>(kSpecial.size())))];
        std::string b;
        const int n = 1 + pick(8);
        for (int k = 0; k < n; ++k) b += static_cast<char>(pick(256));
        return b;
    }

    std::string mutateOnce(std::string s)
    {
        if (s.empty()) return randomToken();
        auto toks = tokens(s);
        auto lns = lines(s);
        switch (pick(14)) {
        case 0: {  // flip a bit
            std::size_t i = pos(s) % s.size();
            s[i] = static_cast<char>(s[i] ^ (1 << pick(8)));
            return s;
        }
        case 1: {  // set a byte
            s[pos(s) % s.size()] = static_cast<char>(pick(256));
            return s;
        }
        case 2: {  // delete a token
            if (toks.empty()) return s;
            auto [b, n] = toks[static_cast<std::size_t>(pick(static_cast<int>(toks.size())))];
            return s.erase(b, n);
        }
        case 3: {  // duplicate a token
            if (toks.empty()) return s;
            auto [b, n] = toks[static_cast<std::size_t>(pick(static_cast<int>(toks.size())))];
            return s.insert(b, s.substr(b, n) + " ");
        }
        case 4: {  // swap two tokens (often neighbours)
            if (toks.size() < 2) return s;
            std::size_t i = static_cast<std::size_t>(pick(static_cast<int>(toks.size()) - 1));
            std::size_t j = pick(2) == 0 ? i + 1 : static_cast<std::size_t>(pick(static_cast<int>(toks.size())));
            if (i == j) return s;
            if (i > j) std::swap(i, j);
            const std::string a = s.substr(toks[i].first, toks[i].second), b = s.substr(toks[j].first, toks[j].second);
            s.replace(toks[j].first, toks[j].second, a);
            s.replace(toks[i].first, toks[i].second, b);
            return s;
        }
        case 5:
        case 6: {  // insert a token, between tokens or anywhere
            std::string t = randomToken();
            if (!toks.empty() && pick(3) != 0) {
                auto [b, n] = toks[static_cast<std::size_t>(pick(static_cast<int>(toks.size())))];
                return s.insert(pick(2) ? b : b + n, " " + t + " ");
            }
            return s.insert(pos(s), t);
        }
        case 7: {  // replace a token
            if (toks.empty()) return s;
            auto [b, n] = toks[static_cast<std::size_t>(pick(static_cast<int>(toks.size())))];
            return s.replace(b, n, randomToken());
        }
        case 8: {  // cut a line short
            auto [b, n] = lns[static_cast<std::size_t>(pick(static_cast<int>(lns.size())))];
            const std::size_t keep = n > 1 ? static_cast<std::size_t>(pick(static_cast<int>(n))) : 0;
            const bool nl = s[b + n - 1] == '\n';
            return s.erase(b + keep, n - keep - (nl ? 1 : 0));
        }
        case 9: {  // delete or duplicate a line
            auto [b, n] = lns[static_cast<std::size_t>(pick(static_cast<int>(lns.size())))];
            if (pick(2)) return s.erase(b, n);
            return s.insert(b, s.substr(b, n));
        }
        case 10: {  // join a line to the next, or break one
            if (pick(2)) {
                std::size_t nl = s.find('\n', pos(s) % s.size());
                if (nl != std::string::npos) s.erase(nl, 1);
                return s;
            }
            return s.insert(pos(s), pick(4) == 0 ? "\r\n" : "\n");
        }
        case 11: {  // random bytes
            return s.insert(pos(s), randomBytes());
        }
        case 12: {  // swap two lines
            if (lns.size() < 2) return s;
            std::size_t i = static_cast<std::size_t>(pick(static_cast<int>(lns.size()) - 1));
            std::string a = s.substr(lns[i].first, lns[i].second), b = s.substr(lns[i + 1].first, lns[i + 1].second);
            if (a.empty() || a.back() != '\n') return s;
            return s.replace(lns[i].first, a.size() + b.size(), b + (b.back() == '\n' ? "" : "\n") + a);
        }
        default: {  // delete a run of bytes
            std::size_t b = pos(s) % s.size();
            return s.erase(b, 1 + static_cast<std::size_t>(pick(16)));
        }
        }
    }
};


/// PADROB_FUZZ_SCALE=n in the environment makes n times as many mutants (and seeds
/// seed, seed + 1000, …), for a long run by hand; the default is 1.
inline int fuzzScale()
{
    const char* s = std::getenv("PADROB_FUZZ_SCALE");
    const int n = s ? std::atoi(s) : 1;
    return n > 0 ? n : 1;
}


/// Tokens every text format's fuzzing inserts: odd numbers, quotes, comments, bytes.
inline std::vector<std::string> commonTokens()
{
    return {"1e999", "-1e999", "1e-999", "1e308", "-1.7976931348623157e308", "4.9e-324", "99999999999999999999999999",
            "2147483647", "2147483648", "-2147483649", "4294967296", "0", "-0", "-1", "1.5", ".5", "-.2", "+4.5E2",
            "1e", "1e+", ".", "-", "+", "e5", "0x10", "1.2.3", "--1", "NaN", "nan", "-nan", "Inf", "-inf", "+INF",
            "infinity", "4,5", "4,38325", "-0,5", "1,2,3", ",", "\"", "\"open", "\"\"", "\"a b\"", "\"\\\"\"",
            "\"\\", "//", "#", "/", "ñ", "€", "😀", "\xEF\xBB\xBF", "\t", "\r", "\v", "\f"};
}

}  // namespace test::fuzz
