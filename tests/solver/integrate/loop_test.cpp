// Closed loops in simulation (issue 4 item 1): the four-bar and the slider-crank
// of models/ against their analytic position solutions, constraint drift, energy,
// consistent initial rates, reactions at a loop-closing joint by hand, and a loop
// that locks up as an event.

#include "solver/dynamics/constraints.h"
#include "solver/dynamics/forward_dynamics.h"
#include "solver/integrate/simulation.h"
#include "solver/kinematics/kinematics.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

namespace solver {
namespace {

using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

using test::rk4;

/// Angle of body b's local x axis in the world x-y plane.
double planarAngle(const Data& d, int b)
{
    const Eigen::Matrix3d R = d.X_wb[b].linear();
    return std::atan2(R(1, 0), R(0, 0));
}

double wrapPi(double a) { return std::remainder(a, 2 * kPi); }

/// World distance between the two sides of each cut joint's points, and the
/// largest misalignment of their axes (|A1 × A2|), at the simulation's state.
void cutGaps(const Simulation& sim, double& gap, double& tilt)
{
    gap = tilt = 0;
    const Model& m = sim.model();
    const Data& d = sim.data();
    for (const CutJoint& c : m.cuts) {
        const Eigen::Isometry3d F1 = c.body1 < 0 ? c.X_1 : d.X_wb[c.body1] * c.X_1;
        const Eigen::Isometry3d F2 = c.body2 < 0 ? c.X_2 : d.X_wb[c.body2] * c.X_2;
        Vector3d delta = F2.translation() - F1.translation();
        double t = F1.linear().col(0).cross(F2.linear().col(0)).norm();
        if (c.type == JointType::Prismatic) {  // P2 slides along R1; the frames stay parallel
            const Vector3d r1 = F1.linear().col(1);
            delta -= delta.dot(r1) * r1;
            t = std::max(t, r1.cross(F2.linear().col(1)).norm());
        }
        gap = std::max(gap, delta.norm());
        tilt = std::max(tilt, t);
    }
}

// ---------------------------------------------------------------- four-bar

// models/four_bar.pad: ground O2–O4 d, crank a, coupler b, rocker c; open assembly
constexpr double kD = 0.40, kA = 0.10, kB = 0.35, kC = 0.30;

/// Coupler and rocker angles for crank angle t2 (open assembly, B on the left of A→O4).
void fourBarAnalytic(double t2, double& t3, double& t4)
{
    const Eigen::Vector2d A(kA * std::cos(t2), kA * std::sin(t2));
    const Eigen::Vector2d O4(kD, 0);
    const Eigen::Vector2d u = (O4 - A).normalized();
    const double e = (O4 - A).norm();
    const double along = (kB * kB - kC * kC + e * e) / (2 * e);
    const double h = std::sqrt(kB * kB - along * along);
    const Eigen::Vector2d B = A + along * u + h * Eigen::Vector2d(-u.y(), u.x());
    t3 = std::atan2(B.y() - A.y(), B.x() - A.x());
    t4 = std::atan2(B.y(), B.x() - kD);
}

TEST(Loops, FourBarFollowsItsAnalyticPositionsForTenSeconds)
{
    const auto model = test::compileExample("four_bar.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    sim.setCommand(m.jointIndex(1), 1.0);  // the motor turns the crank
    const int crank = m.bodyIndex(1), coupler = m.bodyIndex(2), rocker = m.bodyIndex(3);

    std::vector<SimulationEvent> ev;
    std::string err;
    double worstAngle = 0, worstGap = 0, worstTilt = 0, worstRate = 0;
    double t4min = 1e9, t4max = -1e9;
    double turned = 0;
    for (int k = 1; k <= 1000; ++k) {
        ASSERT_TRUE(sim.advanceTo(0.01 * k, ev, err)) << err;
        const Data& d = sim.data();
        const double t2 = planarAngle(d, crank);
        double t3, t4;
        fourBarAnalytic(t2, t3, t4);
        worstAngle = std::max({worstAngle, std::abs(wrapPi(planarAngle(d, coupler) - t3)),
                               std::abs(wrapPi(planarAngle(d, rocker) - t4))});
        double gap, tilt;
        cutGaps(sim, gap, tilt);
        worstGap = std::max(worstGap, gap);
        worstTilt = std::max(worstTilt, tilt);
        // velocity of pin B seen from the coupler and from the rocker
        const CutJoint& cut = m.cuts[0];
        const Vector3d vb1 = bodyPointVelocity(d, cut.body1, cut.X_1.translation());
        const Vector3d vb2 = bodyPointVelocity(d, cut.body2, cut.X_2.translation());
        worstRate = std::max(worstRate, (vb1 - vb2).norm());
        const double deg4 = std::fmod(t4 / kDeg + 360, 360);
        t4min = std::min(t4min, deg4);
        t4max = std::max(t4max, deg4);
        turned = sim.state().q[m.jointIndex(1)];
    }
    EXPECT_LT(worstAngle, 1e-9);
    EXPECT_LT(worstGap, 1e-9);   // constraint drift over 10 s [m]
    EXPECT_LT(worstTilt, 1e-9);
    EXPECT_LT(worstRate, 1e-9);  // [m/s]
    ASSERT_GT(turned, 2 * 2 * kPi) << "the crank should turn several times in 10 s";
    // the rocker swings between the analytic extremes (sampled every 10 ms)
    EXPECT_NEAR(t4min, 101.415158, 0.05);
    EXPECT_NEAR(t4max, 141.375167, 0.05);
    EXPECT_GE(t4min, 101.415158 - 1e-6);
    EXPECT_LE(t4max, 141.375167 + 1e-6);
}

TEST(Loops, InitialRatesOfDependentCoordinatesFollowTheLoop)
{
    // slider-crank: crank VI = 2π rad/s; the rod's and piston's rates by hand (model header)
    const auto model = test::compileExample("slider_crank.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    const State& s = sim.state();
    EXPECT_DOUBLE_EQ(s.qd[m.jointIndex(1)], 6.2831853);  // VI kept
    EXPECT_NEAR(s.qd[m.jointIndex(2)], -7.2095904, 1e-6);
    const int piston = m.bodyIndex(3);
    EXPECT_NEAR(sim.data().vel[piston].x(), -0.6243688, 1e-6);
    EXPECT_NEAR(sim.data().vel[piston].y(), 0.0, 1e-12);
}

TEST(Loops, SliderCrankFollowsItsAnalyticStrokeAndKeepsItsEnergy)
{
    const auto model = test::compileExample("slider_crank.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    SimulationOptions o = rk4(1e-3);
    o.drives = false;  // free motion: energy is conserved
    Simulation sim(model, o);
    const int crank = m.bodyIndex(1), piston = m.bodyIndex(3);
    constexpr double r = 0.10, l = 0.35;
    const double e0 = kineticEnergy(m, sim.data()) + potentialEnergy(m, sim.data());

    std::vector<SimulationEvent> ev;
    std::string err;
    double worstX = 0, worstV = 0, worstE = 0, worstGap = 0, worstY = 0;
    for (int k = 1; k <= 1000; ++k) {
        ASSERT_TRUE(sim.advanceTo(0.01 * k, ev, err)) << err;
        const Data& d = sim.data();
        const double t2 = planarAngle(d, crank);
        const double w = d.omega[crank].z();
        const double root = std::sqrt(l * l - r * r * std::sin(t2) * std::sin(t2));
        const double x = r * std::cos(t2) + root;
        const double xd = -r * w * std::sin(t2) * (1 + r * std::cos(t2) / root);
        const Vector3d pin = d.X_wb[piston].translation();  // the piston's origin is its pin B
        worstX = std::max(worstX, std::abs(pin.x() - x));
        worstY = std::max({worstY, std::abs(pin.y()), std::abs(pin.z())});
        worstV = std::max(worstV, std::abs(d.vel[piston].x() - xd));
        const double e = kineticEnergy(m, d) + potentialEnergy(m, d);
        worstE = std::max(worstE, std::abs(e - e0) / e0);
        double gap, tilt;
        cutGaps(sim, gap, tilt);
        worstGap = std::max({worstGap, gap, tilt});
    }
    EXPECT_LT(worstX, 1e-9);
    EXPECT_LT(worstY, 1e-9);
    EXPECT_LT(worstV, 1e-9);
    EXPECT_LT(worstGap, 1e-9);
    EXPECT_LT(worstE, 1e-6) << "relative energy drift over 10 s";
}

TEST(Loops, DriftShrinksWithTheStepBeforeProjection)
{
    // what the projection removes after one step: RK4's local error, O(h^5)
    const auto model = test::compileExample("slider_crank.pad");
    ASSERT_TRUE(model);
    auto oneStepGap = [&](double h) {
        SimulationOptions oh = rk4(h);
        oh.drives = false;
        Simulation sim(model, oh);
        // integrate without projection: the dynamics alone, one RK4 step by hand
        State s = sim.state();
        Data d(*model);
        auto f = [&](const State& st, Eigen::VectorXd& qd, Eigen::VectorXd& qdd) {
            forwardKinematics(*model, st, d);
            clearAppliedForces(d);
            hybridDynamics(*model, st, d);
            qd = st.qd;
            qdd = d.qdd;
        };
        Eigen::VectorXd k1q, k1v, k2q, k2v, k3q, k3v, k4q, k4v;
        State st = s;
        f(st, k1q, k1v);
        st.q = s.q + h / 2 * k1q;
        st.qd = s.qd + h / 2 * k1v;
        f(st, k2q, k2v);
        st.q = s.q + h / 2 * k2q;
        st.qd = s.qd + h / 2 * k2v;
        f(st, k3q, k3v);
        st.q = s.q + h * k3q;
        st.qd = s.qd + h * k3v;
        f(st, k4q, k4v);
        st.q = s.q + h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
        forwardKinematics(*model, st, d);
        collectConstraints(*model, st, d.constraints);
        Eigen::VectorXd phi;
        constraintResidual(*model, d, d.constraints, phi);
        return phi.norm();
    };
    const double g1 = oneStepGap(4e-3), g2 = oneStepGap(2e-3);
    ASSERT_GT(g1, 0);
    // local error of a 4th-order method: halving h divides it by about 2^5
    EXPECT_GT(g1 / g2, 16.0) << g1 << " " << g2;
    EXPECT_LT(g1 / g2, 64.0) << g1 << " " << g2;
}

// ---------------------------------------------------------------- reactions

/// A 3 m beam of 120 kg pinned to the ground at both ends (x = 0 and x = 3), its
/// centre of mass at x = 1 m: statically, the far pin (the loop-closing joint)
/// carries m g · 1/3 and the near pin m g · 2/3, both upwards.
const std::string kBeam = R"(GRAVITY 0 0 -9.81
B 1 120 1 90 90 CG 1 0 0
C 1 NAME "near pin"
B1 0 P1 0 0 0 A1 0 1 0 R1 1 0 0
B2 1 P2 0 0 0 A2 0 1 0 R2 1 0 0
C 2 NAME "far pin"
B1 1 P1 3 0 0 A1 0 1 0 R1 1 0 0
B2 0 P2 3 0 0 A2 0 1 0 R2 1 0 0
)";

TEST(Loops, ReactionsAtTheLoopClosingJointByHand)
{
    const auto model = test::compileText(kBeam, "beam.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    ASSERT_EQ(m.cuts.size(), 1u);
    Simulation sim(model, rk4(1e-3));
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(1.0, ev, err)) << err;
    const Data& d = sim.data();
    const double w = 120 * 9.81;
    EXPECT_NEAR(sim.state().q[0], 0.0, 1e-12);  // nothing moves
    EXPECT_NEAR(d.qdd[0], 0.0, 1e-12);
    // the far pin: B1 is the beam, B2 the ground; the load side 1 puts on side 2 is
    // the beam pressing down on the ground (−z), i.e. the ground holds it up with +w/3
    ASSERT_EQ(d.constraintReactionWorld.size(), 1u);
    const Vector6d far = d.constraintReactionWorld[0];
    EXPECT_NEAR(far[5], -w / 3, 1e-6 * w);
    EXPECT_NEAR(far[3], 0.0, 1e-6 * w);
    // the near pin (a tree joint): the ground holds the beam up with 2w/3
    EXPECT_NEAR(d.reactionWorld[0][5], 2 * w / 3, 1e-6 * w);
    // the moments about the pins' own axes (y) vanish: they are pins
    EXPECT_NEAR(far[1], 0.0, 1e-6 * w);
    EXPECT_NEAR(d.reactionWorld[0][1], 0.0, 1e-6 * w);
}

TEST(Loops, ConstraintLoadsBalanceEveryFreeJoint)
{
    // the loads λ·W that the loop puts on its two bodies must give, through the tree's
    // backward pass, exactly the generalized force each free joint has: the motor's
    // torque on the crank, nothing on the passive joints (a check that G and the loads
    // W agree, and that M θ̈ + C = τ + Gᵀλ is solved)
    const auto model = test::compileExample("four_bar.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    sim.setCommand(m.jointIndex(1), 0.7);
    std::vector<SimulationEvent> ev;
    std::string err;
    for (double t : {0.05, 0.37, 1.0}) {
        ASSERT_TRUE(sim.advanceTo(t, ev, err)) << err;
        const Data& d = sim.data();
        const double w = std::abs(sim.state().qd[m.jointIndex(1)]);
        const double motor = 0.7 * 0.5 * std::max(0.0, 1 - w / 10.472);  // 0 beyond W0
        EXPECT_NEAR(d.tau[m.jointIndex(1)], motor, 1e-9);
        EXPECT_NEAR(d.driveForce[m.jointIndex(1)], motor, 1e-12);
        EXPECT_NEAR(d.tau[m.jointIndex(2)], 0.0, 1e-9);
        EXPECT_NEAR(d.tau[m.jointIndex(3)], 0.0, 1e-9);
        // and the pin B reaction is a pure force in the plane (moments about the
        // pin's axis vanish)
        ASSERT_EQ(d.constraintReactionJoint.size(), 1u);
        EXPECT_NEAR(d.constraintReactionJoint[0][0], 0.0, 1e-9);
    }
}

// ---------------------------------------------------------------- lock-up

TEST(Loops, ALoopThatLocksUpIsAnEventNotACrash)
{
    // the slider-crank pushed by a hydraulic cylinder on its piston towards the dead
    // centre x = r + l = 0.45 m: from 0.3891 m at 0.1 m/s the crank cannot follow at
    // t = (0.45 − x0)/0.1 ≈ 0.609 s
    std::string text = [] {
        std::ifstream in(test::modelPath("slider_crank.pad"));
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }();
    const auto motor = text.find("D 1 MOTOR");
    if (motor != std::string::npos) text.erase(motor, text.find('\n', motor) - motor);
    const auto c4 = text.find("C 4 ");
    ASSERT_NE(c4, std::string::npos);
    text.insert(c4 + 4, "LL 0.2 UL 0.46 ");
    text += "\nD 4 HYD VMAX 0.1\n";
    const auto model = test::compileText(text, "sc.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, rk4(1e-3));
    sim.setCommand(m.jointIndex(4), 1.0);
    const double x0 = sim.state().q[m.jointIndex(4)];
    std::vector<SimulationEvent> ev;
    std::string err;
    bool ok = true;
    for (int k = 1; k <= 100 && ok; ++k) ok = sim.advanceTo(0.01 * k, ev, err);
    ASSERT_FALSE(ok);
    EXPECT_TRUE(sim.locked());
    EXPECT_NE(err.find("locked up"), std::string::npos) << err;
    ASSERT_FALSE(ev.empty());
    EXPECT_EQ(ev.back().kind, SimulationEvent::Kind::LoopLocked);
    EXPECT_NE(ev.back().describe(m).find("piston pin B"), std::string::npos) << ev.back().describe(m);
    const double tLock = (0.45 - x0) / 0.1;
    EXPECT_NEAR(ev.back().t, tLock, 0.01);
    EXPECT_LE(ev.back().t, tLock + 1e-9);
    // the state is kept, finite, on the loop
    EXPECT_TRUE(sim.state().q.allFinite());
    EXPECT_TRUE(sim.state().qd.allFinite());
    double gap, tilt;
    cutGaps(sim, gap, tilt);
    EXPECT_LT(gap, 1e-6);
    // and it stays stopped
    EXPECT_FALSE(sim.advanceTo(2.0, ev, err));
}

}  // namespace
}  // namespace solver
