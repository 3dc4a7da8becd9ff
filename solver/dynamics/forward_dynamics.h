#pragma once
// Hybrid forward dynamics of the tree in O(n): the articulated-body algorithm with
// prescribed-acceleration joints (Featherstone, RBDA §7.3 and §9.2 "hybrid
// dynamics"), then the joint reactions by the Newton–Euler backward pass (RBDA
// §5.3, thesis eq. 2.8–2.9).
//
// Joints with known acceleration (drives.h): hydraulic drives with the relief valve
// closed and joints at a limit; their generalized force is the unknown. All others
// have a known generalized force τ = drive (drives.h, converted to θ by dq/dθ) +
// Data::tauExt, and an unknown θ̈. Every body carries gravity (Model::gravity at its
// centre of mass) and Data::fext.
//
// Everything is about the world origin in world axes (core/spatial.h): body inertias
// I_i, velocities v_i, motion subspaces S_i (kinematics.h). The passes:
//   1. p_i = v_i ×* I_i v_i − fext_i − f_gravity,i;  I^A_i = I_i, p^A_i = p_i;
//   2. leaves → root: free joint: U = I^A S, D = Sᵀ U, u = τ − Sᵀ p^A,
//        I^A_λ += I^A − U Uᵀ/D,  p^A_λ += p^A + I^A c + U (u − Uᵀc)/D;
//      prescribed joint: I^A_λ += I^A,  p^A_λ += p^A + I^A (c + S θ̈);
//   3. root → leaves: a' = a_λ + c;  free: θ̈ = (u − Uᵀa')/D;  a_i = a' + S θ̈;
//   4. leaves → root: f_i = I_i a_i + p_i + Σ_children f_k (the load the parent
//      exerts on body i through joint i), τ_i = S_iᵀ f_i.
// The reaction is f_i moved to the child's joint point (Data::reactionWorld) and
// turned into the joint frame (Data::reactionJoint).
//
// With constraints (Model::cuts, State::welds; dynamics/constraints.h) the tree's
// O(n) algorithm gives way to a dense one: the mass matrix M by composite rigid
// bodies, the bias C by RNEA at θ̈ = 0, the constraint rows G θ̈ = γ, and then, with
// F the free and P the prescribed coordinates,
//   G_F θ̈_F = γ − G_P θ̈_P                 (least squares by SVD: redundant rows, as in
//                                           a planar loop seen in space, are allowed)
//   Nᵀ (M_FF θ̈_F − (τ_F − C_F − M_FP θ̈_P)) = 0   (N: null space of G_F)
//   G_Fᵀ λ = M_FF θ̈_F − (τ_F − C_F − M_FP θ̈_P)  (λ: the minimum-norm multipliers; with
//                                           redundant rows the reactions of a spatially
//                                           over-constrained loop are not unique)
// and the loads λ·W of the constraints enter the backward pass of 4., which so gives
// every tree joint's reaction; each constraint's own reaction is in
// Data::constraintReactionWorld/Joint. The singular values of G_F are kept
// (Data::constraintSingular) for the loop-lock event.
//
// Without constraints: no allocation (everything is pre-sized in Data; sizes are
// asserted). With constraints the dense solves allocate. No exceptions.

#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/core/state.h"

namespace solver {

/// What hybridDynamics computes besides θ̈.
enum class DynamicsOutputs {
    All,            ///< θ̈, the body accelerations, the joint forces and reactions
    Forces,         ///< all but the reactions (reactionWorld, reactionJoint): the event functions' needs
    Accelerations,  ///< θ̈ only (an integrator's stage): no reactions, no body accelerations
};

/// Sets data.fext and data.tauExt to zero (for callers without applied forces).
void clearAppliedForces(Data& data);

/// Forward dynamics at `state`: runs forwardKinematics, then hybridDynamics. Reads
/// data.fext and data.tauExt as filled by the caller (applyForces, or
/// clearAppliedForces). Outputs data.qdd, tau, driveForce, limitForce, reactionWorld,
/// reactionJoint, and the accelerations data.a, alpha, acc.
void forwardDynamics(const Model& model, const State& state, Data& data);

/// The same without the kinematics: data must hold forwardKinematics of `state`
/// (e.g. forwardKinematics → applyForces → hybridDynamics, which computes the
/// kinematics once).
///
/// `outputs` = Accelerations leaves data.a/alpha/acc/f, tau, driveForce, limitForce and
/// the reactions as they were (the constrained, dense path computes them anyway).
void hybridDynamics(const Model& model, const State& state, Data& data,
                    DynamicsOutputs outputs = DynamicsOutputs::All);

/// hybridDynamics after a change of θ̇ (or of modes, commands, loads) only: data holds
/// an evaluation at the same θ, whose body inertias are kept (velocityKinematics, then
/// applyForces, then this). Without constraints only (the caller checks).
void hybridDynamicsSamePositions(const Model& model, const State& state, Data& data,
                                 DynamicsOutputs outputs = DynamicsOutputs::All);

/// When every joint's acceleration is prescribed at `state` and there are no
/// constraints, θ̈ follows from the drive laws alone (drives.h): writes it into
/// data.qdd and returns true, without kinematics or dynamics. Otherwise returns false
/// and changes nothing. (The liner manipulator with every valve closed: the stages of
/// a step need no dynamics; the forces are found once per step for the events.)
bool kinematicAccelerations(const Model& model, const State& state, Data& data);

/// The rate change Δθ̇ (dim nb, written into `dqd`) of an unconstrained tree when the
/// joints whose acceleration is prescribed at `state` jump by `prescribedJump` (read on
/// those joints only) and the other, free joints receive the generalized impulse
/// `freeImpulse` (read on the free joints only): M_FF Δθ̇_F = ι_F − M_FP Δθ̇_P, Δθ̇_P =
/// the jump. The articulated-body algorithm with the velocity terms and gravity left
/// out (RBDA §9.2 with impulses for forces): O(n), no allocation. Needs data to hold
/// forwardKinematics of `state`; overwrites data's dynamics scratch (IA, pA, U, D, uA,
/// a, Ib, prescribed). No constraints: the caller checks.
/// `alsoFree` (≥ 0): that joint counts as free even where prescribed (a joint taking
/// a limit's impulse).
void impulseResponse(const Model& model, const State& state, Data& data, const Eigen::VectorXd& prescribedJump,
                     const Eigen::VectorXd& freeImpulse, Eigen::VectorXd& dqd, int alsoFree = -1);

}  // namespace solver
