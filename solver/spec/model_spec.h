#pragma once
// ModelSpec: a model as the modeler wrote it (see docs/model-language.md).
//
// The parser fills it; the writer prints it back; the checks and the compiler read
// it. It holds no indices and no derived physics: ids are the modeler's ids, values
// are SI as written (angles given with DEG are already converted to radians), and
// every element keeps the source position of its statement and of each keyword's
// value so that later stages can point at the text.

#include "solver/core/diagnostic.h"
#include "solver/core/kinds.h"

#include <Eigen/Core>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace solver {

/// Positions of the values of an element's keywords ("QI" -> where QI's value is).
struct FieldPositions {
    SourcePos pos;  ///< the statement's first token
    std::map<std::string, SourcePos, std::less<>> at;
    /// False when the statement had syntax errors: later checks skip its values
    /// (the error is already reported; no cascade of follow-up diagnostics).
    bool complete = true;

    /// Position of keyword `key`'s value, or of the statement when it was not written.
    SourcePos where(std::string_view key) const
    {
        auto it = at.find(key);
        return it == at.end() ? pos : it->second;
    }
};

/// `B id [m Ixx Iyy Izz [Ixy Iyz Ixz]] [CG x y z] [NAME "text"]`
struct BodySpec {
    int id = 0;
    bool hasMass = false;       ///< false: massless body (no numbers written)
    double mass = 0;            ///< [kg]
    Eigen::Vector3d inertia = Eigen::Vector3d::Zero();   ///< Ixx Iyy Izz about the CG, local axes [kg m^2]
    bool hasProducts = false;
    /// Ixy Iyz Ixz: the tensor's off-diagonal elements (I = [[Ixx Ixy Ixz][Ixy Iyy Iyz][Ixz Iyz Izz]]),
    /// i.e. Ixy = -∫xy dm [kg m^2].
    Eigen::Vector3d products = Eigen::Vector3d::Zero();
    bool hasCg = false;
    Eigen::Vector3d cg = Eigen::Vector3d::Zero();  ///< centre of mass in the local frame [m]
    std::string name;
    FieldPositions src;

    /// Full inertia tensor about the centre of mass, local axes [kg m^2].
    Eigen::Matrix3d inertiaTensor() const;
};

/// One side of a joint: `B1 i P1 x y z A1 x y z R1 x y z` (or B2/P2/A2/R2).
struct JointSide {
    int body = -1;
    Eigen::Vector3d p = Eigen::Vector3d::Zero();  ///< joint point, body local frame [m]
    Eigen::Vector3d a = Eigen::Vector3d::UnitZ();  ///< axis as written (not normalised)
    Eigen::Vector3d r = Eigen::Vector3d::UnitY();  ///< reference direction as written
    bool present = false;
    FieldPositions src;  ///< pos = the B1/B2 token; at: "B", "P", "A", "R"
};

/// `C id [T type] [LL v] [UL v] [QI v] [VI v] [NAME "text"]` + B1, B2 (+ CL1 CL2 for T 1).
/// For T 0 the coordinate is an angle [rad], for T 2 a displacement [m], for T 1 the
/// actuator length [m].
struct JointSpec {
    int id = 0;
    JointType type = JointType::Revolute;
    bool typeWritten = false;
    std::optional<double> ll, ul, qi, vi;
    std::string name;
    JointSide side1, side2;
    bool hasCl = false;  ///< CL1/CL2 written
    Eigen::Vector3d cl1 = Eigen::Vector3d::Zero();  ///< actuator end on body side1.body, local [m]
    Eigen::Vector3d cl2 = Eigen::Vector3d::Zero();  ///< actuator end on body side2.body, local [m]
    FieldPositions src;  ///< at: "T", "LL", "UL", "QI", "VI", "NAME", "CL1", "CL2"
};

/// Drive kinds: `D joint HYD|MOTOR|PNEU|SERVO|CYL|HMOTOR params…`. HYD is the
/// thesis's prescribed-rate drive; CYL and HMOTOR are fluid-power drives (a valve
/// section fed by a PUMP, chambers with real pressures: solver/hydraulics/).
enum class DriveKind { Hydraulic, Motor, Pneumatic, Servo, Cylinder, HydraulicMotor };

struct DriveSpec {
    int joint = 0;
    DriveKind kind = DriveKind::Hydraulic;
    /// Parameters in the order written, keyword (upper case) → value (SI). CYL and
    /// HMOTOR: PUMP is the pump's id (an integer).
    std::vector<std::pair<std::string, double>> params;
    /// CYL, HMOTOR: options with two numbers (DEAD, VOLUME, P0), in the order written.
    std::vector<std::pair<std::string, std::pair<double, double>>> pairs;
    /// CYL, HMOTOR: COMP's word as written in upper case (NONE, PRE, POST); empty when absent.
    std::string compensation;
    FieldPositions src;  ///< at: each parameter keyword

    std::optional<double> param(std::string_view key) const;
    std::optional<std::pair<double, double>> pair(std::string_view key) const;
    /// CYL or HMOTOR.
    bool isFluidPower() const { return kind == DriveKind::Cylinder || kind == DriveKind::HydraulicMotor; }

    /// A hydraulic drive's effective data, from VMAX/VMIN/FMAX/FMIN or from the
    /// pump and cylinder data (flow = cc·rpm; speeds = flow / bore or annulus area;
    /// forces = pressure · area). Absent forces are unlimited (infinity).
    struct Hydraulic {
        double vmax = 0;  ///< extending speed [m/s or rad/s]
        double vmin = 0;  ///< retracting speed (magnitude)
        double fmax = 0;  ///< relief force extending [N or N m]
        double fmin = 0;  ///< relief force retracting (magnitude)
    };
    Hydraulic hydraulic() const;
};

/// A magnitude: a number, `SIN amp freq phase [offset]`, `TABLE T t v …` or `TABLE Q j q v …`.
struct MagnitudeSpec {
    using Kind = MagnitudeKind;
    Kind kind = Kind::Constant;
    double value = 0;                                  ///< Constant
    double amplitude = 0, frequency = 0, phase = 0, offset = 0;  ///< Sine: freq [Hz], phase [rad]
    bool hasOffset = false;
    int joint = -1;                                    ///< TableJoint
    std::vector<std::pair<double, double>> table;      ///< (t or q, value)
    SourcePos pos;
};

/// `F id kind params…`
struct ForceSpec {
    int id = 0;
    ForceKind kind = ForceKind::Point;
    int body = -1;    ///< POINT, TORQUE, AERO: B i; SPRING: B1 i
    int body2 = -1;   ///< SPRING: B2 k
    int joint = -1;   ///< JOINT j
    Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< P / P1 [m]
    Eigen::Vector3d point2 = Eigen::Vector3d::Zero();  ///< SPRING P2 [m]
    Eigen::Vector3d dir = Eigen::Vector3d::UnitZ();    ///< POINT, TORQUE
    bool local = false;
    MagnitudeSpec mag;  ///< POINT, TORQUE, JOINT
    double stiffness = 0, restLength = 0, damping = 0;  ///< SPRING K [N/m], L0 [m], C [N s/m]
    bool hasDamping = false;
    double area = 0, cd = 0, cl = 0, rho = 1.225;  ///< AERO [m^2], -, -, [kg/m^3]
    bool hasCl = false, hasRho = false;
    FieldPositions src;
};

enum class ShapeKind { Box, Cylinder, Tube, Sphere, Cone, Ellipsoid, Prism, Mesh };

/// `G id B i shape params… [POS x y z] [AXIS x y z] [ROT ax ay az deg] [COLOR r g b] [MASS m | RHO ρ]`
struct GraphicSpec {
    int id = 0;
    int body = -1;
    ShapeKind shape = ShapeKind::Box;
    std::vector<double> dims;  ///< BOX X Y Z; CYL R L; TUBE RO RI L; SPHERE R; CONE R L;
                               ///< ELLIPSOID A B C; PRISM H x1 y1 x2 y2 …; MESH: empty
    std::string meshFile;      ///< MESH "file", relative to the model file
    double scale = 1;          ///< MESH SCALE
    bool hasScale = false;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    bool hasPosition = false;
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    bool hasAxis = false;
    Eigen::Vector3d rotAxis = Eigen::Vector3d::UnitZ();
    double rotDeg = 0;
    bool hasRot = false;
    Eigen::Vector3d color = Eigen::Vector3d(0.6, 0.6, 0.6);
    bool hasColor = false;
    std::optional<double> mass;  ///< [kg]
    std::optional<double> rho;   ///< [kg/m^3]
    bool noContact = false;      ///< NOCONTACT: drawn only, never touches (CONTACT)
    FieldPositions src;
};

/// `CONTACT [MU μ] [E e]`: solids touch (at most one statement; docs/contact.md).
struct ContactSpec {
    std::optional<double> mu;  ///< Coulomb friction coefficient (default kDefaultContactFriction)
    std::optional<double> e;   ///< coefficient of restitution (default 0)
    FieldPositions src;        ///< at: "MU", "E"
};

/// `FLUID [BULK β] [LAMINAR p_lam]`: the hydraulic oil (at most one statement).
struct FluidSpec {
    std::optional<double> bulk;     ///< effective bulk modulus β [Pa] (default kDefaultBulkModulus)
    std::optional<double> laminar;  ///< Δp below which orifices are laminar [Pa] (default kDefaultLaminarPressure)
    FieldPositions src;             ///< at: "BULK", "LAMINAR"
};

/// `PUMP id FLOW Qmax PRESSURE p_max [MARGIN Δp_ls] [NAME "…"]`: a pump feeding any
/// number of CYL/HMOTOR drives; with MARGIN it is load-sensing.
struct PumpSpec {
    int id = 0;
    double flow = 0;      ///< Qmax [m^3/s]
    double pressure = 0;  ///< p_max [Pa] (the compensator's and relief valves' setting)
    std::optional<double> margin;  ///< Δp_ls [Pa]
    std::string name;
    FieldPositions src;   ///< at: "FLOW", "PRESSURE", "MARGIN", "NAME"
};

struct ModelSpec {
    std::string file;  ///< the file it was read from (for diagnostics and mesh paths)
    bool hasGravity = false;
    Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);  ///< [m/s^2]
    SourcePos gravityPos;
    /// `RESTITUTION e`: coefficient of restitution at joint limits, 0 (inelastic,
    /// the default) … 1 (elastic).
    bool hasRestitution = false;
    double restitution = 0;
    SourcePos restitutionPos;
    std::vector<BodySpec> bodies;    ///< in file order (body 0 only if written)
    std::vector<JointSpec> joints;   ///< in file order
    std::vector<DriveSpec> drives;
    std::optional<FluidSpec> fluid;
    std::vector<PumpSpec> pumps;     ///< in file order
    std::optional<ContactSpec> contact;
    std::vector<ForceSpec> forces;
    std::vector<GraphicSpec> graphics;

    const BodySpec* body(int id) const;
    const JointSpec* joint(int id) const;
    const PumpSpec* pump(int id) const;
    /// True when `id` is ground (0) or a written body.
    bool bodyExists(int id) const { return id == 0 || body(id) != nullptr; }
};

const char* jointTypeName(JointType t);  ///< "revolute", "actuator", "prismatic"
const char* driveKindKeyword(DriveKind k);  ///< "HYD", …
const char* forceKindKeyword(ForceKind k);  ///< "POINT", …
const char* shapeKeyword(ShapeKind k);      ///< "BOX", "CYL", …

}  // namespace solver
