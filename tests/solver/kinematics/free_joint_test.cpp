// Free joints (C id T 3; core/model.h "Free joints", docs/free-bodies.md): a body in six
// degrees of freedom, as six tree coordinates turning from a base quaternion. Checked
// against closed forms (the parabola, conserved momentum and energy), an independent
// integration of Euler's rigid-body equations in quaternion form, the thesis's
// Newton–Euler reference, and the errors a modeler can make.

#include "solver/core/state.h"
#include "solver/dynamics/applied_forces.h"
#include "solver/dynamics/forward_dynamics.h"
#include "solver/integrate/simulation.h"
#include "solver/kinematics/kinematics.h"
#include "solver/pipeline.h"
#include "solver/reference/newton_euler.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace solver {
namespace {

using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

// a block free in space; its joint frame on the ground tilted (A1 along y, R1 along z),
// its joint point off the centre of mass, products of inertia
const std::string kBlock = R"pad(GRAVITY 0 0 -9.81
B 1 3.0 0.1 0.2 0.25 0.01 -0.02 0.015 NAME "block"
C 7 T 3 NAME "free"
B1 0 P1 0.5 -0.2 2.0 A1 0 1 0 R1 0 0 1
B2 1 P2 0.1 0.2 -0.3 A2 1 0 0 R2 0 1 0
)pad";

std::string withGravity(std::string text, const std::string& g)
{
    text.replace(text.find("0 0 -9.81"), 9, g);
    return text;
}

Vector3d rotationError(const Matrix3d& a, const Matrix3d& b)
{
    const Eigen::AngleAxisd d(a.transpose() * b);
    return d.angle() * d.axis();
}

TEST(FreeJoint, CompilesIntoSixCoordinatesAndABaseQuaternion)
{
    const CompiledModel c = compileText(kBlock, "block.pad");
    ASSERT_TRUE(c.model);
    const Model& m = *c.model;
    EXPECT_EQ(m.nb, 6);
    EXPECT_EQ(m.nq, 10);
    EXPECT_EQ(m.freeJoints, std::vector<int>{0});
    EXPECT_EQ(m.jointIndex(7), 0);
    EXPECT_EQ(m.bodyIndex(1), 5);
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(m.freeSlot[i], i);
        EXPECT_EQ(m.jointType[i], i < 3 ? JointType::Prismatic : JointType::Revolute);
        EXPECT_EQ(m.bodyId[i], i < 5 ? -1 : 1);
        EXPECT_EQ(m.mass[i], i < 5 ? 0.0 : 3.0);
    }
    EXPECT_EQ(m.freeBase[3], 6);
    const State s = makeState(m);
    EXPECT_EQ(s.q.size(), 10);
    EXPECT_EQ(s.q.tail<4>(), Eigen::Vector4d(1, 0, 0, 0));
    EXPECT_EQ(c.topology->dof, 6);
    EXPECT_EQ(c.topology->independent, std::vector<int>{0});

    // at the start B2's joint frame is B1's: the body frame at P1 − R·P2
    Data d(m);
    forwardKinematics(m, s, d);
    const Matrix3d F1 = (Matrix3d() << 0, 0, 1, 1, 0, 0, 0, 1, 0).finished();  // A1, R1, A1×R1 as columns
    EXPECT_TRUE(d.X_wb[5].linear().isApprox(F1, 1e-15));
    EXPECT_TRUE(d.X_wb[5].translation().isApprox(Vector3d(0.5, -0.2, 2.0) - F1 * Vector3d(0.1, 0.2, -0.3), 1e-15));
    const FreeJointMotion start = freeJointMotion(m, d, s.q, s.qd, 0);
    EXPECT_LT(start.position.norm(), 1e-15);
}

// gravity along −z and a tilted joint frame: the body falls along the parabola, and the
// output columns are its translation along B1's joint axes (RK4 integrates a
// quadratic exactly)
TEST(FreeJoint, FallsAlongTheParabolaInItsJointFramesAxes)
{
    const auto model = test::compileText(kBlock, "block.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, test::rk4(1e-3));
    // thrown: 2 m/s along A1 (world y), 3 m/s up along R1 (world z)
    sim.setInitial(0, 0, 2.0);
    sim.setInitial(1, 0, 3.0);
    std::vector<SimulationEvent> ev;
    std::string err;
    const Vector3d c0 = comPosition(m, sim.data(), 5);
    ASSERT_TRUE(sim.advanceTo(1.5, ev, err)) << err;
    const double t = 1.5, g = 9.81;
    const Vector3d expected = c0 + Vector3d(0, 2.0 * t, 3.0 * t - 0.5 * g * t * t);
    EXPECT_LT((comPosition(m, sim.data(), 5) - expected).norm(), 1e-11);
    const FreeJointMotion out = freeJointMotion(m, sim.data(), sim.state().q, sim.state().qd, 0);
    EXPECT_NEAR(out.position[0], 2.0 * t, 1e-11);                       // along A1 = y
    EXPECT_NEAR(out.position[1], 3.0 * t - 0.5 * g * t * t, 1e-11);     // along R1 = z
    EXPECT_NEAR(out.position[2], 0.0, 1e-11);                           // along A1×R1 = x
    EXPECT_NEAR(out.velocity[1], 3.0 - g * t, 1e-11);
    // no turn: the orientation is the start's
    EXPECT_LT(rotationError(sim.data().X_wb[5].linear(), Matrix3d((Matrix3d() << 0, 0, 1, 1, 0, 0, 0, 1, 0).finished()))
                  .norm(),
              1e-12);
}

/// An independent reference: Euler's equations of a rigid body about its centre of
/// mass, body axes, with the orientation as a unit quaternion; classic RK4 at step h.
struct RigidBody {
    Quaterniond q;   // body → world
    Vector3d w;      // angular velocity, body axes
    Matrix3d I, Iinv;

    void derivative(const Quaterniond& qq, const Vector3d& ww, Eigen::Vector4d& dq, Vector3d& dw) const
    {
        const Quaterniond omega(0, ww.x(), ww.y(), ww.z());
        const Quaterniond r = qq * omega;
        dq = 0.5 * Eigen::Vector4d(r.w(), r.x(), r.y(), r.z());
        dw = Iinv * (-ww.cross(I * ww));
    }

    void step(double h)
    {
        auto add = [](const Quaterniond& a, const Eigen::Vector4d& d, double s) {
            return Quaterniond(a.w() + s * d[0], a.x() + s * d[1], a.y() + s * d[2], a.z() + s * d[3]);
        };
        Eigen::Vector4d k1q, k2q, k3q, k4q;
        Vector3d k1w, k2w, k3w, k4w;
        derivative(q, w, k1q, k1w);
        derivative(add(q, k1q, h / 2), w + h / 2 * k1w, k2q, k2w);
        derivative(add(q, k2q, h / 2), w + h / 2 * k2w, k3q, k3w);
        derivative(add(q, k3q, h), w + h * k3w, k4q, k4w);
        q = add(q, k1q + 2 * k2q + 2 * k3q + k4q, h / 6).normalized();
        w += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
    }
};

// spun mostly about its intermediate principal axis (the tennis-racket theorem: it
// flips over and over, through every Euler angle's gimbal lock), without gravity: the
// real-time RK4 at 1 ms follows the independent reference, and keeps the angular
// momentum (world) and the energy
TEST(FreeJoint, TumblingFollowsEulersEquationsAndKeepsMomentumAndEnergy)
{
    const auto model = test::compileText(withGravity(kBlock, "0 0 0"), "block.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, test::rk4(1e-3));
    // rates of the turns = the angular velocity in B1's joint axes at the start
    const Vector3d omega0(0.05, 6.0, 0.08);
    for (int a = 0; a < 3; ++a) sim.setInitial(3 + a, 0, omega0[a]);
    sim.setInitial(2, 0, 0.4);
    const Data& d = sim.data();
    const int b = 5;

    RigidBody ref;
    const Matrix3d R0 = d.X_wb[b].linear();
    ref.q = Quaterniond(R0);
    ref.w = R0.transpose() * d.omega[b];
    ref.I = m.inertia[b];
    ref.Iinv = ref.I.inverse();
    const Vector3d c0 = comPosition(m, d, b), v0 = comVelocity(m, d, b);
    auto momentum = [&](const Data& data) {
        const Matrix3d R = data.X_wb[b].linear();
        return Vector3d(R * m.inertia[b] * R.transpose() * data.omega[b]);
    };
    const Vector3d L0 = momentum(d);
    const double E0 = kineticEnergy(m, d);

    std::vector<SimulationEvent> ev;
    std::string err;
    double largestTurn = 0, turned = 0;
    Matrix3d last = R0;
    for (int k = 1; k <= 200; ++k) {
        const double t = 0.05 * k;
        ASSERT_TRUE(sim.advanceTo(t, ev, err)) << err;
        for (int s = 0; s < 500; ++s) ref.step(1e-4);
        const Matrix3d R = d.X_wb[b].linear();
        ASSERT_LT(rotationError(R, ref.q.toRotationMatrix()).norm(), 2e-7) << "t = " << t;
        ASSERT_LT((comPosition(m, d, b) - (c0 + v0 * t)).norm(), 1e-8) << "t = " << t;
        ASSERT_LT((momentum(d) - L0).norm(), 1e-8 * L0.norm()) << "t = " << t;
        ASSERT_NEAR(kineticEnergy(m, d), E0, 1e-8 * E0) << "t = " << t;
        for (int a = 3; a < 6; ++a) largestTurn = std::max(largestTurn, std::abs(sim.state().q[a]));
        turned += rotationError(last, R).norm();
        last = R;
        // the base quaternion stays a unit one
        ASSERT_NEAR(sim.state().q.segment<4>(6).norm(), 1.0, 1e-12);
    }
    // it did tumble (the axis flipped: the body-axis y rate changed sign), and the
    // turns stayed far from gimbal lock
    EXPECT_GT(turned, 40.0);
    EXPECT_LT(largestTurn, 0.5);
    EXPECT_LT(ref.w.y() * omega0.y(), 0.0) << "the reference did not flip within 10 s: " << ref.w.transpose();
}

// the error-controlled integrator (SUNDIALS) on the same tumbling: closer still
TEST(FreeJoint, TheAdaptiveIntegratorFollowsTheReferenceToo)
{
    const auto model = test::compileText(withGravity(kBlock, "0 0 0"), "block.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    SimulationOptions o;
    o.integrator.method = IntegrationMethod::Adaptive;
    o.integrator.rtol = 1e-11;
    o.integrator.atol = 1e-13;
    Simulation sim(model, o);
    const Vector3d omega0(0.05, 6.0, 0.08);
    for (int a = 0; a < 3; ++a) sim.setInitial(3 + a, 0, omega0[a]);
    const Data& d = sim.data();
    RigidBody ref;
    ref.q = Quaterniond(d.X_wb[5].linear());
    ref.w = d.X_wb[5].linear().transpose() * d.omega[5];
    ref.I = m.inertia[5];
    ref.Iinv = ref.I.inverse();
    std::vector<SimulationEvent> ev;
    std::string err;
    for (int k = 1; k <= 30; ++k) {
        ASSERT_TRUE(sim.advanceTo(0.1 * k, ev, err)) << err;
        for (int s = 0; s < 1000; ++s) ref.step(1e-4);
        ASSERT_LT(rotationError(d.X_wb[5].linear(), ref.q.toRotationMatrix()).norm(), 2e-8) << "t = " << 0.1 * k;
    }
}

// folding the turns into the base changes the coordinates, never the motion
TEST(FreeJoint, FoldingTheTurnsKeepsPoseAndVelocities)
{
    const auto model = test::compileText(kBlock, "block.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    for (int trial = 0; trial < 50; ++trial) {
        State s = makeState(m);
        for (int i = 0; i < 6; ++i) {
            s.q[i] = u(rng);
            s.qd[i] = 3 * u(rng);
        }
        s.q.segment<4>(6) = Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized();
        Data before(m), after(m);
        forwardKinematics(m, s, before);
        State folded = s;
        ASSERT_TRUE(foldFreeRotations(m, folded, 0.0));
        EXPECT_EQ(folded.q.segment<3>(3), Vector3d::Zero());
        forwardKinematics(m, folded, after);
        EXPECT_TRUE(after.X_wb[5].isApprox(before.X_wb[5], 1e-13));
        EXPECT_TRUE(after.omega[5].isApprox(before.omega[5], 1e-13));
        EXPECT_TRUE(after.vel[5].isApprox(before.vel[5], 1e-13));
        // a threshold above every turn folds nothing
        State kept = s;
        EXPECT_FALSE(foldFreeRotations(m, kept, 2.0));
        EXPECT_EQ(kept.q, s.q);
    }
}

// a free body on a moving body, carrying a pendulum of its own: the articulated-body
// dynamics against the thesis's Newton–Euler system on random states (random base
// orientations too)
TEST(FreeJoint, DynamicsAgreeWithTheNewtonEulerReference)
{
    const std::string text = R"pad(GRAVITY 0.3 -0.2 -9.81
B 1 5.0 0.5 0.6 0.3 NAME "arm"
B 2 2.0 0.05 0.08 0.07 0.004 0.002 -0.003 CG 0.05 -0.02 0.1 NAME "free"
B 3 0.7 0.01 0.012 0.002 NAME "bob"
C 1 NAME "shoulder"
B1 0 P1 0 0 1 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2 T 3 NAME "loose"
B1 1 P1 1 0 0 A1 0 1 1 R1 1 0 0
B2 2 P2 0 0 0.2 A2 1 0 0 R2 0 1 0
C 3 NAME "pendulum"
B1 2 P1 0 0 -0.1 A1 1 0 0 R1 0 1 0
B2 3 P2 0 0 0.4 A2 1 0 0 R2 0 1 0
F 1 POINT B 2 P 0.1 0 0 DIR 1 0 1 MAG 3
)pad";
    const auto model = test::compileText(text, "chain.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    ASSERT_EQ(m.nb, 8);
    reference::NewtonEulerSystem system(m);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    Data d(m);
    for (int trial = 0; trial < 40; ++trial) {
        State s = makeState(m);
        for (int i = 0; i < m.nb; ++i) {
            s.q[i] = 1.5 * u(rng);
            s.qd[i] = 2 * u(rng);
        }
        s.q.segment<4>(m.freeBase[m.freeJoints[0] + 3]) = Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized();
        forwardKinematics(m, s, d);
        applyForces(m, s, d);
        hybridDynamics(m, s, d);
        const reference::NewtonEulerResult& r = system.solve(s, d.fext, d.tauExt);
        EXPECT_LT(r.relativeResidual, 1e-10);
        EXPECT_LT((r.qdd - d.qdd).lpNorm<Eigen::Infinity>(), 1e-9 * std::max(1.0, r.qdd.lpNorm<Eigen::Infinity>()))
            << "reference " << r.qdd.transpose() << "\npadrob    " << d.qdd.transpose();
    }
}

// gripped: welded to the arm it moves with it at a fixed relative pose; released, it
// falls freely from where it was let go
TEST(FreeJoint, AWeldedFreeBodyMovesWithItsHolderAndFallsWhenReleased)
{
    const std::string text = R"pad(GRAVITY 0 0 -9.81
B 1 20.0 2 2 1 NAME "arm"
B 2 4.0 0.1 0.1 0.1 NAME "load"
C 1 NAME "slew"
B1 0 P1 0 0 1 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
D 1 HYD VMAX 0.8 VMIN 0.8
C 2 T 3
B1 0 P1 1.5 0 1 A1 1 0 0 R1 0 1 0
B2 2 P2 0 0 0 A2 1 0 0 R2 0 1 0
)pad";
    const auto model = test::compileText(text, "grip.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Simulation sim(model, test::rk4(1e-3));
    const int arm = m.bodyIndex(1), load = m.bodyIndex(2);
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.weld(arm, load, ev, err)) << err;
    const Eigen::Isometry3d relative = sim.data().X_wb[arm].inverse() * sim.data().X_wb[load];
    sim.setCommand(m.jointIndex(1), 1.0);
    for (int k = 1; k <= 20; ++k) {
        ASSERT_TRUE(sim.advanceTo(0.1 * k, ev, err)) << err;
        const Eigen::Isometry3d now = sim.data().X_wb[arm].inverse() * sim.data().X_wb[load];
        ASSERT_TRUE(now.isApprox(relative, 1e-9)) << "t = " << sim.state().t;
    }
    // the arm turned 1.6 rad, carrying the load round with it
    EXPECT_NEAR(sim.state().q[m.jointIndex(1)], 1.6, 1e-9);
    const Vector3d at = comPosition(m, sim.data(), load);
    EXPECT_NEAR(at.x(), 1.5 * std::cos(1.6), 1e-9);
    EXPECT_NEAR(at.y(), 1.5 * std::sin(1.6), 1e-9);
    const Vector3d v = comVelocity(m, sim.data(), load);
    ASSERT_TRUE(sim.release(arm, load, ev, err)) << err;
    ASSERT_TRUE(sim.advanceTo(2.5, ev, err)) << err;
    const Vector3d expected = at + v * 0.5 + Vector3d(0, 0, -0.5 * 9.81 * 0.25);
    EXPECT_LT((comPosition(m, sim.data(), load) - expected).norm(), 1e-9);
}

struct BadCase {
    const char* text;
    const char* code;
};

TEST(FreeJoint, WhatDoesNotApplyToAFreeJointIsALocatedError)
{
    const std::string bodies = "B 1 1 0.1 0.1 0.1\nB 2 1 0.1 0.1 0.1\n";
    const std::string free = "B1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\n";
    const std::vector<BadCase> cases = {
        {"C 1 T 3 LL -1\n", "free-joint-option"},
        {"C 1 T 3 QI 0.2\n", "free-joint-option"},
        {"C 1 T 3 VI 1 DEG\n", "free-joint-option"},
        {"C 1 T 3\n@\nD 1 HYD VMAX 1 VMIN 1\n", "drive-on-free-joint"},
        {"C 1 T 3\n@\nF 1 JOINT 1 MAG 2\n", "free-joint-coordinate"},
        {"C 1 T 3\n@\nF 1 POINT B 2 DIR 0 0 1 MAG TABLE Q 1 0 0 1 1\nC 2\nB1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0\nB2 2 P2 0 0 0 A2 1 0 0 R2 0 1 0\n",
         "free-joint-coordinate"},
        {"C 1 T 3\nB1 1 P1 0 0 0 A1 1 0 0 R1 0 1 0\nB2 0 P2 0 0 0 A2 1 0 0 R2 0 1 0\n", "free-joint-on-ground"},
        {"C 1 T 3\n@\nC 2\nB1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\n", "free-joint-in-loop"},
        {"C 1 T 3\nB1 2 P1 0 0 0 A1 1 0 0 R1 0 1 0\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\nC 2\nB1 0 P1 0 0 0 A1 1 0 0 R1 0 "
         "1 0\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\n",
         "free-joint-reversed"},
        {"C 1 T 3\n@\nCL1 0 0 0 CL2 0 0 1\n", "unexpected-cl"},
        {"C 1 T 4\n@\n", "bad-joint-type"},
    };
    for (const BadCase& c : cases) {
        std::string text = bodies + c.text;
        if (const std::size_t at = text.find("@\n"); at != std::string::npos) text.replace(at, 2, free);
        SCOPED_TRACE(text);
        const CompiledModel compiled = compileText(text, "bad.pad");
        EXPECT_FALSE(compiled.model);
        const auto found = std::find_if(compiled.diagnostics.begin(), compiled.diagnostics.end(),
                                        [&](const Diagnostic& d) { return d.code == c.code; });
        ASSERT_NE(found, compiled.diagnostics.end()) << "no " << c.code;
        EXPECT_GT(found->pos.line, 0);
        EXPECT_FALSE(found->hint.empty());
    }
}

}  // namespace
}  // namespace solver
