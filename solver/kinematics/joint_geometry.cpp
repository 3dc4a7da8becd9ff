#include "solver/kinematics/joint_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace solver {

namespace {

// a unit vector perpendicular to a unit vector
Eigen::Vector3d anyPerpendicular(const Eigen::Vector3d& a)
{
    Eigen::Vector3d trial =
        std::abs(a.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return (trial - a.dot(trial) * a).normalized();
}

}  // namespace

Eigen::Isometry3d JointFrame::pose() const
{
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.linear() = axes;
    X.translation() = origin;
    return X;
}

JointFrame makeJointFrame(const JointSide& side)
{
    JointFrame f;
    f.origin = side.p;

    // axis: normalised, z when degenerate
    const double an = side.a.norm();
    Eigen::Vector3d a =
        an > 0 && std::isfinite(an) ? Eigen::Vector3d(side.a / an) : Eigen::Vector3d::UnitZ();

    // reference: orthogonalised against the axis, any perpendicular when degenerate
    Eigen::Vector3d r = side.r - a.dot(side.r) * a;
    const double rn = r.norm();
    const double scale = std::max(side.r.norm(), 1e-300);
    r = rn > 1e-12 * scale && std::isfinite(rn) ? Eigen::Vector3d(r / rn) : anyPerpendicular(a);

    f.axes.col(0) = a;
    f.axes.col(1) = r;
    f.axes.col(2) = a.cross(r);
    return f;
}

// ---------------------------------------------------------------- length law

JointGeometry makeJointGeometry(const JointSpec& joint)
{
    JointGeometry g;
    g.type = joint.type;
    g.side1 = makeJointFrame(joint.side1);
    g.side2 = makeJointFrame(joint.side2);
    g.cl1 = joint.cl1;
    g.cl2 = joint.cl2;
    return g;
}

Eigen::Isometry3d JointGeometry::relativePose(double theta) const
{
    // motion of joint frame 2 in joint frame 1 (joint axes: x = A, y = R, z = T)
    Eigen::Isometry3d X_j = Eigen::Isometry3d::Identity();
    if (type == JointType::Prismatic) {
        X_j.translation() = Eigen::Vector3d(0, theta, 0);
    } else {
        X_j.linear() = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitX()).toRotationMatrix();
    }
    return side1.pose() * X_j * side2.pose().inverse(Eigen::Isometry);
}

ActuatorLengthLaw JointGeometry::lengthLaw() const
{
    ActuatorLengthLaw law;
    if (type != JointType::Actuator) return law;

    // L² = |Rx(θ) u − w|² with u, w the actuator ends in the joint frames
    const Eigen::Vector3d u = side2.axes.transpose() * (cl2 - side2.origin);
    const Eigen::Vector3d w = side1.axes.transpose() * (cl1 - side1.origin);
    law.c0 = u.squaredNorm() + w.squaredNorm() - 2 * w.x() * u.x();
    law.c1 = -2 * (w.y() * u.y() + w.z() * u.z());
    law.c2 = -2 * (w.z() * u.y() - w.y() * u.z());
    return law;
}

double JointGeometry::coordinateFromKinematic(double theta) const
{
    return type == JointType::Actuator ? lengthLaw().length(theta) : theta;
}

std::optional<double> JointGeometry::kinematicFromCoordinate(double q) const
{
    if (type != JointType::Actuator) return q;
    return lengthLaw().angle(q);
}

double JointGeometry::measureKinematic(const Eigen::Isometry3d& X_w1,
                                       const Eigen::Isometry3d& X_w2) const
{
    const Eigen::Vector3d r1 = X_w1.linear() * side1.r();
    if (type == JointType::Prismatic) {
        const Eigen::Vector3d p1 = X_w1 * side1.origin;
        const Eigen::Vector3d p2 = X_w2 * side2.origin;
        return (p2 - p1).dot(r1);
    }
    const Eigen::Vector3d a1 = X_w1.linear() * side1.a();
    const Eigen::Vector3d r2 = X_w2.linear() * side2.r();
    return std::atan2(r1.cross(r2).dot(a1), r1.dot(r2));
}

double JointGeometry::measureCoordinate(const Eigen::Isometry3d& X_w1,
                                        const Eigen::Isometry3d& X_w2) const
{
    if (type == JointType::Actuator) return ((X_w2 * cl2) - (X_w1 * cl1)).norm();
    return measureKinematic(X_w1, X_w2);
}

std::vector<JointGeometry> makeJointGeometries(const ModelSpec& spec)
{
    std::vector<JointGeometry> geometry;
    geometry.reserve(spec.joints.size());
    for (const JointSpec& joint : spec.joints) geometry.push_back(makeJointGeometry(joint));
    return geometry;
}

}  // namespace solver
