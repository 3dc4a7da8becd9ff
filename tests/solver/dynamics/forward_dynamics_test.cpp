#include "solver/dynamics/forward_dynamics.h"

#include "solver/pipeline.h"
#include "solver/dynamics/applied_forces.h"
#include "solver/dynamics/constraints.h"
#include "solver/dynamics/drives.h"
#include "solver/dynamics/mass_matrix.h"
#include "solver/kinematics/kinematics.h"
#include "solver/parse/writer.h"
#include "tests/solver/dynamics/random_states.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <random>

namespace solver {
namespace {

using Eigen::Vector3d;
constexpr double kG = 9.81;

// ------------------------------------------------------------------ analytic cases

TEST(ForwardDynamics, SimplePendulum)
{
    // models/pendulum.pad: 1 kg bob on a 1 m massless rod, bob inertia 1e-6 kg m²:
    // θ̈ = −m g L sin θ / (m L² + I) = −(g/L) sin θ / (1 + 1e-6), whatever θ̇
    const auto model = test::compileExample("pendulum.pad");
    ASSERT_TRUE(model);
    Data d(*model);
    clearAppliedForces(d);
    State s = makeState(*model);
    for (double th : {0.1, -0.7, 1.5, 3.0}) {
        for (double thd : {0.0, 2.0}) {
            s.q[0] = th;
            s.qd[0] = thd;
            forwardDynamics(*model, s, d);
            EXPECT_NEAR(d.qdd[0], -kG * std::sin(th) / (1 + 1e-6), 1e-12);
            // the rod pulls the bob towards the pivot (−R2, R2 runs from the pivot to the bob)
            // with m g cos θ + m L θ̇²; no moment about the axis (a passive joint)
            EXPECT_NEAR(d.reactionJoint[0][4], -(kG * std::cos(th) + thd * thd), 1e-12);
            EXPECT_NEAR(d.reactionJoint[0][5], kG * std::sin(th) * (1 - 1 / (1 + 1e-6)), 1e-12);
            EXPECT_NEAR(d.reactionJoint[0][0], 0.0, 1e-12);
            EXPECT_NEAR(d.tau[0], 0.0, 1e-12);
            EXPECT_EQ(d.driveForce[0], 0.0);
        }
    }
    // the figures of the model's comment: θ̈ at QI 0.1 and the rod tension at rest there
    s = makeState(*model);
    forwardDynamics(*model, s, d);
    EXPECT_NEAR(d.qdd[0], -0.9793648, 1e-7);
    EXPECT_NEAR(-d.reactionJoint[0][4], 9.76099, 1e-5);
}

TEST(ForwardDynamics, PendulumWrittenChildToParent)
{
    // the same pendulum with its joint written from the bob to the ground: θ → −θ
    const auto forward = test::compileExample("pendulum.pad");
    const auto reversed = test::compileText(R"(GRAVITY 0 0 -9.81
B 1 1.0 1e-6 1e-6 1e-6
C 1 QI -0.1
B1 1 P1 0 0 1 A1 1 0 0 R1 0 0 -1
B2 0 P2 0 0 0 A2 1 0 0 R2 0 0 -1
D 1 MOTOR T0 3 W0 5
)");
    ASSERT_TRUE(forward && reversed);
    Data a(*forward), b(*reversed);
    clearAppliedForces(a);
    clearAppliedForces(b);
    State sa = makeState(*forward), sb = makeState(*reversed);
    sa.qd[0] = 0.8;
    sb.qd[0] = -0.8;
    sb.u[0] = 0.5;
    forwardDynamics(*forward, sa, a);
    forwardDynamics(*reversed, sb, b);
    // the motor's torque 0.5·3·(1 − 0.8/5) = 1.26 N m turns the bob towards −θ of the forward joint
    const double motor = 0.5 * 3 * (1 - 0.8 / 5);
    EXPECT_NEAR(b.driveForce[0], motor, 1e-15);
    EXPECT_NEAR(-b.qdd[0], a.qdd[0] - motor / (1 + 1e-6), 1e-12);
    EXPECT_NEAR(b.tau[0], motor, 1e-12);
}

TEST(ForwardDynamics, BlockOnAThirtyDegreeIncline)
{
    // models/incline_slider.pad: q̈ = g sin 30° = 4.905 m/s²; the incline pushes the block
    // with N = m g cos 30° = 84.957092 N along its normal (joint axis T2 = −normal), no
    // force along the slope and no moment about the block's centre. (R1 = (0.8660254, 0,
    // −0.5) is 30° to 1e-8: the exact figures use its direction r.)
    const auto model = test::compileExample("incline_slider.pad");
    ASSERT_TRUE(model);
    const Vector3d r = Vector3d(0.8660254, 0, -0.5).normalized();
    const double along = -kG * r.z(), normal = 10 * kG * r.x();
    Data d(*model);
    clearAppliedForces(d);
    State s = makeState(*model);
    for (double q : {0.0, 1.2}) {
        for (double qd : {0.0, 3.0}) {
            s.q[0] = q;
            s.qd[0] = qd;
            forwardDynamics(*model, s, d);
            EXPECT_NEAR(d.qdd[0], along, 1e-12);
            EXPECT_NEAR(d.qdd[0], 4.905, 1e-7);
            EXPECT_NEAR(d.reactionJoint[0][5], -normal, 1e-12);
            EXPECT_NEAR(d.reactionJoint[0][5], -84.957092, 1e-6);
            EXPECT_NEAR(d.reactionJoint[0][3], 0.0, 1e-12);
            EXPECT_NEAR(d.reactionJoint[0][4], 0.0, 1e-12);
            EXPECT_LT(d.reactionJoint[0].head<3>().norm(), 1e-12);
            EXPECT_TRUE(comAcceleration(*model, d, 0).isApprox(along * r, 1e-12));
        }
    }

    // on the end stop (UL 2.0): held, the stop pushes back up the slope with m g sin 30°
    s.q[0] = 2.0;
    s.qd[0] = 0.0;
    s.limit[0] = LimitState::AtUpper;
    forwardDynamics(*model, s, d);
    EXPECT_EQ(d.qdd[0], 0.0);
    EXPECT_NEAR(d.limitForce[0], -10 * along, 1e-12);
    EXPECT_NEAR(d.limitForce[0], -49.05, 1e-6);
    EXPECT_NEAR(d.tau[0], -10 * along, 1e-12);
    EXPECT_EQ(d.driveForce[0], 0.0);
}

TEST(ForwardDynamics, HydraulicBlockHeldAndRelieved)
{
    // the incline with a cylinder along the slope: VMAX 0.1 m/s, relief 20 N extending, 10 N retracting
    const auto model = test::compileText(R"(GRAVITY 0 0 -9.81
B 1 10.0 0.0416667 0.0416667 0.0666667
C 1 T 2 UL 2.0
B1 0 P1 0 0 0 A1 0 1 0 R1 0.8660254 0 -0.5
B2 1 P2 0 0 0 A2 0 1 0 R2 1 0 0
D 1 HYD VMAX 0.1 FMAX 20 FMIN 10
)");
    ASSERT_TRUE(model);
    const double weight = 10 * kG * Vector3d(0.8660254, 0, -0.5).normalized().z();  // −49.05 N along R
    Data d(*model);
    clearAppliedForces(d);
    State s = makeState(*model);

    // valve open at u = 0.5: the block moves down at 0.05 m/s, held back by the cylinder
    s.u[0] = 0.5;
    s.qd[0] = prescribedRate(*model, s, 0);
    EXPECT_DOUBLE_EQ(s.qd[0], 0.05);
    forwardDynamics(*model, s, d);
    EXPECT_EQ(d.qdd[0], 0.0);
    EXPECT_NEAR(d.driveForce[0], weight, 1e-12);  // pulls up the slope: beyond FMIN
    EXPECT_EQ(d.limitForce[0], 0.0);

    // relief open retracting: the cylinder pulls with 10 N, the block accelerates down
    s.relief[0] = ReliefState::OpenRetracting;
    forwardDynamics(*model, s, d);
    EXPECT_NEAR(d.qdd[0], -weight / 10 - 1.0, 1e-12);
    EXPECT_EQ(d.driveForce[0], -10.0);
    s.relief[0] = ReliefState::OpenExtending;
    forwardDynamics(*model, s, d);
    EXPECT_NEAR(d.qdd[0], -weight / 10 + 2.0, 1e-12);
    EXPECT_EQ(d.driveForce[0], 20.0);

    // a hydraulic joint on its stop: the cylinder carries the load, not the stop
    s.relief[0] = ReliefState::Closed;
    s.q[0] = 2.0;
    s.qd[0] = 0.0;
    s.limit[0] = LimitState::AtUpper;
    d.tauExt[0] = 5.0;  // a joint force helps the cylinder
    forwardDynamics(*model, s, d);
    EXPECT_EQ(d.qdd[0], 0.0);
    EXPECT_NEAR(d.driveForce[0], weight - 5.0, 1e-12);
    EXPECT_NEAR(d.tau[0], weight, 1e-12);
    EXPECT_EQ(d.limitForce[0], 0.0);
}

TEST(ForwardDynamics, ANonFiniteLoopGivesNonFiniteAccelerationsNotACrash)
{
    // a factorisation of non-finite numbers is undefined: Eigen's SVD of the constraint
    // rows crashed on them (a piston with Ixx = 1.8e308 in the slider-crank)
    const auto model = test::compileExample("slider_crank.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Data d(m);
    clearAppliedForces(d);
    State s = makeState(m);
    s.q[0] = std::numeric_limits<double>::quiet_NaN();
    forwardDynamics(m, s, d);
    EXPECT_FALSE(d.qdd.allFinite());

    // the projection onto the constraints: no correction from a non-finite mass matrix
    const auto n = static_cast<Eigen::Index>(m.nb);
    Eigen::MatrixXd M = Eigen::MatrixXd::Identity(n, n);
    M(0, 0) = std::numeric_limits<double>::infinity();
    std::vector<int> free(static_cast<std::size_t>(m.nb));
    for (int i = 0; i < m.nb; ++i) free[static_cast<std::size_t>(i)] = i;
    const Eigen::MatrixXd G = Eigen::MatrixXd::Ones(2, n);
    EXPECT_TRUE(constraintCorrection(M, free, G, Eigen::VectorXd::Ones(2)).isZero());
}

TEST(ForwardDynamics, LinerManipulatorHoldsStillWithEveryValveClosed)
{
    const auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    Data d(m);
    clearAppliedForces(d);
    const State s = makeState(m);  // QI, u = 0
    forwardDynamics(m, s, d);
    for (int i = 0; i < m.nb; ++i) EXPECT_EQ(d.qdd[i], 0.0) << "joint " << m.jointId[i];

    // The hand calculation. Boom lift (joint 2): L² = 2.1425 + 0.58 sin θ2 (CL1 = (0.03, 0, −0.2)
    // on the turret at the pivot, CL2 = (0.03, 1.45, 0) from the pivot along the boom), so at
    // QI = 1.464 m sin θ2 = (1.464² − 2.1425)/0.58 (θ2 = +0.0786°) and the lever arm is
    // dL/dθ = 0.58 cos θ2 / (2 L) = 0.198087 m.
    const double L2 = 1.464;
    const double s2 = (L2 * L2 - 2.1425) / 0.58, c2 = std::sqrt(1 - s2 * s2);
    const double arm = 0.58 * c2 / (2 * L2);
    EXPECT_NEAR(arm, 0.198087, 1e-6);
    // Wrist pitch (joint 5): L² = 0.11 + 0.06 cos θ5 + 0.09 sin θ5 (CL1 = (0, −0.15, −0.15) from
    // the pitch pin on the yoke, CL2 = (0, 0.25, −0.05) from it on the rocker); at QI = 0.412 m,
    // on the branch nearest 0: θ5 = φ − acos((L² − 0.11)/ρ), φ = atan2(0.09, 0.06),
    // ρ = √(0.06² + 0.09²): θ5 = −0.16°.
    const double L5 = 0.412;
    const double th5 = std::atan2(0.09, 0.06) - std::acos((L5 * L5 - 0.11) / std::hypot(0.06, 0.09));
    EXPECT_NEAR(th5 * 180 / std::numbers::pi, -0.163, 1e-3);
    const double s5 = std::sin(th5), c5 = std::cos(th5);
    // Centres of mass in the boom's plane, from the boom pivot: (along the boom, up), boom level.
    // Boom 0.8 from the pivot; telescope 0.8 + 0.8 + 0.6 (retracted); yaw yoke 0.225 further;
    // the pitch pin 0.3 below the yoke; rocker 0.25 from the pin; head (0.25 + 0.25, 0.3) from
    // the pin; piston 0.05 + 0.075 + 0.1 ahead of the head; claws (0.15, ±0.35) from the head;
    // every offset past the pin turned by θ5.
    auto turn5 = [&](double y, double z) { return Eigen::Vector2d(y * c5 - z * s5, y * s5 + z * c5); };
    const Eigen::Vector2d yoke(2.425, 0), pin(2.425, -0.3);
    const Eigen::Vector2d head = pin + turn5(0.5, 0.3);
    const std::vector<std::pair<double, Eigen::Vector2d>> bodies{
        {306, {0.8, 0}},          {594, {2.2, 0}},
        {200, yoke},              {100, pin + turn5(0.25, 0)},
        {100, head},              {10, head + turn5(0.225, 0)},
        {2, head + turn5(0.15, 0.35)}, {2, head + turn5(0.15, -0.35)}};
    // moment of the weights about the pivot, with the boom raised by θ2: y_world = y c2 − z s2
    double weightMoment = 0, mass = 0;
    for (const auto& [mk, p] : bodies) {
        weightMoment += mk * kG * (p.x() * c2 - p.y() * s2);
        mass += mk;
    }
    EXPECT_DOUBLE_EQ(mass, 1314.0);
    EXPECT_NEAR(weightMoment, 25903.7, 0.1);  // 26 kN·m
    const double cylinder = weightMoment / arm;  // ≈ 131 kN pushing
    EXPECT_NEAR(d.driveForce[m.jointIndex(2)], cylinder, 1e-9 * cylinder);
    EXPECT_NEAR(d.tau[m.jointIndex(2)], weightMoment, 1e-9 * weightMoment);
    EXPECT_NEAR(cylinder, 130769, 1);  // 131 kN, well inside FMAX 1.54 MN

    // telescope (joint 3): the weight of bodies 3–9 along the boom, raised by θ2
    const double telescope = (1314.0 - 306.0) * kG * s2;
    EXPECT_NEAR(d.driveForce[m.jointIndex(3)], telescope, 1e-9 * cylinder);
    // slew (joint 1) about the vertical: gravity asks nothing of it
    EXPECT_NEAR(d.driveForce[m.jointIndex(1)], 0.0, 1e-9 * weightMoment);

    // the ground carries the whole arm: 1314·9.81 = 12890.34 N straight up
    const Vector6d& r1 = d.reactionWorld[m.jointIndex(1)];
    EXPECT_NEAR(r1[5], 1314 * kG, 1e-9 * 1314 * kG);
    EXPECT_NEAR(r1[3], 0.0, 1e-9 * 1314 * kG);
    EXPECT_NEAR(r1[4], 0.0, 1e-9 * 1314 * kG);
    EXPECT_NEAR(r1[5], 12890.34, 1e-8);
    // the cylinders carry the joints resting on their stops (telescope, piston, claws)
    for (int i = 0; i < m.nb; ++i) EXPECT_EQ(d.limitForce[i], 0.0) << i;
}

TEST(ForwardDynamics, KnownForcesAndPrescribedAccelerationsAreHonoured)
{
    const auto base = test::compileText(test::kZooModel);
    ASSERT_TRUE(base);
    std::mt19937 rng(41);
    for (int trial = 0; trial < 30; ++trial) {
        const Model m = test::withRandomDrives(*base, rng);
        const State s = test::randomState(m, rng);
        Data d(m);
        test::randomAppliedForces(rng, d);
        forwardDynamics(m, s, d);
        for (int i = 0; i < m.nb; ++i) {
            const double dq = m.coordinateRate(i, s.q[i]);
            if (isPrescribed(m, s, i)) {
                EXPECT_EQ(d.qdd[i], prescribedAcceleration(m, s, i));
            } else {
                // what the joint transmits is its drive's force plus the joint force
                const double known = driveForceLaw(m, s, i) * dq + d.tauExt[i];
                EXPECT_NEAR(d.tau[i], known, 1e-9 * std::max(1.0, std::abs(known)));
                EXPECT_EQ(d.limitForce[i], 0.0);
            }
            // S_iᵀ of the reaction: the moment about the axis, or the force along the slide
            const Vector6d& r = d.reactionJoint[i];
            const double alongAxis = m.jointType[i] == JointType::Prismatic ? r[4] : r[0];
            EXPECT_NEAR(m.axisSign[i] * alongAxis, d.tau[i], 1e-9 * std::max(1.0, r.cwiseAbs().maxCoeff()));
            // the joint frame turns the world reaction
            const Eigen::Matrix3d R = d.X_wj[i].linear();
            EXPECT_TRUE((R * r.tail<3>()).isApprox(d.reactionWorld[i].tail<3>(), 1e-12));
        }
    }
}

TEST(ForwardDynamics, AStageEvaluationGivesTheSameAccelerations)
{
    // DynamicsOutputs::Accelerations (an integrator's stage) and the kinematic shortcut
    // with every joint prescribed give θ̈ bit for bit as the whole evaluation does
    const auto base = test::compileText(test::kZooModel);
    ASSERT_TRUE(base);
    std::mt19937 rng(43);
    int shortcuts = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const Model m = test::withRandomDrives(*base, rng);
        State s = test::randomState(m, rng);
        if (trial % 4 == 0) {
            for (LimitState& l : s.limit) l = LimitState::AtUpper;  // every joint held
        }
        Data whole(m), stage(m);
        forwardDynamics(m, s, whole);
        if (kinematicAccelerations(m, s, stage)) {
            ++shortcuts;
        } else {
            forwardKinematics(m, s, stage);
            clearAppliedForces(stage);
            hybridDynamics(m, s, stage, DynamicsOutputs::Accelerations);
        }
        for (int i = 0; i < m.nb; ++i) EXPECT_EQ(stage.qdd[i], whole.qdd[i]) << "trial " << trial << " joint " << i;
    }
    EXPECT_EQ(shortcuts, 10);
}

TEST(ForwardDynamics, ImpulseResponseSolvesTheMassMatrix)
{
    // the O(n) impulse response against M_FF Δθ̇_F = ι_F − M_FP Δθ̇_P solved densely
    const auto base = test::compileText(test::kZooModel);
    ASSERT_TRUE(base);
    std::mt19937 rng(47);
    for (int trial = 0; trial < 30; ++trial) {
        const Model m = test::withRandomDrives(*base, rng);
        const State s = test::randomState(m, rng);
        Data d(m);
        forwardKinematics(m, s, d);
        Eigen::MatrixXd M;
        massMatrix(m, d, M);
        const int alsoFree = trial % 3 == 0 ? trial % m.nb : -1;
        Eigen::VectorXd jump(m.nb), impulse(m.nb), dqd(m.nb);
        std::vector<int> F, P;
        for (int i = 0; i < m.nb; ++i) {
            jump[i] = test::uniform(rng, -1, 1);
            impulse[i] = test::uniform(rng, -10, 10);
            (i != alsoFree && isPrescribed(m, s, i) ? P : F).push_back(i);
        }
        impulseResponse(m, s, d, jump, impulse, dqd, alsoFree);
        const auto nF = static_cast<Eigen::Index>(F.size());
        Eigen::MatrixXd MFF(nF, nF);
        Eigen::VectorXd rhs(nF);
        for (Eigen::Index a = 0; a < nF; ++a) {
            rhs[a] = impulse[F[a]];
            for (int p : P) rhs[a] -= M(F[a], p) * jump[p];
            for (Eigen::Index b = 0; b < nF; ++b) MFF(a, b) = M(F[a], F[b]);
        }
        const Eigen::VectorXd expected = MFF.ldlt().solve(rhs);
        for (Eigen::Index a = 0; a < nF; ++a)
            EXPECT_NEAR(dqd[F[a]], expected[a], 1e-9 * std::max(1.0, expected.cwiseAbs().maxCoeff()))
                << "trial " << trial << " free joint " << F[a];
        for (int p : P) EXPECT_EQ(dqd[p], jump[p]);
    }
}

// ------------------------------------------------------------------ body id order independence

struct Renumbered {
    std::string text;
    std::map<int, int> body, joint;  // old id → new id
};

// the same machine with new ids and the statements shuffled, as model text
Renumbered renumber(const ModelSpec& spec, std::mt19937& rng)
{
    Renumbered out;
    ModelSpec s = spec;
    s.graphics.clear();
    std::vector<int> bodyIds, jointIds;
    for (int k = 0; k < static_cast<int>(s.bodies.size()); ++k) bodyIds.push_back(40 + 3 * k);
    for (int k = 0; k < static_cast<int>(s.joints.size()); ++k) jointIds.push_back(70 + 7 * k);
    std::shuffle(bodyIds.begin(), bodyIds.end(), rng);
    std::shuffle(jointIds.begin(), jointIds.end(), rng);
    out.body[0] = 0;
    for (std::size_t k = 0; k < s.bodies.size(); ++k) {
        if (s.bodies[k].id == 0) continue;
        out.body[s.bodies[k].id] = bodyIds[k];
        s.bodies[k].id = bodyIds[k];
    }
    for (std::size_t k = 0; k < s.joints.size(); ++k) {
        out.joint[s.joints[k].id] = jointIds[k];
        s.joints[k].id = jointIds[k];
        s.joints[k].side1.body = out.body.at(s.joints[k].side1.body);
        s.joints[k].side2.body = out.body.at(s.joints[k].side2.body);
    }
    for (DriveSpec& d : s.drives) d.joint = out.joint.at(d.joint);
    std::shuffle(s.bodies.begin(), s.bodies.end(), rng);
    std::shuffle(s.joints.begin(), s.joints.end(), rng);
    std::shuffle(s.drives.begin(), s.drives.end(), rng);
    out.text = parse::writeModel(s);
    return out;
}

void expectOrderIndependent(const CompiledModel& loaded, unsigned seed)
{
    const auto a = test::modelOrFail(loaded);
    ASSERT_TRUE(a);
    std::mt19937 rng(seed);
    for (int version = 0; version < 3; ++version) {
        const Renumbered r = renumber(loaded.spec, rng);
        const auto b = test::compileText(r.text);
        ASSERT_TRUE(b) << r.text;
        ASSERT_EQ(a->nb, b->nb);

        // joint i of a is joint ji[i] of b, body i of a is body bi[i] of b
        const int nb = a->nb;
        std::vector<int> ji(nb), bi(nb);
        for (int i = 0; i < nb; ++i) {
            ji[i] = b->jointIndex(r.joint.at(a->jointId[i]));
            bi[i] = b->bodyIndex(r.body.at(a->bodyId[i]));
            ASSERT_GE(ji[i], 0);
            ASSERT_GE(bi[i], 0);
        }
        Data da(*a), db(*b);
        for (int trial = 0; trial < 10; ++trial) {
            const State sa = test::randomState(*a, rng);
            test::randomAppliedForces(rng, da);
            State sb = makeState(*b);
            for (int i = 0; i < nb; ++i) {
                sb.q[ji[i]] = sa.q[i];
                sb.qd[ji[i]] = sa.qd[i];
                sb.u[ji[i]] = sa.u[i];
                sb.servoIntegral[ji[i]] = sa.servoIntegral[i];
                sb.limit[ji[i]] = sa.limit[i];
                sb.relief[ji[i]] = sa.relief[i];
                db.tauExt[ji[i]] = da.tauExt[i];
                db.fext[bi[i]] = da.fext[i];
            }
            forwardDynamics(*a, sa, da);
            forwardDynamics(*b, sb, db);
            for (int i = 0; i < nb; ++i) {
                SCOPED_TRACE("joint " + std::to_string(a->jointId[i]));
                const double scale = std::max(1.0, da.reactionWorld[i].cwiseAbs().maxCoeff());
                EXPECT_NEAR(db.qdd[ji[i]], da.qdd[i], 1e-12 * std::max(1.0, std::abs(da.qdd[i])));
                EXPECT_NEAR(db.tau[ji[i]], da.tau[i], 1e-12 * scale);
                EXPECT_NEAR(db.driveForce[ji[i]], da.driveForce[i],
                            1e-12 * std::max(scale, std::abs(da.driveForce[i])));
                EXPECT_NEAR(db.limitForce[ji[i]], da.limitForce[i], 1e-12 * scale);
                EXPECT_LT((db.reactionWorld[ji[i]] - da.reactionWorld[i]).cwiseAbs().maxCoeff(), 1e-12 * scale);
                EXPECT_LT((db.reactionJoint[ji[i]] - da.reactionJoint[i]).cwiseAbs().maxCoeff(), 1e-12 * scale);
                EXPECT_TRUE(db.X_wb[bi[i]].isApprox(da.X_wb[i], 1e-14));
                // (sums taken in another order: a few units in the last place of the terms)
                EXPECT_LT((db.acc[bi[i]] - da.acc[i]).norm(), 1e-10 * std::max(1.0, da.acc[i].norm()));
            }
        }
    }
}

TEST(ForwardDynamics, OutputDoesNotDependOnIdsOrStatementOrder)
{
    expectOrderIndependent(compileFile(test::modelPath("liner_manipulator.pad")), 51);
    expectOrderIndependent(compileText(test::kZooModel), 52);
    expectOrderIndependent(compileText(test::kCylinderArmModel), 53);
}

}  // namespace
}  // namespace solver
