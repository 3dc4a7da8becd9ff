// The machines of models/ beyond the liner manipulator (issue 4 item 4): the
// excavator (a bucket four-bar closed through a T 1 cylinder) and the liner
// station (the manipulator with a 4,500 kg liner on its cart). Each loads, holds
// still with its valves closed, carries what hand statics give, and survives an
// operator slamming every valve.

#include "solver/integrate/simulation.h"
#include "solver/kinematics/kinematics.h"
#include "tests/solver/integrate/statics.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>

namespace solver {
namespace {

using Eigen::Vector3d;

using test::rk4;

/// Largest gap between the two sides of the loop-closing revolute joints.
double loopGap(const Simulation& sim)
{
    const Model& m = sim.model();
    const Data& d = sim.data();
    double gap = 0;
    for (const CutJoint& c : m.cuts) {
        const Vector3d p1 = c.body1 < 0 ? c.X_1.translation() : Vector3d(d.X_wb[c.body1] * c.X_1.translation());
        const Vector3d p2 = c.body2 < 0 ? c.X_2.translation() : Vector3d(d.X_wb[c.body2] * c.X_2.translation());
        gap = std::max(gap, (p2 - p1).norm());
    }
    return gap;
}

// ---------------------------------------------------------------- excavator

TEST(Excavator, LoadsWithItsBucketLoop)
{
    const CompiledModel loaded = compileFile(test::modelPath("excavator.pad"));
    ASSERT_TRUE(loaded.ok());
    EXPECT_TRUE(loaded.diagnostics.empty()) << loaded.diagnostics.items()[0].format();
    ASSERT_TRUE(loaded.topology);
    EXPECT_EQ(loaded.topology->dof, 4);  // slew and three cylinders
    const auto model = test::modelOrFail(loaded);
    ASSERT_TRUE(model);
    EXPECT_EQ(model->nb, 6);
    ASSERT_EQ(model->cuts.size(), 1u);
    EXPECT_EQ(model->cuts[0].jointId, 7);
    for (int id : {1, 2, 3, 4}) EXPECT_FALSE(model->dependent[model->jointIndex(id)]) << id;
    for (int id : {5, 6}) EXPECT_TRUE(model->dependent[model->jointIndex(id)]) << id;
}

TEST(Excavator, HoldsStillWithItsValvesClosedAndItsCylindersCarryTheHandStatics)
{
    const auto model = test::compileExample("excavator.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    const Eigen::VectorXd q0 = sim.state().q;
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(5.0, ev, err)) << err;
    EXPECT_TRUE(ev.empty()) << ev[0].describe(m);
    EXPECT_LT((sim.state().q - q0).lpNorm<Eigen::Infinity>(), 1e-9);
    EXPECT_LT(loopGap(sim), 1e-9);

    // boom: the weights of the whole arm (its subtree) about the boom foot pin, over
    // the boom cylinders' moment arm; the model's header has the same by hand
    const Data& d = sim.data();
    const int boom = m.jointIndex(2), stick = m.jointIndex(3);
    const double fBoom = -test::subtreeWeightMoment(m, d, boom) / test::cylinderArm(m, d, boom);
    EXPECT_NEAR(d.driveForce[boom], fBoom, 1e-6 * std::abs(fBoom));
    EXPECT_NEAR(d.driveForce[boom], 212926, 1.0);  // header: 212,926 N pushing
    EXPECT_NEAR(d.driveForce[stick], -17041, 1.0); // header: 17,041 N pulling
    // the stick cylinder: the stick's subtree about the stick foot pin; its sign is
    // the joint's (A = −y) way, as is dL/dθ's
    const double dl = m.coordinateRate(stick, sim.state().q[stick]);
    const double fStick = -test::subtreeWeightMoment(m, d, stick) / dl;
    EXPECT_NEAR(d.driveForce[stick], fStick, 1e-6 * std::abs(fStick));
    EXPECT_NEAR(d.driveForce[m.jointIndex(4)], 2065.47, 0.5);  // header: by virtual work
}

TEST(Excavator, TheBucketLinkageFollowsItsCylinderAndStaysClosed)
{
    const auto model = test::compileExample("excavator.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    const int bucketCyl = m.jointIndex(4), bucketPin = m.jointIndex(5);
    sim.setCommand(bucketCyl, 1.0);  // curl
    std::vector<SimulationEvent> ev;
    std::string err;
    double last = sim.state().q[bucketPin], worstGap = 0;
    bool monotone = true;
    for (int k = 1; k <= 400; ++k) {
        ASSERT_TRUE(sim.advanceTo(0.01 * k, ev, err)) << err;
        worstGap = std::max(worstGap, loopGap(sim));
        const double q = sim.state().q[bucketPin];
        if (q > last + 1e-12) monotone = false;  // curling turns the bucket one way (−y)
        last = q;
    }
    EXPECT_LT(worstGap, 1e-9);
    EXPECT_TRUE(monotone);
    // it reached full curl: the cylinder's upper limit, the bucket pin at the table's value
    EXPECT_NEAR(m.coordinate(bucketCyl, sim.state().q[bucketCyl]), 2.74, 1e-9);
    EXPECT_NEAR(sim.state().q[bucketPin] * 180 / M_PI, -79.825, 0.01);
}

TEST(Excavator, ASlewingArmFallingFreelyKeepsItsEnergy)
{
    // a spatial motion of the loop (it turns with the slew while it folds): RK4 at
    // 1 ms must neither gain nor lose energy. (Off the constraints, at RK4's inner
    // stages, the planar loop's redundant rows are not exactly redundant; taking them
    // for constraints once bled the slew's energy away.)
    const auto model = test::compileExample("excavator.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    SimulationOptions o = rk4(1e-3);
    o.drives = false;
    o.limits = false;
    Simulation sim(model, o);
    sim.setInitial(m.jointIndex(1), 0.0, 1.0);  // slewing at 1 rad/s
    const double e0 = mechanicalEnergy(m, sim.data());
    std::vector<SimulationEvent> ev;
    std::string err;
    double worst = 0;
    for (int k = 1; k <= 70; ++k) {
        ASSERT_TRUE(sim.advanceTo(0.01 * k, ev, err)) << err;
        worst = std::max(worst, std::abs(mechanicalEnergy(m, sim.data()) - e0) / e0);
    }
    EXPECT_LT(worst, 1e-9);
    EXPECT_LT(sim.state().qd[m.jointIndex(1)], 0.9) << "the folding arm's slew slows down";
    EXPECT_LT(loopGap(sim), 1e-9);
}

TEST(Excavator, SlammingEveryValveAtFullSlewDoesNotBreakTheSimulation)
{
    // an operator throws every lever from full one way to full the other while
    // slewing: relief valves open and close, limits are hit; the run goes on
    const auto model = test::compileExample("excavator.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    for (const double stick : {-1.0, 1.0}) {
        SCOPED_TRACE(stick);
        Simulation sim(model, rk4(1e-3));
        for (int id = 1; id <= 4; ++id) sim.setCommand(m.jointIndex(id), 1.0);
        std::vector<SimulationEvent> ev;
        std::string err;
        ASSERT_TRUE(sim.advanceTo(3.0, ev, err)) << err;
        sim.setCommand(m.jointIndex(1), -1.0);
        sim.setCommand(m.jointIndex(2), stick);
        sim.setCommand(m.jointIndex(3), -1.0);
        sim.setCommand(m.jointIndex(4), -1.0);
        for (int k = 1; k <= 300; ++k) ASSERT_TRUE(sim.advanceTo(3.0 + 0.01 * k, ev, err)) << err;
        EXPECT_TRUE(sim.state().q.allFinite());
        EXPECT_LT(loopGap(sim), 1e-9);
        EXPECT_LT(std::abs(sim.state().qd[m.jointIndex(1)]), 20.0) << "the slew must not run away";
    }
}

// ---------------------------------------------------------------- liner station

TEST(LinerStation, HoldsStillWithTheLinerRestingOnItsCart)
{
    const auto model = test::compileExample("liner_station.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    EXPECT_EQ(m.nb, 15);
    Simulation sim(model, rk4(1e-3));
    const int z = m.jointIndex(12);
    EXPECT_EQ(sim.state().limit[z], LimitState::AtLower);
    const Eigen::VectorXd q0 = sim.state().q;
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(5.0, ev, err)) << err;
    EXPECT_TRUE(ev.empty()) << ev[0].describe(m);
    EXPECT_LT((sim.state().q - q0).lpNorm<Eigen::Infinity>(), 1e-12);
    EXPECT_EQ(sim.state().limit[z], LimitState::AtLower);
    // the cart carries the liner: its stop pushes up with the liner's weight
    EXPECT_NEAR(sim.data().limitForce[z], 4500 * 9.81, 1e-6 * 4500 * 9.81);
}

TEST(LinerStation, TheLinerGraspedBetweenTheClawsLoadsTheBoomAsTheHeaderSays)
{
    const auto model = test::compileExample("liner_station.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    // the pose "between the claws at the manipulator's initial pose" of the header
    sim.setInitial(m.jointIndex(10), 0.0, 0);
    sim.setInitial(m.jointIndex(11), 3.690946, 0);
    sim.setInitial(m.jointIndex(12), 0.277236, 0);
    sim.setInitial(m.jointIndex(13), 0.0, 0);
    sim.setInitial(m.jointIndex(14), 0.0, 0);
    sim.setInitial(m.jointIndex(15), -0.0014693, 0);
    const int boom = m.jointIndex(2);
    const double before = sim.data().driveForce[boom];
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.weld(m.bodyIndex(6), m.bodyIndex(15), ev, err)) << err;
    const double added = sim.data().driveForce[boom] - before;
    const Vector3d liner = comPosition(m, sim.data(), m.bodyIndex(15));
    const double hand = std::abs(test::weightMoment(m, test::jointPivot(m, sim.data(), boom), 4500, liner)) /
                        test::cylinderArm(m, sim.data(), boom);
    EXPECT_NEAR(added, hand, 1e-6 * hand);
    EXPECT_NEAR(added, 822.6e3, 0.2e3);  // the header's figure
    // held for a second with the valves closed: nothing moves, the liner stays off its stop
    const Eigen::VectorXd q0 = sim.state().q;
    ASSERT_TRUE(sim.advanceTo(1.0, ev, err)) << err;
    EXPECT_LT((sim.state().q - q0).lpNorm<Eigen::Infinity>(), 1e-9);
    EXPECT_EQ(sim.state().limit[m.jointIndex(12)], LimitState::Free);
}

}  // namespace
}  // namespace solver
