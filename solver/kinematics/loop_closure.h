#pragma once
// Loop closure: the constraint equations Φ(θ) = 0 of the cut joints, their
// Jacobian Φ_θ with respect to the tree coordinates, and a Newton solver for the
// dependent coordinates.
//
// Per cut joint (world vectors; a, r, t the joint-frame axes of side 1 or 2, p the
// joint points), 5 equations:
//   revolute, T 1:  p2 − p1 (3 rows) [m];  a1·r2, a1·t2 [-]      (same point, A1 ∥ A2)
//   prismatic:      a1·r2, a1·t2, r1·t2 [-];  (p2 − p1)·a1, (p2 − p1)·t1 [m]
//                   (same orientation, P2 on the line through P1 along R1)
// Rows of cut joint topo.loopJoints[k] are 5k .. 5k+4. Jacobian columns are the
// tree joints in topo.treeJoints order.

#include "solver/compile/topology.h"
#include "solver/kinematics/joint_geometry.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace solver {

/// Closure equations per cut joint.
inline constexpr int kClosureEquations = 5;

/// Residual Φ (dim 5·topo.loopJoints.size()) at body poses X_wb (from bodyPoses).
void closureResidual(const Topology& topo, const std::vector<JointGeometry>& geometry,
                     const std::vector<Eigen::Isometry3d>& X_wb, Eigen::VectorXd& phi);

/// Which rows of a cut joint's 5 carry lengths [m] (the others are dimensionless).
bool closureRowIsLength(JointType type, int row);

/// Analytic Jacobian Φ_θ (dim 5·ncut × topo.treeJoints.size()) at poses X_wb.
/// Column k is ∂Φ/∂θ_j for j = topo.treeJoints[k], from the joint's world motion
/// vector: a point x of a body moved by joint j changes by ω × x + v_O, a
/// direction d by ω × d.
void closureJacobian(const Topology& topo, const std::vector<JointGeometry>& geometry,
                     const std::vector<Eigen::Isometry3d>& X_wb, Eigen::MatrixXd& jac);

struct ClosureSolveOptions {
    int maxIterations = 60;
    double tolerance = 1e-10;  ///< converged when |Φ| ≤ tolerance (mixed m and -)
    /// Length that makes length rows and prismatic columns comparable to the
    /// dimensionless ones [m] (e.g. the size of the mechanism).
    double lengthScale = 1.0;
};

struct ClosureSolveResult {
    bool converged = false;
    int iterations = 0;
    double residualNorm = 0;  ///< |Φ| at the returned θ
    Eigen::VectorXd residual;  ///< Φ at the returned θ (dim 5·ncut)
};

/// Solves Φ(θ) = 0 for the coordinates of the spec joints `unknowns` (tree joints),
/// holding every other coordinate of `theta` fixed; `theta` (dim spec joints) holds
/// the starting guess and receives the solution, or the least-squares point
/// reached when the equations cannot be satisfied. Damped Gauss–Newton
/// (Levenberg–Marquardt) on scaled equations.
ClosureSolveResult solveClosure(const Topology& topo, const std::vector<JointGeometry>& geometry,
                                const std::vector<int>& unknowns, Eigen::VectorXd& theta,
                                const ClosureSolveOptions& options = {});

}  // namespace solver
