// Drive faults (issue 10): a burst hose leaves a hydraulic joint passive (or damped, or
// bounded by a residual force) in this Simulation only. Checked against physics: the
// same model with that joint passive, the analytic acceleration of a held arm let go,
// the terminal velocity of a damped fall, and the liner manipulator's boom sagging.

#include "solver/integrate/simulation.h"

#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace solver;
using test::rk4;

namespace {

// a 10 kg arm, its centre of mass 1 m out along y, on a horizontal pin (x); I_x at the
// centre of mass 0.1 kg m²; a hydraulic rotary actuator holds it level (98.1 N m)
const std::string kArm = R"(
GRAVITY 0 0 -9.81
B 1 10 0.1 0.1 0.1 CG 0 1 0 NAME "arm"
C 1 LL -1.2 UL 1.2 QI 0 NAME "shoulder"
B1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0
)";
const std::string kArmDrive = "D 1 HYD VMAX 0.5 FMAX 1000\n";

// 100 kg on a vertical cylinder (981 N to hold)
const std::string kLift = R"(
B 1 100 1 1 1
C 1 T 2 LL 0 UL 1 QI 0.5
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1
D 1 HYD VMAX 0.1 FMAX 2000
)";

bool advance(Simulation& sim, double t, std::vector<SimulationEvent>& ev)
{
    std::string err;
    const bool ok = sim.advanceTo(t, ev, err);
    EXPECT_TRUE(ok) << err;
    return ok;
}

/// A copy of `model` with joint j's drive removed (passive).
std::shared_ptr<const Model> withoutDrive(const Model& model, int j)
{
    auto m = std::make_shared<Model>(model);
    m->drive[std::size_t(j)] = CompiledDrive{};
    return m;
}

}  // namespace

TEST(DriveFault, ABurstHoseLetsAHeldArmFallAsIfItsJointWerePassive)
{
    auto model = test::compileText(kArm + kArmDrive);
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-3));
    std::vector<SimulationEvent> ev;
    ASSERT_TRUE(advance(sim, 0.5, ev));
    EXPECT_NEAR(sim.state().q[0], 0.0, 1e-12);  // held level
    EXPECT_NEAR(sim.data().driveForce[0], 98.1, 1e-9);

    ASSERT_TRUE(sim.setDriveFault(0, DriveFault{}));
    ASSERT_NE(sim.driveFault(0), nullptr);
    EXPECT_EQ(sim.model().drive[0].type, DriveType::Hydraulic);  // the model as compiled
    sim.setCommand(0, 1.0);  // the operator pulls the lever: nothing happens
    ASSERT_TRUE(advance(sim, 0.501, ev));
    // let go from rest: θ̈ = −m g L / (I_x + m L²)
    const double alpha = -10 * 9.81 * 1.0 / (0.1 + 10 * 1.0);
    EXPECT_NEAR(sim.data().qdd[0], alpha, 1e-2 * std::abs(alpha));
    EXPECT_LT(sim.state().qd[0], 0.0);  // down, where gravity pulls
    EXPECT_NEAR(sim.data().driveForce[0], 0.0, 1e-12);

    // the same arm without a drive, let go from the same state, moves the same way
    Simulation passive(withoutDrive(*model, 0), rk4(1e-3));
    std::vector<SimulationEvent> pev;
    for (int k = 1; k <= 300; ++k) {
        ASSERT_TRUE(advance(passive, 0.001 * k, pev));
        if (k > 1) {
            ASSERT_TRUE(advance(sim, 0.5 + 0.001 * k, ev));
        }
        if (k % 50 == 0) {
            EXPECT_NEAR(sim.state().q[0], passive.state().q[0], 1e-9) << k;
            EXPECT_NEAR(sim.state().qd[0], passive.state().qd[0], 1e-9) << k;
        }
    }
    EXPECT_LT(sim.state().q[0], -0.3);
    EXPECT_TRUE(ev.empty());

    // repaired while falling: the valve closed at u = 0 holds it where it is
    sim.setCommand(0, 0.0);
    ASSERT_TRUE(sim.clearDriveFault(0));
    EXPECT_EQ(sim.driveFault(0), nullptr);
    EXPECT_FALSE(sim.clearDriveFault(0));
    ASSERT_TRUE(advance(sim, 0.801, ev));
    const double held = sim.state().q[0];
    ASSERT_TRUE(advance(sim, 1.3, ev));
    EXPECT_NEAR(sim.state().q[0], held, 1e-12);
    EXPECT_NEAR(sim.state().qd[0], 0.0, 1e-15);
    EXPECT_NEAR(sim.data().driveForce[0], 98.1 * std::cos(held), 1e-6);
    EXPECT_TRUE(ev.empty());
    // and the command acts again: q̇ = u·vmax
    sim.setCommand(0, 0.6);
    ASSERT_TRUE(advance(sim, 1.8, ev));
    EXPECT_NEAR(sim.state().qd[0], 0.3, 1e-12);
    EXPECT_NEAR(sim.state().q[0], held + 0.3 * 0.5, 1e-9);
}

TEST(DriveFault, TheOperatorsCommandDoesNothingToABurstDriveAndItFallsToItsLimit)
{
    auto model = test::compileText(kArm + kArmDrive);
    ASSERT_TRUE(model);
    std::vector<double> q;
    for (double u : {1.0, -1.0, 0.0}) {
        Simulation sim(model, rk4(1e-3));
        ASSERT_TRUE(sim.setDriveFault(0, DriveFault{}));
        std::vector<SimulationEvent> ev;
        for (int k = 1; k <= 2000; ++k) {
            sim.setCommand(0, u * std::sin(0.01 * k));
            ASSERT_TRUE(advance(sim, 0.001 * k, ev));
            if (k == 300) q.push_back(sim.state().q[0]);  // on the way down
        }
        // it swung down onto its lower limit and stays there (inelastic stop)
        ASSERT_FALSE(ev.empty());
        EXPECT_EQ(ev.front().kind, SimulationEvent::Kind::LimitHit);
        EXPECT_EQ(ev.front().side, -1);
        EXPECT_NEAR(sim.state().q[0], -1.2, 1e-12);
    }
    ASSERT_EQ(q.size(), 3u);
    EXPECT_LT(q[0], -0.2);
    EXPECT_NEAR(q[0], q[1], 1e-12);
    EXPECT_NEAR(q[0], q[2], 1e-12);
}

TEST(DriveFault, OilEscapingDampsTheFallAndAResidualPressureSlowsIt)
{
    auto model = test::compileText(kLift);
    ASSERT_TRUE(model);
    {
        // viscous: m v̇ = −m g − c v, terminal velocity −m g / c, time constant m / c
        const double c = 4000, vt = -100 * 9.81 / c, tau = 100 / c;
        Simulation sim(model, rk4(1e-4));
        ASSERT_TRUE(sim.setDriveFault(0, DriveFault{c}));
        std::vector<SimulationEvent> ev;
        ASSERT_TRUE(advance(sim, 0.05, ev));
        EXPECT_NEAR(sim.state().qd[0], vt * (1 - std::exp(-0.05 / tau)), 1e-8);
        ASSERT_TRUE(advance(sim, 0.4, ev));
        EXPECT_NEAR(sim.state().qd[0], vt, 1e-6);
        EXPECT_NEAR(sim.data().driveForce[0], 981.0, 1e-3);  // the escaping oil carries the load
    }
    {
        // a residual of 500 N (and a steep damping law that reaches it at once): the load
        // sinks at (500 − 981) / 100 m/s²
        Simulation sim(model, rk4(1e-4));
        ASSERT_TRUE(sim.setDriveFault(0, DriveFault{1e6, 500.0}));
        std::vector<SimulationEvent> ev;
        ASSERT_TRUE(advance(sim, 0.2, ev));
        const double a = (500.0 - 981.0) / 100.0;
        EXPECT_NEAR(sim.state().qd[0], a * 0.2, 1e-3);
        EXPECT_NEAR(sim.data().driveForce[0], 500.0, 1e-9);
    }
}

TEST(DriveFault, OnlyAHydraulicDriveCanBurstAndBadValuesAreRefused)
{
    auto model = test::compileText(kArm + "D 1 MOTOR T0 20 W0 3\n");
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-3));
    EXPECT_FALSE(sim.setDriveFault(0, DriveFault{}));  // a motor has no hose
    EXPECT_FALSE(sim.setDriveFault(1, DriveFault{}));
    EXPECT_FALSE(sim.setDriveFault(-1, DriveFault{}));
    EXPECT_EQ(sim.driveFault(0), nullptr);
    auto hyd = test::compileText(kLift);
    ASSERT_TRUE(hyd);
    Simulation h(hyd, rk4(1e-3));
    EXPECT_FALSE(h.setDriveFault(0, DriveFault{-1.0}));
    EXPECT_FALSE(h.setDriveFault(0, DriveFault{0.0, std::nan("")}));
    EXPECT_EQ(h.driveFault(0), nullptr);
    EXPECT_FALSE(h.clearDriveFault(0));
    // a second Simulation of the same model is not affected by the first one's fault
    ASSERT_TRUE(h.setDriveFault(0, DriveFault{}));
    Simulation other(hyd, rk4(1e-3));
    std::vector<SimulationEvent> ev;
    ASSERT_TRUE(advance(h, 0.1, ev));
    ASSERT_TRUE(advance(other, 0.1, ev));
    EXPECT_NEAR(h.state().q[0], 0.5 - 0.5 * 9.81 * 0.01, 1e-9);
    EXPECT_NEAR(other.state().q[0], 0.5, 1e-12);
}

TEST(DriveFault, TheLinerManipulatorsBoomSagsAsIfItsCylinderWerePassive)
{
    auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const int boom = model->jointIndex(2);  // LEVANTE PLUMA, T 1
    Simulation sim(model, rk4(1e-3));
    std::vector<SimulationEvent> ev;
    ASSERT_TRUE(advance(sim, 0.2, ev));
    const Eigen::VectorXd q0 = sim.state().q;
    ASSERT_GT(sim.data().driveForce[boom], 0.0);  // the cylinder pushes to hold the boom
    const double L0 = model->coordinate(boom, q0[boom]);

    ASSERT_TRUE(sim.setDriveFault(boom, DriveFault{}));
    Simulation passive(withoutDrive(*model, boom), rk4(1e-3));
    std::vector<SimulationEvent> pev;
    for (int k = 1; k <= 150; ++k) {
        sim.setCommand(boom, 1.0);  // lifting does nothing
        ASSERT_TRUE(advance(sim, 0.2 + 0.001 * k, ev));
        ASSERT_TRUE(advance(passive, 0.001 * k, pev));
    }
    // the cylinder is pushed in by the boom's weight
    const double L = model->coordinate(boom, sim.state().q[boom]);
    EXPECT_LT(L, L0 - 1e-3);
    EXPECT_NEAR(sim.state().q[boom], passive.state().q[boom], 1e-9);
    EXPECT_NEAR(sim.state().qd[boom], passive.state().qd[boom], 1e-9);
    // the other drives still hold
    for (int j = 0; j < model->nb; ++j) {
        if (j != boom) {
            EXPECT_NEAR(sim.state().q[j], q0[j], 1e-12) << j;
        }
    }
    // until its stop (LL 1.4 m)
    ASSERT_TRUE(advance(sim, 4.0, ev));
    bool stopped = false;
    for (const SimulationEvent& e : ev) stopped = stopped || (e.kind == SimulationEvent::Kind::LimitHit && e.joint == boom);
    EXPECT_TRUE(stopped);
    EXPECT_NEAR(model->coordinate(boom, sim.state().q[boom]), 1.4, 1e-9);
    // repaired: it lifts again at its speed
    ASSERT_TRUE(sim.clearDriveFault(boom));
    sim.setCommand(boom, 1.0);
    ASSERT_TRUE(advance(sim, 5.0, ev));
    EXPECT_NEAR(model->coordinate(boom, sim.state().q[boom]), 1.4 + model->drive[boom].vmax * 1.0, 1e-6);
}
