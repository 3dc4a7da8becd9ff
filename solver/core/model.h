#pragma once
// Model: the compiled, immutable form of a model, built once by compileModel()
// (solver/compile/compile.h) and shared as std::shared_ptr<const Model> by every
// thread that simulates, draws or checks it. It holds no per-step values: those
// live in State (what the integrator advances) and Data (derived values and
// scratch), so several States can share one Model.
//
// Numbering (Featherstone's, 0-based): the moving bodies are numbered in tree
// order, 0 … nb−1, so that body i's parent joint is joint i and its parent body
// parent[i] < i (−1 = ground). Arrays below are indexed by that number ("tree
// index"); the modeler's ids are in bodyId/jointId.
//
// Coordinates: the state holds each joint's kinematic coordinate θ: the angle
// [rad] for revolute (T 0) and pivoted-actuator (T 1) joints, the displacement
// [m] for prismatic (T 2) joints. For T 1 the modeler's coordinate is the
// actuator length L(θ) (lengthLaw), used for limits, drives and output.
//
// Frames: each joint has a joint frame with axes (A, R, T = A×R) as columns and
// origin P. X_pj is its pose in the parent body's frame, X_cj in the child's. The
// child's pose in the parent's is X_pc(θ) = X_pj · J(σθ) · X_cj⁻¹, where J turns
// about the joint frame's x axis (= A) for T 0/T 1 or shifts along its y axis
// (= R) for T 2, and σ = axisSign is +1, or −1 when the modeler wrote the joint
// from the child to the parent (B1 is the child). Body frames have their origin
// where the modeler put it (the centre of mass unless CG moves it).
//
// Free joints (T 3): a free body's six degrees of freedom are six consecutive tree
// joints (Model::freeSlot 0…5) with five massless bodies between them: three
// prismatic ones along the free joint's B1 frame axes A, R, T (the body frame's
// translation from the start), then three revolute ones about the x, y and z axes of
// a base orientation, a unit quaternion kept in State::q after the nb coordinates
// (Model::freeBase). The turns stay small: the Simulation folds them into the
// quaternion and sets them back to 0 (foldFreeRotations), so the three angles never
// reach gimbal lock and the articulated-body algorithm stays the same O(n) for every
// joint (docs/free-bodies.md).
//
// Closed loops: the joints the spanning tree leaves out (cut joints, Topology::
// loopJoints) are kept in `cuts` with their two bodies' tree indices and frames;
// the dynamics hold them closed as constraints (solver/dynamics/constraints.h).
// Everything indexed by tree index stays as it is.

#include "solver/core/actuator_law.h"
#include "solver/core/contact.h"
#include "solver/core/fluid_power.h"
#include "solver/core/kinds.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace solver {

/// Hydraulic: the thesis's prescribed-rate drive (HYD). FluidPower: a CYL/HMOTOR drive,
/// force-driven by its chambers' pressures (CompiledDrive::circuit, core/fluid_power.h).
enum class DriveType { None, Hydraulic, Motor, Pneumatic, Servo, FluidPower };

/// A joint's drive, in the joint's own coordinate (T 1: the actuator length).
struct CompiledDrive {
    DriveType type = DriveType::None;
    // Hydraulic: q̇ = u·vmax (u > 0) or u·vmin (u < 0); relief at fmax (extending) / fmin (retracting)
    double vmax = 0, vmin = 0;   ///< [m/s or rad/s] (magnitudes)
    double fmax = std::numeric_limits<double>::infinity();  ///< [N or N m] (magnitude)
    double fmin = std::numeric_limits<double>::infinity();  ///< [N or N m] (magnitude)
    // Motor: τ = u·t0·(1 − |q̇|/w0), 0 beyond w0
    double t0 = 0, w0 = 0;       ///< [N m], [rad/s]
    // Pneumatic: F = u·force
    double force = 0;            ///< [N]
    // Servo: PID on the set-point setLow + (u+1)/2·(setHigh − setLow), output clamped to ±servoFmax
    double kp = 0, ki = 0, kd = 0;
    double servoFmax = std::numeric_limits<double>::infinity();
    double setLow = 0, setHigh = 0;
    // FluidPower: its circuit's index in Model::circuits
    int circuit = -1;
};

/// A magnitude law (the spec's MagnitudeSpec compiled: TABLE Q's joint as a tree index).
struct CompiledMagnitude {
    MagnitudeKind kind = MagnitudeKind::Constant;
    double value = 0, amplitude = 0, frequency = 0, phase = 0, offset = 0;
    int joint = -1;  ///< TableJoint: tree index; the table's abscissa is that joint's modeler coordinate
    std::vector<double> x, y;  ///< table abscissae (increasing) and values
};

/// An applied force (ForceSpec compiled: bodies and joints as tree indices, −1 = ground).
struct CompiledForce {
    int id = 0;
    ForceKind kind = ForceKind::Point;
    int body = -1, body2 = -1, joint = -1;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< body-local [m]
    Eigen::Vector3d point2 = Eigen::Vector3d::Zero();  ///< SPRING: on body2, local [m]
    Eigen::Vector3d dir = Eigen::Vector3d::UnitZ();    ///< unit; world axes unless local
    bool local = false;
    CompiledMagnitude mag;
    double stiffness = 0, restLength = 0, damping = 0;
    double area = 0, cd = 0, cl = 0, rho = 1.225;
};

/// A loop-closure (cut) joint: a constraint between two bodies, not a coordinate.
/// A T 1 cut joint constrains like a revolute (its length is then not a coordinate).
struct CutJoint {
    int jointId = 0;           ///< modeler's id
    std::string name;
    JointType type = JointType::Revolute;
    int body1 = -1, body2 = -1;  ///< tree indices of side 1 (B1) and side 2 (B2); −1 = ground
    Eigen::Isometry3d X_1 = Eigen::Isometry3d::Identity();  ///< joint frame (A, R, T at P1) in body 1's frame
    Eigen::Isometry3d X_2 = Eigen::Isometry3d::Identity();  ///< joint frame at P2 in body 2's frame
    Eigen::Vector3d cl1 = Eigen::Vector3d::Zero(), cl2 = Eigen::Vector3d::Zero();  ///< T 1: ends, in bodies 1 and 2
};

/// The modeler's coordinate of a joint as a function of θ, at one θ: q, dq/dθ and
/// d²q/dθ² (T 1: L, L', L''; otherwise θ, 1, 0).
struct CoordinateMap {
    double q = 0;    ///< [rad or m]
    double dq = 1;   ///< [m/rad for T 1, else 1]
    double ddq = 0;  ///< [m/rad^2 for T 1, else 0]
};

struct Model {
    int nb = 0;  ///< moving bodies = tree joints = θ̇ coordinates
    int nq = 0;  ///< dim State::q: the nb coordinates θ, then a quaternion (w, x, y, z) per free joint
    Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.81);  ///< [m/s^2]
    double restitution = 0;  ///< coefficient of restitution at joint limits (0 = inelastic)

    // per body / joint, by tree index (dim nb)
    std::vector<int> parent;            ///< parent body's tree index, −1 = ground
    std::vector<int> bodyId;            ///< modeler's body id
    std::vector<int> jointId;           ///< modeler's id of the body's parent joint
    std::vector<std::string> bodyName, jointName;
    std::vector<JointType> jointType;     ///< a free joint's coordinates: Prismatic (slots 0–2), Revolute (3–5)
    /// −1, or which coordinate of a free joint (T 3) this tree joint is: 0–2 the
    /// translations along the B1 frame's A, R, T axes, 3–5 the turns about the base
    /// orientation's x, y, z axes. Only slot 5's child is the free body; the bodies of
    /// slots 0–4 are massless and have bodyId −1.
    std::vector<int> freeSlot;
    /// Per tree joint: the index in State::q of the base orientation (w, x, y, z) that
    /// slot 3's frame turns by; −1 for every other joint.
    std::vector<int> freeBase;
    /// The tree index of each free joint's slot 0, in tree order.
    std::vector<int> freeJoints;
    std::vector<Eigen::Isometry3d> X_pj;  ///< joint frame in the parent body (ground: world)
    std::vector<Eigen::Isometry3d> X_cj;  ///< joint frame in the child body
    std::vector<Eigen::Isometry3d> X_jc;  ///< X_cj⁻¹: the child body's frame in its joint frame (derived)
    std::vector<double> axisSign;         ///< +1, or −1 when written child → parent
    std::vector<ActuatorLengthLaw> lengthLaw;  ///< T 1 only: L²(θ) law of the actuator
    std::vector<Eigen::Vector3d> cl1, cl2;     ///< T 1 only: actuator ends, in the B1 and B2 body frames
    std::vector<double> lower, upper;     ///< limits on θ (T 1: converted from lengths), ±∞ when absent
    std::vector<double> mass;             ///< [kg]
    std::vector<Eigen::Vector3d> com;     ///< centre of mass in the body frame [m]
    std::vector<Eigen::Matrix3d> inertia; ///< about the centre of mass, body axes [kg m^2]
    std::vector<CompiledDrive> drive;
    /// Initial θ (dim nq: the free joints' quaternions are (1, 0, 0, 0)) and θ̇ (dim nb)
    /// (QI/VI converted).
    std::vector<double> theta0, thetaDot0;
    /// Per joint: 1 when its coordinate follows from the loop closures (Topology::
    /// dependent): its initial rate is solved from the others', its VI is not used.
    std::vector<char> dependent;

    std::vector<CompiledForce> forces;

    // fluid power (solver/hydraulics/): empty without CYL/HMOTOR drives
    CompiledFluid fluid;
    std::vector<CompiledPump> pumps;        ///< in file order
    std::vector<CompiledCircuit> circuits;  ///< one per CYL/HMOTOR drive, by joint id

    /// CONTACT: the contact law and the solids' shapes (core/contact.h); null without
    /// CONTACT (then nothing touches and the model behaves as before).
    std::shared_ptr<const CompiledContact> contact;

    std::vector<CutJoint> cuts;  ///< loop-closure joints (empty for an open tree)
    /// Length [m] that makes the constraints' length rows comparable to their
    /// dimensionless (direction) rows: the size of the mechanism (≥ 1 mm).
    double lengthScale = 1.0;

    /// Tree index of the joint with modeler id `id` (a free joint: its slot 0), or −1.
    int jointIndex(int id) const;
    /// Tree index of the body with modeler id `id`; −1 for ground or an unknown id.
    /// (A free body: slot 5's; the massless bodies between a free joint's slots have id −1.)
    int bodyIndex(int id) const;
    /// The modeler's coordinate q of joint i at θ (T 1: the length L(θ); else θ).
    double coordinate(int i, double theta) const;
    /// dq/dθ of joint i at θ (T 1: dL/dθ; else 1).
    double coordinateRate(int i, double theta) const;
    /// q, dq/dθ and d²q/dθ² of joint i at θ at once (the same values as the two above;
    /// for T 1 one sine and cosine and one square root, for the step loop).
    CoordinateMap coordinateMap(int i, double theta) const;
};

}  // namespace solver
