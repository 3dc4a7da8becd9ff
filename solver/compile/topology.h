#pragma once
// Topology and initial-configuration analysis of a checked ModelSpec:
// spanning tree from ground, loop-closure (cut) joints, kinematic chains,
// independent/dependent coordinates, and the global checks that need geometry
// (T 1 lengths reachable, body connected to ground, every joint/loop moves mass,
// loop closures satisfiable at QI).
//
// OWNER: analysis helper. This header is the contract; see the .cpp for details.

#include "solver/core/diagnostic.h"
#include "solver/model/model_spec.h"

#include <optional>
#include <vector>

namespace solver {

struct Topology {
    /// Body index → modeler id. Index 0 is ground (id 0); then the spec's bodies in
    /// file order (a written `B 0` is ground, not a second body).
    std::vector<int> bodyIds;
    std::vector<int> parentBody;    ///< per body index; -1 for ground
    std::vector<int> parentJoint;   ///< per body index: index into spec.joints; -1 for ground
    std::vector<bool> reversed;     ///< per spec joint: the tree runs it from side 2 to side 1
    std::vector<int> treeJoints;    ///< spec joint indices, every parent before its children
    std::vector<int> loopJoints;    ///< spec joint indices that close loops (cut joints)
    /// Serial kinematic chains: runs of tree joints (spec indices) from ground or a
    /// branching body to a leaf or the next branching body.
    std::vector<std::vector<int>> chains;
    std::vector<int> independent;   ///< tree joints whose coordinates are degrees of freedom
    std::vector<int> dependent;     ///< tree joints whose coordinates follow from loop closures
    int dof = 0;
    double totalMass = 0;           ///< [kg]
    /// Per spec joint: its coordinate in the initial configuration (QI or default for
    /// independent joints; solved for dependent and cut joints). Units of the joint's
    /// coordinate (rad, or m for T 1 and T 2).
    std::vector<double> q0;

    // added by the analysis (after the fields above, which other code relies on)
    /// Per spec joint: body index of side 1 and of side 2 (-1 for a body that does not exist).
    std::vector<int> side1Body;
    std::vector<int> side2Body;
    /// Per spec joint: its kinematic coordinate θ in the initial configuration: as q0,
    /// except for T 1, where it is the joint angle [rad] instead of the length.
    std::vector<double> theta0;
    /// Rank of the loop-closure Jacobian Φ_θ at the initial configuration (number of
    /// independent closure equations; dof = treeJoints.size() − closureRank).
    int closureRank = 0;
};

/// Analyses a spec that passed the local checks (no errors so far). Adds its own
/// diagnostics; returns the topology when it found no errors.
std::optional<Topology> analyzeTopology(const ModelSpec& spec, Diagnostics& diags);

}  // namespace solver
