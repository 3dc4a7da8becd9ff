#pragma once
// Joint-space mass matrix M(θ) of a compiled (open-tree) model by the composite-
// rigid-body algorithm (RBDA §6.2), about the world origin in world axes like the
// rest of the dynamics: M_ij = S_iᵀ C_j S_j for i on j's path to ground, with C_j
// the composite spatial inertia of body j's subtree. Kinetic energy = ½ θ̇ᵀ M θ̇.
//
// For event handling (impulses), not for the step loop: it allocates.

#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/core/state.h"

#include <Eigen/Core>

#include <vector>

namespace solver {

/// Fills M (nb × nb) at the positions of the last forwardKinematics on `data`.
void massMatrix(const Model& model, const Data& data, Eigen::MatrixXd& M);

/// M at θ = state.q: forwardKinematics on `data`, then massMatrix (events, projection
/// and assembly; allocates).
Eigen::MatrixXd massMatrixAt(const Model& model, const State& state, Data& data);

/// The same from each body's spatial inertia about the world origin, given in
/// `composite` (dim nb), which it turns into the composite inertias of the subtrees
/// (the step loop's constrained dynamics passes Data's scratch; no allocation when M
/// has its size).
void massMatrixFromInertias(const Model& model, const Data& data, std::vector<Matrix6d>& composite,
                            Eigen::MatrixXd& M);

}  // namespace solver
