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
#include "tests/common/fuzz.h"
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

using ::test::fuzz::escaped;
using ::test::fuzz::fuzzScale;
using ::test::fuzz::lineLengths;
using ::test::fuzz::Mutator;
using ::test::fuzz::validUtf8;

/// The model language's tokens the mutants get: odd numbers, quotes, keywords, bytes
/// (in the order the seeds' mutants were first made with).
std::vector<std::string> modelTokens()
{
    return {
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
        Simulation sim(m.model, solver::test::rk4(1e-3));
        for (int j = 0; j < m.model->nb; ++j) sim.setCommand(j, j % 2 ? 0.7 : -0.4);
        std::vector<SimulationEvent> events;
        std::string error;
        const bool ran = sim.advanceTo(0.02, events, error);
        if (!ran && error.empty()) out.problem = "the simulation failed without saying why";
        out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return out;
}

/// A folder with meshes/part.stl, where the seed models' MESH graphics are found.
class MeshFolder {
public:
    MeshFolder() : m_tmp("fuzz_test") { m_tmp.write("meshes/part.stl", "solid part\nendsolid part\n"); }
    std::string modelFile() const { return m_tmp.path("m.pad"); }

private:
    solver::test::TempDir m_tmp;
};

/// Checks `count` mutants of `seedText`; at least `minLoaded` of them must load.
void fuzzOnce(const std::string& seedText, std::uint32_t seed, int count, int minLoaded)
{
    const MeshFolder folder;
    Mutator mutator(seed, modelTokens());
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
