// Inverse kinematics: round trips FK → IK → FK on random poses of the liner station's
// arm, limits (T 1 lengths included), a subset of joints, position-only targets, and
// unreachable targets reporting the nearest residual.
#include "solver/kinematics/inverse.h"

#include "solver/kinematics/kinematics.h"
#include "tests/solver/dynamics/random_states.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace solver {
namespace {

using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;

constexpr double pi = std::numbers::pi;

/// Angle between two rotations [rad].
double angleBetween(const Matrix3d& a, const Matrix3d& b)
{
    return std::abs(Eigen::AngleAxisd(Matrix3d(a * b.transpose())).angle());
}

Isometry3d poseAt(const Model& model, const IkFrame& frame, const VectorXd& theta, Data& data)
{
    forwardKinematics(model, theta, VectorXd::Zero(model.nb), data);
    return framePose(data, frame);
}

/// The liner station's arm, the frame at the liner's centre of mass as gripped at the
/// manipulator's initial pose (liner_station.pad's header: 0.765 m ahead of the head).
struct Station {
    std::shared_ptr<const Model> model = test::compileExample("liner_station.pad");
    IkFrame frame;
    std::vector<int> arm;  // tree indices of joints 1–6
    Station()
    {
        if (!model) return;
        frame.body = model->bodyIndex(6);
        frame.X_bf.translation() = Vector3d(0, 0.765, 0.0658);
        for (int id = 1; id <= 6; ++id) arm.push_back(model->jointIndex(id));
    }
    /// Random θ of joints 1–6 inside IK's ranges, slew and roll within ±π.
    VectorXd random(std::mt19937& rng) const
    {
        VectorXd theta = makeState(*model).q;
        for (int i : arm) {
            double lo = 0, hi = 0;
            ikJointRange(*model, i, true, lo, hi);
            if (!std::isfinite(lo)) lo = -pi;
            if (!std::isfinite(hi)) hi = pi;
            theta[i] = test::uniform(rng, lo, hi);
        }
        return theta;
    }
};

TEST(InverseKinematics, RoundTripsOnRandomPosesOfTheLinerStation)
{
    Station st;
    ASSERT_TRUE(st.model);
    const Model& model = *st.model;
    Data data(model);
    std::mt19937 rng(7);
    const VectorXd qi = makeState(model).q;
    IkOptions opt;
    opt.joints = st.arm;
    int attempts = 0;
    for (int n = 0; n < 40; ++n) {
        const VectorXd truth = st.random(rng);
        const Isometry3d X = poseAt(model, st.frame, truth, data);
        IkTarget target;
        target.position = X.translation();
        target.orientation = X.linear();
        // from the initial pose: far from the answer, often on another branch
        const IkResult r = inverseKinematics(model, st.frame, target, qi, data, opt);
        attempts += r.attempts;
        ASSERT_TRUE(r.converged) << "pose " << n << ": " << r.positionError << " m, " << r.angleError << " rad";
        const Isometry3d Y = poseAt(model, st.frame, r.theta, data);
        EXPECT_LT((Y.translation() - X.translation()).norm(), 1e-6) << n;
        EXPECT_LT(angleBetween(Y.linear(), X.linear()), 1e-6) << n;
        EXPECT_LE(r.positionError, 1e-9);
        EXPECT_LE(r.angleError, 1e-9);
        // joints 7–15 held where they were
        for (int i = 0; i < model.nb; ++i) {
            if (std::find(st.arm.begin(), st.arm.end(), i) == st.arm.end()) {
                EXPECT_EQ(r.theta[i], qi[i]);
            }
        }
        // the modeler's coordinates are the same pose's: T 1 lengths within LL … UL
        for (int i : st.arm) {
            EXPECT_DOUBLE_EQ(r.coordinates[i], model.coordinate(i, r.theta[i]));
        }
    }
    // most poses are found from the first start, some need a restart
    EXPECT_LT(attempts, 40 * 3);
}

TEST(InverseKinematics, StartingNearTheAnswerStaysOnItsBranch)
{
    Station st;
    ASSERT_TRUE(st.model);
    const Model& model = *st.model;
    Data data(model);
    std::mt19937 rng(11);
    IkOptions opt;
    opt.joints = st.arm;
    opt.restarts = 0;
    for (int n = 0; n < 20; ++n) {
        const VectorXd truth = st.random(rng);
        VectorXd start = truth;
        for (int i : st.arm) start[i] += test::uniform(rng, -0.02, 0.02);
        const Isometry3d X = poseAt(model, st.frame, truth, data);
        IkTarget target;
        target.position = X.translation();
        target.orientation = X.linear();
        const IkResult r = inverseKinematics(model, st.frame, target, start, data, opt);
        ASSERT_TRUE(r.converged) << n;
        EXPECT_EQ(r.attempts, 1);
        for (int i : st.arm) EXPECT_NEAR(r.theta[i], truth[i], 1e-6) << "pose " << n << " joint " << i;
    }
}

TEST(InverseKinematics, LimitsHoldInTheModelersCoordinates)
{
    // position-only targets ahead and high: the boom and wrist cylinders run to their
    // strokes' ends; every answer is within LL … UL, lengths included
    Station st;
    ASSERT_TRUE(st.model);
    const Model& model = *st.model;
    Data data(model);
    const VectorXd qi = makeState(model).q;
    IkOptions opt;
    opt.joints = st.arm;
    std::mt19937 rng(3);
    int atALimit = 0;
    for (int n = 0; n < 30; ++n) {
        IkTarget target;
        target.position = Vector3d(test::uniform(rng, -5, 5), test::uniform(rng, -5, 5), test::uniform(rng, -3, 6));
        const IkResult r = inverseKinematics(model, st.frame, target, qi, data, opt);
        for (int i : st.arm) {
            EXPECT_GE(r.theta[i], model.lower[i] - 1e-12) << i;
            EXPECT_LE(r.theta[i], model.upper[i] + 1e-12) << i;
        }
        // the lengths of the cylinders C 2 (1.4 … 1.617 m) and C 5 (0.044 … 0.413 m)
        const double boom = r.coordinates[model.jointIndex(2)];
        const double wrist = r.coordinates[model.jointIndex(5)];
        EXPECT_GE(boom, 1.4 - 1e-9);
        EXPECT_LE(boom, 1.617 + 1e-9);
        EXPECT_GE(wrist, 0.044 - 1e-9);
        EXPECT_LE(wrist, 0.413 + 1e-9);
        const double ext = r.coordinates[model.jointIndex(3)];
        EXPECT_GE(ext, 0.0);
        EXPECT_LE(ext, 0.9);
        if (!r.converged) {
            ++atALimit;
            // a target out of reach: some moving joint rests on a limit
            bool onLimit = false;
            for (int i : st.arm)
                onLimit = onLimit || std::abs(r.theta[i] - model.lower[i]) < 1e-9 ||
                          std::abs(r.theta[i] - model.upper[i]) < 1e-9;
            EXPECT_TRUE(onLimit) << n;
        }
    }
    EXPECT_GT(atALimit, 0);  // the box holds targets out of reach
    EXPECT_LT(atALimit, 30);
}

TEST(InverseKinematics, UnreachableTargetReportsTheNearestResidual)
{
    // a 1 m pendulum (bob on a rod from the origin, turning about x): a target 3 m from
    // the pivot in the y-z plane is out of reach; the nearest the bob gets is 2 m
    const auto model = test::compileExample("pendulum.pad");
    ASSERT_TRUE(model);
    Data data(*model);
    IkFrame bob{0, Isometry3d::Identity()};
    IkTarget target;
    target.position = Vector3d(0, 3 * std::sin(0.4), -3 * std::cos(0.4));
    const IkResult r = inverseKinematics(*model, bob, target, VectorXd::Zero(1), data);
    EXPECT_FALSE(r.converged);
    EXPECT_NEAR(r.positionError, 2.0, 1e-9);
    EXPECT_NEAR(r.theta[0], 0.4, 1e-6);
    // off the plane by 0.5 m as well: √(2² + 0.5²)
    target.position.x() = 0.5;
    const IkResult off = inverseKinematics(*model, bob, target, VectorXd::Zero(1), data);
    EXPECT_FALSE(off.converged);
    EXPECT_NEAR(off.positionError, std::hypot(2.0, 0.5), 1e-9);
}

TEST(InverseKinematics, UnreachableTargetOfTheArmIsNoWorseThanAnySampledPose)
{
    // the liner's centre 9 m ahead of the slew axis: nowhere near; the answer is the
    // arm stretched towards it, no farther than the nearest of 20,000 random poses
    Station st;
    ASSERT_TRUE(st.model);
    const Model& model = *st.model;
    Data data(model);
    IkOptions opt;
    opt.joints = st.arm;
    IkTarget target;
    target.position = Vector3d(0, 9, 1.0);
    target.orientation = Matrix3d::Identity();
    target.orientationWeight = 0.1;  // mostly where it is, not how it is turned
    const IkResult r = inverseKinematics(model, st.frame, target, makeState(model).q, data, opt);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.attempts, 1 + opt.restarts);
    const double cost = [&](double p, double a) { return p * p + 0.01 * a * a; }(r.positionError, r.angleError);
    std::mt19937 rng(5);
    double nearest = 1e300;
    for (int n = 0; n < 20000; ++n) {
        const Isometry3d X = poseAt(model, st.frame, st.random(rng), data);
        const double p = (X.translation() - target.position).norm();
        const double a = angleBetween(X.linear(), *target.orientation);
        nearest = std::min(nearest, p * p + 0.01 * a * a);
    }
    EXPECT_LE(cost, nearest + 1e-9);
    // telescope fully out: the reach is spent
    EXPECT_NEAR(r.coordinates[model.jointIndex(3)], 0.9, 1e-9);
    // the residual reported is the one at the returned θ
    const Isometry3d X = poseAt(model, st.frame, r.theta, data);
    EXPECT_NEAR((X.translation() - target.position).norm(), r.positionError, 1e-12);
    EXPECT_NEAR(angleBetween(X.linear(), *target.orientation), r.angleError, 1e-12);
}

TEST(InverseKinematics, HeldJointsStayAndTheRestReachesPositionOnly)
{
    // only the telescope (C 3) and the boom (C 2) move: a point straight ahead of the
    // head at another reach and height is found with the slew and the wrist held
    Station st;
    ASSERT_TRUE(st.model);
    const Model& model = *st.model;
    Data data(model);
    VectorXd truth = makeState(model).q;
    truth[model.jointIndex(1)] = 0.3;
    const int boom = model.jointIndex(2), tele = model.jointIndex(3);
    VectorXd moved = truth;
    moved[boom] += 0.05;
    moved[tele] = 0.6;
    const Vector3d p = poseAt(model, st.frame, moved, data).translation();
    IkOptions opt;
    opt.joints = {boom, tele};
    IkTarget target;
    target.position = p;
    const IkResult r = inverseKinematics(model, st.frame, target, truth, data, opt);
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.theta[boom], moved[boom], 1e-7);
    EXPECT_NEAR(r.theta[tele], 0.6, 1e-7);
    for (int i = 0; i < model.nb; ++i) {
        if (i != boom && i != tele) {
            EXPECT_EQ(r.theta[i], truth[i]);
        }
    }
    EXPECT_EQ(r.angleError, 0.0);
}

TEST(InverseKinematics, OrientationOnlyLeavesThePositionFree)
{
    // the wrist pitch alone (C 5) levels the head at another boom angle: a target with
    // position weight 0 asks for the attitude only, and converges on it
    Station st;
    ASSERT_TRUE(st.model);
    const Model& model = *st.model;
    Data data(model);
    VectorXd start = makeState(model).q;
    start[model.jointIndex(2)] += 0.1;  // boom up
    IkOptions opt;
    opt.joints = {model.jointIndex(5)};
    IkTarget target;
    target.positionWeight = 0;
    target.orientation = poseAt(model, st.frame, makeState(model).q, data).linear();
    const IkResult r = inverseKinematics(model, st.frame, target, start, data, opt);
    EXPECT_TRUE(r.converged);
    EXPECT_LT(r.angleError, 1e-9);
    EXPECT_GT(r.positionError, 0.1);  // the position was not asked for
    // the wrist took up the boom's turn: the two angles sum to what they were
    const VectorXd qi = makeState(model).q;
    EXPECT_NEAR(r.theta[model.jointIndex(5)] - qi[model.jointIndex(5)],
                -(start[model.jointIndex(2)] - qi[model.jointIndex(2)]), 1e-9);
}

TEST(InverseKinematics, UnlimitedCylinderStaysOnItsBranch)
{
    // kCylinderArmModel's stick cylinder (C 3) has no limits: its angle stays between
    // the dead points of the branch that holds its initial angle, so its length still
    // names one angle
    const auto model = test::compileText(test::kCylinderArmModel);
    ASSERT_TRUE(model);
    Data data(*model);
    const int stick = model->jointIndex(3);
    double lo = 0, hi = 0;
    ikJointRange(*model, stick, true, lo, hi);
    ASSERT_TRUE(std::isfinite(lo) && std::isfinite(hi));
    EXPECT_NEAR(hi - lo, pi, 1e-5);
    EXPECT_GT(model->theta0[stick], lo);
    EXPECT_LT(model->theta0[stick], hi);
    const ActuatorLengthLaw& law = model->lengthLaw[stick];
    const double rate0 = law.lengthRate(model->theta0[stick]);
    // a target far out: the stick would straighten past a dead point if it could
    IkFrame tip{model->bodyIndex(4), Isometry3d::Identity()};
    IkTarget target;
    target.position = Vector3d(5, 0, 0);
    const IkResult r = inverseKinematics(*model, tip, target, makeState(*model).q, data);
    EXPECT_FALSE(r.converged);
    EXPECT_GE(r.theta[stick], lo);
    EXPECT_LE(r.theta[stick], hi);
    // dL/dθ keeps its sign: the same monotonic branch
    EXPECT_GT(law.lengthRate(r.theta[stick]) * rate0, 0.0);
}

}  // namespace
}  // namespace solver
