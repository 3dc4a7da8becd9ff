// The `padrob` command line through its real binary: output, exit codes, help.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>

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
                         path + ":3:1: error: unknown keyword 'FOO' [statements are GRAVITY, B, C (with B1, B2, CL1), D, F and G; "
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
