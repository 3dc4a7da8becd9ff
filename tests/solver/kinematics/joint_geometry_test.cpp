#include "solver/kinematics/joint_geometry.h"

#include "tests/solver/spec_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace solver {
namespace {

using Eigen::Vector3d;
using test::side;
constexpr double kPi = std::numbers::pi;

// Appendix A joint 2 (LEVANTE PLUMA): B1 1 P1 0 0 0 A1 x R1 y; B2 2 P2 0 -0.8 0 A2 x R2 y;
// CL1 0.030 0 -.200 CL2 0.030 .650 0. By hand: CL2 relative to P2 is (0.03, 1.45, 0),
// turned by θ about x: (0.03, 1.45 cos θ, 1.45 sin θ); minus CL1: (0, 1.45 cos θ, 1.45 sin θ + 0.2);
// L² = 2.1025 + 0.04 + 0.58 sin θ = 2.1425 + 0.58 sin θ.
JointGeometry appendixJoint2()
{
    JointSpec j;
    j.type = JointType::Actuator;
    j.side1 = side(1, Vector3d(0, 0, 0), Vector3d::UnitX(), Vector3d::UnitY());
    j.side2 = side(2, Vector3d(0, -0.8, 0), Vector3d::UnitX(), Vector3d::UnitY());
    j.cl1 = Vector3d(0.030, 0, -0.200);
    j.cl2 = Vector3d(0.030, 0.650, 0);
    return makeJointGeometry(j);
}

// Appendix A joint 5 (LEVANTE MUÑECA): B1 4 P1 0 0 -0.3; B2 5 P2 0 -0.25 0; A x, R y;
// CL1 0 -0.150 -0.450 CL2 0 0 -0.050. By hand at θ = 0: CL2 − P2 = (0, 0.25, −0.05),
// CL1 − P1 = (0, −0.15, −0.15), difference (0, 0.4, 0.1): L(0) = sqrt(0.17).
// In general u = (0, .25, −.05), w = (0, −.15, −.15): c0 = |u|² + |w|² = 0.11,
// c1 = −2(w_y u_y + w_z u_z) = 0.06, c2 = −2(w_z u_y − w_y u_z) = 0.09.
JointGeometry appendixJoint5()
{
    JointSpec j;
    j.type = JointType::Actuator;
    j.side1 = side(4, Vector3d(0, 0, -0.3), Vector3d::UnitX(), Vector3d::UnitY());
    j.side2 = side(5, Vector3d(0, -0.25, 0), Vector3d::UnitX(), Vector3d::UnitY());
    j.cl1 = Vector3d(0.0, -0.150, -0.450);
    j.cl2 = Vector3d(0.0, 0.0, -0.050);
    return makeJointGeometry(j);
}

// the length measured through the relative pose, not the law
double lengthThroughPose(const JointGeometry& g, double theta)
{
    return (g.relativePose(theta) * g.cl2 - g.cl1).norm();
}

TEST(JointFrame, NormalisesAndOrthogonalises)
{
    const JointFrame f =
        makeJointFrame(side(0, Vector3d(1, 2, 3), Vector3d(0, 0, 2), Vector3d(0, 1, 1)));
    EXPECT_TRUE(f.a().isApprox(Vector3d(0, 0, 1)));
    EXPECT_TRUE(f.r().isApprox(Vector3d(0, 1, 0)));  // (0,1,1) minus its part along A
    EXPECT_TRUE(f.t().isApprox(Vector3d(-1, 0, 0)));  // A × R = z × y
    EXPECT_TRUE(f.origin.isApprox(Vector3d(1, 2, 3)));
    EXPECT_NEAR((f.axes.transpose() * f.axes - Eigen::Matrix3d::Identity()).norm(), 0, 1e-15);
}

TEST(JointFrame, DegenerateInputStillGivesAFrame)
{
    const JointFrame f =
        makeJointFrame(side(0, Vector3d::Zero(), Vector3d::Zero(), Vector3d(0, 0, 1)));
    EXPECT_NEAR(f.axes.determinant(), 1.0, 1e-12);
    EXPECT_NEAR(f.a().dot(f.r()), 0.0, 1e-12);
}

TEST(JointGeometry, RevoluteFramesCoincideAtZeroAndTurnRightHanded)
{
    JointSpec j;  // body 1 point (1,0,0), body 2 point (0,-2,0); A = z, R = x on both sides
    j.side1 = side(1, Vector3d(1, 0, 0));
    j.side2 = side(2, Vector3d(0, -2, 0));
    const JointGeometry g = makeJointGeometry(j);

    const Eigen::Isometry3d x0 = g.relativePose(0);
    EXPECT_TRUE((x0 * j.side2.p).isApprox(j.side1.p));
    EXPECT_TRUE(x0.linear().isIdentity(1e-15));

    // q = π/2: R2 (x in body 2) is R1 (x) turned by 90° about z: +y in body 1
    const Eigen::Isometry3d x1 = g.relativePose(kPi / 2);
    EXPECT_TRUE((x1 * j.side2.p).isApprox(j.side1.p));
    EXPECT_TRUE((x1.linear() * Vector3d::UnitX()).isApprox(Vector3d::UnitY()));
    // body 2's origin is 2 m along body 2's +y from P2: at q = π/2 that is body 1's −x
    EXPECT_TRUE((x1 * Vector3d::Zero()).isApprox(Vector3d(1 - 2, 0, 0)));
}

TEST(JointGeometry, RevoluteWithDifferentFramesOnEachSide)
{
    // side 1: A = x, R = y; side 2: A = z, R = x. At q = 0 body 2's z maps to body 1's x.
    JointSpec j;
    j.side1 = side(1, Vector3d(0, 0, 0), Vector3d::UnitX(), Vector3d::UnitY());
    j.side2 = side(2, Vector3d(0, 0, 0), Vector3d::UnitZ(), Vector3d::UnitX());
    const JointGeometry g = makeJointGeometry(j);
    const Eigen::Matrix3d r0 = g.relativePose(0).linear();
    EXPECT_TRUE((r0 * Vector3d::UnitZ()).isApprox(Vector3d::UnitX()));
    EXPECT_TRUE((r0 * Vector3d::UnitX()).isApprox(Vector3d::UnitY()));
    // measuring the angle back from poses gives q
    for (double q : {-2.5, -0.3, 0.0, 1.0, 3.0}) {
        const Eigen::Isometry3d X_w1 =
            Eigen::Isometry3d(Eigen::AngleAxisd(0.4, Vector3d(1, 2, 3).normalized()));
        const Eigen::Isometry3d X_w2 = X_w1 * g.relativePose(q);
        EXPECT_NEAR(g.measureKinematic(X_w1, X_w2), q, 1e-12) << q;
    }
}

TEST(JointGeometry, PrismaticSlidesAlongR)
{
    JointSpec j;
    j.type = JointType::Prismatic;
    j.side1 = side(1, Vector3d(0, 0.8, 0), Vector3d::UnitZ(), Vector3d::UnitY());
    j.side2 = side(2, Vector3d(0, -0.6, 0), Vector3d::UnitZ(), Vector3d::UnitY());
    const JointGeometry g = makeJointGeometry(j);
    const Eigen::Isometry3d x = g.relativePose(0.25);
    EXPECT_TRUE((x * j.side2.p).isApprox(Vector3d(0, 0.8 + 0.25, 0)));
    EXPECT_TRUE(x.linear().isIdentity(1e-15));
    EXPECT_TRUE((x * Vector3d::Zero()).isApprox(Vector3d(0, 0.8 + 0.25 + 0.6, 0)));
    EXPECT_NEAR(g.measureKinematic(Eigen::Isometry3d::Identity(), x), 0.25, 1e-15);
    EXPECT_NEAR(g.measureCoordinate(Eigen::Isometry3d::Identity(), x), 0.25, 1e-15);
}

TEST(ActuatorLengthLaw, AppendixJoint2Coefficients)
{
    const ActuatorLengthLaw law = appendixJoint2().lengthLaw();
    EXPECT_NEAR(law.c0, 2.1425, 1e-12);
    EXPECT_NEAR(law.c1, 0.0, 1e-12);
    EXPECT_NEAR(law.c2, 0.58, 1e-12);
    EXPECT_NEAR(law.length(0), 1.46373, 5e-6);
    EXPECT_NEAR(law.length(0), std::sqrt(2.1425), 1e-12);
    EXPECT_NEAR(law.minLength(), 1.25, 1e-12);
    EXPECT_NEAR(law.maxLength(), 1.65, 1e-12);
    EXPECT_NEAR(law.angleOfMaxLength(), kPi / 2, 1e-12);
    EXPECT_NEAR(law.angleOfMinLength(), -kPi / 2, 1e-12);
}

TEST(ActuatorLengthLaw, AppendixJoint2LengthFromAngle)
{
    const JointGeometry g = appendixJoint2();
    const ActuatorLengthLaw law = g.lengthLaw();
    for (double theta : {-1.2, -0.32, 0.0, 0.5, 1.0, 2.8}) {
        const double byHand = std::sqrt(2.1425 + 0.58 * std::sin(theta));
        EXPECT_NEAR(law.length(theta), byHand, 1e-12) << theta;
        EXPECT_NEAR(lengthThroughPose(g, theta), byHand, 1e-12) << theta;
        EXPECT_NEAR(g.coordinateFromKinematic(theta), byHand, 1e-12) << theta;
        // dL/dθ = 0.58 cos θ / (2 L)
        EXPECT_NEAR(law.lengthRate(theta), 0.58 * std::cos(theta) / (2 * byHand), 1e-12) << theta;
        EXPECT_NEAR(law.angleRate(theta), 2 * byHand / (0.58 * std::cos(theta)), 1e-9) << theta;
    }
}

TEST(ActuatorLengthLaw, AppendixJoint2AngleFromLength)
{
    const JointGeometry g = appendixJoint2();
    const ActuatorLengthLaw law = g.lengthLaw();
    // the branch nearest 0 is θ = asin((L² − 2.1425) / 0.58), in [−π/2, π/2]
    for (double len : {1.25, 1.3, 1.4, 1.464, 1.5, 1.617, 1.65}) {
        const auto theta = law.angle(len);
        ASSERT_TRUE(theta.has_value()) << len;
        EXPECT_NEAR(*theta, std::asin(std::clamp((len * len - 2.1425) / 0.58, -1.0, 1.0)), 1e-7)
            << len;
        EXPECT_NEAR(law.length(*theta), len, 1e-12) << len;
    }
    EXPECT_NEAR(*law.angle(1.464), 0.00137241, 1e-8);  // Appendix A QI
    EXPECT_NEAR(*law.angle(1.4), -0.320093, 1e-6);  // LL
    EXPECT_NEAR(*law.angle(1.617), 0.951210, 1e-6);  // UL
    EXPECT_NEAR(*g.kinematicFromCoordinate(1.464), *law.angle(1.464), 0);
    // the other branch, when asked near it
    EXPECT_NEAR(*law.angleNear(1.464, 3.0), kPi - 0.00137241, 1e-8);
    // out of reach
    EXPECT_FALSE(law.angle(2.1).has_value());
    EXPECT_FALSE(law.angle(1.2).has_value());
    EXPECT_FALSE(g.kinematicFromCoordinate(2.1).has_value());
    // on the edge, within the tolerance: clamped to the dead point
    EXPECT_NEAR(*law.angle(1.65 + 1e-12), kPi / 2, 1e-5);
}

TEST(ActuatorLengthLaw, AppendixJoint5)
{
    const JointGeometry g = appendixJoint5();
    const ActuatorLengthLaw law = g.lengthLaw();
    EXPECT_NEAR(law.c0, 0.11, 1e-12);
    EXPECT_NEAR(law.c1, 0.06, 1e-12);
    EXPECT_NEAR(law.c2, 0.09, 1e-12);
    EXPECT_NEAR(law.length(0), std::sqrt(0.17), 1e-12);
    EXPECT_NEAR(lengthThroughPose(g, 0), std::sqrt(0.17), 1e-12);
    const double rho = std::hypot(0.06, 0.09);
    EXPECT_NEAR(law.minLength(), std::sqrt(0.11 - rho), 1e-12);
    EXPECT_NEAR(law.maxLength(), std::sqrt(0.11 + rho), 1e-12);
    EXPECT_NEAR(law.minLength(), 0.0428189, 1e-6);
    EXPECT_NEAR(law.maxLength(), 0.467083, 1e-6);

    // QI 0.412: L² = 0.11 + ρ cos(θ − φ), φ = atan2(0.09, 0.06); branch φ − acos(k) is nearer 0
    const double phi = std::atan2(0.09, 0.06);
    const double k = (0.412 * 0.412 - 0.11) / rho;
    const auto theta = law.angle(0.412);
    ASSERT_TRUE(theta.has_value());
    EXPECT_NEAR(*theta, phi - std::acos(k), 1e-12);
    EXPECT_NEAR(*theta, -0.00284176, 1e-8);
    EXPECT_NEAR(lengthThroughPose(g, *theta), 0.412, 1e-12);

    // rates against finite differences
    for (double t : {-2.0, -0.5, 0.0, 0.7, 2.5}) {
        const double h = 1e-6;
        const double fd = (law.length(t + h) - law.length(t - h)) / (2 * h);
        EXPECT_NEAR(law.lengthRate(t), fd, 1e-8) << t;
        EXPECT_NEAR(law.angleRate(t) * law.lengthRate(t), 1.0, 1e-12) << t;
    }
}

TEST(ActuatorLengthLaw, LengthMeasuredFromPoses)
{
    const JointGeometry g = appendixJoint2();
    const Eigen::Isometry3d X_w1(Eigen::AngleAxisd(0.7, Vector3d::UnitZ()));
    const Eigen::Isometry3d X_w2 = X_w1 * g.relativePose(0.3);
    EXPECT_NEAR(g.measureCoordinate(X_w1, X_w2), std::sqrt(2.1425 + 0.58 * std::sin(0.3)), 1e-12);
    EXPECT_NEAR(g.measureKinematic(X_w1, X_w2), 0.3, 1e-12);
}

TEST(ActuatorLengthLaw, ConstantLengthHasNoAngle)
{
    JointSpec j;  // CL1 and CL2 both on the axis
    j.type = JointType::Actuator;
    j.side1 = side(1, Vector3d::Zero(), Vector3d::UnitX(), Vector3d::UnitY());
    j.side2 = side(2, Vector3d::Zero(), Vector3d::UnitX(), Vector3d::UnitY());
    j.cl1 = Vector3d(0.2, 0, 0);
    j.cl2 = Vector3d(0.7, 0, 0);
    const ActuatorLengthLaw law = makeJointGeometry(j).lengthLaw();
    EXPECT_NEAR(law.rho(), 0, 1e-15);
    EXPECT_NEAR(law.length(1.0), 0.5, 1e-15);
    EXPECT_FALSE(law.angle(0.5).has_value());
}

TEST(WrapAngle, ToHalfOpenInterval)
{
    EXPECT_NEAR(wrapAngle(3 * kPi / 2), -kPi / 2, 1e-12);
    EXPECT_NEAR(wrapAngle(-kPi), kPi, 1e-12);
    EXPECT_NEAR(wrapAngle(kPi), kPi, 1e-12);
    EXPECT_NEAR(wrapAngle(0.5), 0.5, 0);
}

}  // namespace
}  // namespace solver
