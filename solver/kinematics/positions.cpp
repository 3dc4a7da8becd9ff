#include "solver/kinematics/positions.h"

#include <cassert>

namespace solver {

int treeChildBody(const Topology& topo, int joint)
{
    const int b = topo.reversed[joint] ? topo.side1Body[joint] : topo.side2Body[joint];
    if (b < 0 || topo.parentJoint[b] != joint) return -1;
    return b;
}

int treeParentBody(const Topology& topo, int joint)
{
    const int child = treeChildBody(topo, joint);
    return child < 0 ? -1 : topo.parentBody[child];
}

bool jointMovesBody(const Topology& topo, int joint, int body)
{
    // walk from the body towards ground
    for (int b = body; b > 0; b = topo.parentBody[b]) {
        if (topo.parentJoint[b] == joint) return true;
    }
    return false;
}

void bodyPoses(const Topology& topo, const std::vector<JointGeometry>& geometry,
               const Eigen::VectorXd& theta, std::vector<Eigen::Isometry3d>& X_wb)
{
    assert(geometry.size() == topo.side1Body.size());
    assert(theta.size() == static_cast<Eigen::Index>(geometry.size()));
    X_wb.assign(topo.bodyIds.size(), Eigen::Isometry3d::Identity());

    // tree joints come parents first: eq. 2.1 applied joint by joint
    for (int j : topo.treeJoints) {
        const Eigen::Isometry3d X_12 = geometry[j].relativePose(theta[j]);
        if (topo.reversed[j]) {
            X_wb[topo.side1Body[j]] = X_wb[topo.side2Body[j]] * X_12.inverse(Eigen::Isometry);
        } else {
            X_wb[topo.side2Body[j]] = X_wb[topo.side1Body[j]] * X_12;
        }
    }
}

std::vector<Eigen::Isometry3d> bodyPoses(const Topology& topo,
                                         const std::vector<JointGeometry>& geometry,
                                         const Eigen::VectorXd& theta)
{
    std::vector<Eigen::Isometry3d> X_wb;
    bodyPoses(topo, geometry, theta, X_wb);
    return X_wb;
}

Vector6d jointMotionWorld(const Topology& topo, const std::vector<JointGeometry>& geometry,
                          const std::vector<Eigen::Isometry3d>& X_wb, int joint)
{
    const JointGeometry& g = geometry[joint];
    const Eigen::Isometry3d& X_w1 = X_wb[topo.side1Body[joint]];
    Vector6d s;
    if (g.type == JointType::Prismatic) {
        s.head<3>().setZero();
        s.tail<3>() = X_w1.linear() * g.side1.r();
    } else {
        const Eigen::Vector3d a = X_w1.linear() * g.side1.a();
        const Eigen::Vector3d p = X_w1 * g.side1.origin;
        s.head<3>() = a;
        s.tail<3>() = p.cross(a);
    }
    return topo.reversed[joint] ? Vector6d(-s) : s;
}

}  // namespace solver
