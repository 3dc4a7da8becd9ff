// The thesis's Appendix A ("Manipulator input model") as printed, and the project's
// model of the liner manipulator built from it.
//
// Appendix A loaded unchanged has one error, the decimal comma of body 4's Izz; with
// that one character fixed it loads, with the inertia warnings its data deserve:
// bodies 3, 5 and 6 have principal moments that break the triangle inequality
//   3: 58.2474 + 58.2474 = 116.4948 < 190.9768
//   5: 0.54153 + 1.25234 = 1.79387 < 4.11914
//   6: 0.369125 + 1.4359 = 1.805025 < 2.65596
// while body 2 (15.1982 + 73.4487 ≥ 73.4487), body 4 (2.07742 + 3.89517 = 5.97259
// ≥ 4.38325) and bodies 7–9 (equal moments) are possible.

#include "solver/pipeline.h"
#include "model_texts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

using namespace solver;
using solver::test::kAppendixA;

namespace {

std::string listing(const Diagnostics& diags)
{
    std::string s;
    for (const Diagnostic& d : diags) s += "  " + d.code + " | " + d.format() + "\n";
    return s.empty() ? "  (none)\n" : s;
}


/// Ids of the bodies whose diagonal inertia breaks Ixx + Iyy >= Izz or a permutation,
/// computed here from the spec (every Appendix A body has zero products).
std::set<int> triangleBreakers(const ModelSpec& spec)
{
    std::set<int> ids;
    for (const BodySpec& b : spec.bodies) {
        if (!b.hasMass) continue;
        EXPECT_FALSE(b.hasProducts);
        const Eigen::Vector3d& I = b.inertia;
        if (I.x() + I.y() < I.z() || I.y() + I.z() < I.x() || I.z() + I.x() < I.y()) ids.insert(b.id);
    }
    return ids;
}

/// Ids of the bodies named by inertia-triangle warnings ("body 3 …" or "body 3 (name)'s …").
std::set<int> triangleWarnings(const Diagnostics& diags)
{
    std::set<int> ids;
    for (const Diagnostic& d : diags) {
        if (d.code != "inertia-triangle") continue;
        EXPECT_EQ(d.severity, Severity::Warning);
        EXPECT_EQ(d.message.rfind("body ", 0), 0u) << d.message;
        ids.insert(std::stoi(d.message.substr(5)));
    }
    return ids;
}

const char* const kTriangle3 =
    "m.pad:83:11: warning: body 3's principal moments of inertia 58.2474, 58.2474, 190.977 kg m² break the "
    "triangle inequality (58.2474 + 58.2474 < 190.977): no real body has them [check the values; the inertia "
    "calculator computes them from the body's shapes]";
const char* const kTriangle5 =
    "m.pad:87:11: warning: body 5's principal moments of inertia 0.54153, 1.25234, 4.11914 kg m² break the "
    "triangle inequality (0.54153 + 1.25234 < 4.11914): no real body has them [check the values; the inertia "
    "calculator computes them from the body's shapes]";
const char* const kTriangle6 =
    "m.pad:89:11: warning: body 6's principal moments of inertia 0.369125, 1.4359, 2.65596 kg m² break the "
    "triangle inequality (0.369125 + 1.4359 < 2.65596): no real body has them [check the values; the inertia "
    "calculator computes them from the body's shapes]";

}  // namespace

TEST(AppendixA, TextIsTheThesisText)
{
    // the statements and numbers that the tests below rely on
    EXPECT_EQ(std::count(kAppendixA.begin(), kAppendixA.end(), '\n'), 95);
    EXPECT_NE(kAppendixA.find("\nB 4 200.0 2.07742 3.89517 4,38325\n"), std::string::npos);
    EXPECT_NE(kAppendixA.find("\nCL1 0.030 0 -.200 CL2 0.030 .650 0\n"), std::string::npos);
    EXPECT_EQ(kAppendixA.rfind("B 9 2.0 0.00001 0.00001 0.00001\n"), kAppendixA.size() - 32);
}

TEST(AppendixA, UnchangedGivesExactlyTheDecimalCommaError)
{
    CompiledModel m = compileText(kAppendixA, "m.pad");
    ASSERT_EQ(m.diagnostics.errorCount(), 1u) << listing(m.diagnostics);
    // the error, and the warnings of the bodies that were read (body 4 is not checked:
    // its numbers are incomplete)
    ASSERT_EQ(m.diagnostics.size(), 4u) << listing(m.diagnostics);
    const auto& d = m.diagnostics.items();
    EXPECT_EQ(d[0].format(), kTriangle3);
    EXPECT_EQ(d[1].code, "decimal-comma");
    EXPECT_EQ(d[1].severity, Severity::Error);
    EXPECT_EQ(d[1].pos, (SourcePos{85, 27}));
    EXPECT_EQ(d[1].format(),
              "m.pad:85:27: error: body 4: '4,38325' is not a number [use '.' as the decimal separator: 4.38325]");
    EXPECT_EQ(d[2].format(), kTriangle5);
    EXPECT_EQ(d[3].format(), kTriangle6);
    EXPECT_FALSE(m.ok());
    EXPECT_FALSE(m.topology.has_value());
}

TEST(AppendixA, CorrectedLoadsWithTheTriangleWarnings)
{
    CompiledModel m = compileText(solver::test::appendixACorrected(), "m.pad");
    ASSERT_EQ(m.diagnostics.size(), 3u) << listing(m.diagnostics);
    EXPECT_EQ(m.diagnostics.items()[0].format(), kTriangle3);
    EXPECT_EQ(m.diagnostics.items()[1].format(), kTriangle5);
    EXPECT_EQ(m.diagnostics.items()[2].format(), kTriangle6);
    EXPECT_EQ(m.diagnostics.errorCount(), 0u);
    EXPECT_EQ(triangleBreakers(m.spec), (std::set<int>{3, 5, 6}));
    EXPECT_EQ(triangleWarnings(m.diagnostics), (std::set<int>{3, 5, 6}));
    ASSERT_TRUE(m.ok());
    ASSERT_TRUE(m.topology.has_value());
    EXPECT_EQ(m.topology->dof, 9);
    EXPECT_EQ(m.topology->totalMass, 1314.0);
    EXPECT_EQ(m.topology->treeJoints.size(), 9u);
    EXPECT_TRUE(m.topology->loopJoints.empty());
    EXPECT_EQ(m.topology->bodyIds.size(), 10u);  // ground and bodies 1–9
}

TEST(AppendixA, CorrectedSpecHasTheThesisValues)
{
    CompiledModel m = compileText(solver::test::appendixACorrected(), "m.pad");
    const ModelSpec& s = m.spec;
    ASSERT_EQ(s.bodies.size(), 10u);  // B 0 … B 9
    ASSERT_EQ(s.joints.size(), 9u);
    EXPECT_FALSE(s.hasGravity);
    EXPECT_EQ(s.gravity, Eigen::Vector3d(0, 0, -9.81));
    EXPECT_FALSE(s.body(1)->hasMass);
    EXPECT_EQ(s.body(4)->inertia, Eigen::Vector3d(2.07742, 3.89517, 4.38325));
    EXPECT_EQ(s.body(3)->mass, 594.0);

    const JointSpec& c2 = *s.joint(2);
    EXPECT_EQ(c2.type, JointType::Actuator);
    EXPECT_EQ(c2.ll, 1.4);
    EXPECT_EQ(c2.ul, 1.617);
    EXPECT_EQ(c2.qi, 1.464);
    EXPECT_TRUE(c2.hasCl);
    EXPECT_EQ(c2.cl1, Eigen::Vector3d(0.030, 0, -0.200));
    EXPECT_EQ(c2.cl2, Eigen::Vector3d(0.030, 0.650, 0));
    EXPECT_EQ(c2.side2.p, Eigen::Vector3d(0, -0.8, 0));

    EXPECT_EQ(s.joint(1)->type, JointType::Revolute);
    EXPECT_FALSE(s.joint(1)->typeWritten);
    EXPECT_EQ(s.joint(8)->type, JointType::Prismatic);
    EXPECT_EQ(s.joint(8)->ll, -0.150);
    EXPECT_EQ(s.joint(8)->side1.p, Eigen::Vector3d(0, 0.05, 0.35));
    EXPECT_EQ(s.joint(8)->side1.a, Eigen::Vector3d(0, 1, 0));
    EXPECT_EQ(s.joint(8)->side1.r, Eigen::Vector3d(0, 0, 1));
    EXPECT_FALSE(s.joint(4)->vi.has_value());
}

TEST(AppendixA, LinerManipulatorModel)
{
    const std::filesystem::path file = std::filesystem::path(PADROB_SOURCE_DIR) / "models" / "liner_manipulator.pad";
    ASSERT_TRUE(std::filesystem::exists(file)) << file << " is missing";
    CompiledModel m = compileFile(file.string());
    EXPECT_EQ(m.diagnostics.errorCount(), 0u) << listing(m.diagnostics);
    // the same three warnings as Appendix A, and nothing else
    ASSERT_EQ(m.diagnostics.size(), 3u) << listing(m.diagnostics);
    EXPECT_EQ(triangleWarnings(m.diagnostics), (std::set<int>{3, 5, 6}));
    EXPECT_EQ(triangleBreakers(m.spec), (std::set<int>{3, 5, 6}));
    EXPECT_EQ(m.spec.joints.size(), 9u);
    ASSERT_TRUE(m.ok());
    ASSERT_TRUE(m.topology.has_value());
    EXPECT_EQ(m.topology->dof, 9);
    EXPECT_DOUBLE_EQ(m.topology->totalMass, 1314.0);
}
