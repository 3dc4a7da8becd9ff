#include "ide/cli/info_report.h"

#include "ide/cli/cli_io.h"
#include "ide/cli/json_writer.h"
#include "ide/i18n/language.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace ide::cli {

using solver::BodySpec;
using solver::DriveSpec;
using solver::JointSpec;
using solver::JointType;
using solver::CompiledModel;
using solver::Topology;

namespace {

using i18n::trStd;

/// `v` as the report shows it: 6 significant digits (ide::cli::num), ∞ for infinities.
std::string shown(double v, int digits = 6)
{
    if (std::isinf(v)) return v > 0 ? "∞" : "-∞";
    return num(v, digits);
}

/// One table row: each cell padded to its width, separated by a space, trailing blanks trimmed.
std::string row(std::initializer_list<std::pair<std::string, int>> cells)
{
    std::string out = " ";
    for (const auto& [text, width] : cells) out += " " + (width < 0 ? pad(text, static_cast<std::size_t>(-width), true) : pad(text, static_cast<std::size_t>(width)));
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out + "\n";
}

std::string vec(const Eigen::Vector3d& v) { return shown(v.x()) + " " + shown(v.y()) + " " + shown(v.z()); }

/// Role of each spec joint: "independent", "dependent" or "loop-closure" (the JSON's values).
std::vector<std::string> roles(const CompiledModel& m)
{
    std::vector<std::string> r(m.spec.joints.size(), "independent");
    const Topology& t = *m.topology;
    for (int j : t.dependent) r[static_cast<std::size_t>(j)] = "dependent";
    for (int j : t.loopJoints) r[static_cast<std::size_t>(j)] = "loop-closure";
    return r;
}

/// A role as the text report shows it, in the current language.
std::string roleText(const std::string& role)
{
    if (role == "dependent") return trStd("padrob", "dependent", "role of a joint's coordinate");
    if (role == "loop-closure") return trStd("padrob", "loop-closure", "role of a joint");
    return trStd("padrob", "independent", "role of a joint's coordinate");
}

/// A joint type as the text report shows it, in the current language.
std::string typeText(JointType t)
{
    switch (t) {
    case JointType::Revolute: return trStd("padrob", "revolute", "joint type (T 0)");
    case JointType::Actuator: return trStd("padrob", "actuator", "joint type (T 1)");
    case JointType::Prismatic: return trStd("padrob", "prismatic", "joint type (T 2)");
    case JointType::Free: return trStd("padrob", "free", "joint type (T 3)");
    }
    return solver::jointTypeName(t);
}

const DriveSpec* driveOf(const CompiledModel& m, int jointId)
{
    for (const DriveSpec& d : m.spec.drives) {
        if (d.joint == jointId) return &d;
    }
    return nullptr;
}

const char* coordinateUnit(JointType t) { return t == JointType::Revolute ? "rad" : "m"; }

std::string label(int id, const std::string& name) { return name.empty() ? std::to_string(id) : std::to_string(id) + " " + name; }

std::string jointIds(const CompiledModel& m, const std::vector<int>& indices)
{
    std::string s;
    for (int j : indices) s += (s.empty() ? "" : ", ") + std::to_string(m.spec.joints[static_cast<std::size_t>(j)].id);
    return s.empty() ? trStd("padrob", "none") : s;
}

std::string driveText(const DriveSpec& d, JointType t)
{
    std::string s = solver::driveKindKeyword(d.kind);
    if (d.kind == solver::DriveKind::Hydraulic) {
        auto h = d.hydraulic();
        const char* v = t == JointType::Revolute ? " rad/s" : " m/s";
        const char* f = t == JointType::Revolute ? " N·m" : " N";
        s += " v " + shown(h.vmax, 4) + "/" + shown(h.vmin, 4) + v + ", F " + shown(h.fmax, 4) + "/" + shown(h.fmin, 4) + f;
    } else {
        for (const auto& [k, v] : d.params) s += " " + k + " " + shown(v, 4);
        for (const auto& [k, v] : d.pairs) s += " " + k + " " + shown(v.first, 4) + " " + shown(v.second, 4);
        if (!d.compensation.empty()) s += " COMP " + d.compensation;
    }
    return s;
}

}  // namespace

std::string infoText(const CompiledModel& m)
{
    const Topology& t = *m.topology;
    std::string out;
    out += fill(trStd("padrob", "Model: %1"), {m.spec.file}) + "\n";
    out += fill(trStd("padrob", "Gravity: %1 m/s²"), {vec(m.spec.gravity)}) + "\n\n";

    std::size_t nBodies = t.bodyIds.size() - 1;
    out += fill(trStd("padrob", "Bodies (%1 + ground), total mass %2 kg"), {std::to_string(nBodies), shown(t.totalMass)}) + "\n";
    out += row({{"id", 6},
                {trStd("padrob", "name"), 22},
                {trStd("padrob", "mass [kg]"), -12},
                {trStd("padrob", "Ixx Iyy Izz [kg m²]"), 34},
                {trStd("padrob", "centre of mass"), 0}});
    for (const BodySpec& b : m.spec.bodies) {
        if (b.id == 0) continue;
        std::string mass = b.hasMass && b.mass > 0 ? shown(b.mass) : trStd("padrob", "massless");
        out += row({{std::to_string(b.id), 6}, {b.name, 22}, {mass, -12}, {vec(b.inertia), 34}, {vec(b.cg), 0}});
    }
    out += "\n" + fill(trStd("padrob", "Joints (%1)"), {std::to_string(m.spec.joints.size())}) + "\n";
    out += row({{"id", 5},
                {trStd("padrob", "name"), 18},
                {trStd("padrob", "type"), 10},
                {"B1-B2", 7},
                {trStd("padrob", "limits"), 22},
                {trStd("padrob", "initial"), 9},
                {trStd("padrob", "role"), 13},
                {trStd("padrob", "drive"), 0}});
    auto r = roles(m);
    for (std::size_t k = 0; k < m.spec.joints.size(); ++k) {
        const JointSpec& j = m.spec.joints[k];
        std::string lim = (j.ll ? shown(*j.ll) : "-∞") + " .. " + (j.ul ? shown(*j.ul) : "∞") + " " + coordinateUnit(j.type);
        if (!j.ll && !j.ul) lim = trStd("padrob", "none");
        std::string bodies = std::to_string(j.side1.body) + "-" + std::to_string(j.side2.body);
        const DriveSpec* d = driveOf(m, j.id);
        std::string q0 = k < t.q0.size() ? shown(t.q0[k], 5) : "?";
        out += row({{std::to_string(j.id), 5}, {j.name, 18}, {typeText(j.type), 10}, {bodies, 7}, {lim, 22},
                    {q0, 9}, {roleText(r[k]), 13}, {d ? driveText(*d, j.type) : trStd("padrob", "passive"), 0}});
    }

    out += "\n" + trStd("padrob", "Spanning tree (parent body <- joint <- body):") + "\n";
    for (std::size_t k = 0; k < t.treeJoints.size(); ++k) {
        const int ji = t.treeJoints[k];
        if (k > 0 && t.treeJoints[k - 1] == ji) continue;  // a free joint's coordinates after its first
        const JointSpec& j = m.spec.joints[static_cast<std::size_t>(ji)];
        bool rev = t.reversed[static_cast<std::size_t>(ji)];
        int parent = rev ? j.side2.body : j.side1.body, child = rev ? j.side1.body : j.side2.body;
        out += "  " + fill(trStd("padrob", "%1 <- joint %2 <- %3"), {std::to_string(parent), label(j.id, j.name), std::to_string(child)}) +
               (rev ? "  (" + trStd("padrob", "written from B2 to B1") + ")" : std::string()) + "\n";
    }
    out += trStd("padrob", "Chains:") + "\n";
    for (std::size_t c = 0; c < t.chains.size(); ++c) {
        out += "  " + fill(trStd("padrob", "%1: joints %2"), {std::to_string(c + 1), jointIds(m, t.chains[c])}) + "\n";
    }
    out += fill(trStd("padrob", "Loop-closure joints: %1"), {jointIds(m, t.loopJoints)}) + "\n";
    out += fill(trStd("padrob", "Degrees of freedom: %1"), {std::to_string(t.dof)}) + "\n";
    out += "  " + fill(trStd("padrob", "independent coordinates (joints): %1"), {jointIds(m, t.independent)}) + "\n";
    out += "  " + fill(trStd("padrob", "dependent coordinates (joints): %1"), {jointIds(m, t.dependent)}) + "\n";
    if (m.model && !m.model->pumps.empty()) {
        const solver::Model& model = *m.model;
        out += "\n" + fill(trStd("padrob", "Fluid power: bulk modulus %1 Pa, laminar below %2 Pa"),
                           {shown(model.fluid.bulk), shown(model.fluid.laminar)}) + "\n";
        for (const solver::CompiledPump& p : model.pumps) {
            std::string drives;
            for (const solver::CompiledCircuit& c : model.circuits) {
                if (model.pumps[static_cast<std::size_t>(c.pump)].id == p.id)
                    drives += (drives.empty() ? "" : ", ") + std::to_string(model.jointId[c.joint]);
            }
            out += "  " + fill(p.loadSensing ? trStd("padrob", "pump %1 %2: %3 L/min, %4 MPa, load-sensing (margin %5 MPa); drives %6")
                                             : trStd("padrob", "pump %1 %2: %3 L/min, %4 MPa, pressure-compensated%5; drives %6"),
                               {std::to_string(p.id), p.name, shown(p.qmax * 60000, 4), shown(p.pmax * 1e-6, 4),
                                p.loadSensing ? shown(p.margin * 1e-6, 3) : std::string(),
                                drives.empty() ? trStd("padrob", "none") : drives}) + "\n";
        }
    }
    return out;
}

std::string infoJson(const CompiledModel& m)
{
    const Topology& t = *m.topology;
    JsonWriter w;
    auto vec3 = [&](const Eigen::Vector3d& v) { w.beginArray().num(v.x()).num(v.y()).num(v.z()).endArray(); };
    auto ids = [&](const std::vector<int>& indices) {
        w.beginArray();
        for (int j : indices) w.integer(m.spec.joints[static_cast<std::size_t>(j)].id);
        w.endArray();
    };
    auto optNum = [&](const std::optional<double>& v) { v ? w.num(*v) : w.null(); };
    w.beginObject();
    w.key("format").str("padrob-info");
    w.key("version").integer(1);
    w.key("file").str(m.spec.file);
    w.key("gravity");
    vec3(m.spec.gravity);
    w.key("total_mass").num(t.totalMass);
    w.key("dof").integer(t.dof);

    w.key("bodies").beginArray();
    for (const BodySpec& b : m.spec.bodies) {
        if (b.id == 0) continue;
        w.beginObject();
        w.key("id").integer(b.id);
        w.key("name").str(b.name);
        w.key("mass").num(b.hasMass ? b.mass : 0.0);
        w.key("massless").boolean(!b.hasMass || b.mass == 0);
        w.key("centre_of_mass");
        vec3(b.cg);
        w.key("inertia").beginArray();
        Eigen::Matrix3d I = b.inertiaTensor();
        for (int r = 0; r < 3; ++r) {
            w.beginArray().num(I(r, 0)).num(I(r, 1)).num(I(r, 2)).endArray();
        }
        w.endArray();
        w.endObject();
    }
    w.endArray();

    auto r = roles(m);
    w.key("joints").beginArray();
    for (std::size_t k = 0; k < m.spec.joints.size(); ++k) {
        const JointSpec& j = m.spec.joints[k];
        w.beginObject();
        w.key("id").integer(j.id);
        w.key("name").str(j.name);
        w.key("type").str(solver::jointTypeName(j.type));
        w.key("type_code").integer(static_cast<int>(j.type));
        w.key("body1").integer(j.side1.body);
        w.key("body2").integer(j.side2.body);
        w.key("unit").str(coordinateUnit(j.type));
        w.key("lower_limit");
        optNum(j.ll);
        w.key("upper_limit");
        optNum(j.ul);
        w.key("initial").num(k < t.q0.size() ? t.q0[k] : 0.0);
        w.key("initial_rate").num(j.vi.value_or(0.0));
        w.key("role").str(r[k]);
        w.key("drive");
        if (const DriveSpec* d = driveOf(m, j.id)) {
            w.beginObject();
            w.key("kind").str(solver::driveKindKeyword(d->kind));
            w.key("params").beginObject();
            for (const auto& [key, v] : d->params) w.key(key).num(v);
            w.endObject();
            if (d->kind == solver::DriveKind::Hydraulic) {
                auto h = d->hydraulic();
                w.key("vmax").num(h.vmax).key("vmin").num(h.vmin).key("fmax").num(h.fmax).key("fmin").num(h.fmin);
            }
            w.endObject();
        } else {
            w.null();
        }
        w.endObject();
    }
    w.endArray();

    // fluid power: the oil, the pumps and one circuit per CYL/HMOTOR drive
    if (m.model) {
        const solver::Model& model = *m.model;
        w.key("fluid").beginObject().key("bulk").num(model.fluid.bulk).key("laminar").num(model.fluid.laminar).endObject();
        w.key("pumps").beginArray();
        for (const solver::CompiledPump& p : model.pumps) {
            w.beginObject();
            w.key("id").integer(p.id).key("name").str(p.name).key("flow").num(p.qmax).key("pressure").num(p.pmax);
            w.key("load_sensing").boolean(p.loadSensing).key("margin").num(p.margin);
            w.key("drives").beginArray();
            for (const solver::CompiledCircuit& c : model.circuits) {
                if (model.pumps[static_cast<std::size_t>(c.pump)].id == p.id) w.integer(model.jointId[c.joint]);
            }
            w.endArray();
            w.endObject();
        }
        w.endArray();
        w.key("circuits").beginArray();
        for (const solver::CompiledCircuit& c : model.circuits) {
            const bool cyl = c.kind == solver::ActuatorKind::Cylinder;
            w.beginObject();
            w.key("joint").integer(model.jointId[c.joint]);
            w.key("kind").str(cyl ? "CYL" : "HMOTOR");
            w.key("pump").integer(model.pumps[static_cast<std::size_t>(c.pump)].id);
            if (cyl) {
                w.key("area_a").num(c.areaA).key("area_b").num(c.areaB);
                w.key("stroke").beginArray().num(c.lower).num(c.upper).endArray();
            } else {
                w.key("displacement").num(c.areaA);
            }
            w.key("volume_a").num(c.deadA).key("volume_b").num(c.deadB);
            w.key("valve_flow").num(c.qn).key("valve_dp").num(c.dpn);
            w.key("compensation").str(c.comp == solver::Compensation::Pre    ? "PRE"
                                      : c.comp == solver::Compensation::Post ? "POST"
                                                                             : "NONE");
            w.key("tau").num(c.tau).key("friction").num(c.friction);
            w.key("p0");
            if (c.hasP0) w.beginArray().num(c.p0A).num(c.p0B).endArray();
            else w.null();
            w.endObject();
        }
        w.endArray();
    }

    w.key("tree").beginArray();
    for (std::size_t k = 0; k < t.treeJoints.size(); ++k) {
        const int ji = t.treeJoints[k];
        if (k > 0 && t.treeJoints[k - 1] == ji) continue;  // a free joint's coordinates after its first
        const JointSpec& j = m.spec.joints[static_cast<std::size_t>(ji)];
        bool rev = t.reversed[static_cast<std::size_t>(ji)];
        w.beginObject();
        w.key("joint").integer(j.id);
        w.key("parent_body").integer(rev ? j.side2.body : j.side1.body);
        w.key("child_body").integer(rev ? j.side1.body : j.side2.body);
        w.key("reversed").boolean(rev);
        w.endObject();
    }
    w.endArray();
    w.key("chains").beginArray();
    for (const auto& c : t.chains) ids(c);
    w.endArray();
    w.key("loop_closures");
    ids(t.loopJoints);
    w.key("independent");
    ids(t.independent);
    w.key("dependent");
    ids(t.dependent);

    w.key("diagnostics").beginArray();
    for (const solver::Diagnostic& d : m.diagnostics) {
        w.beginObject();
        w.key("severity").str(solver::severityName(d.severity));
        w.key("code").str(d.code);
        w.key("line").integer(d.pos.line);
        w.key("column").integer(d.pos.column);
        w.key("message").str(d.message);
        w.key("hint").str(d.hint);
        w.endObject();
    }
    w.endArray();
    w.endObject();
    return w.text() + "\n";
}

}  // namespace ide::cli
