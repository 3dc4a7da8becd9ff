#include "solver/parse/writer.h"

#include <charconv>

namespace solver::parse {

std::string formatNumber(double v)
{
    if (v == 0) return "0";  // also -0
    char buf[64];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, p);
}

namespace {

std::string quote(const std::string& s)
{
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + '"';
}

std::string vec(const Eigen::Vector3d& v)
{
    return formatNumber(v.x()) + ' ' + formatNumber(v.y()) + ' ' + formatNumber(v.z());
}

std::string magnitude(const MagnitudeSpec& m)
{
    switch (m.kind) {
    case MagnitudeSpec::Kind::Constant: return formatNumber(m.value);
    case MagnitudeSpec::Kind::Sine: {
        std::string s = "SIN " + formatNumber(m.amplitude) + ' ' + formatNumber(m.frequency) + ' ' + formatNumber(m.phase);
        if (m.hasOffset) s += ' ' + formatNumber(m.offset);
        return s;
    }
    case MagnitudeSpec::Kind::TableTime:
    case MagnitudeSpec::Kind::TableJoint: {
        std::string s = m.kind == MagnitudeSpec::Kind::TableTime ? "TABLE T" : "TABLE Q " + std::to_string(m.joint);
        for (const auto& [x, y] : m.table) s += ' ' + formatNumber(x) + ' ' + formatNumber(y);
        return s;
    }
    }
    return "0";
}

void writeSide(std::string& out, const JointSide& s, char digit)
{
    out += "B";
    out += digit;
    out += ' ' + std::to_string(s.body) + " P" + digit + ' ' + vec(s.p) + " A" + digit + ' ' + vec(s.a) + " R" +
           digit + ' ' + vec(s.r) + '\n';
}

}  // namespace

std::string writeModel(const ModelSpec& spec)
{
    std::string out;
    if (spec.hasGravity) out += "GRAVITY " + vec(spec.gravity) + "\n";
    if (spec.hasRestitution) out += "RESTITUTION " + formatNumber(spec.restitution) + "\n";
    if (spec.fluid) {
        out += "FLUID";
        if (spec.fluid->bulk) out += " BULK " + formatNumber(*spec.fluid->bulk);
        if (spec.fluid->laminar) out += " LAMINAR " + formatNumber(*spec.fluid->laminar);
        out += '\n';
    }
    for (const PumpSpec& p : spec.pumps) {
        out += "PUMP " + std::to_string(p.id) + " FLOW " + formatNumber(p.flow) + " PRESSURE " + formatNumber(p.pressure);
        if (p.margin) out += " MARGIN " + formatNumber(*p.margin);
        if (!p.name.empty()) out += " NAME " + quote(p.name);
        out += '\n';
    }
    if (spec.contact) {
        out += "CONTACT";
        if (spec.contact->mu) out += " MU " + formatNumber(*spec.contact->mu);
        if (spec.contact->e) out += " E " + formatNumber(*spec.contact->e);
        out += '\n';
    }
    if (spec.hasGravity || spec.hasRestitution || spec.fluid || !spec.pumps.empty() || spec.contact) out += "\n";
    for (const BodySpec& b : spec.bodies) {
        out += "B " + std::to_string(b.id);
        if (b.hasMass) {
            out += ' ' + formatNumber(b.mass) + ' ' + vec(b.inertia);
            if (b.hasProducts) out += ' ' + vec(b.products);
        }
        if (b.hasCg) out += " CG " + vec(b.cg);
        if (!b.name.empty()) out += " NAME " + quote(b.name);
        out += '\n';
    }
    if (!spec.bodies.empty()) out += '\n';
    for (const JointSpec& j : spec.joints) {
        out += "C " + std::to_string(j.id);
        if (j.typeWritten) out += " T " + std::to_string(static_cast<int>(j.type));
        if (j.ll) out += " LL " + formatNumber(*j.ll);
        if (j.ul) out += " UL " + formatNumber(*j.ul);
        if (j.qi) out += " QI " + formatNumber(*j.qi);
        if (j.vi) out += " VI " + formatNumber(*j.vi);
        if (!j.name.empty()) out += " NAME " + quote(j.name);
        out += '\n';
        if (j.side1.present) writeSide(out, j.side1, '1');
        if (j.side2.present) writeSide(out, j.side2, '2');
        if (j.hasCl) out += "CL1 " + vec(j.cl1) + " CL2 " + vec(j.cl2) + '\n';
        out += '\n';
    }
    for (const DriveSpec& d : spec.drives) {
        out += "D " + std::to_string(d.joint) + ' ' + driveKindKeyword(d.kind);
        for (const auto& [k, v] : d.params) out += ' ' + k + ' ' + formatNumber(v);
        if (!d.compensation.empty()) out += " COMP " + d.compensation;
        for (const auto& [k, v] : d.pairs) out += ' ' + k + ' ' + formatNumber(v.first) + ' ' + formatNumber(v.second);
        out += '\n';
    }
    if (!spec.drives.empty()) out += '\n';
    for (const ForceSpec& f : spec.forces) {
        out += "F " + std::to_string(f.id) + ' ' + forceKindKeyword(f.kind);
        switch (f.kind) {
        case ForceKind::Point:
            out += " B " + std::to_string(f.body) + " P " + vec(f.point) + " DIR " + vec(f.dir) + " MAG " + magnitude(f.mag);
            break;
        case ForceKind::Torque:
            out += " B " + std::to_string(f.body) + " DIR " + vec(f.dir) + " MAG " + magnitude(f.mag);
            break;
        case ForceKind::Joint: out += ' ' + std::to_string(f.joint) + " MAG " + magnitude(f.mag); break;
        case ForceKind::Spring:
            out += " B1 " + std::to_string(f.body) + " P1 " + vec(f.point) + " B2 " + std::to_string(f.body2) + " P2 " +
                   vec(f.point2) + " K " + formatNumber(f.stiffness) + " L0 " + formatNumber(f.restLength);
            if (f.hasDamping) out += " C " + formatNumber(f.damping);
            break;
        case ForceKind::Aero:
            out += " B " + std::to_string(f.body) + " P " + vec(f.point) + " AREA " + formatNumber(f.area) + " CD " +
                   formatNumber(f.cd);
            if (f.hasCl) out += " CL " + formatNumber(f.cl);
            if (f.hasRho) out += " RHO " + formatNumber(f.rho);
            break;
        }
        if (f.local) out += " LOCAL";
        out += '\n';
    }
    if (!spec.forces.empty()) out += '\n';
    for (const GraphicSpec& g : spec.graphics) {
        out += "G " + std::to_string(g.id) + " B " + std::to_string(g.body) + ' ' + shapeKeyword(g.shape);
        if (g.shape == ShapeKind::Mesh) out += ' ' + quote(g.meshFile);
        for (double v : g.dims) out += ' ' + formatNumber(v);
        if (g.hasScale) out += " SCALE " + formatNumber(g.scale);
        if (g.hasPosition) out += " POS " + vec(g.position);
        if (g.hasAxis) out += " AXIS " + vec(g.axis);
        if (g.hasRot) out += " ROT " + vec(g.rotAxis) + ' ' + formatNumber(g.rotDeg);
        if (g.hasColor) out += " COLOR " + vec(g.color);
        if (g.mass) out += " MASS " + formatNumber(*g.mass);
        if (g.rho) out += " RHO " + formatNumber(*g.rho);
        if (g.noContact) out += " NOCONTACT";
        out += '\n';
    }
    return out;
}

}  // namespace solver::parse
