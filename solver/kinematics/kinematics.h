#pragma once
// Kinematics of the compiled tree (thesis eq. 2.1–2.7) by one recursion from
// ground to the leaves (tree order, parents first):
//   positions      X_wb,i = X_wb,λ · X_pj,i · J(σθ_i) · X_jc,i               (eq. 2.1)
//   velocities     ω_i = ω_λ + σθ̇_i a_i (revolute, T 1)                      (eq. 2.4)
//                  v_P = v_A + ω × r_AP, + σθ̇_i r_i across a prismatic joint (eq. 2.2–2.3)
//   accelerations  α_i = α_λ + σθ̈_i a_i + σθ̇_i ω_λ × a_i                     (eq. 2.7)
//                  a_P = a_A + α × r_AP + ω × (ω × r_AP), + relative terms   (eq. 2.5–2.6)
// written with spatial vectors about the world origin (core/spatial.h):
//   v_i = v_λ + S_i θ̇_i,   a_i = a_λ + S_i θ̈_i + c_i,   c_i = v_i ×m S_i θ̇_i
// (RBDA §3.5; S_i is fixed in the parent, so Ṡ_i = v_λ ×m S_i = v_i ×m S_i), which
// holds the same terms: for a prismatic joint c_i carries the Coriolis term 2θ̇ ω × r
// of eq. 2.6 once the spatial acceleration is turned into point accelerations.
//
// Body indices are tree indices (Model); −1 is the ground, whose points are world
// points at rest. Units: m, rad, s. No allocation, no exceptions.

#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/core/state.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace solver {

/// Positions and velocities: fills data.X_wb, X_wj, S, v, omega, vel and the
/// velocity-product accelerations of the dynamics (scratch c).
/// q: θ per joint [rad or m], then the free joints' base quaternions (dim nq; dim nb:
/// every base orientation is the start's); qd: θ̇ per joint (dim nb).
void forwardKinematics(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                       Data& data);
/// forwardKinematics(model, state.q, state.qd, data).
void forwardKinematics(const Model& model, const State& state, Data& data);

/// Velocities only, with the positions of the last forwardKinematics on `data` (the same
/// θ, new θ̇, as after a rate jump): fills data.v, omega, vel and c.
void velocityKinematics(const Model& model, const Eigen::VectorXd& qd, Data& data);

/// Accelerations for θ̈ = qdd (dim nb) [rad/s^2 or m/s^2]: fills data.a, alpha and acc.
/// Requires forwardKinematics on the same state first.
void bodyAccelerations(const Model& model, const Eigen::VectorXd& qdd, Data& data);

/// World position of the point `p` (body-local [m]) of body `body`.
Eigen::Vector3d bodyPointPosition(const Data& data, int body, const Eigen::Vector3d& p);
/// World velocity of that point [m/s]: v_o + ω × (x − o) (eq. 2.2).
Eigen::Vector3d bodyPointVelocity(const Data& data, int body, const Eigen::Vector3d& p);
/// World acceleration of that point [m/s^2]: a_o + α × r + ω × (ω × r), r = x − o (eq. 2.5).
/// Needs the accelerations (bodyAccelerations or the dynamics).
Eigen::Vector3d bodyPointAcceleration(const Data& data, int body, const Eigen::Vector3d& p);

/// World position, velocity and acceleration of body `body`'s centre of mass.
Eigen::Vector3d comPosition(const Model& model, const Data& data, int body);
Eigen::Vector3d comVelocity(const Model& model, const Data& data, int body);
Eigen::Vector3d comAcceleration(const Model& model, const Data& data, int body);

/// World pose of joint i's frame (origin P, axes A, R, T): on the child's side by
/// default (= data.X_wj[i]), or on the parent's side (X_wb,λ · X_pj,i), which differs
/// by the joint's motion: a turn σθ about A (T 0, T 1) or a shift σθ along R (T 2).
Eigen::Isometry3d jointFramePose(const Model& model, const Data& data, int joint,
                                 bool parentSide = false);

/// A free joint's (T 3) motion as its output columns give it: the translation of the
/// free body's frame from the start, along the axes A, R, T of the free joint's frame on
/// B1 [m], and its rate in that frame [m/s] (needs forwardKinematics).
struct FreeJointMotion {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
};
/// `first`: the free joint's slot 0 (Model::freeJoints); q, qd as the state's.
FreeJointMotion freeJointMotion(const Model& model, const Data& data, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& qd, int first);

/// Kinetic energy Σ ½ m |v_c|² + ½ ωᵀ I_c ω [J] (needs forwardKinematics).
double kineticEnergy(const Model& model, const Data& data);
/// Gravitational potential energy Σ −m g·c [J], zero with every centre of mass at the
/// world origin (needs the positions).
double potentialEnergy(const Model& model, const Data& data);
/// kineticEnergy + potentialEnergy [J].
double mechanicalEnergy(const Model& model, const Data& data);

}  // namespace solver
