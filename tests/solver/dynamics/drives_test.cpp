#include "solver/dynamics/drives.h"

#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace solver {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Drives, HydraulicCommandRates)
{
    CompiledDrive d;
    d.type = DriveType::Hydraulic;
    d.vmax = 0.2;
    d.vmin = 0.4;
    EXPECT_DOUBLE_EQ(hydraulicCommandRate(d, 0.5), 0.1);    // u·VMAX extending
    EXPECT_DOUBLE_EQ(hydraulicCommandRate(d, -0.5), -0.2);  // u·VMIN retracting
    EXPECT_EQ(hydraulicCommandRate(d, 0.0), 0.0);           // valve closed: held
    EXPECT_DOUBLE_EQ(hydraulicCommandRate(d, 3.0), 0.2);    // u clamped to [−1, 1]
    EXPECT_DOUBLE_EQ(hydraulicCommandRate(d, -3.0), -0.4);
}

TEST(Drives, WhichJointsArePrescribed)
{
    const auto model = test::compileText(test::kZooModel);
    ASSERT_TRUE(model);
    const Model& m = *model;
    State s = makeState(m);
    const int motor = m.jointIndex(1), cylinder = m.jointIndex(3), passive = m.jointIndex(7);
    EXPECT_FALSE(isPrescribed(m, s, motor));
    EXPECT_TRUE(isPrescribed(m, s, cylinder));  // hydraulic, relief closed
    EXPECT_FALSE(isPrescribed(m, s, passive));
    s.relief[cylinder] = ReliefState::OpenExtending;
    EXPECT_FALSE(isPrescribed(m, s, cylinder));
    s.limit[cylinder] = LimitState::AtUpper;  // a limit wins over the open relief
    EXPECT_TRUE(isPrescribed(m, s, cylinder));
    s.limit[passive] = LimitState::AtLower;
    EXPECT_TRUE(isPrescribed(m, s, passive));
    EXPECT_EQ(prescribedAcceleration(m, s, passive), 0.0);
    EXPECT_EQ(prescribedRate(m, s, passive), 0.0);
}

TEST(Drives, LengthSecondDerivativeAgainstFiniteDifferences)
{
    const auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    for (int i : {1, 4}) {
        const ActuatorLengthLaw& law = model->lengthLaw[i];
        for (double th : {-1.5, -0.3, 0.0, 0.4, 0.9}) {
            const double h = 1e-4;
            const double fd = (law.length(th + h) - 2 * law.length(th) + law.length(th - h)) / (h * h);
            EXPECT_NEAR(law.lengthSecondDerivative(th), fd, 1e-6) << i << " " << th;
            const double fd1 = (law.length(th + h) - law.length(th - h)) / (2 * h);
            EXPECT_NEAR(law.lengthRate(th), fd1, 1e-8);
        }
    }
}

TEST(Drives, T1CylinderKeepsItsSpeedWhenHeld)
{
    // boom lift of the liner manipulator extending at full command: L̇ = VMAX held, so
    // θ̇ = VMAX / L'(θ) and θ̈ = −L''θ̇²/L' keep d/dt (L'θ̇) = L''θ̇² + L'θ̈ = 0
    const auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const Model& m = *model;
    State s = makeState(m);
    const int boom = m.jointIndex(2);
    s.u[boom] = 1.0;
    const ActuatorLengthLaw& law = m.lengthLaw[boom];
    for (double th : {-0.3, 0.0, 0.5, 0.9}) {
        s.q[boom] = th;
        s.qd[boom] = prescribedRate(m, s, boom);
        EXPECT_NEAR(s.qd[boom] * law.lengthRate(th), m.drive[boom].vmax, 1e-15);
        const double thdd = prescribedAcceleration(m, s, boom);
        // L̈ along θ(t) = θ + θ̇t + ½θ̈t², by finite differences
        const double h = 1e-3;
        auto L = [&](double t) { return law.length(th + s.qd[boom] * t + 0.5 * thdd * t * t); };
        const double lddot = (L(h) - 2 * L(0) + L(-h)) / (h * h);
        EXPECT_NEAR(lddot, 0.0, 1e-8) << th;
        EXPECT_NEAR(law.lengthSecondDerivative(th) * s.qd[boom] * s.qd[boom] + law.lengthRate(th) * thdd, 0.0, 1e-15);
    }
    // retracting at half command uses VMIN; a revolute or prismatic hydraulic joint has θ̈ = 0
    s.u[boom] = -0.5;
    s.q[boom] = 0.2;
    EXPECT_NEAR(prescribedRate(m, s, boom) * law.lengthRate(0.2), -0.5 * m.drive[boom].vmin, 1e-15);
    const int telescope = m.jointIndex(3);
    s.limit[telescope] = LimitState::Free;
    s.u[telescope] = 0.3;
    EXPECT_DOUBLE_EQ(prescribedRate(m, s, telescope), 0.3 * m.drive[telescope].vmax);
    s.qd[telescope] = 0.3;
    EXPECT_EQ(prescribedAcceleration(m, s, telescope), 0.0);
    // relief open: the rate is the state's own
    s.relief[boom] = ReliefState::OpenRetracting;
    s.qd[boom] = 0.123;
    EXPECT_EQ(prescribedRate(m, s, boom), 0.123);
}

TEST(Drives, ForceLaws)
{
    const auto model = test::compileText(test::kZooModel);
    ASSERT_TRUE(model);
    const Model& m = *model;
    State s = makeState(m);

    // D 1 MOTOR T0 20 W0 3: u·T0·(1 − |q̇|/W0), zero beyond W0
    const int motor = m.jointIndex(1);
    s.u[motor] = 0.5;
    s.qd[motor] = -1.5;
    EXPECT_DOUBLE_EQ(driveForceLaw(m, s, motor), 0.5 * 20 * (1 - 1.5 / 3));
    s.qd[motor] = 3.5;
    EXPECT_EQ(driveForceLaw(m, s, motor), 0.0);

    // D 4 PNEU F 30: u·F
    const int pneu = m.jointIndex(4);
    s.u[pneu] = -0.4;
    EXPECT_DOUBLE_EQ(driveForceLaw(m, s, pneu), -12.0);

    // D 2 SERVO KP 200 KI 10 KD 5 FMAX 80 on LL −1 … UL 1.2: set-point −1 + (u + 1)/2·2.2
    const int servo = m.jointIndex(2);
    const CompiledDrive& sd = m.drive[servo];
    EXPECT_EQ(servoSetPoint(sd, -1), -1.0);
    EXPECT_DOUBLE_EQ(servoSetPoint(sd, 1), 1.2);
    EXPECT_NEAR(servoSetPoint(sd, 0), 0.1, 1e-15);
    s.u[servo] = 0.0;
    s.q[servo] = 0.05;
    s.qd[servo] = 0.2;
    s.servoIntegral[servo] = 0.3;
    EXPECT_NEAR(servoError(m, s, servo), 0.05, 1e-15);
    EXPECT_NEAR(driveForceLaw(m, s, servo), 200 * 0.05 + 10 * 0.3 - 5 * 0.2, 1e-12);  // 12 N m
    s.q[servo] = -0.9;  // far from the set-point: clamped to FMAX
    EXPECT_EQ(driveForceLaw(m, s, servo), 80.0);
    EXPECT_EQ(servoError(m, s, m.jointIndex(7)), 0.0);

    // D 3 HYD … FMAX 5000 FMIN 3000: the relief force when open, nothing known when closed
    const int hyd = m.jointIndex(3);
    EXPECT_EQ(driveForceLaw(m, s, hyd), 0.0);
    s.relief[hyd] = ReliefState::OpenExtending;
    EXPECT_EQ(driveForceLaw(m, s, hyd), 5000.0);
    s.relief[hyd] = ReliefState::OpenRetracting;
    EXPECT_EQ(driveForceLaw(m, s, hyd), -3000.0);

    // passive
    EXPECT_EQ(driveForceLaw(m, s, m.jointIndex(7)), 0.0);
}

TEST(Drives, ServoOnACylinderWorksOnItsLength)
{
    // the cylinder arm's joint 3 (T 1, SERVO KP 5000 KI 100 KD 200 FMAX 3000, no limits):
    // e = set-point − L, ė = −L'θ̇
    const auto model = test::compileText(test::kCylinderArmModel);
    ASSERT_TRUE(model);
    const Model& m = *model;
    State s = makeState(m);
    const int j = m.jointIndex(3);
    const ActuatorLengthLaw& law = m.lengthLaw[j];
    EXPECT_DOUBLE_EQ(m.drive[j].setLow, law.minLength());
    EXPECT_DOUBLE_EQ(m.drive[j].setHigh, law.maxLength());
    s.u[j] = 0.1;
    s.qd[j] = 0.05;
    const double e = servoSetPoint(m.drive[j], 0.1) - law.length(s.q[j]);
    const double force = 5000 * e + 100 * s.servoIntegral[j] - 200 * law.lengthRate(s.q[j]) * 0.05;
    EXPECT_NEAR(servoError(m, s, j), e, 1e-15);
    EXPECT_NEAR(driveForceLaw(m, s, j), std::clamp(force, -3000.0, 3000.0), 1e-12);
    EXPECT_EQ(m.drive[j].servoFmax, 3000.0);
    EXPECT_NE(m.drive[m.jointIndex(2)].fmax, kInf);
}

}  // namespace
}  // namespace solver
