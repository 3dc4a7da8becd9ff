#include "solver/integrate/integrator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace solver {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kOmega = 2 * kPi;  // oscillator: period 1 s
constexpr double kGravity = 9.81;  // [m/s^2]

IntegratorOptions rk4(double step = 1e-3)
{
    IntegratorOptions o;
    o.method = IntegrationMethod::Rk4Fixed;
    o.step = step;
    return o;
}

IntegratorOptions adaptive(double rtol = 1e-10, double atol = 1e-12,
                           IntegrationMethod m = IntegrationMethod::Adaptive)
{
    IntegratorOptions o;
    o.method = m;
    o.rtol = rtol;
    o.atol = atol;
    return o;
}

IntegratorOptions stiff(double rtol = 1e-10, double atol = 1e-12)
{
    return adaptive(rtol, atol, IntegrationMethod::AdaptiveStiff);
}

// x'' = −ω² x as y = (x, v); x(0) = 1, v(0) = 0: x = cos ωt, v = −ω sin ωt.
// Optional event: g0 = x (its zero crossings at t = 1/4 + k/2).
class Oscillator : public OdeSystem {
public:
    explicit Oscillator(bool zeroCrossings = false) : m_roots(zeroCrossings) {}
    int size() const override { return 2; }
    bool rhs(double t, const double* y, double* ydot) override
    {
        maxRhsTime = std::max(maxRhsTime, t);
        ydot[0] = y[1];
        ydot[1] = -kOmega * kOmega * y[0];
        return true;
    }
    int rootCount() const override { return m_roots ? 1 : 0; }
    bool roots(double, const double* y, double* g) override
    {
        g[0] = y[0];
        return true;
    }

    static double x(double t) { return std::cos(kOmega * t); }
    static double v(double t) { return -kOmega * std::sin(kOmega * t); }
    static double energy(const double* y)
    {
        return 0.5 * y[1] * y[1] + 0.5 * kOmega * kOmega * y[0] * y[0];
    }
    static double error(double t, const double* y)
    {
        return std::max(std::abs(y[0] - x(t)), std::abs(y[1] - v(t)) / kOmega);
    }

    double maxRhsTime = -1;

private:
    bool m_roots;
};

// A ball in free fall, y = (height [m], vertical velocity [m/s]). Events:
// g0 = height, reported only falling (the floor); g1 = velocity (the apex);
// g2 = height − 0.5 m, both ways.
class Ball : public OdeSystem {
public:
    int size() const override { return 2; }
    bool rhs(double, const double* y, double* ydot) override
    {
        ydot[0] = y[1];
        ydot[1] = -kGravity;
        return true;
    }
    int rootCount() const override { return 3; }
    bool roots(double, const double* y, double* g) override
    {
        g[0] = y[0];
        g[1] = y[1];
        g[2] = y[0] - 0.5;
        return true;
    }
    int rootDirection(int i) const override { return i == 0 ? -1 : 0; }
};

// y = (x): x' = u with u an input the test changes between calls; event g0 = x − level.
class Input : public OdeSystem {
public:
    int size() const override { return 1; }
    bool rhs(double, const double*, double* ydot) override
    {
        ydot[0] = u;
        return true;
    }
    int rootCount() const override { return 1; }
    bool roots(double, const double* y, double* g) override
    {
        g[0] = y[0] - level;
        return true;
    }
    double u = 0;
    double level = 0.123456;
};

// The oscillator, but the right-hand side fails from t = 0.5 s on: by giving NaN,
// by returning false, or by throwing.
class Broken : public Oscillator {
public:
    enum class Mode { Nan, False, Throw };
    explicit Broken(Mode mode) : m_mode(mode) {}
    bool rhs(double t, const double* y, double* ydot) override
    {
        Oscillator::rhs(t, y, ydot);
        if (t < 0.5) return true;
        switch (m_mode) {
        case Mode::Nan: ydot[1] = std::numeric_limits<double>::quiet_NaN(); return true;
        case Mode::False: return false;
        case Mode::Throw: throw std::runtime_error("boom");
        }
        return true;
    }

private:
    Mode m_mode;
};

// y' = −λ (y − cos t) − sin t, y(0) = 1: y = cos t, stiff for large λ.
class StiffDecay : public OdeSystem {
public:
    int size() const override { return 1; }
    bool rhs(double t, const double* y, double* ydot) override
    {
        ydot[0] = -1e4 * (y[0] - std::cos(t)) - std::sin(t);
        return true;
    }
};

/// Integrates the oscillator from 0 to T, one advanceTo() per output step of dt.
double oscillatorError(const IntegratorOptions& opt, double T, double dt,
                       double* energyDrift = nullptr)
{
    Oscillator osc;
    Integrator in(osc, opt);
    double y[2] = {1.0, 0.0};
    const double e0 = Oscillator::energy(y);
    in.reset(0.0, y);
    double drift = 0;
    const int n = static_cast<int>(std::lround(T / dt));
    for (int k = 1; k <= n; ++k) {
        const AdvanceResult r = in.advanceTo(k * dt, y);
        EXPECT_EQ(r.status, AdvanceStatus::Reached) << r.message;
        drift = std::max(drift, std::abs(Oscillator::energy(y) / e0 - 1));
    }
    if (energyDrift != nullptr) *energyDrift = drift;
    return Oscillator::error(T, y);
}

// ---- accuracy -------------------------------------------------------------------

TEST(IntegratorRk4, MatchesExactSolutionOfOscillator)
{
    // 10 periods at the real-time step 1 ms, one output per step
    const double err = oscillatorError(rk4(1e-3), 10.0, 1e-3);
    EXPECT_LT(err, 1e-9);  // measured 8.2e-10 = 10⁴ steps × (ωh)⁵/120
}

TEST(IntegratorRk4, IsTheClassicFourStageMethod)
{
    // one ARKODE step equals a hand-written classic RK4 step
    const double h = 0.05;
    Oscillator osc;
    Integrator in(osc, rk4(h));
    double y[2] = {1.0, 0.0};
    in.reset(0.0, y);
    ASSERT_EQ(in.advanceTo(h, y).status, AdvanceStatus::Reached);

    auto f = [](const std::array<double, 2>& s) {
        return std::array{s[1], -kOmega * kOmega * s[0]};
    };
    const std::array<double, 2> y0{1.0, 0.0};
    const auto k1 = f(y0);
    const auto k2 = f({y0[0] + h / 2 * k1[0], y0[1] + h / 2 * k1[1]});
    const auto k3 = f({y0[0] + h / 2 * k2[0], y0[1] + h / 2 * k2[1]});
    const auto k4 = f({y0[0] + h * k3[0], y0[1] + h * k3[1]});
    for (int i = 0; i < 2; ++i) {
        const double expected = y0[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
        EXPECT_NEAR(y[i], expected, 1e-14 * std::max(1.0, std::abs(expected)));
    }
    EXPECT_EQ(in.stats().steps, 1);
}

TEST(IntegratorRk4, GlobalErrorHasOrderFour)
{
    // two periods, one advanceTo() call each; the step halves twice
    std::vector<double> errors;
    for (const double h : {1.0 / 50, 1.0 / 100, 1.0 / 200})
        errors.push_back(oscillatorError(rk4(h), 2.0, 2.0));
    for (std::size_t i = 1; i < errors.size(); ++i) {
        const double order = std::log2(errors[i - 1] / errors[i]);
        // measured errors 2.60e-5, 1.63e-6, 1.02e-7: orders 3.994, 3.998
        EXPECT_NEAR(order, 4.0, 0.5) << "h = 1/" << 50 * (1 << i);
    }
}

TEST(IntegratorAdaptive, MeetsItsToleranceOverTenPeriods)
{
    double drift = 0;
    // one output at the end, then an output every 10 ms (stop times, no restart)
    // measured: errors 9.3e-11 and 1.0e-10, energy drifts 1.9e-10 and 2.0e-10
    EXPECT_LT(oscillatorError(adaptive(1e-10, 1e-12), 10.0, 10.0, &drift), 1e-9);
    EXPECT_LT(drift, 1e-8);
    EXPECT_LT(oscillatorError(adaptive(1e-10, 1e-12), 10.0, 0.01, &drift), 1e-9);
    EXPECT_LT(drift, 1e-8);
}

TEST(IntegratorAdaptive, ConservesEnergyWhenRestartedEveryOutputStep)
{
    // what `simulate` does when inputs change every output step: reset() each 10 ms
    Oscillator osc;
    Integrator in(osc, adaptive(1e-10, 1e-12));
    double y[2] = {1.0, 0.0};
    const double e0 = Oscillator::energy(y);
    in.reset(0.0, y);
    double drift = 0;
    for (int k = 1; k <= 1000; ++k) {
        ASSERT_EQ(in.advanceTo(k * 0.01, y).status, AdvanceStatus::Reached);
        in.reset(k * 0.01, y);
        drift = std::max(drift, std::abs(Oscillator::energy(y) / e0 - 1));
    }
    EXPECT_LT(drift, 1e-8);  // measured 2.0e-10
    EXPECT_LT(Oscillator::error(10.0, y), 1e-9);  // measured 1.0e-10
}

TEST(IntegratorAdaptiveStiff, MeetsItsToleranceOverTenPeriods)
{
    // BDF is dissipative: it needs rtol 1e-12 where Dormand–Prince needs 1e-10
    double drift = 0;
    EXPECT_LT(oscillatorError(stiff(1e-12, 1e-14), 10.0, 10.0, &drift), 1e-8);  // measured 7.0e-10
    EXPECT_LT(drift, 1e-8);  // measured 1.4e-9
}

TEST(IntegratorAdaptiveStiff, TakesFarFewerStepsThanExplicitOnAStiffProblem)
{
    long evals[2] = {0, 0};
    int i = 0;
    for (const IntegratorOptions& opt : {adaptive(1e-8, 1e-10), stiff(1e-8, 1e-10)}) {
        StiffDecay sys;
        Integrator in(sys, opt);
        double y = 1.0;
        in.reset(0.0, &y);
        ASSERT_EQ(in.advanceTo(10.0, &y).status, AdvanceStatus::Reached);
        EXPECT_NEAR(y, std::cos(10.0), 1e-7) << integrationMethodName(opt.method);
        evals[i++] = in.stats().rhsEvals;
    }
    // measured: Dormand–Prince 261 853 evaluations (stability-limited), BDF 266
    EXPECT_LT(evals[1] * 100, evals[0]) << "explicit " << evals[0] << ", BDF " << evals[1];
}

// ---- stopping at tout, inputs, counters ----------------------------------------------

class IntegratorAllMethods : public ::testing::TestWithParam<IntegrationMethod> {
protected:
    IntegratorOptions options() const
    {
        IntegratorOptions o;
        o.method = GetParam();
        return o;
    }
};

INSTANTIATE_TEST_SUITE_P(Integrator, IntegratorAllMethods,
                         ::testing::Values(IntegrationMethod::Rk4Fixed, IntegrationMethod::Adaptive,
                                           IntegrationMethod::AdaptiveStiff),
                         [](const auto& info) {
                             switch (info.param) {
                             case IntegrationMethod::Rk4Fixed: return std::string("Rk4Fixed");
                             case IntegrationMethod::Adaptive: return std::string("Adaptive");
                             case IntegrationMethod::AdaptiveStiff:
                                 return std::string("AdaptiveStiff");
                             }
                             return std::string("?");
                         });

TEST_P(IntegratorAllMethods, StopsExactlyAtToutAndNeverEvaluatesBeyond)
{
    // output steps of 1.5 ms, not a multiple of RK4's 1 ms step
    Oscillator osc;
    Integrator in(osc, options());
    double y[2] = {1.0, 0.0};
    in.reset(0.0, y);
    for (int k = 1; k <= 200; ++k) {
        const double tout = k * 1.5e-3;
        const AdvanceResult r = in.advanceTo(tout, y);
        ASSERT_EQ(r.status, AdvanceStatus::Reached);
        ASSERT_EQ(r.t, tout);  // exactly
        ASSERT_EQ(in.time(), tout);
        ASSERT_LE(osc.maxRhsTime, tout);
    }
    EXPECT_LT(Oscillator::error(0.3, y), 1e-7);
}

TEST_P(IntegratorAllMethods, HonoursAnInputChangedEveryOutputStep)
{
    // x' = u, u = k mod 7 held over output step k (1 ms); with reset() at each
    // change x is the exact sum and the event x = level is found exactly
    Input sys;
    Integrator in(sys, options());
    double x = 0;
    in.reset(0.0, &x);
    double exact = 0;
    double exactRoot = -1;
    double root = -1;
    for (int k = 1; k <= 100; ++k) {
        sys.u = k % 7;
        in.reset(in.time(), &x);
        AdvanceResult r = in.advanceTo(k * 1e-3, &x);
        if (r.status == AdvanceStatus::Root) {
            EXPECT_EQ(r.rootsFired[0], +1);
            root = r.t;
            r = in.advanceTo(k * 1e-3, &x);
        }
        ASSERT_EQ(r.status, AdvanceStatus::Reached);
        if (exact < sys.level && exact + sys.u * 1e-3 >= sys.level) {
            exactRoot = (k - 1) * 1e-3 + (sys.level - exact) / sys.u;  // 0.040576 s
        }
        exact += sys.u * 1e-3;
    }
    EXPECT_NEAR(x, exact, 1e-12);
    EXPECT_NEAR(root, exactRoot, 1e-12);
}

TEST_P(IntegratorAllMethods, ToutEqualToTheCurrentTimeReturnsTheState)
{
    Oscillator osc;
    Integrator in(osc, options());
    double y[2] = {1.0, 0.0};
    in.reset(0.25, y);
    double out[2] = {7, 7};
    const AdvanceResult r = in.advanceTo(0.25, out);
    EXPECT_EQ(r.status, AdvanceStatus::Reached);
    EXPECT_EQ(r.t, 0.25);
    EXPECT_EQ(out[0], 1.0);
    EXPECT_EQ(out[1], 0.0);
}

TEST(IntegratorRk4, CountsStepsAndEvaluations)
{
    // 1 s in 1 ms outputs: 1000 steps of 4 evaluations
    Oscillator osc;
    Integrator in(osc, rk4(1e-3));
    double y[2] = {1.0, 0.0};
    in.reset(0.0, y);
    for (int k = 1; k <= 1000; ++k) in.advanceTo(k * 1e-3, y);
    EXPECT_EQ(in.stats().steps, 1000);
    EXPECT_LE(in.stats().rhsEvals, 4 * 1000 + 1);
    EXPECT_EQ(in.stats().resets, 1);
    EXPECT_EQ(in.stats().rootReturns, 0);

    // reset() every step (new inputs each step): the first stage is evaluated at the
    // new start, so 4 evaluations per step still (ARKODE needed 5)
    Integrator again(osc, rk4(1e-3));
    double z[2] = {y[0], y[1]};  // for the third run
    for (int k = 0; k < 1000; ++k) {
        again.reset(k * 1e-3, y);
        again.advanceTo((k + 1) * 1e-3, y);
    }
    EXPECT_EQ(again.stats().steps, 1000);
    EXPECT_EQ(again.stats().rhsEvals, 4 * 1000);
    EXPECT_EQ(again.stats().resets, 1000);

    // with f at the new start handed over (the simulation has it from its mode rules)
    // 3 evaluations per step, and the same solution
    Integrator handed(osc, rk4(1e-3));
    double zdot[2];
    for (int k = 0; k < 1000; ++k) {
        osc.rhs(k * 1e-3, z, zdot);
        handed.reset(k * 1e-3, z, zdot);
        handed.advanceTo((k + 1) * 1e-3, z);
    }
    EXPECT_EQ(handed.stats().rhsEvals, 3 * 1000);
    EXPECT_EQ(z[0], y[0]);
    EXPECT_EQ(z[1], y[1]);
}

// ---- events -------------------------------------------------------------------------

struct BounceRun {
    std::vector<double> floorHits;  ///< times of g0 roots
    std::vector<double> apexes;  ///< times of g1 roots
    std::vector<std::pair<double, int>> halfMeter;  ///< times and directions of g2 roots
    double worstFloorHeight = 0;  ///< |height| at the floor roots
};

/// Drops the ball from 1 m and bounces it (restitution 0.8) `bounces` times.
BounceRun bounce(const IntegratorOptions& opt, int bounces)
{
    Ball ball;
    Integrator in(ball, opt);
    double y[2] = {1.0, 0.0};
    in.reset(0.0, y);
    BounceRun run;
    while (static_cast<int>(run.floorHits.size()) < bounces) {
        const AdvanceResult r = in.advanceTo(100.0, y);
        if (r.status != AdvanceStatus::Root) {
            ADD_FAILURE() << "expected a root, got status " << static_cast<int>(r.status) << " "
                          << r.message;
            break;
        }
        EXPECT_EQ(r.rootsFired.size(), 3u);
        if (r.rootsFired[1] != 0) {
            EXPECT_EQ(r.rootsFired[1], -1);  // the velocity falls through 0 at the apex
            run.apexes.push_back(r.t);
        }
        if (r.rootsFired[2] != 0) run.halfMeter.emplace_back(r.t, r.rootsFired[2]);
        if (r.rootsFired[0] != 0) {
            EXPECT_EQ(r.rootsFired[0], -1);
            run.floorHits.push_back(r.t);
            run.worstFloorHeight = std::max(run.worstFloorHeight, std::abs(y[0]));
            // the bounce: velocity reversed and reduced, height put on the floor
            y[0] = 0;
            y[1] = -0.8 * y[1];
            in.reset(r.t, y);
        }
    }
    EXPECT_EQ(in.stats().rootReturns,
              static_cast<long>(run.floorHits.size() + run.apexes.size() + run.halfMeter.size()));
    return run;
}

/// Analytic bounce times: first hit at sqrt(2 h0 / g), then flights of 2 v_k / g.
std::vector<double> exactFloorHits(int n)
{
    std::vector<double> t{std::sqrt(2.0 / kGravity)};
    double v = kGravity * t[0];
    for (int k = 1; k < n; ++k) {
        v *= 0.8;
        t.push_back(t.back() + 2 * v / kGravity);
    }
    return t;
}

void checkBounces(const BounceRun& run, double tolerance)
{
    const std::vector<double> exact = exactFloorHits(5);
    ASSERT_EQ(run.floorHits.size(), exact.size());
    for (std::size_t k = 0; k < exact.size(); ++k)
        EXPECT_NEAR(run.floorHits[k], exact[k], tolerance) << "hit " << k;
    // an apex half-way between consecutive hits
    ASSERT_EQ(run.apexes.size(), exact.size() - 1);
    for (std::size_t k = 0; k + 1 < exact.size(); ++k) {
        EXPECT_NEAR(run.apexes[k], 0.5 * (exact[k] + exact[k + 1]), tolerance) << "apex " << k;
    }
    // 0.5 m is crossed falling at first, then rising and falling while the bounces
    // still reach it (apex height 0.64^k m: bounce 1 only)
    ASSERT_EQ(run.halfMeter.size(), 3u);
    EXPECT_EQ(run.halfMeter[0].second, -1);
    EXPECT_EQ(run.halfMeter[1].second, +1);
    EXPECT_EQ(run.halfMeter[2].second, -1);
    EXPECT_NEAR(run.halfMeter[0].first, std::sqrt(2 * 0.5 / kGravity), tolerance);
}

TEST(IntegratorAdaptive, LocatesTheFloorWithinANanosecondOverFiveBounces)
{
    const BounceRun run = bounce(adaptive(1e-10, 1e-12), 5);
    checkBounces(run, 1e-9);  // measured: worst hit 6.5e-13 s, apex 6.3e-13 s
    EXPECT_LT(run.worstFloorHeight, 1e-9);  // measured 1.9e-13 m
}

TEST(IntegratorAdaptiveStiff, LocatesTheFloorWithinANanosecondOverFiveBounces)
{
    const BounceRun run = bounce(stiff(1e-10, 1e-12), 5);
    checkBounces(run, 1e-9);  // measured: worst hit 1.4e-10 s, apex 1.2e-10 s
}

TEST(IntegratorRk4, LocatesTheFloorOverFiveBounces)
{
    // the ball's motion is quadratic in t: RK4 and its cubic Hermite interpolant
    // are exact, so only the root finder's tolerance (≈ 100 ulp of t) is left
    const BounceRun run = bounce(rk4(1e-3), 5);
    checkBounces(run, 1e-12);  // measured: worst hit 5.6e-14 s, apex 6.3e-14 s
}

TEST(IntegratorRk4, LocatesOscillatorZeroCrossingsWithinTheInterpolationError)
{
    // x = cos 2πt crosses 0 at 1/4 + k/2. The error of the root time is RK4's own
    // phase error (global, O(h⁴), growing with t) plus that of the cubic Hermite
    // interpolant the root finder searches (≤ h⁴/384·|x⁗|/|x'| ≈ 4e-12 s at 1 ms)
    for (const double h : {1e-3, 1e-2}) {
        Oscillator osc(true);
        Integrator in(osc, rk4(h));
        double y[2] = {1.0, 0.0};
        in.reset(0.0, y);
        double worst = 0;
        int k = 0;
        for (AdvanceResult r = in.advanceTo(5.0, y); r.status == AdvanceStatus::Root;
             r = in.advanceTo(5.0, y)) {
            worst = std::max(worst, std::abs(r.t - (0.25 + 0.5 * k)));
            EXPECT_EQ(r.rootsFired[0], k % 2 == 0 ? -1 : +1);
            ++k;
        }
        EXPECT_EQ(k, 10);
        EXPECT_EQ(in.time(), 5.0);
        if (h == 1e-3) {
            EXPECT_LT(worst, 1e-10) << "h = " << h;  // measured 6.2e-11 s
        } else {
            EXPECT_LT(worst, 1e-6) << "h = " << h;  // measured 6.2e-7 s: 10⁴ times more, O(h⁴)
        }
    }
}

TEST_P(IntegratorAllMethods, ContinuesAfterARootWithoutReset)
{
    // roots that only report: the solution is the same as without them
    Oscillator plain;
    Oscillator withRoots(true);
    Integrator a(plain, options());
    Integrator b(withRoots, options());
    double ya[2] = {1.0, 0.0};
    double yb[2] = {1.0, 0.0};
    a.reset(0.0, ya);
    b.reset(0.0, yb);
    int roots = 0;
    for (int k = 1; k <= 20; ++k) {
        const double tout = 0.1 * k;
        ASSERT_EQ(a.advanceTo(tout, ya).status, AdvanceStatus::Reached);
        AdvanceResult r = b.advanceTo(tout, yb);
        while (r.status == AdvanceStatus::Root) {
            ++roots;
            EXPECT_LT(std::abs(yb[0]), 1e-6);
            r = b.advanceTo(tout, yb);
        }
        ASSERT_EQ(r.status, AdvanceStatus::Reached);
        EXPECT_NEAR(yb[0], ya[0], 1e-12);
        EXPECT_NEAR(yb[1], ya[1], 1e-11);
    }
    EXPECT_EQ(roots, 4);
}

// ---- failures -------------------------------------------------------------------------

TEST_P(IntegratorAllMethods, ANanInTheRightHandSideFailsWithAMessage)
{
    // f gives NaN from t = 0.5 s on; outputs every 0.1 s
    Broken sys(Broken::Mode::Nan);
    Integrator in(sys, options());
    double y[2] = {1.0, 0.0};
    in.reset(0.0, y);
    AdvanceResult r;
    for (int k = 1; k <= 10 && r.ok(); ++k) r = in.advanceTo(0.1 * k, y);
    ASSERT_EQ(r.status, AdvanceStatus::Failed);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.message.find("RHSFUNC"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("non-finite value in component 1 (nan) at t = 0.5"), std::string::npos)
        << r.message;
    // the same, translatable: the flag and the time plain, the cause a phrase of its own
    EXPECT_EQ(r.messageText.english(), r.message);
    EXPECT_STREQ(r.messageText.context(), "Diagnostics");
    ASSERT_GE(r.messageText.args().size(), 3u);
    EXPECT_EQ(r.message.rfind(r.messageText.args()[0].value(), 0), 0u) << r.message;  // the flag's name
    EXPECT_STREQ(r.messageText.args()[2].tmpl(),
                 "the right-hand side gave a non-finite value in component %1 (%2) at t = %3 s");
    EXPECT_EQ(r.badComponent, 1);
    // time and state stay those of the last good output
    EXPECT_DOUBLE_EQ(r.t, 0.4);
    EXPECT_GT(r.failureTime, 0.49);
    EXPECT_LT(r.failureTime, 0.51);
    EXPECT_EQ(in.time(), r.t);
    EXPECT_LT(Oscillator::error(0.4, y), 1e-6);
    EXPECT_LT(in.stats().rhsEvals, 5000);  // gave up at once

    // stays failed until reset
    const AdvanceResult again = in.advanceTo(1.0, y);
    EXPECT_EQ(again.status, AdvanceStatus::Failed);
    EXPECT_EQ(again.message, r.message);
    EXPECT_EQ(again.messageText.english(), r.message);
    double y0[2] = {1.0, 0.0};
    in.reset(0.0, y0);
    EXPECT_EQ(in.advanceTo(0.25, y).status, AdvanceStatus::Reached);
}

TEST_P(IntegratorAllMethods, ARightHandSideReportingFailureFails)
{
    Broken sys(Broken::Mode::False);
    Integrator in(sys, options());
    double y[2] = {1.0, 0.0};
    in.reset(0.0, y);
    const AdvanceResult r = in.advanceTo(1.0, y);
    ASSERT_EQ(r.status, AdvanceStatus::Failed);
    EXPECT_NE(r.message.find("reported a failure"), std::string::npos) << r.message;
    EXPECT_EQ(r.messageText.english(), r.message);
    EXPECT_EQ(r.badComponent, -1);
}

TEST_P(IntegratorAllMethods, AnExceptionInTheRightHandSideDoesNotCrossSundials)
{
    Broken sys(Broken::Mode::Throw);
    Integrator in(sys, options());
    double y[2] = {1.0, 0.0};
    in.reset(0.0, y);
    const AdvanceResult r = in.advanceTo(1.0, y);
    ASSERT_EQ(r.status, AdvanceStatus::Failed);
    EXPECT_NE(r.message.find("threw"), std::string::npos) << r.message;
    EXPECT_EQ(r.messageText.english(), r.message);
}

TEST_P(IntegratorAllMethods, ANanInitialStateFails)
{
    Oscillator osc;
    Integrator in(osc, options());
    double y[2] = {std::numeric_limits<double>::quiet_NaN(), 0.0};
    in.reset(0.0, y);
    const AdvanceResult r = in.advanceTo(1.0, y);
    EXPECT_EQ(r.status, AdvanceStatus::Failed);
    EXPECT_EQ(r.badComponent, 1);
}

TEST_P(IntegratorAllMethods, TooManyStepsFails)
{
    Oscillator osc;
    IntegratorOptions o = options();
    o.maxSteps = 10;
    Integrator in(osc, o);
    double y[2] = {1.0, 0.0};
    in.reset(0.0, y);
    const AdvanceResult r = in.advanceTo(10.0, y);
    ASSERT_EQ(r.status, AdvanceStatus::Failed);
    EXPECT_NE(r.message.find("TOO_MUCH_WORK"), std::string::npos) << r.message;
    EXPECT_EQ(r.messageText.english(), r.message);  // no cause of the system's: flag, time, SUNDIALS' text
    EXPECT_EQ(r.t, 0.0);
    EXPECT_EQ(y[0], 1.0);  // not written
}

TEST(IntegratorContract, RejectsBadOptionsAndCalls)
{
    Oscillator osc;
    IntegratorOptions o = rk4(0.0);
    EXPECT_THROW(Integrator(osc, o), std::invalid_argument);
    o = rk4(std::numeric_limits<double>::quiet_NaN());
    EXPECT_THROW(Integrator(osc, o), std::invalid_argument);
    o = adaptive(-1.0);
    EXPECT_THROW(Integrator(osc, o), std::invalid_argument);
    o = adaptive(1e-8, 0.0);
    EXPECT_THROW(Integrator(osc, o), std::invalid_argument);
    o = rk4();
    o.maxSteps = 0;
    EXPECT_THROW(Integrator(osc, o), std::invalid_argument);
    o = rk4();
    o.rtol = -1;  // unused by a fixed step
    EXPECT_NO_THROW(Integrator(osc, o));

    Integrator in(osc, rk4());
    double y[2] = {1.0, 0.0};
    EXPECT_THROW(in.advanceTo(1.0, y), std::logic_error);
    in.reset(1.0, y);
    EXPECT_THROW(in.advanceTo(0.5, y), std::invalid_argument);
    EXPECT_THROW(in.advanceTo(std::numeric_limits<double>::quiet_NaN(), y), std::invalid_argument);
    EXPECT_THROW(in.reset(std::numeric_limits<double>::infinity(), y), std::invalid_argument);
}

TEST(IntegratorContract, IsMovable)
{
    Oscillator osc;
    Integrator a(osc, adaptive());
    double y[2] = {1.0, 0.0};
    a.reset(0.0, y);
    ASSERT_EQ(a.advanceTo(0.5, y).status, AdvanceStatus::Reached);
    Integrator b(std::move(a));
    ASSERT_EQ(b.advanceTo(1.0, y).status, AdvanceStatus::Reached);
    EXPECT_LT(Oscillator::error(1.0, y), 1e-9);
    EXPECT_EQ(b.size(), 2);
    EXPECT_EQ(b.rootCount(), 0);
}

}  // namespace
}  // namespace solver
