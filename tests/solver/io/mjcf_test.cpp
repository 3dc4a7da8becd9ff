#include "solver/io/mjcf.h"

#include "solver/kinematics/kinematics.h"
#include "solver/pipeline.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace solver {
namespace {

// ---- a minimal XML reader for the tests (the solver has no XML library) -----------
// Elements with attributes in double quotes, comments, nesting; fails on anything
// malformed (unbalanced tags, a "--" inside a comment, text outside elements).

struct Element {
    std::string name;
    std::map<std::string, std::string> attrs;
    std::vector<std::unique_ptr<Element>> children;
    std::vector<std::string> comments;  ///< comments directly inside this element
    Element* parent = nullptr;

    std::string attr(const std::string& key) const
    {
        auto it = attrs.find(key);
        return it == attrs.end() ? std::string() : it->second;
    }
    bool has(const std::string& key) const { return attrs.count(key) > 0; }
    /// Every descendant named `n`, depth first.
    void collect(const std::string& n, std::vector<const Element*>& out) const
    {
        for (const auto& c : children) {
            if (c->name == n) out.push_back(c.get());
            c->collect(n, out);
        }
    }
    std::vector<const Element*> all(const std::string& n) const
    {
        std::vector<const Element*> out;
        collect(n, out);
        return out;
    }
    const Element* child(const std::string& n) const
    {
        for (const auto& c : children)
            if (c->name == n) return c.get();
        return nullptr;
    }
};

/// Parses `xml` into a document whose children are the top-level elements; on
/// malformed text returns nullptr with `error` set.
std::unique_ptr<Element> parseXml(const std::string& xml, std::string& error)
{
    auto doc = std::make_unique<Element>();
    Element* cur = doc.get();
    std::size_t i = 0;
    auto fail = [&](const std::string& what) {
        error = what + " at offset " + std::to_string(i);
        return nullptr;
    };
    auto isSpace = [](char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; };
    while (i < xml.size()) {
        if (isSpace(xml[i])) {
            ++i;
            continue;
        }
        if (xml[i] != '<') return fail("text outside a tag");
        if (xml.compare(i, 4, "<!--") == 0) {
            const std::size_t end = xml.find("-->", i + 4);
            if (end == std::string::npos) return fail("unterminated comment");
            const std::string body = xml.substr(i + 4, end - i - 4);
            if (body.find("--") != std::string::npos || (!body.empty() && body.back() == '-'))
                return fail("'--' inside a comment");
            cur->comments.push_back(body);
            i = end + 3;
            continue;
        }
        if (xml.compare(i, 2, "</") == 0) {
            const std::size_t end = xml.find('>', i);
            if (end == std::string::npos) return fail("unterminated end tag");
            const std::string name = xml.substr(i + 2, end - i - 2);
            if (cur == doc.get() || name != cur->name) return fail("mismatched end tag </" + name + ">");
            cur = cur->parent;
            i = end + 1;
            continue;
        }
        // a start tag
        ++i;
        auto e = std::make_unique<Element>();
        while (i < xml.size() && !isSpace(xml[i]) && xml[i] != '>' && xml[i] != '/') e->name += xml[i++];
        if (e->name.empty()) return fail("element without a name");
        bool selfClosing = false;
        for (;;) {
            while (i < xml.size() && isSpace(xml[i])) ++i;
            if (i >= xml.size()) return fail("unterminated tag");
            if (xml[i] == '>') {
                ++i;
                break;
            }
            if (xml.compare(i, 2, "/>") == 0) {
                i += 2;
                selfClosing = true;
                break;
            }
            std::string key;
            while (i < xml.size() && xml[i] != '=' && !isSpace(xml[i])) key += xml[i++];
            if (xml.compare(i, 2, "=\"") != 0) return fail("attribute '" + key + "' without a quoted value");
            i += 2;
            const std::size_t end = xml.find('"', i);
            if (end == std::string::npos) return fail("unterminated attribute value");
            const std::string value = xml.substr(i, end - i);
            if (value.find('<') != std::string::npos) return fail("'<' in an attribute value");
            if (!e->attrs.emplace(key, value).second) return fail("duplicate attribute '" + key + "'");
            i = end + 1;
        }
        e->parent = cur;
        Element* raw = e.get();
        cur->children.push_back(std::move(e));
        if (!selfClosing) cur = raw;
    }
    if (cur != doc.get()) return fail("unclosed element <" + cur->name + ">");
    return doc;
}

std::vector<double> numbers(const std::string& s)
{
    std::vector<double> out;
    std::istringstream in(s);
    in.imbue(std::locale::classic());
    double v;
    while (in >> v) out.push_back(v);
    return out;
}

Eigen::Vector3d vec(const std::string& s)
{
    const std::vector<double> v = numbers(s);
    EXPECT_EQ(v.size(), 3u) << s;
    return v.size() == 3 ? Eigen::Vector3d(v[0], v[1], v[2]) : Eigen::Vector3d::Zero();
}

/// MJCF text of a compiled model, parsed; fails the test on error.
struct Exported {
    std::string xml;
    std::unique_ptr<Element> doc;
    const Element* root() const { return doc ? doc->child("mujoco") : nullptr; }
};

Exported exportModel(const Model& model, const MjcfOptions& options = {})
{
    Exported e;
    std::string error;
    e.xml = toMjcf(model, options, error);
    EXPECT_EQ(error, "");
    EXPECT_FALSE(e.xml.empty());
    std::string parseError;
    e.doc = parseXml(e.xml, parseError);
    EXPECT_TRUE(e.doc) << parseError << "\n" << e.xml;
    if (e.doc) {
        EXPECT_EQ(e.doc->children.size(), 1u);
        EXPECT_TRUE(e.root());
    }
    return e;
}

/// The pose of a body element in its parent (pos, quat w x y z).
Eigen::Isometry3d bodyPose(const Element& b)
{
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.translation() = vec(b.attr("pos"));
    if (b.has("quat")) {
        const std::vector<double> q = numbers(b.attr("quat"));
        EXPECT_EQ(q.size(), 4u);
        X.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
    }
    return X;
}

/// MuJoCo's joint motion: the body frame in its parent at qpos = x, for a hinge (a
/// turn by x about `axis` through `pos`) or a slide (a shift by x along `axis`), both
/// in the body frame.
Eigen::Isometry3d jointMotion(const Element& j, double x)
{
    const Eigen::Vector3d pos = vec(j.attr("pos")), axis = vec(j.attr("axis")).normalized();
    Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
    if (j.attr("type") == "slide") {
        M.translation() = x * axis;
    } else {
        M.linear() = Eigen::AngleAxisd(x, axis).toRotationMatrix();
        M.translation() = pos - M.linear() * pos;
    }
    return M;
}

/// Body name → world pose with every joint at qpos (by joint name), MuJoCo's way.
void worldPoses(const Element& e, const Eigen::Isometry3d& X_parent, const std::map<std::string, double>& qpos,
                std::map<std::string, Eigen::Isometry3d>& out)
{
    for (const auto& c : e.children) {
        if (c->name != "body") continue;
        Eigen::Isometry3d X = X_parent * bodyPose(*c);
        if (const Element* j = c->child("joint")) {
            auto it = qpos.find(j->attr("name"));
            X = X * jointMotion(*j, it == qpos.end() ? 0.0 : it->second);
        }
        out[c->attr("name")] = X;
        worldPoses(*c, X, qpos, out);
    }
}

/// Checks that the MJCF reproduces Padrob's body poses with qpos = θ.
void expectSamePoses(const Model& model, const Exported& e, const Eigen::VectorXd& theta)
{
    const MjcfNames names = mjcfNames(model);
    std::map<std::string, double> qpos;
    for (int i = 0; i < model.nb; ++i) qpos[names.joint[i]] = theta[i];
    std::map<std::string, Eigen::Isometry3d> X_mj;
    worldPoses(*e.root()->child("worldbody"), Eigen::Isometry3d::Identity(), qpos, X_mj);
    Data data(model);
    forwardKinematics(model, theta, Eigen::VectorXd::Zero(model.nb), data);
    for (int i = 0; i < model.nb; ++i) {
        ASSERT_TRUE(X_mj.count(names.body[i])) << names.body[i];
        const Eigen::Isometry3d& X = X_mj[names.body[i]];
        EXPECT_LT((X.translation() - data.X_wb[i].translation()).norm(), 1e-12) << names.body[i];
        EXPECT_LT((X.linear() - data.X_wb[i].linear()).norm(), 1e-12) << names.body[i];
    }
}

std::shared_ptr<const Model> example(const std::string& name) { return test::compileExample(name); }

TEST(Mjcf, PendulumIsWellFormedWithTheDocumentedOptions)
{
    auto model = example("pendulum.pad");
    ASSERT_TRUE(model);
    MjcfOptions options;
    options.timestep = 0.002;
    options.source = "models/pendulum.pad";
    const Exported e = exportModel(*model, options);
    ASSERT_TRUE(e.root());
    EXPECT_EQ(e.xml.rfind("<!--", 0), 0u) << "starts with the header comment";
    EXPECT_EQ(e.root()->attr("model"), "pendulum");
    ASSERT_EQ(e.doc->comments.size(), 1u);
    const std::string& header = e.doc->comments[0];
    EXPECT_NE(header.find("models/pendulum.pad"), std::string::npos) << header;
    EXPECT_NE(header.find("NOT exported"), std::string::npos) << header;
    EXPECT_NE(header.find("passive"), std::string::npos) << header;

    const Element* compiler = e.root()->child("compiler");
    ASSERT_TRUE(compiler);
    EXPECT_EQ(compiler->attr("angle"), "radian");
    EXPECT_EQ(compiler->attr("inertiafromgeom"), "false");
    const Element* option = e.root()->child("option");
    ASSERT_TRUE(option);
    EXPECT_EQ(option->attr("timestep"), "0.002");
    EXPECT_EQ(option->attr("integrator"), "RK4");
    EXPECT_EQ(vec(option->attr("gravity")), Eigen::Vector3d(0, 0, -9.81));
    ASSERT_TRUE(option->child("flag"));
    EXPECT_EQ(option->child("flag")->attr("contact"), "disable");

    const auto bodies = e.root()->all("body");
    ASSERT_EQ(bodies.size(), 1u);
    EXPECT_EQ(bodies[0]->attr("name"), "bob");
    EXPECT_EQ(vec(bodies[0]->attr("pos")), Eigen::Vector3d(0, 0, -1));  // 1 m under the pivot
    const Element* joint = bodies[0]->child("joint");
    ASSERT_TRUE(joint);
    EXPECT_EQ(joint->attr("name"), "pivot");
    EXPECT_EQ(joint->attr("type"), "hinge");
    EXPECT_EQ(vec(joint->attr("pos")), Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(vec(joint->attr("axis")), Eigen::Vector3d(1, 0, 0));
    EXPECT_FALSE(joint->has("range"));
    const Element* inertial = bodies[0]->child("inertial");
    ASSERT_TRUE(inertial);
    EXPECT_EQ(inertial->attr("mass"), "1");
    EXPECT_EQ(inertial->attr("fullinertia"), "1e-06 1e-06 1e-06 0 0 0");

    const Element* key = e.root()->child("keyframe") ? e.root()->child("keyframe")->child("key") : nullptr;
    ASSERT_TRUE(key);
    EXPECT_EQ(key->attr("name"), "initial");
    EXPECT_EQ(key->attr("qpos"), "0.1");
    EXPECT_EQ(key->attr("qvel"), "0");
}

TEST(Mjcf, LinerManipulatorBodiesJointsAndMasses)
{
    auto model = example("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const Exported e = exportModel(*model);
    ASSERT_TRUE(e.root());
    const auto bodies = e.root()->all("body");
    ASSERT_EQ(bodies.size(), 9u);
    const auto joints = e.root()->all("joint");
    ASSERT_EQ(joints.size(), 9u);
    // depth-first: turret ⊃ boom ⊃ extension ⊃ wrist ⊃ rocker ⊃ head ⊃ {piston, jaws}
    const std::vector<std::string> expected = {"torreta", "pluma",  "extension",      "muneca",        "balancin",
                                               "cabezal", "piston", "garra_superior", "garra_inferior"};
    for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_EQ(bodies[k]->attr("name"), expected[k]);
    EXPECT_EQ(bodies[6]->parent, bodies[5]);
    EXPECT_EQ(bodies[8]->parent, bodies[5]);
    const std::vector<std::string> types = {"hinge", "hinge", "slide", "hinge", "hinge",
                                            "hinge", "slide", "slide", "slide"};
    for (std::size_t k = 0; k < types.size(); ++k) EXPECT_EQ(joints[k]->attr("type"), types[k]) << k;
    EXPECT_EQ(joints[1]->attr("name"), "LEVANTE_PLUMA");
    EXPECT_EQ(joints[4]->attr("name"), "LEVANTE_MUNECA");
    EXPECT_EQ(joints[5]->attr("name"), "ROTACION_MUNECA");
    EXPECT_EQ(vec(joints[0]->attr("axis")), Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(vec(joints[2]->attr("axis")), Eigen::Vector3d(0, 1, 0));  // T 2 slides along R
    // two-sided limits as ranges; T 1's on the angle
    EXPECT_EQ(joints[0]->attr("range"), "");
    EXPECT_EQ(joints[2]->attr("limited"), "true");
    EXPECT_EQ(numbers(joints[2]->attr("range")), (std::vector<double>{0.0, 0.9}));
    const std::vector<double> boomRange = numbers(joints[1]->attr("range"));
    ASSERT_EQ(boomRange.size(), 2u);
    const int boom = model->jointIndex(2);
    EXPECT_EQ(boomRange[0], model->lower[boom]);
    EXPECT_EQ(boomRange[1], model->upper[boom]);
    // masses as written, the massless turret as a placeholder
    const std::vector<std::string> masses = {"1e-09", "306", "594", "200", "100", "100", "10", "2", "2"};
    for (std::size_t k = 0; k < masses.size(); ++k) EXPECT_EQ(bodies[k]->child("inertial")->attr("mass"), masses[k]);
    // the key holds θ0 in MuJoCo's order (depth first = tree order here)
    const std::vector<double> q = numbers(e.root()->child("keyframe")->child("key")->attr("qpos"));
    ASSERT_EQ(q.size(), 9u);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(q[i], model->theta0[i]);
    expectSamePoses(*model, e, Eigen::VectorXd::Zero(model->nb));
    expectSamePoses(*model, e, Eigen::Map<const Eigen::VectorXd>(model->theta0.data(), model->nb));
}

TEST(Mjcf, PlaceholdersCarryTheTrueValuesInAComment)
{
    auto model = example("liner_manipulator.pad");
    ASSERT_TRUE(model);
    const Exported e = exportModel(*model);
    ASSERT_TRUE(e.root());
    const auto bodies = e.root()->all("body");
    ASSERT_EQ(bodies.size(), 9u);
    auto commentsOf = [](const Element* b) {
        std::string all;
        for (const std::string& c : b->comments) all += c + "\n";
        return all;
    };
    // the turret: massless
    const std::string turret = commentsOf(bodies[0]);
    EXPECT_NE(turret.find("placeholder mass 1e-09 kg: massless in Padrob"), std::string::npos) << turret;
    EXPECT_NE(turret.find("placeholder inertia"), std::string::npos) << turret;
    EXPECT_EQ(bodies[0]->child("inertial")->attr("diaginertia"), "1e-12 1e-12 1e-12");
    // the thesis's bodies 3, 5, 6 break the triangle inequality
    for (int k : {2, 4, 5}) {
        const std::string c = commentsOf(bodies[static_cast<std::size_t>(k)]);
        EXPECT_NE(c.find("placeholder inertia: the true tensor"), std::string::npos) << k << c;
        EXPECT_NE(c.find("break I1 + I2 >= I3"), std::string::npos) << k << c;
        const Element* in = bodies[static_cast<std::size_t>(k)]->child("inertial");
        EXPECT_FALSE(in->has("fullinertia"));
        EXPECT_FALSE(in->has("quat")) << "diagonal in body axes";
        const std::vector<double> d = numbers(in->attr("diaginertia"));
        ASSERT_EQ(d.size(), 3u);
        EXPECT_GE(d[0] + d[1], d[2]);
        EXPECT_GE(d[0] + d[2], d[1]);
        EXPECT_GE(d[1] + d[2], d[0]);
    }
    EXPECT_NE(commentsOf(bodies[4]).find("0.54153 1.25234 4.11914 0 0 0"), std::string::npos);
    // the others are written as they are
    for (int k : {1, 3, 6, 7, 8}) {
        EXPECT_EQ(commentsOf(bodies[static_cast<std::size_t>(k)]).find("placeholder"), std::string::npos) << k;
        EXPECT_TRUE(bodies[static_cast<std::size_t>(k)]->child("inertial")->has("fullinertia")) << k;
    }
    EXPECT_EQ(bodies[1]->child("inertial")->attr("fullinertia"), "73.4487 15.1982 73.4487 0 0 0");
    EXPECT_NE(e.doc->comments[0].find("4 bodies have placeholder mass properties"), std::string::npos);
}

TEST(Mjcf, PlaceholderIsTheNearestValidInertia)
{
    auto model = example("liner_manipulator.pad");
    ASSERT_TRUE(model);
    // body 5 "balancín": 0.54153 + 1.25234 < 4.11914
    const MjcfInertial p = mjcfInertial(*model, model->bodyIndex(5));
    EXPECT_TRUE(p.diagonal);
    EXPECT_FALSE(p.placeholderMass);
    EXPECT_TRUE(p.placeholderInertia);
    EXPECT_EQ(p.principal, Eigen::Vector3d(0.54153, 1.25234, 4.11914));
    const double delta = 4.11914 - 0.54153 - 1.25234;
    EXPECT_NEAR(p.writtenPrincipal[0], 0.54153 + delta / 3, 1e-12);
    EXPECT_NEAR(p.writtenPrincipal[1], 1.25234 + delta / 3, 1e-12);
    EXPECT_NEAR(p.writtenPrincipal[2], 4.11914 - delta / 3, 1e-12);
    EXPECT_EQ(p.writtenPrincipal[0] + p.writtenPrincipal[1], p.writtenPrincipal[2]);  // on the boundary, exactly
    EXPECT_EQ(p.writtenMass, 100.0);

    // the turret: massless
    const MjcfInertial t = mjcfInertial(*model, model->bodyIndex(1));
    EXPECT_TRUE(t.placeholderMass);
    EXPECT_TRUE(t.placeholderInertia);
    EXPECT_EQ(t.mass, 0.0);
    EXPECT_EQ(t.writtenMass, kMjcfMinMass);
    EXPECT_EQ(t.writtenPrincipal, Eigen::Vector3d::Constant(kMjcfMinInertia));

    // the boom: valid, unchanged
    const MjcfInertial b = mjcfInertial(*model, model->bodyIndex(2));
    EXPECT_FALSE(b.placeholder());
    EXPECT_EQ(b.writtenPrincipal, b.principal);
}

TEST(Mjcf, ProductsOfInertiaInMujocosOrderAndPrincipalAxesForAPlaceholder)
{
    // Padrob's B line: Ixx Iyy Izz Ixy Iyz Ixz; MJCF's fullinertia: Ixx Iyy Izz Ixy Ixz Iyz
    auto model = test::compileText(R"(
B 1 2.0 0.5 0.6 0.7 0.01 0.02 0.03 CG 0.1 0.2 0.3 NAME "lump"
B 2 1.0 0.1 0.1 0.5 0.02 0 0 NAME "flat, rotated"
C 1
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0
C 2
B1 1 P1 0 0 -1 A1 1 0 0 R1 0 1 0
B2 2 P2 0 0 0 A2 1 0 0 R2 0 1 0
)");
    ASSERT_TRUE(model);
    const Exported e = exportModel(*model);
    ASSERT_TRUE(e.root());
    const auto bodies = e.root()->all("body");
    ASSERT_EQ(bodies.size(), 2u);
    const Element* lump = bodies[0]->child("inertial");
    EXPECT_EQ(lump->attr("fullinertia"), "0.5 0.6 0.7 0.01 0.03 0.02");
    EXPECT_EQ(vec(lump->attr("pos")), Eigen::Vector3d(0.1, 0.2, 0.3));
    EXPECT_EQ(bodies[0]->attr("name"), "lump");
    EXPECT_EQ(bodies[1]->attr("name"), "flat_rotated");

    // 0.1 ± 0.02 and 0.5 break the triangle inequality: principal axes and moments
    const MjcfInertial p = mjcfInertial(*model, 1);
    EXPECT_FALSE(p.diagonal);
    EXPECT_TRUE(p.placeholderInertia);
    const Element* flat = bodies[1]->child("inertial");
    ASSERT_TRUE(flat->has("quat"));
    const std::vector<double> q = numbers(flat->attr("quat"));
    ASSERT_EQ(q.size(), 4u);
    const Eigen::Matrix3d R = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
    // the true tensor from its principal decomposition
    const Eigen::Matrix3d I = p.principalAxes.toRotationMatrix() * p.principal.asDiagonal() *
                              p.principalAxes.toRotationMatrix().transpose();
    EXPECT_LT((I - model->inertia[1]).norm(), 1e-12);
    EXPECT_LT((R - p.principalAxes.toRotationMatrix()).norm(), 1e-15);
    const std::vector<double> d = numbers(flat->attr("diaginertia"));
    ASSERT_EQ(d.size(), 3u);
    EXPECT_GE(d[0] + d[1], d[2]);
    EXPECT_GE(d[0] + d[2], d[1]);
    EXPECT_GE(d[1] + d[2], d[0]);
}

TEST(Mjcf, BranchingTreeWithReversedJointsKeepsPadrobsPoses)
{
    // joints written child → parent (axisSign −1), T 1 and T 2 joints, tilted axes,
    // centres of mass off the origin: MuJoCo's qpos = θ must give Padrob's poses
    auto model = test::compileText(test::kZooModel);
    ASSERT_TRUE(model);
    const Exported e = exportModel(*model);
    ASSERT_TRUE(e.root());
    EXPECT_EQ(e.root()->all("body").size(), 7u);
    expectSamePoses(*model, e, Eigen::VectorXd::Zero(model->nb));
    Eigen::VectorXd theta(model->nb);
    for (int i = 0; i < model->nb; ++i) theta[i] = 0.3 - 0.17 * i;
    expectSamePoses(*model, e, theta);
    // a reversed joint's axis is −A of the child's side
    const MjcfNames names = mjcfNames(*model);
    const int shoulder = model->jointIndex(2);
    ASSERT_LT(model->axisSign[shoulder], 0);
    for (const Element* j : e.root()->all("joint")) {
        if (j->attr("name") != names.joint[shoulder]) continue;
        EXPECT_LT((vec(j->attr("axis")) + model->X_cj[shoulder].linear().col(0)).norm(), 1e-15);
    }
    // its initial rate VI 0.5 on joint 7 lands in the key's qvel
    const std::vector<double> qvel = numbers(e.root()->child("keyframe")->child("key")->attr("qvel"));
    ASSERT_EQ(qvel.size(), 7u);
    double sum = 0;
    for (double v : qvel) sum += v;
    EXPECT_EQ(sum, 0.5);
}

TEST(Mjcf, OneSidedLimitsAreOnlyNoted)
{
    auto model = example("incline_slider.pad");
    ASSERT_TRUE(model);
    const Exported e = exportModel(*model);
    ASSERT_TRUE(e.root());
    const Element* joint = e.root()->all("joint").at(0);
    EXPECT_EQ(joint->attr("type"), "slide");
    EXPECT_FALSE(joint->has("range"));
    EXPECT_LT((vec(joint->attr("axis")) - Eigen::Vector3d(1, 0, 0)).norm(), 1e-15);  // R2 in the block's frame
    std::string comments;
    for (const std::string& c : e.root()->all("body").at(0)->comments) comments += c;
    EXPECT_NE(comments.find("one-sided limit not exported"), std::string::npos) << comments;
    expectSamePoses(*model, e, Eigen::VectorXd::Constant(1, 0.7));

    MjcfOptions noLimits;
    noLimits.limits = false;
    const Exported f = exportModel(*example("liner_manipulator.pad"), noLimits);
    ASSERT_TRUE(f.root());
    for (const Element* j : f.root()->all("joint")) EXPECT_FALSE(j->has("range"));
}

TEST(Mjcf, LoopsAreRefused)
{
    for (const char* name : {"four_bar.pad", "slider_crank.pad", "excavator.pad"}) {
        auto model = example(name);
        ASSERT_TRUE(model) << name;
        std::string error;
        EXPECT_EQ(toMjcf(*model, error), "") << name;
        EXPECT_EQ(error.rfind("MJCF export needs a tree: the model closes 1 loop through joint ", 0), 0u) << error;
    }
    auto model = example("four_bar.pad");
    std::string error;
    toMjcf(*model, error);
    EXPECT_NE(error.find("\"" + model->cuts[0].name + "\""), std::string::npos) << error;
}

TEST(Mjcf, BadTimestepIsRefused)
{
    auto model = example("pendulum.pad");
    ASSERT_TRUE(model);
    for (double dt : {0.0, -1e-3, std::nan("")}) {
        MjcfOptions o;
        o.timestep = dt;
        std::string error;
        EXPECT_EQ(toMjcf(*model, o, error), "");
        EXPECT_NE(error, "");
    }
}

TEST(Mjcf, NamesAreSanitisedAndUnique)
{
    auto model = test::compileText(R"(
B 1 1 0.1 0.1 0.1 NAME "arm -- one <&>"
B 2 1 0.1 0.1 0.1 NAME "arm -- one <&>"
B 3 1 0.1 0.1 0.1
B 4 1 0.1 0.1 0.1 NAME "world"
C 1 NAME "Ñandú çava"
B1 0 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0
C 2 NAME "Ñandú çava"
B1 1 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 2 P2 0 0 0 A2 1 0 0 R2 0 1 0
C 3 NAME "日本"
B1 2 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 3 P2 0 0 0 A2 1 0 0 R2 0 1 0
C 4 NAME "joint3"
B1 3 P1 0 0 0 A1 1 0 0 R1 0 1 0
B2 4 P2 0 0 0 A2 1 0 0 R2 0 1 0
)");
    ASSERT_TRUE(model);
    const MjcfNames n = mjcfNames(*model);
    auto body = [&](int id) { return n.body[static_cast<std::size_t>(model->bodyIndex(id))]; };
    auto joint = [&](int id) { return n.joint[static_cast<std::size_t>(model->jointIndex(id))]; };
    EXPECT_EQ(body(1), "arm_--_one");
    EXPECT_EQ(body(2), "arm_--_one_2");
    EXPECT_EQ(body(3), "body3");
    EXPECT_EQ(body(4), "world_4");
    EXPECT_EQ(joint(1), "Nandu_cava");
    EXPECT_EQ(joint(2), "Nandu_cava_2");
    EXPECT_EQ(joint(3), "joint3");
    EXPECT_EQ(joint(4), "joint3_4");
    // and the text stays well-formed ("--" and "<&>" in comments and names)
    const Exported e = exportModel(*model);
    ASSERT_TRUE(e.root());
}

TEST(Mjcf, EveryBundledTreeModelExports)
{
    for (const char* name : {"pendulum.pad", "double_pendulum.pad", "incline_slider.pad", "knuckle_boom_crane.pad",
                             "liner_manipulator.pad", "liner_station.pad"}) {
        auto model = example(name);
        ASSERT_TRUE(model) << name;
        const Exported e = exportModel(*model);
        ASSERT_TRUE(e.root()) << name;
        EXPECT_EQ(e.root()->all("body").size(), static_cast<std::size_t>(model->nb)) << name;
        EXPECT_EQ(e.root()->all("joint").size(), static_cast<std::size_t>(model->nb)) << name;
        expectSamePoses(*model, e, Eigen::Map<const Eigen::VectorXd>(model->theta0.data(), model->nb));
    }
}

// CONTACT: the graphics become geoms in their bodies' frames, NOCONTACT ones visual,
// a TUBE a ring of boxes, the scene's graphics world geoms, the contact settings in
// <default>, the pair overlapping at the start excluded; without CONTACT none of it.
TEST(Mjcf, ContactWritesGeomsSettingsAndExcludes)
{
    const std::string text = "GRAVITY 0 0 -9.81\n"
                             "CONTACT MU 0.4\n"
                             "B 1 10 1 1 1 NAME \"arm\"\n"
                             "C 1 NAME \"pivot\"\n"
                             "B1 0 P1 0 0 1 A1 1 0 0 R1 0 1 0\n"
                             "B2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\n"
                             "G 1 B 1 BOX 0.2 0.4 0.6 POS 0 0.5 0\n"
                             "G 2 B 1 CYL 0.1 0.3 POS 0 0 0 AXIS 1 0 0 NOCONTACT\n"
                             "G 3 B 1 CONE 0.1 0.2 POS 0 1 0\n"
                             "G 4 B 0 CYL 0.05 0.5 POS 0 0 1 AXIS 1 0 0\n"  // the pin through the arm's hub
                             "G 5 B 0 TUBE 3 2.9 2 POS 0 0 0 AXIS 0 1 0\n";
    const CompiledModel compiled = compileText(text, "contact.pad");
    ASSERT_TRUE(compiled.model);
    ASSERT_TRUE(compiled.model->contact);
    const CompiledModel scene = compileText("G 7 B 0 SPHERE 0.25 POS 2 0 0\nG 8 B 0 BOX 1 1 1 POS 0 -3 0\n", "scene.pad");
    ASSERT_TRUE(scene.ok());
    const CompiledModel withScene = compileSpec(compiled.spec, &scene.spec);
    ASSERT_TRUE(withScene.model);
    MjcfOptions options;
    options.spec = &withScene.spec;
    options.scene = &scene.spec;
    const Exported e = exportModel(*withScene.model, options);
    ASSERT_TRUE(e.root());
    const Element* option = e.root()->child("option");
    ASSERT_TRUE(option && option->child("flag"));
    EXPECT_FALSE(option->child("flag")->has("contact"));  // contacts on
    EXPECT_EQ(option->child("flag")->attr("filterparent"), "disable");
    EXPECT_EQ(option->attr("cone"), "elliptic");
    const Element* defaults = e.root()->child("default");
    ASSERT_TRUE(defaults && defaults->child("geom"));
    EXPECT_EQ(numbers(defaults->child("geom")->attr("friction"))[0], 0.4);
    const std::vector<double> solref = numbers(defaults->child("geom")->attr("solref"));
    ASSERT_EQ(solref.size(), 2u);
    EXPECT_NEAR(solref[0], 1 / 300.0, 1e-12);  // 1/(ω ζ), ζ = 1 for E 0
    EXPECT_EQ(solref[1], 1);

    std::map<std::string, const Element*> geoms;
    for (const Element* g : e.root()->all("geom")) geoms[g->attr("name")] = g;
    ASSERT_TRUE(geoms.count("g1") && geoms.count("g2") && geoms.count("g3") && geoms.count("g4"));
    EXPECT_EQ(geoms["g1"]->parent->attr("name"), "arm");
    EXPECT_EQ(geoms["g1"]->attr("type"), "box");
    EXPECT_EQ(vec(geoms["g1"]->attr("size")), Eigen::Vector3d(0.1, 0.2, 0.3));
    EXPECT_EQ(vec(geoms["g1"]->attr("pos")), Eigen::Vector3d(0, 0.5, 0));
    EXPECT_EQ(geoms["g2"]->attr("contype"), "0");
    EXPECT_EQ(geoms["g2"]->attr("conaffinity"), "0");
    EXPECT_FALSE(geoms["g1"]->has("contype"));
    EXPECT_EQ(geoms["g3"]->attr("type"), "mesh");
    EXPECT_EQ(geoms["g4"]->parent->name, "worldbody");
    // the tube: a ring of boxes in the world, their centres on the mean radius
    int ring = 0;
    for (const auto& [name, g] : geoms) {
        if (name.rfind("g5_", 0) != 0) continue;
        ++ring;
        EXPECT_EQ(g->attr("type"), "box");
        const Eigen::Vector3d c = vec(g->attr("pos"));
        EXPECT_NEAR(std::hypot(c.x(), c.z()), 2.95, 1e-9) << name;
        EXPECT_NEAR(c.y(), 0, 1e-12) << name;
    }
    EXPECT_EQ(ring, mjcfTubeSegments(3));
    // the scene's
    ASSERT_TRUE(geoms.count("scene_g7") && geoms.count("scene_g8"));
    EXPECT_EQ(geoms["scene_g7"]->attr("type"), "sphere");
    EXPECT_EQ(geoms["scene_g7"]->parent->name, "worldbody");
    // the cone's vertices in <asset>
    ASSERT_TRUE(e.root()->child("asset"));
    EXPECT_EQ(e.root()->child("asset")->child("mesh")->attr("name"), "mesh_g3");
    // the pin G 4 is inside only G 2, which is NOCONTACT: the arm and the world may touch
    EXPECT_FALSE(e.root()->child("contact"));

    // a pin through the arm's box: the world and the arm never touch in MuJoCo
    const CompiledModel pinned = compileText(text + "G 6 B 0 CYL 0.05 1 POS 0 0.5 1 AXIS 1 0 0\n", "pinned.pad");
    ASSERT_TRUE(pinned.model);
    MjcfOptions pinnedOptions;
    pinnedOptions.spec = &pinned.spec;
    const Exported p = exportModel(*pinned.model, pinnedOptions);
    ASSERT_TRUE(p.root() && p.root()->child("contact"));
    const Element* exclude = p.root()->child("contact")->child("exclude");
    ASSERT_TRUE(exclude);
    EXPECT_EQ(exclude->attr("body1"), "arm");
    EXPECT_EQ(exclude->attr("body2"), "world");

    // without CONTACT, as before: no geoms, contacts off
    const CompiledModel plain = compileText(text.substr(0, text.find("CONTACT")) + text.substr(text.find("B 1 10")), "plain.pad");
    ASSERT_TRUE(plain.model);
    ASSERT_FALSE(plain.model->contact);
    MjcfOptions plainOptions;
    plainOptions.spec = &plain.spec;
    const Exported q = exportModel(*plain.model, plainOptions);
    ASSERT_TRUE(q.root());
    EXPECT_TRUE(q.root()->all("geom").empty());
    EXPECT_EQ(q.root()->child("option")->child("flag")->attr("contact"), "disable");
}

}  // namespace
}  // namespace solver
