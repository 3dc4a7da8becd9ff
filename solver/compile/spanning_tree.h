#pragma once
// Spanning tree of a model's joint graph: which joints form the tree that the
// position recursion follows from ground, which ones close loops (cut joints),
// how the tree is oriented, and how it splits into serial chains.

#include "solver/compile/topology.h"
#include "solver/spec/model_spec.h"

#include <vector>

namespace solver {

/// Fills the graph part of `topo` from `spec`: bodyIds, side1Body, side2Body,
/// parentBody, parentJoint, reversed, treeJoints, loopJoints and chains.
///
/// Joints are taken in priority order — joints named by a drive first, then the
/// others, each group in file order — and a union-find over bodies decides: a
/// joint that joins two separate groups of bodies is a tree joint, one whose
/// bodies are already connected closes a loop and becomes a cut joint. The tree
/// is then oriented by breadth-first search from ground (body index 0), so
/// `treeJoints` lists parents before children; a joint reached from its side 2
/// body is `reversed`. Joints naming a missing body, or the same body twice, are
/// neither tree nor cut joints. Joints in groups that ground does not reach are
/// left out of `treeJoints` and `loopJoints`.
///
/// Returns, per body index, whether ground reaches it.
std::vector<bool> buildSpanningTree(const ModelSpec& spec, Topology& topo);

}  // namespace solver
