// `padrob export --mjcf` through the real binary: the MJCF on standard output or in a
// file (atomically), loops and bad arguments refused, and --check (MuJoCo against
// Padrob) on every bundled tree model when the binary has MuJoCo.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "tests/common/components.h"
#include "cli_run.h"

using namespace test;

namespace {

namespace fs = std::filesystem;

/// A fresh empty folder for output files.
fs::path outDir(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("padrob_export_test_" + std::to_string(::getpid())) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::vector<std::string> listing(const fs::path& dir)
{
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    return names;
}

/// Whether the build that made the binary found MuJoCo: its CMakeCache.txt (next to
/// bin/padrob's folder) has PADROB_WITH_MUJOCO on and a mujoco_DIR that was found.
/// Used so that --check is required, not skipped, in a build with MuJoCo.
bool buildHasMujoco()
{
    const fs::path cache = fs::path(PADROB_CLI).parent_path().parent_path() / "CMakeCache.txt";
    const std::string text = slurp(cache.string());
    if (text.find("PADROB_WITH_MUJOCO:BOOL=OFF") != std::string::npos) return false;
    const std::size_t at = text.find("mujoco_DIR:PATH=");
    if (at == std::string::npos) return false;
    const std::string value = text.substr(at + 16, text.find('\n', at) - at - 16);
    return value.find("NOTFOUND") == std::string::npos && !value.empty();
}

/// A tree that exercises what the bundled models do not: joints written child →
/// parent, products of inertia, centres of mass off the frame origin, a massless
/// body, an inertia breaking the triangle inequality off the body axes, tilted
/// gravity, T 1 and T 2 joints, an initial rate, a drive and an applied force.
const char* const kTreeZoo = R"(GRAVITY 0.4 -0.3 -9.81
B 1 5.0 0.20 0.30 0.25 0.010 -0.020 0.015 CG 0.10 -0.05 0.20 NAME "column"
B 2 NAME "massless yoke"
B 3 3.0 0.10 0.12 0.08 0.005 0.000 -0.010 CG 0.00 0.30 0.05 NAME "arm"
B 4 2.0 0.1 0.1 0.5 0.02 0 0 CG 0.02 0.01 -0.10 NAME "flat, rotated"
B 5 1.5 0.02 0.03 0.025 0.001 0.002 0.003 NAME "slide"
C 1 VI 0.4 NAME "slew"
B1 0 P1 0.1 0.2 0.5 A1 0 0.2 1 R1 1 0 0
B2 1 P2 0 0 -0.3 A2 0 0 1 R2 1 0 0
C 2 NAME "yoke, written child to parent"
B1 2 P1 0 -0.2 0 A1 1 0 0 R1 0 1 0
B2 1 P2 0.2 0.1 0.3 A2 1 0 0 R2 0 0 1
C 3 T 1 LL 0.91 UL 0.96 VI 0.01 NAME "cylinder"
B1 2 P1 0 0.6 0 A1 0 1 0 R1 1 0 0
B2 3 P2 0 -0.3 0 A2 0 1 0 R2 1 0 0
CL1 0.2 0 -0.1 CL2 -0.1 0 -0.08
C 4 QI 0.3 NAME "wrist"
B1 3 P1 0.1 0.2 0 A1 0 0 1 R1 1 0 0
B2 4 P2 -0.1 0 0 A2 0 0 1 R2 0 1 0
C 5 T 2 LL -0.2 UL 0.4 QI 0.1 NAME "slide, written child to parent"
B1 5 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0.3 0 0.1 A2 0 0 1 R2 1 1 0
D 5 PNEU F 30
F 1 POINT B 3 P 0 0 0 DIR 0 0 1 MAG 10
)";

}  // namespace

TEST(CliExport, Help)
{
    CliRun h = padrob("export --help");
    EXPECT_EQ(h.status, 0);
    EXPECT_EQ(h.out.rfind("Usage: padrob export --mjcf MODEL", 0), 0u) << h.out;
    for (const char* option : {"--out FILE", "--dt H", "--check", "Exit status"}) {
        EXPECT_NE(h.out.find(option), std::string::npos) << option;
    }
    EXPECT_EQ(h.err, "");
}

TEST(CliExport, PendulumToStandardOutput)
{
    CliRun r = padrob("export --mjcf models/pendulum.pad");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out.rfind("<!--", 0), 0u);
    EXPECT_NE(r.out.find("model models/pendulum.pad as MuJoCo MJCF"), std::string::npos);
    EXPECT_NE(r.out.find("<mujoco model=\"pendulum\">"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("<option timestep=\"0.001\" gravity=\"0 0 -9.81\" integrator=\"RK4\">"), std::string::npos);
    EXPECT_NE(r.out.find("<body name=\"bob\" pos=\"0 0 -1\">"), std::string::npos);
    EXPECT_NE(r.out.find("<joint name=\"pivot\" type=\"hinge\" pos=\"0 0 1\" axis=\"1 0 0\"/>"), std::string::npos);
    EXPECT_NE(r.out.find("<key name=\"initial\" qpos=\"0.1\" qvel=\"0\"/>"), std::string::npos);
    const std::string end = "</mujoco>\n";
    ASSERT_GE(r.out.size(), end.size());
    EXPECT_EQ(r.out.substr(r.out.size() - end.size()), end);

    CliRun dt = padrob("export models/pendulum.pad --dt 0.0005 --mjcf");
    EXPECT_EQ(dt.status, 0) << dt.err;
    EXPECT_NE(dt.out.find("timestep=\"5e-04\""), std::string::npos) << dt.out;
}

// a free joint (T 3) becomes a freejoint on a body of the world, posed where it starts;
// the keyframe holds its position and quaternion; on a moving body it is refused
TEST(CliExport, AFreeBodyIsAFreejointOnTheWorld)
{
    CliRun r = padrob("export --mjcf models/tumbling_block.pad");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("<body name=\"block\" pos=\"0 0 1\">"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("<freejoint name=\"free\"/>"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("<key name=\"initial\" qpos=\"0 0 1 1 0 0 0\" qvel=\"0 0 0 0 0 0\"/>"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("1 free joint)"), std::string::npos) << r.out;

    const std::string onArm = writeTemp("free_on_arm.pad", R"(B 1 1 1 1 1
B 2 1 0.1 0.1 0.1
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2 T 3
B1 1 P1 1 0 0 A1 1 0 0 R1 0 1 0
B2 2 P2 0 0 0 A2 1 0 0 R2 0 1 0
)");
    CliRun refused = padrob("export --mjcf '" + onArm + "'");
    EXPECT_NE(refused.status, 0);
    EXPECT_NE(refused.err.find("MuJoCo allows a free joint only on a body of the world"), std::string::npos)
        << refused.err;
    EXPECT_EQ(refused.out, "");
}

TEST(CliExport, OutWritesTheFileWhole)
{
    const fs::path dir = outDir("out");
    const fs::path file = dir / "liner.xml";
    CliRun r = padrob("export --mjcf models/liner_manipulator.pad --out '" + file.string() + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "");
    CliRun stdoutRun = padrob("export --mjcf models/liner_manipulator.pad");
    EXPECT_EQ(slurp(file.string()), stdoutRun.out);
    EXPECT_NE(stdoutRun.out.find("placeholder mass 1e-09 kg"), std::string::npos);
    EXPECT_EQ(listing(dir), std::vector<std::string>{"liner.xml"}) << "no temporary file left";

    // an existing file is replaced
    CliRun again = padrob("export --mjcf models/pendulum.pad --out '" + file.string() + "'");
    EXPECT_EQ(again.status, 0) << again.err;
    EXPECT_EQ(slurp(file.string()), padrob("export --mjcf models/pendulum.pad").out);
    EXPECT_EQ(listing(dir), std::vector<std::string>{"liner.xml"});
}

TEST(CliExport, LoopsAreRefusedWithoutOutput)
{
    const fs::path dir = outDir("loops");
    const fs::path file = dir / "loop.xml";
    for (const char* model : {"models/four_bar.pad", "models/slider_crank.pad", "models/excavator.pad"}) {
        CliRun r = padrob(std::string("export --mjcf ") + model + " --out '" + file.string() + "'");
        EXPECT_EQ(r.status, 1) << model;
        EXPECT_NE(r.err.find(std::string("padrob export: ") + model +
                             ": MJCF export needs a tree: the model closes 1 loop through joint "),
                  std::string::npos)
            << r.err;
        EXPECT_EQ(r.out, "");
        EXPECT_FALSE(fs::exists(file)) << model;
    }
    CliRun fourBar = padrob("export --mjcf models/four_bar.pad");
    EXPECT_EQ(fourBar.status, 1);
    EXPECT_EQ(fourBar.out, "");
}

TEST(CliExport, ModelErrorsExitOne)
{
    const std::string bad = writeTemp("export_bad.pad", "B 1 1.0 0.1 0.1 0.1\nC 1\nB1 0 P1 0 0 0 A1 1 0 0 R1 1 0 0\n");
    CliRun r = padrob("export --mjcf '" + bad + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("error"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
}

TEST(CliExport, BadArgumentsExitTwoAndWriteNothing)
{
    const fs::path dir = outDir("bad");
    const std::string out = (dir / "never.xml").string();
    struct Case {
        std::string args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"models/pendulum.pad", "give the format: --mjcf"},
        {"--mjcf", "no model given"},
        {"--mjcf models/pendulum.pad models/double_pendulum.pad", "give one model"},
        {"--mjcf models/pendulum.pad --bogus", "unknown option '--bogus'"},
        {"--mjcf models/pendulum.pad --dt 0", "--dt must be a positive number of seconds, not '0'"},
        {"--mjcf models/pendulum.pad --dt abc", "--dt must be a positive number of seconds, not 'abc'"},
        {"--mjcf /nonexistent/model.pad", "/nonexistent/model.pad"},
        {"--mjcf models", "models"},
    };
    for (const Case& c : cases) {
        CliRun r = padrob("export " + c.args + " --out '" + out + "'");
        EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(r.out, "") << c.args;
        EXPECT_FALSE(fs::exists(out)) << c.args;
    }
    CliRun noValue = padrob("export --mjcf models/pendulum.pad --out");
    EXPECT_EQ(noValue.status, 2);
    EXPECT_NE(noValue.err.find("--out needs a value"), std::string::npos) << noValue.err;
    // a folder that does not exist
    CliRun noFolder = padrob("export --mjcf models/pendulum.pad --out '" + (dir / "no" / "such.xml").string() + "'");
    EXPECT_EQ(noFolder.status, 2);
    EXPECT_NE(noFolder.err.find("cannot create"), std::string::npos) << noFolder.err;
    CliRun folder = padrob("export --mjcf models/pendulum.pad --out '" + dir.string() + "'");
    EXPECT_EQ(folder.status, 2);
    EXPECT_NE(folder.err.find("it is a folder"), std::string::npos) << folder.err;
    EXPECT_TRUE(listing(dir).empty());
}

// --check runs MuJoCo in the padrob process: the binary has it exactly when the build
// found it (buildHasMujoco); without it --check is a usage error, which the test
// accepts only for a build without MuJoCo.
TEST(CliExport, CheckAgreesWithMujocoOnEveryTreeModel)
{
    const bool mujoco = buildHasMujoco();
    const std::string zoo = writeTemp("export_zoo.pad", kTreeZoo);
    // a free body carrying a pendulum that starts swinging, and a slider: the free body
    // turns and drifts (MuJoCo integrates its quaternion, Padrob its turns and base)
    const std::string freeZoo = writeTemp("export_free.pad", R"(GRAVITY 0.4 -0.3 -9.81
B 1 3.0 0.1 0.2 0.25 0.01 -0.02 0.015 CG 0.02 0.01 -0.03 NAME "hull"
B 2 0.8 0.02 0.03 0.01 NAME "bob"
B 3 0.5 0.01 0.01 0.01 NAME "slider"
C 1 T 3 NAME "free"
B1 0 P1 0.5 -0.2 2.0 A1 0 1 0 R1 0 0 1
B2 1 P2 0.1 0.2 -0.3 A2 1 0 0 R2 0 1 0
C 2 VI 4 QI 0.3 NAME "swing"
B1 1 P1 0 0 -0.2 A1 1 0 1 R1 0 1 0
B2 2 P2 0 0 0.5 A2 1 0 0 R2 0 1 0
C 3 T 2 VI -1.5 NAME "rail"
B1 1 P1 0.1 0 0 A1 1 0 0 R1 0 0 1
B2 3 P2 0 0 0 A2 1 0 0 R2 0 0 1
)");
    const std::vector<std::string> models = {"models/pendulum.pad",        "models/double_pendulum.pad",
                                             "models/incline_slider.pad",  "models/knuckle_boom_crane.pad",
                                             "models/liner_manipulator.pad", "models/liner_station.pad",
                                             "'" + zoo + "'", "'" + freeZoo + "'", "models/tumbling_block.pad"};
    for (const std::string& model : models) {
        CliRun r = padrob("export --mjcf " + model + " --check");
        if (!mujoco) {
            EXPECT_EQ(r.status, 2) << model;
            EXPECT_NE(r.err.find("--check needs MuJoCo, and this padrob was built without it"), std::string::npos)
                << r.err;
            EXPECT_EQ(r.out, "");
            continue;
        }
        EXPECT_EQ(r.status, 0) << model << "\n" << r.err;
        EXPECT_NE(r.err.find("MuJoCo agrees with Padrob over 0.2 s"), std::string::npos) << model << "\n" << r.err;
        EXPECT_EQ(r.out, padrob("export --mjcf " + model).out) << model;
    }
    if (!mujoco) PADROB_NEEDS_COMPONENT("padrob was built without MuJoCo: --check refused as documented");

    // the liner manipulator's placeholders are replaced by the true values
    CliRun liner = padrob("export --mjcf models/liner_manipulator.pad --check");
    for (const char* body :
         {"body 1 \"torreta\"", "body 3 \"extensión\"", "body 5 \"balancín\"", "body 6 \"cabezal\""}) {
        EXPECT_NE(liner.err.find(std::string("set in MuJoCo after loading: ") + body), std::string::npos)
            << body << "\n" << liner.err;
    }
    EXPECT_NE(liner.err.find("note: every joint passive in both: the model's 9 drives are not exported"),
              std::string::npos)
        << liner.err;
    CliRun zooRun = padrob("export --mjcf '" + zoo + "' --check");
    EXPECT_NE(zooRun.err.find("without the model's 1 applied force (F): it is not exported"), std::string::npos) << zooRun.err;

    // a loop is refused before MuJoCo is asked
    CliRun loop = padrob("export --mjcf models/four_bar.pad --check");
    EXPECT_EQ(loop.status, 1);
    EXPECT_NE(loop.err.find("MJCF export needs a tree"), std::string::npos);
}

namespace {

/// "  body 1: Padrob x y z, MuJoCo x y z" of --check's run with contacts: the two
/// centres of mass at its end (nothing when the line is missing).
using V3 = std::array<double, 3>;

double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 minus(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

bool contactEnd(const std::string& err, const std::string& body, V3& padrob, V3& mujoco)
{
    const std::string key = "  body " + body + ": Padrob ";
    const std::size_t at = err.find(key);
    if (at == std::string::npos) return false;
    double v[6];
    const int n = std::sscanf(err.c_str() + at + key.size(), "%lf %lf %lf, MuJoCo %lf %lf %lf", &v[0], &v[1], &v[2],
                              &v[3], &v[4], &v[5]);
    padrob = {v[0], v[1], v[2]};
    mujoco = {v[3], v[4], v[5]};
    return n == 6;
}

std::string fixed9(double v)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9f", v);
    return buf;
}

}  // namespace

// CONTACT: the export has geoms and contacts on; MuJoCo loads it (--check) and runs it
// side by side with Padrob for 1 s. The two contact laws differ (docs/contact.md,
// "MuJoCo"): a box dropped 5 cm onto the floor rests at the same height within 0.3 mm
// (Padrob's compliant contact sinks g/ω² = 0.11 mm, MuJoCo's soft constraint a few µm),
// and a block sliding down a 35° incline (MU 0.5) covers ½·g(sin θ − μ cos θ)·t² in both
// within 3 % of the closed form.
TEST(CliExport, ContactScenesFollowMujocoWithinTheLawsDifferences)
{
    const std::string box = writeTemp("export_contact_box.pad", "GRAVITY 0 0 -9.81\nCONTACT\n"
                                                                "B 1 100 16.667 16.667 16.667\nC 1 T 3\n"
                                                                "B1 0 P1 0.2 -0.1 0.55 A1 1 0 0 R1 0 1 0\n"
                                                                "B2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\n"
                                                                "G 1 B 1 BOX 1 1 1\nG 2 B 0 BOX 4 4 1 POS 0 0 -0.5\n"
                                                                "G 3 B 1 SPHERE 0.2 POS 0 0 0.6 NOCONTACT\n");
    CliRun plain = padrob("export --mjcf '" + box + "'");
    ASSERT_EQ(plain.status, 0) << plain.err;
    EXPECT_NE(plain.out.find("<geom name=\"g1\" type=\"box\" size=\"0.5 0.5 0.5\""), std::string::npos) << plain.out;
    EXPECT_NE(plain.out.find("<geom name=\"g2\" type=\"box\" size=\"2 2 0.5\" pos=\"0 0 -0.5\""), std::string::npos);
    EXPECT_NE(plain.out.find("contype=\"0\" conaffinity=\"0\""), std::string::npos);  // G 3, NOCONTACT
    EXPECT_EQ(plain.out.find("contact=\"disable\""), std::string::npos);
    if (!buildHasMujoco()) PADROB_NEEDS_COMPONENT("padrob was built without MuJoCo: no side-by-side run");

    CliRun r = padrob("export --mjcf '" + box + "' --check");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("MuJoCo loads the export with its 3 geoms and contacts on"), std::string::npos) << r.err;
    V3 p, m;
    ASSERT_TRUE(contactEnd(r.err, "1", p, m)) << r.err;
    std::printf("box at rest: Padrob z %.6f, MuJoCo z %.6f\n", p[2], m[2]);
    EXPECT_NEAR(p[2], 0.5, 0.3e-3);
    EXPECT_NEAR(m[2], 0.5, 0.3e-3);
    EXPECT_NEAR(p[2], m[2], 0.3e-3);
    for (const V3& q : {p, m}) {  // neither drifts
        EXPECT_NEAR(q[0], 0.2, 0.1e-3);
        EXPECT_NEAR(q[1], -0.1, 0.1e-3);
    }

    // a free block on a 35° incline (MU 0.5), from rest: s = ½·a·t² after 1 s
    const double th = 35 * std::numbers::pi / 180;
    const V3 n = {std::sin(th), 0, std::cos(th)}, c = {0.25 * n[0], 0, 0.25 * n[2]};
    const std::string incline = writeTemp(
        "export_contact_incline.pad",
        "GRAVITY 0 0 -9.81\nCONTACT MU 0.5\nB 1 100 4.1667 4.1667 4.1667\nC 1 T 3\nB1 0 P1 " + fixed9(c[0]) + " 0 " +
            fixed9(c[2]) + " A1 " + fixed9(std::cos(th)) + " 0 " + fixed9(-std::sin(th)) +
            " R1 0 1 0\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\nG 1 B 1 BOX 0.5 0.5 0.5\nG 2 B 0 BOX 20 4 1 POS " +
            fixed9(-0.5 * n[0]) + " 0 " + fixed9(-0.5 * n[2]) + " ROT 0 1 0 35\n");
    CliRun s = padrob("export --mjcf '" + incline + "' --check");
    ASSERT_EQ(s.status, 0) << s.err;
    ASSERT_TRUE(contactEnd(s.err, "1", p, m)) << s.err;
    const double a = 9.81 * (std::sin(th) - 0.5 * std::cos(th)), expected = 0.5 * a;
    const V3 down = {std::cos(th), 0, -std::sin(th)};
    const double sp = dot(minus(p, c), down), sm = dot(minus(m, c), down);
    std::printf("block on 35 deg after 1 s: closed form %.4f m, Padrob %.4f m, MuJoCo %.4f m\n", expected, sp, sm);
    EXPECT_NEAR(sp, expected, 0.03 * expected);
    EXPECT_NEAR(sm, expected, 0.03 * expected);
}

// the liner manipulator in the SAG mill with CONTACT: the scene's solids are world geoms,
// and MuJoCo loads the whole export
TEST(CliExport, TheLinerManipulatorInTheMillExportsWithItsScene)
{
    const std::string text = slurp(std::string(PADROB_SOURCE_DIR) + "/models/liner_mill.pad");
    ASSERT_FALSE(text.empty());
    const std::string model = writeTemp("liner_mill_contact.pad", "CONTACT\n" + text);
    CliRun r = padrob("export --mjcf '" + model + "' --scene resources/scenes/sag_mill.pad");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("<geom name=\"scene_g1_0\" type=\"box\""), std::string::npos);  // the shell: a ring of boxes
    EXPECT_NE(r.out.find("<geom name=\"scene_g3\" type=\"cylinder\""), std::string::npos);  // the grate
    EXPECT_NE(r.out.find("<exclude "), std::string::npos);  // the pins in their bores
    CliRun noScene = padrob("export --mjcf '" + model + "'");
    EXPECT_EQ(noScene.out.find("scene_g"), std::string::npos);
    if (!buildHasMujoco()) PADROB_NEEDS_COMPONENT("padrob was built without MuJoCo: the export is not loaded");
    CliRun c = padrob("export --mjcf '" + model + "' --scene resources/scenes/sag_mill.pad --check");
    EXPECT_EQ(c.status, 0) << c.err;
    EXPECT_NE(c.err.find("MuJoCo loads the export with its "), std::string::npos) << c.err;
}
