#pragma once
// Test-only reference dynamics: the thesis's assembled Newton–Euler system
// A·X = B (seed/thesis.txt §2.2, eq. 2.8–2.11), built straightforwardly with dense
// Eigen matrices and solved by LU, to check the O(n) hybrid articulated-body
// algorithm (solver/dynamics/forward_dynamics.h) against.
//
// Unknowns (eq. 2.10), 13 per tree index i (body i and its parent joint i):
//   a_G,i (3)  acceleration of body i's centre of mass, world [m/s^2]
//   α_i   (3)  angular acceleration of body i, world [rad/s^2]
//   F_i   (3)  force the parent exerts on body i through joint i, world [N]
//   M_i   (3)  moment of that load about the child's joint point x_i, world [N m]
//   θ̈_i   (1)
// (one set of reactions per joint; the parent receives −F_i, −M_i: Newton's third law).
// Rows, 13 per i:
//   Newton about G_i (eq. 2.8):  m a_G − F_i + Σ_k F_k = m g + F_ext
//   Euler about G_i (eq. 2.9):   I α − M_i − (x_i − G_i) × F_i + Σ_k [M_k + (x_k − G_i) × F_k]
//                                = M_ext,G − ω × I ω          (k: the children of body i)
//   joint i, rotation (eq. 2.7): α_i − α_λ − σθ̈ a = σθ̇ ω_λ × a   (T 0, T 1);  α_i − α_λ = 0 (T 2)
//   joint i, translation (eq. 2.5–2.6): the child's joint point moves with the parent's
//                                point there (T 0, T 1), plus σθ̈ r + 2σθ̇ ω_λ × r (T 2)
//   joint i, drive or passive: θ̈ = known (at a limit, hydraulic T 0/T 2 held), or for a
//                                hydraulic T 1 with the relief closed L̈ = 0 written on the
//                                actuator's end points; else the reaction along the joint's
//                                free direction: σ a·M_i (T 0, T 1) or σ r·F_i (T 2) = drive + tauExt.
// Velocities come from eq. 2.2–2.4 by their own recursion; the drive laws, actuator
// lengths, rates and lever arms are computed here from the world geometry, not
// with the library's helpers.

#include "solver/core/model.h"
#include "solver/core/spatial.h"
#include "solver/core/state.h"

#include <Eigen/Core>

#include <vector>

namespace solver::test {

struct OracleResult {
    Eigen::VectorXd qdd;                ///< θ̈ (dim nb)
    std::vector<Eigen::Vector3d> aG;    ///< centre-of-mass accelerations, world
    std::vector<Eigen::Vector3d> alpha; ///< angular accelerations, world
    std::vector<Vector6d> reaction;     ///< [M_i; F_i], world, about the child's joint point
    Eigen::VectorXd tau;                ///< generalized force along θ transmitted by each joint
    Eigen::VectorXd driveForce;         ///< as Data::driveForce
    Eigen::VectorXd limitForce;         ///< as Data::limitForce
    double relativeResidual = 0;        ///< |A X − B| / |B|
};

/// Builds and solves the system at `state` with applied loads fext (per body,
/// [moment about the body frame's origin; force], world) and tauExt (per joint, on θ).
OracleResult solveThesisSystem(const Model& model, const State& state,
                               const std::vector<Vector6d>& fext, const Eigen::VectorXd& tauExt);

}  // namespace solver::test
