// A deterministic mutation fuzzer of the model loader.
//
// From two seed models (the thesis's Appendix A, and a model with every statement)
// it makes thousands of mutants with fixed seeds: byte flips, token deletion,
// duplication and swaps, inserted tokens (huge numbers, NaN, "4,5", quotes,
// keywords, …), cut, deleted, duplicated and joined lines, random bytes (invalid
// UTF-8, NUL, control characters). For every mutant, compileText must return in
// time, and its diagnostics must be well formed:
//   - each has a position inside the text: 1 ≤ line ≤ number of lines, and
//     1 ≤ column ≤ the length of that line in characters + 1 (whole-file
//     diagnostics: "binary-file" may use 1:1);
//   - each error formats as "m.pad:L:C: error: message";
//   - a model with errors has no topology; one without errors has one, and writes
//     and reads back as the same model.
// On a failure the mutant is printed (escaped) with its seed and index.

#include "model_texts.h"
#include "solver/integrate/simulation.h"
#include "solver/pipeline.h"
#include "solver/parse/parser.h"
#include "solver/parse/writer.h"
#include "temp_dir.h"
#include "test_models.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <string_view>
#include <vector>

using namespace solver;

namespace {

bool validUtf8(std::string_view s)
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
std::vector<int> lineLengths(std::string_view text)
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

std::string escaped(std::string_view s)
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

struct Outcome {
    std::string problem;  ///< the first invariant broken, or empty
    double seconds = 0;   ///< time to load
    bool loaded = false;  ///< the mutant loaded without errors
};

/// The first invariant that the loaded model `m` of `text` breaks, or "".
std::string firstProblem(const CompiledModel& m, const std::string& text, const std::string& file)
{
    const std::vector<int> lengths = lineLengths(text);
    for (const Diagnostic& d : m.diagnostics) {
        const std::string f = d.format();
        const bool wholeFile = d.code == "binary-file" && d.pos == SourcePos{1, 1};
        if (!wholeFile) {
            if (d.pos.line < 1 || d.pos.line > static_cast<int>(lengths.size())) {
                return "line out of the text (" + std::to_string(lengths.size()) + " lines): " + f;
            }
            const int len = lengths[static_cast<std::size_t>(d.pos.line - 1)];
            if (d.pos.column < 1 || d.pos.column > len + 1) {
                return "column out of line " + std::to_string(d.pos.line) + " (" + std::to_string(len) +
                       " characters): " + f;
            }
        }
        if (d.file != file) return "file name '" + d.file + "': " + f;
        if (d.code.empty() || d.message.empty()) return "no code or message: " + f;
        if (d.severity == Severity::Error) {
            const std::string prefix =
                file + ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column) + ": error: ";
            if (f.compare(0, prefix.size(), prefix) != 0 || f.size() == prefix.size()) return "badly formatted: " + f;
        }
    }
    if (m.ok() == m.diagnostics.hasErrors()) return "ok() disagrees with the errors";
    if (!m.ok() && m.topology) return "a model with errors has a topology";
    if (m.ok() && !m.topology) return "a model without errors has no topology";
    if (m.ok()) {
        // a model that loads writes out and reads back as the same model
        const std::string written = parse::writeModel(m.spec);
        CompiledModel back = compileText(written, file);
        if (!back.ok()) return "its written form does not load:\n" + written;
        if (parse::writeModel(back.spec) != written) return "its written form does not read back the same:\n" + written;
    }
    return {};
}

/// Loads one text as the model file `file` and checks the invariants.
Outcome checkInvariants(const std::string& text, const std::string& file = "m.pad")
{
    Outcome out;
    const auto t0 = std::chrono::steady_clock::now();
    const CompiledModel m = compileText(text, file);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.loaded = m.ok();
    out.problem = firstProblem(m, text, file);
    if (out.problem.empty() && m.model) {
        // a model that loads must also run (or stop with an error): 20 steps of the
        // real-time path with every drive commanded, never a crash or a hang
        Simulation sim(m.model, test::rk4(1e-3));
        for (int j = 0; j < m.model->nb; ++j) sim.setCommand(j, j % 2 ? 0.7 : -0.4);
        std::vector<SimulationEvent> events;
        std::string error;
        const bool ran = sim.advanceTo(0.02, events, error);
        if (!ran && error.empty()) out.problem = "the simulation failed without saying why";
        out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return out;
}

class Mutator {
public:
    explicit Mutator(std::uint32_t seed) : m_rng(seed) {}

    std::string mutate(std::string s)
    {
        const int n = 1 + pick(4);
        for (int k = 0; k < n; ++k) s = mutateOnce(std::move(s));
        return s;
    }

private:
    std::mt19937 m_rng;

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
        static const std::vector<std::string> kTokens = {
            "1e999", "-1e999", "1e-999", "1e308", "-1.7976931348623157e308", "4.9e-324",
            "99999999999999999999999999", "2147483647", "2147483648", "-2147483649", "4294967296", "0", "-0",
            "-1", "1.5", ".5", "-.2", "+4.5E2", "1e", "1e+", ".", "-", "+", "e5", "0x10", "1.2.3", "--1",
            "NaN", "nan", "-nan", "Inf", "-inf", "+INF", "infinity", "4,5", "4,38325", "-0,5", "1,2,3", ",",
            "\"", "\"open", "\"\"", "\"a b\"", "\"\\\"\"", "\"\\", "//", "#", "/", "DEG", "deg",
            "GRAVITY", "B", "C", "D", "F", "G", "B1", "B2", "CL1", "CL2", "P1", "P2", "A1", "A2", "R1", "R2",
            "T", "LL", "UL", "QI", "VI", "NAME", "CG", "HYD", "MOTOR", "PNEU", "SERVO", "VMAX", "VMIN", "FMAX",
            "FMIN", "PUMP", "RPM", "BORE", "ROD", "PRESSURE", "T0", "W0", "KP", "KI", "KD", "POINT", "TORQUE",
            "JOINT", "SPRING", "AERO", "P", "DIR", "MAG", "SIN", "TABLE", "Q", "LOCAL", "K", "L0", "AREA",
            "CD", "CL", "RHO", "BOX", "CYL", "TUBE", "SPHERE", "CONE", "ELLIPSOID", "PRISM", "MESH", "SCALE",
            "POS", "AXIS", "ROT", "COLOR", "MASS", "ñ", "€", "😀", "\xEF\xBB\xBF", "\t", "\r", "\v", "\f",
        };
        return kTokens[static_cast<std::size_t>(pick(static_cast<int>(kTokens.size())))];
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

/// A folder with meshes/part.stl, where the seed models' MESH graphics are found.
class MeshFolder {
public:
    MeshFolder() : m_tmp("fuzz_test") { m_tmp.write("meshes/part.stl", "solid part\nendsolid part\n"); }
    std::string modelFile() const { return m_tmp.path("m.pad"); }

private:
    solver::test::TempDir m_tmp;
};

/// PADROB_FUZZ_SCALE=n in the environment makes n times as many mutants (and seeds
/// seed, seed + 1000, …), for a long run by hand; the default is 1.
int fuzzScale()
{
    const char* s = std::getenv("PADROB_FUZZ_SCALE");
    const int n = s ? std::atoi(s) : 1;
    return n > 0 ? n : 1;
}

/// Checks `count` mutants of `seedText`; at least `minLoaded` of them must load.
void fuzzOnce(const std::string& seedText, std::uint32_t seed, int count, int minLoaded)
{
    const MeshFolder folder;
    Mutator mutator(seed);
    double worst = 0, total = 0;
    int loaded = 0;
    for (int k = 0; k < count; ++k) {
        const std::string mutant = mutator.mutate(seedText);
        const Outcome o = checkInvariants(mutant, folder.modelFile());
        worst = std::max(worst, o.seconds);
        total += o.seconds;
        loaded += o.loaded ? 1 : 0;
        if (!o.problem.empty()) {
            ADD_FAILURE() << "seed " << seed << ", mutant " << k << ": " << o.problem << "\n--- mutant:\n"
                          << escaped(mutant) << "\n---";
            return;  // one report per seed is enough to reproduce
        }
    }
    // no mutant may take long (a hang or a quadratic blow-up), even under ASan
    EXPECT_LT(worst, 1.0) << "slowest of " << count << " mutants";
    // many mutants must load, or the checks after a successful load test little
    EXPECT_GE(loaded, minLoaded) << "mutants that loaded: " << loaded << " of " << count;
    std::printf("[ fuzz     ] seed %u: %d mutants, %d load, %.3f s, slowest %.4f s\n", seed, count, loaded, total,
                worst);
}

void fuzz(const std::string& seedText, std::uint32_t seed, int count, int minLoaded)
{
    for (int run = 0; run < fuzzScale() && !testing::Test::HasFailure(); ++run) {
        fuzzOnce(seedText, seed + 1000u * static_cast<std::uint32_t>(run), count, minLoaded);
    }
}


}  // namespace

TEST(Fuzz, SeedsSatisfyTheInvariants)
{
    const MeshFolder folder;
    const Outcome a = checkInvariants(solver::test::kAppendixA);
    EXPECT_EQ(a.problem, "");
    EXPECT_FALSE(a.loaded);  // the decimal comma
    const Outcome c = checkInvariants(solver::test::appendixACorrected());
    EXPECT_EQ(c.problem, "");
    EXPECT_TRUE(c.loaded);
    const Outcome e = checkInvariants(solver::test::kEveryStatement, folder.modelFile());
    EXPECT_EQ(e.problem, "");
    EXPECT_TRUE(e.loaded);
}

TEST(Fuzz, CheckerSeesBadPositions)
{
    // the checker's own arithmetic: lines, characters, BOM, CR, Latin-1
    EXPECT_EQ(lineLengths("ab\ncd\r\n"), (std::vector<int>{2, 2, 0}));
    EXPECT_EQ(lineLengths("\xEF\xBB\xBF" "añb"), (std::vector<int>{3}));
    EXPECT_EQ(lineLengths("a\xF1" "b\n"), (std::vector<int>{3, 0}));  // not UTF-8: Latin-1
    EXPECT_FALSE(validUtf8("\xED\xA0\x80"));  // a surrogate
    EXPECT_FALSE(validUtf8("\xC0\x80"));      // overlong
    EXPECT_TRUE(validUtf8("😀ñ"));
}

TEST(Fuzz, AppendixAMutants)
{
    fuzz(solver::test::kAppendixA, 1, 600, 0);
    fuzz(solver::test::appendixACorrected(), 2, 900, 90);
}

TEST(Fuzz, ClosedLoopMutants)
{
    // the slider-crank's loop goes through the constraint solver (SVD, projection): a
    // piston's Ixx of 1.7976931348623157e308 once crashed it there
    std::ifstream in(solver::test::modelPath("slider_crank.pad"));
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(text.empty());
    fuzz(text, 5, 500, 50);
}

TEST(Fuzz, EveryStatementMutants)
{
    fuzz(solver::test::kEveryStatement, 3, 750, 30);
    fuzz(solver::test::kEveryStatement, 4, 750, 30);
}
