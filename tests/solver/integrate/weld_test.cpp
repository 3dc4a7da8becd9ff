// Run-time welds (issue 4 item 2): a weld is a plastic impact (momentum kept,
// energy lost as the hand formula says) and its release changes nothing; a weld of
// bodies at rest does not jump the state; a 4,500 kg liner welded to the liner
// manipulator's claws raises the lift cylinder's force by its weight's moment about
// the boom pivot over the cylinder's moment arm; the welded body moves with the
// other; bad welds are refused and change nothing, and say why in English and as a
// translatable Text.

#include "solver/integrate/simulation.h"
#include "solver/kinematics/kinematics.h"
#include "tests/solver/integrate/statics.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace solver {
namespace {

using Eigen::Vector3d;

using test::rk4;

// Two carts on parallel rails along x (no gravity): 2 kg at +1 m/s and 3 kg at −0.5 m/s;
// a disc of 0.5 kg m² spinning at 4 rad/s beside a coaxial disc of 1.5 kg m² at 0.
const std::string kCarts = R"(GRAVITY 0 0 0
B 1 2 0.1 0.1 0.1 NAME "cart 1"
B 2 3 0.1 0.1 0.1 NAME "cart 2"
B 3 1 0.5 0.5 0.5 NAME "disc 1"
B 4 1 1.5 1.5 1.5 NAME "disc 2"
C 1 T 2 VI 1.0
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2 T 2 VI -0.5
B1 0 P1 0 1 0 A1 0 0 1 R1 1 0 0
B2 2 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 3 VI 4
B1 0 P1 5 0 0 A1 1 0 0 R1 0 1 0
B2 3 P2 0 0 0 A2 1 0 0 R2 0 1 0
C 4
B1 0 P1 5 0 0 A1 1 0 0 R1 0 1 0
B2 4 P2 0 0 0 A2 1 0 0 R2 0 1 0
)";

TEST(Welds, AWeldIsAPlasticImpactAndItsReleaseChangesNothing)
{
    const auto model = test::compileText(kCarts, "carts.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    const int c1 = m.bodyIndex(1), c2 = m.bodyIndex(2), d1 = m.bodyIndex(3), d2 = m.bodyIndex(4);
    const int j1 = m.jointIndex(1), j2 = m.jointIndex(2), j3 = m.jointIndex(3), j4 = m.jointIndex(4);
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(0.3, ev, err)) << err;
    const Eigen::VectorXd qBefore = sim.state().q;
    const double p0 = 2 * 1.0 + 3 * -0.5;  // linear momentum [kg m/s]
    const double h0 = 0.5 * 4.0;           // angular momentum about x [kg m²/s]
    const double ke0 = kineticEnergy(m, sim.data());

    ASSERT_TRUE(sim.weld(c1, c2, ev, err)) << err;
    ASSERT_TRUE(sim.weld(d1, d2, ev, err)) << err;
    ASSERT_EQ(ev.size(), 2u);
    EXPECT_EQ(ev[0].kind, SimulationEvent::Kind::Weld);
    EXPECT_EQ(ev[0].describe(m), "t=0.300000 s: body 2 cart 2 welded to body 1 cart 1");
    // positions do not jump; the rates become the common ones
    EXPECT_TRUE(sim.state().q.isApprox(qBefore, 1e-15));
    const State& s = sim.state();
    EXPECT_NEAR(s.qd[j1], p0 / 5, 1e-12);
    EXPECT_NEAR(s.qd[j2], p0 / 5, 1e-12);
    EXPECT_NEAR(s.qd[j3], h0 / 2, 1e-12);
    EXPECT_NEAR(s.qd[j4], h0 / 2, 1e-12);
    // the energy lost: ½ μ Δv² with μ = m1 m2 / (m1 + m2), and ½ I1 I2/(I1 + I2) Δω²
    const double lost = 0.5 * (2.0 * 3 / 5) * 1.5 * 1.5 + 0.5 * (0.5 * 1.5 / 2) * 4 * 4;
    EXPECT_NEAR(ke0 - kineticEnergy(m, sim.data()), lost, 1e-12);

    // welded: they move together
    ASSERT_TRUE(sim.advanceTo(0.6, ev, err)) << err;
    EXPECT_NEAR(sim.state().q[j1] - sim.state().q[j2], qBefore[j1] - qBefore[j2], 1e-12);
    EXPECT_NEAR(sim.state().q[j3] - sim.state().q[j4], qBefore[j3] - qBefore[j4], 1e-12);

    // released: nothing jumps, and they go on at the common rates
    const Eigen::VectorXd qd = sim.state().qd;
    ASSERT_TRUE(sim.release(c1, c2, ev, err)) << err;
    ASSERT_TRUE(sim.release(d1, d2, ev, err)) << err;
    EXPECT_EQ(ev.back().kind, SimulationEvent::Kind::Release);
    EXPECT_TRUE(sim.state().qd.isApprox(qd, 1e-15));
    ASSERT_TRUE(sim.advanceTo(0.9, ev, err)) << err;
    EXPECT_NEAR(sim.state().qd[j1], p0 / 5, 1e-12);
    EXPECT_NEAR(sim.state().qd[j2], p0 / 5, 1e-12);
    EXPECT_NEAR(sim.state().qd[j3], h0 / 2, 1e-12);
    EXPECT_NEAR(2 * sim.state().qd[j1] + 3 * sim.state().qd[j2], p0, 1e-12);
}

TEST(Welds, BadWeldsAreRefusedAndChangeNothing)
{
    const auto model = test::compileText(kCarts, "carts.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    const int c1 = m.bodyIndex(1), c2 = m.bodyIndex(2), d1 = m.bodyIndex(3);
    std::vector<SimulationEvent> ev;
    std::string err;
    const Eigen::VectorXd qd0 = sim.state().qd;

    EXPECT_FALSE(sim.weld(c1, c1, ev, err));
    EXPECT_NE(err.find("to itself"), std::string::npos) << err;
    EXPECT_FALSE(sim.weld(c1, 17, ev, err));
    EXPECT_NE(err.find("no such body"), std::string::npos) << err;
    EXPECT_FALSE(sim.weld(-2, c1, ev, err));
    EXPECT_FALSE(sim.release(c1, c2, ev, err));
    EXPECT_NE(err.find("is not welded to"), std::string::npos) << err;
    EXPECT_TRUE(ev.empty());
    EXPECT_TRUE(sim.state().welds.empty());
    EXPECT_TRUE(sim.state().qd.isApprox(qd0));

    ASSERT_TRUE(sim.weld(c1, c2, ev, err)) << err;
    const Eigen::VectorXd qd1 = sim.state().qd;
    // a second weld on a body already welded
    EXPECT_FALSE(sim.weld(d1, c2, ev, err));
    EXPECT_NE(err.find("already welded"), std::string::npos) << err;
    EXPECT_FALSE(sim.weld(c1, d1, ev, err));
    EXPECT_FALSE(sim.release(c2, c1, ev, err));  // the weld is of 2 to 1, not 1 to 2
    EXPECT_EQ(sim.state().welds.size(), 1u);
    EXPECT_EQ(ev.size(), 1u);
    EXPECT_TRUE(sim.state().qd.isApprox(qd1));
    // to the ground: allowed, and it stops the body
    ASSERT_TRUE(sim.weld(-1, d1, ev, err)) << err;
    EXPECT_NEAR(sim.state().qd[m.jointIndex(3)], 0.0, 1e-12);
    ASSERT_TRUE(sim.advanceTo(0.2, ev, err)) << err;
    EXPECT_NEAR(sim.state().q[m.jointIndex(3)], 0.0, 1e-12);
}

TEST(Welds, BadWeldsCarryATranslatableTextOfTheirEnglishMessage)
{
    const auto model = test::compileText(kCarts, "carts.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    const int c1 = m.bodyIndex(1), c2 = m.bodyIndex(2);
    std::vector<SimulationEvent> ev;
    std::string err;
    Text text;
    // every refusal: the Text (context "Diagnostics") says in English what `error` says
    auto expectText = [&](const char* tmpl) {
        EXPECT_FALSE(text.empty()) << err;
        EXPECT_STREQ(text.context(), "Diagnostics");
        EXPECT_STREQ(text.tmpl(), tmpl);
        EXPECT_EQ(text.english(), err);
        text = {};
    };
    EXPECT_FALSE(sim.weld(c1, c1, ev, err, &text));
    EXPECT_EQ(err, "cannot weld body 1 cart 1 to itself");
    expectText("cannot weld %1 to itself");
    EXPECT_FALSE(sim.weld(c1, 17, ev, err, &text));
    EXPECT_EQ(err, "cannot weld: no such body");
    expectText("cannot weld: no such body");
    EXPECT_FALSE(sim.release(c1, c2, ev, err, &text));
    EXPECT_EQ(err, "cannot release: body 2 cart 2 is not welded to body 1 cart 1");
    expectText("cannot release: %1 is not welded to %2");
    EXPECT_FALSE(sim.release(-1, 17, ev, err, &text));
    EXPECT_EQ(err, "cannot release: no such body");
    expectText("cannot release: no such body");
    ASSERT_TRUE(sim.weld(c1, c2, ev, err, &text)) << err;
    EXPECT_TRUE(text.empty());  // untouched on success
    EXPECT_FALSE(sim.weld(-1, c2, ev, err, &text));
    EXPECT_EQ(err, "cannot weld body 2 cart 2 to the ground: body 2 cart 2 is already welded (release that weld first)");
    const Text already = text;
    expectText("cannot weld %1 to %2: %3 is already welded (release that weld first)");

    // the bodies are phrases of their own, translated with the sentence (names stay)
    const std::string es = already.render([](const char*, const char* tmpl) -> std::string {
        const std::string t = tmpl;
        if (t == "cannot weld %1 to %2: %3 is already welded (release that weld first)")
            return "no se puede soldar %1 a %2: %3 ya está soldado (libere primero esa soldadura)";
        if (t == "body %1 %2") return "cuerpo %1 %2";
        if (t == "the ground") return "el suelo";
        return t;
    });
    EXPECT_EQ(es, "no se puede soldar cuerpo 2 cart 2 a el suelo: cuerpo 2 cart 2 ya está soldado "
                  "(libere primero esa soldadura)");
}

// ---------------------------------------------------------------- the liner

std::string readFile(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// The liner manipulator plus a free 4,500 kg liner (a 1.9 × 0.75 × 0.35 m steel
/// block) on a 6-DOF chain of massless bodies from the ground: x, y, z slides, then
/// turns about z, y, x. No limits: nothing but a weld holds it.
std::string linerStation()
{
    return readFile(test::modelPath("liner_manipulator.pad")) + R"(
B 20 NAME "x carrier"
B 21 NAME "y carrier"
B 22 NAME "z carrier"
B 23 NAME "yaw carrier"
B 24 NAME "pitch carrier"
B 25 4500 256.875 1399.69 1564.69 NAME "liner"
C 20 T 2
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 20 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 21 T 2
B1 20 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 21 P2 0 0 0 A2 0 0 1 R2 0 1 0
C 22 T 2
B1 21 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 22 P2 0 0 0 A2 1 0 0 R2 0 0 1
C 23
B1 22 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 23 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 24
B1 23 P1 0 0 0 A1 0 1 0 R1 1 0 0
B2 24 P2 0 0 0 A2 0 1 0 R2 1 0 0
C 25
B1 24 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 25 P2 0 0 0 A2 1 0 0 R2 0 1 0
)";
}

TEST(Welds, AWeldedLinerLoadsTheLiftCylinderByItsMomentAboutTheBoomPivot)
{
    const auto model = test::compileText(linerStation(), "liner_station.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    const int claw = m.bodyIndex(8), liner = m.bodyIndex(25);
    // the liner's centre of mass at the upper claw's origin, level
    const Vector3d grip = sim.data().X_wb[claw].translation();
    sim.setInitial(m.jointIndex(20), grip.x(), 0);
    sim.setInitial(m.jointIndex(21), grip.y(), 0);
    sim.setInitial(m.jointIndex(22), grip.z(), 0);
    ASSERT_TRUE(sim.data().X_wb[liner].translation().isApprox(grip, 1e-12));
    const double before = sim.data().driveForce[m.jointIndex(2)];
    const Eigen::VectorXd q0 = sim.state().q, qd0 = sim.state().qd;

    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.weld(claw, liner, ev, err)) << err;
    // everything at rest: the weld changes nothing in the state
    EXPECT_TRUE(sim.state().q == q0);
    EXPECT_LT((sim.state().qd - qd0).lpNorm<Eigen::Infinity>(), 1e-12);
    const double after = sim.data().driveForce[m.jointIndex(2)];

    // by hand: ΔF · arm = m g · (the liner's lever about the pivot axis)
    const int lift = m.jointIndex(2);
    const double arm = test::cylinderArm(m, sim.data(), lift);
    const double moment = std::abs(test::weightMoment(m, test::jointPivot(m, sim.data(), lift), 4500, grip));
    const double expected = moment / arm;
    EXPECT_GT(after - before, 0.0) << "the cylinder must push harder";
    EXPECT_NEAR(after - before, expected, 1e-6 * expected)
        << "before " << before << " N, after " << after << " N, arm " << arm << " m, lever "
        << moment / (4500 * 9.81) << " m";
    // the liner's whole weight goes through the weld (the liner hangs from the claw)
    ASSERT_EQ(sim.data().constraintReactionWorld.size(), 1u);
    EXPECT_NEAR(sim.data().constraintReactionWorld[0][5], 4500 * 9.81, 1e-6 * 4500 * 9.81);
}

TEST(Welds, TheWeldedLinerMovesWithTheClawsAndFallsWhenReleased)
{
    const auto model = test::compileText(linerStation(), "liner_station.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    const int claw = m.bodyIndex(8), liner = m.bodyIndex(25);
    const Vector3d grip = sim.data().X_wb[claw].translation();
    sim.setInitial(m.jointIndex(20), grip.x(), 0);
    sim.setInitial(m.jointIndex(21), grip.y(), 0);
    sim.setInitial(m.jointIndex(22), grip.z() - 0.1, 0);  // 10 cm below the claw
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.weld(claw, liner, ev, err)) << err;
    const Eigen::Isometry3d rel0 = sim.data().X_wb[claw].inverse() * sim.data().X_wb[liner];

    // slew, lift the boom, roll the head: the liner stays put in the claw's frame
    sim.setCommand(m.jointIndex(1), 0.5);
    sim.setCommand(m.jointIndex(2), 0.3);
    sim.setCommand(m.jointIndex(6), 0.4);
    double worst = 0;
    for (int k = 1; k <= 100; ++k) {
        ASSERT_TRUE(sim.advanceTo(0.01 * k, ev, err)) << err;
        const Eigen::Isometry3d rel = sim.data().X_wb[claw].inverse() * sim.data().X_wb[liner];
        worst = std::max(worst, (rel.matrix() - rel0.matrix()).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-9);
    const Vector3d moved = sim.data().X_wb[liner].translation() - (grip - Vector3d(0, 0, 0.1));
    EXPECT_GT(moved.norm(), 0.05) << "the liner must have been carried";

    // released with the valves closed: it falls freely
    for (int id = 1; id <= 9; ++id) sim.setCommand(m.jointIndex(id), 0.0);
    ASSERT_TRUE(sim.advanceTo(1.2, ev, err)) << err;
    ASSERT_TRUE(sim.release(claw, liner, ev, err)) << err;
    ASSERT_TRUE(sim.advanceTo(1.21, ev, err)) << err;
    EXPECT_NEAR(sim.data().acc[liner].z(), -9.81, 1e-9);
    EXPECT_NEAR(sim.data().acc[claw].norm(), 0.0, 1e-9);
}


TEST(Welds, ALinerLyingOnItsStopAndWeldedToTheHeadLeavesTheStopWhenTheBoomLifts)
{
    // models/liner_station.pad: the claws around the liner's edge on the cart, the liner
    // resting on its z stop (C 12 at LL); welded to the head, the boom lifts it off
    const auto model = test::compileExample("liner_station.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    sim.setInitial(m.jointIndex(1), -std::numbers::pi / 2, 0);
    sim.setInitial(m.jointIndex(2), *m.lengthLaw[m.jointIndex(2)].angle(1.46095), 0);
    sim.setInitial(m.jointIndex(3), 0.45, 0);
    sim.setInitial(m.jointIndex(5), *m.lengthLaw[m.jointIndex(5)].angle(0.413), 0);
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(0.1, ev, err)) << err;
    const int z = m.jointIndex(12), lift = m.jointIndex(2);
    ASSERT_EQ(sim.state().limit[z], LimitState::AtLower);
    const double before = sim.data().driveForce[lift];
    ASSERT_TRUE(sim.weld(m.bodyIndex(6), m.bodyIndex(15), ev, err)) << err;
    ASSERT_TRUE(sim.advanceTo(0.2, ev, err)) << err;
    EXPECT_EQ(sim.state().limit[z], LimitState::AtLower) << "at rest it stays on its stop";
    ev.clear();
    sim.setCommand(lift, 1.0);
    ASSERT_TRUE(sim.advanceTo(1.2, ev, err)) << err;
    bool left = false;
    for (const SimulationEvent& e : ev) left = left || (e.kind == SimulationEvent::Kind::LimitLeave && e.joint == z);
    EXPECT_TRUE(left);
    EXPECT_EQ(sim.state().limit[z], LimitState::Free);
    EXPECT_GT(sim.state().q[z], 0.228 + 0.3);  // the boom's tip rises ~0.38 m/s at 4 m
    // the cylinder now holds the liner too (827 kN by hand, models/liner_station.pad)
    EXPECT_GT(sim.data().driveForce[lift] - before, 7e5);
    EXPECT_LT(sim.data().driveForce[lift] - before, 1.1e6);
}

}  // namespace
}  // namespace solver
