#include "solver/io/mjcf.h"

#include "solver/inertia/solid_inertia.h"
#include "solver/inertia/triangle_mesh.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>

namespace solver {

namespace {

/// Shortest round-trip text of v, C locale; "0" for ±0.
std::string num(double v)
{
    if (v == 0) return "0";
    char buf[32];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
    (void)ec;
    return std::string(buf, p);
}

/// A geometric value (a position [m], a unit vector's component): rounding noise
/// below 1e-15 is written as 0.
std::string geo(double v) { return num(std::abs(v) < 1e-15 ? 0.0 : v); }

std::string vec3(const Eigen::Vector3d& v, bool geometric = true)
{
    auto f = geometric ? geo : num;
    return f(v.x()) + " " + f(v.y()) + " " + f(v.z());
}

/// A value with 6 significant digits, for comments.
std::string short6(double v)
{
    if (v == 0) return "0";
    char buf[32];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 6);
    (void)ec;
    return std::string(buf, p);
}

/// Text made safe inside an XML comment: no "--", not ending in '-'.
std::string commentSafe(std::string s)
{
    for (std::size_t i; (i = s.find("--")) != std::string::npos;) s.replace(i, 2, "- -");
    if (!s.empty() && s.back() == '-') s += ' ';
    return s;
}

/// Text escaped for an XML attribute value in double quotes.
std::string attr(const std::string& s)
{
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

/// ASCII for a Latin-1 letter U+00C0 … U+00FF ("" for × and ÷).
const char* latin1Ascii(unsigned code)
{
    static const std::array<const char*, 64> table = {
        "A", "A", "A", "A", "A", "A", "AE", "C", "E", "E", "E", "E", "I", "I", "I", "I",   // C0–CF
        "D", "N", "O", "O", "O", "O", "O", "",  "O", "U", "U", "U", "U", "Y", "TH", "ss",  // D0–DF
        "a", "a", "a", "a", "a", "a", "ae", "c", "e", "e", "e", "e", "i", "i", "i", "i",   // E0–EF
        "d", "n", "o", "o", "o", "o", "o", "",  "o", "u", "u", "u", "u", "y", "th", "y",   // F0–FF
    };
    return code >= 0xC0 && code <= 0xFF ? table[code - 0xC0] : "";
}

/// A name as MJCF gets it (see MjcfNames); "" when nothing is left.
std::string sanitize(const std::string& name)
{
    std::string out;
    auto put = [&](char c) {
        if (c == '_' && (out.empty() || out.back() == '_')) return;
        out += c;
    };
    for (std::size_t i = 0; i < name.size();) {
        const auto c = static_cast<unsigned char>(name[i]);
        if (c < 0x80) {
            const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                              c == '-' || c == '.';
            put(keep ? static_cast<char>(c) : '_');
            ++i;
            continue;
        }
        // a UTF-8 sequence: its length from the lead byte, then the continuation bytes
        std::size_t len = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
        unsigned code = 0;
        if (len == 2 && i + 1 < name.size()) {
            code = ((c & 0x1Fu) << 6) | (static_cast<unsigned char>(name[i + 1]) & 0x3Fu);
        }
        const char* ascii = latin1Ascii(code);
        if (*ascii) {
            for (const char* p = ascii; *p; ++p) put(*p);
        } else {
            put('_');
        }
        i += len;
    }
    while (!out.empty() && out.back() == '_') out.pop_back();
    return out;
}

/// `base`, or `base_<id>` (then `base_<id>_2`, …) when taken; records it as taken.
std::string unique(std::string base, int id, std::set<std::string>& taken)
{
    if (taken.insert(base).second) return base;
    const std::string withId = base + "_" + std::to_string(id);
    std::string name = withId;
    for (int k = 2; !taken.insert(name).second; ++k) name = withId + "_" + std::to_string(k);
    return name;
}

const char* driveName(DriveType t)
{
    switch (t) {
    case DriveType::Hydraulic: return "hydraulic drive (HYD, with its relief valve)";
    case DriveType::Motor: return "motor drive (MOTOR)";
    case DriveType::Pneumatic: return "pneumatic drive (PNEU)";
    case DriveType::Servo: return "servo drive (SERVO)";
    case DriveType::FluidPower: return "fluid-power drive (CYL/HMOTOR: valve, chambers and pump)";
    case DriveType::None: break;
    }
    return "";
}

const char* jointTypeText(JointType t)
{
    switch (t) {
    case JointType::Revolute: return "T 0, revolute: hinge, qpos = angle [rad]";
    case JointType::Actuator:
        return "T 1, pivoted actuator: hinge, qpos = the joint angle [rad], not the cylinder length";
    case JointType::Prismatic: return "T 2, prismatic: slide along R, qpos = displacement [m]";
    case JointType::Free: return "T 3, free body: freejoint, qpos = position and quaternion (w x y z)";
    }
    return "";
}

std::string quoted(const std::string& name) { return name.empty() ? std::string() : " \"" + name + "\""; }

}  // namespace

MjcfNames mjcfNames(const Model& model)
{
    MjcfNames names;
    std::set<std::string> bodies{"world"}, joints;
    for (int i = 0; i < model.nb; ++i) {
        std::string b = sanitize(model.bodyName[i]);
        if (b.empty()) b = "body" + std::to_string(model.bodyId[i]);
        names.body.push_back(unique(b, model.bodyId[i], bodies));
        std::string j = sanitize(model.jointName[i]);
        if (j.empty()) j = "joint" + std::to_string(model.jointId[i]);
        names.joint.push_back(unique(j, model.jointId[i], joints));
    }
    return names;
}

MjcfInertial mjcfInertial(const Model& model, int body)
{
    MjcfInertial r;
    r.mass = model.mass[body];
    r.com = model.com[body];
    const Eigen::Matrix3d& I = model.inertia[body];
    r.diagonal = I(0, 1) == 0 && I(0, 2) == 0 && I(1, 2) == 0 && I(1, 0) == 0 && I(2, 0) == 0 && I(2, 1) == 0;
    if (r.diagonal) {
        r.principal = I.diagonal();
    } else {
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(I);
        Eigen::Matrix3d axes = eig.eigenvectors();
        if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
        r.principal = eig.eigenvalues().cwiseMax(0.0);  // a PSD tensor: below 0 is rounding
        r.principalAxes = Eigen::Quaterniond(axes).normalized();
        if (r.principalAxes.w() < 0) r.principalAxes.coeffs() = -r.principalAxes.coeffs();
    }

    // the mass
    r.placeholderMass = !(r.mass >= kMjcfMinMass);
    r.writtenMass = r.placeholderMass ? kMjcfMinMass : r.mass;

    // the moments, sorted a ≤ b ≤ c: the triangle inequality first, then the floor
    std::array<int, 3> k{0, 1, 2};
    std::sort(k.begin(), k.end(), [&](int x, int y) { return r.principal[x] < r.principal[y]; });
    const int a = k[0], b = k[1], c = k[2];
    Eigen::Vector3d w = r.principal;
    const double delta = w[c] - w[a] - w[b];
    if (delta > 0) {
        w[a] += delta / 3;
        w[b] += delta / 3;
        w[c] = w[a] + w[b];  // exactly, as MuJoCo will add them
    }
    for (int i = 0; i < 3; ++i) w[i] = std::max(w[i], kMjcfMinInertia);
    if (w[a] + w[b] < w[c]) w[c] = w[a] + w[b];
    r.writtenPrincipal = w;
    r.placeholderInertia = w != r.principal;
    return r;
}

MjcfContact mjcfContact(const CompiledContact& law, double timestep)
{
    MjcfContact c;
    c.mu = law.mu;
    // the linear spring–damper's restitution e = exp(−ζπ/√(1 − ζ²)), inverted
    if (law.restitution > 0) {
        const double l = std::log(law.restitution);
        c.dampratio = -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
    }
    c.timeconst = std::max(1 / (law.omega * c.dampratio), 2 * timestep);
    return c;
}

int mjcfTubeSegments(double outerRadius)
{
    // boxes about 0.7 m wide round a mill's shell, at least 12 round a pipe
    return std::clamp(static_cast<int>(std::ceil(2 * std::numbers::pi * outerRadius / 0.7)), 12, 48);
}

namespace {

/// Whether MuJoCo may refuse `in` written as fullinertia (its own eigen-decomposition
/// is accurate to about 1e-15 relative): moments within 1e-12 of the triangle
/// inequality or of the floor are written in principal form instead.
bool needsPrincipalForm(const MjcfInertial& in)
{
    if (in.placeholderInertia) return true;
    const Eigen::Vector3d& p = in.principal;
    const double largest = p.maxCoeff(), smallest = p.minCoeff();
    if (smallest < kMjcfMinInertia + 1e-9 * largest) return true;
    const double sum = p.sum();
    return sum - 2 * largest < 1e-12 * sum;  // I1 + I2 − I3 < 1e-12 (I1 + I2 + I3)
}

/// The tree's children of each body (−1 = the world at index 0), in tree order.
std::vector<std::vector<int>> childrenOf(const Model& model)
{
    std::vector<std::vector<int>> children(static_cast<std::size_t>(model.nb) + 1);
    for (int i = 0; i < model.nb; ++i) children[static_cast<std::size_t>(model.parent[i] + 1)].push_back(i);
    return children;
}

class Writer {
public:
    Writer(const Model& model, const MjcfOptions& options)
        : m_model(model), m_options(options), m_names(mjcfNames(model)), m_children(childrenOf(model))
    {
    }

    std::string run()
    {
        header();
        m_out += "<mujoco model=\"" + attr(modelName()) + "\">\n";
        m_out += "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n";
        m_out += "  <option timestep=\"" + num(m_options.timestep) + "\" gravity=\"" +
                 vec3(m_model.gravity, false) + "\" integrator=\"RK4\"" + (contacts() ? " cone=\"elliptic\"" : "") + ">\n";
        m_out += contacts() ? "    <flag filterparent=\"disable\"/>\n" : "    <flag contact=\"disable\"/>\n";
        m_out += "  </option>\n";
        if (contacts()) contactDefaults();
        const std::size_t assetsAt = m_out.size();
        m_out += "  <worldbody>\n";
        if (contacts()) {
            for (const GraphicSpec& g : m_options.spec->graphics)
                if (g.body == 0) geom(g, *m_options.spec, false, "    ");
            if (m_options.scene)
                for (const GraphicSpec& g : m_options.scene->graphics)
                    if (g.body == 0) geom(g, *m_options.scene, true, "    ");
        }
        for (int i : m_children[0]) body(i, 2);
        m_out += "  </worldbody>\n";
        if (contacts()) excludes();
        keyframe();
        m_out += "</mujoco>\n";
        if (!m_assets.empty()) m_out.insert(assetsAt, "  <asset>\n" + m_assets + "  </asset>\n");
        return std::move(m_out);
    }

private:
    const Model& m_model;
    const MjcfOptions& m_options;
    MjcfNames m_names;
    std::vector<std::vector<int>> m_children;
    std::vector<int> m_order;  // bodies (= joints) in the order written: MuJoCo's qpos order
    std::string m_out;
    std::string m_assets;  // <mesh> elements (cones, prisms, meshes)

    /// Geoms and contacts are written: the model has CONTACT and the spec is given.
    bool contacts() const { return m_model.contact && m_options.spec; }

    void contactDefaults()
    {
        const MjcfContact c = mjcfContact(*m_model.contact, m_options.timestep);
        m_out += "  <!-- " +
                 commentSafe("CONTACT MU " + short6(m_model.contact->mu) + " E " + short6(m_model.contact->restitution) +
                             ": friction mu; solref = (1/(omega zeta), zeta) so that MuJoCo's contact frequency is "
                             "Padrob's omega " + short6(m_model.contact->omega) + " rad/s (docs/contact.md)") +
                 " -->\n";
        m_out += "  <default>\n";
        m_out += "    <geom condim=\"3\" friction=\"" + num(c.mu) + " 0.005 0.0001\" solref=\"" + num(c.timeconst) + " " +
                 num(c.dampratio) + "\" solimp=\"" + kMjcfSolimp + "\" margin=\"0\"/>\n";
        m_out += "  </default>\n";
    }

    /// The geom(s) of graphic g (on the body being written, or the world), in its body frame.
    void geom(const GraphicSpec& g, const ModelSpec& from, bool scene, const std::string& in)
    {
        const std::string name = (scene ? "scene_g" : "g") + std::to_string(g.id);
        Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
        local.linear() = shapeRotation(g);
        local.translation() = g.position;
        const std::string common = std::string(g.noContact ? " contype=\"0\" conaffinity=\"0\"" : "") + " rgba=\"" +
                                   vec3(g.color, false) + " 1\"";
        const auto& d = g.dims;
        auto put = [&](const std::string& n, const std::string& typeAndSize, const Eigen::Isometry3d& X) {
            m_out += in + "<geom name=\"" + attr(n) + "\" " + typeAndSize + pose(X) + common + "/>\n";
        };
        auto mesh = [&](const std::vector<Eigen::Vector3d>& vertices) {
            const std::string meshName = "mesh_" + name;
            std::string v;
            for (const Eigen::Vector3d& p : vertices) v += (v.empty() ? "" : " ") + vec3(p);
            m_assets += "    <mesh name=\"" + attr(meshName) + "\" vertex=\"" + v + "\"/>\n";
            put(name, "type=\"mesh\" mesh=\"" + attr(meshName) + "\"", local);
        };
        switch (g.shape) {
        case ShapeKind::Box: put(name, "type=\"box\" size=\"" + vec3(Eigen::Vector3d(d[0], d[1], d[2]) / 2, false) + "\"", local); break;
        case ShapeKind::Sphere: put(name, "type=\"sphere\" size=\"" + num(d[0]) + "\"", local); break;
        case ShapeKind::Ellipsoid:
            put(name, "type=\"ellipsoid\" size=\"" + vec3(Eigen::Vector3d(d[0], d[1], d[2]), false) + "\"", local);
            break;
        case ShapeKind::Cylinder: put(name, "type=\"cylinder\" size=\"" + num(d[0]) + " " + num(d[1] / 2) + "\"", local); break;
        case ShapeKind::Cone: {
            std::vector<Eigen::Vector3d> v;
            constexpr int kRound = 32;
            for (int k = 0; k < kRound; ++k) {
                const double a = 2 * std::numbers::pi * k / kRound;
                v.emplace_back(d[0] * std::cos(a), d[0] * std::sin(a), 0.0);
            }
            v.emplace_back(0.0, 0.0, d[1]);
            mesh(v);
            break;
        }
        case ShapeKind::Prism: {
            std::vector<Eigen::Vector3d> v;
            for (double z : {0.0, d[0]})
                for (std::size_t i = 1; i + 1 < d.size(); i += 2) v.emplace_back(d[i], d[i + 1], z);
            mesh(v);
            break;
        }
        case ShapeKind::Mesh: {
            const std::filesystem::path dir = std::filesystem::path(from.file).parent_path();
            const MeshLoad load = loadTriangleMesh((dir / g.meshFile).string(), g.hasScale ? g.scale : 1.0);
            if (!load.mesh) {
                m_out += in + "<!-- " + commentSafe("G " + std::to_string(g.id) + ": mesh not exported: " + load.error) + " -->\n";
                return;
            }
            mesh(load.mesh->vertices);
            break;
        }
        case ShapeKind::Tube: {
            // a ring of boxes, each as wide as the outer wall's chord
            const int n = mjcfTubeSegments(d[0]);
            const double ro = d[0], ri = d[1];
            const Eigen::Vector3d half((ro - ri) / 2, ro * std::sin(std::numbers::pi / n), d[2] / 2);
            m_out += in + "<!-- " + commentSafe("G " + std::to_string(g.id) + " TUBE: a ring of " + std::to_string(n) + " boxes") + " -->\n";
            for (int k = 0; k < n; ++k) {
                const double a = 2 * std::numbers::pi * k / n;
                Eigen::Isometry3d X = local;
                X.translate(Eigen::Vector3d((ro + ri) / 2 * std::cos(a), (ro + ri) / 2 * std::sin(a), 0));
                X.rotate(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()));
                put(name + "_" + std::to_string(k), "type=\"box\" size=\"" + vec3(half, false) + "\"", X);
            }
            break;
        }
        }
    }

    /// pos and quat attributes of a frame (quat left out when it is the identity).
    static std::string pose(const Eigen::Isometry3d& X)
    {
        std::string out = " pos=\"" + vec3(X.translation()) + "\"";
        Eigen::Quaterniond q(X.linear());
        q.normalize();
        if (q.w() < 0) q.coeffs() = -q.coeffs();
        if (std::abs(q.w() - 1) > 1e-15) out += " quat=\"" + geo(q.w()) + " " + geo(q.x()) + " " + geo(q.y()) + " " + geo(q.z()) + "\"";
        return out;
    }

    /// The graphics of body i (tree index) as geoms.
    void bodyGeoms(int i, const std::string& in)
    {
        if (!contacts()) return;
        for (const GraphicSpec& g : m_options.spec->graphics)
            if (g.body != 0 && m_model.bodyIndex(g.body) == i) geom(g, *m_options.spec, false, in);
    }

    /// MuJoCo excludes body pairs: every pair of bodies with two solids that overlap at the
    /// initial pose (Padrob excludes only those two solids).
    void excludes()
    {
        std::set<std::pair<std::string, std::string>> pairs;
        for (const auto& [a, b] : contactExcludedBodies(*m_model.contact)) {
            std::string na = a < 0 ? "world" : m_names.body[a], nb = b < 0 ? "world" : m_names.body[b];
            if (na > nb) std::swap(na, nb);
            pairs.emplace(na, nb);
        }
        if (pairs.empty()) return;
        m_out += "  <contact>\n";
        m_out += "    <!-- solids overlapping at the initial pose (Padrob: kInitialOverlap): these bodies never touch -->\n";
        for (const auto& [a, b] : pairs) m_out += "    <exclude body1=\"" + attr(a) + "\" body2=\"" + attr(b) + "\"/>\n";
        m_out += "  </contact>\n";
    }

    std::string modelName() const
    {
        std::string file = m_options.source;
        const std::size_t slash = file.find_last_of("/\\");
        if (slash != std::string::npos) file = file.substr(slash + 1);
        const std::size_t dot = file.rfind('.');
        if (dot != std::string::npos && dot > 0) file = file.substr(0, dot);
        const std::string name = sanitize(file);
        return name.empty() ? "padrob" : name;
    }

    void header()
    {
        int hinges = 0, slides = 0, placeholders = 0;
        int frees = 0;
        for (int i = 0; i < m_model.nb; ++i) {
            if (m_model.freeSlot[i] >= 0) {
                frees += m_model.freeSlot[i] == 0;
                if (m_model.freeSlot[i] < kFreeJointCoordinates - 1) continue;  // (massless: not written)
            } else {
                (m_model.jointType[i] == JointType::Prismatic ? slides : hinges) += 1;
            }
            if (mjcfInertial(m_model, i).placeholder()) ++placeholders;
        }
        int driven = 0;
        for (const CompiledDrive& d : m_model.drive) driven += d.type != DriveType::None;
        const auto count = [](std::size_t n, const char* one, const char* many) {
            return std::to_string(n) + " " + (n == 1 ? one : many);
        };
        const std::size_t nb = static_cast<std::size_t>(m_model.nb - (kFreeJointCoordinates - 1) * frees);
        std::string h;
        h += "Padrob " PADROB_VERSION " model";
        if (!m_options.source.empty()) h += " " + m_options.source;
        h += " as MuJoCo MJCF (padrob export).\n\n";
        h += "Exported: " + count(nb, "body", "bodies") + " on " + count(nb, "joint", "joints") + " (" +
             count(static_cast<std::size_t>(hinges), "hinge", "hinges") + ", " +
             count(static_cast<std::size_t>(slides), "slide", "slides") +
             (frees > 0 ? ", " + count(static_cast<std::size_t>(frees), "free joint", "free joints") : std::string()) +
             "), posed with every joint at\n"
             "theta = 0, so that each joint's qpos is Padrob's coordinate theta and qvel its\n"
             "rate: hinges in rad (T 1 pivoted-actuator joints too: their Padrob coordinate,\n"
             "the cylinder length, is not one here), slides in m; masses, centres of mass and\n"
             "inertia tensors (about the centre of mass, body axes); gravity; the time step,\n"
             "with RK4. Keyframe \"initial\": the model's initial state (QI, VI).\n"
             "Joint ranges (two-sided limits only) are informative: Padrob's stops are hard\n"
             "(an impulse, restitution " +
             short6(m_model.restitution) + "), MuJoCo's limits are soft constraints.\n\n";
        h += "NOT exported, so MuJoCo gets a passive model:\n"
             "  drives (" + std::to_string(driven) + " here): hydraulic drives and their relief valves, motors,\n"
             "    pneumatic cylinders, servos;\n"
             "  joint limit events and their impulses;\n"
             "  applied forces (" + std::to_string(m_model.forces.size()) + " F statements here);\n";
        h += contacts() ? "CONTACT: the graphics are geoms (TUBE: a ring of boxes; CONE, PRISM, MESH: their\n"
                          "convex hulls), NOCONTACT ones visual only" +
                              std::string(m_options.scene ? ", the scene's as world geoms" : "") +
                              "; contacts are on with\n"
                              "MuJoCo's soft-constraint law set to approximate Padrob's compliant one\n"
                              "(docs/contact.md): results agree within the two laws' differences.\n"
                        : "  graphics: no geoms, and contacts are off (the model has no CONTACT).\n";
        if (placeholders > 0) {
            h += "\n" + count(static_cast<std::size_t>(placeholders), "body has", "bodies have") +
                 " placeholder mass properties: MuJoCo's compiler refuses\n"
                 "massless bodies and inertias breaking I1 + I2 >= I3. The true values are in a\n"
                 "comment at each; padrob bench and padrob export's check set them into the\n"
                 "loaded model (body_mass, body_inertia, body_iquat).\n";
        }
        m_out += "<!--\n" + commentSafe(h) + "-->\n";
    }

    /// A free joint (T 3, slot 0 at i, on the world): one body with a freejoint, posed
    /// where the body starts; its qpos is the position and quaternion (w x y z), its
    /// qvel the linear velocity (world) and the angular velocity (body axes).
    void freeBody(int i, int depth)
    {
        m_order.push_back(i);
        const int b = i + kFreeJointCoordinates - 1;
        const std::string in(static_cast<std::size_t>(2 * depth), ' ');
        const Model& m = m_model;
        m_out += in + "<!-- " +
                 commentSafe("B " + std::to_string(m.bodyId[b]) + quoted(m.bodyName[b]) + ", joint C " +
                             std::to_string(m.jointId[i]) + quoted(m.jointName[i]) + " (" +
                             jointTypeText(JointType::Free) + ")") +
                 " -->\n";
        const Eigen::Isometry3d X = freeStartPose(i);
        m_out += in + "<body name=\"" + attr(m_names.body[b]) + "\" pos=\"" + vec3(X.translation()) + "\"";
        Eigen::Quaterniond q(X.linear());
        q.normalize();
        if (std::abs(q.w() - 1) > 1e-15) {
            m_out += " quat=\"" + geo(q.w()) + " " + geo(q.x()) + " " + geo(q.y()) + " " + geo(q.z()) + "\"";
        }
        m_out += ">\n";
        const std::string in2 = in + "  ";
        m_out += in2 + "<freejoint name=\"" + attr(m_names.joint[i]) + "\"/>\n";
        inertial(b, in2);
        bodyGeoms(b, in2);
        for (int c : m_children[static_cast<std::size_t>(b) + 1]) body(c, depth + 1);
        m_out += in + "</body>\n";
    }

    /// The free body's frame in its parent's (the world's) at the start: the slots' frames
    /// composed at θ = 0 with the base orientation the start's.
    Eigen::Isometry3d freeStartPose(int first) const
    {
        Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
        for (int k = 0; k < kFreeJointCoordinates; ++k) X = X * m_model.X_pj[first + k] * m_model.X_jc[first + k];
        return X;
    }

    void body(int i, int depth)
    {
        if (m_model.freeSlot[i] == 0) {
            freeBody(i, depth);
            return;
        }
        m_order.push_back(i);
        const std::string in(static_cast<std::size_t>(2 * depth), ' ');
        const Model& m = m_model;

        // the body's description
        std::string note = "B " + std::to_string(m.bodyId[i]) + quoted(m.bodyName[i]) + ", joint C " +
                           std::to_string(m.jointId[i]) + quoted(m.jointName[i]) + " (" +
                           jointTypeText(m.jointType[i]) + ")";
        if (m.axisSign[i] < 0) note += "; the joint is written from this body to its parent: axis reversed";
        if (m.drive[i].type != DriveType::None) {
            note += std::string("; ") + driveName(m.drive[i].type) + " not exported";
        }
        m_out += in + "<!-- " + commentSafe(note) + " -->\n";

        // the body frame in the parent's at θ = 0
        const Eigen::Isometry3d X = m.X_pj[i] * m.X_jc[i];
        m_out += in + "<body name=\"" + attr(m_names.body[i]) + "\" pos=\"" + vec3(X.translation()) + "\"";
        Eigen::Quaterniond q(X.linear());
        q.normalize();
        if (q.w() < 0) q.coeffs() = -q.coeffs();
        if (std::abs(q.w() - 1) > 1e-15) {
            m_out += " quat=\"" + geo(q.w()) + " " + geo(q.x()) + " " + geo(q.y()) + " " + geo(q.z()) + "\"";
        }
        m_out += ">\n";
        const std::string in2 = in + "  ";

        joint(i, in2);
        inertial(i, in2);
        bodyGeoms(i, in2);
        for (int c : m_children[static_cast<std::size_t>(i) + 1]) body(c, depth + 1);
        m_out += in + "</body>\n";
    }

    void joint(int i, const std::string& in)
    {
        const Model& m = m_model;
        const bool slide = m.jointType[i] == JointType::Prismatic;
        const Eigen::Vector3d axis = m.axisSign[i] * m.X_cj[i].linear().col(slide ? 1 : 0);
        const bool lo = std::isfinite(m.lower[i]), hi = std::isfinite(m.upper[i]);
        if (m_options.limits && lo != hi) {
            m_out += in + "<!-- " +
                     commentSafe(std::string("one-sided limit not exported (MJCF ranges have two ends): ") +
                                 (lo ? "theta >= " + short6(m.lower[i]) : "theta <= " + short6(m.upper[i]))) +
                     " -->\n";
        }
        if (m_options.limits && lo && hi && m.jointType[i] == JointType::Actuator) {
            m_out += in + "<!-- " +
                     commentSafe("range: the angles of the stroke " + short6(m.coordinate(i, m.lower[i])) + " … " +
                                 short6(m.coordinate(i, m.upper[i])) + " m") +
                     " -->\n";
        }
        m_out += in + "<joint name=\"" + attr(m_names.joint[i]) + "\" type=\"" + (slide ? "slide" : "hinge") +
                 "\" pos=\"" + vec3(m.X_cj[i].translation()) + "\" axis=\"" + vec3(axis) + "\"";
        if (m_options.limits && lo && hi) {
            m_out += " limited=\"true\" range=\"" + num(m.lower[i]) + " " + num(m.upper[i]) + "\"";
        }
        m_out += "/>\n";
    }

    void inertial(int i, const std::string& in)
    {
        const MjcfInertial p = mjcfInertial(m_model, i);
        const Eigen::Matrix3d& I = m_model.inertia[i];
        const std::string full = num(I(0, 0)) + " " + num(I(1, 1)) + " " + num(I(2, 2)) + " " + num(I(0, 1)) + " " +
                                 num(I(0, 2)) + " " + num(I(1, 2));
        if (p.placeholderMass) {
            std::string why = p.mass == 0 ? "massless in Padrob (mass 0)" : "mass " + num(p.mass) + " kg in Padrob";
            m_out += in + "<!-- " +
                     commentSafe("placeholder mass " + num(kMjcfMinMass) + " kg: " + why +
                                 "; MuJoCo's compiler refuses moving bodies without mass") +
                     " -->\n";
        }
        if (p.placeholderInertia) {
            std::string why;
            const double sum = p.principal.sum(), largest = p.principal.maxCoeff();
            if (sum - 2 * largest < 0) {
                why = "its principal moments " + short6(p.principal[0]) + ", " + short6(p.principal[1]) + ", " +
                      short6(p.principal[2]) + " kg m^2 break I1 + I2 >= I3";
            } else {
                why = "a principal moment is below " + num(kMjcfMinInertia) + " kg m^2";
            }
            m_out += in + "<!-- " +
                     commentSafe("placeholder inertia: the true tensor (Ixx Iyy Izz Ixy Ixz Iyz, body axes) is " +
                                 full + " kg m^2; " + why +
                                 ", which MuJoCo's compiler refuses; written as the nearest tensor it accepts") +
                     " -->\n";
        }
        m_out += in + "<inertial pos=\"" + vec3(p.com, false) + "\" mass=\"" + num(p.writtenMass) + "\"";
        if (needsPrincipalForm(p)) {
            if (!p.diagonal) {
                const Eigen::Quaterniond& q = p.principalAxes;
                m_out += " quat=\"" + num(q.w()) + " " + num(q.x()) + " " + num(q.y()) + " " + num(q.z()) + "\"";
            }
            m_out += " diaginertia=\"" + vec3(p.writtenPrincipal, false) + "\"/>\n";
        } else {
            m_out += " fullinertia=\"" + full + "\"/>\n";
        }
    }

    void keyframe()
    {
        if (m_order.empty()) return;
        std::string qpos, qvel;
        for (int i : m_order) {
            if (m_model.freeSlot[i] == 0) {
                const Eigen::Isometry3d X = freeStartPose(i);
                Eigen::Quaterniond q(X.linear());
                q.normalize();
                const Eigen::Vector3d& p = X.translation();
                for (double v : {p.x(), p.y(), p.z(), q.w(), q.x(), q.y(), q.z()}) {
                    qpos += (qpos.empty() ? "" : " ") + num(v);
                }
                for (int k = 0; k < 6; ++k) qvel += (qvel.empty() ? "" : " ") + std::string("0");
                continue;
            }
            qpos += (qpos.empty() ? "" : " ") + num(m_model.theta0[i]);
            qvel += (qvel.empty() ? "" : " ") + num(m_model.thetaDot0[i]);
        }
        m_out += "  <keyframe>\n";
        m_out += "    <key name=\"initial\" qpos=\"" + qpos + "\" qvel=\"" + qvel + "\"/>\n";
        m_out += "  </keyframe>\n";
    }
};

}  // namespace

std::string toMjcf(const Model& model, const MjcfOptions& options, std::string& error)
{
    error.clear();
    if (!model.cuts.empty()) {
        const std::size_t n = model.cuts.size();
        std::string joints;
        for (std::size_t k = 0; k < n; ++k) {
            joints += (k == 0 ? "" : ", ") + std::to_string(model.cuts[k].jointId) + quoted(model.cuts[k].name);
        }
        error = "MJCF export needs a tree: the model closes " + std::to_string(n) + (n == 1 ? " loop" : " loops") +
                " through " + (n == 1 ? "joint " : "joints ") + joints +
                " (MuJoCo would need an equality constraint for each, which the export does not write)";
        return {};
    }
    for (int first : model.freeJoints) {
        if (model.parent[first] < 0) continue;
        error = "MJCF export: joint " + std::to_string(model.jointId[first]) + quoted(model.jointName[first]) +
                " is a free joint (T 3) on a moving body, and MuJoCo allows a free joint only on a body of the world";
        return {};
    }
    if (!(options.timestep > 0) || !std::isfinite(options.timestep)) {
        error = "the MJCF timestep must be a positive number of seconds";
        return {};
    }
    return Writer(model, options).run();
}

std::string toMjcf(const Model& model, std::string& error) { return toMjcf(model, MjcfOptions{}, error); }

}  // namespace solver
