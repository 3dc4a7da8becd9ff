#pragma once
// A kinematic constraint between two bodies, as the dynamics hold it: a model's
// loop-closure (cut) joint (Model::cuts) or a run-time weld (State::welds).
// See solver/dynamics/constraints.h for its equations.

#include <Eigen/Geometry>

namespace solver {

enum class ConstraintKind {
    Revolute,   ///< same point, same axis A (5 equations): T 0 and T 1 cut joints
    Prismatic,  ///< same orientation, P2 on the line through P1 along R (5 equations): T 2
    Weld,       ///< same pose (6 equations)
};

/// Number of equations (rows) of a constraint of this kind.
constexpr int constraintRowCount(ConstraintKind kind) { return kind == ConstraintKind::Weld ? 6 : 5; }

struct Constraint {
    ConstraintKind kind = ConstraintKind::Revolute;
    int body1 = -1, body2 = -1;  ///< tree indices; −1 = ground
    /// Frames (origin P, axes A, R, T as columns) in body 1's and body 2's frames
    /// (ground: the world); the constraint holds them together as its kind says.
    Eigen::Isometry3d X_1 = Eigen::Isometry3d::Identity();
    Eigen::Isometry3d X_2 = Eigen::Isometry3d::Identity();
    int cut = -1;   ///< index in Model::cuts, or −1
    int weld = -1;  ///< index in State::welds, or −1
};

}  // namespace solver
