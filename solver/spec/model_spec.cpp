#include "solver/spec/model_spec.h"

#include <limits>
#include <numbers>

namespace solver {

Eigen::Matrix3d BodySpec::inertiaTensor() const
{
    Eigen::Matrix3d I;
    const double ixy = products.x(), iyz = products.y(), ixz = products.z();
    I << inertia.x(), ixy, ixz,
         ixy, inertia.y(), iyz,
         ixz, iyz, inertia.z();
    return I;
}

std::optional<double> DriveSpec::param(std::string_view key) const
{
    for (const auto& [k, v] : params) {
        if (k == key) return v;
    }
    return std::nullopt;
}

std::optional<std::pair<double, double>> DriveSpec::pair(std::string_view key) const
{
    for (const auto& [k, v] : pairs) {
        if (k == key) return v;
    }
    return std::nullopt;
}

DriveSpec::Hydraulic DriveSpec::hydraulic() const
{
    Hydraulic h;
    const double inf = std::numeric_limits<double>::infinity();
    if (auto pump = param("PUMP")) {
        const double flow = *pump * 1e-6 * param("RPM").value_or(0) / 60.0;  // [m^3/s]
        const double bore = param("BORE").value_or(0), rod = param("ROD").value_or(0);
        const double area = std::numbers::pi / 4 * bore * bore;
        const double annulus = area - std::numbers::pi / 4 * rod * rod;
        const double pressure = param("PRESSURE").value_or(0);
        h.vmax = area > 0 ? flow / area : 0;
        h.vmin = annulus > 0 ? flow / annulus : 0;
        h.fmax = pressure * area;
        h.fmin = pressure * annulus;
        return h;
    }
    h.vmax = param("VMAX").value_or(0);
    h.vmin = param("VMIN").value_or(h.vmax);
    h.fmax = param("FMAX").value_or(inf);
    h.fmin = param("FMIN").value_or(h.fmax);
    return h;
}

const BodySpec* ModelSpec::body(int id) const
{
    for (const BodySpec& b : bodies) {
        if (b.id == id) return &b;
    }
    return nullptr;
}

const JointSpec* ModelSpec::joint(int id) const
{
    for (const JointSpec& j : joints) {
        if (j.id == id) return &j;
    }
    return nullptr;
}

const PumpSpec* ModelSpec::pump(int id) const
{
    for (const PumpSpec& p : pumps) {
        if (p.id == id) return &p;
    }
    return nullptr;
}

const char* jointTypeName(JointType t)
{
    switch (t) {
    case JointType::Revolute: return "revolute";
    case JointType::Actuator: return "actuator";
    case JointType::Prismatic: return "prismatic";
    case JointType::Free: return "free";
    }
    return "revolute";
}

const char* driveKindKeyword(DriveKind k)
{
    switch (k) {
    case DriveKind::Hydraulic: return "HYD";
    case DriveKind::Motor: return "MOTOR";
    case DriveKind::Pneumatic: return "PNEU";
    case DriveKind::Servo: return "SERVO";
    case DriveKind::Cylinder: return "CYL";
    case DriveKind::HydraulicMotor: return "HMOTOR";
    }
    return "HYD";
}

const char* forceKindKeyword(ForceKind k)
{
    switch (k) {
    case ForceKind::Point: return "POINT";
    case ForceKind::Torque: return "TORQUE";
    case ForceKind::Joint: return "JOINT";
    case ForceKind::Spring: return "SPRING";
    case ForceKind::Aero: return "AERO";
    }
    return "POINT";
}

const char* shapeKeyword(ShapeKind k)
{
    switch (k) {
    case ShapeKind::Box: return "BOX";
    case ShapeKind::Cylinder: return "CYL";
    case ShapeKind::Tube: return "TUBE";
    case ShapeKind::Sphere: return "SPHERE";
    case ShapeKind::Cone: return "CONE";
    case ShapeKind::Ellipsoid: return "ELLIPSOID";
    case ShapeKind::Prism: return "PRISM";
    case ShapeKind::Mesh: return "MESH";
    }
    return "BOX";
}

}  // namespace solver
