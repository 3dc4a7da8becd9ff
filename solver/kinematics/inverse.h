#pragma once
// Inverse kinematics: the joint coordinates that bring a frame fixed on a body to a
// target pose in the world, by damped least squares (Levenberg–Marquardt) on the
// compiled tree, within the joints' limits, with a few restarts.
//
// Problem. A frame F is fixed on body b (tree index) at the pose X_bf in b's frame.
// For the coordinates θ of a chosen subset of joints (the others held at their start
// values) find θ with
//   p_F(θ) = p*            (position of F's origin in the world [m])
//   R_F(θ) = R*            (F's axes in the world; optional)
//   lower_i ≤ θ_i ≤ upper_i (Model::lower/upper: LL/UL, T 1 lengths as angles).
// The residual is e = [w_p (p* − p_F); w_o log(R* R_Fᵀ)], the rotation part the
// rotation vector (axis · angle, world axes) that turns F onto the target. Its
// Jacobian comes from the joints' world motion vectors S_i = [ω; v_O] about the world
// origin (Data::S after forwardKinematics): a point p moves by v_O + ω × p, a
// direction turns by ω (RBDA §2.9), so per joint i that moves b:
//   J_p,i = S_i.tail(3) + S_i.head(3) × p_F,   J_o,i = S_i.head(3).
// Step: (JᵀJ + λ diag(JᵀJ + ε)) Δθ = Jᵀe over the free joints (Marquardt's scaling,
// so metres and radians need no common unit), λ raised on a failed step and lowered
// on a good one; θ + Δθ is clamped to the limits, and a joint pressed against a limit
// by the gradient leaves the free set for that step (a projected, active-set LM).
//
// Coordinates: θ are kinematic coordinates (State::q): angles [rad] for T 0 and
// T 1 joints, displacements [m] for T 2. The modeler's coordinates q (T 1: the
// cylinder's length [m]) are returned too (IkResult::coordinates), and the limits
// hold in both, since a T 1 joint's θ limits are its LL/UL on the monotonic branch of
// L(θ) that holds its initial angle (solver/compile/compile.h step 5). A T 1 joint
// without limits is kept inside that branch as well (between its dead points), so
// that its length still names one angle. An unlimited revolute angle is returned
// within π of its start value.
//
// Restarts: the first attempt starts from `start`; when it does not converge, up to
// IkOptions::restarts more start from random θ of the moving joints (uniform within
// their limits; unlimited revolute joints within ±π of the start, unlimited
// prismatic ones within ±1 m), reproducibly (IkOptions::seed). The result is the
// attempt with the smallest weighted residual.
//
// Closed loops (Model::cuts) are not held: the solver moves the tree. Choose joints
// outside the loops, or close them afterwards (solver/dynamics/constraints.h: projectOntoConstraints).
//
// Units: m, rad. Allocates (not for the step loop); no exceptions: sizes are asserted.

#include "solver/core/data.h"
#include "solver/core/model.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <vector>

namespace solver {

/// A frame fixed on a body: where the target applies.
struct IkFrame {
    int body = -1;  ///< tree index of the body (not the ground)
    /// The frame's pose in the body's frame (x_body = X_bf · x_frame) [m].
    Eigen::Isometry3d X_bf = Eigen::Isometry3d::Identity();
};

/// Where the frame should be, and how closely.
struct IkTarget {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< the frame's origin, world [m]
    /// The frame's axes in the world (columns x, y, z); nullopt: position only.
    std::optional<Eigen::Matrix3d> orientation;
    /// w_p [1/m]: weight of a metre of position error. 0: the position is free (it
    /// neither pulls nor counts for convergence: an orientation-only target).
    double positionWeight = 1.0;
    double orientationWeight = 1.0;  ///< w_o [1/rad]: weight of a radian of angle error (≥ 0)
    double positionTolerance = 1e-9;  ///< converged when |p* − p_F| ≤ this [m] (if w_p > 0) …
    double angleTolerance = 1e-9;     ///< … and the angle between R* and R_F ≤ this [rad] (if w_o > 0)
};

struct IkOptions {
    /// Tree indices of the joints IK may move (Model::jointIndex(id)); empty: every
    /// joint on the path from the ground to the target's body. Joints that do not
    /// move the body are ignored.
    std::vector<int> joints;
    int maxIterations = 200;  ///< LM iterations per attempt
    int restarts = 8;         ///< further attempts from random θ when one does not converge
    unsigned seed = 1;        ///< of the random restarts
    double initialDamping = 1e-3;  ///< λ at the start of an attempt [-]
    bool limits = true;       ///< false: ignore Model::lower/upper (T 1 branches still held)
};

struct IkResult {
    bool converged = false;  ///< both tolerances met
    /// θ for every joint (dim nb): the moving joints solved, the others as in `start`.
    /// Kinematic coordinates (State::q): rad for T 0 and T 1, m for T 2.
    Eigen::VectorXd theta;
    /// The modeler's coordinates of the same pose (dim nb): as theta, except T 1
    /// joints, whose entry is the cylinder's length L(θ) [m] (Model::coordinate).
    Eigen::VectorXd coordinates;
    double positionError = 0;  ///< |p* − p_F| at theta [m]
    double angleError = 0;     ///< angle between R* and R_F at theta [rad]; 0 without orientation
    int iterations = 0;        ///< LM iterations over all attempts
    int attempts = 0;          ///< attempts made (1 + restarts used)
};

/// The frame's world pose at the kinematics in `data` (after forwardKinematics).
Eigen::Isometry3d framePose(const Data& data, const IkFrame& frame);

/// Solves the problem above from `start` (θ per joint, dim nb). `data` is scratch
/// (its kinematics are left at the result's θ with zero rates).
IkResult inverseKinematics(const Model& model, const IkFrame& frame, const IkTarget& target,
                           const Eigen::VectorXd& start, Data& data, const IkOptions& options = {});

/// The θ range inverse kinematics keeps joint i in [rad or m]: its limits (when
/// `limits`), further narrowed for a T 1 joint to the monotonic branch of L(θ) that
/// holds its initial angle; ±∞ where nothing bounds it.
void ikJointRange(const Model& model, int i, bool limits, double& lower, double& upper);

}  // namespace solver
