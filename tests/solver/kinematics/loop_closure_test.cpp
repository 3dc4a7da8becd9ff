#include "solver/kinematics/loop_closure.h"

#include "solver/compile/spanning_tree.h"
#include "solver/kinematics/positions.h"
#include "tests/solver/spec_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace solver {
namespace {

using Eigen::Vector3d;
using test::side;
constexpr double kPi = std::numbers::pi;

// Planar four-bar: ground pivots at (0,0,0) and (2,0,0); crank 1 m (body 1), coupler 2 m
// (body 2), rocker 1.5 m (body 3); links along their local x, all axes z. Joint 4 closes it.
ModelSpec fourBar()
{
    test::SpecBuilder b;
    b.body(1, 1.0, Vector3d(0.1, 0.1, 0.1), Vector3d(0.5, 0, 0));
    b.body(2, 2.0, Vector3d(0.1, 0.1, 0.1), Vector3d(1.0, 0, 0));
    b.body(3, 1.5, Vector3d(0.1, 0.1, 0.1), Vector3d(0.75, 0, 0));
    b.joint(1, JointType::Revolute, side(0, Vector3d(0, 0, 0)), side(1, Vector3d(0, 0, 0)));
    b.joint(2, JointType::Revolute, side(1, Vector3d(1, 0, 0)), side(2, Vector3d(0, 0, 0)));
    b.joint(3, JointType::Revolute, side(2, Vector3d(2, 0, 0)), side(3, Vector3d(0, 0, 0)));
    b.joint(4, JointType::Revolute, side(3, Vector3d(1.5, 0, 0)), side(0, Vector3d(2, 0, 0)));
    return b.spec;
}

// Slider-crank whose slider joint (T 2 along x, joint 4) closes the loop.
ModelSpec sliderCrankPrismaticCut()
{
    test::SpecBuilder b;
    b.body(1, 1.0, Vector3d(0.1, 0.1, 0.1));
    b.body(2, 1.0, Vector3d(0.1, 0.1, 0.1));
    b.body(3, 1.0, Vector3d(0.1, 0.1, 0.1));
    b.joint(1, JointType::Revolute, side(0, Vector3d::Zero()), side(1, Vector3d::Zero()));
    b.joint(2, JointType::Revolute, side(1, Vector3d(1, 0, 0)), side(2, Vector3d::Zero()));
    b.joint(3, JointType::Revolute, side(2, Vector3d(2, 0, 0)), side(3, Vector3d::Zero()));
    b.joint(4, JointType::Prismatic,
            side(0, Vector3d(0, 0, 0), Vector3d::UnitZ(), Vector3d::UnitX()),
            side(3, Vector3d(0, 0, 0), Vector3d::UnitZ(), Vector3d::UnitX()));
    return b.spec;
}

void expectJacobianMatchesFiniteDifferences(const ModelSpec& spec, const Eigen::VectorXd& theta)
{
    Topology topo;
    buildSpanningTree(spec, topo);
    ASSERT_FALSE(topo.loopJoints.empty());
    const auto geometry = makeJointGeometries(spec);
    Eigen::MatrixXd jac;
    closureJacobian(topo, geometry, bodyPoses(topo, geometry, theta), jac);
    ASSERT_EQ(jac.rows(), 5 * static_cast<Eigen::Index>(topo.loopJoints.size()));
    ASSERT_EQ(jac.cols(), static_cast<Eigen::Index>(topo.treeJoints.size()));
    const double h = 1e-6;
    for (std::size_t c = 0; c < topo.treeJoints.size(); ++c) {
        Eigen::VectorXd tp = theta, tm = theta;
        tp[topo.treeJoints[c]] += h;
        tm[topo.treeJoints[c]] -= h;
        Eigen::VectorXd fp, fm;
        closureResidual(topo, geometry, bodyPoses(topo, geometry, tp), fp);
        closureResidual(topo, geometry, bodyPoses(topo, geometry, tm), fm);
        const Eigen::VectorXd fd = (fp - fm) / (2 * h);
        EXPECT_LT((jac.col(c) - fd).norm(), 1e-8) << "column " << c << "\n"
                                                  << jac.col(c) << "\n"
                                                  << fd;
    }
}

TEST(LoopClosure, JacobianMatchesFiniteDifferencesRevoluteCut)
{
    // an arbitrary, not closed configuration
    Eigen::VectorXd theta(4);
    theta << 0.4, -0.9, 1.3, 0.0;
    expectJacobianMatchesFiniteDifferences(fourBar(), theta);
}

TEST(LoopClosure, JacobianMatchesFiniteDifferencesPrismaticCut)
{
    Eigen::VectorXd theta(4);
    theta << 0.7, -1.1, 0.2, 0.0;
    expectJacobianMatchesFiniteDifferences(sliderCrankPrismaticCut(), theta);
}

TEST(LoopClosure, JacobianMatchesFiniteDifferencesSpatialLoop)
{
    // non-planar loop: skew axes, a T 1 joint in the tree, revolute cut
    test::SpecBuilder b;
    b.body(1, 1.0, Vector3d(1, 1, 1));
    b.body(2, 1.0, Vector3d(1, 1, 1));
    b.joint(1, JointType::Revolute,
            side(0, Vector3d(0, 0, 0), Vector3d(0, 1, 1), Vector3d(1, 0, 0)),
            side(1, Vector3d(0.1, 0, 0), Vector3d::UnitZ(), Vector3d::UnitX()));
    b.actuator(2, side(1, Vector3d(1, 0, 0), Vector3d(1, 0, 1), Vector3d(0, 1, 0)),
               side(2, Vector3d(0, 0, 0), Vector3d::UnitX(), Vector3d::UnitY()),
               Vector3d(0, 0.3, 0), Vector3d(0, 0.2, 0.4));
    b.joint(3, JointType::Revolute,
            side(2, Vector3d(0.5, 0.5, 0), Vector3d::UnitY(), Vector3d::UnitZ()),
            side(0, Vector3d(1, 1, 1), Vector3d::UnitX(), Vector3d::UnitY()));
    Eigen::VectorXd theta(3);
    theta << 0.3, 0.8, 0.0;
    expectJacobianMatchesFiniteDifferences(b.spec, theta);
}

TEST(LoopClosure, ResidualVanishesAtHandSolvedFourBar)
{
    // crank at 60°: coupler and rocker angles by intersecting circles (see topology_test)
    const ModelSpec spec = fourBar();
    Topology topo;
    buildSpanningTree(spec, topo);
    const auto geometry = makeJointGeometries(spec);
    Eigen::VectorXd theta(4);
    theta << kPi / 3, -0.7554323113484815, -2.143214898887717, 0;
    Eigen::VectorXd phi;
    closureResidual(topo, geometry, bodyPoses(topo, geometry, theta), phi);
    EXPECT_LT(phi.norm(), 1e-12);

    // off the solution the point rows give the gap between P1 and P2
    theta[2] += 0.1;
    closureResidual(topo, geometry, bodyPoses(topo, geometry, theta), phi);
    EXPECT_NEAR(phi.head<3>().norm(), 2 * 1.5 * std::sin(0.05), 1e-12);
    EXPECT_NEAR(phi.tail<2>().norm(), 0, 1e-15);  // planar: axes stay parallel
}

TEST(LoopClosure, SolveFromNearbyGuess)
{
    const ModelSpec spec = fourBar();
    Topology topo;
    buildSpanningTree(spec, topo);
    const auto geometry = makeJointGeometries(spec);
    Eigen::VectorXd theta(4);
    theta << kPi / 3, -0.5, -2.5, 0;
    const ClosureSolveResult r = solveClosure(topo, geometry, {1, 2}, theta);
    EXPECT_TRUE(r.converged);
    EXPECT_LT(r.residualNorm, 1e-10);
    EXPECT_NEAR(theta[0], kPi / 3, 0);  // held
    EXPECT_NEAR(theta[1], -0.7554323113484815, 1e-9);
    EXPECT_NEAR(theta[2], -2.143214898887717, 1e-9);
}

}  // namespace
}  // namespace solver
