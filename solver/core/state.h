#pragma once
// State: what the integrator advances, one per simulation (GUI, solver thread,
// tutorial checker and tests each hold their own). Sized for a Model by
// makeState(); nothing here is derived (derived values live in Data).

#include "solver/core/model.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace solver {

enum class LimitState { Free, AtLower, AtUpper };

/// Per fluid-power circuit in State::fluid: spool, p_A, p_B.
inline constexpr int kFluidStates = 3;
/// A hydraulic joint's relief valve: closed (rate prescribed) or open, the joint
/// then driven by the relief force while extending (+fmax) or retracting (−fmin).
enum class ReliefState { Closed, OpenExtending, OpenRetracting };

/// A run-time weld (Simulation::weld): body b held at the pose X_ab in body a's frame
/// (a grasp). Tree indices; a = −1 welds b to the ground.
struct Weld {
    int bodyA = -1;
    int bodyB = -1;
    Eigen::Isometry3d X_ab = Eigen::Isometry3d::Identity();
};

/// A push of the mouse (Simulation::setPush): body `body`'s point `point` is pulled
/// toward the world point `target` by a spring–damper scaled by the mass it moves
/// (dynamics/applied_forces.h "The push"). A command, as u: held, not integrated.
struct Push {
    int body = -1;  ///< tree index; −1: no push
    Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< in the body's frame [m]
    Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< world [m]
};

struct State {
    double t = 0;               ///< [s]
    /// θ per joint [rad or m], then each free joint's base orientation as a unit
    /// quaternion (w, x, y, z) (dim Model::nq; core/model.h "Free joints")
    Eigen::VectorXd q;
    Eigen::VectorXd qd;         ///< θ̇ per joint (dim nb)
    Eigen::VectorXd u;          ///< operator command per joint in [−1, 1] (dim nb; ignored without a drive)
    Eigen::VectorXd servoIntegral;  ///< ∫ set-point error dt per joint (servo drives) (dim nb)
    std::vector<LimitState> limit;  ///< per joint
    std::vector<ReliefState> relief;  ///< per joint (hydraulic drives)
    std::vector<Weld> welds;          ///< welds in force (none at the start)
    Push push;                        ///< the mouse's push (none at the start)
    /// Fluid-power states, kFluidStates per Model::circuits entry: the spool x in
    /// [−1, 1], the pressures p_A and p_B [Pa] (gauge, ≥ 0).
    Eigen::VectorXd fluid;
    /// Rank of the constraint Jacobian over the free coordinates, as the Simulation
    /// fixed it at its last mode change (on the constraints, where the redundant rows
    /// of a planar loop are exactly redundant); the dynamics use that many singular
    /// values. −1: the dynamics find it from the singular values (above 1e-9 of the
    /// largest).
    int constraintRank = -1;
    /// CONTACT: the tangential anchors of the sticking contacts (core/contact.h),
    /// renewed at every step's end (capacity kMaxContacts; empty without CONTACT).
    std::vector<ContactAnchor> contacts;
};

/// The initial state: θ = theta0, θ̇ = thetaDot0, t = 0, u = 0, servo integrals 0,
/// relief valves Closed, spools closed, fluid pressures P0 (0 where not given: the
/// Simulation sets the holding pressures); a joint that starts on a limit (within 1e-9, relative above
/// 1) and does not start moving away from it is AtLower/AtUpper, the others Free.
/// (solver/core/state.cpp)
State makeState(const Model& model);

/// Folds the turns of every free joint whose largest turn exceeds `threshold` [rad]
/// (0: every free joint) into its base orientation: the quaternion becomes the
/// orientation reached, the three turns 0, and their rates the angular velocity
/// relative to the B1 frame in the new base axes. The motion is unchanged; only its
/// coordinates move away from the three angles' gimbal lock. Returns whether any joint
/// was folded (an integrator must then restart). (solver/core/state.cpp)
bool foldFreeRotations(const Model& model, State& state, double threshold);

}  // namespace solver
