#pragma once
// The one implementation of the constraints of loop-closure joints and welds
// (core/constraint.h) on the tree coordinates θ of a compiled Model: the residual
// Φ(θ), the Jacobian G = Φ_θ and the acceleration right-hand side γ of G θ̈ = γ
// (= −Ġ θ̇), and what is built on them:
//   - the dynamics' constraint rows (forward_dynamics.cpp: G θ̈ = γ, loads Gᵀλ);
//   - the initial assembly (compile: closing the loops at QI, assembleLoops);
//   - the projection after every step, every velocity jump and every weld
//     (Simulation: projectOntoConstraints, constraintCorrection, freeResponse).
//
// Equations per constraint (world vectors; p, a, r, t: the frame's origin and axes
// on body 1 or 2):
//   revolute (T 0, T 1)  p2 − p1 (3 rows);  a1·r2, a1·t2          (A2 ∥ A1)
//   prismatic (T 2)      a1·r2, a1·t2, r1·t2;  (p2 − p1)·a1, (p2 − p1)·t1
//   weld                 p2 − p1 (3 rows);  a1·r2, a1·t2, r1·t2
// Rows that are lengths are divided by Model::lengthScale, so that every row is
// dimensionless (what rank and conditioning tests need).
//
// Each row is linear in the two bodies' spatial velocities: Φ̇_r = W1_rᵀ v_1 + W2_rᵀ v_2,
// with W1_r, W2_r force vectors (about the world origin, world axes): the load the
// constraint puts on body 1 and body 2 per unit multiplier λ_r. So G_rj = Σ W·S_j over
// the joints j on each body's path to ground, and the constraint's generalized force
// is Gᵀλ (M θ̈ + C = τ + Gᵀλ). γ_r = −Φ̈_r at θ̈ = 0, from the second derivatives of
// body-fixed points (ẍ = a_O + α × x + ω × ẋ) and directions (d̈ = α × d + ω × (ω × d))
// with the bias accelerations (θ̈ = 0).
//
// No allocation once the Data's constraint arrays have their size.

#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/core/state.h"

#include <Eigen/Core>

#include <vector>

namespace solver {

/// The model's cut joints, then the state's welds, into `out` (cleared first).
void collectConstraints(const Model& model, const State& state, std::vector<Constraint>& out);

/// Total number of rows of `constraints`.
int constraintRowTotal(const std::vector<Constraint>& constraints);

/// True when the model has cut joints or the state has welds.
bool hasConstraints(const Model& model, const State& state);

/// Φ (scaled) at the poses in data.X_wb; phi is resized to the row total.
void constraintResidual(const Model& model, const Data& data, const std::vector<Constraint>& constraints,
                        Eigen::VectorXd& phi);

/// G (rows × nb), and per row the loads W1, W2 and the constraint index, at the
/// positions and velocities of the last forwardKinematics: fills data.G, W1, W2,
/// rowConstraint for data.constraints. With `a0` (the bias accelerations of
/// every body, θ̈ = 0) also data.gamma; pass nullptr to skip it.
void constraintJacobian(const Model& model, Data& data, const std::vector<Vector6d>* a0);

/// What a loop-closing joint would read as a tree joint, at the positions and
/// velocities of the last forwardKinematics: its modeler's coordinate q and rate q̇
/// (revolute: the angle from R1 to R2 about A1 [rad]; prismatic: (P2 − P1)·R1 [m];
/// T 1: the length |CL2 − CL1| [m]) and, for revolute and T 1 joints, the angle.
struct CutReading {
    double q = 0, qd = 0;
    double angle = 0;
};
CutReading readCut(const Model& model, const Data& data, int cut);

/// True when row `row` of a constraint of kind `kind` is a length [m] (divided by
/// Model::lengthScale in Φ and G); the other rows are dimensionless.
bool constraintRowIsLength(ConstraintKind kind, int row);

/// G at θ = state.q (forwardKinematics first, then the state's constraints
/// collected into data.constraints); 0 rows without constraints. Allocates: for
/// events and assembly, not for the step loop.
Eigen::MatrixXd constraintJacobianAt(const Model& model, const State& state, Data& data);

// ---- corrections: the least change of the coordinates that moves the rows ----

/// Δ (dim nb) on the joints `free` (tree indices; the others held) with
/// Δ_F = M_FF⁻¹ G_Fᵀ μ and G_F Δ_F = target: the M-weighted least change that moves
/// the constraint rows G (dim rows × nb) by `target` (dim rows); minimum-norm μ when
/// the rows are redundant or conflicting. M: mass matrix (nb × nb), or any metric.
Eigen::VectorXd constraintCorrection(const Eigen::MatrixXd& M, const std::vector<int>& free,
                                     const Eigen::MatrixXd& G, const Eigen::VectorXd& target);

/// The rate change (dim nb; 0 on the held joints) of the joints `free` under the
/// generalized impulse `impulse` (dim nb), every other joint held, the constraints G
/// kept: M_FF Δθ̇_F = impulse_F + G_Fᵀ μ with G (θ̇ + Δθ̇) = 0, where θ̇ = `rates`
/// (pass zeros for the response alone). Without constraints (G has no rows):
/// M_FF Δθ̇_F = impulse_F.
Eigen::VectorXd freeResponse(const Eigen::MatrixXd& M, const std::vector<int>& free,
                             const Eigen::VectorXd& impulse, const Eigen::MatrixXd& G,
                             const Eigen::VectorXd& rates);

/// Projects the state onto its constraints (Model::cuts and State::welds), moving only
/// the joints `free` (tree indices): positions by Gauss–Newton, each step the
/// mass-weighted least change (constraintCorrection), until max |Φ| ≤ 1e-12 (scaled
/// rows, at most 20 steps); then velocities by the plastic-impact projection
/// (G θ̇ = 0, mass-weighted). Returns false when the positions could not be brought
/// within 1e-9. Leaves data at the kinematics of the projected positions.
bool projectOntoConstraints(const Model& model, State& state, Data& data, const std::vector<int>& free);

// ---- the initial assembly (compile) -------------------------------------------

struct AssemblyOptions {
    int maxIterations = 60;
    double tolerance = 1e-10;  ///< converged when |Φ| ≤ tolerance (unscaled rows: m and -)
    /// Length [m] that makes the length rows and the prismatic columns comparable to
    /// the dimensionless ones while solving (the size of the mechanism).
    double lengthScale = 1.0;
};

struct AssemblyResult {
    bool converged = false;
    int iterations = 0;
    double residualNorm = 0;   ///< |Φ| at the returned θ (unscaled rows)
    /// Φ of the model's cut joints at the returned θ, unscaled (length rows [m], the
    /// others dimensionless), 5 rows per cut joint in Model::cuts order.
    Eigen::VectorXd residual;
};

/// Closes the model's loops (Model::cuts; welds are not assembled) by moving the
/// coordinates `unknowns` (tree indices) of `theta` (dim nb), holding the others;
/// `theta` holds the starting guess and receives the solution, or the least-squares
/// point reached when the loops cannot be closed. Damped Gauss–Newton (Levenberg–
/// Marquardt) on the scaled equations, with the rows of constraintResidual and the
/// Jacobian of constraintJacobian. Uses data as scratch (its kinematics end at θ).
AssemblyResult assembleLoops(const Model& model, Data& data, const std::vector<int>& unknowns,
                             Eigen::VectorXd& theta, const AssemblyOptions& options = {});

}  // namespace solver
