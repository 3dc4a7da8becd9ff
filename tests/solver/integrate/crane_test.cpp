// The knuckle-boom crane (models/knuckle_boom_crane.pad): loads cleanly, holds
// still with every valve closed, its lift cylinder carries what a hand
// calculation of moments gives, and a slew start sets the hanging load swinging
// (the impulse rule of solver/integrate/simulation.h).

#include "solver/integrate/simulation.h"
#include "solver/kinematics/kinematics.h"
#include "solver/pipeline.h"

#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace solver;

namespace {

const std::string kCraneFile = std::string(PADROB_SOURCE_DIR) + "/models/knuckle_boom_crane.pad";

std::shared_ptr<const Model> compileCrane()
{
    CompiledModel loaded = compileFile(kCraneFile);
    EXPECT_TRUE(loaded.ok());
    return loaded.model;
}

using test::rk4;

constexpr double kG = 9.81;

}  // namespace

TEST(Crane, LoadsWithoutErrorsOrWarnings)
{
    CompiledModel loaded = compileFile(kCraneFile);
    ASSERT_TRUE(loaded.ok()) << (loaded.diagnostics.empty() ? "" : loaded.diagnostics.items()[0].format());
    EXPECT_TRUE(loaded.diagnostics.empty()) << loaded.diagnostics.items()[0].format();
    auto model = loaded.model;
    ASSERT_TRUE(model);
    EXPECT_EQ(model->nb, 6);
}

TEST(Crane, HoldsStillWithEveryValveClosed)
{
    auto model = compileCrane();
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-3));
    const Eigen::VectorXd q0 = sim.state().q;
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(2.0, ev, err)) << err;
    EXPECT_TRUE(ev.empty());  // no relief valve opens, no limit is hit
    EXPECT_LT((sim.state().q - q0).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT(sim.state().qd.cwiseAbs().maxCoeff(), 1e-9);
    // the passive swing joints included: the load hangs straight down
    EXPECT_NEAR(sim.state().q[model->jointIndex(5)], 0.0, 1e-9);
    EXPECT_NEAR(sim.state().q[model->jointIndex(6)], 0.0, 1e-9);
}

TEST(Crane, LiftCylinderForceAtRestMatchesMoments)
{
    auto model = compileCrane();
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-3));
    // booms exactly horizontal (θ = 0 for both T 1 joints), load hanging
    sim.setInitial(model->jointIndex(2), 0.0, 0.0);
    sim.setInitial(model->jointIndex(3), 0.0, 0.0);
    sim.evaluate();

    // Hand calculation, world x–z at this pose (see the model's header):
    // main boom pivot (0, 1.9). Horizontal distances of the weights from it:
    //   main boom 450 kg at 1.9 m, outer boom 320 kg at 5.4 m, extension 150 kg
    //   at 6.0 m, swivel 15 kg and load 500 kg under the hook pin at 7.25 m.
    const double moment = kG * (450 * 1.9 + 320 * 5.4 + 150 * 6.0 + (15 + 500) * 7.25);  // 70 796.3 N m
    // Lift cylinder from CL1 = column (0.30, 0, -0.70) → world (0.30, 0.30) to
    // CL2 = main boom (-0.8, 0, -0.25) → world (1.10, 1.65). Lever arm about the
    // pivot: |r × u| with r = CL2 − pivot = (1.10, -0.25), u = (0.80, 1.35)/L.
    const double length = std::hypot(0.80, 1.35);                   // 1.569235 m
    const double arm = (1.10 * 1.35 - (-0.25) * 0.80) / length;      // 1.073771 m
    const double expected = moment / arm;                            // 65 932.4 N
    EXPECT_NEAR(expected, 65932.4, 0.1);

    const double f2 = sim.data().driveForce[model->jointIndex(2)];
    EXPECT_NEAR(f2, expected, 1e-6 * expected);
    EXPECT_GT(f2, 0.0);  // the cylinder pushes

    // and the relief valves stay closed: far below FMAX = 28 MPa · π 0.110²/4
    EXPECT_LT(f2, 28e6 * std::numbers::pi * 0.110 * 0.110 / 4);
    EXPECT_LT(sim.data().driveForce[model->jointIndex(3)], 28e6 * std::numbers::pi * 0.140 * 0.140 / 4);

    // the fold cylinder likewise, about the knuckle (3.8, 1.9): outer boom at
    // 1.6 m, extension at 2.2 m, swivel and load at 3.45 m; CL1 (2.10, 1.62),
    // CL2 (4.25, 1.60), r = CL2 − knuckle = (0.45, -0.30).
    const double foldMoment = kG * (320 * 1.6 + 150 * 2.2 + (15 + 500) * 3.45);
    const double foldLength = std::hypot(2.15, 0.02);
    const double foldArm = (0.45 * (-0.02) - (-0.30) * 2.15) / foldLength;  // 0.295801 m
    const double f3 = sim.data().driveForce[model->jointIndex(3)];
    EXPECT_NEAR(f3, foldMoment / foldArm, 1e-6 * f3);
}

TEST(Crane, SlewStartSetsTheLoadSwinging)
{
    auto model = compileCrane();
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-4));
    const int slew = model->jointIndex(1), swingX = model->jointIndex(5), swingY = model->jointIndex(6);
    sim.setCommand(slew, 1.0);
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(1e-9, ev, err)) << err;

    // the valve opens at once: the ring turns at VMAX
    EXPECT_NEAR(sim.state().qd[slew], 0.28, 1e-12);
    // The hook pin (7.25 m from the slew axis) moves sideways (+y) at
    // v = 0.28 · 7.25 = 2.03 m/s. The free joints' generalized momentum stays 0
    // through the impulse: about the swing-x axis through the hook pin,
    //   Σ m_i d_i (v + d_i θ̇) + Σ I_i,xx θ̇ = 0   (a point at depth d moves +d θ̇ in y)
    // with the swivel (15 kg, d 0.05 m, Ixx 0.068) and the load (500 kg,
    // d 2.4 m, Ixx 41.667):
    const double v = 0.28 * 7.25;
    const double md = 15 * 0.05 + 500 * 2.4;
    const double J = 15 * 0.05 * 0.05 + 0.068 + 500 * 2.4 * 2.4 + 41.667;
    const double expected = -v * md / J;  // −0.8343 rad/s
    EXPECT_NEAR(sim.state().qd[swingX], expected, 1e-6 * std::abs(expected));
    EXPECT_GT(std::abs(sim.state().qd[swingX]), 0.8);
    EXPECT_NEAR(sim.state().qd[swingY], 0.0, 1e-9);  // no swing along the boom
    EXPECT_NEAR(sim.state().q[swingX], 0.0, 1e-9);   // no jump in position

    // The load's world velocity stays ~0 at that instant: only its own rotational
    // inertia about x (41.667 of 2921.7 kg m²) lets it move, at
    // v + 2.4 θ̇ = 2.03 − 2.4 · 0.8343 = 0.028 m/s, against 2.03 m/s at the hook pin.
    sim.evaluate();
    const Eigen::Vector3d vLoad = comVelocity(*model, sim.data(), model->bodyIndex(6));
    EXPECT_NEAR(vLoad.y(), v + 2.4 * expected, 1e-6);
    EXPECT_LT(vLoad.norm(), 0.015 * v);
    const Eigen::Vector3d vPin = comVelocity(*model, sim.data(), model->bodyIndex(5));
    EXPECT_GT(vPin.norm(), 0.9 * v);  // the swivel, 0.05 m under the pin, moves with it

    // and it keeps swinging: 0.5 s later it has swung out to one side
    ASSERT_TRUE(sim.advanceTo(0.5, ev, err)) << err;
    EXPECT_LT(sim.state().q[swingX], -0.2);
}
