// Simulation: the dynamics integrated in time, with drives, relief valves and
// limits as events, checked against physics (analytic periods, energy, hand-derived
// holding forces, analytic event times) and against itself (order of convergence,
// independence of the modeler's numbering).

#include "solver/integrate/simulation.h"
#include "solver/kinematics/kinematics.h"
#include "solver/pipeline.h"

#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace solver;

namespace {

std::shared_ptr<const Model> compileModelText(const std::string& text) { return test::compileText(text, "m.pad"); }

std::shared_ptr<const Model> compileModelFile(const std::string& name) { return test::compileExample(name); }

SimulationOptions adaptive(double rtol)
{
    SimulationOptions o;
    o.integrator.method = IntegrationMethod::Adaptive;
    o.integrator.rtol = rtol;
    o.integrator.atol = rtol * 1e-2;
    return o;
}

using test::rk4;

/// Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean.
double ellipticK(double k)
{
    double a = 1, b = std::sqrt(1 - k * k);
    for (int i = 0; i < 40; ++i) {
        const double an = (a + b) / 2;
        b = std::sqrt(a * b);
        a = an;
    }
    return std::numbers::pi / (2 * a);
}

const char* kDoublePendulum = R"(
GRAVITY 0 0 -9.81
B 1 2.0 0.02 0.01 0.01 NAME "upper"
B 2 1.5 0.015 0.01 0.008 CG 0 0.05 0 NAME "lower"
C 1 QI 1.0 NAME "shoulder"
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 -1
B2 1 P2 0 0 0.5 A2 1 0 0 R2 0 0 -1
C 2 QI -0.6 VI 1.5 NAME "elbow"
B1 1 P1 0 0 -0.5 A1 1 0 0 R1 0 0 -1
B2 2 P2 0 0 0.4 A2 1 0 0 R2 0 0 -1
)";

/// The state every 0.1 s over 2 s (columns).
Eigen::MatrixXd trajectory(const std::shared_ptr<const Model>& model, const SimulationOptions& o)
{
    Simulation sim(model, o);
    std::vector<SimulationEvent> ev;
    std::string err;
    Eigen::MatrixXd y(2 * model->nb, 20);
    for (int k = 1; k <= 20; ++k) {
        EXPECT_TRUE(sim.advanceTo(0.1 * k, ev, err)) << err;
        y.col(k - 1) << sim.state().q, sim.state().qd;
    }
    return y;
}

}  // namespace

TEST(Simulation, PendulumPeriodMatchesTheLargeAmplitudeFormula)
{
    auto model = compileModelFile("pendulum.pad");
    ASSERT_TRUE(model);
    Simulation sim(model, adaptive(1e-11));
    // analytic period of a compound pendulum: I = m L² + Ixx about the pivot, amplitude 0.1 rad
    const double I = 1.0 * 1.0 + 1e-6, mgl = 1.0 * 9.81 * 1.0, theta0 = 0.1;
    const double period = 4 * std::sqrt(I / mgl) * ellipticK(std::sin(theta0 / 2));
    // times where θ̇ goes from + to − (the maxima of θ), interpolated between 1 ms samples
    std::vector<double> maxima;
    std::vector<SimulationEvent> ev;
    std::string err;
    double tPrev = 0, wPrev = sim.state().qd[0];
    for (int k = 1; k <= 4200; ++k) {
        ASSERT_TRUE(sim.advanceTo(k * 1e-3, ev, err)) << err;
        const double w = sim.state().qd[0];
        if (wPrev > 0 && w <= 0) maxima.push_back(tPrev + 1e-3 * wPrev / (wPrev - w));
        tPrev = sim.state().t;
        wPrev = w;
    }
    ASSERT_EQ(maxima.size(), 2u);
    EXPECT_NEAR(maxima[0], period, 2e-7);
    EXPECT_NEAR(maxima[1] - maxima[0], period, 2e-7);
    EXPECT_NEAR(period, 2.0073222, 1e-6);  // the figure quoted in models/pendulum.pad (+ the bob's Ixx)
}

TEST(Simulation, AdaptiveIntegratorConservesEnergyOfAPassiveModel)
{
    auto model = compileModelText(kDoublePendulum);
    ASSERT_TRUE(model);
    Simulation sim(model, adaptive(1e-11));
    const double e0 = mechanicalEnergy(*model, sim.data());
    std::vector<SimulationEvent> ev;
    std::string err;
    double worst = 0;
    for (int k = 1; k <= 100; ++k) {
        ASSERT_TRUE(sim.advanceTo(0.1 * k, ev, err)) << err;
        worst = std::max(worst, std::abs(mechanicalEnergy(*model, sim.data()) - e0));
    }
    // relative to the energy that moves: the kinetic energy scale of the motion
    const double scale = std::abs(e0 - (-9.81 * (2.0 * -0.5 + 1.5 * -1.4)));
    EXPECT_LT(worst / scale, 1e-8) << "drift " << worst << " J of " << scale << " J";
    EXPECT_TRUE(ev.empty());
}

TEST(Simulation, Rk4ConvergesWithOrderFour)
{
    // the double pendulum, swinging moderately (the asymptotic range starts near h = 5 ms)
    std::string text = kDoublePendulum;
    text.replace(text.find("QI 1.0"), 6, "QI 0.3");
    text.replace(text.find("QI -0.6 VI 1.5"), 14, "QI -0.2");
    auto model = compileModelText(text);
    ASSERT_TRUE(model);
    const Eigen::MatrixXd ref = trajectory(model, adaptive(1e-13));
    std::vector<double> errors;
    for (double h : {0.005, 0.0025, 0.00125, 0.000625}) {
        errors.push_back((trajectory(model, rk4(h)) - ref).cwiseAbs().maxCoeff());
    }
    // measured: 1.78e-6, 1.13e-7, 7.15e-9, 4.52e-10 (orders 3.97, 3.99, 3.98)
    for (std::size_t k = 1; k < errors.size(); ++k) {
        const double order = std::log2(errors[k - 1] / errors[k]);
        EXPECT_GT(order, 3.8) << "h = " << 0.005 / (1 << k);
        EXPECT_LT(order, 4.2) << "h = " << 0.005 / (1 << k);
    }
}

TEST(Simulation, PrismaticJointUnderGravityAndItsLimitTime)
{
    auto model = compileModelFile("incline_slider.pad");
    ASSERT_TRUE(model);
    Simulation sim(model, adaptive(1e-12));
    std::vector<SimulationEvent> ev;
    std::string err;
    // g sin 30°, with the slope exactly as written (R1 0.8660254 0 -0.5)
    const double a = 9.81 * 0.5 / std::hypot(0.8660254, 0.5);
    ASSERT_TRUE(sim.advanceTo(0.5, ev, err)) << err;
    EXPECT_NEAR(sim.state().q[0], 0.5 * a * 0.25, 1e-10);
    EXPECT_NEAR(sim.state().qd[0], a * 0.5, 1e-10);
    ASSERT_TRUE(sim.advanceTo(1.5, ev, err)) << err;
    ASSERT_EQ(ev.size(), 1u);
    EXPECT_EQ(ev[0].kind, SimulationEvent::Kind::LimitHit);
    EXPECT_EQ(ev[0].side, +1);
    EXPECT_NEAR(ev[0].t, std::sqrt(2 * 2.0 / a), 1e-9);
    // inelastic stop: it stays there, the stop carrying the weight's component along the slope
    EXPECT_DOUBLE_EQ(sim.state().q[0], 2.0);
    EXPECT_EQ(sim.state().qd[0], 0.0);
    EXPECT_EQ(sim.state().limit[0], LimitState::AtUpper);
    EXPECT_NEAR(sim.data().limitForce[0], -10.0 * a, 1e-9);
}

TEST(Simulation, HydraulicCylinderLiftsAtItsSpeedAndItsReliefValveStallsAnOverload)
{
    // a 100 kg load on a vertical cylinder: 981 N to hold
    const std::string text = R"(
B 1 100 1 1 1
C 1 T 2 LL 0 UL 1 QI 0.2
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1
)";
    {
        auto model = compileModelText(text + "D 1 HYD VMAX 0.1 FMAX 2000\n");
        Simulation sim(model, rk4(1e-3));
        sim.setCommand(0, 1.0);
        std::vector<SimulationEvent> ev;
        std::string err;
        ASSERT_TRUE(sim.advanceTo(1.0, ev, err)) << err;
        EXPECT_TRUE(ev.empty());
        EXPECT_NEAR(sim.state().q[0], 0.3, 1e-12);
        EXPECT_NEAR(sim.data().driveForce[0], 981.0, 1e-9);
        // valve closed: it holds
        sim.setCommand(0, 0.0);
        ASSERT_TRUE(sim.advanceTo(2.0, ev, err)) << err;
        EXPECT_NEAR(sim.state().q[0], 0.3, 1e-12);
    }
    {
        auto model = compileModelText(text + "D 1 HYD VMAX 0.1 FMAX 500\n");
        Simulation sim(model, adaptive(1e-10));
        sim.setCommand(0, 1.0);
        std::vector<SimulationEvent> ev;
        std::string err;
        ASSERT_TRUE(sim.advanceTo(0.1, ev, err)) << err;
        ASSERT_FALSE(ev.empty());
        EXPECT_EQ(ev[0].kind, SimulationEvent::Kind::ReliefOpen);
        EXPECT_EQ(ev[0].t, 0.0);
        EXPECT_EQ(ev[0].side, +1);
        EXPECT_EQ(sim.state().relief[0], ReliefState::OpenExtending);
        // the load wins: it sinks with a = (500 − 981) / 100
        const double a = (500.0 - 981.0) / 100.0;
        EXPECT_NEAR(sim.state().q[0], 0.2 + 0.5 * a * 0.01, 1e-9);
        EXPECT_NEAR(sim.data().driveForce[0], 500.0, 1e-9);
    }
}

TEST(Simulation, LinerManipulatorHoldsStillWithEveryValveClosed)
{
    auto model = compileModelFile("liner_manipulator.pad");
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-3));
    const Eigen::VectorXd q0 = sim.state().q;
    const double f2 = sim.data().driveForce[model->jointIndex(2)];
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(2.0, ev, err)) << err;
    EXPECT_LT((sim.state().q - q0).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT(sim.state().qd.cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(sim.data().driveForce[model->jointIndex(2)], f2, 1e-6 * std::abs(f2));
    EXPECT_GT(f2, 0.0);  // the boom cylinder pushes
}

TEST(Simulation, OutputDoesNotDependOnTheModelersNumbering)
{
    std::string renumbered = kDoublePendulum;
    // bodies 1, 2 → 12, 5 and joints 1, 2 → 9, 4, statements in another order
    renumbered = R"(
GRAVITY 0 0 -9.81
C 4 QI -0.6 VI 1.5 NAME "elbow"
B1 12 P1 0 0 -0.5 A1 1 0 0 R1 0 0 -1
B2 5 P2 0 0 0.4 A2 1 0 0 R2 0 0 -1
B 5 1.5 0.015 0.01 0.008 CG 0 0.05 0 NAME "lower"
C 9 QI 1.0 NAME "shoulder"
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 -1
B2 12 P2 0 0 0.5 A2 1 0 0 R2 0 0 -1
B 12 2.0 0.02 0.01 0.01 NAME "upper"
)";
    auto a = compileModelText(kDoublePendulum);
    auto b = compileModelText(renumbered);
    ASSERT_TRUE(a && b);
    Simulation sa(a, rk4(1e-3)), sb(b, rk4(1e-3));
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sa.advanceTo(1.0, ev, err));
    ASSERT_TRUE(sb.advanceTo(1.0, ev, err));
    const int s1 = a->jointIndex(1), e1 = a->jointIndex(2), s2 = b->jointIndex(9), e2 = b->jointIndex(4);
    EXPECT_EQ(sa.state().q[s1], sb.state().q[s2]);
    EXPECT_EQ(sa.state().q[e1], sb.state().q[e2]);
    EXPECT_EQ(sa.state().qd[e1], sb.state().qd[e2]);
}

TEST(Simulation, ADivergingModelStopsWithTheTimeAndTheJoint)
{
    // a stiff spring integrated with a far too long step blows up
    auto model = compileModelText(R"(
B 1 1 0.1 0.1 0.1
C 7 T 2 QI 0.1 NAME "slider"
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1
F 1 SPRING B1 0 P1 0 0 -1 B2 1 P2 0 0 0 K 1e12 L0 1
)");
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(0.01));
    std::vector<SimulationEvent> ev;
    std::string err;
    EXPECT_FALSE(sim.advanceTo(100.0, ev, err));
    EXPECT_NE(err.find("the simulation failed at t = "), std::string::npos) << err;
    EXPECT_NE(err.find("joint 7 (slider)"), std::string::npos) << err;
    // the likely cause: the spring, its period against the step, and what to do
    EXPECT_NE(err.find("the likely cause: spring force 1 (K = 1e+12 N/m on a body of 1 kg, a natural period of 6.28319e-06 s) "
                       "is too stiff for the step of 0.01 s; use a step under 5e-07 s or the adaptive integrator"),
              std::string::npos)
        << err;
}

TEST(Simulation, ADivergingModelWithoutASpringNamesTheUsualCauses)
{
    // a damper far too hard for the step (no stiffness to blame): the usual suspects and
    // the remedies
    auto model = compileModelText(R"(
B 1 1 0.1 0.1 0.1
C 3 T 2 QI 0.1 NAME "arm"
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1
F 1 SPRING B1 0 P1 0 0 -1 B2 1 P2 0 0 0 K 0 L0 1 C 1e9
)");
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(0.01));
    std::vector<SimulationEvent> ev;
    std::string err;
    sim.setInitial(0, 0.1, 1.0);
    EXPECT_FALSE(sim.advanceTo(100.0, ev, err));
    EXPECT_NE(err.find("joint 3 (arm)"), std::string::npos) << err;
    EXPECT_NE(err.find("the likely cause: a spring, force or hydraulic drive too stiff for the step of 0.01 s"), std::string::npos)
        << err;
}

TEST(Simulation, AFailureCarriesATranslatableTextOfItsEnglishMessage)
{
    // the diverging slider above: the simulation's sentence (time, joint) holds the
    // integrator's cause as a phrase of its own
    auto model = compileModelText(R"(
B 1 1 0.1 0.1 0.1
C 7 T 2 QI 0.1 NAME "slider"
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1
F 1 SPRING B1 0 P1 0 0 -1 B2 1 P2 0 0 0 K 1e12 L0 1
)");
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(0.01));
    std::vector<SimulationEvent> ev;
    std::string err;
    Text text;
    EXPECT_FALSE(sim.advanceTo(100.0, ev, err, &text));
    EXPECT_EQ(text.english(), err);
    EXPECT_STREQ(text.context(), "Diagnostics");
    EXPECT_STREQ(text.tmpl(), "the simulation failed at t = %1 s, joint %2 (%3): %4; %5");
    ASSERT_EQ(text.args().size(), 5u);
    EXPECT_EQ(text.args()[1].value(), "7");
    EXPECT_EQ(text.args()[2].value(), "slider");
    const Text& cause = text.args()[3];
    ASSERT_NE(cause.tmpl(), nullptr);  // a phrase, not a plain value
    EXPECT_STREQ(cause.context(), "Diagnostics");
    EXPECT_NE(err.find(": " + cause.english() + "; "), std::string::npos) << err;
    const Text& likely = text.args()[4];
    ASSERT_NE(likely.tmpl(), nullptr);
    EXPECT_EQ(err.substr(err.size() - likely.english().size()), likely.english());
    // every template translated, every plain value kept
    const std::string marked = text.render([](const char*, const char* tmpl) { return "<" + std::string(tmpl) + ">"; });
    EXPECT_EQ(marked.rfind("<the simulation failed at t = ", 0), 0u) << marked;
    EXPECT_NE(marked.find("joint 7 (slider): <"), std::string::npos) << marked;
    // a failed simulation keeps failing (the integrator stays failed) with the same text
    std::string again;
    Text againText;
    EXPECT_FALSE(sim.advanceTo(100.0, ev, again, &againText));
    EXPECT_EQ(againText.english(), again);
}

TEST(Simulation, RestitutionBouncesAJointOffItsLimit)
{
    // a block falling 0.5 m onto the lower stop of a vertical slider
    auto model = compileModelText(R"(
RESTITUTION 0.5
B 1 2 0.1 0.1 0.1
C 1 T 2 LL 0 QI 0.5
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1
)");
    ASSERT_TRUE(model);
    EXPECT_EQ(model->restitution, 0.5);
    Simulation sim(model, adaptive(1e-12));
    std::vector<SimulationEvent> ev;
    std::string err;
    const double tHit = std::sqrt(2 * 0.5 / 9.81), vHit = 9.81 * tHit;
    ASSERT_TRUE(sim.advanceTo(tHit + 0.01, ev, err)) << err;
    ASSERT_EQ(ev.size(), 1u);
    EXPECT_NEAR(ev[0].t, tHit, 1e-9);
    // it leaves the stop upwards at half the speed it hit it with, and stays free
    EXPECT_EQ(sim.state().limit[0], LimitState::Free);
    EXPECT_NEAR(sim.state().qd[0], 0.5 * vHit - 9.81 * 0.01, 1e-8);
    // the next hit comes after a flight of 2 · (v/2) / g
    ASSERT_TRUE(sim.advanceTo(tHit + vHit / 9.81 + 0.001, ev, err)) << err;
    ASSERT_EQ(ev.size(), 2u);
    EXPECT_NEAR(ev[1].t, tHit + vHit / 9.81, 1e-8);
}

TEST(Simulation, AJointLeavesItsLimitWhenTheDynamicsPullItAway)
{
    // a 100 kg block resting on the lower stop of a vertical slider; a force ramping
    // up from 0 to 2000 N over 1 s lifts it off when it exceeds the weight, at t = 0.4905 s
    auto model = compileModelText(R"(
B 1 100 1 1 1
C 1 T 2 LL 0 QI 0
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1
F 1 POINT B 1 P 0 0 0 DIR 0 0 1 MAG TABLE T 0 0 1 2000
)");
    ASSERT_TRUE(model);
    Simulation sim(model, adaptive(1e-12));
    EXPECT_EQ(sim.state().limit[0], LimitState::AtLower);
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(0.3, ev, err)) << err;
    EXPECT_TRUE(ev.empty());
    EXPECT_NEAR(sim.data().limitForce[0], 981.0 - 600.0, 1e-9);  // the stop carries the rest of the weight
    EXPECT_EQ(sim.state().q[0], 0.0);
    ASSERT_TRUE(sim.advanceTo(0.6, ev, err)) << err;
    ASSERT_EQ(ev.size(), 1u);
    EXPECT_EQ(ev[0].kind, SimulationEvent::Kind::LimitLeave);
    EXPECT_EQ(ev[0].side, -1);
    EXPECT_NEAR(ev[0].t, 0.4905, 1e-9);
    EXPECT_GT(sim.state().q[0], 0.0);
}

TEST(Simulation, AHydraulicCylinderStallsAtItsLimitAndLeavesItWhenCommandedBack)
{
    auto model = compileModelText(R"(
B 1 100 1 1 1
C 1 T 2 LL 0 UL 0.25 QI 0.2
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1
D 1 HYD VMAX 0.1 FMAX 5000
)");
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-3));
    sim.setCommand(0, 1.0);
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(1.0, ev, err)) << err;
    ASSERT_EQ(ev.size(), 1u);
    EXPECT_EQ(ev[0].kind, SimulationEvent::Kind::LimitHit);
    EXPECT_NEAR(ev[0].t, 0.5, 1e-12);  // 0.05 m at 0.1 m/s
    EXPECT_EQ(sim.state().q[0], 0.25);
    EXPECT_EQ(sim.state().qd[0], 0.0);
    EXPECT_NEAR(sim.data().driveForce[0], 981.0, 1e-9);  // the cylinder still carries the load
    // pushing further changes nothing; commanding back leaves the stop at once
    sim.setCommand(0, -0.5);
    ev.clear();
    ASSERT_TRUE(sim.advanceTo(1.2, ev, err)) << err;
    ASSERT_EQ(ev.size(), 1u);
    EXPECT_EQ(ev[0].kind, SimulationEvent::Kind::LimitLeave);
    EXPECT_EQ(ev[0].t, 1.0);
    EXPECT_NEAR(sim.state().q[0], 0.25 - 0.05 * 0.2, 1e-12);
}

TEST(Simulation, AReliefValveOpensUnderAnOverloadAndClosesWhenItPasses)
{
    // lifting 100 kg at 0.1 m/s needs 981 N; an extra 500 N pushes down from 0.2 s to
    // 0.4 s, beyond the 1200 N relief setting: the valve opens, the load sinks, and
    // when the push ends the cylinder accelerates it back to its commanded rate
    auto model = compileModelText(R"(
B 1 100 1 1 1
C 1 T 2 LL 0 UL 2 QI 0.5
B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1
B2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1
D 1 HYD VMAX 0.1 FMAX 1200
F 1 POINT B 1 P 0 0 0 DIR 0 0 -1 MAG TABLE T 0.19999 0 0.2 500 0.4 500 0.40001 0
)");
    ASSERT_TRUE(model);
    Simulation sim(model, adaptive(1e-11));
    sim.setCommand(0, 1.0);
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(1.0, ev, err)) << err;
    ASSERT_EQ(ev.size(), 2u);
    EXPECT_EQ(ev[0].kind, SimulationEvent::Kind::ReliefOpen);
    EXPECT_EQ(ev[0].side, +1);
    EXPECT_DOUBLE_EQ(ev[0].value, 1200.0);
    // the push reaches 1200 − 981 = 219 N on its ramp from 0.19999 s
    EXPECT_NEAR(ev[0].t, 0.19999 + 1e-5 * 219.0 / 500.0, 1e-9);
    EXPECT_EQ(ev[1].kind, SimulationEvent::Kind::ReliefClose);
    EXPECT_GT(ev[1].t, 0.4);
    EXPECT_EQ(sim.state().relief[0], ReliefState::Closed);
    EXPECT_NEAR(sim.state().qd[0], 0.1, 1e-12);
    // while open, the cylinder pushed with 1200 N: net (1200 − 981 − 500) / 100 m/s² down
    // for 0.2 s, then (1200 − 981)/100 up until back at 0.1 m/s
    const double down = (1200.0 - 981.0 - 500.0) / 100.0, up = (1200.0 - 981.0) / 100.0;
    const double vLow = 0.1 + down * 0.2;  // at 0.4 s (ramps neglected: 1e-5 s)
    EXPECT_NEAR(ev[1].t, 0.4 + (0.1 - vLow) / up, 1e-4);
}

TEST(Simulation, ASuddenHydraulicStartSwingsAHangingLoadInsteadOfJerkingIt)
{
    // a hydraulic carriage on a horizontal rail carries a 1 m pendulum with a point-like
    // 10 kg bob; when the carriage starts at 0.2 m/s at once, the rod (which can only
    // pull along itself) leaves the bob's horizontal velocity at 0: θ̇ = −0.2 / 1 rad/s
    auto model = compileModelText(R"(
B 1 50 1 1 1 NAME "carriage"
B 2 10 1e-9 1e-9 1e-9 NAME "bob"
C 1 T 2 QI 0
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 0 A2 0 0 1 R2 0 1 0
C 2 QI 0
B1 1 P1 0 0 0 A1 1 0 0 R1 0 0 -1
B2 2 P2 0 0 1 A2 1 0 0 R2 0 0 -1
D 1 HYD VMAX 0.2
)");
    ASSERT_TRUE(model);
    Simulation sim(model, adaptive(1e-12));
    sim.setCommand(model->jointIndex(1), 1.0);
    std::vector<SimulationEvent> ev;
    std::string err;
    ASSERT_TRUE(sim.advanceTo(1e-9, ev, err)) << err;
    const int rail = model->jointIndex(1), swing = model->jointIndex(2);
    EXPECT_NEAR(sim.state().qd[rail], 0.2, 1e-15);
    // the bob's world velocity stays 0: the carriage's 0.2 m/s and the swing's L·θ̇ cancel
    const Eigen::Vector3d vBob = comVelocity(*model, sim.data(), model->bodyIndex(2));
    EXPECT_NEAR(vBob.norm(), 0.0, 1e-8);
    EXPECT_NEAR(std::abs(sim.state().qd[swing]), 0.2, 1e-8);
}
