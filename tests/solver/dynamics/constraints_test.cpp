// The one constraint implementation (solver/dynamics/constraints.h) on compiled
// models: the rows Φ and their Jacobian G, the initial assembly (assembleLoops) that
// the compiler closes loops with, and the projection the simulation keeps them with.

#include "solver/dynamics/constraints.h"

#include "solver/compile/compile.h"
#include "solver/dynamics/mass_matrix.h"
#include "solver/kinematics/joint_geometry.h"
#include "solver/kinematics/kinematics.h"
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
// (body 2), rocker 1.5 m (body 3); links along their local x, all axes z. Joint 4 closes
// it; the tree's joints 1, 2, 3 are tree indices 0, 1, 2.
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
    b.set(1, "QI", kPi / 3, 7);
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
    b.joint(4, JointType::Prismatic, side(0, Vector3d(0, 0, 0), Vector3d::UnitZ(), Vector3d::UnitX()),
            side(3, Vector3d(0, 0, 0), Vector3d::UnitZ(), Vector3d::UnitX()));
    return b.spec;
}

// A non-planar loop: skew axes, a T 1 joint in the tree, a revolute cut.
ModelSpec spatialLoop()
{
    test::SpecBuilder b;
    b.body(1, 1.0, Vector3d(1, 1, 1));
    b.body(2, 1.0, Vector3d(1, 1, 1));
    b.joint(1, JointType::Revolute, side(0, Vector3d(0, 0, 0), Vector3d(0, 1, 1), Vector3d(1, 0, 0)),
            side(1, Vector3d(0.1, 0, 0), Vector3d::UnitZ(), Vector3d::UnitX()));
    b.actuator(2, side(1, Vector3d(1, 0, 0), Vector3d(1, 0, 1), Vector3d(0, 1, 0)),
               side(2, Vector3d(0, 0, 0), Vector3d::UnitX(), Vector3d::UnitY()), Vector3d(0, 0.3, 0),
               Vector3d(0, 0.2, 0.4));
    b.joint(3, JointType::Revolute, side(2, Vector3d(0.5, 0.5, 0), Vector3d::UnitY(), Vector3d::UnitZ()),
            side(0, Vector3d(1, 1, 1), Vector3d::UnitX(), Vector3d::UnitY()));
    return b.spec;
}

/// A model whose loops need not close at its QI (the spatial loop does not): numbered
/// and framed as compile does it, without the initial assembly.
std::shared_ptr<const Model> modelOf(const ModelSpec& spec)
{
    Diagnostics diags("m.pad");
    const CompileResult r = compileModel(spec, diags);
    EXPECT_TRUE(r.model) << (diags.empty() ? "" : diags.items()[0].format());
    return r.model;
}

Eigen::VectorXd residualAt(const Model& m, Data& d, const Eigen::VectorXd& q)
{
    State s = makeState(m);
    s.q = q;
    forwardKinematics(m, s, d);
    collectConstraints(m, s, d.constraints);
    Eigen::VectorXd phi;
    constraintResidual(m, d, d.constraints, phi);
    return phi;
}

void expectJacobianMatchesFiniteDifferences(const Model& m, const Eigen::VectorXd& q)
{
    Data d(m);
    State s = makeState(m);
    s.q = q;
    s.qd.setZero();
    const Eigen::MatrixXd G = constraintJacobianAt(m, s, d);
    ASSERT_EQ(G.rows(), 5 * static_cast<Eigen::Index>(m.cuts.size()));
    ASSERT_EQ(G.cols(), m.nb);
    const double h = 1e-6;
    for (int c = 0; c < m.nb; ++c) {
        Eigen::VectorXd qp = q, qm = q;
        qp[c] += h;
        qm[c] -= h;
        const Eigen::VectorXd fd = (residualAt(m, d, qp) - residualAt(m, d, qm)) / (2 * h);
        EXPECT_LT((G.col(c) - fd).norm(), 1e-8) << "column " << c << "\n" << G.col(c) << "\n" << fd;
    }
}

TEST(Constraints, JacobianMatchesFiniteDifferencesRevoluteCut)
{
    const auto m = modelOf(fourBar());
    ASSERT_TRUE(m);
    Eigen::VectorXd q(3);
    q << 0.4, -0.9, 1.3;  // an arbitrary, not closed configuration
    expectJacobianMatchesFiniteDifferences(*m, q);
}

TEST(Constraints, JacobianMatchesFiniteDifferencesPrismaticCut)
{
    const auto m = modelOf(sliderCrankPrismaticCut());
    ASSERT_TRUE(m);
    Eigen::VectorXd q(3);
    q << 0.7, -1.1, 0.2;
    expectJacobianMatchesFiniteDifferences(*m, q);
}

TEST(Constraints, JacobianMatchesFiniteDifferencesSpatialLoop)
{
    // the loop cannot close at every configuration: compile the open tree, then add the
    // cut joint 3 as the compiler would
    ModelSpec spec = spatialLoop();
    const JointSpec cutSpec = spec.joints[2];
    spec.joints.pop_back();
    const auto tree = modelOf(spec);
    ASSERT_TRUE(tree);
    auto m = std::make_shared<Model>(*tree);
    const JointGeometry g = makeJointGeometry(cutSpec);
    CutJoint cut;
    cut.jointId = cutSpec.id;
    cut.type = cutSpec.type;
    cut.body1 = m->bodyIndex(cutSpec.side1.body);
    cut.body2 = m->bodyIndex(cutSpec.side2.body);
    cut.X_1 = g.side1.pose();
    cut.X_2 = g.side2.pose();
    m->cuts.push_back(cut);
    Eigen::VectorXd q(2);
    q << 0.3, 0.8;
    expectJacobianMatchesFiniteDifferences(*m, q);
}

TEST(Constraints, ResidualVanishesAtHandSolvedFourBar)
{
    // crank at 60°: coupler and rocker angles by intersecting circles (see topology_test)
    const auto m = modelOf(fourBar());
    ASSERT_TRUE(m);
    Data d(*m);
    Eigen::VectorXd q(3);
    q << kPi / 3, -0.7554323113484815, -2.143214898887717;
    EXPECT_LT(residualAt(*m, d, q).norm(), 1e-12);

    // off the solution the point rows (scaled by the model's length) give the gap between P1 and P2
    q[2] += 0.1;
    const Eigen::VectorXd phi = residualAt(*m, d, q);
    EXPECT_NEAR(phi.head<3>().norm() * m->lengthScale, 2 * 1.5 * std::sin(0.05), 1e-12);
    EXPECT_NEAR(phi.tail<2>().norm(), 0, 1e-15);  // planar: axes stay parallel
    EXPECT_TRUE(constraintRowIsLength(ConstraintKind::Revolute, 0));
    EXPECT_FALSE(constraintRowIsLength(ConstraintKind::Revolute, 3));
    EXPECT_FALSE(constraintRowIsLength(ConstraintKind::Prismatic, 0));
    EXPECT_TRUE(constraintRowIsLength(ConstraintKind::Prismatic, 4));
}

TEST(Constraints, AssemblyFromANearbyGuess)
{
    const auto m = modelOf(fourBar());
    ASSERT_TRUE(m);
    Data d(*m);
    Eigen::VectorXd q(3);
    q << kPi / 3, -0.5, -2.5;
    AssemblyOptions options;
    options.lengthScale = 4;
    const AssemblyResult r = assembleLoops(*m, d, {1, 2}, q, options);
    EXPECT_TRUE(r.converged);
    EXPECT_LT(r.residualNorm, 1e-10);
    EXPECT_EQ(r.residual.size(), 5);
    EXPECT_NEAR(q[0], kPi / 3, 0);  // held
    EXPECT_NEAR(q[1], -0.7554323113484815, 1e-9);
    EXPECT_NEAR(q[2], -2.143214898887717, 1e-9);
}

TEST(Constraints, AssemblyOfALoopThatCannotCloseLeavesTheGapInMetres)
{
    // the four-bar's rocker pivot moved 4 m from the ground's: the loop stays open by 1 m at
    // least; the residual is unscaled whatever the model's length scale
    ModelSpec spec = fourBar();
    spec.joints[3].side2.p = Vector3d(4, 0, 0);
    spec.joints[1].side1.p = Vector3d(1, 0, 0);
    spec.joints[2].side1.p = Vector3d(1, 0, 0);
    spec.joints[3].side1.p = Vector3d(1, 0, 0);
    Diagnostics diags("m.pad");
    EXPECT_FALSE(compileModel(spec, diags).model);
    ASSERT_EQ(diags.errorCount(), 1u);
    EXPECT_EQ(diags.items()[0].code, "loop-unsatisfiable");
    EXPECT_NE(diags.items()[0].message.find("P1 and P2 stay"), std::string::npos) << diags.items()[0].message;
}

TEST(Constraints, ProjectionClosesPositionsAndRatesMovingOnlyTheFreeJoints)
{
    const auto m = modelOf(sliderCrankPrismaticCut());
    ASSERT_TRUE(m);
    Data d(*m);
    State s = makeState(*m);
    s.q[1] += 0.05;  // open the loop
    s.q[2] -= 0.03;
    s.qd << 0.4, 1.0, -0.7;  // rates that do not keep it
    const double crank = s.q[0], crankRate = s.qd[0];
    ASSERT_TRUE(projectOntoConstraints(*m, s, d, {1, 2}));
    EXPECT_EQ(s.q[0], crank);  // held
    EXPECT_EQ(s.qd[0], crankRate);
    EXPECT_LT(residualAt(*m, d, s.q).lpNorm<Eigen::Infinity>(), 1e-12);
    const Eigen::MatrixXd G = constraintJacobianAt(*m, s, d);
    EXPECT_LT((G * s.qd).lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST(Constraints, FreeResponseKeepsTheConstraintsAndIsMassWeighted)
{
    const auto m = modelOf(fourBar());
    ASSERT_TRUE(m);
    Data d(*m);
    const State s = makeState(*m);  // assembled by the compiler
    const Eigen::MatrixXd G = constraintJacobianAt(*m, s, d);
    forwardKinematics(*m, s, d);
    Eigen::MatrixXd M;
    massMatrix(*m, d, M);
    // an impulse on the crank, all three joints free: the rate change keeps G Δθ̇ = 0 and is
    // M-orthogonal to every motion the loop allows but the one it takes
    const Eigen::VectorXd impulse = Eigen::VectorXd::Unit(3, 0);
    const Eigen::VectorXd dq = freeResponse(M, {0, 1, 2}, impulse, G, Eigen::VectorXd::Zero(3));
    EXPECT_LT((G * dq).norm(), 1e-12);
    EXPECT_GT(dq[0], 0);
    // the work of the impulse equals the kinetic energy it gives (a plastic, constrained response)
    EXPECT_NEAR(impulse.dot(dq), dq.dot(M * dq), 1e-12);
}

}  // namespace
}  // namespace solver
