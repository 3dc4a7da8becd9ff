#pragma once
// The reference dynamics: the thesis's assembled Newton–Euler system A·X = B
// (seed/thesis.txt §2.2, eq. 2.8–2.11), built straightforwardly with dense Eigen
// matrices and solved by Gaussian elimination (LU). It is what PADROB solved; the
// simulator does NOT use it (solver/dynamics/forward_dynamics.h is the O(n) hybrid
// articulated-body algorithm). It is kept for two jobs:
//   - the oracle of the dynamics tests (tests/solver/dynamics/thesis_oracle.h):
//     both agree to 1e-9 relative on random states of every test model;
//   - the baseline of `padrob bench` (docs/performance.md): the cost of the thesis's
//     method against Padrob's on the same model and state.
//
// Unknowns (eq. 2.10), 13 per tree index i (body i and its parent joint i):
//   a_G,i (3)  acceleration of body i's centre of mass, world [m/s^2]
//   α_i   (3)  angular acceleration of body i, world [rad/s^2]
//   F_i   (3)  force the parent exerts on body i through joint i, world [N]
//   M_i   (3)  moment of that load about the child's joint point x_i, world [N m]
//   θ̈_i   (1)
// (one set of reactions per joint; the parent receives −F_i, −M_i: Newton's third law,
// which halves the thesis's F_j1, F_j2, M_j1, M_j2), then 7 per loop-closing (cut)
// joint c of Model::cuts: F_c, M_c (the load body 1 exerts on body 2, moment about
// body 2's joint point P2) and the cut's own θ̈_c.
// Rows, 13 per i:
//   Newton about G_i (eq. 2.8):  m a_G − F_i + Σ_k F_k = m g + F_ext
//   Euler about G_i (eq. 2.9):   I α − M_i − (x_i − G_i) × F_i + Σ_k [M_k + (x_k − G_i) × F_k]
//                                = M_ext,G − ω × I ω          (k: the children of body i;
//                                a cut's load enters body 2's rows as a parent joint's
//                                does, and body 1's as a child's)
//   joint i, rotation (eq. 2.7): α_i − α_λ − σθ̈ a = σθ̇ ω_λ × a   (T 0, T 1);  α_i − α_λ = 0 (T 2)
//   joint i, translation (eq. 2.5–2.6): the child's joint point moves with the parent's
//                                point there (T 0, T 1), plus σθ̈ r + 2σθ̇ ω_λ × r (T 2)
//   joint i, drive or passive: θ̈ = known (at a limit, hydraulic T 0/T 2 held), or for a
//                                hydraulic T 1 with the relief closed L̈ = 0 written on the
//                                actuator's end points; else the reaction along the joint's
//                                free direction: σ a·M_i (T 0, T 1) or σ r·F_i (T 2) = drive + tauExt.
// and 7 per cut joint: its rotation and translation rows as above (body 1 in the
// parent's place, body 2 in the child's; a T 1 cut holds like a revolute joint) and
// a·M_c = 0 (T 0, T 1) or r·F_c = 0 (T 2): a cut joint is never driven.
// Velocities come from eq. 2.2–2.4 by their own recursion; the drive laws, actuator
// lengths, rates and lever arms are computed here from the world geometry, not
// with the library's helpers. Run-time welds (State::welds) are not included.
//
// Solving: a tree's A is regular and is solved by LU with partial pivoting. A loop
// seen in space may be over-constrained (a planar loop: only 3 of its 6 closure rows
// are independent), which makes A singular: then LU with complete pivoting, which
// finds the unique accelerations and one of the reactions that hold the loop (the
// indeterminate components are arbitrary, unlike Data::constraintReactionWorld,
// which takes the minimum-norm ones).
//
// Cost: A has n = 13·nb + 7·ncuts rows, dense; LU takes ~(2/3) n³ flops (partial
// pivoting), complete pivoting several times that. Assembly is O(n²) (clearing A).
// The system's buffers are allocated once, by the constructor.

#include "solver/core/model.h"
#include "solver/core/spatial.h"
#include "solver/core/state.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <vector>

namespace solver::reference {

struct NewtonEulerResult {
    Eigen::VectorXd qdd;                ///< θ̈ (dim nb)
    std::vector<Eigen::Vector3d> aG;    ///< centre-of-mass accelerations, world (dim nb)
    std::vector<Eigen::Vector3d> alpha; ///< angular accelerations, world (dim nb)
    std::vector<Vector6d> reaction;     ///< [M_i; F_i], world, about the child's joint point (dim nb)
    std::vector<Vector6d> cutReaction;  ///< [M_c; F_c], world, about P2 of each cut (dim cuts)
    Eigen::VectorXd tau;                ///< generalized force along θ transmitted by each joint
    Eigen::VectorXd driveForce;         ///< as Data::driveForce
    Eigen::VectorXd limitForce;         ///< as Data::limitForce
    double relativeResidual = 0;        ///< |A X − B| / |B| (when asked for; else 0)
};

/// The system of one model, with its buffers. Not thread-safe: one per thread.
class NewtonEulerSystem {
public:
    /// Keeps a reference to `model`, which must outlive the system.
    explicit NewtonEulerSystem(const Model& model);

    /// Number of unknowns n = 13·nb + 7·cuts.
    int size() const { return static_cast<int>(m_B.size()); }

    /// Builds and solves the system at `state` with applied loads fext (per body,
    /// [moment about the body frame's origin; force], world, dim nb) and tauExt (per
    /// joint, on θ, dim nb). With `residual` the result's relativeResidual is computed
    /// (one more n² product). The result lives in the system until the next solve().
    const NewtonEulerResult& solve(const State& state, const std::vector<Vector6d>& fext,
                                   const Eigen::VectorXd& tauExt, bool residual = true);

    /// The system last assembled (A, B).
    const Eigen::MatrixXd& matrix() const { return m_A; }
    const Eigen::VectorXd& rhs() const { return m_B; }

private:
    const Model& m_model;
    // geometry and velocities (per tree index)
    std::vector<Eigen::Isometry3d> m_X;
    std::vector<Eigen::Vector3d> m_G, m_x, m_axis, m_slide, m_w, m_vG;
    std::vector<Eigen::Matrix3d> m_Iw;
    Eigen::VectorXd m_q, m_qdot, m_dq;
    // the system and its solvers
    Eigen::MatrixXd m_A;
    Eigen::VectorXd m_B, m_Xu;
    Eigen::PartialPivLU<Eigen::MatrixXd> m_lu;
    Eigen::FullPivLU<Eigen::MatrixXd> m_fullLu;
    NewtonEulerResult m_result;

    void assemble(const State& state, const std::vector<Vector6d>& fext, const Eigen::VectorXd& tauExt);
    void solveLinear();
};

/// One-shot: builds a NewtonEulerSystem for `model` and solves it at `state`
/// (allocates; for tests).
NewtonEulerResult solveNewtonEuler(const Model& model, const State& state, const std::vector<Vector6d>& fext,
                                   const Eigen::VectorXd& tauExt);

/// One classic Runge–Kutta step of h [s] over y = [θ; θ̇] with θ̈ from the system:
/// 4 solves and the update. The modes (limits, relief valves), commands, servo
/// integrals and applied loads are held over the step; the caller's `state` gets the
/// new θ, θ̇ and t. No events, no projection onto loop constraints: the reference's
/// cost, not a simulator. Scratch in `work` (sized on first use).
struct Rk4Work {
    State stage;                 ///< the state each stage solves at
    Eigen::VectorXd q0, qd0;     ///< θ, θ̇ at the step's start
    Eigen::VectorXd kq, kv;      ///< the last stage's slopes (θ̇, θ̈)
    Eigen::VectorXd accQ, accV;  ///< their weighted sums (1, 2, 2, 1)
};
void rk4Step(NewtonEulerSystem& system, State& state, const std::vector<Vector6d>& fext,
             const Eigen::VectorXd& tauExt, double h, Rk4Work& work);

}  // namespace solver::reference
