#include "solver/compile/compile.h"

#include "solver/pipeline.h"

#include "solver/core/data.h"
#include "solver/core/state.h"
#include "solver/kinematics/kinematics.h"
#include "tests/solver/spec_oracle.h"
#include "tests/solver/dynamics/random_states.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace solver {
namespace {

using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ------------------------------------------------------------------ numbering and frames

TEST(Compile, PendulumFramesAndBody)
{
    const auto model = test::compileExample("pendulum.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    ASSERT_EQ(m.nb, 1);
    EXPECT_EQ(m.parent[0], -1);
    EXPECT_EQ(m.bodyId[0], 1);
    EXPECT_EQ(m.jointId[0], 1);
    EXPECT_EQ(m.bodyName[0], "bob");
    EXPECT_EQ(m.jointName[0], "pivot");
    EXPECT_EQ(m.jointType[0], JointType::Revolute);
    EXPECT_EQ(m.axisSign[0], 1.0);
    EXPECT_EQ(m.gravity, Vector3d(0, 0, -9.81));

    // joint frame (A, R, T = A × R) = (x, −z, y), at the origin on the ground, 1 m above the bob
    Eigen::Matrix3d axes;
    axes << 1, 0, 0, 0, 0, 1, 0, -1, 0;
    EXPECT_TRUE(m.X_pj[0].linear().isApprox(axes));
    EXPECT_TRUE(m.X_pj[0].translation().isZero());
    EXPECT_TRUE(m.X_cj[0].linear().isApprox(axes));
    EXPECT_TRUE(m.X_cj[0].translation().isApprox(Vector3d(0, 0, 1)));
    EXPECT_TRUE((m.X_cj[0] * m.X_jc[0]).matrix().isIdentity(1e-15));

    EXPECT_EQ(m.mass[0], 1.0);
    EXPECT_TRUE(m.com[0].isZero());
    EXPECT_TRUE(m.inertia[0].isApprox(1e-6 * Eigen::Matrix3d::Identity()));
    EXPECT_EQ(m.lower[0], -kInf);
    EXPECT_EQ(m.upper[0], kInf);
    EXPECT_DOUBLE_EQ(m.theta0[0], 0.1);
    EXPECT_EQ(m.thetaDot0[0], 0.0);
    EXPECT_EQ(m.drive[0].type, DriveType::None);
    EXPECT_TRUE(m.forces.empty());
}

TEST(Compile, LinerManipulatorTreeOrderAndBodies)
{
    const auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    ASSERT_EQ(m.nb, 9);
    // a serial chain up to the head (body 6), which carries the piston and both claws
    EXPECT_EQ(m.bodyId, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
    EXPECT_EQ(m.jointId, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
    EXPECT_EQ(m.parent, (std::vector<int>{-1, 0, 1, 2, 3, 4, 5, 5, 5}));
    for (int i = 0; i < m.nb; ++i) {
        EXPECT_LT(m.parent[i], i);
        EXPECT_EQ(m.axisSign[i], 1.0);
    }
    EXPECT_EQ(m.jointType[1], JointType::Actuator);
    EXPECT_EQ(m.jointType[2], JointType::Prismatic);
    EXPECT_EQ(m.jointName[1], "LEVANTE PLUMA");

    // body 1 is massless; the arm weighs 1314 kg
    EXPECT_EQ(m.mass[0], 0.0);
    EXPECT_TRUE(m.inertia[0].isZero());
    double total = 0;
    for (double mass : m.mass) total += mass;
    EXPECT_DOUBLE_EQ(total, 1314.0);
    EXPECT_TRUE(m.inertia[3].isApprox(Eigen::Vector3d(2.07742, 3.89517, 4.38325).asDiagonal().toDenseMatrix()));
    EXPECT_EQ(m.jointIndex(5), 4);
    EXPECT_EQ(m.bodyIndex(9), 8);
    EXPECT_EQ(m.bodyIndex(0), -1);
    EXPECT_EQ(m.jointIndex(10), -1);
}

TEST(Compile, LinerManipulatorActuatorLawsAndLimits)
{
    const auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;

    // boom lift (joint 2): CL2 at (0.03, 1.45, 0) from the pivot in the boom, CL1 at
    // (0.03, 0, −0.2) on the turret: L² = 1.45² + 0.2² + 2·0.2·1.45 sin θ = 2.1425 + 0.58 sin θ
    const ActuatorLengthLaw& boom = m.lengthLaw[1];
    EXPECT_NEAR(boom.c0, 2.1425, 1e-12);
    EXPECT_NEAR(boom.c1, 0.0, 1e-12);
    EXPECT_NEAR(boom.c2, 0.58, 1e-12);
    EXPECT_NEAR(m.lower[1], std::asin((1.4 * 1.4 - 2.1425) / 0.58), 1e-12);    // −18.3°
    EXPECT_NEAR(m.upper[1], std::asin((1.617 * 1.617 - 2.1425) / 0.58), 1e-12);  // +54.5°
    EXPECT_NEAR(m.lower[1], -0.320093, 1e-6);
    EXPECT_NEAR(m.upper[1], 0.951210, 1e-6);
    EXPECT_NEAR(m.theta0[1], std::asin((1.464 * 1.464 - 2.1425) / 0.58), 1e-12);  // +0.08°
    EXPECT_NEAR(m.coordinate(1, m.theta0[1]), 1.464, 1e-12);
    EXPECT_NEAR(m.coordinateRate(1, m.theta0[1]), 0.29 * std::cos(m.theta0[1]) / 1.464, 1e-12);
    EXPECT_TRUE(m.cl1[1].isApprox(Vector3d(0.03, 0, -0.2)));
    EXPECT_TRUE(m.cl2[1].isApprox(Vector3d(0.03, 0.65, 0)));

    // wrist pitch (joint 5): L² = 0.11 + 0.06 cos θ + 0.09 sin θ, LL 0.044 → −121.2°, UL 0.413 → +0.36°
    const ActuatorLengthLaw& wrist = m.lengthLaw[4];
    EXPECT_NEAR(wrist.c0, 0.11, 1e-12);
    EXPECT_NEAR(wrist.c1, 0.06, 1e-12);
    EXPECT_NEAR(wrist.c2, 0.09, 1e-12);
    EXPECT_NEAR(m.lower[4] * 180 / kPi, -121.2, 0.05);
    EXPECT_NEAR(m.upper[4] * 180 / kPi, 0.36, 0.01);
    EXPECT_NEAR(m.coordinate(4, m.lower[4]), 0.044, 1e-12);
    EXPECT_NEAR(m.coordinate(4, m.upper[4]), 0.413, 1e-12);
    EXPECT_NEAR(m.coordinate(4, m.theta0[4]), 0.412, 1e-12);

    // prismatic and revolute limits as written
    EXPECT_EQ(m.lower[2], 0.0);
    EXPECT_EQ(m.upper[2], 0.9);
    EXPECT_EQ(m.lower[3], -1.1344);
    EXPECT_EQ(m.upper[3], 1.1344);
    EXPECT_EQ(m.lower[0], -kInf);
    EXPECT_EQ(m.upper[5], kInf);
}

TEST(Compile, LinerManipulatorDrives)
{
    const auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    for (int i = 0; i < m.nb; ++i) EXPECT_EQ(m.drive[i].type, DriveType::Hydraulic) << i;

    // D 2 HYD PUMP 45 RPM 1480 BORE 0.280 ROD 0.180 PRESSURE 25e6: 66.6 l/min
    const double flow = 45e-6 * 1480 / 60;
    const double bore = kPi / 4 * 0.28 * 0.28, annulus = bore - kPi / 4 * 0.18 * 0.18;
    EXPECT_DOUBLE_EQ(m.drive[1].vmax, flow / bore);
    EXPECT_DOUBLE_EQ(m.drive[1].vmin, flow / annulus);
    EXPECT_NEAR(m.drive[1].vmax, 0.0180, 1e-4);
    EXPECT_NEAR(m.drive[1].vmin, 0.0307, 1e-4);
    EXPECT_NEAR(m.drive[1].fmax, 1.539e6, 1e3);
    EXPECT_NEAR(m.drive[1].fmin, 0.903e6, 1e3);

    // D 1 HYD VMAX 0.131 FMAX 54000: VMIN = VMAX, FMIN = FMAX
    EXPECT_EQ(m.drive[0].vmax, 0.131);
    EXPECT_EQ(m.drive[0].vmin, 0.131);
    EXPECT_EQ(m.drive[0].fmax, 54000.0);
    EXPECT_EQ(m.drive[0].fmin, 54000.0);
    // D 8 HYD VMAX 0.054 VMIN 0.033 FMAX 77000 FMIN 126000
    EXPECT_EQ(m.drive[7].vmin, 0.033);
    EXPECT_EQ(m.drive[7].fmin, 126000.0);
}

TEST(Compile, MakeStateRestsJointsOnTheirLimits)
{
    const auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const State s = makeState(*model);
    ASSERT_EQ(s.q.size(), 9);
    EXPECT_EQ(s.t, 0.0);
    EXPECT_TRUE(s.u.isZero());
    EXPECT_TRUE(s.qd.isZero());
    EXPECT_TRUE(s.servoIntegral.isZero());
    for (int i = 0; i < 9; ++i) {
        EXPECT_EQ(s.q[i], model->theta0[i]);
        EXPECT_EQ(s.relief[i], ReliefState::Closed);
    }
    // telescope QI 0 = LL, piston QI 0.075 = LL, upper claw QI 0 = UL, lower claw QI 0 = LL
    const std::vector<LimitState> expected{LimitState::Free,    LimitState::Free,    LimitState::AtLower,
                                           LimitState::Free,    LimitState::Free,    LimitState::Free,
                                           LimitState::AtLower, LimitState::AtUpper, LimitState::AtLower};
    EXPECT_EQ(s.limit, expected);
}

TEST(Compile, InitialRatesOfRevoluteAndT1Joints)
{
    const auto zoo = test::compileText(test::kZooModel);
    ASSERT_TRUE(zoo);
    EXPECT_EQ(zoo->thetaDot0[zoo->jointIndex(7)], 0.5);  // VI 0.5 rad/s
    EXPECT_EQ(makeState(*zoo).qd[zoo->jointIndex(7)], 0.5);

    // T 1 with VI −0.02 m/s: θ̇ = VI / (dL/dθ)
    const auto arm = test::compileText(test::kCylinderArmModel);
    ASSERT_TRUE(arm);
    const int i = arm->jointIndex(3);
    const double rate = arm->lengthLaw[i].lengthRate(arm->theta0[i]);
    EXPECT_NEAR(arm->thetaDot0[i], -0.02 / rate, 1e-15);
    EXPECT_NEAR(arm->thetaDot0[i] * arm->coordinateRate(i, arm->theta0[i]), -0.02, 1e-15);
}

TEST(Compile, ActuatorWhoseLengthShrinksAsTheAngleGrows)
{
    // the cylinder arm's boom cylinder: LL 0.55 / UL 0.75 m with dL/dθ < 0, so UL gives the lower angle
    const auto model = test::compileText(test::kCylinderArmModel);
    ASSERT_TRUE(model);
    const Model& m = *model;
    const int i = m.jointIndex(2);
    EXPECT_LT(m.coordinateRate(i, m.theta0[i]), 0.0);
    EXPECT_LT(m.lower[i], m.theta0[i]);
    EXPECT_GT(m.upper[i], m.theta0[i]);
    EXPECT_NEAR(m.coordinate(i, m.lower[i]), 0.75, 1e-12);
    EXPECT_NEAR(m.coordinate(i, m.upper[i]), 0.55, 1e-12);
    EXPECT_NEAR(m.coordinate(i, m.theta0[i]), 0.65, 1e-12);  // mid-stroke
    EXPECT_EQ(m.bodyName[i], "boom");
    EXPECT_EQ(m.mass[m.bodyIndex(1)], 0.0);  // the massless yoke
}

TEST(Compile, ReversedJointsGetNegativeAxisSign)
{
    const auto model = test::compileText(test::kZooModel);
    ASSERT_TRUE(model);
    const Model& m = *model;
    // the tree: slew, shoulder, slide, elbow, rocker cylinder, tip slide, wrist
    EXPECT_EQ(m.jointId, (std::vector<int>{1, 2, 4, 3, 5, 6, 7}));
    EXPECT_EQ(m.bodyId, (std::vector<int>{1, 2, 4, 3, 5, 6, 7}));
    EXPECT_EQ(m.parent, (std::vector<int>{-1, 0, 0, 1, 2, 2, 4}));
    for (int id : {2, 5, 6}) EXPECT_EQ(m.axisSign[m.jointIndex(id)], -1.0) << id;
    for (int id : {1, 3, 4, 7}) EXPECT_EQ(m.axisSign[m.jointIndex(id)], 1.0) << id;

    // joint 2 is written B1 2 (child) … B2 1 (parent): X_pj is its B2 frame, at P2 on body 1
    const int j2 = m.jointIndex(2);
    EXPECT_TRUE(m.X_pj[j2].translation().isApprox(Vector3d(0.2, 0.1, 0.3)));
    EXPECT_TRUE(m.X_cj[j2].translation().isApprox(Vector3d(0, -0.2, 0)));
    // products of inertia and centre of mass of the column
    const int b1 = m.bodyIndex(1);
    Eigen::Matrix3d I;
    I << 0.20, 0.010, 0.015, 0.010, 0.30, -0.020, 0.015, -0.020, 0.25;
    EXPECT_TRUE(m.inertia[b1].isApprox(I));
    EXPECT_TRUE(m.com[b1].isApprox(Vector3d(0.10, -0.05, 0.20)));
    EXPECT_TRUE(m.gravity.isApprox(Vector3d(0.4, -0.3, -9.81)));
}

// The body poses of the compiled model equal those of the topology analysis
// (tests/solver/spec_oracle.h, which works on the spec) at random coordinates.
void expectPosesAgreeWithTopology(const CompiledModel& loaded)
{
    const auto model = test::modelOrFail(loaded);
    ASSERT_TRUE(model);
    const Model& m = *model;
    const Topology& topo = *loaded.topology;
    const std::vector<JointGeometry> geometry = makeJointGeometries(loaded.spec);

    std::mt19937 rng(11);
    Data data(m);
    for (int trial = 0; trial < 20; ++trial) {
        const State s = test::randomState(m, rng, false);
        forwardKinematics(m, s, data);
        Eigen::VectorXd theta = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(geometry.size()));
        for (std::size_t j = 0; j < loaded.spec.joints.size(); ++j) {
            theta[static_cast<Eigen::Index>(j)] = s.q[m.jointIndex(loaded.spec.joints[j].id)];
        }
        const std::vector<Eigen::Isometry3d> X = test::bodyPoses(topo, geometry, theta);
        for (std::size_t b = 1; b < topo.bodyIds.size(); ++b) {
            const int i = m.bodyIndex(topo.bodyIds[b]);
            EXPECT_TRUE(data.X_wb[i].matrix().isApprox(X[b].matrix(), 1e-12))
                << "body " << topo.bodyIds[b] << "\n" << data.X_wb[i].matrix() << "\n" << X[b].matrix();
        }
    }
}

TEST(Compile, PosesAgreeWithTheTopologyAnalysis)
{
    expectPosesAgreeWithTopology(compileText(test::kZooModel));
    expectPosesAgreeWithTopology(compileText(test::kCylinderArmModel));
    for (const char* name : {"pendulum.pad", "double_pendulum.pad", "incline_slider.pad",
                             "liner_manipulator.pad"}) {
        SCOPED_TRACE(name);
        expectPosesAgreeWithTopology(compileFile(test::modelPath(name)));
    }
}

TEST(Compile, JointWrittenChildToParentNegatesTheCoordinate)
{
    // the pendulum with its joint written from the bob to the ground, QI negated
    const auto forward = test::compileExample("pendulum.pad");
    const auto reversed = test::compileText(R"(B 1 1.0 1e-6 1e-6 1e-6
C 1 QI -0.1
B1 1 P1 0 0 1 A1 1 0 0 R1 0 0 -1
B2 0 P2 0 0 0 A2 1 0 0 R2 0 0 -1
)");
    ASSERT_TRUE(forward && reversed);
    EXPECT_EQ(reversed->axisSign[0], -1.0);
    EXPECT_DOUBLE_EQ(reversed->theta0[0], -0.1);
    Data a(*forward), b(*reversed);
    forwardKinematics(*forward, makeState(*forward), a);
    forwardKinematics(*reversed, makeState(*reversed), b);
    EXPECT_TRUE(a.X_wb[0].matrix().isApprox(b.X_wb[0].matrix(), 1e-15));
}

// ------------------------------------------------------------------ drives and forces

TEST(Compile, ServoSetPointRanges)
{
    const auto model = test::compileText(R"(B 1 1 0.1 0.1 0.1
B 2 1 0.1 0.1 0.1
B 3 1 0.1 0.1 0.1
C 1 LL -0.5 UL 0.7
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 -0.5 0 0 A2 0 0 1 R2 1 0 0
C 2
B1 1 P1 0.5 0 0 A1 0 0 1 R1 1 0 0
B2 2 P2 -0.5 0 0 A2 0 0 1 R2 1 0 0
C 3 T 1
B1 2 P1 0.5 0 0 A1 0 0 1 R1 1 0 0
B2 3 P2 -0.5 0 0 A2 0 0 1 R2 1 0 0
CL1 0.5 0.2 0 CL2 -0.5 0.3 0
D 1 SERVO KP 100 KI 1 KD 10 FMAX 50
D 2 SERVO KP 1 KI 0 KD 0
D 3 SERVO KP 2 KI 0 KD 0
)");
    ASSERT_TRUE(model);
    const Model& m = *model;
    const CompiledDrive& d1 = m.drive[m.jointIndex(1)];
    EXPECT_EQ(d1.type, DriveType::Servo);
    EXPECT_EQ(d1.kp, 100.0);
    EXPECT_EQ(d1.ki, 1.0);
    EXPECT_EQ(d1.kd, 10.0);
    EXPECT_EQ(d1.servoFmax, 50.0);
    EXPECT_EQ(d1.setLow, -0.5);
    EXPECT_EQ(d1.setHigh, 0.7);
    const CompiledDrive& d2 = m.drive[m.jointIndex(2)];
    EXPECT_EQ(d2.servoFmax, kInf);
    EXPECT_DOUBLE_EQ(d2.setLow, -kPi);
    EXPECT_DOUBLE_EQ(d2.setHigh, kPi);
    // T 1 without limits: the reachable lengths; CL1, CL2 are 0.2 and 0.3 m off the axis:
    // 0.3 − 0.2 .. 0.3 + 0.2 m
    const CompiledDrive& d3 = m.drive[m.jointIndex(3)];
    EXPECT_NEAR(d3.setLow, 0.1, 1e-12);
    EXPECT_NEAR(d3.setHigh, 0.5, 1e-12);
}

TEST(Compile, MotorAndPneumaticDrives)
{
    const auto model = test::compileText(test::kZooModel);
    ASSERT_TRUE(model);
    const Model& m = *model;
    const CompiledDrive& motor = m.drive[m.jointIndex(1)];
    EXPECT_EQ(motor.type, DriveType::Motor);
    EXPECT_EQ(motor.t0, 20.0);
    EXPECT_EQ(motor.w0, 3.0);
    const CompiledDrive& pneu = m.drive[m.jointIndex(4)];
    EXPECT_EQ(pneu.type, DriveType::Pneumatic);
    EXPECT_EQ(pneu.force, 30.0);
    EXPECT_EQ(m.drive[m.jointIndex(7)].type, DriveType::None);
}

TEST(Compile, ForcesUseTreeIndices)
{
    // body 5 hangs from the ground by joint 7, body 3 from body 5 by joint 4
    const auto model = test::compileText(R"(B 3 1 0.1 0.1 0.1
B 5 2 0.1 0.1 0.1
C 4
B1 5 P1 0.5 0 0 A1 0 0 1 R1 1 0 0
B2 3 P2 -0.5 0 0 A2 0 0 1 R2 1 0 0
C 7
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 5 P2 -0.5 0 0 A2 0 0 1 R2 1 0 0
F 1 POINT B 3 P 0.1 0 0 DIR 0 0 -2 MAG 10
F 2 TORQUE B 5 DIR 3 4 0 MAG SIN 1 2 0.5 0.1 LOCAL
F 3 JOINT 4 MAG TABLE Q 7 0 0 1 5
F 4 SPRING B1 0 P1 0 0 1 B2 3 P2 0 0 0 K 100 L0 0.5 C 2
F 5 AERO B 3 P 0 0 0 AREA 0.5 CD 1.2 CL 0.3 RHO 1.0
)");
    ASSERT_TRUE(model);
    const Model& m = *model;
    EXPECT_EQ(m.bodyId, (std::vector<int>{5, 3}));
    EXPECT_EQ(m.jointId, (std::vector<int>{7, 4}));
    ASSERT_EQ(m.forces.size(), 5u);

    const CompiledForce& point = m.forces[0];
    EXPECT_EQ(point.kind, ForceKind::Point);
    EXPECT_EQ(point.body, 1);
    EXPECT_TRUE(point.dir.isApprox(Vector3d(0, 0, -1)));
    EXPECT_TRUE(point.point.isApprox(Vector3d(0.1, 0, 0)));
    EXPECT_EQ(point.mag.kind, MagnitudeSpec::Kind::Constant);
    EXPECT_EQ(point.mag.value, 10.0);

    const CompiledForce& torque = m.forces[1];
    EXPECT_EQ(torque.body, 0);
    EXPECT_TRUE(torque.local);
    EXPECT_TRUE(torque.dir.isApprox(Vector3d(0.6, 0.8, 0)));
    EXPECT_EQ(torque.mag.kind, MagnitudeSpec::Kind::Sine);
    EXPECT_EQ(torque.mag.amplitude, 1.0);
    EXPECT_EQ(torque.mag.frequency, 2.0);
    EXPECT_EQ(torque.mag.phase, 0.5);
    EXPECT_EQ(torque.mag.offset, 0.1);

    const CompiledForce& joint = m.forces[2];
    EXPECT_EQ(joint.joint, 1);
    EXPECT_EQ(joint.mag.kind, MagnitudeSpec::Kind::TableJoint);
    EXPECT_EQ(joint.mag.joint, 0);  // joint 7
    EXPECT_EQ(joint.mag.x, (std::vector<double>{0, 1}));
    EXPECT_EQ(joint.mag.y, (std::vector<double>{0, 5}));

    const CompiledForce& spring = m.forces[3];
    EXPECT_EQ(spring.body, -1);
    EXPECT_EQ(spring.body2, 1);
    EXPECT_TRUE(spring.point.isApprox(Vector3d(0, 0, 1)));
    EXPECT_EQ(spring.stiffness, 100.0);
    EXPECT_EQ(spring.restLength, 0.5);
    EXPECT_EQ(spring.damping, 2.0);

    const CompiledForce& aero = m.forces[4];
    EXPECT_EQ(aero.body, 1);
    EXPECT_EQ(aero.area, 0.5);
    EXPECT_EQ(aero.cd, 1.2);
    EXPECT_EQ(aero.cl, 0.3);
    EXPECT_EQ(aero.rho, 1.0);
}

// ------------------------------------------------------------------ what is not compiled

TEST(Compile, LoopModelsKeepTheirCutJoints)
{
    // four-bar: tree 1 (crank), 2 (coupler on the crank), 3 (rocker); joint 4 closes the loop
    const auto model = test::compileExample("four_bar.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    EXPECT_EQ(m.nb, 3);
    ASSERT_EQ(m.cuts.size(), 1u);
    const CutJoint& cut = m.cuts[0];
    EXPECT_EQ(cut.jointId, 4);
    EXPECT_EQ(cut.name, "rocker pin B");
    EXPECT_EQ(cut.type, JointType::Revolute);
    EXPECT_EQ(cut.body1, m.bodyIndex(2));
    EXPECT_EQ(cut.body2, m.bodyIndex(3));
    EXPECT_TRUE(cut.X_1.translation().isApprox(Vector3d(0.175, 0, 0)));
    EXPECT_TRUE(cut.X_2.translation().isApprox(Vector3d(0.15, 0, 0)));
    EXPECT_TRUE(cut.X_1.linear().col(0).isApprox(Vector3d::UnitZ()));  // A
    EXPECT_TRUE(cut.X_1.linear().col(1).isApprox(Vector3d::UnitX()));  // R
    // the largest joint point distance from a body origin: O4 at 0.4 m from the world's
    EXPECT_NEAR(m.lengthScale, 0.4, 1e-12);
    // the crank's coordinate is the degree of freedom; coupler and rocker follow
    EXPECT_FALSE(m.dependent[m.jointIndex(1)]);
    EXPECT_TRUE(m.dependent[m.jointIndex(2)]);
    EXPECT_TRUE(m.dependent[m.jointIndex(3)]);

    // slider-crank: the piston's slide (a prismatic joint) is the tree joint of the
    // piston or the cut; either way the cut's kind follows its joint type
    const auto sc = test::compileExample("slider_crank.pad");
    ASSERT_TRUE(sc);
    ASSERT_EQ(sc->cuts.size(), 1u);
    EXPECT_EQ(sc->nb, 3);
}

TEST(Compile, DriveOnALoopClosingJointIsAnError)
{
    // every joint of the loop driven: the spanning tree must cut a driven joint
    const std::string text = R"(B 1 1 0.01 0.01 0.01
B 2 1 0.01 0.01 0.01
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 -0.5 0 0 A2 0 0 1 R2 1 0 0
C 2
B1 1 P1 0.5 0 0 A1 0 0 1 R1 1 0 0
B2 2 P2 -0.5 0 0 A2 0 0 1 R2 1 0 0
C 3 LL -1 UL 1
B1 2 P1 0.5 0 0 A1 0 0 1 R1 1 0 0
B2 0 P2 2 0 0 A2 0 0 1 R2 1 0 0
D 1 MOTOR T0 1 W0 1
D 2 MOTOR T0 1 W0 1
D 3 MOTOR T0 1 W0 1
)";
    // (the model loads as text; compiling it fails)
    const CompiledModel loaded = compileText(text, "loop.pad");
    Diagnostics graph(loaded.spec.file);
    ASSERT_EQ(analyzeTopology(loaded.spec, graph).loopJoints.size(), 1u);
    EXPECT_EQ(loaded.model, nullptr);
    const Diagnostics& diags = loaded.diagnostics;
    bool driven = false, limits = false;
    for (const Diagnostic& d : diags) {
        if (d.code == "loop-joint-driven") {
            driven = true;
            EXPECT_EQ(d.severity, Severity::Error);
            EXPECT_EQ(d.pos.line, 14) << d.format();  // the D 3 line
            EXPECT_NE(d.message.find("closes a loop"), std::string::npos);
        }
        if (d.code == "loop-joint-limits-ignored") {
            limits = true;
            EXPECT_EQ(d.severity, Severity::Warning);
            EXPECT_EQ(d.pos.line, 9) << d.format();
        }
    }
    EXPECT_TRUE(driven);
    EXPECT_TRUE(limits);
}

TEST(Compile, ModelWithErrorsGivesNothing)
{
    const CompiledModel loaded = compileText("B 1 1 1 1 1\nC 1\nB1 0 P1 0 0 0 A1 0 0 0 R1 1 0 0\n");
    ASSERT_FALSE(loaded.ok());
    EXPECT_EQ(loaded.model, nullptr);
    EXPECT_FALSE(loaded.topology);
}

TEST(Compile, DataIsSizedForTheModel)
{
    const auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const Data d(*model);
    EXPECT_EQ(d.X_wb.size(), 9u);
    EXPECT_EQ(d.X_wj.size(), 9u);
    EXPECT_EQ(d.fext.size(), 9u);
    EXPECT_EQ(d.tauExt.size(), 9);
    EXPECT_EQ(d.qdd.size(), 9);
    EXPECT_EQ(d.driveForce.size(), 9);
    EXPECT_EQ(d.limitForce.size(), 9);
    EXPECT_EQ(d.reactionWorld.size(), 9u);
    EXPECT_EQ(d.reactionJoint.size(), 9u);
    EXPECT_EQ(d.IA.size(), 9u);
    EXPECT_TRUE(d.tauExt.isZero());
}

}  // namespace
}  // namespace solver
