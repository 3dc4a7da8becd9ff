#pragma once
// Constraint equations of loop-closure joints and welds (core/constraint.h) on the
// tree coordinates θ: the residual Φ(θ), the Jacobian G = Φ_θ and the acceleration
// right-hand side γ of G θ̈ = γ (= −Ġ θ̇).
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

}  // namespace solver
