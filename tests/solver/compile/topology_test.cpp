#include "solver/compile/topology.h"

#include "solver/kinematics/joint_geometry.h"
#include "solver/compile/compile.h"
#include "solver/pipeline.h"
#include "tests/solver/model_texts.h"
#include "tests/solver/spec_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace solver {
namespace {

using Eigen::Vector3d;
using test::side;
constexpr double kPi = std::numbers::pi;

// the topology as compiled (the graph, the loops closed at QI on the compiled model);
// nullopt with errors
std::optional<Topology> analyze(const ModelSpec& spec, Diagnostics& diags)
{
    return compileModel(spec, diags).topology;
}

// the diagnostics with a code
std::vector<Diagnostic> withCode(const Diagnostics& diags, const std::string& code)
{
    std::vector<Diagnostic> out;
    for (const Diagnostic& d : diags) {
        if (d.code == code) out.push_back(d);
    }
    return out;
}

std::string listing(const Diagnostics& diags)
{
    std::string out;
    for (const Diagnostic& d : diags) out += d.format() + "\n";
    return out;
}

// exactly one diagnostic with this code; checks severity and position
Diagnostic single(const CompiledModel& m, const std::string& code, Severity severity, int line,
                  int column)
{
    const auto found = withCode(m.diagnostics, code);
    EXPECT_EQ(found.size(), 1u) << listing(m.diagnostics);
    if (found.empty()) return {};
    EXPECT_EQ(found[0].severity, severity) << found[0].format();
    EXPECT_EQ(found[0].pos, (SourcePos{line, column})) << found[0].format();
    EXPECT_EQ(found[0].file, "m.pad");
    return found[0];
}

// ------------------------------------------------------------------ Appendix A

TEST(Topology, LinerManipulatorAppendixA)
{
    const CompiledModel m = compileText(solver::test::appendixACorrected(), "m.pad");
    ASSERT_TRUE(m.ok()) << listing(m.diagnostics);
    ASSERT_TRUE(m.topology.has_value());
    const Topology& t = *m.topology;

    // bodies: ground, then 1..9 (the written B 0 is ground)
    EXPECT_EQ(t.bodyIds, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
    EXPECT_EQ(t.dof, 9);
    EXPECT_TRUE(t.loopJoints.empty());
    EXPECT_TRUE(t.dependent.empty());
    EXPECT_EQ(t.independent, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(t.treeJoints, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(t.closureRank, 0);
    EXPECT_NEAR(t.totalMass, 1314.0, 1e-9);

    // a serial arm up to body 6, which carries the piston and both claws
    EXPECT_EQ(t.parentBody, (std::vector<int>{-1, 0, 1, 2, 3, 4, 5, 6, 6, 6}));
    EXPECT_EQ(t.parentJoint, (std::vector<int>{-1, 0, 1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(t.chains, (std::vector<std::vector<int>>{{0, 1, 2, 3, 4, 5}, {6}, {7}, {8}}));
    EXPECT_TRUE(std::none_of(t.reversed.begin(), t.reversed.end(), [](bool r) { return r; }));

    // initial coordinates: as written; T 1 lengths give angles on the branch nearest 0
    ASSERT_EQ(t.q0.size(), 9u);
    EXPECT_NEAR(t.q0[1], 1.464, 1e-12);
    EXPECT_NEAR(t.theta0[1], std::asin((1.464 * 1.464 - 2.1425) / 0.58), 1e-12);
    EXPECT_NEAR(t.q0[4], 0.412, 1e-12);
    EXPECT_NEAR(t.theta0[4], -0.00284176, 1e-8);
    EXPECT_NEAR(t.q0[6], 0.075, 0);

    // no T 1 complaint: every length is reachable and both strokes are limited
    for (const Diagnostic& d : m.diagnostics)
        EXPECT_EQ(d.code.rfind("actuator-", 0), std::string::npos) << d.format();
}

// ------------------------------------------------------------------ loops

// Planar four-bar, lengths 1 (crank), 2 (coupler), 1.5 (rocker), ground pivots 2 m apart.
// Joint 4 closes the loop; the crank angle QI = 60° is the degree of freedom.
const char* const kFourBar = R"(B 1 1 0.1 0.1 0.1 CG 0.5 0 0 NAME "crank"
B 2 2 0.1 0.1 0.1 CG 1 0 0
B 3 1.5 0.1 0.1 0.1 CG 0.75 0 0
C 1 QI 1.0471975511965976 NAME "crank"
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2 QI -0.5
B1 1 P1 1 0 0 A1 0 0 1 R1 1 0 0
B2 2 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 3 QI -2.5
B1 2 P1 2 0 0 A1 0 0 1 R1 1 0 0
B2 3 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 4
B1 3 P1 1.5 0 0 A1 0 0 1 R1 1 0 0
B2 0 P2 2 0 0 A2 0 0 1 R2 1 0 0
)";

// The four-bar's coupler point B by hand: crank tip A = (cos 60°, sin 60°), D = (2, 0);
// B is at 2 m from A and 1.5 m from D, on the side the QI guesses point to (above AD).
struct FourBarByHand {
    double coupler;  // joint 2: coupler angle relative to the crank [rad]
    double rocker;  // joint 3: rocker angle relative to the coupler [rad]
    double closing;  // joint 4: angle from the rocker's R to ground's R [rad]
};

FourBarByHand fourBarByHand(double crank, const Eigen::Vector2d& d = Eigen::Vector2d(2, 0),
                            double side = 1)
{
    const Eigen::Vector2d a(std::cos(crank), std::sin(crank));
    const double lAD = (d - a).norm();
    const Eigen::Vector2d u = (d - a) / lAD, n(-u.y(), u.x());
    const double x = (2.0 * 2.0 - 1.5 * 1.5 + lAD * lAD) / (2 * lAD);
    const Eigen::Vector2d b = a + x * u + side * std::sqrt(4.0 - x * x) * n;
    const double coupler = std::atan2(b.y() - a.y(), b.x() - a.x());
    const double rocker = std::atan2(d.y() - b.y(), d.x() - b.x());
    return {coupler - crank, rocker - coupler, -rocker};
}

TEST(Topology, FourBarTreeCutJointAndDependentAngles)
{
    const CompiledModel m = compileText(kFourBar, "m.pad");
    ASSERT_TRUE(m.ok()) << listing(m.diagnostics);
    const Topology& t = *m.topology;

    EXPECT_EQ(t.treeJoints, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(t.loopJoints, (std::vector<int>{3}));
    EXPECT_EQ(t.chains, (std::vector<std::vector<int>>{{0, 1, 2}}));
    // 5 closure equations, planar: rank 2; the later, undriven joints are dependent
    EXPECT_EQ(t.closureRank, 2);
    EXPECT_EQ(t.dof, 1);
    EXPECT_EQ(t.independent, (std::vector<int>{0}));
    EXPECT_EQ(t.dependent, (std::vector<int>{1, 2}));

    const FourBarByHand h = fourBarByHand(kPi / 3);
    EXPECT_NEAR(h.coupler, -0.7554323113484815, 1e-12);  // the numbers, for the record
    EXPECT_NEAR(h.rocker, -2.143214898887717, 1e-12);
    EXPECT_NEAR(t.q0[0], kPi / 3, 1e-15);
    EXPECT_NEAR(t.q0[1], h.coupler, 1e-9);
    EXPECT_NEAR(t.q0[2], h.rocker, 1e-9);
    EXPECT_NEAR(t.q0[3], h.closing, 1e-9);
    EXPECT_NEAR(t.totalMass, 4.5, 1e-12);
}

TEST(Topology, FourBarAssemblesFromAStraightGuess)
{
    // no QI for the dependent joints: the guess (0, 0) is a straight, singular chain; the rank is
    // still 2 and the loop still closes, in one of its two assembly modes
    std::string text = kFourBar;
    text.replace(text.find("C 2 QI -0.5"), 11, "C 2");
    text.replace(text.find("C 3 QI -2.5"), 11, "C 3");
    const CompiledModel m = compileText(text, "m.pad");
    ASSERT_TRUE(m.ok()) << listing(m.diagnostics);
    const Topology& t = *m.topology;
    EXPECT_EQ(t.closureRank, 2);
    EXPECT_EQ(t.dof, 1);
    EXPECT_EQ(t.dependent, (std::vector<int>{1, 2}));
    const FourBarByHand up = fourBarByHand(kPi / 3), down = fourBarByHand(kPi / 3, {2, 0}, -1);
    const bool isUp = std::abs(wrapAngle(t.q0[1] - up.coupler)) < 1e-9 &&
                      std::abs(wrapAngle(t.q0[2] - up.rocker)) < 1e-9;
    const bool isDown = std::abs(wrapAngle(t.q0[1] - down.coupler)) < 1e-9 &&
                        std::abs(wrapAngle(t.q0[2] - down.rocker)) < 1e-9;
    EXPECT_TRUE(isUp || isDown) << t.q0[1] << " " << t.q0[2];
    // revolute solutions are reported within half a turn of their guess
    EXPECT_LE(std::abs(t.q0[1]), kPi);
    EXPECT_LE(std::abs(t.q0[2]), kPi);
}

TEST(Topology, TwoLoopsOnOneCrank)
{
    // a second coupler and rocker, mirrored, from the crank tip to a ground pivot at (−2, 0)
    const std::string text = std::string(kFourBar) + R"(B 4 2 0.1 0.1 0.1 CG 1 0 0
B 5 1.5 0.1 0.1 0.1 CG 0.75 0 0
C 5 QI 1.8
B1 1 P1 1 0 0 A1 0 0 1 R1 1 0 0
B2 4 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 6 QI 1.4
B1 4 P1 2 0 0 A1 0 0 1 R1 1 0 0
B2 5 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 7
B1 5 P1 1.5 0 0 A1 0 0 1 R1 1 0 0
B2 0 P2 -2 0 0 A2 0 0 1 R2 1 0 0
)";
    const CompiledModel m = compileText(text, "m.pad");
    ASSERT_TRUE(m.ok()) << listing(m.diagnostics);
    const Topology& t = *m.topology;
    EXPECT_EQ(t.treeJoints, (std::vector<int>{0, 1, 4, 2, 5}));
    EXPECT_EQ(t.loopJoints, (std::vector<int>{3, 6}));
    EXPECT_EQ(t.chains, (std::vector<std::vector<int>>{{0}, {1, 2}, {4, 5}}));
    EXPECT_EQ(t.closureRank, 4);
    EXPECT_EQ(t.dof, 1);
    EXPECT_EQ(t.independent, (std::vector<int>{0}));
    EXPECT_EQ(t.dependent, (std::vector<int>{1, 2, 4, 5}));

    const FourBarByHand right = fourBarByHand(kPi / 3);
    const FourBarByHand left = fourBarByHand(kPi / 3, {-2, 0}, -1);  // B above the line A–(−2, 0)
    EXPECT_NEAR(t.q0[1], right.coupler, 1e-9);
    EXPECT_NEAR(t.q0[2], right.rocker, 1e-9);
    EXPECT_NEAR(wrapAngle(t.q0[4] - left.coupler), 0, 1e-9);
    EXPECT_NEAR(wrapAngle(t.q0[5] - left.rocker), 0, 1e-9);
    EXPECT_NEAR(t.q0[4], 1.8304618579996774, 1e-9);
    EXPECT_NEAR(t.q0[5], -4.837716811552755 + 2 * kPi, 1e-9);  // the turn nearest its QI 1.4
    EXPECT_NEAR(wrapAngle(t.q0[6] - left.closing), 0, 1e-9);
}

TEST(Topology, DrivenJointsEnterTheTreeFirst)
{
    // the same four-bar with a drive on joint 4: joint 4 is a tree joint, joint 3 closes the loop,
    // and the driven joint 4 is the one kept independent, at the QI that gives the crank 60°
    std::string text = std::string(kFourBar) + "D 4 HYD VMAX 0.5\n";
    text.replace(text.find("C 4\n"), 4, "C 4 QI 1.851449659039601\n");
    const CompiledModel m = compileText(text, "m.pad");
    ASSERT_TRUE(m.ok()) << listing(m.diagnostics);
    const Topology& t = *m.topology;
    EXPECT_EQ(t.treeJoints, (std::vector<int>{3, 0, 1}));
    EXPECT_EQ(t.loopJoints, (std::vector<int>{2}));
    EXPECT_TRUE(t.reversed[3]);  // written B1 3 … B2 0: reached from ground, its side 2
    EXPECT_EQ(t.parentBody[3], 0);
    EXPECT_EQ(t.chains, (std::vector<std::vector<int>>{{3}, {0, 1}}));
    EXPECT_EQ(t.dof, 1);
    EXPECT_EQ(t.independent, (std::vector<int>{3}));
    EXPECT_EQ(t.dependent, (std::vector<int>{0, 1}));
    const FourBarByHand h = fourBarByHand(kPi / 3);
    EXPECT_NEAR(t.q0[3], 1.851449659039601, 0);  // held at QI
    EXPECT_NEAR(h.closing, 1.851449659039601, 1e-12);
    EXPECT_NEAR(t.q0[0], kPi / 3, 1e-9);  // solved from the guesses QI 60°, -0.5
    EXPECT_NEAR(t.q0[1], h.coupler, 1e-9);
    EXPECT_NEAR(t.q0[2], h.rocker, 1e-9);  // the cut joint, measured
}

// Slider-crank: crank 1 m (joint 1, driven, QI 60°), slider on x (joint 2, T 2), connecting
// rod 2 m (joint 3); joint 4 pins the rod to the slider and closes the loop.
const char* const kSliderCrank = R"(B 1 1 0.01 0.1 0.1 CG 0.5 0 0
B 2 2 0.01 0.5 0.5 CG 1 0 0
B 3 5 0.1 0.1 0.1
C 1 QI 1.0471975511965976
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2 T 2 QI 2.0
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 3 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 3 QI -1.0
B1 1 P1 1 0 0 A1 0 0 1 R1 1 0 0
B2 2 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 4
B1 2 P1 2 0 0 A1 0 0 1 R1 1 0 0
B2 3 P2 0 0 0 A2 0 0 1 R2 1 0 0
D 1 HYD VMAX 1
)";

TEST(Topology, SliderCrankRevoluteCut)
{
    const CompiledModel m = compileText(kSliderCrank, "m.pad");
    ASSERT_TRUE(m.ok()) << listing(m.diagnostics);
    const Topology& t = *m.topology;
    EXPECT_EQ(t.treeJoints, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(t.loopJoints, (std::vector<int>{3}));
    EXPECT_EQ(t.chains, (std::vector<std::vector<int>>{{0, 2}, {1}}));
    EXPECT_EQ(t.closureRank, 2);
    EXPECT_EQ(t.dof, 1);
    EXPECT_EQ(t.independent, (std::vector<int>{0}));
    EXPECT_EQ(t.dependent, (std::vector<int>{1, 2}));

    // by hand: x = r cos θ + sqrt(l² − r² sin² θ) = 0.5 + sqrt(3.25);
    // rod angle φ = atan2(−sin θ, x − cos θ)
    const double theta = kPi / 3;
    const double x = std::cos(theta) + std::sqrt(4 - std::sin(theta) * std::sin(theta));
    const double phi = std::atan2(-std::sin(theta), x - std::cos(theta));
    EXPECT_NEAR(x, 2.302775637731995, 1e-12);
    EXPECT_NEAR(t.q0[1], x, 1e-9);
    EXPECT_NEAR(t.q0[2], phi - theta, 1e-9);  // rod relative to the crank
    EXPECT_NEAR(t.q0[3], -phi, 1e-9);  // slider's R relative to the rod's
    EXPECT_NEAR(t.q0[3], 0.44783239692893245, 1e-9);
}

TEST(Topology, SliderCrankPrismaticCut)
{
    // the slider joint written last: it closes the loop (5 equations, planar: rank 2)
    test::SpecBuilder b;
    b.body(1, 1.0, Vector3d(0.01, 0.1, 0.1), Vector3d(0.5, 0, 0));
    b.body(2, 2.0, Vector3d(0.01, 0.5, 0.5), Vector3d(1, 0, 0));
    b.body(3, 5.0, Vector3d(0.1, 0.1, 0.1));
    b.joint(1, JointType::Revolute, side(0, Vector3d::Zero()), side(1, Vector3d::Zero()));
    b.set(1, "QI", kPi / 3, 7);
    b.joint(2, JointType::Revolute, side(1, Vector3d(1, 0, 0)), side(2, Vector3d::Zero()));
    b.set(2, "QI", -1.2, 7);
    b.joint(3, JointType::Revolute, side(2, Vector3d(2, 0, 0)), side(3, Vector3d::Zero()));
    b.set(3, "QI", 0.3, 7);
    b.joint(4, JointType::Prismatic, side(0, Vector3d::Zero()), side(3, Vector3d::Zero()));
    Diagnostics diags("m.pad");
    const auto t = analyze(b.spec, diags);
    ASSERT_TRUE(t.has_value()) << listing(diags);
    EXPECT_EQ(t->loopJoints, (std::vector<int>{3}));
    EXPECT_EQ(t->closureRank, 2);
    EXPECT_EQ(t->dof, 1);
    EXPECT_EQ(t->independent, (std::vector<int>{0}));
    EXPECT_EQ(t->dependent, (std::vector<int>{1, 2}));

    const double theta = kPi / 3;
    const double x = std::cos(theta) + std::sqrt(4 - std::sin(theta) * std::sin(theta));
    const double phi = std::atan2(-std::sin(theta), x - std::cos(theta));
    EXPECT_NEAR(t->q0[1], phi - theta, 1e-9);  // rod relative to crank
    EXPECT_NEAR(t->q0[2], -phi, 1e-9);  // slider keeps the ground's orientation
    EXPECT_NEAR(t->q0[3], x, 1e-9);  // the cut joint's own coordinate: slider travel
    EXPECT_NEAR(t->totalMass, 8.0, 1e-12);
}

// Crank 1, coupler 1, rocker 1 and ground pivots 4 m apart: with the crank at 0 the coupler and
// rocker reach at most 2 m from the crank tip at 1 m: the loop stays open by 1 m.
const char* const kLinkTooShort = R"(B 1 1 0.1 0.1 0.1
B 2 1 0.1 0.1 0.1
B 3 1 0.1 0.1 0.1
C 1 QI 0
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2 QI 0.3
B1 1 P1 1 0 0 A1 0 0 1 R1 1 0 0
B2 2 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 3 QI -0.5
B1 2 P1 1 0 0 A1 0 0 1 R1 1 0 0
B2 3 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 4 NAME "rocker pivot"
B1 3 P1 1 0 0 A1 0 0 1 R1 1 0 0
B2 0 P2 4 0 0 A2 0 0 1 R2 1 0 0
)";

TEST(Topology, LoopUnsatisfiable)
{
    const CompiledModel m = compileText(kLinkTooShort, "m.pad");
    EXPECT_FALSE(m.ok());
    EXPECT_FALSE(m.topology.has_value());
    EXPECT_EQ(m.diagnostics.errorCount(), 1u) << listing(m.diagnostics);
    const Diagnostic d = single(m, "loop-unsatisfiable", Severity::Error, 13, 1);
    EXPECT_EQ(
        d.message,
        "the loop closed by joint 4 \"rocker pivot\" cannot be assembled at the initial "
        "configuration: its closure equations keep a residual of 1 (P1 and P2 stay 1 m apart)");
    EXPECT_EQ(d.hint,
              "check the joint points P1, P2 and the link lengths of the loop, and the QI of its "
              "independent coordinates (joint 1)");
}

TEST(Topology, LoopUnsatisfiableResidualIsTheGap)
{
    // the same through the C++ spec: the least-squares residual is the 1 m gap
    const CompiledModel m = compileText(kLinkTooShort, "m.pad");
    Diagnostics diags("m.pad");
    EXPECT_FALSE(analyze(m.spec, diags).has_value());
    ASSERT_EQ(withCode(diags, "loop-unsatisfiable").size(), 1u);

    // crank at 0.5 rad instead: the gap is |D − A| − 2 with A = (cos 0.5, sin 0.5)
    ModelSpec spec = m.spec;
    spec.joints[0].qi = 0.5;
    Diagnostics diags2("m.pad");
    EXPECT_FALSE(analyze(spec, diags2).has_value());
    const auto found = withCode(diags2, "loop-unsatisfiable");
    ASSERT_EQ(found.size(), 1u);
    const double gap = std::hypot(4 - std::cos(0.5), std::sin(0.5)) - 2;
    char expected[64];
    std::snprintf(expected, sizeof expected, "residual of %.3g (P1 and P2 stay %.3g m apart)", gap,
                  gap);
    EXPECT_NE(found[0].message.find(expected), std::string::npos)
        << found[0].message << " / " << expected;
}

// ------------------------------------------------------------------ connectivity

TEST(Topology, BodyNotConnected)
{
    const char* text = R"(B 1 1 0.1 0.1 0.1
B 2 3 0.1 0.1 0.1 NAME "loose"
B 3 1 0.1 0.1 0.1
B 4 1 0.1 0.1 0.1
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2
B1 3 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 4 P2 1 0 0 A2 0 0 1 R2 1 0 0
)";
    const CompiledModel m = compileText(text, "m.pad");
    EXPECT_FALSE(m.ok());
    const auto found = withCode(m.diagnostics, "body-not-connected");
    ASSERT_EQ(found.size(), 3u) << listing(m.diagnostics);
    EXPECT_EQ(m.diagnostics.errorCount(), 3u) << listing(m.diagnostics);
    EXPECT_EQ(found[0].severity, Severity::Error);
    EXPECT_EQ(found[0].pos, (SourcePos{2, 1}));
    EXPECT_EQ(
        found[0].message,
        "body 2 \"loose\" is not connected to ground: no chain of joints leads from body 0 to it");
    EXPECT_EQ(found[0].hint, "add a joint (C) that connects it to ground or to a connected body");
    // bodies 3 and 4 are joined to each other only
    EXPECT_EQ(found[1].pos, (SourcePos{3, 1}));
    EXPECT_EQ(found[1].message,
              "body 3 is not connected to ground: no chain of joints leads from body 0 to it");
    EXPECT_EQ(found[2].pos, (SourcePos{4, 1}));
}

// ------------------------------------------------------------------ mass

TEST(Topology, JointMovesNoMassMasslessLeaf)
{
    const char* text = R"(B 1 1 0.1 0.1 0.1
B 2
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2 NAME "wrist"
B1 1 P1 1 0 0 A1 0 0 1 R1 1 0 0
B2 2 P2 0 0 0 A2 0 0 1 R2 1 0 0
)";
    const CompiledModel m = compileText(text, "m.pad");
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.diagnostics.errorCount(), 1u) << listing(m.diagnostics);
    const Diagnostic d = single(m, "joint-moves-no-mass", Severity::Error, 6, 1);
    EXPECT_EQ(
        d.message,
        "joint 2 \"wrist\" moves no mass: the bodies it moves have no mass, or only mass on its "
        "axis and no inertia about it, so the mass matrix is singular at the initial "
        "configuration");
    EXPECT_EQ(d.hint, "give the bodies it moves a mass (B id m Ixx Iyy Izz), or remove the joint");
}

TEST(Topology, JointMovesNoMassPointMassOnAxis)
{
    // body 2: 3 kg, no inertia, its centre of mass on joint 2's axis (z through its origin)
    const char* text = R"(B 1 1 0.1 0.1 0.1
B 2 3 0 0 0 CG 0 0 0.5
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2
B1 1 P1 1 0 0 A1 0 0 1 R1 1 0 0
B2 2 P2 0 0 0 A2 0 0 1 R2 1 0 0
)";
    const CompiledModel m = compileText(text, "m.pad");
    EXPECT_FALSE(m.ok());
    const Diagnostic d = single(m, "joint-moves-no-mass", Severity::Error, 6, 1);
    EXPECT_EQ(d.message.rfind("joint 2 moves no mass: ", 0), 0u) << d.message;

    // the same point mass off the axis is fine
    std::string moved = text;
    moved.replace(moved.find("CG 0 0 0.5"), 10, "CG 0.2 0 0");
    const CompiledModel ok = compileText(moved, "m.pad");
    EXPECT_TRUE(ok.ok()) << listing(ok.diagnostics);
}

TEST(Topology, JointMovesNoMassPrismaticLeaf)
{
    test::SpecBuilder b;
    b.body(1, 1.0, Vector3d(0.1, 0.1, 0.1));
    b.body(2);
    b.joint(1, JointType::Revolute, side(0, Vector3d::Zero()), side(1, Vector3d::Zero()));
    b.joint(2, JointType::Prismatic, side(1, Vector3d::Zero()), side(2, Vector3d::Zero()), "claw");
    Diagnostics diags("m.pad");
    EXPECT_FALSE(analyze(b.spec, diags).has_value());
    ASSERT_EQ(diags.size(), 1u) << listing(diags);
    EXPECT_EQ(diags.items()[0].code, "joint-moves-no-mass");
    EXPECT_EQ(diags.items()[0].pos, (SourcePos{6, 1}));
    EXPECT_EQ(
        diags.items()[0].message,
        "joint 2 \"claw\" moves no mass: the bodies it moves have no mass, so the mass matrix is "
        "singular at the initial configuration");
}

TEST(Topology, JointsMoveNoMassTogether)
{
    // two coaxial revolutes in series, the first body massless: turning joint 1 one way and
    // joint 2 the other leaves body 2 still
    const char* text = R"(B 1
B 2 1 0.1 0.1 0.1 CG 0.5 0 0
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2
B1 1 P1 0 0 0.2 A1 0 0 1 R1 1 0 0
B2 2 P2 0 0 0 A2 0 0 1 R2 1 0 0
)";
    const CompiledModel m = compileText(text, "m.pad");
    EXPECT_FALSE(m.ok());
    const auto found = withCode(m.diagnostics, "joint-moves-no-mass");
    ASSERT_EQ(found.size(), 2u) << listing(m.diagnostics);
    EXPECT_EQ(found[0].pos, (SourcePos{3, 1}));
    EXPECT_EQ(found[1].pos, (SourcePos{6, 1}));
    EXPECT_EQ(
        found[0].message,
        "joints 1 and 2 together move no mass: the motion with rates 1 for joint 1, -1 for joint 2 "
        "leaves every body with mass at rest, so the mass matrix is singular at the initial "
        "configuration");
}

TEST(Topology, MasslessBodyInsideAChainIsFine)
{
    // Appendix A body 1: massless, but joint 1 moves the heavy bodies beyond it
    const char* text = R"(B 1
B 2 306 73.4487 15.1982 73.4487
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0
B2 1 P2 0 0 -0.21 A2 0 0 1 R2 0 1 0
C 2 T 1 LL 1.4 UL 1.617 QI 1.464
B1 1 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 2 P2 0 -0.8 0 A2 1 0 0 R2 0 1 0
CL1 0.030 0 -.200 CL2 0.030 .650 0
)";
    const CompiledModel m = compileText(text, "m.pad");
    EXPECT_TRUE(m.ok()) << listing(m.diagnostics);
    EXPECT_EQ(m.topology->dof, 2);
    EXPECT_NEAR(m.topology->totalMass, 306, 0);
}

TEST(Topology, LoopThatMovesNoMass)
{
    // the four-bar with massless links: the crank and the loop it drives move no mass
    test::SpecBuilder b;
    b.body(1);
    b.body(2);
    b.body(3);
    b.joint(1, JointType::Revolute, side(0, Vector3d::Zero()), side(1, Vector3d::Zero()), "crank");
    b.set(1, "QI", kPi / 3, 7);
    b.joint(2, JointType::Revolute, side(1, Vector3d(1, 0, 0)), side(2, Vector3d::Zero()));
    b.set(2, "QI", -0.5, 7);
    b.joint(3, JointType::Revolute, side(2, Vector3d(2, 0, 0)), side(3, Vector3d::Zero()));
    b.set(3, "QI", -2.5, 7);
    b.joint(4, JointType::Revolute, side(3, Vector3d(1.5, 0, 0)), side(0, Vector3d(2, 0, 0)));
    Diagnostics diags("m.pad");
    EXPECT_FALSE(analyze(b.spec, diags).has_value());
    ASSERT_EQ(diags.size(), 1u) << listing(diags);
    EXPECT_EQ(diags.items()[0].code, "joint-moves-no-mass");
    EXPECT_EQ(diags.items()[0].pos, (SourcePos{4, 1}));
    EXPECT_EQ(diags.items()[0].message.rfind(
                  "joint 1 \"crank\" and the loop it drives (joints 2 and 3) move no mass: ", 0),
              0u)
        << diags.items()[0].message;
}

// ------------------------------------------------------------------ T 1 actuators

// Appendix A joints 1 and 2 with the C 2 line replaced.
std::string boomWith(const std::string& cLine,
                     const std::string& clLine = "CL1 0.030 0 -.200 CL2 0.030 .650 0")
{
    return "B 1\n"
           "B 2 306 73.4487 15.1982 73.4487\n"
           "C 1\n"
           "B1 0 P1 0 0 0 A1 0 0 1 R1 0 1 0\n"
           "B2 1 P2 0 0 -0.21 A2 0 0 1 R2 0 1 0\n" +
           cLine + "\n" +
           "B1 1 P1 0 0 0 A1 1 0 0 R1 0 1 0\n"
           "B2 2 P2 0 -0.8 0 A2 1 0 0 R2 0 1 0\n" +
           clLine + "\n";
}

TEST(Topology, ActuatorQiUnreachable)
{
    // 0        1         2
    // 123456789012345678901234567890
    // C 2 T 1 QI 2.1
    const CompiledModel m = compileText(boomWith("C 2 T 1 QI 2.1"), "m.pad");
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.diagnostics.errorCount(), 1u) << listing(m.diagnostics);
    const Diagnostic d = single(m, "actuator-unreachable", Severity::Error, 6, 12);
    EXPECT_EQ(d.message, "QI = 2.1 m is beyond the reach of joint 2's actuator (1.25 m .. 1.65 m)");
    EXPECT_EQ(
        d.hint,
        "the actuator length |CL2 − CL1| goes from 1.25 m to 1.65 m as the joint turns; choose QI "
        "within that range, or check CL1, CL2 and the joint points P1, P2 (a reachable QI is taken "
        "at "
        "the joint angle nearest to 0)");
}

TEST(Topology, ActuatorLimitsUnreachable)
{
    // C 2 T 1 LL 1.2 UL 1.7 QI 1.5: LL at column 12, UL at column 19
    const CompiledModel m = compileText(boomWith("C 2 T 1 LL 1.2 UL 1.7 QI 1.5"), "m.pad");
    EXPECT_FALSE(m.ok());
    const auto found = withCode(m.diagnostics, "actuator-unreachable");
    ASSERT_EQ(found.size(), 2u) << listing(m.diagnostics);
    EXPECT_EQ(found[0].pos, (SourcePos{6, 12}));
    EXPECT_EQ(found[0].message,
              "LL = 1.2 m is beyond the reach of joint 2's actuator (1.25 m .. 1.65 m)");
    EXPECT_EQ(found[1].pos, (SourcePos{6, 19}));
    EXPECT_EQ(found[1].message,
              "UL = 1.7 m is beyond the reach of joint 2's actuator (1.25 m .. 1.65 m)");
    EXPECT_EQ(found[1].severity, Severity::Error);
    // the limits are out of reach: no dead-point warning on top
    EXPECT_TRUE(withCode(m.diagnostics, "actuator-dead-point").empty()) << listing(m.diagnostics);
}

TEST(Topology, ActuatorConstantLength)
{
    // CL1 and CL2 on the joint axis (x through the joint point): the length is 0.5 m at any angle
    const CompiledModel m =
        compileText(boomWith("C 2 T 1 QI 0.5", "CL1 0.2 0 0 CL2 0.7 -0.8 0"), "m.pad");
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.diagnostics.errorCount(), 1u) << listing(m.diagnostics);
    const Diagnostic d = single(m, "actuator-constant-length", Severity::Error, 9, 5);
    EXPECT_EQ(d.message, "joint 2's actuator keeps the same length 0.5 m whatever the joint angle: "
                         "CL1 or CL2 lies on "
                         "the joint axis A, so the actuator cannot turn the joint");
    EXPECT_EQ(
        d.hint,
        "place CL1 (on body 1) and CL2 (on body 2) away from the joint axis, so that the actuator "
        "length changes as the joint turns");
}

TEST(Topology, ActuatorDeadPointWithoutUpperLimit)
{
    const CompiledModel m = compileText(boomWith("C 2 T 1 LL 1.3"), "m.pad");
    EXPECT_TRUE(m.ok()) << listing(m.diagnostics);
    const Diagnostic d = single(m, "actuator-dead-point", Severity::Warning, 6, 1);
    EXPECT_EQ(d.message, "joint 2's actuator reaches a dead point inside its stroke: its length is "
                         "longest (1.65 m) at "
                         "joint angle 1.5708 rad, and no UL stops it before");
    EXPECT_EQ(
        d.hint,
        "the cylinder cannot drive the joint through that point (dL/dθ = 0 there); set UL below "
        "1.65 m");
    // default QI: the middle of [LL, longest length]
    EXPECT_NEAR(m.topology->q0[1], (1.3 + 1.65) / 2, 1e-12);
}

TEST(Topology, ActuatorDeadPointsWithoutLimits)
{
    const CompiledModel m = compileText(boomWith("C 2 T 1"), "m.pad");
    EXPECT_TRUE(m.ok()) << listing(m.diagnostics);
    const auto found = withCode(m.diagnostics, "actuator-dead-point");
    ASSERT_EQ(found.size(), 2u) << listing(m.diagnostics);
    EXPECT_NE(found[1].message.find(
                  "its length is shortest (1.25 m) at joint angle -1.5708 rad, and no LL"),
              std::string::npos)
        << found[1].message;
    EXPECT_NE(found[1].hint.find("set LL above 1.25 m"), std::string::npos) << found[1].hint;
    // default QI: the middle of the reachable range, at the angle nearest 0
    EXPECT_NEAR(m.topology->q0[1], 1.45, 1e-12);
    EXPECT_NEAR(m.topology->theta0[1], std::asin((1.45 * 1.45 - 2.1425) / 0.58), 1e-12);
}

TEST(Topology, ActuatorDefaultQiBetweenLimits)
{
    const CompiledModel m = compileText(boomWith("C 2 T 1 LL 1.4 UL 1.6"), "m.pad");
    ASSERT_TRUE(m.ok()) << listing(m.diagnostics);
    EXPECT_TRUE(m.diagnostics.empty()) << listing(m.diagnostics);
    EXPECT_NEAR(m.topology->q0[1], 1.5, 1e-12);
    EXPECT_NEAR(m.topology->theta0[1], std::asin((1.5 * 1.5 - 2.1425) / 0.58), 1e-12);
}

TEST(Topology, ReversedJointInTheTree)
{
    // C 1 is written from body 1 to ground; the tree runs it backwards
    test::SpecBuilder b;
    b.body(1, 2.0, Vector3d(0.1, 0.1, 0.1));
    b.joint(1, JointType::Revolute, side(1, Vector3d(-1, 0, 0)), side(0, Vector3d::Zero()));
    Diagnostics diags("m.pad");
    const auto t = analyze(b.spec, diags);
    ASSERT_TRUE(t.has_value()) << listing(diags);
    EXPECT_TRUE(t->reversed[0]);
    EXPECT_EQ(t->parentBody, (std::vector<int>{-1, 0}));
    EXPECT_EQ(t->parentJoint, (std::vector<int>{-1, 0}));
    EXPECT_EQ(t->side1Body, std::vector<int>{1});
    EXPECT_EQ(t->side2Body, std::vector<int>{0});
    EXPECT_EQ(t->dof, 1);
}

TEST(Topology, EmptyModel)
{
    Diagnostics diags("m.pad");
    const auto t = analyze(ModelSpec{}, diags);
    ASSERT_TRUE(t.has_value());
    EXPECT_EQ(t->bodyIds, std::vector<int>{0});
    EXPECT_EQ(t->dof, 0);
    EXPECT_TRUE(diags.empty());
}

}  // namespace
}  // namespace solver
