#pragma once
// The joint-space mass matrix at one configuration, for the "every joint moves
// mass" check: spatial inertias about the world origin, composite inertias of
// subtrees, and M_ij = S_iᵀ C_k S_j (composite-rigid-body algorithm, RBDA §6.2,
// written in world coordinates).

#include "solver/compile/topology.h"
#include "solver/kinematics/joint_geometry.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace solver {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// Inertial data of a body in its local frame.
struct BodyInertia {
    double mass = 0;  ///< [kg]
    Eigen::Vector3d cg = Eigen::Vector3d::Zero();  ///< centre of mass, local [m]
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about the CG, local axes [kg m^2]
};

/// Spatial inertia (6×6, motion vectors ordered [ω; v_O]) about the world origin
/// of a body at pose X_wb: [[I_c + m [c]×[c]×ᵀ, m [c]×], [m [c]×ᵀ, m 1]] with c
/// the world centre of mass and I_c = R I Rᵀ. Kinetic energy = ½ Vᵀ I V.
Matrix6d spatialInertiaWorld(const BodyInertia& body, const Eigen::Isometry3d& X_wb);

/// Composite spatial inertia about the world origin of every body's subtree
/// (dim topo.bodyIds.size()): the body's own plus all its descendants'.
std::vector<Matrix6d> compositeInertias(const Topology& topo, const std::vector<Eigen::Isometry3d>& X_wb,
                                        const std::vector<BodyInertia>& bodies);

/// Per spec joint: true for a tree joint whose diagonal mass-matrix entry is zero
/// (its subtree has no mass off its axis and no inertia about it; for a prismatic
/// joint, no mass). O(n·depth) and exact (a sum of non-negative terms), for models
/// too large for the dense check. Cut joints and joints outside the tree: false.
std::vector<bool> jointsMovingNoMass(const Topology& topo, const std::vector<JointGeometry>& geometry,
                                     const std::vector<Eigen::Isometry3d>& X_wb,
                                     const std::vector<BodyInertia>& bodies);

/// Joint-space mass matrix of the spanning tree (dim n × n, n = topo.treeJoints.size(),
/// rows/columns in treeJoints order) at poses X_wb, for kinematic coordinates
/// (T 1 by its angle). bodies: per body index (dim topo.bodyIds.size()).
/// M_ij = S_iᵀ C_k S_j, with S the joints' world motion vectors and C_k the
/// composite inertia of the subtree moved by the deeper of i and j; 0 when
/// neither joint lies on the other's path to ground.
Eigen::MatrixXd treeMassMatrix(const Topology& topo, const std::vector<JointGeometry>& geometry,
                               const std::vector<Eigen::Isometry3d>& X_wb,
                               const std::vector<BodyInertia>& bodies);

}  // namespace solver
