#include "solver/kinematics/kinematics.h"

#include "tests/solver/spec_oracle.h"
#include "tests/solver/dynamics/random_states.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

namespace solver {
namespace {

using Eigen::Vector3d;
using Eigen::VectorXd;

// ------------------------------------------------------------------ by hand

TEST(Kinematics, PendulumByHand)
{
    // bob at (0, sin θ, −cos θ), turning about x
    const auto model = test::compileExample("pendulum.pad");
    ASSERT_TRUE(model);
    const double th = 0.3, thd = 0.7, thdd = -1.1;
    Data d(*model);
    forwardKinematics(*model, VectorXd::Constant(1, th), VectorXd::Constant(1, thd), d);
    bodyAccelerations(*model, VectorXd::Constant(1, thdd), d);
    const double s = std::sin(th), c = std::cos(th);
    EXPECT_TRUE(comPosition(*model, d, 0).isApprox(Vector3d(0, s, -c), 1e-15));
    EXPECT_TRUE(d.vel[0].isApprox(thd * Vector3d(0, c, s), 1e-15));
    EXPECT_TRUE(d.omega[0].isApprox(Vector3d(thd, 0, 0), 1e-15));
    EXPECT_TRUE(d.alpha[0].isApprox(Vector3d(thdd, 0, 0), 1e-15));
    EXPECT_TRUE(d.acc[0].isApprox(Vector3d(0, thdd * c - thd * thd * s, thdd * s + thd * thd * c), 1e-14));
    // the joint point stays at the origin; the rod's far end (P2, 1 m above the bob) too
    EXPECT_TRUE(bodyPointPosition(d, 0, Vector3d(0, 0, 1)).isZero(1e-15));
    EXPECT_TRUE(bodyPointVelocity(d, 0, Vector3d(0, 0, 1)).isZero(1e-15));
    EXPECT_TRUE(bodyPointAcceleration(d, 0, Vector3d(0, 0, 1)).isZero(1e-14));
    // energy: ½ (m L² + I) θ̇² − m g L cos θ
    EXPECT_NEAR(kineticEnergy(*model, d), 0.5 * (1 + 1e-6) * thd * thd, 1e-15);
    EXPECT_NEAR(potentialEnergy(*model, d), -9.81 * c, 1e-14);
    EXPECT_NEAR(mechanicalEnergy(*model, d), 0.5 * (1 + 1e-6) * thd * thd - 9.81 * c, 1e-14);
}

TEST(Kinematics, InclineByHand)
{
    // the block's centre at q·(cos 30°, 0, −sin 30°)
    const auto model = test::compileExample("incline_slider.pad");
    ASSERT_TRUE(model);
    Data d(*model);
    forwardKinematics(*model, VectorXd::Constant(1, 1.5), VectorXd::Constant(1, 2.0), d);
    bodyAccelerations(*model, VectorXd::Constant(1, 4.905), d);
    const Vector3d down(0.8660254, 0, -0.5);
    const Vector3d r = down.normalized();
    EXPECT_TRUE(comPosition(*model, d, 0).isApprox(1.5 * r, 1e-15));
    EXPECT_TRUE(comVelocity(*model, d, 0).isApprox(2.0 * r, 1e-15));
    EXPECT_TRUE(comAcceleration(*model, d, 0).isApprox(4.905 * r, 1e-15));
    EXPECT_TRUE(d.omega[0].isZero());
    // the joint frame on the block's side moves with it; on the ground's side it stays
    EXPECT_TRUE(jointFramePose(*model, d, 0).translation().isApprox(1.5 * r, 1e-15));
    EXPECT_TRUE(jointFramePose(*model, d, 0, true).translation().isZero());
    EXPECT_NEAR(potentialEnergy(*model, d), 10 * 9.81 * 1.5 * r.z(), 1e-12);
}

// ------------------------------------------------------------------ finite differences

// fourth-order central difference of f at 0: (−f(2h) + 8f(h) − 8f(−h) + f(−2h)) / 12h
template <typename F>
auto derivative(F f, double h) -> decltype(f(0.0))
{
    return (-f(2 * h) + 8 * f(h) - 8 * f(-h) + f(-2 * h)) / (12 * h);
}

// ω from Ṙ Rᵀ = [ω]×
Vector3d angularVelocity(const Eigen::Matrix3d& rdot, const Eigen::Matrix3d& r)
{
    const Eigen::Matrix3d w = rdot * r.transpose();
    return 0.5 * Vector3d(w(2, 1) - w(1, 2), w(0, 2) - w(2, 0), w(1, 0) - w(0, 1));
}

void checkAgainstFiniteDifferences(const std::shared_ptr<const Model>& model, unsigned seed)
{
    ASSERT_TRUE(model);
    const Model& m = *model;
    std::mt19937 rng(seed);
    Data d(m), dt(m);
    for (int trial = 0; trial < 10; ++trial) {
        const State s = test::randomState(m, rng, false);
        VectorXd qdd(m.nb);
        for (int i = 0; i < m.nb; ++i) qdd[i] = test::uniform(rng, -2, 2);
        forwardKinematics(m, s, d);
        bodyAccelerations(m, qdd, d);

        // the motion θ(t) = θ + θ̇t + ½θ̈t², at time t into dt
        auto at = [&](double t) -> const Data& {
            const VectorXd q = s.q + s.qd * t + 0.5 * qdd * t * t;
            const VectorXd qd = s.qd + qdd * t;
            forwardKinematics(m, q, qd, dt);
            bodyAccelerations(m, qdd, dt);
            return dt;
        };
        const double h = 1e-3;
        for (int i = 0; i < m.nb; ++i) {
            SCOPED_TRACE("body " + std::to_string(m.bodyId[i]));
            const Vector3d p(test::uniform(rng, -1, 1), test::uniform(rng, -1, 1), test::uniform(rng, -1, 1));
            const double tol = 1e-8;

            // velocities: derivatives of positions (eq. 2.2–2.4)
            const Vector3d vO = derivative([&](double t) { return Vector3d(at(t).X_wb[i].translation()); }, h);
            EXPECT_LT((d.vel[i] - vO).norm(), tol);
            const Eigen::Matrix3d rdot = derivative([&](double t) { return Eigen::Matrix3d(at(t).X_wb[i].linear()); }, h);
            const Vector3d w = angularVelocity(rdot, d.X_wb[i].linear());
            EXPECT_LT((d.omega[i] - w).norm(), tol);
            const Vector3d vp = derivative([&](double t) { return bodyPointPosition(at(t), i, p); }, h);
            EXPECT_LT((bodyPointVelocity(d, i, p) - vp).norm(), tol);
            const Vector3d vc = derivative([&](double t) { return comPosition(m, at(t), i); }, h);
            EXPECT_LT((comVelocity(m, d, i) - vc).norm(), tol);

            // accelerations: derivatives of velocities (eq. 2.5–2.7)
            const Vector3d aO = derivative([&](double t) { return Vector3d(at(t).vel[i]); }, h);
            EXPECT_LT((d.acc[i] - aO).norm(), tol);
            const Vector3d al = derivative([&](double t) { return Vector3d(at(t).omega[i]); }, h);
            EXPECT_LT((d.alpha[i] - al).norm(), tol);
            const Vector3d ap = derivative([&](double t) { return bodyPointVelocity(at(t), i, p); }, h);
            EXPECT_LT((bodyPointAcceleration(d, i, p) - ap).norm(), tol);
            const Vector3d ac = derivative([&](double t) { return comVelocity(m, at(t), i); }, h);
            EXPECT_LT((comAcceleration(m, d, i) - ac).norm(), tol);

            // the joint frames: the child's is carried by the child
            EXPECT_TRUE((d.X_wb[i] * m.X_cj[i]).isApprox(jointFramePose(m, d, i), 1e-14));
            const Eigen::Isometry3d parentSide = jointFramePose(m, d, i, true);
            const Eigen::Isometry3d childSide = jointFramePose(m, d, i);
            if (m.jointType[i] == JointType::Prismatic) {
                EXPECT_TRUE(parentSide.linear().isApprox(childSide.linear(), 1e-14));
                const Vector3d shift = childSide.translation() - parentSide.translation();
                EXPECT_LT((shift - m.axisSign[i] * s.q[i] * parentSide.linear().col(1)).norm(), 1e-14);
            } else {
                EXPECT_LT((parentSide.translation() - childSide.translation()).norm(), 1e-14);
                EXPECT_LT((parentSide.linear().col(0) - childSide.linear().col(0)).norm(), 1e-14);
                const double angle = std::atan2(
                    parentSide.linear().col(1).cross(childSide.linear().col(1)).dot(parentSide.linear().col(0)),
                    parentSide.linear().col(1).dot(childSide.linear().col(1)));
                EXPECT_NEAR(angle, wrapAngle(m.axisSign[i] * s.q[i]), 1e-12);
            }
        }
    }
}

TEST(Kinematics, VelocitiesAndAccelerationsAgainstFiniteDifferences)
{
    checkAgainstFiniteDifferences(test::compileText(test::kZooModel), 21);
    checkAgainstFiniteDifferences(test::compileText(test::kCylinderArmModel), 22);
    checkAgainstFiniteDifferences(test::compileExample("liner_manipulator.pad"), 23);
    checkAgainstFiniteDifferences(test::compileExample("incline_slider.pad"), 24);
}

// ------------------------------------------------------------------ energy

// E = ½θ̇ᵀMθ̇ + Σ −m g·c, with M from the spec oracle's composite-rigid-body mass matrix (tests/solver/spec_oracle.h)
void checkEnergy(const CompiledModel& loaded, unsigned seed)
{
    const auto model = test::modelOrFail(loaded);
    ASSERT_TRUE(model);
    const Model& m = *model;
    const Topology& topo = *loaded.topology;
    const std::vector<JointGeometry> geometry = makeJointGeometries(loaded.spec);
    std::vector<test::BodyInertia> inertia(topo.bodyIds.size());
    for (std::size_t b = 1; b < topo.bodyIds.size(); ++b) {
        const BodySpec* body = loaded.spec.body(topo.bodyIds[b]);
        if (!body || !body->hasMass) continue;
        inertia[b].mass = body->mass;
        inertia[b].cg = body->cg;
        inertia[b].inertia = body->inertiaTensor();
    }

    std::mt19937 rng(seed);
    Data d(m);
    for (int trial = 0; trial < 10; ++trial) {
        const State s = test::randomState(m, rng, false);
        forwardKinematics(m, s, d);

        // the tree's joints in Topology::treeJoints order are the model's tree indices
        VectorXd theta = VectorXd::Zero(static_cast<Eigen::Index>(geometry.size()));
        for (int i = 0; i < m.nb; ++i) {
            ASSERT_EQ(loaded.spec.joints[topo.treeJoints[i]].id, m.jointId[i]);
            theta[topo.treeJoints[i]] = s.q[i];
        }
        const std::vector<Eigen::Isometry3d> X = test::bodyPoses(topo, geometry, theta);
        const Eigen::MatrixXd M = test::treeMassMatrix(topo, geometry, X, inertia);
        double potential = 0;
        for (std::size_t b = 1; b < topo.bodyIds.size(); ++b) {
            potential -= inertia[b].mass * m.gravity.dot(X[b] * inertia[b].cg);
        }
        const double kinetic = 0.5 * s.qd.dot(M * s.qd);
        EXPECT_NEAR(kineticEnergy(m, d), kinetic, 1e-12 * std::max(1.0, kinetic));
        EXPECT_NEAR(potentialEnergy(m, d), potential, 1e-12 * std::max(1.0, std::abs(potential)));
        EXPECT_NEAR(mechanicalEnergy(m, d), kinetic + potential,
                    1e-12 * std::max(1.0, std::abs(kinetic) + std::abs(potential)));
    }
}

TEST(Kinematics, EnergyEqualsHalfQdotMQdotPlusPotential)
{
    checkEnergy(compileText(test::kZooModel), 31);
    checkEnergy(compileText(test::kCylinderArmModel), 32);
    for (const char* name : {"pendulum.pad", "double_pendulum.pad", "incline_slider.pad",
                             "liner_manipulator.pad"}) {
        SCOPED_TRACE(name);
        checkEnergy(compileFile(test::modelPath(name)), 33);
    }
}

TEST(Kinematics, DoublePendulumEnergyAtItsInitialState)
{
    // models/double_pendulum.pad: E = m g L [2(1 − cos θ1) + (1 − cos θ2)] = 0.0490347 J above
    // the hanging rest state, whose potential is −m g L (1 + 2) = −3·9.81 J
    const auto model = test::compileExample("double_pendulum.pad");
    ASSERT_TRUE(model);
    Data d(*model);
    forwardKinematics(*model, makeState(*model), d);
    EXPECT_NEAR(mechanicalEnergy(*model, d) + 3 * 9.81, 0.0490347, 1e-7);
}

// ------------------------------------------------------------------ T 1 coordinates kept per evaluation

TEST(Kinematics, AKeptT1CoordinateIsNeverAnotherModelsLengthLaw)
{
    // Data::coordinates keeps a T 1 joint's sine, cosine and length-law values for the
    // angle last asked for (the kinematics, the circuits and the dynamics share them):
    // the same angle asked with a model whose cylinder is mounted 1 mm elsewhere (another
    // length law) is answered from that model's law, not from what was kept
    const auto a = test::compileText(test::kCylinderArmModel);
    std::string movedText = test::kCylinderArmModel;
    const std::string mount = "CL1 -0.4 0 0 CL2 -0.2 0 0.14\n";
    ASSERT_NE(movedText.find(mount), std::string::npos);
    movedText.replace(movedText.find(mount), mount.size(), "CL1 -0.4 0 0 CL2 -0.2 0 0.141\n");
    const auto b = test::compileText(movedText);
    ASSERT_TRUE(a && b);
    const int j = a->jointIndex(2);
    ASSERT_EQ(a->jointType[j], JointType::Actuator);
    const double theta = 0.1;
    ASSERT_NE(a->coordinateMap(j, theta).q, b->coordinateMap(j, theta).q);

    Data data(*a);
    for (const Model* m : {a.get(), b.get(), a.get()}) {
        const CoordinateMap kept = coordinateMapAt(*m, data, j, theta);
        const CoordinateMap fresh = m->coordinateMap(j, theta);
        EXPECT_EQ(kept.q, fresh.q);
        EXPECT_EQ(kept.dq, fresh.dq);
        EXPECT_EQ(kept.ddq, fresh.ddq);
    }
}

}  // namespace
}  // namespace solver
