// parse → writeModel → parse gives the same model: every field of ModelSpec except
// the source positions (which keywords were written, FieldPositions::at's keys, is
// compared; where they were is not). Values must be exact: the writer prints every
// number in its shortest round-trip form.

#include "model_texts.h"
#include "solver/pipeline.h"
#include "solver/parse/parser.h"
#include "solver/parse/writer.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace solver;
using solver::test::kAppendixA;
using solver::test::kEveryStatement;

namespace {

std::string str(double v)
{
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

std::string str(const Eigen::Vector3d& v) { return "(" + str(v.x()) + ", " + str(v.y()) + ", " + str(v.z()) + ")"; }

/// Finds the first difference between two specs, as "path: a vs b".
class SpecComparer {
public:
    std::string firstDifference(const ModelSpec& a, const ModelSpec& b)
    {
        m_diff.clear();
        same("file", a.file, b.file);
        same("hasGravity", a.hasGravity, b.hasGravity);
        same("gravity", a.gravity, b.gravity);
        same("hasRestitution", a.hasRestitution, b.hasRestitution);
        same("restitution", a.restitution, b.restitution);
        list("bodies", a.bodies, b.bodies, [&](const std::string& p, const BodySpec& x, const BodySpec& y) {
            same(p + ".id", x.id, y.id);
            same(p + ".hasMass", x.hasMass, y.hasMass);
            same(p + ".mass", x.mass, y.mass);
            same(p + ".inertia", x.inertia, y.inertia);
            same(p + ".hasProducts", x.hasProducts, y.hasProducts);
            same(p + ".products", x.products, y.products);
            same(p + ".hasCg", x.hasCg, y.hasCg);
            same(p + ".cg", x.cg, y.cg);
            same(p + ".name", x.name, y.name);
            fields(p + ".src", x.src, y.src);
        });
        list("joints", a.joints, b.joints, [&](const std::string& p, const JointSpec& x, const JointSpec& y) {
            same(p + ".id", x.id, y.id);
            same(p + ".type", static_cast<int>(x.type), static_cast<int>(y.type));
            same(p + ".typeWritten", x.typeWritten, y.typeWritten);
            same(p + ".ll", x.ll, y.ll);
            same(p + ".ul", x.ul, y.ul);
            same(p + ".qi", x.qi, y.qi);
            same(p + ".vi", x.vi, y.vi);
            same(p + ".name", x.name, y.name);
            side(p + ".side1", x.side1, y.side1);
            side(p + ".side2", x.side2, y.side2);
            same(p + ".hasCl", x.hasCl, y.hasCl);
            same(p + ".cl1", x.cl1, y.cl1);
            same(p + ".cl2", x.cl2, y.cl2);
            fields(p + ".src", x.src, y.src);
        });
        list("drives", a.drives, b.drives, [&](const std::string& p, const DriveSpec& x, const DriveSpec& y) {
            same(p + ".joint", x.joint, y.joint);
            same(p + ".kind", static_cast<int>(x.kind), static_cast<int>(y.kind));
            same(p + ".params.size", x.params.size(), y.params.size());
            for (std::size_t k = 0; k < std::min(x.params.size(), y.params.size()); ++k) {
                same(p + ".params[" + std::to_string(k) + "].key", x.params[k].first, y.params[k].first);
                same(p + ".params[" + std::to_string(k) + "].value", x.params[k].second, y.params[k].second);
            }
            fields(p + ".src", x.src, y.src);
        });
        list("forces", a.forces, b.forces, [&](const std::string& p, const ForceSpec& x, const ForceSpec& y) {
            same(p + ".id", x.id, y.id);
            same(p + ".kind", static_cast<int>(x.kind), static_cast<int>(y.kind));
            same(p + ".body", x.body, y.body);
            same(p + ".body2", x.body2, y.body2);
            same(p + ".joint", x.joint, y.joint);
            same(p + ".point", x.point, y.point);
            same(p + ".point2", x.point2, y.point2);
            same(p + ".dir", x.dir, y.dir);
            same(p + ".local", x.local, y.local);
            magnitude(p + ".mag", x.mag, y.mag);
            same(p + ".stiffness", x.stiffness, y.stiffness);
            same(p + ".restLength", x.restLength, y.restLength);
            same(p + ".damping", x.damping, y.damping);
            same(p + ".hasDamping", x.hasDamping, y.hasDamping);
            same(p + ".area", x.area, y.area);
            same(p + ".cd", x.cd, y.cd);
            same(p + ".cl", x.cl, y.cl);
            same(p + ".rho", x.rho, y.rho);
            same(p + ".hasCl", x.hasCl, y.hasCl);
            same(p + ".hasRho", x.hasRho, y.hasRho);
            fields(p + ".src", x.src, y.src);
        });
        list("graphics", a.graphics, b.graphics, [&](const std::string& p, const GraphicSpec& x, const GraphicSpec& y) {
            same(p + ".id", x.id, y.id);
            same(p + ".body", x.body, y.body);
            same(p + ".shape", static_cast<int>(x.shape), static_cast<int>(y.shape));
            same(p + ".dims.size", x.dims.size(), y.dims.size());
            for (std::size_t k = 0; k < std::min(x.dims.size(), y.dims.size()); ++k) {
                same(p + ".dims[" + std::to_string(k) + "]", x.dims[k], y.dims[k]);
            }
            same(p + ".meshFile", x.meshFile, y.meshFile);
            same(p + ".scale", x.scale, y.scale);
            same(p + ".hasScale", x.hasScale, y.hasScale);
            same(p + ".position", x.position, y.position);
            same(p + ".hasPosition", x.hasPosition, y.hasPosition);
            same(p + ".axis", x.axis, y.axis);
            same(p + ".hasAxis", x.hasAxis, y.hasAxis);
            same(p + ".rotAxis", x.rotAxis, y.rotAxis);
            same(p + ".rotDeg", x.rotDeg, y.rotDeg);
            same(p + ".hasRot", x.hasRot, y.hasRot);
            same(p + ".color", x.color, y.color);
            same(p + ".hasColor", x.hasColor, y.hasColor);
            same(p + ".mass", x.mass, y.mass);
            same(p + ".rho", x.rho, y.rho);
            fields(p + ".src", x.src, y.src);
        });
        return m_diff;
    }

private:
    std::string m_diff;

    void differ(const std::string& path, const std::string& a, const std::string& b)
    {
        if (m_diff.empty()) m_diff = path + ": " + a + " vs " + b;
    }

    void same(const std::string& path, bool a, bool b)
    {
        if (a != b) differ(path, a ? "true" : "false", b ? "true" : "false");
    }
    void same(const std::string& path, int a, int b)
    {
        if (a != b) differ(path, std::to_string(a), std::to_string(b));
    }
    void same(const std::string& path, std::size_t a, std::size_t b)
    {
        if (a != b) differ(path, std::to_string(a), std::to_string(b));
    }
    void same(const std::string& path, double a, double b)
    {
        // exact; NaN never equals (a model has no NaN)
        if (!(a == b)) differ(path, str(a), str(b));
    }
    void same(const std::string& path, const std::string& a, const std::string& b)
    {
        if (a != b) differ(path, "\"" + a + "\"", "\"" + b + "\"");
    }
    void same(const std::string& path, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
    {
        if (!(a.x() == b.x() && a.y() == b.y() && a.z() == b.z())) differ(path, str(a), str(b));
    }
    void same(const std::string& path, const std::optional<double>& a, const std::optional<double>& b)
    {
        if (a.has_value() != b.has_value()) {
            differ(path, a ? str(*a) : "none", b ? str(*b) : "none");
        } else if (a) {
            same(path, *a, *b);
        }
    }

    /// Which keywords were written and whether the statement was complete; not where.
    void fields(const std::string& path, const FieldPositions& a, const FieldPositions& b)
    {
        same(path + ".complete", a.complete, b.complete);
        std::string ka, kb;
        for (const auto& [k, pos] : a.at) ka += k + " ";
        for (const auto& [k, pos] : b.at) kb += k + " ";
        same(path + ".at (keys)", ka, kb);
    }

    void side(const std::string& p, const JointSide& x, const JointSide& y)
    {
        same(p + ".body", x.body, y.body);
        same(p + ".p", x.p, y.p);
        same(p + ".a", x.a, y.a);
        same(p + ".r", x.r, y.r);
        same(p + ".present", x.present, y.present);
        fields(p + ".src", x.src, y.src);
    }

    void magnitude(const std::string& p, const MagnitudeSpec& x, const MagnitudeSpec& y)
    {
        same(p + ".kind", static_cast<int>(x.kind), static_cast<int>(y.kind));
        same(p + ".value", x.value, y.value);
        same(p + ".amplitude", x.amplitude, y.amplitude);
        same(p + ".frequency", x.frequency, y.frequency);
        same(p + ".phase", x.phase, y.phase);
        same(p + ".offset", x.offset, y.offset);
        same(p + ".hasOffset", x.hasOffset, y.hasOffset);
        same(p + ".joint", x.joint, y.joint);
        same(p + ".table.size", x.table.size(), y.table.size());
        for (std::size_t k = 0; k < std::min(x.table.size(), y.table.size()); ++k) {
            same(p + ".table[" + std::to_string(k) + "].x", x.table[k].first, y.table[k].first);
            same(p + ".table[" + std::to_string(k) + "].y", x.table[k].second, y.table[k].second);
        }
    }

    template <typename T, typename F>
    void list(const std::string& name, const std::vector<T>& a, const std::vector<T>& b, F each)
    {
        same(name + ".size", a.size(), b.size());
        for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
            each(name + "[" + std::to_string(k) + "]", a[k], b[k]);
        }
    }
};

std::string firstDifference(const ModelSpec& a, const ModelSpec& b) { return SpecComparer().firstDifference(a, b); }

std::string listing(const Diagnostics& diags)
{
    std::string s;
    for (const Diagnostic& d : diags) s += "  " + d.format() + "\n";
    return s.empty() ? "  (none)\n" : s;
}

/// Parses `text`, writes it, parses the result: both parses must be free of
/// diagnostics and give the same spec, and writing again gives the same text.
void expectRoundTrip(const std::string& text)
{
    Diagnostics d1("m.pad");
    ModelSpec first = parse::parseModel(text, d1);
    first.file = "m.pad";
    ASSERT_TRUE(d1.empty()) << listing(d1);
    const std::string written = parse::writeModel(first);
    Diagnostics d2("m.pad");
    ModelSpec second = parse::parseModel(written, d2);
    second.file = "m.pad";
    ASSERT_TRUE(d2.empty()) << listing(d2) << "written:\n" << written;
    EXPECT_EQ(firstDifference(first, second), "") << "written:\n" << written;
    EXPECT_EQ(parse::writeModel(second), written);
}


}  // namespace

TEST(RoundTrip, EveryStatementOptionAndShape)
{
    // the model is valid (with its mesh in place), so the round trip covers a real model
    const test::TempDir tmp("roundtrip_test");
    tmp.write("meshes/part.stl", "solid part\nendsolid part\n");
    CompiledModel m = compileText(kEveryStatement, tmp.path("m.pad"));
    EXPECT_TRUE(m.diagnostics.empty()) << listing(m.diagnostics);

    expectRoundTrip(kEveryStatement);

    // and it really holds what it says: a spot check of the parsed values
    Diagnostics d;
    ModelSpec s = parse::parseModel(kEveryStatement, d);
    EXPECT_EQ(s.bodies.size(), 6u);
    EXPECT_EQ(s.joints.size(), 5u);
    EXPECT_EQ(s.drives.size(), 5u);
    EXPECT_EQ(s.forces.size(), 10u);
    EXPECT_EQ(s.graphics.size(), 9u);
    EXPECT_EQ(s.body(2)->name, "arm \"A\" \\ muñeca");
    EXPECT_EQ(s.body(5)->mass, 450.0);
    EXPECT_EQ(s.joint(4)->ll, -90 * std::numbers::pi / 180);
    EXPECT_EQ(s.joint(4)->vi, 0.5 * std::numbers::pi / 180);
}

TEST(RoundTrip, AppendixACorrected)
{
    expectRoundTrip(solver::test::appendixACorrected());
}

TEST(RoundTrip, AwkwardNumbersAreExact)
{
    const double third = 1.0 / 3.0;
    ModelSpec spec;
    spec.hasGravity = true;
    spec.gravity = {third, -std::numeric_limits<double>::min(), std::numeric_limits<double>::max()};
    BodySpec b;
    b.id = 1;
    b.hasMass = true;
    b.mass = 0.1 + 0.2;
    b.inertia = {std::numeric_limits<double>::denorm_min(), 1e-300, 123456789.123456789};
    b.hasCg = true;
    b.cg = {-0.0, 5e-324, -1.7976931348623157e308};
    b.name = "tab\there, quote \" and backslash \\";
    b.src.at = {{"m", {}}, {"I", {}}, {"CG", {}}, {"NAME", {}}};  // the keywords the text will have
    spec.bodies.push_back(b);
    const std::string written = parse::writeModel(spec);
    Diagnostics d("m.pad");
    ModelSpec back = parse::parseModel(written, d);
    ASSERT_TRUE(d.empty()) << listing(d) << written;
    EXPECT_EQ(firstDifference(spec, back), "") << written;
    EXPECT_EQ(parse::writeModel(back), written);
}

TEST(RoundTrip, EveryModelInModelsFolder)
{
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(PADROB_SOURCE_DIR) / "models";
    int tried = 0;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        if (entry.path().extension() != ".pad") continue;
        CompiledModel m = compileFile(entry.path().string());
        SCOPED_TRACE(entry.path().string());
        // a shipped model must load
        if (!m.ok()) {
            ADD_FAILURE() << entry.path() << " does not load";
            continue;
        }
        std::ifstream in(entry.path(), std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        expectRoundTrip(text.str());
        ++tried;
    }
    ASSERT_FALSE(ec) << dir << ": " << ec.message();
    EXPECT_GT(tried, 0) << "no model in " << dir;
}

// ---- the comparison itself must see every difference ------------------------------

TEST(RoundTrip, ComparerSeesEveryField)
{
    Diagnostics d;
    const ModelSpec base = parse::parseModel(kEveryStatement, d);
    ASSERT_TRUE(d.empty());
    ASSERT_EQ(firstDifference(base, base), "");

    struct Mutation {
        std::string expected;  ///< the start of the reported difference
        std::function<void(ModelSpec&)> apply;
    };
    const std::vector<Mutation> mutations = {
        {"file", [](ModelSpec& s) { s.file = "other.pad"; }},
        {"hasGravity", [](ModelSpec& s) { s.hasGravity = false; }},
        {"gravity", [](ModelSpec& s) { s.gravity.z() = -9.80665; }},
        {"hasRestitution", [](ModelSpec& s) { s.hasRestitution = !s.hasRestitution; }},
        {"restitution", [](ModelSpec& s) { s.restitution = 0.25; }},
        {"bodies.size", [](ModelSpec& s) { s.bodies.pop_back(); }},
        {"bodies[2].id", [](ModelSpec& s) { s.bodies[2].id = 7; }},
        {"bodies[2].hasMass", [](ModelSpec& s) { s.bodies[2].hasMass = false; }},
        {"bodies[2].mass", [](ModelSpec& s) { s.bodies[2].mass = std::nextafter(12.5, 13.0); }},
        {"bodies[2].inertia", [](ModelSpec& s) { s.bodies[2].inertia.y() = 0.41; }},
        {"bodies[3].hasProducts", [](ModelSpec& s) { s.bodies[3].hasProducts = false; }},
        {"bodies[3].products", [](ModelSpec& s) { s.bodies[3].products.z() = 0; }},
        {"bodies[2].hasCg", [](ModelSpec& s) { s.bodies[2].hasCg = false; }},
        {"bodies[2].cg", [](ModelSpec& s) { s.bodies[2].cg.x() = 1; }},
        {"bodies[2].name", [](ModelSpec& s) { s.bodies[2].name = "arm"; }},
        {"bodies[2].src.complete", [](ModelSpec& s) { s.bodies[2].src.complete = false; }},
        {"bodies[2].src.at (keys)", [](ModelSpec& s) { s.bodies[2].src.at.erase("CG"); }},
        {"joints[0].id", [](ModelSpec& s) { s.joints[0].id = 9; }},
        {"joints[2].type", [](ModelSpec& s) { s.joints[2].type = JointType::Revolute; }},
        {"joints[0].typeWritten", [](ModelSpec& s) { s.joints[0].typeWritten = true; }},
        {"joints[2].ll", [](ModelSpec& s) { s.joints[2].ll.reset(); }},
        {"joints[2].ul", [](ModelSpec& s) { s.joints[2].ul = 1.0; }},
        {"joints[2].qi", [](ModelSpec& s) { s.joints[2].qi = 0.31; }},
        {"joints[2].vi", [](ModelSpec& s) { s.joints[2].vi.reset(); }},
        {"joints[0].name", [](ModelSpec& s) { s.joints[0].name.clear(); }},
        {"joints[0].side1.body", [](ModelSpec& s) { s.joints[0].side1.body = 2; }},
        {"joints[0].side1.p", [](ModelSpec& s) { s.joints[0].side1.p.x() = 0.5; }},
        {"joints[0].side2.a", [](ModelSpec& s) { s.joints[0].side2.a.z() = 2; }},
        {"joints[0].side2.r", [](ModelSpec& s) { s.joints[0].side2.r.y() = -1; }},
        {"joints[0].side2.present", [](ModelSpec& s) { s.joints[0].side2.present = false; }},
        {"joints[0].side1.src.complete", [](ModelSpec& s) { s.joints[0].side1.src.complete = false; }},
        {"joints[1].hasCl", [](ModelSpec& s) { s.joints[1].hasCl = false; }},
        {"joints[1].cl1", [](ModelSpec& s) { s.joints[1].cl1.z() = -0.3; }},
        {"joints[1].cl2", [](ModelSpec& s) { s.joints[1].cl2.y() = 0.6; }},
        {"joints[1].src.at (keys)", [](ModelSpec& s) { s.joints[1].src.at.erase("CL2"); }},
        {"drives[0].joint", [](ModelSpec& s) { s.drives[0].joint = 2; }},
        {"drives[0].kind", [](ModelSpec& s) { s.drives[0].kind = DriveKind::Servo; }},
        {"drives[0].params.size", [](ModelSpec& s) { s.drives[0].params.pop_back(); }},
        {"drives[0].params[1].key", [](ModelSpec& s) { s.drives[0].params[1].first = "FMIN"; }},
        {"drives[0].params[1].value", [](ModelSpec& s) { s.drives[0].params[1].second = 0.25; }},
        {"forces[0].id", [](ModelSpec& s) { s.forces[0].id = 11; }},
        {"forces[0].kind", [](ModelSpec& s) { s.forces[0].kind = ForceKind::Torque; }},
        {"forces[0].body", [](ModelSpec& s) { s.forces[0].body = 3; }},
        {"forces[5].body2", [](ModelSpec& s) { s.forces[5].body2 = 2; }},
        {"forces[3].joint", [](ModelSpec& s) { s.forces[3].joint = 1; }},
        {"forces[0].point", [](ModelSpec& s) { s.forces[0].point.y() = 0.4; }},
        {"forces[5].point2", [](ModelSpec& s) { s.forces[5].point2.x() = 0.1; }},
        {"forces[0].dir", [](ModelSpec& s) { s.forces[0].dir.z() = 1; }},
        {"forces[1].local", [](ModelSpec& s) { s.forces[1].local = false; }},
        {"forces[0].mag.kind", [](ModelSpec& s) { s.forces[0].mag.kind = MagnitudeSpec::Kind::Sine; }},
        {"forces[0].mag.value", [](ModelSpec& s) { s.forces[0].mag.value = 999; }},
        {"forces[1].mag.amplitude", [](ModelSpec& s) { s.forces[1].mag.amplitude = 5; }},
        {"forces[1].mag.frequency", [](ModelSpec& s) { s.forces[1].mag.frequency = 1; }},
        {"forces[1].mag.phase", [](ModelSpec& s) { s.forces[1].mag.phase = 0; }},
        {"forces[2].mag.offset", [](ModelSpec& s) { s.forces[2].mag.offset = 0; }},
        {"forces[2].mag.hasOffset", [](ModelSpec& s) { s.forces[2].mag.hasOffset = false; }},
        {"forces[4].mag.joint", [](ModelSpec& s) { s.forces[4].mag.joint = 2; }},
        {"forces[3].mag.table.size", [](ModelSpec& s) { s.forces[3].mag.table.pop_back(); }},
        {"forces[3].mag.table[2].x", [](ModelSpec& s) { s.forces[3].mag.table[2].first = 3; }},
        {"forces[3].mag.table[2].y", [](ModelSpec& s) { s.forces[3].mag.table[2].second = 50; }},
        {"forces[5].stiffness", [](ModelSpec& s) { s.forces[5].stiffness = 1; }},
        {"forces[5].restLength", [](ModelSpec& s) { s.forces[5].restLength = 1; }},
        {"forces[5].damping", [](ModelSpec& s) { s.forces[5].damping = 1; }},
        {"forces[5].hasDamping", [](ModelSpec& s) { s.forces[5].hasDamping = false; }},
        {"forces[7].area", [](ModelSpec& s) { s.forces[7].area = 1; }},
        {"forces[7].cd", [](ModelSpec& s) { s.forces[7].cd = 1; }},
        {"forces[7].cl", [](ModelSpec& s) { s.forces[7].cl = 1; }},
        {"forces[7].rho", [](ModelSpec& s) { s.forces[7].rho = 1; }},
        {"forces[7].hasCl", [](ModelSpec& s) { s.forces[7].hasCl = false; }},
        {"forces[7].hasRho", [](ModelSpec& s) { s.forces[7].hasRho = false; }},
        {"forces[0].src.at (keys)", [](ModelSpec& s) { s.forces[0].src.at["LOCAL"] = {}; }},
        {"graphics[0].id", [](ModelSpec& s) { s.graphics[0].id = 99; }},
        {"graphics[0].body", [](ModelSpec& s) { s.graphics[0].body = 1; }},
        {"graphics[0].shape", [](ModelSpec& s) { s.graphics[0].shape = ShapeKind::Ellipsoid; }},
        {"graphics[0].dims.size", [](ModelSpec& s) { s.graphics[0].dims.pop_back(); }},
        {"graphics[0].dims[1]", [](ModelSpec& s) { s.graphics[0].dims[1] = 1.3; }},
        {"graphics[7].meshFile", [](ModelSpec& s) { s.graphics[7].meshFile = "part.stl"; }},
        {"graphics[7].scale", [](ModelSpec& s) { s.graphics[7].scale = 1; }},
        {"graphics[7].hasScale", [](ModelSpec& s) { s.graphics[7].hasScale = false; }},
        {"graphics[0].position", [](ModelSpec& s) { s.graphics[0].position.z() = 0; }},
        {"graphics[0].hasPosition", [](ModelSpec& s) { s.graphics[0].hasPosition = false; }},
        {"graphics[1].axis", [](ModelSpec& s) { s.graphics[1].axis = Eigen::Vector3d::UnitY(); }},
        {"graphics[1].hasAxis", [](ModelSpec& s) { s.graphics[1].hasAxis = false; }},
        {"graphics[4].rotAxis", [](ModelSpec& s) { s.graphics[4].rotAxis = Eigen::Vector3d::UnitX(); }},
        {"graphics[4].rotDeg", [](ModelSpec& s) { s.graphics[4].rotDeg = 45; }},
        {"graphics[4].hasRot", [](ModelSpec& s) { s.graphics[4].hasRot = false; }},
        {"graphics[0].color", [](ModelSpec& s) { s.graphics[0].color.x() = 0.5; }},
        {"graphics[0].hasColor", [](ModelSpec& s) { s.graphics[0].hasColor = false; }},
        {"graphics[3].mass", [](ModelSpec& s) { s.graphics[3].mass.reset(); }},
        {"graphics[2].rho", [](ModelSpec& s) { s.graphics[2].rho = 2700.0; }},
        {"graphics[8].src.complete", [](ModelSpec& s) { s.graphics[8].src.complete = false; }},
    };
    for (const Mutation& m : mutations) {
        ModelSpec changed = base;
        m.apply(changed);
        const std::string diff = firstDifference(base, changed);
        EXPECT_EQ(diff.substr(0, m.expected.size() + 2), m.expected + ": ") << "got: " << diff;
    }
    // positions alone are not a difference
    ModelSpec moved = base;
    moved.bodies[2].src.pos.line += 10;
    moved.bodies[2].src.at["CG"].column += 3;
    moved.gravityPos.line = 40;
    moved.forces[0].mag.pos.column = 1;
    EXPECT_EQ(firstDifference(base, moved), "");
}
