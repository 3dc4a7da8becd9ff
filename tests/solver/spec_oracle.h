#pragma once
// A second, independent implementation of a model's positions and mass matrix,
// computed on the spec (Topology and JointGeometry: the modeler's joints, in file
// order) instead of the compiled Model: the oracle the compiled model's kinematics
// and dynamics are checked against (tests/solver/compile, tests/solver/kinematics).
//
// Positions by recursion along the spanning tree from ground (thesis eq. 2.1); the
// joint-space mass matrix by the composite-rigid-body algorithm (RBDA §6.2) written
// in world coordinates. Coordinates are indexed by spec joint; entries of cut joints
// and of joints outside the tree are ignored.

#include "solver/compile/topology.h"
#include "solver/kinematics/joint_geometry.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cassert>
#include <vector>

namespace solver::test {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

/// The body a tree joint moves (the one farther from ground); -1 outside the tree.
inline int treeChildBody(const Topology& topo, int joint)
{
    const int b = topo.reversed[joint] ? topo.side1Body[joint] : topo.side2Body[joint];
    if (b < 0 || topo.parentJoint[b] != joint) return -1;
    return b;
}

/// World poses of all bodies (dim topo.bodyIds.size(); ground: the identity). A body
/// reached through joint j from side 1 gets X_w2 = X_w1 · X_12(θ_j); from side 2 (a
/// reversed joint) X_w1 = X_w2 · X_12(θ_j)⁻¹. theta: per spec joint.
inline std::vector<Eigen::Isometry3d> bodyPoses(const Topology& topo, const std::vector<JointGeometry>& geometry,
                                                const Eigen::VectorXd& theta)
{
    assert(geometry.size() == topo.side1Body.size());
    std::vector<Eigen::Isometry3d> X_wb(topo.bodyIds.size(), Eigen::Isometry3d::Identity());
    for (int j : topo.treeJoints) {
        const Eigen::Isometry3d X_12 = geometry[j].relativePose(theta[j]);
        if (topo.reversed[j]) {
            X_wb[topo.side1Body[j]] = X_wb[topo.side2Body[j]] * X_12.inverse(Eigen::Isometry);
        } else {
            X_wb[topo.side2Body[j]] = X_wb[topo.side1Body[j]] * X_12;
        }
    }
    return X_wb;
}

/// World motion vector S = [ω; v_O] of tree joint `joint` per unit rate: revolute and
/// T 1 about world axis a through world point p: [a; p × a]; prismatic along r: [0; r].
/// Negated for a reversed joint.
inline Vector6 jointMotionWorld(const Topology& topo, const std::vector<JointGeometry>& geometry,
                                const std::vector<Eigen::Isometry3d>& X_wb, int joint)
{
    const JointGeometry& g = geometry[joint];
    const Eigen::Isometry3d& X_w1 = X_wb[topo.side1Body[joint]];
    Vector6 s;
    if (g.type == JointType::Prismatic) {
        s.head<3>().setZero();
        s.tail<3>() = X_w1.linear() * g.side1.r();
    } else {
        const Eigen::Vector3d a = X_w1.linear() * g.side1.a();
        const Eigen::Vector3d p = X_w1 * g.side1.origin;
        s.head<3>() = a;
        s.tail<3>() = p.cross(a);
    }
    return topo.reversed[joint] ? Vector6(-s) : s;
}

/// Inertial data of a body in its local frame.
struct BodyInertia {
    double mass = 0;  ///< [kg]
    Eigen::Vector3d cg = Eigen::Vector3d::Zero();  ///< centre of mass, local [m]
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< about the CG, local axes [kg m^2]
};

/// Spatial inertia about the world origin of a body at pose X_wb.
inline Matrix6 spatialInertiaWorld(const BodyInertia& body, const Eigen::Isometry3d& X_wb)
{
    const Eigen::Vector3d c = X_wb * body.cg;
    const Eigen::Matrix3d r = X_wb.linear();
    Eigen::Matrix3d cx;
    cx << 0, -c.z(), c.y(), c.z(), 0, -c.x(), -c.y(), c.x(), 0;
    Matrix6 inertia;
    inertia.topLeftCorner<3, 3>() = r * body.inertia * r.transpose() + body.mass * cx * cx.transpose();
    inertia.topRightCorner<3, 3>() = body.mass * cx;
    inertia.bottomLeftCorner<3, 3>() = body.mass * cx.transpose();
    inertia.bottomRightCorner<3, 3>() = body.mass * Eigen::Matrix3d::Identity();
    return inertia;
}

/// Joint-space mass matrix of the spanning tree (n × n, n = topo.treeJoints.size(),
/// in treeJoints order) at poses X_wb: M_ij = S_iᵀ C_k S_j, C_k the composite inertia
/// of the subtree moved by the deeper of i and j; 0 when neither lies on the other's
/// path to ground. bodies: per body index.
inline Eigen::MatrixXd treeMassMatrix(const Topology& topo, const std::vector<JointGeometry>& geometry,
                                      const std::vector<Eigen::Isometry3d>& X_wb,
                                      const std::vector<BodyInertia>& bodies)
{
    const auto n = static_cast<Eigen::Index>(topo.treeJoints.size());
    std::vector<Matrix6> composite(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) composite[b] = spatialInertiaWorld(bodies[b], X_wb[b]);
    for (auto it = topo.treeJoints.rbegin(); it != topo.treeJoints.rend(); ++it) {
        const int child = treeChildBody(topo, *it);
        composite[topo.parentBody[child]] += composite[child];
    }
    std::vector<Eigen::Index> column(geometry.size(), -1);
    std::vector<Vector6> s(static_cast<std::size_t>(n));
    for (Eigen::Index k = 0; k < n; ++k) {
        column[topo.treeJoints[k]] = k;
        s[k] = jointMotionWorld(topo, geometry, X_wb, topo.treeJoints[k]);
    }
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index k = 0; k < n; ++k) {
        const int child = treeChildBody(topo, topo.treeJoints[k]);
        const Vector6 f = composite[child] * s[k];
        m(k, k) = s[k].dot(f);
        for (int b = topo.parentBody[child]; b > 0; b = topo.parentBody[b]) {
            const Eigen::Index i = column[topo.parentJoint[b]];
            m(i, k) = m(k, i) = s[i].dot(f);
        }
    }
    return m;
}

}  // namespace solver::test
