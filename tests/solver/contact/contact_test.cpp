// Contact dynamics (CONTACT, issue 22; docs/contact.md) with the prismatic and
// revolute joints: a 4.5 t box dropped on the floor rests ≤ 2 mm in and stays; a ball
// with E 0.5 bounces to e²·h; a CYL pushing a body into a wall stops it ≤ 5 mm in while
// its pressure rises to the relief setting; solids overlapping at the start and
// NOCONTACT graphics never touch; without touching nothing changes; energy never grows
// with E 0; bad CONTACT input is a located error and the writer prints it back.

#include "solver/contact/contact_geometry.h"
#include "solver/integrate/simulation.h"
#include "solver/parse/parser.h"
#include "solver/parse/writer.h"
#include "solver/pipeline.h"
#include "tests/solver/temp_dir.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

namespace solver {
namespace {

using test::rk4;

/// Runs `sim` to time t in 1 ms calls, calling `each` after every one.
template <class F>
void run(Simulation& sim, double t, F each)
{
    std::vector<SimulationEvent> events;
    std::string error;
    while (sim.state().t < t - 1e-12) {
        ASSERT_TRUE(sim.advanceTo(std::min(t, sim.state().t + 1e-3), events, error)) << error;
        each();
    }
}

void run(Simulation& sim, double t)
{
    run(sim, t, [] {});
}

/// A box of `mass` (1 m cube) on a vertical prismatic joint, its centre at z = q0 + … ,
/// over a floor whose top is z = 0.
std::string dropModel(double mass, double q0, const std::string& contact = "CONTACT\n", const std::string& floorFlags = "")
{
    return "GRAVITY 0 0 -9.81\n" + contact + "B 1 " + std::to_string(mass) + " " + std::to_string(mass / 6) + " " +
           std::to_string(mass / 6) + " " + std::to_string(mass / 6) + "\nC 1 T 2 QI " + std::to_string(q0) +
           "\nB1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1\n"
           "G 1 B 1 BOX 1 1 1\nG 2 B 0 BOX 4 4 1 POS 0 0 -0.5" + floorFlags + "\n";
}

TEST(Contact, HeavyBoxDroppedOnTheFloorRestsWithin2mmAndStays)
{
    auto model = test::compileText(dropModel(4500, 0.6));
    ASSERT_TRUE(model);
    ASSERT_TRUE(model->contact);
    Simulation sim(model, rk4(1e-3));
    run(sim, 2.0);
    const double sink = 0.5 - sim.state().q[0];
    EXPECT_GT(sink, 0.0);
    EXPECT_LE(sink, 2e-3);
    EXPECT_LT(std::abs(sim.state().qd[0]), 1e-4);
    const double q2 = sim.state().q[0];
    run(sim, 6.0);
    EXPECT_NEAR(sim.state().q[0], q2, 1e-6);
    std::printf("4.5 t box: sinks %.4f mm\n", sink * 1e3);
}

class ContactBounce : public ::testing::TestWithParam<double> {};

TEST_P(ContactBounce, BallBouncesToRestitutionSquaredTimesHeight)
{
    const double h = GetParam(), e = 0.5;
    const std::string text = "GRAVITY 0 0 -9.81\nCONTACT E 0.5\nB 1 1 0.004 0.004 0.004\nC 1 T 2 QI " +
                             std::to_string(0.1 + h) +
                             "\nB1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1\n"
                             "G 1 B 1 SPHERE 0.1\nG 2 B 0 BOX 4 4 1 POS 0 0 -0.5\n";
    auto model = test::compileText(text);
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-3));
    bool touched = false;
    double peak = -1;
    run(sim, 1.2, [&] {
        const double z = sim.state().q[0] - 0.1;  // the ball's lowest point
        if (z < 0) touched = true;
        if (touched && z > 0) peak = std::max(peak, z);
    });
    ASSERT_TRUE(touched);
    // at the 1 ms step the bounce comes out 3 … 6 % low (docs/contact.md: 3 … 4 % low
    // at a 0.01 ms step, gravity acting during the ~10 ms impact; the rest the step)
    EXPECT_NEAR(peak, e * e * h, 0.10 * e * e * h);
    std::printf("bounce: %.4f m (e^2 h = %.4f m): %+.1f %%\n", peak, e * e * h, 100 * (peak / (e * e * h) - 1));
}

// drops whose impacts fall at different points of the 1 ms step
INSTANTIATE_TEST_SUITE_P(Contact, ContactBounce, ::testing::Values(0.5, 0.3017, 0.7543, 1.2031));

/// A 2 t body on a horizontal prismatic joint, pushed by a CYL (relief 100 bar) into a
/// wall whose face is at x = 1.
std::string wallModel(const std::string& contact)
{
    return "GRAVITY 0 0 -9.81\n" + contact +
           "PUMP 1 FLOW 1e-3 PRESSURE 10e6\nB 1 2000 100 100 100\nC 1 T 2 LL 0 UL 2 QI 0.5\n"
           "B1 0 P1 0 0 0 A1 0 1 0 R1 1 0 0\nB2 1 P2 0 0 0 A2 0 1 0 R2 1 0 0\n"
           "D 1 CYL PUMP 1 BORE 0.1 ROD 0.05 VALVE 1e-3 DP 1e6\n"
           "G 1 B 1 BOX 0.5 0.5 0.5\nG 2 B 0 BOX 1 2 2 POS 1.5 0 0\n";
}

TEST(Contact, CylinderPushingIntoAWallStopsThereWhileItsPressureReachesTheRelief)
{
    auto model = test::compileText(wallModel("CONTACT\n"));
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-3));
    sim.setCommand(0, 1.0);
    double deepest = 0;
    run(sim, 5.0, [&] { deepest = std::max(deepest, sim.state().q[0] + 0.25 - 1.0); });
    EXPECT_GT(deepest, 0.0);  // it reached the wall
    EXPECT_LE(deepest, 5e-3);
    EXPECT_LT(std::abs(sim.state().qd[0]), 1e-3);
    EXPECT_GT(sim.data().pressureA[0], 0.97 * 10e6);
    std::printf("cylinder into wall: deepest %.4f mm, p_A %.2f bar\n", deepest * 1e3, sim.data().pressureA[0] / 1e5);
    // without CONTACT the body goes through the wall
    auto free = test::compileText(wallModel(""));
    ASSERT_TRUE(free);
    Simulation through(free, rk4(1e-3));
    through.setCommand(0, 1.0);
    run(through, 5.0);
    EXPECT_GT(through.state().q[0] + 0.25 - 1.0, 0.1);
}

TEST(Contact, SolidsOverlappingAtTheStartAndNoContactGraphicsNeverTouch)
{
    // the box starts 5 cm into the floor: it falls freely through it
    auto overlapping = test::compileText(dropModel(100, 0.45));
    ASSERT_TRUE(overlapping);
    ASSERT_EQ(overlapping->contact->geometry->excluded.size(), 1u);
    const CompiledModel noted = solver::compileText(dropModel(100, 0.45), "o.pad");
    ASSERT_EQ(noted.diagnostics.size(), 1u);
    EXPECT_EQ(noted.diagnostics.begin()->code, "contact-overlap");
    EXPECT_EQ(noted.diagnostics.begin()->message, "G 1 and G 2 overlap by 50.0 mm at the initial pose: they never touch each other");
    Simulation a(overlapping, rk4(1e-3));
    run(a, 0.3);
    EXPECT_NEAR(a.state().q[0], 0.45 - 0.5 * 9.81 * 0.09, 1e-6);
    // a floor marked NOCONTACT is drawn only
    auto drawn = test::compileText(dropModel(100, 0.6, "CONTACT\n", " NOCONTACT"));
    ASSERT_TRUE(drawn);
    Simulation b(drawn, rk4(1e-3));
    run(b, 0.5);
    EXPECT_NEAR(b.state().q[0], 0.6 - 0.5 * 9.81 * 0.25, 1e-6);
    // the same floor without the flag holds it
    auto held = test::compileText(dropModel(100, 0.6));
    Simulation c(held, rk4(1e-3));
    run(c, 0.5);
    EXPECT_GT(c.state().q[0], 0.49);
}

TEST(Contact, WithoutTouchingTheTrajectoryIsTheSameToTheBit)
{
    // a pendulum swinging clear of the floor, with and without CONTACT
    auto text = [](const std::string& contact) {
        return "GRAVITY 0 0 -9.81\n" + contact +
               "B 1 10 0.1 0.1 0.1\nC 1 QI 1.0\nB1 0 P1 0 0 2 A1 1 0 0 R1 0 0 -1\nB2 1 P2 0 0 1 A2 1 0 0 R2 0 0 -1\n"
               "G 1 B 1 SPHERE 0.1\nG 2 B 0 BOX 4 4 1 POS 0 0 -0.5\n";
    };
    auto plain = test::compileText(text(""));
    auto touching = test::compileText(text("CONTACT\n"));
    ASSERT_TRUE(plain && touching);
    EXPECT_FALSE(plain->contact);
    ASSERT_TRUE(touching->contact);
    Simulation a(plain, rk4(1e-3)), b(touching, rk4(1e-3));
    run(a, 2.0);
    run(b, 2.0);
    EXPECT_EQ(a.state().q[0], b.state().q[0]);
    EXPECT_EQ(a.state().qd[0], b.state().qd[0]);
    EXPECT_TRUE(b.data().contacts.empty());
}

/// A 100 kg block on an incline of `deg` degrees (MU 0.5) with two prismatic joints:
/// joint 1 (a 1 g carrier) along the incline's normal n, joint 2 along its slope t
/// downhill; the block does not turn. Its weight's normal part rests on the contact.
std::string inclineModel(double deg)
{
    const double th = deg * std::numbers::pi / 180;
    const std::string n = std::to_string(std::sin(th)) + " 0 " + std::to_string(std::cos(th));
    const std::string t = std::to_string(std::cos(th)) + " 0 " + std::to_string(-std::sin(th));
    const std::string rot = " ROT 0 1 0 " + std::to_string(deg);
    return "GRAVITY 0 0 -9.81\nCONTACT MU 0.5\nB 1 0.001 1e-6 1e-6 1e-6\nB 2 100 4 4 4\n"
           "C 1 T 2 QI 0.25\nB1 0 P1 0 0 0 A1 0 1 0 R1 " + n + "\nB2 1 P2 0 0 0 A2 0 1 0 R2 " + n + "\n" +
           "C 2 T 2\nB1 1 P1 0 0 0 A1 0 1 0 R1 " + t + "\nB2 2 P2 0 0 0 A2 0 1 0 R2 " + t + "\n" +
           "G 1 B 2 BOX 0.5 0.5 0.5" + rot + "\nG 2 B 0 BOX 20 4 1 POS " + std::to_string(-0.5 * std::sin(th)) +
           " 0 " + std::to_string(-0.5 * std::cos(th)) + rot + "\n";
}

/// The block's place along the slope and its rate there at t0 and t1 [m, m/s].
struct Slope {
    double q0 = 0, qd0 = 0, q1 = 0, qd1 = 0;
};

Slope slide(double deg, double t0, double t1)
{
    Slope out;
    auto model = test::compileText(inclineModel(deg));
    if (!model) return out;
    Simulation sim(model, rk4(1e-3));
    const int slope = model->jointIndex(2);
    run(sim, t0);
    out.q0 = sim.state().q[slope];
    out.qd0 = sim.state().qd[slope];
    run(sim, t1);
    out.q1 = sim.state().q[slope];
    out.qd1 = sim.state().qd[slope];
    return out;
}

TEST(Contact, BlockOnAnInclineHoldsAt20DegreesWithoutCreep)
{
    const Slope s = slide(20, 0.5, 5.5);
    EXPECT_GT(s.q0, 0.0);   // the tangential spring's stretch under m·g·sin θ
    EXPECT_LT(s.q0, 1e-3);
    EXPECT_NEAR(s.q1, s.q0, 1e-7);  // no creep over 5 s
    EXPECT_LT(std::abs(s.qd1), 1e-6);
    std::printf("incline 20 deg: held %.4f mm down the slope, crept %.2e m in 5 s\n", s.q0 * 1e3, s.q1 - s.q0);
}

TEST(Contact, BlockOnAnInclineSlidesAt35DegreesAtCoulombsAcceleration)
{
    const Slope s = slide(35, 0.3, 1.3);
    const double a = s.qd1 - s.qd0;  // over 1 s
    const double th = 35 * std::numbers::pi / 180;
    const double expected = 9.81 * (std::sin(th) - 0.5 * std::cos(th));
    EXPECT_NEAR(a, expected, 0.03 * expected);
    std::printf("incline 35 deg: a = %.4f m/s^2 (g(sin - mu cos) = %.4f): %+.2f %%\n", a, expected,
                100 * (a / expected - 1));
}

/// Kinetic plus potential energy of every body (the body frames at the centres of mass).
double energy(const Model& m, const Data& d)
{
    double e = 0;
    for (int i = 0; i < m.nb; ++i) {
        const Eigen::Matrix3d R = d.X_wb[i].linear();
        e += 0.5 * m.mass[i] * d.vel[i].squaredNorm() + 0.5 * d.omega[i].dot(R * m.inertia[i] * R.transpose() * d.omega[i]);
        e -= m.mass[i] * m.gravity.dot(d.X_wb[i].translation());
    }
    return e;
}

/// A pendulum whose box strikes the floor at an angle, and slides and rocks on it.
const char* const kStrikingPendulum = "GRAVITY 0 0 -9.81\nCONTACT MU 0.3\nB 1 50 1 1 1\nC 1 QI 1.2\n"
                                      "B1 0 P1 0 0 1.15 A1 1 0 0 R1 0 0 -1\nB2 1 P2 0 0 1 A2 1 0 0 R2 0 0 -1\n"
                                      "G 1 B 1 BOX 0.3 0.3 0.3\nG 2 B 0 BOX 4 4 1 POS 0 0 -0.5\n";

TEST(Contact, EnergyNeverGrowsWithoutRestitution)
{
    auto model = test::compileText(kStrikingPendulum);
    ASSERT_TRUE(model);
    Simulation sim(model, rk4(1e-3));
    const double e0 = energy(*model, sim.data());
    double worst = -1e300;
    bool touched = false;
    run(sim, 3.0, [&] {
        worst = std::max(worst, energy(*model, sim.data()) - e0);
        touched = touched || !sim.data().contacts.empty();
    });
    EXPECT_TRUE(touched);
    EXPECT_LE(worst, 1e-6 * std::abs(e0) + 1e-6);
    EXPECT_LT(energy(*model, sim.data()), e0 - 1.0);  // the contact took energy
}

/// Microseconds per 1 ms step of `model` over 2,000 steps after 0.5 s.
double microsecondsPerStep(const std::shared_ptr<const Model>& model)
{
    Simulation sim(model, rk4(1e-3));
    run(sim, 0.5);
    std::vector<SimulationEvent> ev;
    std::string err;
    const auto t0 = std::chrono::steady_clock::now();
    const int steps = 2000;
    for (int i = 0; i < steps; ++i) EXPECT_TRUE(sim.advanceTo(sim.state().t + 1e-3, ev, err)) << err;
    return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / steps;
}

TEST(Contact, OneStepCostsLittle)
{
    auto model = test::compileText(dropModel(4500, 0.5));
    auto plain = test::compileText(dropModel(4500, 0.5, ""));
    ASSERT_TRUE(model && plain);
    const double with = microsecondsPerStep(model), without = microsecondsPerStep(plain);
    std::printf("box resting on the floor: %.2f us per 1 ms step with CONTACT (4 contacts), %.2f us without\n", with,
                without);
    EXPECT_LT(with, 200.0);  // a loose bound (debug builds, a busy machine); the figure is printed
}

/// The diagnostics' codes and positions of `text`.
std::vector<std::string> codes(const std::string& text)
{
    const CompiledModel m = solver::compileText(text, "bad.pad");
    std::vector<std::string> out;
    for (const Diagnostic& d : m.diagnostics)
        if (d.severity == Severity::Error) out.push_back(d.code + "@" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.column));
    return out;
}

TEST(Contact, BadInputIsALocatedError)
{
    const std::string body = "B 1 1 1 1 1\nC 1 T 2\nB1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1\n";
    EXPECT_EQ(codes("CONTACT MU -0.2\n" + body), std::vector<std::string>{"bad-friction@1:12"});
    EXPECT_EQ(codes("CONTACT E 1.5\n" + body), std::vector<std::string>{"bad-contact-restitution@1:11"});
    EXPECT_EQ(codes("CONTACT E -0.1\n" + body), std::vector<std::string>{"bad-contact-restitution@1:11"});
    EXPECT_EQ(codes("CONTACT\nCONTACT MU 0.3\n" + body), std::vector<std::string>{"duplicate-contact@2:1"});
    // a mesh file that is not a mesh: an error under CONTACT (at the G statement), and
    // nothing without it (a ground graphic without MASS: drawn, its inertia not needed)
    const test::TempDir dir("contact-mesh");
    dir.write("bad.stl", "this is not a mesh\n");
    const std::string mesh = "G 9 B 0 MESH \"bad.stl\"\n";
    const CompiledModel withContact = solver::compileText("CONTACT\n" + body + mesh, dir.path("m.pad"));
    ASSERT_FALSE(withContact.ok());
    bool found = false;
    for (const Diagnostic& d : withContact.diagnostics) {
        if (d.code == "contact-shape" && d.pos.line == 6) found = true;
    }
    EXPECT_TRUE(found);
    EXPECT_TRUE(solver::compileText(body + mesh, dir.path("m.pad")).ok());
}

TEST(Contact, WriterPrintsContactAndNoContactBack)
{
    Diagnostics d("x.pad");
    const ModelSpec spec = parse::parseModel("CONTACT MU 0.3 E 0.25\nB 1 1 1 1 1\nG 1 B 1 BOX 1 1 1 NOCONTACT\n", d);
    ASSERT_FALSE(d.hasErrors());
    const std::string text = parse::writeModel(spec);
    EXPECT_NE(text.find("CONTACT MU 0.3 E 0.25\n"), std::string::npos) << text;
    EXPECT_NE(text.find("BOX 1 1 1 NOCONTACT"), std::string::npos) << text;
    Diagnostics d2("y.pad");
    const ModelSpec again = parse::parseModel(text, d2);
    ASSERT_TRUE(again.contact);
    EXPECT_EQ(*again.contact->mu, 0.3);
    EXPECT_EQ(*again.contact->e, 0.25);
    EXPECT_TRUE(again.graphics[0].noContact);
    // without CONTACT the writer writes none
    const ModelSpec none = parse::parseModel("B 1 1 1 1 1\n", d2);
    EXPECT_EQ(parse::writeModel(none).find("CONTACT"), std::string::npos);
}

TEST(Contact, DampingRatioGivesTheRestitution)
{
    EXPECT_GT(dampingRatioFor(0.0), 1.0);
    EXPECT_LT(dampingRatioFor(0.9), dampingRatioFor(0.5));
    EXPECT_NEAR(dampingRatioFor(1.0), 0.0, 1e-6);
}

// A box dropped inside a TUBE (the mill's shell seen from inside) comes to rest on its
// bore: the narrow phase skips the tube only for solids clear of its walls (clearOfTube),
// never for one touching them; from the centre the box is clear, and still lands. (A
// SPHERE falls through a TUBE, before this skip too: FCL's sphere–mesh contacts; see
// docs/contact.md, "Not done yet".)
/// A 10 kg solid (graphic `solid`) dropped from the axis of a TUBE of bore 1 m: where it
/// comes to rest, and its speed there.
std::pair<double, double> restOnTheBore(const std::string& solid)
{
    auto model = test::compileText("GRAVITY 0 0 -9.81\nCONTACT\nB 1 10 0.15 0.15 0.15\nC 1 T 2 QI 0\n"
                                   "B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1\n"
                                   "G 1 B 1 " + solid + "\nG 2 B 0 TUBE 1.2 1 2 AXIS 1 0 0\n");
    EXPECT_TRUE(model);
    if (!model) return {0, 0};
    Simulation sim(model, rk4(1e-3));
    run(sim, 2.0);
    return {sim.state().q[0], sim.state().qd[0]};
}

TEST(Contact, BoxInsideATubeRestsOnItsBore)
{
    const auto [q, qd] = restOnTheBore("BOX 0.3 0.3 0.3");
    // its lower corners on the bore (radius 1, a 64-gon): the centre √(1 − 0.15²) − 0.15 down
    EXPECT_NEAR(q, -(std::sqrt(1 - 0.15 * 0.15) - 0.15), 3e-3);
    EXPECT_LT(std::abs(qd), 1e-3);
}

// FCL's sphere–triangle test gives the depth negated: a ball inside a TUBE (the mill's
// shell) fell through it, no force at all. It rests on the bore now.
TEST(Contact, SphereInsideATubeRestsOnItsBore)
{
    const auto [q, qd] = restOnTheBore("SPHERE 0.15");
    // on the bore (a 64-gon: its flat sides cos(π/64) from the axis) less its radius,
    // within the millimetres its weight presses it in
    EXPECT_NEAR(q, -(std::cos(std::numbers::pi / 64) - 0.15), 3e-3);
    EXPECT_LT(std::abs(qd), 1e-3);
}

}  // namespace
}  // namespace solver
