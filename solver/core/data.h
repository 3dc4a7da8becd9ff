#pragma once
// Data: values derived from a Model and a State, and the algorithms' scratch.
// Allocated once by Data(model); the step loop never allocates. One per thread.
//
// 3D vectors are in world axes. Spatial vectors (core/spatial.h) are in world axes
// too: motion vectors [ω; v] and force vectors [moment; force], with the point
// the velocity or the moment refers to named in each field's comment.

#include "solver/core/constraint.h"
#include "solver/core/model.h"
#include "solver/core/spatial.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace solver {

struct Data {
    explicit Data(const Model& model);

    // ---- kinematics (solver/kinematics/kinematics.h) ------------------------
    std::vector<Eigen::Isometry3d> X_wb;  ///< pose of each body frame in the world (dim nb)
    /// Pose in the world of each joint's frame on the child's side (dim nb): origin at
    /// the child's joint point P, axes (A, R, T) as carried by the child (= X_wb · X_cj).
    std::vector<Eigen::Isometry3d> X_wj;
    std::vector<Eigen::Vector3d> omega;   ///< angular velocity, world axes [rad/s] (dim nb)
    std::vector<Eigen::Vector3d> vel;     ///< velocity of the body frame's origin, world [m/s]
    std::vector<Eigen::Vector3d> alpha;   ///< angular acceleration, world [rad/s^2]
    std::vector<Eigen::Vector3d> acc;     ///< acceleration of the body frame's origin, world [m/s^2]
    /// Joint motion subspace S_i (dim nb): the child's spatial velocity relative to its
    /// parent per unit θ̇_i, about the world origin: σ[a; p × a] for T 0/T 1 (a: world
    /// axis A, p: joint point), σ[0; r] for T 2 (r: world direction R).
    std::vector<Vector6d> S;
    std::vector<Vector6d> v;   ///< spatial velocity [ω; v_O] of each body, about the world origin
    std::vector<Vector6d> a;   ///< spatial acceleration [α; a_O] = d/dt v (RBDA §2.11)

    // ---- applied loads (solver/dynamics/applied_forces.h) --------------------
    std::vector<Vector6d> fext;           ///< applied load on each body, about its frame origin (dim nb)
    Eigen::VectorXd tauExt;               ///< generalized applied force on each θ (F JOINT, by θ) (dim nb)

    // ---- contact (solver/contact/contact_forces.h): empty without CONTACT -------
    /// The contacts of the last evaluation (capacity kMaxContacts; size: how many).
    std::vector<ContactPoint> contacts;
    std::unique_ptr<ContactScratch> contactScratch;  ///< FCL objects of this thread

    // ---- fluid power (solver/hydraulics/circuit.h): sized 0 without circuits --
    /// d/dt State::fluid (dim kFluidStates · circuits): spool rate, ṗ_A, ṗ_B.
    Eigen::VectorXd fluidRate;
    Eigen::VectorXd supplyPressure;  ///< per pump: p_S [Pa]
    Eigen::VectorXd pumpFlow;        ///< per pump: the flow it delivers [m^3/s] (≤ Qmax)
    /// Per pump: what the open sections would draw at the pump's own setting [m^3/s];
    /// above Qmax the pump saturates (the flows are shared out, or the supply falls).
    Eigen::VectorXd pumpDemand;
    Eigen::VectorXd pumpShare;       ///< per pump: the factor on its meter-in flows (POST saturation), else 1
    Eigen::VectorXd pressureA, pressureB;  ///< per circuit: p_A, p_B as used (≥ 0) [Pa]
    Eigen::VectorXd flowA, flowB;    ///< per circuit: valve flow into A and into B [m^3/s] (< 0: out)
    Eigen::VectorXd reliefFlow;      ///< per circuit: port relief flow to tank, both chambers [m^3/s]
    /// Per circuit: 1 chamber A, 2 chamber B, 3 both cavitate (the pressure is held at
    /// 0 while the flow would take it lower).
    std::vector<int> cavitation;
    /// Per circuit: the oil spring β·(A_A²/V_A + A_B²/V_B) [N/m or N m/rad] and the
    /// fastest pressure relaxation β/V·∂Q/∂p [1/s] with the spool's 1/τ: what the
    /// real-time integrator's sub-steps are chosen from (hydraulics/circuit.h).
    Eigen::VectorXd oilStiffness, fluidDecay;
    /// Per joint: the least inertia the dynamics give the joint's own degree of freedom,
    /// along the modeler's coordinate [kg or kg m^2] (an armature added where the
    /// articulated inertia is below it: RBDA's D_i); empty: none. At the real-time
    /// step h the Simulation sets oilSpringStep = h, and every evaluation of the
    /// circuits then sets a fluid-power joint's floor to its oil stiffness·(h/0.6)², so
    /// that the oil spring of a light part stays resolved (hydraulics/circuit.h).
    Eigen::VectorXd inertiaFloor;
    double oilSpringStep = 0;  ///< [s]; 0: no floor

    // ---- dynamics (solver/dynamics/forward_dynamics.h) ----------------------
    Eigen::VectorXd qdd;          ///< θ̈ (dim nb)
    /// Generalized force the joint transmits along θ (dim nb) [N or N m]: drive +
    /// tauExt + the limit stop's force. For a joint with prescribed acceleration
    /// (hydraulic with the relief closed, or at a limit) this is what the hybrid
    /// algorithm solves for.
    Eigen::VectorXd tau;
    /// Per joint: its drive's force in the modeler's coordinate — the cylinder's force
    /// along its axis [N] for T 1, the force [N] for T 2, the torque [N m] for T 0 —
    /// positive when it pushes q up; 0 for a passive joint. A hydraulic joint with the
    /// relief closed, or at a limit, carries what it must: (tau − tauExt) / (dq/dθ).
    Eigen::VectorXd driveForce;
    /// Per joint: the generalized force along θ of the limit stop of a joint at a
    /// limit (tau − drive − tauExt) [N or N m]; ≥ 0 pushes θ up (a lower stop holding),
    /// ≤ 0 down. 0 for a free joint, and for a hydraulic joint (its cylinder carries
    /// the load, in driveForce).
    Eigen::VectorXd limitForce;
    /// Per joint: the load the parent body exerts on the child through the joint
    /// (drive and constraint together), world axes, moment about the child's joint
    /// point (the origin of X_wj): [M; F] [N m; N].
    std::vector<Vector6d> reactionWorld;
    /// The same in the axes of the joint frame X_wj (A, R, T): [M_a M_r M_t F_a F_r F_t].
    std::vector<Vector6d> reactionJoint;

    // ---- constraints: loop closures and welds (solver/dynamics/constraints.h) --
    /// The constraints of the last dynamics evaluation: Model::cuts, then State::welds.
    std::vector<Constraint> constraints;
    /// Per constraint: the load body 1 exerts on body 2 through it, world axes,
    /// moment about body 2's constraint point (P2): [M; F] [N m; N].
    std::vector<Vector6d> constraintReactionWorld;
    /// The same in the axes of the constraint's frame on body 2 (A, R, T).
    std::vector<Vector6d> constraintReactionJoint;
    /// Singular values of the constraint Jacobian over the coordinates that are free
    /// in this evaluation (scaled rows), largest first; their ratios tell how close
    /// the loops are to locking up (Simulation's loop-lock event).
    Eigen::VectorXd constraintSingular;
    int constraintRank = 0;  ///< its numerical rank (singular values above 1e-9 of the largest)

    // ---- scratch of the algorithms (owned by them; do not read) ---------------
    // forward dynamics (RBDA §7.3 articulated-body algorithm, §9.2 hybrid dynamics),
    // all about the world origin in world axes
    std::vector<Vector6d> c;        ///< velocity-product acceleration c_i = v_i ×m S_i θ̇_i
    std::vector<RigidInertia> Ib;   ///< body spatial inertia
    std::vector<Eigen::Vector3d> com;  ///< body centre of mass in the world, at the pose Ib was found at
    std::vector<Vector6d> pb;       ///< body bias force v ×* I v − fext − gravity
    std::vector<Matrix6d> IA;       ///< articulated-body inertia
    std::vector<Vector6d> pA;       ///< articulated-body bias force
    std::vector<Vector6d> U;        ///< U_i = I^A_i S_i
    std::vector<Vector6d> f;        ///< force transmitted through each joint, parent → child
    Eigen::VectorXd D;              ///< D_i = S_iᵀ U_i
    Eigen::VectorXd uA;             ///< u_i = τ_i − S_iᵀ p^A_i
    Eigen::VectorXd tauKnown;       ///< known generalized force of a free joint (drive + tauExt)
    Eigen::VectorXd tauDrive;       ///< the drive's generalized force along θ (force-driven joints)
    Eigen::VectorXd dq;             ///< dq/dθ: the modeler's coordinate's rate per unit θ̇ (T 1: dL/dθ)
    std::vector<char> prescribed;   ///< per joint: acceleration known in this evaluation
    /// Per T 1 joint: its angle's cosine and sine and Model::coordinateMap at the angle
    /// `theta` (NaN: none yet) for the length law `law`, so that the kinematics, the
    /// circuits and the dynamics of one evaluation find them once: one sine and cosine
    /// and one root (actuatorCoordinateAt).
    struct CoordinateCache {
        double theta = std::numeric_limits<double>::quiet_NaN();
        ActuatorLengthLaw law;
        double cos = 1, sin = 0;
        CoordinateMap map;
    };
    std::vector<CoordinateCache> coordinates;
    // constrained dynamics (forward_dynamics.cpp, constraints.cpp); sized on first use
    Eigen::MatrixXd M;              ///< joint-space mass matrix (nb × nb)
    Eigen::VectorXd bias;           ///< C: generalized force for θ̈ = 0 (gravity, fext, velocity terms)
    std::vector<Vector6d> a0;       ///< body spatial acceleration for θ̈ = 0
    Eigen::MatrixXd G;              ///< constraint Jacobian (rows × nb), scaled rows
    Eigen::VectorXd gamma;          ///< G θ̈ = γ (scaled rows)
    Eigen::VectorXd phi;            ///< constraint residual Φ (scaled rows)
    Eigen::VectorXd lambda;         ///< constraint multipliers (scaled rows)
    std::vector<Vector6d> W1, W2;   ///< per row: its load on body 1 and body 2 per unit λ
    std::vector<int> rowConstraint; ///< per row: its constraint's index in `constraints`
};

/// T 1 joint j's cos θ, sin θ and model.coordinateMap(j, θ), kept in `data` for the
/// next call at the same angle with the same length law (a Data outlives no model's
/// geometry by mistake: the law's coefficients are compared too).
inline const Data::CoordinateCache& actuatorCoordinateAt(const Model& model, Data& data, int j, double theta)
{
    Data::CoordinateCache& k = data.coordinates[static_cast<std::size_t>(j)];
    const ActuatorLengthLaw& law = model.lengthLaw[j];
    if (!(k.theta == theta && k.law.c0 == law.c0 && k.law.c1 == law.c1 && k.law.c2 == law.c2)) {
        k.law = law;
        k.cos = std::cos(theta);
        k.sin = std::sin(theta);
        law.lengthDerivativesAt(k.cos, k.sin, k.map.q, k.map.dq, k.map.ddq);
        k.theta = theta;
    }
    return k;
}

/// model.coordinateMap(j, theta), for a T 1 joint kept in `data` (actuatorCoordinateAt).
inline CoordinateMap coordinateMapAt(const Model& model, Data& data, int j, double theta)
{
    if (model.jointType[j] != JointType::Actuator) return model.coordinateMap(j, theta);
    return actuatorCoordinateAt(model, data, j, theta).map;
}

}  // namespace solver
