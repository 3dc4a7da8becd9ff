// The `padrob` command line through its real binary: output, exit codes, help.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "cli_run.h"

using namespace test;

TEST(Cli, VersionAndHelp)
{
    CliRun v = padrob("--version");
    EXPECT_EQ(v.status, 0);
    EXPECT_EQ(v.out, std::string("padrob ") + PADROB_VERSION + "\n");
    CliRun h = padrob("--help");
    EXPECT_EQ(h.status, 0);
    EXPECT_NE(h.out.find("check MODEL..."), std::string::npos);
    EXPECT_NE(h.out.find("info MODEL [--json]"), std::string::npos);
    CliRun hc = padrob("check --help");
    EXPECT_EQ(hc.status, 0);
    EXPECT_NE(hc.out.find("file:line:column: error|warning: message [hint]"), std::string::npos);
    CliRun hi = padrob("info --help");
    EXPECT_EQ(hi.status, 0);
    EXPECT_NE(hi.out.find("--json"), std::string::npos);
}

TEST(Cli, UsageErrorsExitTwo)
{
    EXPECT_EQ(padrob("").status, 2);
    CliRun u = padrob("frobnicate");
    EXPECT_EQ(u.status, 2);
    EXPECT_NE(u.err.find("unknown command 'frobnicate'"), std::string::npos);
    EXPECT_EQ(padrob("check").status, 2);
    EXPECT_EQ(padrob("check --bogus models/pendulum.pad").status, 2);
    EXPECT_EQ(padrob("info").status, 2);
    EXPECT_EQ(padrob("info a.pad b.pad").status, 2);
}

TEST(Cli, CheckUnreadableFilesExitTwo)
{
    CliRun missing = padrob("check /nonexistent/model.pad");
    EXPECT_EQ(missing.status, 2);
    EXPECT_EQ(missing.out.rfind("/nonexistent/model.pad: error: no such file [check the path]\n", 0), 0u) << missing.out;
    CliRun dir = padrob("check models");
    EXPECT_EQ(dir.status, 2);
    EXPECT_NE(dir.out.find("models: error: this is a folder, not a model file"), std::string::npos) << dir.out;
}

TEST(Cli, CheckReportsEveryErrorInCompilerFormat)
{
    const std::string path = writeTemp("bad.pad",
                                       "GRAVITY 0 0 -9.81\n"
                                       "B 1 2,5 1 1 1\n"
                                       "FOO 3\n"
                                       "C 1\n"
                                       "B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0\n"
                                       "B2 7 P2 0 0 0 A2 0 0 1 R2 0 1 0\n");
    CliRun r = padrob("check '" + path + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, path + ":2:5: error: body 1: '2,5' is not a number [use '.' as the decimal separator: 2.5]\n" +
                         path + ":3:1: error: unknown keyword 'FOO' [statements are GRAVITY, RESTITUTION, FLUID, PUMP, B, C (with B1, B2, CL1), D, F and G; "
                                "comments start with // or #]\n" +
                         path + ":6:4: error: joint 1: body 7 (B2) is not defined [add 'B 7 m Ixx Iyy Izz', or use an existing body]\n" +
                         path + ": 3 errors\n");
}

TEST(Cli, CheckAcceptsWarningsAndSeveralFiles)
{
    const std::string good = writeTemp("warn.pad",
                                       "B 1 1 0.1 0.1 0.5\n"
                                       "C 1\n"
                                       "B1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0\n"
                                       "B2 1 P2 0 0 0.5 A2 1 0 0 R2 0 1 0\n");
    CliRun r = padrob("check '" + good + "'");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find(good + ":1:7: warning: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(good + ": ok (1 warning)\n"), std::string::npos) << r.out;
    CliRun both = padrob("check '" + good + "' /nonexistent.pad");
    EXPECT_EQ(both.status, 2);
}

TEST(Cli, CheckBundledModelsHaveNoErrors)
{
    for (const auto& e : std::filesystem::directory_iterator(std::string(PADROB_SOURCE_DIR) + "/models")) {
        if (e.path().extension() != ".pad") continue;
        CliRun r = padrob("check '" + e.path().string() + "'");
        EXPECT_EQ(r.status, 0) << e.path() << "\n" << r.out;
        EXPECT_EQ(r.out.find(": error: "), std::string::npos) << r.out;
    }
}

TEST(Cli, InfoOnTheLinerManipulator)
{
    CliRun r = padrob("info models/liner_manipulator.pad");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("total mass 1314 kg"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Degrees of freedom: 9\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Loop-closure joints: none\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("LEVANTE PLUMA"), std::string::npos) << r.out;
    // the warnings go to stderr, in the compiler format
    EXPECT_NE(r.err.find("models/liner_manipulator.pad:"), std::string::npos);
    EXPECT_NE(r.err.find(": warning: body 3"), std::string::npos) << r.err;
}

TEST(Cli, InfoJsonIsStable)
{
    CliRun r = padrob("info --json models/liner_manipulator.pad");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.rfind("{\n  \"format\": \"padrob-info\",\n  \"version\": 1,\n  \"file\": \"models/liner_manipulator.pad\",", 0), 0u)
        << r.out.substr(0, 200);
    EXPECT_NE(r.out.find("\"dof\": 9,"), std::string::npos);
    EXPECT_NE(r.out.find("\"total_mass\": 1314,"), std::string::npos);
    EXPECT_NE(r.out.find("\"loop_closures\": [],"), std::string::npos);
    EXPECT_NE(r.out.find("\"type\": \"actuator\""), std::string::npos);
    EXPECT_EQ(r.err, "");
}

TEST(Cli, InfoOnALoopShowsDependentCoordinates)
{
    CliRun r = padrob("info --json models/four_bar.pad");
    ASSERT_EQ(r.status, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("\"dof\": 1,"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"role\": \"loop-closure\""), std::string::npos);
    EXPECT_NE(r.out.find("\"role\": \"dependent\""), std::string::npos);
}

TEST(Cli, InfoOnABrokenModelPrintsItsErrors)
{
    const std::string bad = writeTemp("broken.pad", "B 1 -5 1 1 1\n");
    CliRun r = padrob("info '" + bad + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find(bad + ":1:5: error: body 1 has a negative mass (-5 kg)"), std::string::npos) << r.err;
}

// ---- padrob simulate ---------------------------------------------------------


TEST(CliSimulate, HelpListsEveryOption)
{
    CliRun r = padrob("simulate --help");
    EXPECT_EQ(r.status, 0);
    for (const char* opt : {"--time", "--dt", "--integrator", "--rtol", "--input", "--set", "--rate", "--passive",
                            "--no-limits", "--every", "--out", "--weld", "--release", "--input-log", "--profile"}) {
        EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
    }
}

TEST(CliSimulate, LinerManipulatorColumnsInTheDocumentedOrder)
{
    CliRun r = padrob("simulate models/liner_manipulator.pad --time 0.01 --every 5");
    ASSERT_EQ(r.status, 0) << r.err;
    auto rows = lines(r.out);
    ASSERT_EQ(rows.size(), 4u);  // header, t = 0, 0.005, 0.01
    EXPECT_EQ(rows[0],
              "t,q1,q2,q3,q4,q5,q6,q7,q8,q9,qd1,qd2,qd3,qd4,qd5,qd6,qd7,qd8,qd9,ang2,ang5,"
              "x1,y1,z1,x2,y2,z2,x3,y3,z3,x4,y4,z4,x5,y5,z5,x6,y6,z6,x7,y7,z7,x8,y8,z8,x9,y9,z9,"
              "F1,F2,F3,F4,F5,F6,F7,F8,F9,E");
    EXPECT_EQ(rows[1].rfind("0,0,1.464,0,0,0.41", 0), 0u) << rows[1];
    EXPECT_EQ(rows[3].rfind("0.01,", 0), 0u) << rows[3];
    EXPECT_EQ(r.err, "");  // valves closed: no events
}

TEST(CliSimulate, InputsDriveTheCylindersAndEventsGoToStderr)
{
    const std::string input = writeTemp("in.csv", "t,u1,u2,u3,u4,u5,u6,u7,u8,u9\n0,0,0,1,0,0,0,0,0,0\n0.5,0,0,0,0,0,0,0,0,0\n");
    const std::string out = writeTemp("out.csv", "");
    CliRun r = padrob("simulate models/liner_manipulator.pad --time 1 --input '" + input + "' --out '" + out + "' --every 1000");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "t=0.000000 s: joint 3 EXTENSIÓN left its lower limit 0 m\n");
    auto rows = lines(slurp(out));
    ASSERT_EQ(rows.size(), 3u);
    // the telescope extends at its pump speed (0.0904 m/s) for 0.5 s, then holds
    const double vmax = 45e-6 * 1480 / 60 / (3.14159265358979 / 4 * 0.125 * 0.125);
    const std::string last = rows[2];
    std::vector<double> v;
    std::size_t p = 0;
    while (p <= last.size()) {
        std::size_t c = last.find(',', p);
        if (c == std::string::npos) c = last.size();
        v.push_back(std::stod(last.substr(p, c - p)));
        p = c + 1;
    }
    EXPECT_NEAR(v[3], 0.5 * vmax, 1e-9);  // q3
}

TEST(CliSimulate, FluidPowerColumnsAfterTheForces)
{
    // pA<j>,pB<j> per CYL/HMOTOR drive in joint id order, then pP<id> per pump, then E
    const std::string model = writeTemp("fluid.pad", R"pad(GRAVITY 0 0 -9.81
PUMP 4 FLOW 2e-3 PRESSURE 20e6 NAME "main"
B 1 1000 10 10 10
C 2 T 2 LL 0 UL 1 QI 0.3 NAME "lift"
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1
D 2 CYL PUMP 4 BORE 0.1 ROD 0.05 VALVE 1e-3 DP 1e6 COMP PRE DEAD 2e-4 3e-4
)pad");
    const std::string input = writeTemp("fluid_in.csv", "t,u2\n0,1\n");
    CliRun r = padrob("simulate '" + model + "' --time 1 --every 1000 --input '" + input + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    auto rows = lines(r.out);
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[0], "t,q2,qd2,x1,y1,z1,F2,pA2,pB2,pP4,E");
    // at rest: the holding pressure m·g/A_A; the pump at its setting
    EXPECT_NE(rows[1].find(",1249047.99338"), std::string::npos) << rows[1];
    EXPECT_NE(rows[1].find(",2e+07,"), std::string::npos) << rows[1];
    // lifting at Qn/A_A = 0.1273 m/s (compensated)
    const std::string last = rows[2];
    const double qd = std::stod(last.substr(last.find(',', last.find(',') + 1) + 1));
    EXPECT_NEAR(qd, 1e-3 / (3.14159265358979 / 4 * 0.01), 0.002);

    CliRun info = padrob("info --json '" + model + "'");
    ASSERT_EQ(info.status, 0) << info.err;
    std::string compact;  // (pretty-printed: compared without the white space)
    for (char c : info.out) {
        if (c != ' ' && c != '\n') compact += c;
    }
    for (const char* key : {"\"pumps\":", "\"circuits\":", "\"load_sensing\":false", "\"kind\":\"CYL\"",
                            "\"compensation\":\"PRE\"", "\"drives\":[2]"}) {
        EXPECT_NE(compact.find(key), std::string::npos) << key << "\n" << info.out;
    }
    // the text says the whole drive: its volumes and compensation too
    CliRun text = padrob("info '" + model + "'");
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_NE(text.out.find("CYL PUMP 4 BORE 0.1 ROD 0.05 VALVE 0.001 DP 1e+06 DEAD 0.0002 0.0003 COMP PRE"), std::string::npos) << text.out;
}

TEST(CliSimulate, LimitEventsAreReported)
{
    CliRun r = padrob("simulate models/incline_slider.pad --time 1.2 --every 1200");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("s: joint 1 slope hit its upper limit 2 m\n"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.rfind("t=0.903", 0), 0u) << r.err;
}

TEST(CliSimulate, SetAndRateOverrideTheInitialValues)
{
    CliRun r = padrob("simulate models/pendulum.pad --time 0.001 --set 1=0.5 --rate 1=2 --every 10");
    ASSERT_EQ(r.status, 0) << r.err;
    auto rows = lines(r.out);
    ASSERT_GE(rows.size(), 2u);
    EXPECT_EQ(rows[1].rfind("0,0.5,2,", 0), 0u) << rows[1];
}

// a free body (T 3): three columns per coordinate, its motion, its six degrees of
// freedom; --set and --rate cannot name it
TEST(CliSimulate, AFreeBodyHasThreeColumnsPerCoordinate)
{
    CliRun r = padrob("simulate models/tumbling_block.pad --time 3 --every 1000");
    ASSERT_EQ(r.status, 0) << r.err;
    auto rows = lines(r.out);
    ASSERT_EQ(rows.size(), 5u);
    EXPECT_EQ(rows[0], "t,q1x,q1y,q1z,qd1x,qd1y,qd1z,x1,y1,z1,E");
    for (std::size_t k = 1; k < rows.size(); ++k) {
        std::vector<double> v;
        std::size_t start = 0;
        while (start <= rows[k].size()) {
            const std::size_t comma = std::min(rows[k].find(',', start), rows[k].size());
            v.push_back(std::stod(rows[k].substr(start, comma - start)));
            start = comma + 1;
        }
        ASSERT_EQ(v.size(), 11u) << rows[k];
        for (int c = 1; c <= 6; ++c) EXPECT_NEAR(v[c], 0.0, 1e-9) << rows[k];  // the centre of mass stays
        EXPECT_NEAR(v[7], 0.0, 1e-9);
        EXPECT_NEAR(v[9], 1.0, 1e-9);
        if (v[0] > 0.6) {
            EXPECT_NEAR(v[10], 0.452673, 1e-6) << rows[k];  // L²/(2 I) (models/tumbling_block.pad)
        }
    }

    CliRun info = padrob("info models/tumbling_block.pad");
    EXPECT_EQ(info.status, 0) << info.err;
    EXPECT_NE(info.out.find("Degrees of freedom: 6"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find(" free "), std::string::npos) << info.out;
    EXPECT_NE(padrob("info --json models/tumbling_block.pad").out.find("\"dof\": 6"), std::string::npos);

    CliRun set = padrob("simulate models/tumbling_block.pad --time 1 --set 1=0.5");
    EXPECT_EQ(set.status, 2);
    EXPECT_NE(set.err.find("free joint (T 3)"), std::string::npos) << set.err;
    EXPECT_EQ(set.out, "");
}

TEST(CliSimulate, BadArgumentsExitTwoAndLeaveNoFile)
{
    const std::string out = (std::filesystem::temp_directory_path() / "padrob_sim_never.csv").string();
    std::filesystem::remove(out);
    struct Case {
        std::string args;
        std::string message;
    };
    const std::string model = "models/liner_manipulator.pad";
    const std::string missingT = writeTemp("missingt.csv", "u1\n0.5\n");
    const std::string missingCol = writeTemp("missing.csv", "t,u1,u2,u4,u5,u6,u7,u8,u9\n0,0,0,0,0,0,0,0,0\n");
    const std::string text = writeTemp("text.csv", "t,u1,u2,u3,u4,u5,u6,u7,u8,u9\n0,0,0,abc,0,0,0,0,0,0\n");
    const std::string unsorted = writeTemp("unsorted.csv", "t,u1,u2,u3,u4,u5,u6,u7,u8,u9\n1,0,0,0,0,0,0,0,0,0\n0.5,0,0,0,0,0,0,0,0,0\n");
    const std::string undriven = writeTemp("undriven.csv", "t,u1\n0,0.5\n");
    const std::vector<Case> cases = {
        {model + " --time 1 --dt 0", "--dt must be a positive number of seconds, not '0'"},
        {model + " --time 1 --dt -0.001", "--dt must be a positive number of seconds, not '-0.001'"},
        {model + " --time nan", "--time must be a positive number of seconds, not 'nan'"},
        {model, "--time is required"},
        {model + " --time 1 --integrator euler", "--integrator must be rk4 or adaptive, not 'euler'"},
        {model + " --time 1 --every 0", "--every must be a whole number ≥ 1, not '0'"},
        {model + " --time 1 --set 42=1", "--set: the model has no joint 42"},
        {model + " --time 1 --set 1", "--set takes J=VALUE (a joint id and a number), not '1'"},
        // checked as QI and VI in the file are
        {model + " --time 1 --set 1=1e308", "QI = 1e+308 is beyond any machine's"},
        {model + " --time 1 --set 1=nan", "--set takes J=VALUE (a joint id and a number), not '1=nan'"},
        {model + " --time 1 --rate 1=5", "VI = 5 is faster than its hydraulic drive can move it"},
        {model + " --time 1 --set 3=99", "is above the upper limit"},
        {model + " --time 1 --input " + missingT, "t"},
        {model + " --time 1 --input " + missingCol, "error: no column for joint 3's drive"},
        {model + " --time 1 --input " + text, "'abc' is not a number"},
        {model + " --time 1 --input " + unsorted, "0.5"},
        {"models/pendulum.pad --time 1 --input " + undriven, "joint 1"},
        {model + " --time 1 --input /nonexistent.csv", "/nonexistent.csv"},
    };
    for (const Case& c : cases) {
        CliRun r = padrob("simulate " + c.args + " --out '" + out + "'");
        EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.args;
        EXPECT_EQ(r.out, "") << c.args;
    }
}

TEST(CliSimulate, AnOutputThatCannotBeWrittenIsAUsageError)
{
    // the CSV writer's errors, printed from their translatable text: in English word for word
    const auto dir = std::filesystem::temp_directory_path() / "padrob_sim_out_folder";
    std::filesystem::create_directories(dir);
    const CliRun folder = padrob("simulate models/pendulum.pad --time 0.1 --out '" + dir.string() + "'");
    EXPECT_EQ(folder.status, 2) << folder.err;
    EXPECT_EQ(folder.err, "padrob simulate: cannot write " + dir.string() + ": it is a folder\n");
    EXPECT_EQ(folder.out, "");
    const std::string missing = (dir / "no such folder" / "out.csv").string();
    const CliRun create = padrob("simulate models/pendulum.pad --time 0.1 --out '" + missing + "'");
    EXPECT_EQ(create.status, 2) << create.err;
    EXPECT_EQ(create.err, "padrob simulate: cannot create " + missing + ": No such file or directory\n");
    std::filesystem::remove_all(dir);
}

TEST(CliSimulate, ADivergingSimulationFailsWithoutOutput)
{
    const std::string model = writeTemp("stiff.pad",
                                        "B 1 1 0.1 0.1 0.1\n"
                                        "C 7 T 2 QI 0.1 NAME \"slider\"\n"
                                        "B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1\n"
                                        "B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1\n"
                                        "F 1 SPRING B1 0 P1 0 0 -1 B2 1 P2 0 0 0 K 1e12 L0 1\n");
    const std::string out = (std::filesystem::temp_directory_path() / "padrob_sim_diverge.csv").string();
    std::filesystem::remove(out);
    CliRun r = padrob("simulate '" + model + "' --time 100 --dt 0.01 --out '" + out + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("padrob simulate: the simulation failed at t = "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("joint 7 (slider)"), std::string::npos) << r.err;
    // the likely cause, and what to do
    EXPECT_NE(r.err.find("the likely cause: spring force 1 (K = 1e+12 N/m on a body of 1 kg"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("run it again with a smaller --dt (now 0.01 s; e.g. --dt 0.001) or with --integrator adaptive"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

namespace {

/// A CSV of numbers with a header, parsed.
struct Csv {
    std::vector<std::string> header;
    std::vector<std::vector<double>> rows;

    std::size_t column(const std::string& name) const
    {
        for (std::size_t c = 0; c < header.size(); ++c) {
            if (header[c] == name) return c;
        }
        ADD_FAILURE() << "no column " << name;
        return 0;
    }
    double at(std::size_t row, const std::string& name) const { return rows.at(row).at(column(name)); }
    /// The row whose t is `t` (to 1e-9).
    std::size_t rowAt(double t) const
    {
        for (std::size_t r = 0; r < rows.size(); ++r) {
            if (std::abs(rows[r][0] - t) < 1e-9) return r;
        }
        ADD_FAILURE() << "no row at t = " << t;
        return 0;
    }
};

Csv parseCsv(const std::string& text)
{
    auto split = [](const std::string& line) {
        std::vector<std::string> fields;
        std::size_t p = 0;
        while (p <= line.size()) {
            std::size_t c = line.find(',', p);
            if (c == std::string::npos) c = line.size();
            fields.push_back(line.substr(p, c - p));
            p = c + 1;
        }
        return fields;
    };
    Csv csv;
    auto ls = lines(text);
    if (ls.empty()) return csv;
    csv.header = split(ls[0]);
    for (std::size_t i = 1; i < ls.size(); ++i) {
        std::vector<double> row;
        for (const std::string& f : split(ls[i])) row.push_back(std::stod(f));
        EXPECT_EQ(row.size(), csv.header.size()) << ls[i];
        csv.rows.push_back(std::move(row));
    }
    return csv;
}

}  // namespace

TEST(CliSimulate, ClosedLoopModelsSimulate)
{
    // four-bar: the motor at full command turns the crank; the coupler's centre of
    // mass stays midway between the crank pin A and the rocker pin B (the loop closes)
    const std::string input = writeTemp("four_bar_in.csv", "t,u1\n0,1\n");
    CliRun fb = padrob("simulate models/four_bar.pad --time 1 --input '" + input + "'");
    ASSERT_EQ(fb.status, 0) << fb.err;
    Csv four = parseCsv(fb.out);
    ASSERT_EQ(four.rows.size(), 1001u);
    EXPECT_EQ(four.header.front(), "t");
    EXPECT_EQ(four.rows.back()[0], 1.0);
    EXPECT_GT(four.rows.back()[four.column("q1")], four.rows.front()[four.column("q1")] + 0.5);
    for (std::size_t r : {std::size_t(0), std::size_t(500), four.rows.size() - 1}) {
        const double ax = 2 * four.at(r, "x1"), ay = 2 * four.at(r, "y1");  // crank: O2 at the origin
        const double bx = 2 * four.at(r, "x3") - 0.4, by = 2 * four.at(r, "y3");  // rocker: O4 = (0.4, 0)
        EXPECT_NEAR(four.at(r, "x2"), (ax + bx) / 2, 1e-6) << "t = " << four.rows[r][0];
        EXPECT_NEAR(four.at(r, "y2"), (ay + by) / 2, 1e-6) << "t = " << four.rows[r][0];
        EXPECT_NEAR(std::hypot(bx - ax, by - ay), 0.35, 1e-6);
    }

    // slider-crank, turning at its initial rate: the piston follows
    // x_B = r cos θ2 + √(l² − r² sin² θ2)
    CliRun sc = padrob("simulate models/slider_crank.pad --time 1");
    ASSERT_EQ(sc.status, 0) << sc.err;
    Csv slider = parseCsv(sc.out);
    ASSERT_EQ(slider.rows.size(), 1001u);
    EXPECT_EQ(slider.rows.back()[0], 1.0);
    for (std::size_t r = 0; r < slider.rows.size(); r += 100) {
        const double th = slider.at(r, "q1"), rr = 0.1, l = 0.35;
        EXPECT_NEAR(slider.at(r, "x3"), rr * std::cos(th) + std::sqrt(l * l - rr * rr * std::sin(th) * std::sin(th)), 1e-6)
            << "t = " << slider.rows[r][0];
    }
}

TEST(CliSimulate, ALoopDrivenToItsDeadCentreLocksUp)
{
    // the slider-crank's piston pushed by a cylinder at 0.1 m/s from x = 0.39 m toward
    // the dead centre x = 0.45 m (crank and rod in line), reached at t = 0.6 s
    std::string text = slurp(std::string(PADROB_SOURCE_DIR) + "/models/slider_crank.pad");
    const std::string c4 = "C 4 T 2 QI 0.39 NAME \"cylinder\"";
    ASSERT_NE(text.find(c4), std::string::npos);
    text.replace(text.find(c4), c4.size(), "C 4 T 2 QI 0.39 LL 0.2 UL 0.46 NAME \"cylinder\"");
    const std::size_t motor = text.find("D 1 MOTOR");
    ASSERT_NE(motor, std::string::npos);
    text.erase(motor, text.find('\n', motor) + 1 - motor);
    text += "D 4 HYD VMAX 0.1\n";
    const std::string model = writeTemp("slider_crank_lock.pad", text);
    const std::string input = writeTemp("slider_crank_lock.csv", "t,u4\n0,1\n");
    const std::string out = (std::filesystem::temp_directory_path() / "padrob_sim_lock.csv").string();
    std::filesystem::remove(out);
    CliRun r = padrob("simulate '" + model + "' --time 1 --input '" + input + "' --out '" + out + "'");
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("locked up"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.rfind("t=0.600000 s: ", 0), 0u) << r.err;  // the event line, first
    EXPECT_NE(r.err.find("padrob simulate: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("0.6 s"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliSimulate, WeldAndReleaseHoldTheRelativePose)
{
    // double pendulum: bob 2 welded to bob 1 from 0.5 s to 1 s swings with it rigidly
    CliRun r = padrob("simulate models/double_pendulum.pad --time 1.5 --weld 0.5:1:2 --release 1:1:2");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "t=0.500000 s: body 2 bob 2 welded to body 1 bob 1\n"
                     "t=1.000000 s: body 2 bob 2 released from body 1 bob 1\n");
    Csv csv = parseCsv(r.out);
    ASSERT_EQ(csv.rows.size(), 1501u);
    const std::size_t w = csv.rowAt(0.5), rel = csv.rowAt(1.0);
    const double q2 = csv.at(w, "q2");
    EXPECT_NE(q2, csv.at(w - 1, "q2"));  // it moved before
    for (std::size_t k = w; k <= rel; ++k) {
        EXPECT_NEAR(csv.at(k, "q2"), q2, 1e-9) << "t = " << csv.rows[k][0];
        EXPECT_NEAR(csv.at(k, "qd2"), 0, 1e-9) << "t = " << csv.rows[k][0];
    }
    EXPECT_GT(std::abs(csv.at(rel, "q1") - csv.at(w, "q1")), 0.01);  // the pair kept swinging
    EXPECT_GT(std::abs(csv.rows.back()[csv.column("q2")] - q2), 1e-3);  // free again after the release

    // a weld between output rows (--dt 0.01, T = 0.505): the run stops there, the
    // rows stay on the --dt grid; at one T the switches apply in the order given
    CliRun off = padrob("simulate models/double_pendulum.pad --time 0.6 --dt 0.01 --weld 0.505:1:2 "
                        "--release 0.52:1:2 --weld 0.52:0:1");
    ASSERT_EQ(off.status, 0) << off.err;
    EXPECT_EQ(off.err, "t=0.505000 s: body 2 bob 2 welded to body 1 bob 1\n"
                       "t=0.520000 s: body 2 bob 2 released from body 1 bob 1\n"
                       "t=0.520000 s: body 1 bob 1 welded to the ground\n");
    Csv grid = parseCsv(off.out);
    ASSERT_EQ(grid.rows.size(), 61u);
    for (std::size_t k = 0; k < grid.rows.size(); ++k) EXPECT_NEAR(grid.rows[k][0], 0.01 * static_cast<double>(k), 1e-12);
    const std::size_t r50 = grid.rowAt(0.5), r51 = grid.rowAt(0.51), r52 = grid.rowAt(0.52);
    EXPECT_NE(grid.at(r50, "q2"), grid.at(r51, "q2"));  // the weld came after the row at 0.5
    EXPECT_NEAR(grid.at(r52, "q2"), grid.at(r51, "q2"), 1e-9);
    for (std::size_t k = r52; k < grid.rows.size(); ++k) {  // bob 1 held by the ground, bob 2 free
        EXPECT_NEAR(grid.at(k, "q1"), grid.at(r52, "q1"), 1e-9) << "t = " << grid.rows[k][0];
    }
    EXPECT_GT(std::abs(grid.rows.back()[grid.column("q2")] - grid.at(r52, "q2")), 1e-3);

    // the same switches the other way round: bob 1 is still welded to bob 2
    const std::string out = (std::filesystem::temp_directory_path() / "padrob_sim_weld_order.csv").string();
    std::filesystem::remove(out);
    CliRun rev = padrob("simulate models/double_pendulum.pad --time 0.6 --dt 0.01 --weld 0.505:1:2 "
                        "--weld 0.52:0:1 --release 0.52:1:2 --out '" + out + "'");
    EXPECT_EQ(rev.status, 1);
    EXPECT_NE(rev.err.find("padrob simulate: --weld '0.52:0:1': cannot weld body 1 bob 1 to the ground: "
                           "body 1 bob 1 is already welded"),
              std::string::npos) << rev.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliSimulate, BadWeldsAreUsageErrors)
{
    const std::string out = (std::filesystem::temp_directory_path() / "padrob_sim_weld_never.csv").string();
    std::filesystem::remove(out);
    struct Case {
        std::string args;
        std::string message;
    };
    const std::string model = "models/double_pendulum.pad --time 1";
    const std::vector<Case> cases = {
        {model + " --weld", "--weld needs a value"},
        {model + " --weld 0.5", "--weld takes T:A:B: a time [s] and two body ids, to weld body B to body A (0 = the ground), "
                                "e.g. 0.5:0:2; not '0.5'"},
        {model + " --weld 0.5:1", "--weld takes T:A:B"},
        {model + " --weld 0.5:1:2:3", "--weld takes T:A:B"},
        {model + " --weld x:1:2", "--weld takes T:A:B"},
        {model + " --weld 0.5:one:2", "--weld takes T:A:B"},
        {model + " --release 0.5:1:", "--release takes T:A:B"},
        {model + " --weld -0.5:1:2", "--weld '-0.5:1:2': the time must be a finite number of seconds ≥ 0"},
        {model + " --weld inf:1:2", "--weld 'inf:1:2': the time must be a finite number of seconds ≥ 0"},
        {model + " --release nan:1:2", "--release 'nan:1:2': the time must be a finite number of seconds ≥ 0"},
        {model + " --weld 1.5:1:2", "--weld '1.5:1:2': the time is after the end of the simulation (--time 1 s)"},
        {"models/double_pendulum.pad --release 2:1:2 --time 1", "--release '2:1:2': the time is after the end"},
        {model + " --weld 0.5:1:7", "--weld '0.5:1:7': the model has no body 7; its bodies are 0 (the ground), 1, 2"},
        {model + " --release 0.5:9:2", "--release '0.5:9:2': the model has no body 9; its bodies are 0 (the ground), 1, 2"},
        {model + " --weld 0.5:2:2", "--weld '0.5:2:2': cannot weld a body to itself"},
        {model + " --release 0.5:1:1", "--release '0.5:1:1': cannot release a body from itself"},
        {model + " --weld 0.5:1:0", "--weld '0.5:1:0': the ground cannot be welded to a body: put the ground as A, '0.5:0:1'"},
        {model + " --release 0.5:2:0", "--release '0.5:2:0': the ground is never the welded body B"},
    };
    for (const Case& c : cases) {
        CliRun r = padrob("simulate --out '" + out + "' " + c.args);
        EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
        EXPECT_EQ(r.err.rfind("padrob simulate: " + c.message, 0), 0u) << c.args << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.args;
        EXPECT_EQ(r.out, "") << c.args;
    }
    // errors that depend on the run: exit 1 with the simulation's reason, no file left
    const std::vector<Case> runtime = {
        {model + " --release 0.5:1:2", "padrob simulate: --release '0.5:1:2': cannot release: body 2 bob 2 is not welded "
                                       "to body 1 bob 1\n"},
        {model + " --weld 0.2:1:2 --release 0.4:1:2 --release 0.6:1:2",
         "padrob simulate: --release '0.6:1:2': cannot release: body 2 bob 2 is not welded to body 1 bob 1\n"},
        {model + " --weld 0.5:1:2 --weld 0.7:0:2",
         "padrob simulate: --weld '0.7:0:2': cannot weld body 2 bob 2 to the ground: body 2 bob 2 is already welded "
         "(release that weld first)\n"},
    };
    for (const Case& c : runtime) {
        CliRun r = padrob("simulate --out '" + out + "' " + c.args);
        EXPECT_EQ(r.status, 1) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.args;
    }
}

namespace {

/// A model with two bodies drawn by solids, comments and a NAME on the B lines.
std::string inertiaModel()
{
    return "// inertia test model\n"
           "B 1 10 1 1 1 NAME \"arm\"   // the arm\n"
           "B 2 5 0.1 0.1 0.1\n"
           "C 1\n"
           "B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0\n"
           "B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0\n"
           "C 2\n"
           "B1 1 P1 0 1 0 A1 0 0 1 R1 0 1 0\n"
           "B2 2 P2 0 0 0 A2 0 0 1 R2 0 1 0\n"
           "G 1 B 1 BOX 0.2 0.4 0.6 RHO 1000 POS 0 0.1 0  # 48 kg\n"
           "G 2 B 2 SPHERE 0.1 MASS 5\n";
}

}  // namespace

TEST(CliInertia, PrintsComputedBesideWrittenLines)
{
    const std::string model = writeTemp("inertia_print.pad", inertiaModel());
    CliRun r = padrob("inertia '" + model + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    // box 0.2 × 0.4 × 0.6 m, 1000 kg/m³: 48 kg, Ixx = 2.08, Iyy = 1.6, Izz = 0.8; sphere: 0.4·5·0.01 = 0.02
    EXPECT_NE(r.out.find("body 1 \"arm\"\n  file:      B 1 10 1 1 1 NAME \"arm\"   // the arm\n"
                         "  computed:  B 1 48 2.08 1.6 0.8 0 0 0 CG 0 0.1 0\n"
                         "  difference: m +380.00%  Ixx +108.00%  Iyy +60.00%  Izz -20.00%\n"),
              std::string::npos) << r.out;
    EXPECT_NE(r.out.find("  computed:  B 2 5 0.02 0.02 0.02 0 0 0 CG 0 0 0\n"), std::string::npos) << r.out;
    EXPECT_EQ(slurp(model), inertiaModel());  // printing changes nothing
    CliRun one = padrob("inertia '" + model + "' --body 2");
    EXPECT_EQ(one.status, 0);
    EXPECT_EQ(one.out.find("body 1"), std::string::npos) << one.out;
    EXPECT_NE(one.out.find("body 2"), std::string::npos) << one.out;
    EXPECT_FALSE(std::filesystem::exists(model + ".bak"));
}

TEST(CliInertia, WriteKeepsEverythingElseAndMakesABackup)
{
    const std::string model = writeTemp("inertia_write.pad", inertiaModel());
    std::filesystem::remove(model + ".bak");
    namespace fs = std::filesystem;
    fs::permissions(model, fs::perms::owner_read | fs::perms::owner_write);  // a model kept private
    CliRun r = padrob("inertia '" + model + "' --write");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(fs::status(model).permissions() & fs::perms::mask, fs::perms::owner_read | fs::perms::owner_write);
    std::vector<std::string> left;  // the model, its backup, nothing else of it
    for (const auto& e : fs::directory_iterator(fs::path(model).parent_path()))
        if (e.path().filename().string().find("inertia_write") != std::string::npos) left.push_back(e.path().filename().string());
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::string>{"inertia_write.pad", "inertia_write.pad.bak"}));
    EXPECT_NE(r.out.find("Wrote 2 B lines to " + model), std::string::npos) << r.out;
    EXPECT_EQ(slurp(model + ".bak"), inertiaModel());
    std::string want = inertiaModel();
    const std::string oldArm = "B 1 10 1 1 1 NAME \"arm\"   // the arm";
    want.replace(want.find(oldArm), oldArm.size(), "B 1 48 2.08 1.6 0.8 0 0 0 CG 0 0.1 0 NAME \"arm\"  // the arm");
    want.replace(want.find("B 2 5 0.1 0.1 0.1"), 17, "B 2 5 0.02 0.02 0.02 0 0 0 CG 0 0 0");
    EXPECT_EQ(slurp(model), want);
    EXPECT_EQ(padrob("check '" + model + "'").status, 0);
    // a second run finds nothing to change
    CliRun again = padrob("inertia '" + model + "'");
    EXPECT_NE(again.out.find("  difference: m +0.00%  Ixx +0.00%  Iyy +0.00%  Izz +0.00%\n"), std::string::npos) << again.out;
}

TEST(CliInertia, ErrorsLeaveTheFileAlone)
{
    // a model with errors: exit 1, untouched, no backup
    const std::string bad = writeTemp("inertia_bad.pad", inertiaModel() + "G 3 B 1 BOX 1 1 1 RHO -5\n");
    std::filesystem::remove(bad + ".bak");
    CliRun r = padrob("inertia '" + bad + "' --write");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find(bad + ":12:"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(bad), inertiaModel() + "G 3 B 1 BOX 1 1 1 RHO -5\n");
    EXPECT_FALSE(std::filesystem::exists(bad + ".bak"));
    // an open mesh: the error names the open edges, at the statement
    const std::string mesh = writeTemp("inertia_open.stl",
                                       "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
                                       " endloop\nendfacet\nendsolid t\n");
    const std::string open = writeTemp("inertia_open.pad", inertiaModel() + "G 3 B 1 MESH \"inertia_open.stl\" RHO 1\n");
    CliRun o = padrob("inertia '" + open + "' --write");
    EXPECT_EQ(o.status, 1);
    EXPECT_NE(o.err.find(open + ":12:14: error: graphic 3: the mesh is not closed: 3 open edges"), std::string::npos) << o.err;
    EXPECT_FALSE(std::filesystem::exists(open + ".bak"));
    // usage errors
    const std::string model = writeTemp("inertia_usage.pad", inertiaModel());
    EXPECT_EQ(padrob("inertia").status, 2);
    EXPECT_EQ(padrob("inertia '" + model + "' --bogus").status, 2);
    EXPECT_EQ(padrob("inertia '" + model + "' --body").status, 2);
    EXPECT_EQ(padrob("inertia '" + model + "' --body x").status, 2);
    CliRun nb = padrob("inertia '" + model + "' --body 9");
    EXPECT_EQ(nb.status, 2);
    EXPECT_NE(nb.err.find("--body: the model has no body 9"), std::string::npos) << nb.err;
    EXPECT_EQ(padrob("inertia /nonexistent.pad").status, 2);
    CliRun h = padrob("inertia --help");
    EXPECT_EQ(h.status, 0);
    EXPECT_NE(h.out.find("--write"), std::string::npos);
    EXPECT_NE(padrob("--help").out.find("inertia MODEL [--body I] [--write]"), std::string::npos);
    // a model without solids: nothing to compute
    CliRun none = padrob("inertia models/pendulum.pad");
    EXPECT_EQ(none.status, 0);
    EXPECT_NE(none.out.find("nothing to compute"), std::string::npos) << none.out;
}

namespace {

const char* kKeyboardLogHead =
    "# padrob input log 1\n"
    "#device 0 {\"id\":\"keyboard\",\"name\":\"Keyboard\",\"kind\":\"keyboard\",\"axes\":["
    "{\"name\":\"Q / A\",\"min\":-1,\"rest\":0,\"max\":1},{\"name\":\"W / S\",\"min\":-1,\"rest\":0,\"max\":1},"
    "{\"name\":\"E / D\",\"min\":-1,\"rest\":0,\"max\":1}],\"buttons\":[]}\n";

}  // namespace

TEST(CliSimulate, AnInputLogReplaysThroughTheProfileLikeTheSameCommands)
{
    // the keyboard's third pair (E / D) held from 0.1 s to 0.6 s: with the profile made
    // for the model it is drive C 3, so the run equals --input with u3 = 1 then
    const std::string log = writeTemp("keys.log", std::string(kKeyboardLogHead) +
                                                      "0,0,0,0,0\n0.1,0,0,0,1\n0.6,0,0,0,0\n");
    const std::string csv = writeTemp("keys.csv", "t,u1,u2,u3,u4,u5,u6,u7,u8,u9\n0,0,0,0,0,0,0,0,0,0\n"
                                                   "0.1,0,0,1,0,0,0,0,0,0\n0.6,0,0,0,0,0,0,0,0,0\n");
    CliRun replay = padrob("simulate models/liner_manipulator.pad --time 1 --every 50 --input-log '" + log + "'");
    ASSERT_EQ(replay.status, 0) << replay.err;
    CliRun table = padrob("simulate models/liner_manipulator.pad --time 1 --every 50 --input '" + csv + "'");
    ASSERT_EQ(table.status, 0) << table.err;
    EXPECT_EQ(replay.out, table.out);
    EXPECT_EQ(replay.err, table.err);
    const auto rows = lines(replay.out);
    ASSERT_EQ(rows.size(), 22u);
    EXPECT_NE(rows[1], rows[21]);  // it moved
}

TEST(CliSimulate, AGamepadLogDrivesTheShippedGamepadProfileByName)
{
    // left stick pulled back from 0.1 s to 0.5 s: bank Boom lifts C 2 (18 mm/s)
    std::string head = "# padrob input log 1\n#device 0 {\"id\":\"sdl:0300abcd\",\"name\":\"Pad\",\"kind\":\"gamepad\","
                       "\"axes\":[";
    const char* axes[] = {"leftx", "lefty", "rightx", "righty", "lefttrigger", "righttrigger"};
    for (int a = 0; a < 6; ++a)
        head += std::string(a ? "," : "") + "{\"name\":\"" + axes[a] + "\",\"min\":" + (a < 4 ? "-32768" : "0") +
                ",\"rest\":0,\"max\":32767}";
    head += "],\"buttons\":[\"a\",\"b\",\"x\",\"y\"]}\n";
    const std::string log =
        writeTemp("pad.log", head + "0,0,0,0,0,0,0,0,0,0,0,0\n0.1,0,0,32767,0,0,0,0,0,0,0,0\n0.5,0,0,0,0,0,0,0,0,0,0,0\n");
    CliRun r = padrob("simulate models/liner_manipulator.pad --time 0.6 --every 100 --input-log '" + log +
                      "' --profile Gamepad");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = lines(r.out);
    ASSERT_EQ(rows.size(), 8u);
    auto column = [](const std::string& row, int c) {
        std::size_t p = 0;
        for (int i = 0; i < c; ++i) p = row.find(',', p) + 1;
        return std::stod(row.substr(p));
    };
    const double vmax = 45e-6 * 1480 / 60 / (3.14159265358979 / 4 * 0.28 * 0.28);
    EXPECT_NEAR(column(rows[7], 2) - column(rows[1], 2), 0.4 * vmax, 0.05 * vmax);  // q2
}

TEST(CliSimulate, BadInputLogsAndProfilesExitTwo)
{
    const std::string bad = writeTemp("bad.log", std::string(kKeyboardLogHead) + "0,0,0,0,0\n0.5,0,1\n");
    CliRun r = padrob("simulate models/liner_manipulator.pad --time 1 --input-log '" + bad + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("line 4"), std::string::npos) << r.err;
    const std::string good = writeTemp("good.log", std::string(kKeyboardLogHead) + "0,0,0,0,0\n");
    r = padrob("simulate models/liner_manipulator.pad --time 1 --input-log '" + good + "' --profile Nonexistent");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("Nonexistent"), std::string::npos) << r.err;
    const std::string future = writeTemp("future.json", "{\"format\":\"padrob-station-profile\",\"version\":5,\"name\":\"x\"}");
    r = padrob("simulate models/liner_manipulator.pad --time 1 --input-log '" + good + "' --profile '" + future + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("newer"), std::string::npos) << r.err;
    r = padrob("simulate models/liner_manipulator.pad --time 1 --input-log '" + good + "' --input x.csv");
    EXPECT_EQ(r.status, 2);
    r = padrob("simulate models/liner_manipulator.pad --time 1 --profile Gamepad");
    EXPECT_EQ(r.status, 2);
}
