#include "solver/kinematics/positions.h"

#include "solver/compile/spanning_tree.h"
#include "tests/solver/spec_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace solver {
namespace {

using Eigen::Vector3d;
using test::side;
constexpr double kPi = std::numbers::pi;

// A double pendulum in the xy plane: link 1 (body 1) of 1 m from the origin along its local x,
// link 2 (body 2) of 0.5 m hung at link 1's tip; both joints about z, R = x, so q = 0 is stretched
// along world x and each angle is measured from the previous link.
ModelSpec doublePendulum()
{
    test::SpecBuilder b;
    b.body(1, 1.0, Vector3d(0.1, 0.1, 0.1));
    b.body(2, 1.0, Vector3d(0.1, 0.1, 0.1));
    b.joint(1, JointType::Revolute, side(0, Vector3d::Zero()), side(1, Vector3d::Zero()));
    b.joint(2, JointType::Revolute, side(1, Vector3d(1, 0, 0)), side(2, Vector3d::Zero()));
    return b.spec;
}

TEST(Positions, DoublePendulumByHand)
{
    const ModelSpec spec = doublePendulum();
    Topology topo;
    buildSpanningTree(spec, topo);
    const auto geometry = makeJointGeometries(spec);

    const double q1 = kPi / 6, q2 = kPi / 4;
    const auto X = bodyPoses(topo, geometry, Eigen::Vector2d(q1, q2));
    ASSERT_EQ(X.size(), 3u);
    EXPECT_TRUE(X[0].isApprox(Eigen::Isometry3d::Identity()));

    // body 1 at the origin, turned by 30°; body 2 at link 1's tip, turned by 75°
    EXPECT_TRUE(X[1].translation().isZero(1e-15));
    EXPECT_TRUE(
        X[1].linear().isApprox(Eigen::AngleAxisd(q1, Vector3d::UnitZ()).toRotationMatrix()));
    EXPECT_TRUE(X[2].translation().isApprox(Vector3d(std::cos(q1), std::sin(q1), 0)));
    EXPECT_TRUE(
        X[2].linear().isApprox(Eigen::AngleAxisd(q1 + q2, Vector3d::UnitZ()).toRotationMatrix()));

    // tip of link 2 (0.5, 0, 0 local): (cos 30° + 0.5 cos 75°, sin 30° + 0.5 sin 75°, 0)
    const Vector3d tip = X[2] * Vector3d(0.5, 0, 0);
    EXPECT_NEAR(tip.x(), std::cos(q1) + 0.5 * std::cos(q1 + q2), 1e-15);
    EXPECT_NEAR(tip.y(), std::sin(q1) + 0.5 * std::sin(q1 + q2), 1e-15);
    EXPECT_NEAR(tip.x(), 0.995435, 1e-6);
    EXPECT_NEAR(tip.y(), 0.982963, 1e-6);
    EXPECT_NEAR(tip.z(), 0.0, 1e-15);
}

TEST(Positions, ReversedRevoluteJoint)
{
    // C 1: B1 1 … B2 0 …: the tree reaches body 1 from ground, i.e. from side 2.
    // q is the angle from R1 (on body 1) to R2 (on ground): body 1 is turned by −q.
    test::SpecBuilder b;
    b.body(1, 1.0, Vector3d(1, 1, 1));
    b.joint(1, JointType::Revolute, side(1, Vector3d(-1, 0, 0)), side(0, Vector3d(2, 0, 0)));
    Topology topo;
    buildSpanningTree(b.spec, topo);
    ASSERT_EQ(topo.treeJoints, std::vector<int>{0});
    EXPECT_TRUE(topo.reversed[0]);
    EXPECT_EQ(topo.parentBody[1], 0);
    EXPECT_EQ(treeChildBody(topo, 0), 1);
    EXPECT_EQ(treeParentBody(topo, 0), 0);

    const double q = 0.3;
    const auto X = bodyPoses(topo, makeJointGeometries(b.spec), Eigen::VectorXd::Constant(1, q));
    EXPECT_TRUE(
        X[1].linear().isApprox(Eigen::AngleAxisd(-q, Vector3d::UnitZ()).toRotationMatrix()));
    // body 1's point (−1, 0, 0) sits on ground's (2, 0, 0); body 1's origin 1 m along its own x
    EXPECT_TRUE((X[1] * Vector3d(-1, 0, 0)).isApprox(Vector3d(2, 0, 0)));
    EXPECT_TRUE(X[1].translation().isApprox(Vector3d(2 + std::cos(-q), std::sin(-q), 0)));
    // the measured angle is q again
    EXPECT_NEAR(makeJointGeometries(b.spec)[0].measureKinematic(X[1], X[0]), q, 1e-12);
}

TEST(Positions, ReversedPrismaticJoint)
{
    // C 1 T 2: B1 1 P1 0 0 0 R1 x; B2 0 P2 0 0 0: P2 = P1 + q R1, so body 1 sits at −q along x
    test::SpecBuilder b;
    b.body(1, 1.0, Vector3d(1, 1, 1));
    b.joint(1, JointType::Prismatic, side(1, Vector3d::Zero()), side(0, Vector3d::Zero()));
    Topology topo;
    buildSpanningTree(b.spec, topo);
    EXPECT_TRUE(topo.reversed[0]);
    const auto X = bodyPoses(topo, makeJointGeometries(b.spec), Eigen::VectorXd::Constant(1, 0.4));
    EXPECT_TRUE(X[1].translation().isApprox(Vector3d(-0.4, 0, 0)));
}

TEST(Positions, MotionVectorsMatchFiniteDifferences)
{
    // a spatial chain with a reversed joint, a prismatic and a T 1 joint
    test::SpecBuilder b;
    b.body(1, 1.0, Vector3d(1, 1, 1));
    b.body(2, 1.0, Vector3d(1, 1, 1));
    b.body(3, 1.0, Vector3d(1, 1, 1));
    b.body(4, 1.0, Vector3d(1, 1, 1));
    b.joint(1, JointType::Revolute,
            side(0, Vector3d(0, 0, 0.5), Vector3d::UnitZ(), Vector3d::UnitX()),
            side(1, Vector3d(0.1, 0, 0), Vector3d::UnitZ(), Vector3d::UnitY()));
    b.joint(2, JointType::Revolute,
            side(2, Vector3d(0, -0.3, 0), Vector3d(1, 1, 0), Vector3d(0, 0, 1)),
            side(1, Vector3d(0.5, 0.2, 0), Vector3d::UnitX(), Vector3d::UnitY()));  // reversed
    b.joint(3, JointType::Prismatic,
            side(2, Vector3d(0, 0.4, 0), Vector3d::UnitZ(), Vector3d(0, 1, 0.3)),
            side(3, Vector3d(0, -0.2, 0), Vector3d::UnitZ(), Vector3d::UnitY()));
    b.actuator(4, side(3, Vector3d(0, 0.1, 0), Vector3d::UnitX(), Vector3d::UnitY()),
               side(4, Vector3d(0, -0.1, 0.1), Vector3d::UnitX(), Vector3d::UnitZ()),
               Vector3d(0, 0, -0.2), Vector3d(0, 0.3, 0));
    Topology topo;
    buildSpanningTree(b.spec, topo);
    ASSERT_EQ(topo.treeJoints, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_FALSE(topo.reversed[0]);
    EXPECT_TRUE(topo.reversed[1]);
    const auto geometry = makeJointGeometries(b.spec);

    const Eigen::Vector4d theta(0.3, -0.7, 0.15, 0.4);
    const auto X = bodyPoses(topo, geometry, theta);
    const double h = 1e-6;
    for (int j = 0; j < 4; ++j) {
        const Vector6d s = jointMotionWorld(topo, geometry, X, j);
        Eigen::Vector4d tp = theta, tm = theta;
        tp[j] += h;
        tm[j] -= h;
        const auto Xp = bodyPoses(topo, geometry, tp);
        const auto Xm = bodyPoses(topo, geometry, tm);
        const int child = treeChildBody(topo, j);
        // a point of the child body: dx = ω × x + v_O
        const Vector3d local(0.3, -0.2, 0.5);
        const Vector3d dx = (Xp[child] * local - Xm[child] * local) / (2 * h);
        const Vector3d x = X[child] * local;
        EXPECT_TRUE((s.head<3>().cross(x) + s.tail<3>()).isApprox(dx, 1e-7)) << "joint " << j;
        // the body's rotation rate: dR Rᵀ = [ω]×
        const Eigen::Matrix3d dR = (Xp[child].linear() - Xm[child].linear()) / (2 * h);
        const Eigen::Matrix3d w = dR * X[child].linear().transpose();
        EXPECT_NEAR(w(2, 1), s[0], 1e-7) << j;
        EXPECT_NEAR(w(0, 2), s[1], 1e-7) << j;
        EXPECT_NEAR(w(1, 0), s[2], 1e-7) << j;
        // joints on the path to ground move the body, others not
        EXPECT_TRUE(jointMovesBody(topo, j, 4));
    }
    EXPECT_FALSE(jointMovesBody(topo, 2, 2));
    EXPECT_TRUE(jointMovesBody(topo, 1, 2));
    EXPECT_FALSE(jointMovesBody(topo, 0, 0));
}

}  // namespace
}  // namespace solver
