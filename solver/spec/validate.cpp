#include "solver/spec/validate.h"

#include <Eigen/Eigenvalues>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>

namespace solver {

namespace {

std::string fmt(double v)
{
    char buf[64];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 6);
    return ec == std::errc() ? std::string(buf, p) : std::string("?");
}

/// "body 3" or "body 3 (boom)"
Text bodyNamed(int id, const std::string& name)
{
    return name.empty() ? trText("Diagnostics", "body %1").with(std::to_string(id))
                        : trText("Diagnostics", "body %1 (%2)").with(std::to_string(id)).with(name);
}

/// "joint 3" or "joint 3 (boom swing)"
Text jointNamed(int id, const std::string& name)
{
    return name.empty() ? trText("Diagnostics", "joint %1").with(std::to_string(id))
                        : trText("Diagnostics", "joint %1 (%2)").with(std::to_string(id)).with(name);
}

Text driveOn(int joint)
{
    return trText("Diagnostics", "drive on joint %1").with(std::to_string(joint));
}

/// Reports the second and later definitions of the same id. `what` is the element's
/// phrase with a %1 for its id (trText("Diagnostics", "body %1")).
template <typename Items, typename Id>
void checkDuplicates(const Items& items, Id idOf, const Text& what, Diagnostics& d)
{
    std::map<int, SourcePos> seen;
    for (const auto& it : items) {
        int id = idOf(it);
        auto [pos, inserted] = seen.emplace(id, it.src.pos);
        if (!inserted) {
            Text who = what;
            who.arg(id);
            d.error("duplicate-id", it.src.pos,
                    trText("Diagnostics", "%1 is defined twice (first at line %2)")
                        .with(std::move(who))
                        .with(std::to_string(pos->second.line)),
                    trText("Diagnostics", "give it another id or remove one of the two"));
        }
    }
}

constexpr double kMaxBodyMass = 1e12;     // [kg] (a million tonnes is 1e9)
// [m, rad, m/s, rad/s] LL, UL, QI, VI: a kilometre-long stroke or a thousand turns is
// already no machine; beyond this a value is a slip of units or a typo (1e308)
constexpr double kMaxJointValue = 1e6;
constexpr double kMaxBodyInertia = 1e18;  // [kg m²]

void checkBody(const BodySpec& b, Diagnostics& d)
{
    auto who = [&] { return bodyNamed(b.id, b.name); };
    if (b.id == 0) {
        if (b.hasMass) {
            d.error("ground-mass", b.src.where("m"),
                    trText("Diagnostics", "body 0 is the ground and cannot have a mass or inertia"),
                    trText("Diagnostics", "remove the numbers from 'B 0', or give the body another id"));
        }
        return;
    }
    if (!b.src.complete || !b.hasMass) return;
    if (b.mass < 0) {
        d.error("negative-mass", b.src.where("m"),
                trText("Diagnostics", "%1 has a negative mass (%2 kg)").with(who()).with(fmt(b.mass)),
                trText("Diagnostics", "a mass is zero or positive, in kg"));
    }
    // beyond any machine, and summed along the tree (composite inertias, parallel axes)
    // they would overflow to inf: the dynamics would have nothing finite to factorise
    if (b.mass > kMaxBodyMass) {
        d.error("too-large", b.src.where("m"),
                trText("Diagnostics", "%1's mass %2 kg is beyond any machine's (at most %3 kg)").with(who()).with(fmt(b.mass)).with(fmt(kMaxBodyMass)),
                trText("Diagnostics", "check the units: a mass is in kg"));
        return;
    }
    Eigen::Matrix3d I = b.inertiaTensor();
    if (I.cwiseAbs().maxCoeff() > kMaxBodyInertia) {
        d.error("too-large", b.src.where("I"),
                trText("Diagnostics", "%1's inertia %2 kg m² is beyond any machine's (at most %3 kg m²)")
                    .with(who())
                    .with(fmt(I.cwiseAbs().maxCoeff()))
                    .with(fmt(kMaxBodyInertia)),
                trText("Diagnostics", "check the units: moments and products of inertia are in kg m²"));
        return;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(I, Eigen::EigenvaluesOnly);
    Eigen::Vector3d ev = es.eigenvalues();  // ascending
    const double scale = std::max(1.0, I.cwiseAbs().maxCoeff());
    const double tol = 1e-12 * scale;
    const SourcePos at = b.src.where("I");
    if (ev[0] < -tol) {
        d.error("inertia-not-psd", at,
                trText("Diagnostics", "%1's inertia tensor is not positive semi-definite (principal moments %2, %3, "
                                      "%4 kg m²)")
                    .with(who())
                    .with(fmt(ev[0]))
                    .with(fmt(ev[1]))
                    .with(fmt(ev[2])),
                trText("Diagnostics", "moments of inertia are zero or positive, and products of inertia cannot "
                                      "outweigh them; check signs and units (kg m²)"));
        return;
    }
    // triangle inequality on the principal moments: I1 + I2 >= I3
    if (ev[0] + ev[1] < ev[2] - 1e-9 * scale) {
        d.warning("inertia-triangle", at,
                  trText("Diagnostics", "%1's principal moments of inertia %2, %3, %4 kg m² break the triangle "
                                        "inequality (%2 + %3 < %4): no real body has them")
                      .with(who())
                      .with(fmt(ev[0]))
                      .with(fmt(ev[1]))
                      .with(fmt(ev[2])),
                  trText("Diagnostics", "check the values; the inertia calculator computes them from the body's shapes"));
    }
    if (b.mass == 0 && ev[2] > 0) {
        d.warning("inertia-without-mass", b.src.where("m"),
                  trText("Diagnostics", "%1 has no mass but a non-zero inertia").with(who()),
                  trText("Diagnostics", "give its mass, or set the inertia to zero as well"));
    }
}

/// Checks one side's A and R, with `digit` 1 or 2.
void checkAxes(const JointSpec& j, const JointSide& s, int digit, Diagnostics& d)
{
    auto who = [&] { return jointNamed(j.id, j.name); };
    const std::string n = std::to_string(digit);
    const double la = s.a.norm(), lr = s.r.norm();
    bool bad = false;
    if (!(la > 1e-12)) {
        d.error("zero-vector", s.src.where("A"), trText("Diagnostics", "%1: %2 has zero length").with(who()).with("A" + n),
                trText("Diagnostics", "the axis is a direction, e.g. A%1 0 0 1").with(n));
        bad = true;
    }
    if (!(lr > 1e-12)) {
        d.error("zero-vector", s.src.where("R"), trText("Diagnostics", "%1: %2 has zero length").with(who()).with("R" + n),
                trText("Diagnostics", "the reference direction is a direction perpendicular to A%1, e.g. R%1 0 1 0")
                    .with(n));
        bad = true;
    }
    if (bad) return;
    const double c = s.a.dot(s.r) / (la * lr);
    if (std::abs(c) > 1 - 1e-9) {
        d.error("axis-parallel", s.src.where("R"), trText("Diagnostics", "%1: R%2 is parallel to A%2").with(who()).with(n),
                trText("Diagnostics", "R%1 must be perpendicular to the axis A%1").with(n));
    } else if (std::abs(c) > kPerpendicularTolerance) {
        const double deg = std::acos(std::abs(c)) * 180.0 / std::numbers::pi;
        d.warning("not-perpendicular", s.src.where("R"),
                  trText("Diagnostics", "%1: R%2 is not perpendicular to A%2 (angle %3°); R%2 is made perpendicular")
                      .with(who())
                      .with(n)
                      .with(fmt(deg)),
                  trText("Diagnostics", "write R%1 at 90° to A%1").with(n));
    }
}

/// A free joint (T 3): no limits, no initial values (the body starts where its frames
/// coincide, at rest), a moving B2.
void checkFreeJoint(const JointSpec& j, Diagnostics& d)
{
    for (const auto& [key, v] : {std::pair{"LL", j.ll}, std::pair{"UL", j.ul}, std::pair{"QI", j.qi}, std::pair{"VI", j.vi}}) {
        if (!v) continue;
        // (a value given on the command line, --set/--rate, has no position of its own)
        d.error("free-joint-option", j.src.at.count(key) ? j.src.where(key) : j.src.pos,
                trText("Diagnostics", "joint %1 is a free joint (T 3): %2 does not apply to it")
                    .with(std::to_string(j.id))
                    .with(key),
                trText("Diagnostics", "remove %1; place the free body with the joint's P1, A1 and R1 (it starts where "
                                      "its two joint frames coincide, at rest)")
                    .with(key));
    }
    if (j.side1.present && j.side2.present && j.side2.body == 0) {
        d.error("free-joint-on-ground", j.side2.src.where("B"),
                trText("Diagnostics", "joint %1 is a free joint (T 3) whose B2 is the ground").with(std::to_string(j.id)),
                trText("Diagnostics", "the free body is B2: write B1 0 … and B2 with the body that moves"));
    }
}

void checkJoint(const ModelSpec& spec, const JointSpec& j, Diagnostics& d)
{
    auto who = [&] { return jointNamed(j.id, j.name); };
    for (int digit : {1, 2}) {
        const JointSide& s = digit == 1 ? j.side1 : j.side2;
        const std::string n = std::to_string(digit);
        if (!s.present) {
            d.error("missing-joint-line", j.src.pos, trText("Diagnostics", "%1 has no B%2 line").with(who()).with(n),
                    trText("Diagnostics", "follow the C line with B%1 body P%1 x y z A%1 x y z R%1 x y z").with(n));
            continue;
        }
        if (s.body >= 0 && !spec.bodyExists(s.body)) {
            d.error("undefined-body", s.src.where("B"),
                    trText("Diagnostics", "%1: body %2 (B%3) is not defined").with(who()).with(std::to_string(s.body)).with(n),
                    trText("Diagnostics", "add 'B %1 m Ixx Iyy Izz', or use an existing body").with(std::to_string(s.body)));
        }
        if (s.src.complete) checkAxes(j, s, digit, d);
    }
    if (j.side1.present && j.side2.present && j.side1.body >= 0 && j.side1.body == j.side2.body) {
        d.error("same-body", j.side2.src.where("B"),
                trText("Diagnostics", "%1 connects body %2 to itself").with(who()).with(std::to_string(j.side1.body)),
                trText("Diagnostics", "B1 and B2 must name two different bodies"));
    }
    const bool needsCl = j.type == JointType::Actuator;
    const bool hasCl1 = j.src.at.count("CL1") > 0, hasCl2 = j.src.at.count("CL2") > 0;
    if (needsCl && (!hasCl1 || !hasCl2)) {
        d.error("missing-cl", j.src.pos,
                !hasCl1 && !hasCl2
                    ? trText("Diagnostics", "%1 is a pivoted linear actuator (T 1) but has no CL1/CL2 line").with(who())
                    : trText("Diagnostics", "%1 is a pivoted linear actuator (T 1) but has no %2")
                          .with(who())
                          .with(!hasCl1 ? "CL1" : "CL2"),
                trText("Diagnostics", "add 'CL1 x y z CL2 x y z': the actuator's ends on body B1 and body B2, in "
                                      "their local frames"));
    }
    if (!needsCl && (hasCl1 || hasCl2)) {
        d.error("unexpected-cl", j.src.where(hasCl1 ? "CL1" : "CL2"),
                trText("Diagnostics", "%1 has CL1/CL2 but is not a pivoted linear actuator").with(who()),
                trText("Diagnostics", "CL1/CL2 belong to T 1 joints; add 'T 1' to the C line, or remove the CL line"));
    }
    if (!j.src.complete) return;
    if (j.type == JointType::Free) {
        checkFreeJoint(j, d);
        return;
    }
    // limits and initial values, with their unit
    const char* unit = j.type == JointType::Revolute ? " rad" : " m";
    auto value = [&](double v) { return fmt(v) + unit; };
    bool tooLarge = false;
    for (const auto& [key, v] : {std::pair{"LL", j.ll}, std::pair{"UL", j.ul}, std::pair{"QI", j.qi}, std::pair{"VI", j.vi}}) {
        if (!v || std::abs(*v) <= kMaxJointValue) continue;
        d.error("too-large", j.src.where(key),
                trText("Diagnostics", "%1: %2 = %3 is beyond any machine's (at most %4 in size)")
                    .with(who())
                    .with(key)
                    .with(fmt(*v))
                    .with(fmt(kMaxJointValue)),
                trText("Diagnostics", "check the units: lengths in m, angles in rad, rates in m/s or rad/s"));
        tooLarge = true;
    }
    if (tooLarge) return;
    if (j.ll && j.ul && *j.ll > *j.ul) {
        d.error("limits-reversed", j.src.where("LL"),
                trText("Diagnostics", "%1: the lower limit LL = %2 is above the upper limit UL = %3")
                    .with(who())
                    .with(value(*j.ll))
                    .with(value(*j.ul)),
                trText("Diagnostics", "swap LL and UL"));
        return;
    }
    if (j.type == JointType::Actuator) {
        for (const char* k : {"LL", "UL"}) {
            const auto& v = std::string(k) == "LL" ? j.ll : j.ul;
            if (v && !(*v > 0)) {
                d.error("bad-length", j.src.where(k),
                        trText("Diagnostics", "%1: %2 = %3 m, but a T 1 joint's coordinate is the actuator's length")
                            .with(who())
                            .with(k)
                            .with(fmt(*v)),
                        trText("Diagnostics", "give the cylinder's length between CL1 and CL2, in metres (positive)"));
            }
        }
        if (j.qi && !(*j.qi > 0)) {
            d.error("bad-length", j.src.where("QI"),
                    trText("Diagnostics", "%1: %2 = %3 m, but a T 1 joint's coordinate is the actuator's length")
                        .with(who())
                        .with("QI")
                        .with(fmt(*j.qi)),
                    trText("Diagnostics", "give the cylinder's initial length between CL1 and CL2, in metres (positive)"));
        }
    }
    const double eps = 1e-12;
    if (j.qi) {
        if (j.ll && *j.qi < *j.ll - eps) {
            d.error("qi-outside-limits", j.src.where("QI"),
                    trText("Diagnostics", "%1: QI = %2 is below the lower limit LL = %3")
                        .with(who())
                        .with(value(*j.qi))
                        .with(value(*j.ll)),
                    trText("Diagnostics", "give QI between LL and UL"));
        } else if (j.ul && *j.qi > *j.ul + eps) {
            d.error("qi-outside-limits", j.src.where("QI"),
                    trText("Diagnostics", "%1: QI = %2 is above the upper limit UL = %3")
                        .with(who())
                        .with(value(*j.qi))
                        .with(value(*j.ul)),
                    trText("Diagnostics", "give QI between LL and UL"));
        }
    }
    // a T 1 joint without QI starts mid-range (inside its limits), so only a written QI can sit on one
    if (j.vi && *j.vi != 0 && (j.qi || j.type != JointType::Actuator)) {
        const double q = j.qi.value_or(0.0);
        if (*j.vi > 0 && j.ul && q >= *j.ul - eps) {
            d.error("vi-outside-limits", j.src.where("VI"),
                    trText("Diagnostics", "%1: VI = %2 moves the joint past its upper limit UL = %3, where it starts")
                        .with(who())
                        .with(fmt(*j.vi))
                        .with(value(*j.ul)),
                    trText("Diagnostics", "start it inside its limits, or give VI ≤ 0"));
        } else if (*j.vi < 0 && j.ll && q <= *j.ll + eps) {
            d.error("vi-outside-limits", j.src.where("VI"),
                    trText("Diagnostics", "%1: VI = %2 moves the joint past its lower limit LL = %3, where it starts")
                        .with(who())
                        .with(fmt(*j.vi))
                        .with(value(*j.ll)),
                    trText("Diagnostics", "start it inside its limits, or give VI ≥ 0"));
        }
    }
}

/// A CYL or HMOTOR drive: its joint's type and stroke, its pump.
void checkFluidDrive(const ModelSpec& spec, const DriveSpec& dr, const JointSpec& j, Diagnostics& d)
{
    const bool cyl = dr.kind == DriveKind::Cylinder;
    if (cyl && j.type == JointType::Revolute) {
        d.error("cyl-on-revolute", dr.src.where("kind"),
                trText("Diagnostics", "%1: a CYL drive needs a T 1 or T 2 joint, but %2 is revolute")
                    .with(driveOn(dr.joint))
                    .with(jointNamed(j.id, j.name)),
                trText("Diagnostics", "drive a revolute joint with D j HMOTOR PUMP id DISP Dm VALVE Qn DP dp, or make "
                                      "the joint T 1 (a pivoted cylinder) or T 2"));
    } else if (!cyl && j.type != JointType::Revolute) {
        d.error("hmotor-on-linear", dr.src.where("kind"),
                trText("Diagnostics", "%1: an HMOTOR drive turns a revolute joint, but %2 is T %3")
                    .with(driveOn(dr.joint))
                    .with(jointNamed(j.id, j.name))
                    .with(std::to_string(static_cast<int>(j.type))),
                trText("Diagnostics", "drive a T 1 or T 2 joint with D j CYL PUMP id BORE d ROD d VALVE Qn DP dp"));
    } else if (cyl && (!j.ll || !j.ul)) {
        d.error("cyl-without-stroke", dr.src.where("kind"),
                trText("Diagnostics", "%1: a CYL drive needs the stroke, but %2 has no %3")
                    .with(driveOn(dr.joint))
                    .with(jointNamed(j.id, j.name))
                    .with(!j.ll && !j.ul ? "LL/UL" : !j.ll ? "LL" : "UL"),
                trText("Diagnostics", "give the joint LL (fully retracted) and UL (fully extended): the chamber "
                                      "volumes follow from them"));
    } else if (cyl && *j.ll >= *j.ul) {
        d.error("cyl-without-stroke", dr.src.where("kind"),
                trText("Diagnostics", "%1: the stroke of %2 is empty (LL %3 ≥ UL %4)")
                    .with(driveOn(dr.joint))
                    .with(jointNamed(j.id, j.name))
                    .with(fmt(*j.ll))
                    .with(fmt(*j.ul)),
                trText("Diagnostics", "LL is the fully retracted and UL the fully extended coordinate"));
    }
    const auto pumpId = dr.param("PUMP");
    if (pumpId && !spec.pump(static_cast<int>(*pumpId))) {
        std::string ids;
        for (const PumpSpec& p : spec.pumps) ids += (ids.empty() ? "" : ", ") + std::to_string(p.id);
        d.error("undefined-pump", dr.src.where("PUMP"),
                trText("Diagnostics", "%1: pump %2 is not defined").with(driveOn(dr.joint)).with(fmt(*pumpId)),
                ids.empty() ? trText("Diagnostics", "add a PUMP id FLOW Qmax PRESSURE p_max statement")
                            : trText("Diagnostics", "the pumps are %1").with(ids));
    }
}

void checkDrives(const ModelSpec& spec, Diagnostics& d)
{
    std::map<int, SourcePos> driven;
    for (const DriveSpec& dr : spec.drives) {
        const JointSpec* j = spec.joint(dr.joint);
        if (!j) {
            d.error("undefined-joint", dr.src.pos,
                    trText("Diagnostics", "%1: joint %2 is not defined").with(driveOn(dr.joint)).with(std::to_string(dr.joint)),
                    trText("Diagnostics", "use the id of a joint (C id …)"));
            continue;
        }
        auto [it, inserted] = driven.emplace(dr.joint, dr.src.pos);
        if (!inserted) {
            d.error("duplicate-drive", dr.src.pos,
                    trText("Diagnostics", "%1 already has a drive (line %2)")
                        .with(jointNamed(j->id, j->name))
                        .with(std::to_string(it->second.line)),
                    trText("Diagnostics", "one joint takes one drive; remove one of them"));
            continue;
        }
        if (!dr.src.complete) continue;
        if (j->type == JointType::Free) {
            d.error("drive-on-free-joint", dr.src.pos,
                    trText("Diagnostics", "%1: %2 is a free joint (T 3), which no drive can move")
                        .with(driveOn(dr.joint))
                        .with(jointNamed(j->id, j->name)),
                    trText("Diagnostics", "drive a T 0, T 1 or T 2 joint; push a free body with a force (F … POINT) "
                                          "instead"));
            continue;
        }
        if (dr.isFluidPower()) {
            checkFluidDrive(spec, dr, *j, d);
            continue;
        }
        if (dr.kind == DriveKind::Hydraulic && dr.param("PUMP") && j->type == JointType::Revolute) {
            d.error("pump-on-revolute", dr.src.where("PUMP"),
                    trText("Diagnostics", "%1: PUMP/BORE/ROD describe a cylinder, but %2 is revolute")
                        .with(driveOn(dr.joint))
                        .with(jointNamed(j->id, j->name)),
                    trText("Diagnostics", "for a hydraulic motor give VMAX (rad/s) and FMAX (N·m); or make the joint "
                                          "T 1 or T 2"));
        }
        if (dr.kind == DriveKind::Hydraulic && j->vi && j->src.complete) {
            // the speeds written (VMAX/VMIN) or those of the pump and cylinder data
            const DriveSpec::Hydraulic h = dr.hydraulic();
            const bool pump = dr.param("PUMP").has_value();
            if (h.vmax > 0) {
                const double up = h.vmax, down = h.vmin;
                if (*j->vi > up * (1 + 1e-12) || -*j->vi > down * (1 + 1e-12)) {
                    Text message = pump ? trText("Diagnostics", "%1: VI = %2 is faster than its hydraulic drive can "
                                                                "move it (%3, from its pump and cylinder data)")
                                        : trText("Diagnostics", "%1: VI = %2 is faster than its hydraulic drive can "
                                                                "move it (%3)");
                    message.arg(jointNamed(j->id, j->name)).arg(fmt(*j->vi)).arg(fmt(*j->vi > 0 ? up : down));
                    d.error("vi-above-vmax", j->src.where("VI"), std::move(message),
                            pump ? trText("Diagnostics", "give |VI| ≤ flow / bore area (extending) or flow / annulus "
                                                         "area (retracting)")
                                 : trText("Diagnostics", "give |VI| ≤ VMAX (extending) or VMIN (retracting)"));
                }
            }
        }
    }
}

void checkForces(const ModelSpec& spec, Diagnostics& d)
{
    for (const ForceSpec& f : spec.forces) {
        auto who = [&] { return trText("Diagnostics", "force %1").with(std::to_string(f.id)); };
        auto needBody = [&](int body, const char* key) {
            if (body >= 0 && !spec.bodyExists(body)) {
                d.error("undefined-body", f.src.where(key),
                        trText("Diagnostics", "%1: body %2 is not defined").with(who()).with(std::to_string(body)),
                        trText("Diagnostics", "use the id of a body (B id …)"));
            }
        };
        auto needJoint = [&](int joint, SourcePos at) {
            if (joint >= 0 && !spec.joint(joint)) {
                d.error("undefined-joint", at,
                        trText("Diagnostics", "%1: joint %2 is not defined").with(who()).with(std::to_string(joint)),
                        trText("Diagnostics", "use the id of a joint (C id …)"));
            } else if (joint >= 0 && spec.joint(joint)->type == JointType::Free) {
                d.error("free-joint-coordinate", at,
                        trText("Diagnostics", "%1: joint %2 is a free joint (T 3), which has no single coordinate")
                            .with(who())
                            .with(std::to_string(joint)),
                        trText("Diagnostics", "use a T 0, T 1 or T 2 joint here; load a free body with a force on the "
                                              "body (F … POINT or TORQUE)"));
            }
        };
        auto negative = [&](const char* key, Text hint) {
            d.error("negative-value", f.src.where(key), trText("Diagnostics", "%1: %2 is negative").with(who()).with(key),
                    std::move(hint));
        };
        auto notPositive = [&](const char* key, Text hint) {
            d.error("not-positive", f.src.where(key),
                    trText("Diagnostics", "%1: %2 must be positive").with(who()).with(key), std::move(hint));
        };
        switch (f.kind) {
        case ForceKind::Point:
        case ForceKind::Torque:
        case ForceKind::Aero: needBody(f.body, "B"); break;
        case ForceKind::Spring:
            needBody(f.body, "B1");
            needBody(f.body2, "B2");
            if (f.body >= 0 && f.body == f.body2) {
                d.error("same-body", f.src.where("B2"),
                        trText("Diagnostics", "%1: the spring connects body %2 to itself").with(who()).with(std::to_string(f.body)),
                        trText("Diagnostics", "B1 and B2 must name two different bodies"));
            }
            break;
        case ForceKind::Joint: needJoint(f.joint, f.src.where("JOINT")); break;
        }
        if (f.mag.kind == MagnitudeSpec::Kind::TableJoint) {
            // point at the joint id after TABLE Q, where the parser recorded it
            needJoint(f.mag.joint, f.src.at.count("Q") ? f.src.where("Q") : f.mag.pos);
        }
        if (!f.src.complete) continue;
        if ((f.kind == ForceKind::Point || f.kind == ForceKind::Torque) && !(f.dir.norm() > 1e-12)) {
            d.error("zero-vector", f.src.where("DIR"), trText("Diagnostics", "%1: %2 has zero length").with(who()).with("DIR"),
                    trText("Diagnostics", "give the force's direction, e.g. DIR 0 0 -1"));
        }
        if (f.kind == ForceKind::Spring) {
            if (f.stiffness < 0) negative("K", trText("Diagnostics", "a stiffness is ≥ 0, in N/m"));
            if (f.restLength < 0) negative("L0", trText("Diagnostics", "a rest length is ≥ 0, in m"));
            if (f.hasDamping && f.damping < 0) negative("C", trText("Diagnostics", "a damping is ≥ 0, in N s/m"));
        }
        if (f.kind == ForceKind::Aero) {
            if (!(f.area > 0)) notPositive("AREA", trText("Diagnostics", "the reference area in m²"));
            if (f.cd < 0) negative("CD", trText("Diagnostics", "a drag coefficient is ≥ 0"));
            if (f.hasRho && !(f.rho > 0)) {
                notPositive("RHO", trText("Diagnostics", "the fluid's density in kg/m³ (air: 1.225)"));
            }
        }
    }
}

void checkGraphics(const ModelSpec& spec, Diagnostics& d, const std::string& baseDir)
{
    for (const GraphicSpec& g : spec.graphics) {
        auto who = [&] { return trText("Diagnostics", "graphic %1").with(std::to_string(g.id)); };
        if (g.body >= 0 && !spec.bodyExists(g.body)) {
            d.error("undefined-body", g.src.where("B"),
                    trText("Diagnostics", "%1: body %2 is not defined").with(who()).with(std::to_string(g.body)),
                    trText("Diagnostics", "use the id of a body (B id …), or 0 for the ground"));
        }
        if (!g.src.complete) continue;
        if (g.shape == ShapeKind::Prism) {
            // area of the polygon (shoelace); a degenerate outline has none
            double area = 0;
            const std::size_t nv = (g.dims.size() - 1) / 2;
            for (std::size_t k = 0; k < nv; ++k) {
                const double x1 = g.dims[1 + 2 * k], y1 = g.dims[2 + 2 * k];
                const double x2 = g.dims[1 + 2 * ((k + 1) % nv)], y2 = g.dims[2 + 2 * ((k + 1) % nv)];
                area += x1 * y2 - x2 * y1;
            }
            if (!(g.dims[0] > 0)) {
                d.error("not-positive", g.src.where("dims"),
                        trText("Diagnostics", "%1: the PRISM's height H must be positive").with(who()),
                        trText("Diagnostics", "H is in metres"));
            }
            if (!(std::abs(area) > 1e-12)) {
                d.error("bad-prism", g.src.where("dims"), trText("Diagnostics", "%1: the PRISM's outline has no area").with(who()),
                        trText("Diagnostics", "give at least three x y vertices that are not on one line"));
            }
        } else {
            for (std::size_t k = 0; k < g.dims.size(); ++k) {
                if (!(g.dims[k] > 0)) {
                    d.error("not-positive", g.src.where("dims"),
                            trText("Diagnostics", "%1: %2 dimension %3 must be positive, not %4")
                                .with(who())
                                .with(shapeKeyword(g.shape))
                                .with(std::to_string(k + 1))
                                .with(fmt(g.dims[k])),
                            trText("Diagnostics", "dimensions are lengths in metres"));
                    break;
                }
            }
        }
        if (g.shape == ShapeKind::Tube && g.dims.size() == 3 && g.dims[1] >= g.dims[0]) {
            d.error("tube-radii", g.src.where("dims"),
                    trText("Diagnostics", "%1: the TUBE's inner radius is not smaller than its outer radius").with(who()),
                    trText("Diagnostics", "write TUBE RO RI L with RI < RO"));
        }
        if (g.shape == ShapeKind::Mesh) {
            if (g.hasScale && !(g.scale > 0)) {
                d.error("not-positive", g.src.where("SCALE"), trText("Diagnostics", "%1: %2 must be positive").with(who()).with("SCALE"),
                        trText("Diagnostics", "SCALE 0.001 turns millimetres into metres"));
            }
            if (!baseDir.empty() && !g.meshFile.empty()) {
                std::error_code ec;
                std::filesystem::path p = std::filesystem::path(baseDir) / g.meshFile;
                if (!std::filesystem::is_regular_file(p, ec)) {
                    d.error("mesh-not-found", g.src.where("dims"),
                            trText("Diagnostics", "%1: mesh file '%2' not found (looked for %3)")
                                .with(who())
                                .with(g.meshFile)
                                .with(p.string()),
                            trText("Diagnostics", "mesh paths are relative to the model file's folder"));
                }
            }
        }
        if (g.hasAxis && !(g.axis.norm() > 1e-12)) {
            d.error("zero-vector", g.src.where("AXIS"), trText("Diagnostics", "%1: %2 has zero length").with(who()).with("AXIS"),
                    trText("Diagnostics", "give a direction, e.g. AXIS 1 0 0"));
        }
        if (g.hasRot && !(g.rotAxis.norm() > 1e-12)) {
            d.error("zero-vector", g.src.where("ROT"), trText("Diagnostics", "%1: the ROT axis has zero length").with(who()),
                    trText("Diagnostics", "write ROT ax ay az degrees, e.g. ROT 0 0 1 90"));
        }
        if (g.hasColor && (g.color.minCoeff() < 0 || g.color.maxCoeff() > 1)) {
            d.error("bad-color", g.src.where("COLOR"),
                    trText("Diagnostics", "%1: COLOR components must lie between 0 and 1").with(who()),
                    trText("Diagnostics", "write COLOR r g b with 0 ≤ r, g, b ≤ 1 (e.g. 0.8 0.1 0.1 for red)"));
        }
        if (g.mass && *g.mass < 0) {
            d.error("negative-mass", g.src.where("MASS"), trText("Diagnostics", "%1: %2 is negative").with(who()).with("MASS"),
                    trText("Diagnostics", "a mass is ≥ 0, in kg"));
        }
        if (g.rho && !(*g.rho > 0)) {
            d.error("not-positive", g.src.where("RHO"), trText("Diagnostics", "%1: %2 must be positive").with(who()).with("RHO"),
                    trText("Diagnostics", "a density in kg/m³ (steel: 7850)"));
        }
    }
}

}  // namespace

void validateModel(const ModelSpec& spec, Diagnostics& d, const std::string& baseDir)
{
    if (spec.bodies.size() > kMaxBodies) {
        d.error("model-too-large", spec.bodies[kMaxBodies].src.pos,
                trText("Diagnostics", "the model has %1 bodies; Padrob takes at most %2")
                    .with(std::to_string(spec.bodies.size()))
                    .with(std::to_string(kMaxBodies)),
                trText("Diagnostics", "split the machine into smaller models, or merge bodies that move together"));
    }
    if (spec.joints.size() > kMaxJoints) {
        d.error("model-too-large", spec.joints[kMaxJoints].src.pos,
                trText("Diagnostics", "the model has %1 joints; Padrob takes at most %2")
                    .with(std::to_string(spec.joints.size()))
                    .with(std::to_string(kMaxJoints)),
                trText("Diagnostics", "split the machine into smaller models, or remove joints that never move"));
    }
    checkDuplicates(spec.bodies, [](const BodySpec& b) { return b.id; }, trText("Diagnostics", "body %1"), d);
    checkDuplicates(spec.joints, [](const JointSpec& j) { return j.id; }, trText("Diagnostics", "joint %1"), d);
    checkDuplicates(spec.forces, [](const ForceSpec& f) { return f.id; }, trText("Diagnostics", "force %1"), d);
    checkDuplicates(spec.graphics, [](const GraphicSpec& g) { return g.id; }, trText("Diagnostics", "graphic %1"), d);
    for (const BodySpec& b : spec.bodies) checkBody(b, d);
    for (const JointSpec& j : spec.joints) checkJoint(spec, j, d);
    checkDrives(spec, d);
    checkForces(spec, d);
    checkGraphics(spec, d, baseDir);
}

}  // namespace solver
