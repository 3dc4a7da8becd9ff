#pragma once
// Topology: the joint graph of a checked ModelSpec — spanning tree from ground,
// loop-closure (cut) joints, kinematic chains, bodies that ground does not reach —
// and, once compileModel (compile.h) has closed the loops on the compiled model,
// what follows from the geometry: the degrees of freedom, which coordinates are
// independent and which follow from the loops, and the initial configuration.
//
// Indices here are the spec's: body index 0 is ground, then the spec's bodies in
// file order; joint indices are positions in spec.joints. The compiled Model
// renumbers them in tree order (Model::jointId, Model::bodyId give the ids back).

#include "solver/core/diagnostic.h"
#include "solver/spec/model_spec.h"

#include <vector>

namespace solver {

struct Topology {
    // ---- the graph (analyzeTopology) ----------------------------------------
    /// Body index → modeler id. Index 0 is ground (id 0); then the spec's bodies in
    /// file order (a written `B 0` is ground, not a second body).
    std::vector<int> bodyIds;
    std::vector<int> parentBody;    ///< per body index; -1 for ground
    std::vector<int> parentJoint;   ///< per body index: index into spec.joints; -1 for ground
    std::vector<bool> reversed;     ///< per spec joint: the tree runs it from side 2 to side 1
    /// Spec joint indices, every parent before its children, one per compiled coordinate:
    /// a free joint (T 3) appears six times in a row (its coordinates, Model::freeSlot).
    std::vector<int> treeJoints;
    std::vector<int> loopJoints;    ///< spec joint indices that close loops (cut joints)
    /// Serial kinematic chains: runs of tree joints (spec indices) from ground or a
    /// branching body to a leaf or the next branching body.
    std::vector<std::vector<int>> chains;
    /// Per spec joint: body index of side 1 and of side 2 (-1 for a body that does not exist).
    std::vector<int> side1Body;
    std::vector<int> side2Body;

    // ---- filled by compileModel, from the compiled model ----------------------
    std::vector<int> independent;   ///< tree joints whose coordinates are degrees of freedom
    std::vector<int> dependent;     ///< tree joints whose coordinates follow from loop closures
    int dof = 0;
    double totalMass = 0;           ///< [kg]
    /// Per spec joint: its coordinate in the initial configuration (QI or default for
    /// independent joints; solved for dependent and cut joints). Units of the joint's
    /// coordinate (rad, or m for T 1 and T 2).
    std::vector<double> q0;
    /// Per spec joint: its kinematic coordinate θ in the initial configuration: as q0,
    /// except for T 1, where it is the joint angle [rad] instead of the length.
    std::vector<double> theta0;
    /// Rank of the loop-closure Jacobian Φ_θ at the initial configuration (number of
    /// independent closure equations; dof = treeJoints.size() − closureRank).
    int closureRank = 0;
};

/// The graph of a spec that passed the local checks (solver/spec/validate.h): the
/// spanning tree (spanning_tree.h), cut joints and chains; an error
/// "body-not-connected" for every body that ground does not reach. Fills the graph
/// fields of the Topology; the others stay empty until compileModel.
Topology analyzeTopology(const ModelSpec& spec, Diagnostics& diags);

}  // namespace solver
