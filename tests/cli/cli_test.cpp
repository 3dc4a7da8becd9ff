// The `padrob` command line through its real binary: output, exit codes, help.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

struct CliRun {
    int status = -1;
    std::string out;  // stdout
    std::string err;  // stderr
};

std::string slurp(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Runs `padrob ARGS` in the source tree; captures stdout, stderr and the exit status.
CliRun padrob(const std::string& args)
{
    static int counter = 0;
    const auto dir = std::filesystem::temp_directory_path() / ("padrob_cli_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string errFile = (dir / ("err" + std::to_string(counter++))).string();
    const std::string cmd = std::string("cd '") + PADROB_SOURCE_DIR + "' && '" + PADROB_CLI + "' " + args + " 2>'" + errFile + "'";
    CliRun r;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf;
    std::size_t n;
    while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
    int st = pclose(p);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.err = slurp(errFile);
    std::filesystem::remove(errFile);
    return r;
}

std::string writeTemp(const std::string& name, const std::string& text)
{
    const auto dir = std::filesystem::temp_directory_path() / ("padrob_cli_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto path = dir / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

}  // namespace

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
                         path + ":3:1: error: unknown keyword 'FOO' [statements are GRAVITY, RESTITUTION, B, C (with B1, B2, CL1), D, F and G; "
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

namespace {

std::vector<std::string> lines(const std::string& s)
{
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < s.size()) {
        std::size_t nl = s.find('\n', start);
        if (nl == std::string::npos) nl = s.size();
        out.push_back(s.substr(start, nl - start));
        start = nl + 1;
    }
    return out;
}

}  // namespace

TEST(CliSimulate, HelpListsEveryOption)
{
    CliRun r = padrob("simulate --help");
    EXPECT_EQ(r.status, 0);
    for (const char* opt : {"--time", "--dt", "--integrator", "--rtol", "--input", "--set", "--rate", "--passive",
                            "--no-limits", "--every", "--out"}) {
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
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliSimulate, ModelsWithLoopsAreRefusedClearly)
{
    CliRun r = padrob("simulate models/four_bar.pad --time 1");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("closes a loop: closed loops are not simulated yet"), std::string::npos) << r.err;
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
    CliRun r = padrob("inertia '" + model + "' --write");
    EXPECT_EQ(r.status, 0) << r.err;
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
