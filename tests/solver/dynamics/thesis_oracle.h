#pragma once
// Test-only name of the reference dynamics: the thesis's assembled Newton–Euler
// system A·X = B (seed/thesis.txt §2.2, eq. 2.8–2.11), which lives in the solver
// library as solver/reference/newton_euler.h (so `padrob bench` can time it too).
// The dynamics tests check the O(n) hybrid articulated-body algorithm
// (solver/dynamics/forward_dynamics.h) against it; the system's unknowns, rows and
// solving are documented there.

#include "solver/core/model.h"
#include "solver/core/spatial.h"
#include "solver/core/state.h"
#include "solver/reference/newton_euler.h"

#include <Eigen/Core>

#include <vector>

namespace solver::test {

using OracleResult = reference::NewtonEulerResult;

/// Builds and solves the system at `state` with applied loads fext (per body,
/// [moment about the body frame's origin; force], world) and tauExt (per joint, on θ).
OracleResult solveThesisSystem(const Model& model, const State& state,
                               const std::vector<Vector6d>& fext, const Eigen::VectorXd& tauExt);

}  // namespace solver::test
