#pragma once
// Applied forces: the loads of a model's `F` statements (MODEL_LANGUAGE.md
// "Forces") evaluated at one state, as body loads Data::fext and generalized
// forces Data::tauExt, which the dynamics add to gravity and the drives.
//
// Conventions (core/data.h): Data::fext[i] = [moment; force] in world axes [N m; N],
// the moment taken about body i's frame origin o_i = X_wb[i].translation(); a force
// F at the world point p contributes [(p − o_i) × F; F]. The velocity of a point p
// of body i is vel[i] + omega[i] × (p − o_i). Data::tauExt[j] is a generalized
// force on joint j's kinematic coordinate θ_j [N m for T 0 and T 1, N for T 2].
// Loads on the ground (body −1) are dropped: the ground does not move.
//
// The kinds (CompiledForce::kind):
// - POINT: F = MAG·d at the body point P; d = dir in world axes, or R_wb·dir with LOCAL.
// - TORQUE: a pure moment M = MAG·d (d as for POINT).
// - JOINT: a generalized force MAG on joint j's modeler coordinate q [N m revolute,
//   N prismatic and T 1]; on θ that is τ_θ = MAG·dq/dθ (Model::coordinateRate),
//   the virtual work MAG·δq = τ_θ·δθ.
// - SPRING: a linear spring–damper between P1 on body1 and P2 on body2 (either may
//   be the ground, −1, whose points are world points). With L = |p2 − p1| and
//   e = (p2 − p1)/L, the tension T = K·(L − L0) + C·L̇, L̇ = e·(v2 − v1), pulls p1
//   by +T·e and p2 by −T·e (T < 0 pushes them apart). A spring of zero length has
//   no direction and exerts nothing.
// - AERO: the air is still; v is the world velocity of P on body i, V = |v|.
//   Drag D = −½·ρ·CD·AREA·V·v (against v); lift Lf = ½·ρ·CL·AREA·V²·n, with n the
//   unit vector perpendicular to v in the plane of v and "up" that points up:
//   n = (u − (u·v̂)v̂)/|u − (u·v̂)v̂|, u = −gravity/|gravity| (world +z when the model
//   has no gravity). No lift when v is zero or vertical (|u − (u·v̂)v̂| < 1e-9);
//   a negative CL pushes down. Both act at P.
//
// The push (State::push, Simulation::setPush: the studio's Ctrl + drag, as MuJoCo's
// `simulate` perturbs a body): body b's point P (body frame) is pulled toward the
// world target T by a spring–damper scaled by the mass m that b carries (its own and
// every body outboard of it: the subtree mass, as MuJoCo's), so that every body
// answers alike, as a mass on a critically damped spring of natural frequency ω₀:
//     F = k·(T − p) − c·v_p,   k = ω₀²·m,  c = 2·ω₀·m,
// with p and v_p P's world position and velocity, |F| capped at a_max·m (a mouse far
// away pulls hard, not without bound); and a moment −2·ω₀·I_w·ω that damps b's spin
// (I_w: b's own inertia about its centre of mass, in world axes), so that a body held
// off its centre of mass settles instead of swinging about P for ever. A push on the
// ground, on a body out of range or on a body that carries no mass exerts nothing.

#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/core/state.h"

namespace solver {

/// The push's natural frequency ω₀ [rad/s]: k = 100 N/m per kg (MuJoCo's default
/// perturbation stiffness), critically damped.
inline constexpr double kPushFrequency = 10.0;
/// The push's largest force per kilogram pushed [m/s²] (about 10 g; k·d reaches it
/// when the target is 1 m from the point).
inline constexpr double kPushMaxAcceleration = 100.0;

/// The mass body `body` carries: its own and every body's outboard of it [kg] (0 for
/// an index out of range). O(nb · depth), no allocation.
double subtreeMass(const Model& model, int body);

/// Value of a magnitude law at time t [s] and state `state`:
/// - Constant: `value`;
/// - Sine: offset + amplitude·sin(2π·frequency·t + phase) (frequency [Hz], phase [rad]);
/// - TableTime: linear interpolation of (x, y) at t, held at y.front() before x.front()
///   and at y.back() after x.back();
/// - TableJoint: the same at joint `joint`'s modeler coordinate
///   q = Model::coordinate(joint, state.q[joint]) (T 1: the actuator length [m]).
/// An empty table gives 0, a one-point table its value. A TableJoint whose joint is
/// not a tree index in [0, nb) gives 0. Units are those of the force it scales.
/// No allocation.
double evaluateMagnitude(const CompiledMagnitude& mag, double t, const Model& model,
                         const State& state);

/// Sets data.fext (dim nb) and data.tauExt (dim nb) to the sum of every load in
/// model.forces at state `state` (time state.t), and the push state.push. Reads data.X_wb, data.omega and
/// data.vel, which the kinematics must have computed for `state` (the velocities only
/// for SPRING with damping and AERO). Forces naming a body or joint outside [0, nb)
/// other than the ground (−1) are ignored. No allocation, no exceptions.
void applyForces(const Model& model, const State& state, Data& data);

}  // namespace solver
