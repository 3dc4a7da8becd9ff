#pragma once
// Joint geometry: the joint frames written in a model, the relative pose of the
// two bodies a joint connects as a function of its coordinate, and the length
// law of a pivoted linear actuator (T 1).
//
// Conventions (MODEL_LANGUAGE.md "Joints"): on each side k the joint frame is
// F_k = (A_k, R_k, T_k = A_k × R_k) with origin P_k, given in body k's local frame;
// A is normalised, R is orthogonalised against A and normalised. A pose X_ab maps
// frame b coordinates into frame a: x_a = X_ab * x_b.
//
// The kinematic coordinate θ of a joint is what the position recursion uses:
// the angle [rad] for T 0 and T 1, the displacement [m] for T 2. The modeler's
// coordinate q is the same except for T 1, where it is the actuator length [m].

#include "solver/core/actuator_law.h"
#include "solver/spec/model_spec.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <vector>

namespace solver {

/// One side's joint frame in its body's local frame.
struct JointFrame {
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  ///< columns A, R, T (unit, right-handed)
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< P [m]

    Eigen::Vector3d a() const { return axes.col(0); }
    Eigen::Vector3d r() const { return axes.col(1); }
    Eigen::Vector3d t() const { return axes.col(2); }
    /// Pose of the joint frame in the body frame (x_body = X * x_joint).
    Eigen::Isometry3d pose() const;
};

/// Builds the orthonormal joint frame of one side: A normalised, R orthogonalised
/// against A (Gram–Schmidt) and normalised, T = A × R. Degenerate input (A or R of
/// zero length, A ∥ R; rejected by the local checks) gives a valid frame anyway:
/// A falls back to z, R to a direction perpendicular to A.
JointFrame makeJointFrame(const JointSide& side);

/// The geometry of one joint, independent of names and of the tree.
struct JointGeometry {
    JointType type = JointType::Revolute;
    JointFrame side1;  ///< in side 1's body frame
    JointFrame side2;  ///< in side 2's body frame
    Eigen::Vector3d cl1 = Eigen::Vector3d::Zero();  ///< T 1: actuator end on body 1, local [m]
    Eigen::Vector3d cl2 = Eigen::Vector3d::Zero();  ///< T 1: actuator end on body 2, local [m]

    bool isRotational() const { return type != JointType::Prismatic; }

    /// Relative pose X_12(θ) of side 2's body frame in side 1's body frame.
    /// Revolute and T 1: X_12 = X_1j · Rot(A, θ) · X_2j⁻¹, i.e. the joint frames
    /// coincide at θ = 0 and R2 is R1 turned by θ about A (right hand).
    /// Prismatic: X_12 = X_1j · Trans(θ R) · X_2j⁻¹ (P2 = P1 + θ R1, same orientation).
    /// θ: angle [rad] (T 0, T 1) or displacement [m] (T 2). Thesis eq. 2.1.
    Eigen::Isometry3d relativePose(double theta) const;

    /// T 1 only: the length law L²(θ) (zero coefficients for other types).
    ActuatorLengthLaw lengthLaw() const;

    /// The joint's coordinate q (rad; m for T 1 and T 2) from its kinematic
    /// coordinate θ: the identity except for T 1, where q = L(θ).
    double coordinateFromKinematic(double theta) const;
    /// θ from q: the identity except for T 1 (branch nearest 0; nullopt if unreachable).
    std::optional<double> kinematicFromCoordinate(double q) const;

    /// Measures θ from the two bodies' world poses (X_w1 of side 1's body, X_w2 of
    /// side 2's body), for a joint whose constraints hold: the angle from R1 to R2
    /// about A1 (T 0, T 1), or (P2 − P1)·R1 (T 2).
    double measureKinematic(const Eigen::Isometry3d& X_w1, const Eigen::Isometry3d& X_w2) const;
    /// Measures q from the two bodies' world poses: as measureKinematic, except
    /// for T 1, where q = |world CL2 − world CL1| [m].
    double measureCoordinate(const Eigen::Isometry3d& X_w1, const Eigen::Isometry3d& X_w2) const;
};

/// Builds a joint's geometry from its spec (frames normalised, see makeJointFrame).
JointGeometry makeJointGeometry(const JointSpec& joint);

/// The geometry of every joint of a spec, indexed like spec.joints.
std::vector<JointGeometry> makeJointGeometries(const ModelSpec& spec);

}  // namespace solver
