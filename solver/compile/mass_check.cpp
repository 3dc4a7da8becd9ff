#include "solver/compile/mass_check.h"

#include "solver/kinematics/positions.h"

#include <cassert>

namespace solver {

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d s;
    // clang-format off
    s << 0, -v.z(), v.y(),
         v.z(), 0, -v.x(),
         -v.y(), v.x(), 0;
    // clang-format on
    return s;
}

}  // namespace

Matrix6d spatialInertiaWorld(const BodyInertia& body, const Eigen::Isometry3d& X_wb)
{
    const Eigen::Vector3d c = X_wb * body.cg;
    const Eigen::Matrix3d r = X_wb.linear();
    const Eigen::Matrix3d cx = skew(c);
    Matrix6d inertia;
    inertia.topLeftCorner<3, 3>() =
        r * body.inertia * r.transpose() + body.mass * cx * cx.transpose();
    inertia.topRightCorner<3, 3>() = body.mass * cx;
    inertia.bottomLeftCorner<3, 3>() = body.mass * cx.transpose();
    inertia.bottomRightCorner<3, 3>() = body.mass * Eigen::Matrix3d::Identity();
    return inertia;
}

std::vector<Matrix6d> compositeInertias(const Topology& topo, const std::vector<Eigen::Isometry3d>& X_wb,
                                       const std::vector<BodyInertia>& bodies)
{
    // leaves first: every body's inertia is added to its parent's
    std::vector<Matrix6d> composite(bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b)
        composite[b] = spatialInertiaWorld(bodies[b], X_wb[b]);
    for (auto it = topo.treeJoints.rbegin(); it != topo.treeJoints.rend(); ++it) {
        const int child = treeChildBody(topo, *it);
        composite[topo.parentBody[child]] += composite[child];
    }
    return composite;
}

std::vector<bool> jointsMovingNoMass(const Topology& topo, const std::vector<JointGeometry>& geometry,
                                     const std::vector<Eigen::Isometry3d>& X_wb,
                                     const std::vector<BodyInertia>& bodies)
{
    // per joint: M_kk as a sum of non-negative terms, and the scale of those terms
    std::vector<double> sum(geometry.size(), 0.0), scale(geometry.size(), 0.0);
    std::vector<Eigen::Vector3d> axis(geometry.size()), point(geometry.size());
    for (int j : topo.treeJoints) {
        const bool rev = topo.reversed[static_cast<std::size_t>(j)];
        const JointFrame& f = rev ? geometry[j].side1 : geometry[j].side2;
        const Eigen::Isometry3d& X = X_wb[treeChildBody(topo, j)];
        axis[j] = X.linear() * (geometry[j].isRotational() ? f.a() : f.r());
        point[j] = X * f.origin;
    }
    for (std::size_t b = 1; b < bodies.size(); ++b) {
        const BodyInertia& body = bodies[b];
        if (body.mass == 0 && body.inertia.isZero()) continue;
        const Eigen::Vector3d c = X_wb[b] * body.cg;
        const Eigen::Matrix3d I = X_wb[b].linear() * body.inertia * X_wb[b].linear().transpose();
        for (int k = static_cast<int>(b); k > 0; k = topo.parentBody[k]) {
            const int j = topo.parentJoint[k];
            if (geometry[j].isRotational()) {
                const Eigen::Vector3d r = c - point[j];
                sum[j] += body.mass * axis[j].cross(r).squaredNorm() + axis[j].dot(I * axis[j]);
                scale[j] += body.mass * r.squaredNorm() + I.trace();
            } else {
                sum[j] += body.mass;
                scale[j] += body.mass;
            }
        }
    }
    std::vector<bool> none(geometry.size(), false);
    for (int j : topo.treeJoints) none[j] = !(sum[j] > 1e-12 * scale[j]);
    return none;
}

Eigen::MatrixXd treeMassMatrix(const Topology& topo, const std::vector<JointGeometry>& geometry,
                               const std::vector<Eigen::Isometry3d>& X_wb,
                               const std::vector<BodyInertia>& bodies)
{
    assert(bodies.size() == topo.bodyIds.size());
    const auto n = static_cast<Eigen::Index>(topo.treeJoints.size());
    const std::vector<Matrix6d> composite = compositeInertias(topo, X_wb, bodies);

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
