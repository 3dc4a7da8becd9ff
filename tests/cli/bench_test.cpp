// `padrob bench` through the real binary: the table, the JSON keys and their
// consistency, the scaling section, errors and help. Cheap runs only (--steps 200
// --runs 2); no speed is asserted.

#include "cli_run.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace test;

namespace {

// ---- a small JSON reader (enough for padrob's own output) ---------------------

struct Json {
    enum class Kind { Null, Bool, Number, String, Array, Object } kind = Kind::Null;
    bool boolean = false;
    double number = 0;
    std::string string;
    std::vector<Json> array;
    std::map<std::string, Json> object;

    bool has(const std::string& k) const { return kind == Kind::Object && object.count(k) > 0; }
    const Json& operator[](const std::string& k) const { return object.at(k); }
};

class JsonReader {
public:
    explicit JsonReader(const std::string& s) : m_s(s) {}
    /// The document, or nullptr when it is not one JSON value.
    std::unique_ptr<Json> read()
    {
        auto v = std::make_unique<Json>();
        if (!value(*v)) return nullptr;
        space();
        return m_i == m_s.size() ? std::move(v) : nullptr;
    }

private:
    const std::string& m_s;
    std::size_t m_i = 0;

    void space()
    {
        while (m_i < m_s.size() && std::isspace(static_cast<unsigned char>(m_s[m_i]))) ++m_i;
    }
    bool literal(const char* word)
    {
        const std::string w(word);
        if (m_s.compare(m_i, w.size(), w) != 0) return false;
        m_i += w.size();
        return true;
    }
    bool str(std::string& out)
    {
        if (m_i >= m_s.size() || m_s[m_i] != '"') return false;
        ++m_i;
        while (m_i < m_s.size() && m_s[m_i] != '"') {
            if (m_s[m_i] == '\\') {
                if (++m_i >= m_s.size()) return false;
                const char c = m_s[m_i];
                out += c == 'n' ? '\n' : c == 't' ? '\t' : c == 'r' ? '\r' : c;
                if (c == 'u') return false;  // not produced for these texts
            } else {
                out += m_s[m_i];
            }
            ++m_i;
        }
        if (m_i >= m_s.size()) return false;
        ++m_i;
        return true;
    }
    bool value(Json& v)
    {
        space();
        if (m_i >= m_s.size()) return false;
        const char c = m_s[m_i];
        if (c == '{') {
            v.kind = Json::Kind::Object;
            ++m_i;
            space();
            if (m_i < m_s.size() && m_s[m_i] == '}') return ++m_i, true;
            while (true) {
                space();
                std::string k;
                if (!str(k)) return false;
                space();
                if (m_i >= m_s.size() || m_s[m_i++] != ':') return false;
                Json item;
                if (!value(item) || v.object.count(k)) return false;  // duplicate keys are an error here
                v.object.emplace(k, std::move(item));
                space();
                if (m_i < m_s.size() && m_s[m_i] == ',') { ++m_i; continue; }
                if (m_i < m_s.size() && m_s[m_i] == '}') return ++m_i, true;
                return false;
            }
        }
        if (c == '[') {
            v.kind = Json::Kind::Array;
            ++m_i;
            space();
            if (m_i < m_s.size() && m_s[m_i] == ']') return ++m_i, true;
            while (true) {
                Json item;
                if (!value(item)) return false;
                v.array.push_back(std::move(item));
                space();
                if (m_i < m_s.size() && m_s[m_i] == ',') { ++m_i; continue; }
                if (m_i < m_s.size() && m_s[m_i] == ']') return ++m_i, true;
                return false;
            }
        }
        if (c == '"') {
            v.kind = Json::Kind::String;
            return str(v.string);
        }
        if (literal("true")) { v.kind = Json::Kind::Bool; v.boolean = true; return true; }
        if (literal("false")) { v.kind = Json::Kind::Bool; return true; }
        if (literal("null")) return true;
        const char* begin = m_s.c_str() + m_i;
        char* end = nullptr;
        v.number = std::strtod(begin, &end);
        if (end == begin) return false;
        v.kind = Json::Kind::Number;
        m_i += static_cast<std::size_t>(end - begin);
        return true;
    }
};

std::unique_ptr<Json> parse(const std::string& s) { return JsonReader(s).read(); }

// a positive finite number under `key`, with _min ≤ it ≤ _max when `figure`
void expectFigure(const Json& j, const std::string& key, bool figure = true)
{
    ASSERT_TRUE(j.has(key)) << key;
    ASSERT_EQ(j[key].kind, Json::Kind::Number) << key;
    const double v = j[key].number;
    EXPECT_TRUE(std::isfinite(v) && v > 0) << key << " = " << v;
    if (!figure) return;
    ASSERT_TRUE(j.has(key + "_min") && j.has(key + "_max")) << key;
    EXPECT_GT(j[key + "_min"].number, 0) << key;
    EXPECT_LE(j[key + "_min"].number, v) << key;
    EXPECT_GE(j[key + "_max"].number, v) << key;
}

const std::string kCheap = " --steps 200 --runs 2";

}  // namespace

TEST(CliBench, HelpListsEveryOption)
{
    CliRun r = padrob("bench --help");
    EXPECT_EQ(r.status, 0);
    for (const char* o : {"--steps N", "--runs R", "--dt H", "--integrator M", "--json", "--scaling", "--no-mujoco",
                          "Exit status"}) {
        EXPECT_NE(r.out.find(o), std::string::npos) << o;
    }
    EXPECT_EQ(r.err, "");
    EXPECT_NE(padrob("--help").out.find("bench MODEL"), std::string::npos);
}

TEST(CliBench, TheTableHasEveryFigure)
{
    CliRun r = padrob("bench models/liner_manipulator.pad --no-mujoco" + kCheap);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out.rfind("machine: ", 0), 0u) << r.out;
    EXPECT_NE(r.out.find(" cores"), std::string::npos);
    EXPECT_NE(r.out.find("model: models/liner_manipulator.pad (bodies: 9, drives: 9, loop closures: 0)"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("steps: 200 of dt = 1 ms, RK4"), std::string::npos) << r.out;
    // each figure's row: a label, the median and the min – max range
    for (const char* label : {"forward dynamics, per evaluation", "RK4 step ", "RK4 step, commands held",
                              "RK4 step, passive, no limits",
                              "reference N–E system, per solve", "reference RK4 step"}) {
        bool found = false;
        for (const std::string& line : lines(r.out)) {
            if (line.find(label) == std::string::npos) continue;
            found = true;
            EXPECT_NE(line.find(" – "), std::string::npos) << line;
            EXPECT_NE(line.find_first_of("0123456789"), std::string::npos) << line;
        }
        EXPECT_TRUE(found) << label << "\n" << r.out;
    }
    EXPECT_NE(r.out.find("realtime factor "), std::string::npos);
    EXPECT_NE(r.out.find("evaluations/s"), std::string::npos);
    EXPECT_NE(r.out.find("the joint reactions computed"), std::string::npos);
    EXPECT_EQ(r.out.find("MuJoCo RK4"), std::string::npos);  // --no-mujoco
}

TEST(CliBench, JsonParsesAndItsFiguresAreConsistent)
{
    CliRun r = padrob("bench models/liner_manipulator.pad --json" + kCheap);
    ASSERT_EQ(r.status, 0) << r.err;
    auto doc = parse(r.out);
    ASSERT_TRUE(doc) << r.out;
    const Json& j = *doc;
    EXPECT_EQ(j["format"].string, "padrob-bench");
    EXPECT_EQ(j["version"].number, 1);
    EXPECT_EQ(j["model"].string, "models/liner_manipulator.pad");
    EXPECT_EQ(j["integrator"].string, "rk4");
    EXPECT_EQ(j["steps"].number, 200);
    EXPECT_EQ(j["runs"].number, 2);
    EXPECT_EQ(j["dt"].number, 0.001);
    EXPECT_EQ(j["bodies"].number, 9);
    EXPECT_FALSE(j["machine"]["cpu"].string.empty());
    EXPECT_GE(j["machine"]["cores"].number, 1);
    for (const char* k : {"forward_dynamics_us", "rk4_step_us", "held_rk4_step_us", "passive_rk4_step_us",
                          "reference_forward_us",
                          "reference_rk4_step_us", "realtime_factor"}) {
        expectFigure(j, k);
    }
    for (const char* k : {"steps_per_second", "forward_evaluations_per_second", "reference_forward_ratio",
                          "reference_rk4_ratio"}) {
        expectFigure(j, k, false);
    }
    // realtime factor = dt / step time, and its range from the slowest and fastest runs
    const double step = j["rk4_step_us"].number;
    EXPECT_NEAR(j["realtime_factor"].number, 1e3 / step, 1e-9 * (1e3 / step));
    EXPECT_NEAR(j["realtime_factor_min"].number, 1e3 / j["rk4_step_us_max"].number, 1e-9 * (1e3 / step));
    EXPECT_NEAR(j["steps_per_second"].number, 1e6 / step, 1e-9 * (1e6 / step));
    EXPECT_NEAR(j["reference_rk4_ratio"].number, j["reference_rk4_step_us"].number / step,
                1e-9 * j["reference_rk4_ratio"].number);
    // the reference solves the same dynamics
    EXPECT_LT(j["reference_qdd_difference"].number, 1e-8);
    EXPECT_EQ(j["reference_evaluations"].number, 200);
    EXPECT_EQ(j["reference_steps"].number, 200);
    EXPECT_GE(j["events"].number, 0);
    // MuJoCo: its figures when it ran, else why not (on standard error too); never both
    if (j.has("mujoco_rk4_step_us")) {
        EXPECT_FALSE(j.has("mujoco_error"));
        expectFigure(j, "mujoco_rk4_step_us");
        expectFigure(j, "mujoco_forward_us");
        EXPECT_NEAR(j["ratio_vs_mujoco"].number, step / j["mujoco_rk4_step_us"].number,
                    1e-9 * j["ratio_vs_mujoco"].number);
        EXPECT_GE(j["mujoco_max_position_error_m"].number, 0);
        EXPECT_EQ(j["mujoco_adjustments"].kind, Json::Kind::Array);
    } else if (j.has("mujoco_error")) {
        EXPECT_FALSE(j["mujoco_error"].string.empty());
        EXPECT_NE(r.err.find("MuJoCo: " + j["mujoco_error"].string), std::string::npos) << r.err;
    }
    EXPECT_FALSE(j.has("scaling"));
}

TEST(CliBench, NoMujocoLeavesItsKeysOut)
{
    CliRun r = padrob("bench models/pendulum.pad --json --no-mujoco" + kCheap);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    auto doc = parse(r.out);
    ASSERT_TRUE(doc) << r.out;
    for (const auto& [k, v] : doc->object) EXPECT_EQ(k.find("mujoco"), std::string::npos) << k;
}

TEST(CliBench, AClosedLoopTakesTheDensePathAndNoMujoco)
{
    CliRun r = padrob("bench models/excavator.pad --json" + kCheap);
    ASSERT_EQ(r.status, 0) << r.err;
    auto doc = parse(r.out);
    ASSERT_TRUE(doc) << r.out;
    const Json& j = *doc;
    EXPECT_EQ(j["loop_closures"].number, 1);
    expectFigure(j, "rk4_step_us");
    expectFigure(j, "reference_forward_us");
    EXPECT_LT(j["reference_qdd_difference"].number, 1e-6);
    EXPECT_FALSE(j.has("mujoco_rk4_step_us"));  // MuJoCo only on trees
    EXPECT_FALSE(j.has("mujoco_error"));
}

TEST(CliBench, AdaptiveIsTimedPerSimulatedMillisecond)
{
    CliRun r = padrob("bench models/liner_manipulator.pad --integrator adaptive --json --steps 100 --runs 1");
    ASSERT_EQ(r.status, 0) << r.err;
    auto doc = parse(r.out);
    ASSERT_TRUE(doc) << r.out;
    const Json& j = *doc;
    EXPECT_EQ(j["integrator"].string, "adaptive");
    expectFigure(j, "adaptive_us_per_ms");
    EXPECT_FALSE(j.has("rk4_step_us"));
    EXPECT_NEAR(j["realtime_factor"].number, 1e3 / j["adaptive_us_per_ms"].number, 1e-9 * j["realtime_factor"].number);
}

TEST(CliBench, ScalingHasFiveChainsFiveTreesAndExponents)
{
    CliRun r = padrob("bench --scaling --json" + kCheap);
    ASSERT_EQ(r.status, 0) << r.err;
    auto doc = parse(r.out);
    ASSERT_TRUE(doc) << r.out;
    const Json& j = *doc;
    EXPECT_FALSE(j.has("model"));
    ASSERT_TRUE(j.has("scaling"));
    const Json& s = j["scaling"];
    for (const char* kind : {"chain", "tree"}) {
        SCOPED_TRACE(kind);
        ASSERT_EQ(s[kind].kind, Json::Kind::Array);
        ASSERT_EQ(s[kind].array.size(), 5u);
        const int sizes[] = {10, 30, 100, 300, 1000};
        for (std::size_t k = 0; k < 5; ++k) {
            const Json& p = s[kind].array[k];
            EXPECT_EQ(p["bodies"].number, sizes[k]);
            EXPECT_GE(p["steps"].number, 20);
            expectFigure(p, "rk4_step_us");
            expectFigure(p, "commanded_rk4_step_us");
            EXPECT_GE(p["events"].number, 0);
            EXPECT_GE(p["commanded_events"].number, 0);
        }
    }
    for (const char* k : {"chain_exponent", "tree_exponent", "chain_commanded_exponent", "tree_commanded_exponent"}) {
        ASSERT_EQ(s[k].kind, Json::Kind::Number) << k;
        EXPECT_TRUE(std::isfinite(s[k].number)) << k;
    }
    // and the table
    CliRun t = padrob("bench --scaling --steps 20 --runs 1");
    ASSERT_EQ(t.status, 0) << t.err;
    EXPECT_NE(t.out.find("time ∝ n^p by least squares on log–log"), std::string::npos) << t.out;
    bool sizes = false, exponents = false;
    for (const std::string& line : lines(t.out)) {
        sizes = sizes || line.rfind("     1000 ", 0) == 0;
        exponents = exponents || line.rfind("  p ", 0) == 0;
    }
    EXPECT_TRUE(sizes && exponents) << t.out;
}

TEST(CliBench, BadOptionsExitTwo)
{
    const std::string m = " models/pendulum.pad";
    struct Case {
        std::string args, message;
    };
    for (const Case& c : std::vector<Case>{
             {"bench", "no model given"},
             {"bench --bogus" + m, "unknown option '--bogus'"},
             {"bench" + m + " models/four_bar.pad", "give one model"},
             {"bench" + m + " --steps", "--steps needs a value"},
             {"bench" + m + " --steps 0", "--steps must be a whole number from 1"},
             {"bench" + m + " --steps 1.5", "--steps must be a whole number from 1 to 100000000, not '1.5'"},
             {"bench" + m + " --runs x", "--runs must be a whole number"},
             {"bench" + m + " --dt -1", "--dt must be a number of seconds"},
             {"bench" + m + " --dt nan", "--dt must be"},
             {"bench" + m + " --integrator euler", "--integrator must be rk4 or adaptive, not 'euler'"},
         }) {
        SCOPED_TRACE(c.args);
        CliRun r = padrob(c.args);
        EXPECT_EQ(r.status, 2);
        EXPECT_EQ(r.out, "");
        EXPECT_NE(r.err.find("padrob bench: " + c.message), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("Try 'padrob bench --help'."), std::string::npos);
    }
    CliRun missing = padrob("bench /nonexistent/model.pad");
    EXPECT_EQ(missing.status, 2);
    EXPECT_NE(missing.err.find("/nonexistent/model.pad: error:"), std::string::npos) << missing.err;
    EXPECT_EQ(padrob("bench models").status, 2);
}

TEST(CliBench, AModelWithErrorsExitsOne)
{
    const std::string path = writeTemp("bench_bad.pad", "B 1 1 1 1 1\nC 1\nB1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1\n"
                                                         "B2 7 P2 0 0 1 A2 1 0 0 R2 0 0 1\n");
    CliRun r = padrob("bench '" + path + "'" + kCheap);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("bench_bad.pad:4:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("error"), std::string::npos) << r.err;
}

// --scene: the model runs in the scene with contacts (CONTACT added when it has none),
// the contact phase is timed apart (contact_us) and, with MuJoCo, mj_step on the export
// with its geoms is the denominator of ratio_vs_mujoco. No speed is asserted here (the
// targets live in docs/performance.md).
TEST(CliBench, ASceneTimesTheContactPhaseAndMujocoWithGeoms)
{
    CliRun r = padrob("bench models/liner_mill.pad --scene resources/scenes/sag_mill.pad --json" + kCheap);
    ASSERT_EQ(r.status, 0) << r.err;
    auto doc = parse(r.out);
    ASSERT_TRUE(doc) << r.out;
    const Json& j = *doc;
    EXPECT_EQ(j["scene"].string, "resources/scenes/sag_mill.pad");
    EXPECT_EQ(j["contact_source"].string, "added");  // liner_mill.pad has no CONTACT
    expectFigure(j, "contact_us");
    expectFigure(j, "rk4_step_us");
    EXPECT_LT(j["contact_us"].number, j["rk4_step_us_max"].number * 1.5);  // a part of the step (its clock aside)
    EXPECT_GE(j["contact_points"].number, 0);
    if (j.has("mujoco_rk4_step_us")) {
        expectFigure(j, "mujoco_contact_rk4_step_us");
        EXPECT_GT(j["mujoco_geoms"].number, 200);  // the machine's and the mill's solids, the shell a ring of boxes
        EXPECT_NEAR(j["ratio_vs_mujoco"].number, j["rk4_step_us"].number / j["mujoco_contact_rk4_step_us"].number,
                    1e-9 * j["ratio_vs_mujoco"].number);
        EXPECT_TRUE(std::isfinite(j["ratio_vs_mujoco"].number) && j["ratio_vs_mujoco"].number > 0);
    } else {
        ASSERT_TRUE(j.has("mujoco_error")) << r.out;
    }
    // without a scene nothing of it
    CliRun plain = padrob("bench models/pendulum.pad --json --no-mujoco" + kCheap);
    auto p = parse(plain.out);
    ASSERT_TRUE(p);
    EXPECT_FALSE(p->has("contact_us"));
    EXPECT_FALSE(p->has("scene"));
    // a scene that cannot be read is a usage error
    EXPECT_EQ(padrob("bench models/pendulum.pad --scene no_such_scene.pad" + kCheap).status, 2);
    EXPECT_EQ(padrob("bench models/pendulum.pad --scene").status, 2);
}
