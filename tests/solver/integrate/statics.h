#pragma once
// Hand statics for the machine tests: moment arms of T 1 cylinders and moments of
// weights about a joint's axis, from the kinematics alone (positions of pins and
// centres of mass), never from the dynamics they check.

#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/kinematics/kinematics.h"

#include <Eigen/Core>

#include <cmath>

namespace solver::test {

/// Pivot point and axis (A) of joint j in the world.
struct Pivot {
    Eigen::Vector3d point, axis;
};

inline Pivot jointPivot(const Model& m, const Data& d, int j)
{
    const Eigen::Isometry3d F = jointFramePose(m, d, j);
    return {F.translation(), F.linear().col(0)};
}

/// The moment arm [m] of T 1 joint j's cylinder (the line CL1–CL2) about the joint's
/// own axis: |((CL2 − P) × ê)·A|.
inline double cylinderArm(const Model& m, const Data& d, int j)
{
    const Pivot p = jointPivot(m, d, j);
    const int parent = m.parent[j];
    const int b1 = m.axisSign[j] > 0 ? parent : j;  // CL1 is on B1: the parent unless written child → parent
    const int b2 = m.axisSign[j] > 0 ? j : parent;
    auto world = [&](int b, const Eigen::Vector3d& x) { return b < 0 ? x : Eigen::Vector3d(d.X_wb[b] * x); };
    const Eigen::Vector3d c1 = world(b1, m.cl1[j]), c2 = world(b2, m.cl2[j]);
    const Eigen::Vector3d e = (c2 - c1).normalized();
    return std::abs((c2 - p.point).cross(e).dot(p.axis));
}

/// The moment about the pivot's axis [N m] of the weight m·g of a mass at `x`.
inline double weightMoment(const Model& m, const Pivot& p, double mass, const Eigen::Vector3d& x)
{
    return (x - p.point).cross(mass * m.gravity).dot(p.axis);
}

/// The moment about joint j's axis of the weights of every body in j's subtree.
inline double subtreeWeightMoment(const Model& m, const Data& d, int j)
{
    const Pivot p = jointPivot(m, d, j);
    double sum = 0;
    for (int b = 0; b < m.nb; ++b) {
        bool inside = false;
        for (int a = b; a >= 0 && !inside; a = m.parent[a]) inside = a == j;
        if (inside) sum += weightMoment(m, p, m.mass[b], comPosition(m, d, b));
    }
    return sum;
}

}  // namespace solver::test
