// Calibration maths, property-tested over many random calibrations and readings
// (seeded): range, monotonicity, centre, extremes, dead bands, continuity, curves,
// filter, capture.
#include "trainer/station/calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using trainer::CalibrationCapture;
using trainer::ChannelCalibration;
using trainer::LowPass;
using trainer::ResponseCurve;

namespace {

ChannelCalibration randomCalibration(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    ChannelCalibration c;
    c.rawMin = -5000.0 + 10000.0 * u(rng);
    c.rawMax = c.rawMin + 10.0 + 60000.0 * u(rng);
    c.rawCentre = c.rawMin + (c.rawMax - c.rawMin) * (0.1 + 0.8 * u(rng));
    c.deadBandLow = 0.3 * u(rng);
    c.deadBandHigh = 0.3 * u(rng);
    c.inverted = u(rng) < 0.5;
    c.curve = u(rng) < 0.5 ? ResponseCurve::Linear : ResponseCurve::Exponential;
    c.exponent = 0.1 + 5.0 * u(rng);
    c.captured = true;
    return c;
}

}  // namespace

TEST(Calibration, PropertiesHoldForRandomCalibrations)
{
    std::mt19937 rng(20261122);
    for (int trial = 0; trial < 500; ++trial) {
        const ChannelCalibration c = randomCalibration(rng);
        ASSERT_TRUE(c.isValid()) << c.problem().toStdString();
        const double sign = c.inverted ? -1.0 : 1.0;
        EXPECT_EQ(c.apply(c.rawCentre), 0.0);
        EXPECT_NEAR(c.apply(c.rawMax), sign * 1.0, 1e-12);
        EXPECT_NEAR(c.apply(c.rawMin), sign * -1.0, 1e-12);
        EXPECT_NEAR(c.apply(c.rawMax + 1e6), sign * 1.0, 1e-12);  // clamped beyond the range
        // monotone (non-decreasing, or non-increasing when inverted), in [−1, 1]
        double previous = -2.0 * sign;
        const double span = c.rawMax - c.rawMin;
        for (int k = -10; k <= 1010; ++k) {
            const double raw = c.rawMin + span * k / 1000.0;
            const double y = c.apply(raw);
            ASSERT_LE(std::abs(y), 1.0);
            ASSERT_GE(sign * (y - previous), -1e-15) << "trial " << trial << " raw " << raw;
            previous = y;
        }
        // dead band: zero inside, non-zero just outside, continuous at its edge
        const double upEdge = c.rawCentre + c.deadBandHigh * (c.rawMax - c.rawCentre);
        const double downEdge = c.rawCentre - c.deadBandLow * (c.rawCentre - c.rawMin);
        EXPECT_EQ(c.apply(0.5 * (c.rawCentre + upEdge)), 0.0);
        EXPECT_EQ(c.apply(0.5 * (c.rawCentre + downEdge)), 0.0);
        EXPECT_NE(c.apply(upEdge + 1e-3 * span), 0.0);
        EXPECT_NE(c.apply(downEdge - 1e-3 * span), 0.0);
        EXPECT_LT(std::abs(c.apply(upEdge + 1e-9 * span)), 1e-6);
    }
}

TEST(Calibration, SidesAreScaledSeparately)
{
    // a pot resting at 600 of 0…1023: half travel on each side gives ±0.5
    const ChannelCalibration c{0, 600, 1023};
    EXPECT_NEAR(c.apply(300), -0.5, 1e-12);
    EXPECT_NEAR(c.apply(600 + 423.0 / 2), 0.5, 1e-12);
}

TEST(Calibration, DeadBandStretchesTheRestOfTheTravel)
{
    ChannelCalibration c{-100, 0, 100, 0.2, 0.1};
    EXPECT_EQ(c.apply(10), 0.0);
    EXPECT_EQ(c.apply(-20), 0.0);
    EXPECT_NEAR(c.apply(55), 0.5, 1e-12);   // (0.55 − 0.1) / 0.9
    EXPECT_NEAR(c.apply(-60), -0.5, 1e-12);  // (0.6 − 0.2) / 0.8
}

TEST(Calibration, ExponentialCurveIsFinerNearTheCentreAndTendsToLinear)
{
    ChannelCalibration c{-1, 0, 1};
    c.curve = ResponseCurve::Exponential;
    c.exponent = 3.0;
    EXPECT_NEAR(c.apply(0.5), std::expm1(1.5) / std::expm1(3.0), 1e-12);
    EXPECT_LT(c.apply(0.5), 0.5);
    EXPECT_NEAR(c.apply(-0.5), -c.apply(0.5), 1e-15);  // odd
    c.exponent = ChannelCalibration::kMinExponent;
    EXPECT_NEAR(c.apply(0.3), 0.3, 0.01);
}

TEST(Calibration, OneSidedTriggerGivesZeroToOne)
{
    const ChannelCalibration c{0, 0, 32767};
    ASSERT_TRUE(c.isValid());
    EXPECT_EQ(c.apply(0), 0.0);
    EXPECT_NEAR(c.apply(32767), 1.0, 1e-12);
    EXPECT_NEAR(c.apply(-500), 0.0, 1e-12);
}

TEST(Calibration, OutOfRangeIsFlaggedBeyondTheMargin)
{
    const ChannelCalibration c{100, 500, 900};
    EXPECT_FALSE(c.outOfRange(95));   // within 3 % of the 800 span
    EXPECT_TRUE(c.outOfRange(60));
    EXPECT_TRUE(c.outOfRange(960));
    EXPECT_TRUE(c.outOfRange(std::nan("")));
    EXPECT_EQ(c.apply(std::nan("")), 0.0);
}

TEST(Calibration, InvalidCalibrationsSayWhyAndGiveZero)
{
    EXPECT_FALSE((ChannelCalibration{5, 3, 4}).isValid());
    EXPECT_FALSE((ChannelCalibration{5, 5, 5}).problem().isEmpty());
    EXPECT_FALSE((ChannelCalibration{0, 1, 2, 0.95}).isValid());
    ChannelCalibration bad{0, 1, 2};
    bad.filterHz = -1;
    EXPECT_FALSE(bad.problem().isEmpty());
    EXPECT_EQ((ChannelCalibration{5, 3, 4}).apply(4.5), 0.0);
}

TEST(Calibration, JsonRoundTripAndTypeErrors)
{
    std::mt19937 rng(7);
    for (int i = 0; i < 50; ++i) {
        ChannelCalibration c = randomCalibration(rng);
        c.filterHz = 12.5;
        ChannelCalibration back;
        QString error;
        ASSERT_TRUE(ChannelCalibration::fromJson(c.toJson(), back, &error)) << error.toStdString();
        EXPECT_EQ(back, c);
    }
    QJsonObject o{{"min", "low"}};
    ChannelCalibration out;
    QString error;
    EXPECT_FALSE(ChannelCalibration::fromJson(o, out, &error));
    EXPECT_TRUE(error.contains("min"));
    EXPECT_FALSE(ChannelCalibration::fromJson(QJsonObject{{"min", 5}, {"max", 1}}, out, &error));
    EXPECT_FALSE(error.isEmpty());
}

TEST(Calibration, LowPassHasTheTimeConstantOfItsCutoff)
{
    LowPass f;
    const double fc = 5.0, dt = 1e-3;
    f.update(0.0, fc, dt);
    double y = 0.0;
    const double tau = 1.0 / (2.0 * std::numbers::pi * fc);
    const int steps = int(std::round(tau / dt));
    for (int i = 0; i < steps; ++i) y = f.update(1.0, fc, dt);
    EXPECT_NEAR(y, 1.0 - std::exp(-steps * dt / tau), 1e-9);  // 63 % after one time constant
    LowPass none;
    none.update(0.0, 0.0, dt);
    EXPECT_EQ(none.update(0.7, 0.0, dt), 0.7);
}

TEST(Calibration, CaptureFindsCentreAndTravelAndDetectsOneSidedLevers)
{
    CalibrationCapture cap;
    QString why;
    EXPECT_FALSE(cap.complete(1023, &why));
    EXPECT_FALSE(why.isEmpty());
    cap.startRest();
    for (double v : {498.0, 502.0, 500.0, 501.0, 499.0}) cap.add(v);
    EXPECT_DOUBLE_EQ(cap.centre(), 500.0);
    EXPECT_DOUBLE_EQ(cap.restSpread(), 4.0);
    EXPECT_FALSE(cap.complete(1023, &why));
    cap.startTravel();
    for (double v : {520.0, 900.0, 1010.0, 700.0, 300.0, 12.0, 400.0}) cap.add(v);
    EXPECT_TRUE(cap.complete(1023, &why)) << why.toStdString();
    ChannelCalibration base;
    base.deadBandHigh = 0.05;
    const ChannelCalibration c = cap.result(base);
    EXPECT_EQ(c.rawMin, 12.0);
    EXPECT_EQ(c.rawMax, 1010.0);
    EXPECT_EQ(c.rawCentre, 500.0);
    EXPECT_EQ(c.deadBandHigh, 0.05);
    EXPECT_TRUE(c.captured);

    CalibrationCapture trigger;  // rests at its minimum
    trigger.startRest();
    trigger.add(3.0);
    trigger.startTravel();
    for (double v : {0.0, 15000.0, 32767.0}) trigger.add(v);
    const ChannelCalibration t = trigger.result({});
    EXPECT_EQ(t.rawCentre, t.rawMin);
    EXPECT_TRUE(t.isValid());
}
