#include "solver/compile/mass_check.h"

#include "solver/kinematics/positions.h"

#include <cassert>

namespace solver {

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d s;
    s << 0, -v.z(), v.y(),
         v.z(), 0, -v.x(),
         -v.y(), v.x(), 0;
    return s;
}

}  // namespace

Matrix6d spatialInertiaWorld(const BodyInertia& body, const Eigen::Isometry3d& X_wb)
{
    const Eigen::Vector3d c = X_wb * body.cg;
    const Eigen::Matrix3d r = X_wb.linear();
    const Eigen::Matrix3d cx = skew(c);
    Matrix6d inertia;
    inertia.topLeftCorner<3, 3>() = r * body.inertia * r.transpose() + body.mass * cx * cx.transpose();
    inertia.topRightCorner<3, 3>() = body.mass * cx;
    inertia.bottomLeftCorner<3, 3>() = body.mass * cx.transpose();
    inertia.bottomRightCorner<3, 3>() = body.mass * Eigen::Matrix3d::Identity();
    return inertia;
}

Eigen::MatrixXd treeMassMatrix(const Topology& topo, const std::vector<JointGeometry>& geometry,
                               const std::vector<Eigen::Isometry3d>& X_wb,
                               const std::vector<BodyInertia>& bodies)
{
    assert(bodies.size() == topo.bodyIds.size());
    const auto n = static_cast<Eigen::Index>(topo.treeJoints.size());

    // composite inertias, leaves first
    std::vector<Matrix6d> composite(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) composite[b] = spatialInertiaWorld(bodies[b], X_wb[b]);
    for (auto it = topo.treeJoints.rbegin(); it != topo.treeJoints.rend(); ++it) {
        const int child = treeChildBody(topo, *it);
        composite[topo.parentBody[child]] += composite[child];
    }

    // column of each tree joint
    std::vector<Eigen::Index> column(geometry.size(), -1);
    std::vector<Vector6d> s(static_cast<std::size_t>(n));
    for (Eigen::Index k = 0; k < n; ++k) {
        column[topo.treeJoints[k]] = k;
        s[k] = jointMotionWorld(topo, geometry, X_wb, topo.treeJoints[k]);
    }

    // M_jj and M_ij for the joints i on j's path to ground
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index k = 0; k < n; ++k) {
        const int child = treeChildBody(topo, topo.treeJoints[k]);
        const Vector6d f = composite[child] * s[k];
        m(k, k) = s[k].dot(f);
        for (int b = topo.parentBody[child]; b > 0; b = topo.parentBody[b]) {
            const Eigen::Index i = column[topo.parentJoint[b]];
            m(i, k) = m(k, i) = s[i].dot(f);
        }
    }
    return m;
}

}  // namespace solver
