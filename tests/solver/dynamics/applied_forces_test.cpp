#include "solver/dynamics/applied_forces.h"
#include "solver/spec/model_spec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace solver {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

/// A model of nb bodies with every per-body array sized (revolute joints, chain
/// parent[i] = i − 1, unit masses); the tests fill in what they use.
Model chainModel(int nb)
{
    Model m;
    m.nb = nb;
    const auto n = static_cast<std::size_t>(nb);
    for (int i = 0; i < nb; ++i) {
        m.parent.push_back(i - 1);
        m.bodyId.push_back(i + 1);
        m.jointId.push_back(i + 1);
    }
    m.bodyName.assign(n, "");
    m.jointName.assign(n, "");
    m.jointType.assign(n, JointType::Revolute);
    m.X_pj.assign(n, Isometry3d::Identity());
    m.X_cj.assign(n, Isometry3d::Identity());
    m.axisSign.assign(n, 1.0);
    m.lengthLaw.assign(n, ActuatorLengthLaw{});
    m.cl1.assign(n, Vector3d::Zero());
    m.cl2.assign(n, Vector3d::Zero());
    m.lower.assign(n, -std::numeric_limits<double>::infinity());
    m.upper.assign(n, std::numeric_limits<double>::infinity());
    m.mass.assign(n, 1.0);
    m.com.assign(n, Vector3d::Zero());
    m.inertia.assign(n, Eigen::Matrix3d::Identity());
    m.drive.assign(n, CompiledDrive{});
    m.theta0.assign(n, 0.0);
    m.thetaDot0.assign(n, 0.0);
    return m;
}

State stateOf(const Model& m, double t = 0)
{
    State s;
    s.t = t;
    s.q = Eigen::VectorXd::Zero(m.nb);
    s.qd = Eigen::VectorXd::Zero(m.nb);
    s.u = Eigen::VectorXd::Zero(m.nb);
    s.servoIntegral = Eigen::VectorXd::Zero(m.nb);
    s.limit.assign(static_cast<std::size_t>(m.nb), LimitState::Free);
    s.relief.assign(static_cast<std::size_t>(m.nb), ReliefState::Closed);
    return s;
}

/// Body poses set directly: body i at `origin`, turned by `angle` about `axis`.
void place(Data& d, int i, const Vector3d& origin, double angle = 0,
           const Vector3d& axis = Vector3d::UnitZ(), const Vector3d& vel = Vector3d::Zero(),
           const Vector3d& omega = Vector3d::Zero())
{
    Isometry3d X = Isometry3d::Identity();
    X.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
    X.translation() = origin;
    d.X_wb[i] = X;
    d.vel[i] = vel;
    d.omega[i] = omega;
}

CompiledMagnitude constant(double v)
{
    CompiledMagnitude m;
    m.kind = MagnitudeSpec::Kind::Constant;
    m.value = v;
    return m;
}

CompiledMagnitude table(MagnitudeSpec::Kind kind, std::vector<double> x, std::vector<double> y,
                        int joint = -1)
{
    CompiledMagnitude m;
    m.kind = kind;
    m.x = std::move(x);
    m.y = std::move(y);
    m.joint = joint;
    return m;
}

CompiledForce pointForce(int body, const Vector3d& p, const Vector3d& dir, double mag,
                         bool local = false)
{
    CompiledForce f;
    f.kind = ForceKind::Point;
    f.body = body;
    f.point = p;
    f.dir = dir.normalized();
    f.local = local;
    f.mag = constant(mag);
    return f;
}

CompiledForce torqueForce(int body, const Vector3d& dir, double mag, bool local = false)
{
    CompiledForce f;
    f.kind = ForceKind::Torque;
    f.body = body;
    f.dir = dir.normalized();
    f.local = local;
    f.mag = constant(mag);
    return f;
}

CompiledForce jointForce(int joint, double mag)
{
    CompiledForce f;
    f.kind = ForceKind::Joint;
    f.joint = joint;
    f.mag = constant(mag);
    return f;
}

CompiledForce spring(int b1, const Vector3d& p1, int b2, const Vector3d& p2, double k, double l0,
                     double c)
{
    CompiledForce f;
    f.kind = ForceKind::Spring;
    f.body = b1;
    f.point = p1;
    f.body2 = b2;
    f.point2 = p2;
    f.stiffness = k;
    f.restLength = l0;
    f.damping = c;
    return f;
}

CompiledForce aero(int body, const Vector3d& p, double area, double cd, double cl, double rho)
{
    CompiledForce f;
    f.kind = ForceKind::Aero;
    f.body = body;
    f.point = p;
    f.area = area;
    f.cd = cd;
    f.cl = cl;
    f.rho = rho;
    return f;
}

void expectVec(const Vector3d& actual, const Vector3d& expected, double tol = 1e-12)
{
    EXPECT_NEAR(actual.x(), expected.x(), tol) << "actual " << actual.transpose() << ", expected "
                                               << expected.transpose();
    EXPECT_NEAR(actual.y(), expected.y(), tol) << "actual " << actual.transpose() << ", expected "
                                               << expected.transpose();
    EXPECT_NEAR(actual.z(), expected.z(), tol) << "actual " << actual.transpose() << ", expected "
                                               << expected.transpose();
}

Vector3d moment(const Data& d, int i) { return d.fext[i].head<3>(); }
Vector3d force(const Data& d, int i) { return d.fext[i].tail<3>(); }

// A pivoted actuator about z at the origin: CL1 on the ground at (−1, 0, 0), CL2 on
// the body at 0.5 m along its x, so L²(θ) = (1 + 0.5 cos θ)² + (0.5 sin θ)² = 1.25 + cos θ.
Model actuatorModel()
{
    Model m = chainModel(1);
    m.jointType[0] = JointType::Actuator;
    m.lengthLaw[0] = ActuatorLengthLaw{1.25, 1.0, 0.0};
    m.cl1[0] = Vector3d(-1, 0, 0);
    m.cl2[0] = Vector3d(0.5, 0, 0);
    return m;
}

// ---- magnitudes ---------------------------------------------------------------

TEST(AppliedMagnitude, Constant)
{
    const Model m = chainModel(1);
    const State s = stateOf(m);
    EXPECT_EQ(evaluateMagnitude(constant(-12.5), 3.0, m, s), -12.5);
}

TEST(AppliedMagnitude, SineWithPhaseAndOffset)
{
    const Model m = chainModel(1);
    const State s = stateOf(m);
    CompiledMagnitude mag;
    mag.kind = MagnitudeSpec::Kind::Sine;
    mag.amplitude = 2;
    mag.frequency = 0.5;  // period 2 s
    mag.phase = kPi / 2;  // starts at its crest
    mag.offset = 1;
    EXPECT_NEAR(evaluateMagnitude(mag, 0.0, m, s), 3.0, 1e-15);  // 1 + 2·sin(π/2)
    EXPECT_NEAR(evaluateMagnitude(mag, 0.25, m, s), 1.0 + std::sqrt(2.0), 1e-14);  // 1 + 2·sin(3π/4)
    EXPECT_NEAR(evaluateMagnitude(mag, 0.5, m, s), 1.0, 1e-14);  // 1 + 2·sin(π)
    EXPECT_NEAR(evaluateMagnitude(mag, 1.0, m, s), -1.0, 1e-14);  // 1 + 2·sin(3π/2)
    EXPECT_NEAR(evaluateMagnitude(mag, 2.0, m, s), 3.0, 1e-14);  // one period on
    mag.phase = 0;
    mag.offset = 0;
    EXPECT_NEAR(evaluateMagnitude(mag, 0.0, m, s), 0.0, 1e-15);
    EXPECT_NEAR(evaluateMagnitude(mag, 0.25, m, s), std::sqrt(2.0), 1e-14);  // 2·sin(π/4)
    EXPECT_NEAR(evaluateMagnitude(mag, 0.5, m, s), 2.0, 1e-14);             // 2·sin(π/2)
    EXPECT_NEAR(evaluateMagnitude(mag, 1.0, m, s), 0.0, 1e-14);             // 2·sin(π)
}

TEST(AppliedMagnitude, TableByTimeInterpolatesAndHoldsTheEnds)
{
    const Model m = chainModel(1);
    const State s = stateOf(m);
    const auto mag = table(MagnitudeSpec::Kind::TableTime, {1, 2, 4}, {10, 20, -20});
    EXPECT_EQ(evaluateMagnitude(mag, -5.0, m, s), 10.0);  // before the first point: held
    EXPECT_EQ(evaluateMagnitude(mag, 0.0, m, s), 10.0);
    EXPECT_EQ(evaluateMagnitude(mag, 1.0, m, s), 10.0);  // at a point: its value
    EXPECT_NEAR(evaluateMagnitude(mag, 1.5, m, s), 15.0, 1e-14);
    EXPECT_NEAR(evaluateMagnitude(mag, 1.75, m, s), 17.5, 1e-14);
    EXPECT_EQ(evaluateMagnitude(mag, 2.0, m, s), 20.0);
    EXPECT_NEAR(evaluateMagnitude(mag, 3.0, m, s), 0.0, 1e-14);
    EXPECT_NEAR(evaluateMagnitude(mag, 3.5, m, s), -10.0, 1e-14);
    EXPECT_EQ(evaluateMagnitude(mag, 4.0, m, s), -20.0);
    EXPECT_EQ(evaluateMagnitude(mag, 100.0, m, s), -20.0);  // after the last point: held

    // degenerate tables: one point is a constant, none is zero
    EXPECT_EQ(evaluateMagnitude(table(MagnitudeSpec::Kind::TableTime, {2}, {7}), 0.0, m, s), 7.0);
    EXPECT_EQ(evaluateMagnitude(table(MagnitudeSpec::Kind::TableTime, {2}, {7}), 9.0, m, s), 7.0);
    EXPECT_EQ(evaluateMagnitude(table(MagnitudeSpec::Kind::TableTime, {}, {}), 1.0, m, s), 0.0);
}

TEST(AppliedMagnitude, TableByJointReadsTheActuatorLength)
{
    const Model m = actuatorModel();
    State s = stateOf(m);
    s.q[0] = kPi / 2;  // θ = 90°: L = √1.25 = 1.1180…
    const double L = std::sqrt(1.25);
    // by length: between (1.0, 0) and (1.2, 100); by angle (1.57) it would be held at 100
    const auto mag = table(MagnitudeSpec::Kind::TableJoint, {1.0, 1.2}, {0.0, 100.0}, 0);
    EXPECT_NEAR(evaluateMagnitude(mag, 0.0, m, s), (L - 1.0) / 0.2 * 100.0, 1e-12);
    // θ = 0: L = 1.5, beyond the table: held at 100; θ = π: L = 0.5, before it: 0
    s.q[0] = 0;
    EXPECT_EQ(evaluateMagnitude(mag, 0.0, m, s), 100.0);
    s.q[0] = kPi;
    EXPECT_EQ(evaluateMagnitude(mag, 0.0, m, s), 0.0);
}

TEST(AppliedMagnitude, TableByJointOnARevoluteJointReadsTheAngle)
{
    const Model m = chainModel(2);
    State s = stateOf(m);
    s.q[1] = 0.25;
    const auto mag = table(MagnitudeSpec::Kind::TableJoint, {0.0, 1.0}, {0.0, -8.0}, 1);
    EXPECT_NEAR(evaluateMagnitude(mag, 0.0, m, s), -2.0, 1e-15);
    // not a tree joint: no force
    EXPECT_EQ(evaluateMagnitude(table(MagnitudeSpec::Kind::TableJoint, {0.0, 1.0}, {5.0, 5.0}, 2),
                                0.0, m, s),
              0.0);
}

// ---- kinds ---------------------------------------------------------------------

TEST(AppliedForces, StartsFromZero)
{
    Model m = chainModel(2);
    Data d(m);
    place(d, 0, Vector3d::Zero());
    place(d, 1, Vector3d::Zero());
    for (auto& w : d.fext) w.setConstant(99);
    d.tauExt.setConstant(99);
    applyForces(m, stateOf(m), d);
    for (const auto& w : d.fext) EXPECT_TRUE(w.isZero());
    EXPECT_TRUE(d.tauExt.isZero());
}

TEST(AppliedForces, PointForceMomentArmWorldDirection)
{
    Model m = chainModel(1);
    m.forces.push_back(pointForce(0, Vector3d(1, 0, 0), Vector3d(2, 0, 0), 10));  // dir normalised
    Data d(m);
    // body at (1, 2, 3) turned 90° about z: its local x is world y
    place(d, 0, Vector3d(1, 2, 3), kPi / 2);
    applyForces(m, stateOf(m), d);
    // point at (1, 3, 3); arm (0, 1, 0) from the origin; F = (10, 0, 0): M = arm × F = (0, 0, −10)
    expectVec(force(d, 0), Vector3d(10, 0, 0));
    expectVec(moment(d, 0), Vector3d(0, 0, -10));
    EXPECT_TRUE(d.tauExt.isZero());
}

TEST(AppliedForces, PointForceLocalDirectionTurnsWithTheBody)
{
    Model m = chainModel(1);
    m.forces.push_back(pointForce(0, Vector3d(1, 0, 0), Vector3d(0, 1, 0), 10, /*local*/ true));
    Data d(m);
    place(d, 0, Vector3d(1, 2, 3), kPi / 2);
    applyForces(m, stateOf(m), d);
    // local y is world −x: F = (−10, 0, 0) at arm (0, 1, 0): M = (0, 0, 10)
    expectVec(force(d, 0), Vector3d(-10, 0, 0));
    expectVec(moment(d, 0), Vector3d(0, 0, 10));

    // the same direction in world axes stays world y: F ∥ arm, no moment
    m.forces[0].local = false;
    applyForces(m, stateOf(m), d);
    expectVec(force(d, 0), Vector3d(0, 10, 0));
    expectVec(moment(d, 0), Vector3d::Zero());
}

TEST(AppliedForces, PointForceMagnitudeFollowsTime)
{
    Model m = chainModel(1);
    CompiledForce f = pointForce(0, Vector3d::Zero(), Vector3d(0, 0, 1), 0);
    f.mag = table(MagnitudeSpec::Kind::TableTime, {0, 1}, {0, 50});
    m.forces.push_back(f);
    Data d(m);
    place(d, 0, Vector3d::Zero());
    applyForces(m, stateOf(m, 0.5), d);
    expectVec(force(d, 0), Vector3d(0, 0, 25));
}

TEST(AppliedForces, LoadsOnTheGroundAreDropped)
{
    Model m = chainModel(1);
    m.forces.push_back(pointForce(-1, Vector3d(1, 0, 0), Vector3d(0, 0, 1), 10));
    m.forces.push_back(torqueForce(-1, Vector3d(0, 0, 1), 10));
    m.forces.push_back(aero(-1, Vector3d::Zero(), 1, 1, 1, 1));
    m.forces.push_back(jointForce(-1, 10));
    Data d(m);
    place(d, 0, Vector3d::Zero(), 0, Vector3d::UnitZ(), Vector3d(1, 0, 0));
    applyForces(m, stateOf(m), d);
    EXPECT_TRUE(d.fext[0].isZero());
    EXPECT_TRUE(d.tauExt.isZero());
}

TEST(AppliedForces, TorqueWorldAndLocal)
{
    Model m = chainModel(2);
    m.forces.push_back(torqueForce(0, Vector3d(1, 0, 0), 5));                  // world x
    m.forces.push_back(torqueForce(1, Vector3d(1, 0, 0), 5, /*local*/ true));  // body 1's x
    Data d(m);
    place(d, 0, Vector3d(4, 5, 6), kPi / 2);  // a pure moment does not depend on where the body is
    place(d, 1, Vector3d(1, 1, 1), kPi / 2);  // local x = world y
    applyForces(m, stateOf(m), d);
    expectVec(moment(d, 0), Vector3d(5, 0, 0));
    expectVec(force(d, 0), Vector3d::Zero());
    expectVec(moment(d, 1), Vector3d(0, 5, 0));
    expectVec(force(d, 1), Vector3d::Zero());
}

TEST(AppliedForces, JointForceOnARevoluteJointIsTheTorque)
{
    Model m = chainModel(2);
    m.forces.push_back(jointForce(1, 7.5));
    m.forces.push_back(jointForce(1, -2.5));  // forces on one joint add up
    Data d(m);
    place(d, 0, Vector3d::Zero());
    place(d, 1, Vector3d::Zero());
    applyForces(m, stateOf(m), d);
    EXPECT_EQ(d.tauExt[0], 0.0);
    EXPECT_DOUBLE_EQ(d.tauExt[1], 5.0);
    for (const auto& w : d.fext) EXPECT_TRUE(w.isZero());
}

TEST(AppliedForces, JointForceOnAnActuatorActsAlongItsLength)
{
    Model m = actuatorModel();
    m.forces.push_back(jointForce(0, 100));  // 100 N along the cylinder
    Data d(m);
    place(d, 0, Vector3d::Zero(), kPi / 2);
    State s = stateOf(m);
    s.q[0] = kPi / 2;
    applyForces(m, s, d);
    // L² = 1.25 + cos θ: dL/dθ = −sin θ / (2L) = −1/(2·√1.25) at 90°; τ = F·dL/dθ
    EXPECT_NEAR(d.tauExt[0], -100.0 / (2.0 * std::sqrt(1.25)), 1e-12);
    // check: the same cylinder force as a pair of point forces has the same torque about the pivot:
    // CL2 = (0, 0.5, 0), CL1 = (−1, 0, 0); e = (1, 0.5, 0)/√1.25; the push on CL2 is +100·e
    const Vector3d e = Vector3d(1, 0.5, 0) / std::sqrt(1.25);
    const Vector3d torque = Vector3d(0, 0.5, 0).cross(100.0 * e);
    EXPECT_NEAR(d.tauExt[0], torque.z(), 1e-12);
}

TEST(AppliedForces, SpringToGroundWithDamping)
{
    Model m = chainModel(1);
    // ground point (0, 0, 0); body point 1 m above the body's origin
    m.forces.push_back(spring(-1, Vector3d::Zero(), 0, Vector3d(0, 0, 1), 100, 4, 10));
    Data d(m);
    // origin (3, 4, −1): the point is at (3, 4, 0), L = 5, e = (0.6, 0.8, 0) from ground to body;
    // point velocity = (1, 0, 0) + (1, 0, 0) × (0, 0, 1) = (1, −1, 0): L̇ = 0.6 − 0.8 = −0.2
    place(d, 0, Vector3d(3, 4, -1), 0, Vector3d::UnitZ(), Vector3d(1, 0, 0), Vector3d(1, 0, 0));
    applyForces(m, stateOf(m), d);
    // tension 100·(5 − 4) + 10·(−0.2) = 98 pulls the point towards the ground point
    const Vector3d f(-58.8, -78.4, 0);
    expectVec(force(d, 0), f, 1e-12);
    expectVec(moment(d, 0), Vector3d(0, 0, 1).cross(f), 1e-12);  // = (78.4, −58.8, 0)
    expectVec(moment(d, 0), Vector3d(78.4, -58.8, 0), 1e-12);
}

TEST(AppliedForces, SpringBetweenTwoBodiesIsEqualAndOpposite)
{
    Model m = chainModel(2);
    m.forces.push_back(spring(0, Vector3d(0.5, 0, 0), 1, Vector3d(0, 0.25, 0), 200, 1, 3));
    Data d(m);
    place(d, 0, Vector3d(0.1, 0.2, 0.3), 0.4, Vector3d(1, 2, 3), Vector3d(0.3, -0.2, 0.1),
          Vector3d(0.5, 0.1, -0.7));
    place(d, 1, Vector3d(1.5, -0.5, 0.8), -1.1, Vector3d(-1, 0, 2), Vector3d(-0.4, 0.9, 0.2),
          Vector3d(0.2, 0.6, 0.3));
    applyForces(m, stateOf(m), d);
    const Vector3d p1 = d.X_wb[0] * Vector3d(0.5, 0, 0);
    const Vector3d p2 = d.X_wb[1] * Vector3d(0, 0.25, 0);
    const double L = (p2 - p1).norm();
    const Vector3d e = (p2 - p1) / L;
    const Vector3d v1 = d.vel[0] + d.omega[0].cross(p1 - d.X_wb[0].translation());
    const Vector3d v2 = d.vel[1] + d.omega[1].cross(p2 - d.X_wb[1].translation());
    const double tension = 200 * (L - 1) + 3 * e.dot(v2 - v1);
    expectVec(force(d, 0), tension * e, 1e-12);
    expectVec(force(d, 1), -tension * e, 1e-12);
    // equal and opposite along one line: no net force, no net moment about any point
    expectVec(force(d, 0) + force(d, 1), Vector3d::Zero(), 1e-12);
    const Vector3d o0 = d.X_wb[0].translation(), o1 = d.X_wb[1].translation();
    expectVec(moment(d, 0) + o0.cross(force(d, 0)) + moment(d, 1) + o1.cross(force(d, 1)),
              Vector3d::Zero(), 1e-12);
}

TEST(AppliedForces, CompressedSpringPushesApart)
{
    Model m = chainModel(1);
    m.forces.push_back(spring(-1, Vector3d::Zero(), 0, Vector3d::Zero(), 50, 2, 0));
    Data d(m);
    place(d, 0, Vector3d(0, 0, 1.5));  // L = 1.5 < L0 = 2: tension −25
    applyForces(m, stateOf(m), d);
    expectVec(force(d, 0), Vector3d(0, 0, 25));
}

TEST(AppliedForces, ZeroLengthSpringExertsNothing)
{
    Model m = chainModel(2);
    m.forces.push_back(spring(0, Vector3d(1, 0, 0), 1, Vector3d::Zero(), 100, 0.5, 10));
    Data d(m);
    place(d, 0, Vector3d::Zero(), 0, Vector3d::UnitZ(), Vector3d(1, 2, 3));
    place(d, 1, Vector3d(1, 0, 0));  // body 1's point coincides with body 0's
    applyForces(m, stateOf(m), d);
    for (const auto& w : d.fext) {
        EXPECT_TRUE(w.allFinite());
        EXPECT_TRUE(w.isZero());
    }
}

TEST(AppliedForces, AeroDragAndLiftInLevelMotion)
{
    Model m = chainModel(1);
    m.forces.push_back(aero(0, Vector3d::Zero(), 2.0, 0.5, 0.3, 1.2));
    Data d(m);
    place(d, 0, Vector3d(5, 5, 5), 0, Vector3d::UnitZ(), Vector3d(10, 0, 0));
    applyForces(m, stateOf(m), d);
    // ½ρA = 1.2; drag 1.2·0.5·10² = 60 against v; lift 1.2·0.3·10² = 36 straight up
    expectVec(force(d, 0), Vector3d(-60, 0, 36), 1e-12);
    expectVec(moment(d, 0), Vector3d::Zero());
}

TEST(AppliedForces, AeroLiftIsPerpendicularToTheVelocityAndUp)
{
    Model m = chainModel(1);
    m.forces.push_back(aero(0, Vector3d::Zero(), 2.0, 0.5, 0.3, 1.2));
    Data d(m);
    place(d, 0, Vector3d::Zero(), 0, Vector3d::UnitZ(), Vector3d(3, 0, 4));  // climbing, |v| = 5
    applyForces(m, stateOf(m), d);
    // drag −1.2·0.5·5·(3, 0, 4) = (−9, 0, −12); lift 1.2·0.3·25 = 9 along n = (−0.8, 0, 0.6)
    expectVec(force(d, 0), Vector3d(-9 - 7.2, 0, -12 + 5.4), 1e-12);
}

TEST(AppliedForces, AeroNoLiftWhenMovingVerticallyOrAtRest)
{
    Model m = chainModel(1);
    m.forces.push_back(aero(0, Vector3d::Zero(), 2.0, 0.5, 0.3, 1.2));
    Data d(m);
    place(d, 0, Vector3d::Zero(), 0, Vector3d::UnitZ(), Vector3d(0, 0, -10));  // falling
    applyForces(m, stateOf(m), d);
    expectVec(force(d, 0), Vector3d(0, 0, 60), 1e-12);  // drag only, upwards
    place(d, 0, Vector3d::Zero());
    applyForces(m, stateOf(m), d);
    EXPECT_TRUE(d.fext[0].isZero());
}

TEST(AppliedForces, AeroUpIsAgainstGravity)
{
    Model m = chainModel(1);
    m.gravity = Vector3d(0, -9.81, 0);  // y up
    m.forces.push_back(aero(0, Vector3d::Zero(), 1.0, 0.0, 1.0, 2.0));  // lift only
    Data d(m);
    place(d, 0, Vector3d::Zero(), 0, Vector3d::UnitZ(), Vector3d(0, 0, 3));
    applyForces(m, stateOf(m), d);
    expectVec(force(d, 0), Vector3d(0, 9, 0), 1e-12);  // ½·2·1·1·3² up y
    // without gravity, up is world z
    m.gravity = Vector3d::Zero();
    place(d, 0, Vector3d::Zero(), 0, Vector3d::UnitZ(), Vector3d(3, 0, 0));
    applyForces(m, stateOf(m), d);
    expectVec(force(d, 0), Vector3d(0, 0, 9), 1e-12);
}

TEST(AppliedForces, AeroUsesThePointVelocityAndItsMomentArm)
{
    Model m = chainModel(1);
    m.forces.push_back(aero(0, Vector3d(0, 1, 0), 1.0, 1.0, 0.0, 2.0));  // drag only, ½ρ·CD·A = 1
    Data d(m);
    // spinning about z at 2 rad/s, origin at rest: the point (0, 1, 0) moves at (−2, 0, 0)
    place(d, 0, Vector3d::Zero(), 0, Vector3d::UnitZ(), Vector3d::Zero(), Vector3d(0, 0, 2));
    applyForces(m, stateOf(m), d);
    expectVec(force(d, 0), Vector3d(4, 0, 0), 1e-12);  // −1·2·(−2, 0, 0)
    expectVec(moment(d, 0), Vector3d(0, 1, 0).cross(Vector3d(4, 0, 0)),
              1e-12);  // (0, 0, −4): it brakes the spin
}

// ---- virtual power -------------------------------------------------------------------

// Two revolute joints in 3D: joint 0 turns body 0 about the world axis a0 through c0;
// joint 1 turns body 1 about body 0's axis a1 through c1 (body 0 coordinates). At θ = 0
// the bodies are at B0 (world) and B01 (in body 0).
struct TwoLink {
    Vector3d a0 = Vector3d(0.2, -0.3, 1).normalized(), c0 = Vector3d(0.1, 0.2, -0.1);
    Vector3d a1 = Vector3d(1, 0.4, 0.1).normalized(), c1 = Vector3d(0.8, 0.1, 0.05);
    Isometry3d B0 = pose(Vector3d(0.4, 0.1, 0.0), 0.3, Vector3d(1, 1, 0));
    Isometry3d B01 = pose(Vector3d(1.1, 0.3, -0.2), -0.6, Vector3d(0, 1, 1));

    static Isometry3d pose(const Vector3d& origin, double angle, const Vector3d& axis)
    {
        Isometry3d X = Isometry3d::Identity();
        X.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
        X.translation() = origin;
        return X;
    }
    /// A turn by `angle` about `axis` through `point`.
    static Isometry3d turn(const Vector3d& axis, const Vector3d& point, double angle)
    {
        Isometry3d X = Isometry3d::Identity();
        X.linear() = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
        X.translation() = point - X.linear() * point;
        return X;
    }
    Isometry3d X0(const Eigen::Vector2d& q) const { return turn(a0, c0, q[0]) * B0; }
    Isometry3d X1(const Eigen::Vector2d& q) const { return X0(q) * turn(a1, c1, q[1]) * B01; }
    Isometry3d X(int i, const Eigen::Vector2d& q) const { return i == 0 ? X0(q) : X1(q); }

    /// Poses and velocities of both bodies (the kinematics' job, done by hand).
    void kinematics(const Eigen::Vector2d& q, const Eigen::Vector2d& qd, Data& d) const
    {
        d.X_wb[0] = X0(q);
        d.X_wb[1] = X1(q);
        const Vector3d o0 = d.X_wb[0].translation(), o1 = d.X_wb[1].translation();
        const Vector3d a1w = d.X_wb[0].linear() * a1, c1w = d.X_wb[0] * c1;
        d.omega[0] = a0 * qd[0];
        d.vel[0] = d.omega[0].cross(o0 - c0);
        d.omega[1] = d.omega[0] + a1w * qd[1];
        d.vel[1] = d.vel[0] + d.omega[0].cross(o1 - o0) + (a1w * qd[1]).cross(o1 - c1w);
    }
};

TEST(AppliedForces, GeneralizedForcesEqualTheVirtualPowerOfEveryLoad)
{
    const TwoLink link;
    Model m = chainModel(2);
    m.forces.push_back(pointForce(0, Vector3d(0.3, -0.2, 0.1), Vector3d(1, 2, -1), 40));
    m.forces.push_back(
        pointForce(1, Vector3d(-0.1, 0.4, 0.2), Vector3d(0, 1, 1), -25, /*local*/ true));
    m.forces.push_back(torqueForce(0, Vector3d(0, 0, 1), 7));
    m.forces.push_back(torqueForce(1, Vector3d(1, -1, 0), 3, /*local*/ true));
    m.forces.push_back(spring(0, Vector3d(0.2, 0.2, 0), 1, Vector3d(0.3, 0, -0.1), 150, 0.4, 12));
    m.forces.push_back(spring(-1, Vector3d(2, 1, 1), 1, Vector3d(0.1, 0.1, 0.1), 80, 0.7, 5));
    m.forces.push_back(aero(1, Vector3d(0.5, -0.2, 0.3), 0.8, 1.1, 0.6, 1.225));
    m.forces.push_back(jointForce(1, 4.5));

    const Eigen::Vector2d q(0.7, -1.2), qd(1.3, -2.1);
    Data d(m);
    link.kinematics(q, qd, d);
    State s = stateOf(m);
    s.q = q;
    s.qd = qd;
    applyForces(m, s, d);

    // projection: Q_j = Σ_i fext_i · (ω_i, v_i)(θ̇ = e_j) + tauExt_j
    Data unit(m);
    Eigen::Vector2d Q = d.tauExt;
    for (int j = 0; j < 2; ++j) {
        link.kinematics(q, Eigen::Vector2d::Unit(j), unit);
        for (int i = 0; i < 2; ++i)
            Q[j] += moment(d, i).dot(unit.omega[i]) + force(d, i).dot(unit.vel[i]);
    }

    // by hand: each load evaluated from the positions alone (velocities by finite
    // differences along the motion), its virtual work per δθ_j by finite differences
    const double h = 1e-6;
    auto world = [&](int body, const Vector3d& p, const Eigen::Vector2d& qq) {
        return body < 0 ? p : Vector3d(link.X(body, qq) * p);
    };
    auto velocity = [&](int body, const Vector3d& p) {
        return Vector3d((world(body, p, q + h * qd) - world(body, p, q - h * qd)) / (2 * h));
    };
    auto dpdq = [&](int body, const Vector3d& p, int j) {
        const Eigen::Vector2d e = Eigen::Vector2d::Unit(j);
        return Vector3d((world(body, p, q + h * e) - world(body, p, q - h * e)) / (2 * h));
    };
    Eigen::Vector2d expected = Eigen::Vector2d::Zero();
    for (int j = 0; j < 2; ++j) {
        // point forces
        expected[j] +=
            40 * Vector3d(1, 2, -1).normalized().dot(dpdq(0, Vector3d(0.3, -0.2, 0.1), j));
        const Vector3d dirLocal = link.X1(q).linear() * Vector3d(0, 1, 1).normalized();
        expected[j] += -25 * dirLocal.dot(dpdq(1, Vector3d(-0.1, 0.4, 0.2), j));
        // torques: the angular velocity of body i per θ̇_j is joint j's world axis when j drives i
        const Vector3d axis0 = link.a0, axis1 = link.X0(q).linear() * link.a1;
        const Vector3d jointAxis = j == 0 ? axis0 : axis1;
        expected[j] += j == 0 ? 7 * Vector3d(0, 0, 1).dot(jointAxis) : 0.0;
        expected[j] += 3 * (link.X1(q).linear() * Vector3d(1, -1, 0).normalized()).dot(jointAxis);
        // springs: tension from length and its rate, along the line
        auto springWork = [&](int b1, const Vector3d& p1, int b2, const Vector3d& p2, double k,
                              double l0, double c) {
            const Vector3d x1 = world(b1, p1, q), x2 = world(b2, p2, q);
            const double L = (x2 - x1).norm();
            const Vector3d e = (x2 - x1) / L;
            const double tension = k * (L - l0) + c * e.dot(velocity(b2, p2) - velocity(b1, p1));
            return tension * e.dot(dpdq(b1, p1, j)) -
                   tension * e.dot(b2 < 0 ? Vector3d::Zero() : dpdq(b2, p2, j));
        };
        expected[j] +=
            springWork(0, Vector3d(0.2, 0.2, 0), 1, Vector3d(0.3, 0, -0.1), 150, 0.4, 12);
        expected[j] += springWork(-1, Vector3d(2, 1, 1), 1, Vector3d(0.1, 0.1, 0.1), 80, 0.7, 5);
        // aero: drag against v, lift across it (up = +z here)
        const Vector3d pa(0.5, -0.2, 0.3);
        const Vector3d v = velocity(1, pa);
        const double qa = 0.5 * 1.225 * 0.8;
        const Vector3d up = Vector3d::UnitZ();
        const Vector3d n = (up - up.dot(v.normalized()) * v.normalized()).normalized();
        const Vector3d fa = -qa * 1.1 * v.norm() * v + qa * 0.6 * v.squaredNorm() * n;
        expected[j] += fa.dot(dpdq(1, pa, j));
        // joint force on a revolute joint
        expected[j] += j == 1 ? 4.5 : 0.0;
    }
    EXPECT_NEAR(Q[0], expected[0], 1e-6 * (1 + std::abs(expected[0])));
    EXPECT_NEAR(Q[1], expected[1], 1e-6 * (1 + std::abs(expected[1])));

    // and the power of the loads is Σ fext·(ω, v) + τ·θ̇ (drag takes power, lift none)
    double power = d.tauExt.dot(qd);
    link.kinematics(q, qd, unit);
    for (int i = 0; i < 2; ++i)
        power += moment(d, i).dot(unit.omega[i]) + force(d, i).dot(unit.vel[i]);
    EXPECT_NEAR(power, Q.dot(qd), 1e-9 * (1 + std::abs(power)));
}

TEST(AppliedForces, AeroPowerIsTheDragPower)
{
    // lift does no work: the power of an aero load is −½ρ·CD·A·|v|³
    const TwoLink link;
    Model m = chainModel(2);
    m.forces.push_back(aero(1, Vector3d(0.5, -0.2, 0.3), 0.8, 1.1, 0.6, 1.225));
    const Eigen::Vector2d q(-0.4, 0.9), qd(-0.8, 1.7);
    Data d(m);
    link.kinematics(q, qd, d);
    State s = stateOf(m);
    s.q = q;
    s.qd = qd;
    applyForces(m, s, d);
    double power = 0;
    for (int i = 0; i < 2; ++i) power += moment(d, i).dot(d.omega[i]) + force(d, i).dot(d.vel[i]);
    const Vector3d p = d.X_wb[1] * Vector3d(0.5, -0.2, 0.3);
    const double speed = (d.vel[1] + d.omega[1].cross(p - d.X_wb[1].translation())).norm();
    EXPECT_NEAR(power, -0.5 * 1.225 * 1.1 * 0.8 * speed * speed * speed,
                1e-12 * (1 + std::abs(power)));
    EXPECT_LT(power, 0.0);
}

}  // namespace
}  // namespace solver
