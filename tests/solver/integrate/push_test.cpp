// The mouse's push (issue 22 item 4; Simulation::setPush, applied_forces.h "The
// push"): a free body pushed toward a target comes to rest there, held at its centre
// of mass or off it; a pendulum pushed sideways settles at the angle its stiffness and
// gravity give, tan θ = ω₀²·d / (g + ω₀²·L); the force is capped for a far target;
// clearing the push leaves the body moving freely; bad pushes are refused; the liner
// manipulator's boom, held by its slew motor, slews only when pushed past its relief.

#include "solver/dynamics/applied_forces.h"
#include "solver/integrate/simulation.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace solver {
namespace {

using Eigen::Vector3d;
using test::rk4;

/// Runs `sim` to time t, failing the test on an error.
void runTo(Simulation& sim, double t)
{
    std::vector<SimulationEvent> events;
    std::string error;
    ASSERT_TRUE(sim.advanceTo(t, events, error)) << error;
}

/// World position of body b's point `local` at the simulation's current state.
Vector3d worldPointOf(const Simulation& sim, int b, const Vector3d& local)
{
    return sim.data().X_wb[static_cast<std::size_t>(b)] * local;
}

/// The tumbling block (models/tumbling_block.pad: a 2 kg free body, no gravity), its
/// simulation (RK4, 1 ms) and its centre of mass in its frame.
class BlockPush : public ::testing::Test {
protected:
    std::shared_ptr<const Model> model = test::compileExample("tumbling_block.pad");
    Simulation sim{model, rk4(1e-3)};
    int block = model->bodyIndex(1);
    Vector3d com = model->com[static_cast<std::size_t>(block)];
};

TEST_F(BlockPush, AFreeBodyPushedAtItsCentreComesToRestAtTheTarget)
{
    runTo(sim, 0.6);  // spun up: the block tumbles
    const Vector3d target(0.8, -0.4, 1.3);
    ASSERT_TRUE(sim.setPush(block, com, target));
    EXPECT_EQ(sim.state().push.body, block);
    runTo(sim, 4.0);
    const Vector3d p = worldPointOf(sim, block, com);
    EXPECT_LT((p - target).norm(), 1e-3) << p.transpose();
    EXPECT_LT(sim.data().vel[static_cast<std::size_t>(block)].norm(), 1e-3);
    EXPECT_LT(sim.data().omega[static_cast<std::size_t>(block)].norm(), 1e-2) << "its spin is damped";
}

TEST_F(BlockPush, AFreeBodyHeldOffItsCentreSettlesWithThePointAtTheTarget)
{
    const Vector3d corner = model->com[static_cast<std::size_t>(block)] + Vector3d(0.5, 0.25, 0.125);
    const Vector3d start = worldPointOf(sim, block, corner);
    const Vector3d target = start + Vector3d(-0.6, 0.3, 0.2);
    ASSERT_TRUE(sim.setPush(block, corner, target));
    runTo(sim, 1e-3);
    EXPECT_GT(sim.data().vel[static_cast<std::size_t>(block)].dot(target - start), 0.0) << "it moves toward it";
    runTo(sim, 8.0);
    EXPECT_LT((worldPointOf(sim, block, corner) - target).norm(), 2e-3);
    EXPECT_LT(sim.data().omega[static_cast<std::size_t>(block)].norm(), 2e-2);
}

// A 2 kg bob on a massless rod of 1 m, swinging about y at the origin, under gravity.
const std::string kPendulum = R"(GRAVITY 0 0 -9.81
B 1 2 0.001 0.001 0.001 NAME "bob"
C 1 NAME "pivot"
B1 0 P1 0 0 0 A1 0 1 0 R1 1 0 0
B2 1 P2 0 0 1 A2 0 1 0 R2 1 0 0
)";

TEST(Push, APendulumPushedSidewaysDeflectsAsItsStiffnessAndGravityGive)
{
    const auto model = test::compileText(kPendulum, "pendulum.pad");
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-3));
    const int bob = model->bodyIndex(1);
    const Vector3d centre = Vector3d::Zero();  // the bob's frame origin, its centre of mass
    const Vector3d rest = worldPointOf(sim, bob, centre);
    ASSERT_LT((rest - Vector3d(0, 0, -1)).norm(), 1e-12) << rest.transpose();
    const double d = 0.5, L = 1.0, g = 9.81, w2 = kPushFrequency * kPushFrequency;
    ASSERT_TRUE(sim.setPush(bob, centre, rest + Vector3d(d, 0, 0)));
    runTo(sim, 6.0);
    // the bob at (L sin θ, 0, −L cos θ): V = −m g L cos θ + ½ k |T − p|², k = ω₀² m,
    // dV/dθ = 0 gives tan θ = ω₀² d / (g + ω₀² L)
    const double expected = std::atan(w2 * d / (g + w2 * L));
    const Vector3d p = worldPointOf(sim, bob, centre);
    EXPECT_NEAR(std::atan2(p.x(), -p.z()), expected, 1e-5) << "expected " << expected << " rad";
    EXPECT_NEAR(p.norm(), L, 1e-9);
    EXPECT_NEAR(sim.state().qd[model->jointIndex(1)], 0.0, 1e-5);
}

TEST_F(BlockPush, AFarTargetPullsWithTheCappedForce)
{
    ASSERT_TRUE(sim.setPush(block, com, worldPointOf(sim, block, com) + Vector3d(1000, 0, 0)));
    sim.evaluate();
    const Vector6d& load = sim.data().fext[static_cast<std::size_t>(block)];
    EXPECT_NEAR(load.tail<3>().norm(), kPushMaxAcceleration * 2.0, 1e-9);  // 2 kg
    EXPECT_NEAR(load.tail<3>().x(), kPushMaxAcceleration * 2.0, 1e-9);
    EXPECT_EQ(subtreeMass(*model, block), 2.0);
}

TEST_F(BlockPush, ClearingThePushLeavesTheBodyMovingFreely)
{
    ASSERT_TRUE(sim.setPush(block, com, worldPointOf(sim, block, com) + Vector3d(0, 2, 0)));
    runTo(sim, 0.2);
    sim.clearPush();
    EXPECT_EQ(sim.state().push.body, -1);
    runTo(sim, 0.7);  // the spin-up torque ends at 0.501 s: no load from here on
    const Vector3d v = sim.data().vel[static_cast<std::size_t>(block)];
    const Vector3d p = worldPointOf(sim, block, com);
    EXPECT_GT(v.y(), 0.5) << "the push left it moving";
    runTo(sim, 1.7);
    EXPECT_LT((sim.data().vel[static_cast<std::size_t>(block)] - v).norm(), 1e-9) << "no force: constant velocity";
    EXPECT_LT((worldPointOf(sim, block, com) - (p + v)).norm(), 1e-9);
}

TEST_F(BlockPush, BadPushesAreRefusedAndChangeNothing)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    ASSERT_TRUE(sim.setPush(block, Vector3d::Zero(), Vector3d(0, 0, 1)));
    EXPECT_FALSE(sim.setPush(block, Vector3d::Zero(), Vector3d(nan, 0, 1)));
    EXPECT_FALSE(sim.setPush(block, Vector3d::Zero(), Vector3d(0, inf, 1)));
    EXPECT_FALSE(sim.setPush(block, Vector3d(0, 0, -inf), Vector3d(0, 0, 1)));
    EXPECT_FALSE(sim.setPush(-1, Vector3d::Zero(), Vector3d(0, 0, 1)));
    EXPECT_FALSE(sim.setPush(model->nb, Vector3d::Zero(), Vector3d(0, 0, 1)));
    const Push& p = sim.state().push;
    EXPECT_EQ(p.body, block);
    EXPECT_EQ(p.target, Vector3d(0, 0, 1));
    runTo(sim, 0.1);
    EXPECT_TRUE(sim.state().q.allFinite());
}

// The liner manipulator's boom slew (C 1, a hydraulic motor whose relief holds 54 kN·m):
// the telescope (C 3's body, carrying the wrist and the claws) pushed sideways at the
// wrist, a few metres from the slew axis. A slight push is held (the valve closed, the
// boom still); a hard one opens the relief valve and the boom slews against it, the way
// the push pulls.
TEST(Push, TheLinerManipulatorsBoomSlewsAgainstItsReliefOnlyWhenPushedHard)
{
    const auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const int slew = model->jointIndex(1), telescope = model->jointIndex(3), wrist = model->jointIndex(4);
    for (const double reach : {0.05, 2.0}) {
        // 0.05 m: 5 kN at a 2.4 m arm, 12 kN·m (held); 2 m: the cap, 100 kN, 240 kN·m
        Simulation sim(model, rk4(1e-3));
        runTo(sim, 0.05);
        const double theta0 = sim.state().q[slew];
        const Data& d = sim.data();
        const Eigen::Isometry3d& X = d.X_wb[static_cast<std::size_t>(telescope)];
        const Vector3d at = d.X_wb[static_cast<std::size_t>(wrist)].translation();
        const Eigen::Isometry3d& J = d.X_wj[static_cast<std::size_t>(slew)];
        const Vector3d axis = J.linear().col(0);  // A
        const Vector3d sideways = axis.cross(at - J.translation());
        ASSERT_GT(sideways.norm(), 2.0) << "the wrist is metres from the slew axis";
        ASSERT_TRUE(sim.setPush(telescope, X.inverse() * at, at + reach * sideways.normalized()));
        std::vector<SimulationEvent> events;
        std::string error;
        ASSERT_TRUE(sim.advanceTo(1.0, events, error)) << error;
        bool opened = false;
        for (const SimulationEvent& e : events)
            opened = opened || (e.kind == SimulationEvent::Kind::ReliefOpen && e.joint == slew);
        const double turned = model->axisSign[static_cast<std::size_t>(slew)] * (sim.state().q[slew] - theta0);
        if (reach < 1) {
            EXPECT_FALSE(opened) << "12 kN·m is below the relief's 54 kN·m";
            EXPECT_NEAR(turned, 0.0, 1e-9);
        } else {
            EXPECT_TRUE(opened);
            EXPECT_GT(turned, 0.3) << "it slews the way the push pulls";
        }
    }
}

}  // namespace
}  // namespace solver
