#pragma once
// The initial configuration of a model being compiled (compile.cpp's steps 2, 5
// and 7): the T 1 checks and initial guesses on the spec, then, on the compiled
// model, the loops closed at QI (with solver/dynamics/constraints.h, the one
// constraint implementation) and the check that every joint moves mass.
// Internal to solver/compile.

#include "solver/compile/topology.h"
#include "solver/core/data.h"
#include "solver/core/diagnostic.h"
#include "solver/core/model.h"
#include "solver/kinematics/joint_geometry.h"
#include "solver/spec/model_spec.h"

#include <Eigen/Core>

#include <vector>

namespace solver {

/// Checks every T 1 joint's lengths (reachable, not constant, no dead point inside
/// the stroke) and gives every spec joint its initial guess: topo.q0 (QI, the middle
/// of a T 1 stroke, else 0) and θ (dim spec.joints; T 1: the angle of that length
/// nearest to 0). geometry: makeJointGeometries(spec).
void initialGuess(const ModelSpec& spec, const std::vector<JointGeometry>& geometry, Topology& topo,
                  Eigen::VectorXd& theta, Diagnostics& diags);

/// What the initial assembly found, for the mass check.
struct LoopAssembly {
    bool assembled = true;           ///< the loops closed (or there are none)
    std::vector<int> independent;    ///< tree indices of the independent coordinates, increasing
    std::vector<int> dependent;      ///< tree indices of the dependent ones, in the order chosen
    Eigen::MatrixXd jacobian;        ///< G at θ0 (rows × nb, Φ's scaled rows); 0 rows without loops
};

/// Closes the compiled model's loops at the initial guess: the rank of the loops and
/// the dependent coordinates (undriven before driven, later in the file first), then
/// assembleLoops on them holding the independent ones at QI (from the dependent
/// ones' QI, else from where an assembly moving every coordinate put them); revolute
/// angles on the turn nearest their guess. An error "loop-unsatisfiable" per loop that
/// stays open. Fills topo's closureRank, independent, dependent, dof, and q0/theta0 of
/// the dependent and cut joints; `theta` (per spec joint) receives the assembled θ and
/// `model.theta0` too; data ends at its kinematics.
LoopAssembly assembleInitialConfiguration(const ModelSpec& spec, Topology& topo, Model& model, Data& data,
                                          Eigen::VectorXd& theta, Diagnostics& diags);

/// The mass matrix of the compiled model at the kinematics in `data`, on the
/// independent coordinates (through the loops when they closed), must not be
/// singular: an error "joint-moves-no-mass" for every joint, or set of joints, that
/// moves nothing with mass. Above 1,500 tree joints only each joint's own diagonal
/// term is checked (O(n), exact).
void checkMovesMass(const ModelSpec& spec, const Topology& topo, const Model& model, const Data& data,
                    const LoopAssembly& loops, Diagnostics& diags);

}  // namespace solver
