// Fluid-power drives (docs/hydraulics.md) against closed forms, at the real-time step
// (RK4, 1 ms) unless said: steady speeds with and without compensation, the oil
// spring's frequency, pressure build-up at a stop, flow sharing (POST) and starving
// (PRE) on one pump, a tiny dead volume behind a big valve, oil volume conservation
// with the valve closed, cavitation, the initial holding pressures, and the errors.

#include "../test_models.h"
#include "solver/hydraulics/orifice.h"
#include "solver/hydraulics/valve.h"
#include "solver/parse/writer.h"
#include "solver/reference/newton_euler.h"
#include "solver/dynamics/applied_forces.h"
#include "solver/dynamics/forward_dynamics.h"
#include "solver/kinematics/kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using namespace solver;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kBore = 0.1, kRod = 0.05;
const double kAreaA = kPi / 4 * kBore * kBore;
const double kAreaB = kAreaA - kPi / 4 * kRod * kRod;

/// A mass on a prismatic joint (stroke 0 … 1 m, starting at q0) lifted by a CYL (BORE
/// 0.1, ROD 0.05) fed by pump 1; `vertical`: the joint is along z (gravity loads it).
std::string liftModel(double mass, const std::string& drive, const std::string& pump, bool vertical = true,
                      double q0 = 0.3, const std::string& extra = "")
{
    const std::string r = vertical ? "0 0 1" : "1 0 0";
    return "GRAVITY 0 0 -9.81\n" + pump + "\n" + extra + "B 1 " + std::to_string(mass) +
           " 10 10 10\nC 1 T 2 LL 0 UL 1 QI " + std::to_string(q0) + " NAME \"lift\"\nB1 0 P1 0 0 0 A1 0 1 0 R1 " + r +
           "\nB2 1 P2 0 0 0 A2 0 1 0 R2 " + r + "\nD 1 CYL PUMP 1 BORE 0.1 ROD 0.05 " + drive + "\n";
}

/// Runs to time t with joint 0's command u (events collected); fails the test on error.
void run(Simulation& sim, double t, std::vector<SimulationEvent>* events = nullptr, double dt = 1e-3)
{
    std::vector<SimulationEvent> local;
    std::string error;
    while (sim.state().t < t - 1e-12) {
        if (!sim.advanceTo(std::min(t, sim.state().t + dt), events ? *events : local, error)) {
            FAIL() << error;
        }
    }
}

double rate(const Simulation& sim, int j) { return sim.state().qd[j] * sim.model().coordinateRate(j, sim.state().q[j]); }

double coordinate(const Simulation& sim, int j) { return sim.model().coordinate(j, sim.state().q[j]); }

/// The mean rates of joints 0 and 1 over the next `duration` seconds (a load bounces on
/// the oil, lightly damped, around its steady speed).
std::pair<double, double> meanRates(Simulation& sim, double duration)
{
    const double a0 = coordinate(sim, 0), b0 = sim.model().nb > 1 ? coordinate(sim, 1) : 0;
    run(sim, sim.state().t + duration);
    const double a1 = coordinate(sim, 0), b1 = sim.model().nb > 1 ? coordinate(sim, 1) : 0;
    return {(a1 - a0) / duration, (b1 - b0) / duration};
}

}  // namespace

TEST(Hydraulics, OrificeLawIsContinuousAtTheLaminarThreshold)
{
    const double pLam = 2e5;
    EXPECT_NEAR(hydraulics::orificeLaw(pLam, pLam).g, std::sqrt(pLam), 1e-9);
    EXPECT_NEAR(hydraulics::orificeLaw(pLam * (1 - 1e-12), pLam).g, std::sqrt(pLam), 1e-6);
    EXPECT_DOUBLE_EQ(hydraulics::orificeLaw(-4e6, pLam).g, -2000.0);
    EXPECT_DOUBLE_EQ(hydraulics::orificeLaw(1e5, pLam).g, 1e5 / std::sqrt(pLam));
    EXPECT_DOUBLE_EQ(hydraulics::orificeLaw(0, pLam).g, 0.0);
}

TEST(Hydraulics, InitialPressuresHoldThePoseAtRest)
{
    auto model = test::compileText(liftModel(1000, "VALVE 1e-3 DP 1e6 COMP PRE", "PUMP 1 FLOW 2e-3 PRESSURE 20e6"));
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    EXPECT_NEAR(sim.state().fluid[1], 1000 * 9.81 / kAreaA, 1e-6);
    EXPECT_EQ(sim.state().fluid[2], 0.0);
    run(sim, 0.5);
    EXPECT_NEAR(sim.model().coordinate(0, sim.state().q[0]), 0.3, 1e-9);  // held, no sag
}

TEST(Hydraulics, CompensatedSpeedIsQnUOverAWhateverTheLoad)
{
    for (double mass : {100.0, 2000.0}) {
        for (const char* comp : {"PRE", "POST"}) {
            auto model = test::compileText(liftModel(mass, std::string("VALVE 1e-3 DP 1e6 COMP ") + comp,
                                                     "PUMP 1 FLOW 5e-3 PRESSURE 20e6"));
            ASSERT_TRUE(model);
            Simulation sim(model, test::rk4(1e-3));
            sim.setCommand(0, 0.5);
            run(sim, 1.0);
            const double expected = 1e-3 * 0.5 / kAreaA;
            EXPECT_NEAR(rate(sim, 0), expected, 0.01 * expected) << mass << " kg, COMP " << comp;
        }
    }
}

TEST(Hydraulics, UncompensatedSpeedFollowsTheOrificeLaw)
{
    // v = K·u·√((A_A·p_S − F)/(A_A³ + A_B³)), F the weight
    const double qn = 1e-3, dpn = 1e6, pS = 10e6, u = 0.8;
    for (double mass : {200.0, 3000.0}) {
        auto model = test::compileText(liftModel(mass, "VALVE 1e-3 DP 1e6 COMP NONE",
                                                 "PUMP 1 FLOW 5e-3 PRESSURE 10e6", true, 0.1));
        ASSERT_TRUE(model);
        Simulation sim(model, test::rk4(1e-3));
        sim.setCommand(0, u);
        run(sim, 1.0);
        const double k = qn / std::sqrt(dpn), f = mass * 9.81;
        const double expected = k * u * std::sqrt((kAreaA * pS - f) / (std::pow(kAreaA, 3) + std::pow(kAreaB, 3)));
        EXPECT_NEAR(rate(sim, 0), expected, 0.01 * expected) << mass << " kg";
        // and the adaptive integrator (the reference) agrees
        SimulationOptions o;
        o.integrator.method = IntegrationMethod::Adaptive;
        o.integrator.rtol = 1e-8;
        Simulation ref(model, o);
        ref.setCommand(0, u);
        run(ref, 1.0, nullptr, 0.01);
        EXPECT_NEAR(rate(sim, 0), rate(ref, 0), 1e-4 * expected);
    }
}

TEST(Hydraulics, OilSpringFrequencyWithTheValveClosed)
{
    // horizontal, P0 balanced (p_A·A_A = p_B·A_B), a small push: ω = √(β(A_A²/V_A + A_B²/V_B)/m)
    const double m = 1000, beta = 1.2e9, dead = 1e-3, q0 = 0.5;
    const double pA = 3e6, pB = pA * kAreaA / kAreaB;
    std::string text = liftModel(m, "VALVE 1e-3 DP 1e6 DEAD 1e-3 1e-3 P0 " + std::to_string(pA) + " " +
                                        std::to_string(pB),
                                 "PUMP 1 FLOW 2e-3 PRESSURE 20e6", false, q0);
    text.replace(text.find("QI 0.5"), 6, "QI 0.5 VI 0.002");
    auto model = test::compileText(text);
    ASSERT_TRUE(model);
    const double vA = dead + kAreaA * q0, vB = dead + kAreaB * (1 - q0);
    const double omega = std::sqrt(beta * (kAreaA * kAreaA / vA + kAreaB * kAreaB / vB) / m);
    Simulation sim(model, test::rk4(1e-3));
    // the period from the rate's downward zero crossings over several cycles
    std::vector<double> crossings;
    double prev = rate(sim, 0);
    std::vector<SimulationEvent> events;
    std::string error;
    for (int k = 0; k < 400; ++k) {
        const double t0 = sim.state().t;
        ASSERT_TRUE(sim.advanceTo(t0 + 1e-3, events, error)) << error;
        const double v = rate(sim, 0);
        if (prev > 0 && v <= 0) crossings.push_back(t0 + 1e-3 * prev / (prev - v));
        prev = v;
    }
    ASSERT_GE(crossings.size(), 5u);
    const double period = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    EXPECT_NEAR(2 * kPi / period, omega, 0.02 * omega);
}

TEST(Hydraulics, PressureBuildsToTheSettingAgainstAStop)
{
    auto model = test::compileText(liftModel(100, "VALVE 1e-3 DP 1e6 COMP PRE", "PUMP 1 FLOW 2e-3 PRESSURE 20e6",
                                             true, 0.95));
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    sim.setCommand(0, 1);
    std::vector<SimulationEvent> events;
    run(sim, 2.0, &events);
    EXPECT_EQ(sim.state().limit[0], LimitState::AtUpper);
    EXPECT_NEAR(sim.data().pressureA[0], 20e6, 0.01 * 20e6);
    EXPECT_NEAR(sim.data().driveForce[0], 20e6 * kAreaA, 0.01 * 20e6 * kAreaA);
    bool relief = false;
    for (const SimulationEvent& e : events) relief |= e.kind == SimulationEvent::Kind::ReliefOpen && e.joint == 0;
    EXPECT_TRUE(relief) << "reaching the setting is a relief event (a tutorial penalty)";
}

namespace {

/// Two lifts side by side on one pump: joint 1 carries m1, joint 2 carries m2.
std::string twoLifts(double m1, double m2, const std::string& comp, double qmax)
{
    auto lift = [&](int id, double m, double x) {
        const std::string i = std::to_string(id);
        return "B " + i + " " + std::to_string(m) + " 10 10 10\nC " + i + " T 2 LL 0 UL 2 QI 0.2\nB1 0 P1 " +
               std::to_string(x) + " 0 0 A1 0 1 0 R1 0 0 1\nB2 " + i + " P2 0 0 0 A2 0 1 0 R2 0 0 1\nD " + i +
               " CYL PUMP 1 BORE 0.1 ROD 0.05 VALVE 1e-3 DP 1e6 COMP " + comp + "\n";
    };
    return "GRAVITY 0 0 -9.81\nPUMP 1 FLOW " + std::to_string(qmax) + " PRESSURE 20e6\n" + lift(1, m1, 0) +
           lift(2, m2, 1);
}

}  // namespace

TEST(Hydraulics, PostCompensationSharesTheFlowEqually)
{
    auto model = test::compileText(twoLifts(200, 5000, "POST", 1.2e-3));
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    sim.setCommand(0, 1);
    sim.setCommand(1, 1);
    std::vector<SimulationEvent> events;
    run(sim, 0.5, &events);
    const auto [v1, v2] = meanRates(sim, 1.0);
    const double expected = 1e-3 * (1.2e-3 / 2e-3) / kAreaA;  // each section's Qn scaled by Qmax/ΣQn
    EXPECT_NEAR(v1, expected, 0.01 * expected);
    EXPECT_NEAR(v2, expected, 0.01 * expected);
    bool saturated = false;
    for (const SimulationEvent& e : events) saturated |= e.kind == SimulationEvent::Kind::PumpSaturation && e.side > 0;
    EXPECT_TRUE(saturated);
}

TEST(Hydraulics, PreCompensationStarvesTheHighLoad)
{
    auto model = test::compileText(twoLifts(200, 5000, "PRE", 1.2e-3));
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    sim.setCommand(0, 1);
    sim.setCommand(1, 1);
    run(sim, 0.5);
    const auto [light, heavy] = meanRates(sim, 1.0);
    EXPECT_NEAR(light * kAreaA, 1e-3, 0.01 * 1e-3) << "the light load takes its full Qn";
    EXPECT_LT(heavy, 0.5 * light) << "the heavy load starves";
    EXPECT_NEAR((light + heavy) * kAreaA, 1.2e-3, 0.01 * 1.2e-3) << "the pump gives Qmax";
    EXPECT_LT(sim.data().supplyPressure[0], 20e6);
}

TEST(Hydraulics, TinyDeadVolumeBehindABigValveStaysStable)
{
    // 10 mL behind a 200 L/min valve, starting at the stroke's end (V_A = 10 mL)
    auto model = test::compileText(liftModel(50, "VALVE 3.333e-3 DP 5e5 COMP PRE TAU 0.01 DEAD 1e-5 1e-5",
                                             "PUMP 1 FLOW 5e-3 PRESSURE 20e6", true, 0.0));
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    std::vector<SimulationEvent> events;
    for (double u : {1.0, 0.0, -1.0, 0.3}) {
        sim.setCommand(0, u);
        run(sim, sim.state().t + 0.25, &events);
        for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(sim.state().fluid[k]));
        EXPECT_LT(sim.data().pressureA[0], 1.2 * 20e6);
        EXPECT_LT(sim.data().pressureB[0], 1.2 * 20e6);
    }
    // and it moves as commanded (0.3 up, compensated)
    const double v = meanRates(sim, 0.5).first;
    EXPECT_NEAR(v, 0.3 * 3.333e-3 / kAreaA, 0.01 * 0.3 * 3.333e-3 / kAreaA);
}

TEST(Hydraulics, OilVolumeIsConservedWithTheValveClosed)
{
    // closed valve: ṗ = −β·V̇/V, so p − p0 = −β·ln(V/V0) in each chamber
    const double beta = 1.2e9;
    // both chambers well above tank pressure (P0), so that neither cavitates
    const double pA = 5e6, pB = (pA * kAreaA - 400 * 9.81) / kAreaB;
    std::string text = liftModel(400, "VALVE 1e-3 DP 1e6 DEAD 2e-3 2e-3 P0 " + std::to_string(pA) + " " +
                                          std::to_string(pB),
                                 "PUMP 1 FLOW 2e-3 PRESSURE 20e6", true, 0.5);
    auto model = test::compileText(text);
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    sim.setInitial(0, 0.5, 0.05);  // a push: it bounces on the oil
    const CompiledCircuit& c = sim.model().circuits[0];
    const double pA0 = sim.state().fluid[1], pB0 = sim.state().fluid[2];
    const double vA0 = c.volumeA(0.5), vB0 = c.volumeB(0.5);
    double worst = 0;
    for (int k = 0; k < 300; ++k) {
        run(sim, sim.state().t + 1e-3);
        const double q = sim.model().coordinate(0, sim.state().q[0]);
        const double a = sim.state().fluid[1], b = sim.state().fluid[2];
        ASSERT_GT(std::min(a, b), 0.0);
        worst = std::max(worst, std::abs(a - pA0 + beta * std::log(c.volumeA(q) / vA0)) / pA0);
        worst = std::max(worst, std::abs(b - pB0 + beta * std::log(c.volumeB(q) / vB0)) / pB0);
    }
    EXPECT_LT(worst, 1e-6);
}

TEST(Hydraulics, CavitationHoldsThePressureAtZeroWithoutNaN)
{
    // a heavy load lowered with an uncompensated valve and a small pump: it runs ahead
    // of the oil, the rod side cannot be filled and cavitates
    auto model = test::compileText(liftModel(8000, "VALVE 2e-3 DP 1e6 COMP NONE TAU 0.01",
                                             "PUMP 1 FLOW 1e-4 PRESSURE 20e6", true, 0.9));
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    sim.setCommand(0, -1);
    std::vector<SimulationEvent> events;
    bool cavitated = false;
    for (int k = 0; k < 1000; ++k) {
        run(sim, sim.state().t + 1e-3, &events);
        for (int i = 0; i < 3; ++i) ASSERT_TRUE(std::isfinite(sim.state().fluid[i]));
        ASSERT_GE(sim.data().pressureA[0], 0.0);
        ASSERT_GE(sim.data().pressureB[0], 0.0);
        cavitated |= sim.data().cavitation[0] != 0;
    }
    EXPECT_TRUE(cavitated);
    bool event = false;
    for (const SimulationEvent& e : events) event |= e.kind == SimulationEvent::Kind::Cavitation && e.side > 0;
    EXPECT_TRUE(event);
}

TEST(Hydraulics, NonFinitePressuresStopWithTheDriveNamed)
{
    auto model = test::compileText(liftModel(100, "VALVE 1e-3 DP 1e6", "PUMP 1 FLOW 2e-3 PRESSURE 20e6", true, 0.3,
                                             "FLUID BULK 1e306\n"));
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    sim.setCommand(0, 1);
    std::vector<SimulationEvent> events;
    std::string error;
    bool ok = true;
    for (int k = 0; k < 100 && ok; ++k) ok = sim.advanceTo(sim.state().t + 1e-3, events, error);
    ASSERT_FALSE(ok);
    EXPECT_NE(error.find("joint 1 (lift)"), std::string::npos) << error;
    EXPECT_NE(error.find("pressures"), std::string::npos) << error;
}

TEST(Hydraulics, LoadSensingSupplyFollowsTheHighestLoad)
{
    auto model = test::compileText(liftModel(1000, "VALVE 1e-3 DP 1e6 COMP PRE",
                                             "PUMP 1 FLOW 5e-3 PRESSURE 20e6 MARGIN 2e6"));
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    run(sim, 0.1);
    EXPECT_NEAR(sim.data().supplyPressure[0], 2e6, 1) << "standby: the margin";
    sim.setCommand(0, 1);
    run(sim, 1.0);
    EXPECT_NEAR(sim.data().supplyPressure[0], sim.data().pressureA[0] + 2e6, 1e3);
    EXPECT_NEAR(rate(sim, 0), 1e-3 / kAreaA, 0.01 * 1e-3 / kAreaA);
}

TEST(Hydraulics, MotorTurnsAtQnOverDm)
{
    const std::string text = "GRAVITY 0 0 -9.81\nPUMP 1 FLOW 2e-3 PRESSURE 20e6\nB 1 500 50 50 80\n"
                             "C 1 QI 0 NAME \"slew\"\nB1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0\nB2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0\n"
                             "D 1 HMOTOR PUMP 1 DISP 1e-3 VALVE 5e-4 DP 1e6 COMP PRE VOLUME 1e-3 1e-3 FRICTION 100\n";
    auto model = test::compileText(text);
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    sim.setCommand(0, -0.6);
    run(sim, 3.0);
    EXPECT_NEAR(rate(sim, 0), -0.6 * 5e-4 / 1e-3, 0.01 * 0.3);
    // the torque balances the friction: Dm·(p_B − p_A) = c·|ω|
    EXPECT_NEAR(1e-3 * (sim.data().pressureB[0] - sim.data().pressureA[0]), 100 * 0.3, 0.02 * 30);
}

TEST(Hydraulics, BadInputIsALocatedErrorWithAHint)
{
    const std::string base = "PUMP 1 FLOW 2e-3 PRESSURE 20e6\nB 1 100 1 1 1\n";
    auto joint = [](const std::string& c) { return c + "\nB1 0 P1 0 0 0 A1 0 1 0 R1 0 0 1\nB2 1 P2 0 0 0 A2 0 1 0 R2 0 0 1\n"; };
    struct Case {
        std::string text, code;
    };
    const std::vector<Case> cases = {
        {base + joint("C 1 QI 0") + "D 1 CYL PUMP 1 BORE 0.1 ROD 0.05 VALVE 1e-3 DP 1e6\n", "cyl-on-revolute"},
        {base + joint("C 1 T 2 UL 1") + "D 1 CYL PUMP 1 BORE 0.1 ROD 0.05 VALVE 1e-3 DP 1e6\n", "cyl-without-stroke"},
        {base + joint("C 1 T 2 LL 0 UL 1") + "D 1 CYL PUMP 7 BORE 0.1 ROD 0.05 VALVE 1e-3 DP 1e6\n", "undefined-pump"},
        {base + joint("C 1 T 2 LL 0 UL 1") + "D 1 CYL PUMP 1 BORE 0.05 ROD 0.05 VALVE 1e-3 DP 1e6\n", "rod-too-large"},
        {base + joint("C 1 T 2 LL 0 UL 1") + "D 1 CYL PUMP 1 BORE 0.1 ROD 0.05 VALVE 1e-3 DP 1e6 DEAD 0 1e-3\n",
         "not-positive"},
        {base + joint("C 1 T 2 LL 0 UL 1") + "D 1 CYL PUMP 1 BORE 0.1 ROD 0.05 VALVE 1e-3 DP 1e6 TAU 0\n",
         "not-positive"},
        {base + joint("C 1 T 2 LL 0 UL 1") + "D 1 CYL PUMP 1 BORE 0.1 ROD 0.05 VALVE 1e-3 DP 1e6 VMAX 0.2\n",
         "hyd-keyword-in-fluid-drive"},
        {base + joint("C 1 T 2 LL 0 UL 1") + "D 1 CYL PUMP 1 BORE 0.1 ROD 0.05 VALVE 1e-3 DP 1e6 COMP MID\n",
         "bad-compensation"},
        {base + joint("C 1 T 2 LL 0 UL 1") + "D 1 HMOTOR PUMP 1 DISP 1e-3 VALVE 1e-3 DP 1e6\n", "hmotor-on-linear"},
        {base + joint("C 1 QI 0") + "D 1 HMOTOR PUMP 1 DISP 1e-3 VALVE 1e-3 DP 1e6 VOLUME -1 1e-3\n", "not-positive"},
        {"PUMP 1 FLOW 0 PRESSURE 20e6\n", "not-positive"},
        {"PUMP 1 FLOW 1e-3\n", "missing-option"},
        {"FLUID BULK 1e9\nFLUID LAMINAR 1e5\n", "duplicate-fluid"},
        {"PUMP 1 FLOW 1e-3 PRESSURE 1e7\nPUMP 1 FLOW 1e-3 PRESSURE 1e7\n", "duplicate-pump"},
    };
    for (const Case& c : cases) {
        const CompiledModel m = compileText(c.text, "m.pad");
        EXPECT_FALSE(m.ok()) << c.text;
        bool found = false;
        for (const Diagnostic& d : m.diagnostics) {
            if (d.code != c.code) continue;
            found = true;
            EXPECT_GT(d.pos.line, 0) << d.format();
            EXPECT_FALSE(d.hintText.english().empty()) << d.format();
        }
        EXPECT_TRUE(found) << "expected " << c.code << " for:\n" << c.text;
    }
}

TEST(Hydraulics, WrittenBackAndReadAgainIsTheSameModel)
{
    const std::string text = "FLUID BULK 1.5e9 LAMINAR 3e5\nPUMP 2 FLOW 1.11e-3 PRESSURE 25e6 MARGIN 2e6 NAME \"main\"\n" +
                             liftModel(100, "VALVE 1e-3 DP 1e6 COMP POST TAU 0.03 DEAD 1e-4 2e-4 FRICTION 50 P0 1e6 2e6",
                                       "");
    std::string t = text;
    t.replace(t.find("CYL PUMP 1"), 10, "CYL PUMP 2");
    const CompiledModel a = compileText(t, "a.pad");
    ASSERT_TRUE(a.ok());
    const std::string written = parse::writeModel(a.spec);
    const CompiledModel b = compileText(written, "a.pad");
    ASSERT_TRUE(b.ok()) << written;
    EXPECT_EQ(parse::writeModel(b.spec), written);
    const CompiledCircuit& c = b.model->circuits[0];
    EXPECT_EQ(c.comp, Compensation::Post);
    EXPECT_DOUBLE_EQ(c.deadB, 2e-4);
    EXPECT_DOUBLE_EQ(c.p0B, 2e6);
    EXPECT_DOUBLE_EQ(b.model->fluid.bulk, 1.5e9);
    EXPECT_TRUE(b.model->pumps[0].loadSensing);
}

// The fluid liner driven by every lever: at each state the thesis's Newton–Euler system
// (which writes the actuator's force out on its own) gives the same θ̈ and drive forces
// as the articulated-body dynamics, evaluated without the real-time inertia floor.
TEST(Hydraulics, TheNewtonEulerReferenceAgreesOnTheFluidLiner)
{
    const auto model = test::compileExample("liner_manipulator_fluid.pad");
    ASSERT_TRUE(model);
    Simulation sim(model, test::rk4(1e-3));
    reference::NewtonEulerSystem system(*model);
    Data data(*model);
    std::vector<SimulationEvent> events;
    std::string error;
    for (int k = 1; k <= 20; ++k) {
        for (int j = 0; j < model->nb; ++j) sim.setCommand(j, 0.8 * std::sin(0.3 * k + j));
        ASSERT_TRUE(sim.advanceTo(0.05 * k, events, error)) << error;
        const State& s = sim.state();
        forwardKinematics(*model, s, data);
        applyForces(*model, s, data);
        hybridDynamics(*model, s, data);
        const reference::NewtonEulerResult& r = system.solve(s, data.fext, data.tauExt);
        const double scale = std::max(1.0, data.qdd.lpNorm<Eigen::Infinity>());
        EXPECT_LT((r.qdd - data.qdd).lpNorm<Eigen::Infinity>() / scale, 1e-8)
            << "t = " << s.t << "\n reference " << r.qdd.transpose() << "\n padrob    " << data.qdd.transpose();
        const double fscale = std::max(1.0, data.driveForce.lpNorm<Eigen::Infinity>());
        EXPECT_LT((r.driveForce - data.driveForce).lpNorm<Eigen::Infinity>() / fscale, 1e-8) << "t = " << s.t;
    }
}
