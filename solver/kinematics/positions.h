#pragma once
// Positions: world pose of every body for a vector of kinematic coordinates, by
// recursion along the spanning tree from ground (thesis eq. 2.1), and the world
// motion vector of each tree joint (thesis eq. 2.3–2.4 per unit rate).
//
// Coordinates are indexed by spec joint (dim spec.joints.size()); entries of cut
// joints and of joints outside the tree are ignored. They are kinematic
// coordinates θ (angle for T 0 and T 1 [rad], displacement for T 2 [m]).

#include "solver/compile/topology.h"
#include "solver/kinematics/joint_geometry.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace solver {

using Vector6d = Eigen::Matrix<double, 6, 1>;

/// The body a tree joint moves (the one farther from ground): side 2's body, or
/// side 1's when the joint is reversed; -1 for a joint outside the tree.
int treeChildBody(const Topology& topo, int joint);
/// The other body of a tree joint (nearer to ground); -1 outside the tree.
int treeParentBody(const Topology& topo, int joint);

/// True when tree joint `joint` lies on the tree path from ground to `body`
/// (so its coordinate moves that body).
bool jointMovesBody(const Topology& topo, int joint, int body);

/// World poses of all bodies: X_wb (dim topo.bodyIds.size()); ground's pose is the
/// identity (ground's frame is the world frame). A body reached through joint j
/// from side 1 gets X_w2 = X_w1 · X_12(θ_j); reached from side 2 (a reversed joint)
/// it gets X_w1 = X_w2 · X_12(θ_j)⁻¹. Bodies not reached from ground keep the identity.
/// geometry: per spec joint; theta: per spec joint.
void bodyPoses(const Topology& topo, const std::vector<JointGeometry>& geometry,
               const Eigen::VectorXd& theta, std::vector<Eigen::Isometry3d>& X_wb);

/// Convenience overload returning the poses.
std::vector<Eigen::Isometry3d> bodyPoses(const Topology& topo,
                                         const std::vector<JointGeometry>& geometry,
                                         const Eigen::VectorXd& theta);

/// World motion vector S = [ω; v_O] (dim 6) of tree joint `joint`: the spatial
/// velocity, about the world origin O, of its child body relative to its parent
/// per unit rate θ̇. Revolute and T 1 about world axis a through world point p:
/// [a; p × a] [1/s per rad/s, m/s per rad/s]; prismatic along world r: [0; r].
/// Negated for a reversed joint. X_wb: the poses from bodyPoses.
Vector6d jointMotionWorld(const Topology& topo, const std::vector<JointGeometry>& geometry,
                          const std::vector<Eigen::Isometry3d>& X_wb, int joint);

}  // namespace solver
