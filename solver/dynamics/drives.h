#pragma once
// Drive laws (MODEL_LANGUAGE.md "Drives"): what each joint's drive imposes at one
// state, in the modeler's coordinate q (T 1: the actuator length L [m]), and the
// conversions to the kinematic coordinate θ the dynamics use (dq/dθ = dL/dθ for T 1,
// 1 otherwise; virtual work: τ_θ = F_q · dq/dθ, θ̇ = q̇ / (dq/dθ)).
//
// A joint's acceleration is prescribed (known θ̈, unknown force) when
//   - it is at a limit (State::limit AtLower/AtUpper): held, θ̈ = 0; or
//   - it has a hydraulic drive whose relief valve is Closed: the rate is prescribed,
//     q̇ = q̇_cmd = u·vmax (u > 0) or u·vmin (u < 0), 0 when u = 0 (held), and θ̈ is the
//     derivative of θ̇ with the command held: 0 for T 0/T 2; for T 1, q̇ = L'(θ)θ̇ held
//     constant gives L''θ̇² + L'θ̈ = 0, θ̈ = −L''(θ)θ̇²/L'(θ).
// Every other joint is force-driven (known generalized force, unknown θ̈):
//   - motor       F = u·t0·(1 − |q̇|/w0), 0 beyond w0 (w0 ≤ 0: u·t0);
//   - pneumatic   F = u·force;
//   - servo       F = kp·e + ki·∫e dt + kd·ė, clamped to ±servoFmax, with the
//                 set-point s = setLow + (u + 1)/2·(setHigh − setLow), e = s − q and
//                 ė = −q̇ (the set-point is held between commands);
//   - hydraulic with the relief open: +fmax (OpenExtending) or −fmin (OpenRetracting);
//   - fluid power (CYL, HMOTOR): F = p_A·A_A − p_B·A_B − c·q̇ from State::fluid
//                 (solver/hydraulics/actuator.h);
//   - passive: 0.
// No allocation, no exceptions; i is a tree index.

#include "solver/core/model.h"
#include "solver/core/state.h"

namespace solver {

/// True when joint i's acceleration is prescribed at `state` (see above).
bool isPrescribed(const Model& model, const State& state, int i);

/// A hydraulic drive's commanded rate in the modeler's coordinate [m/s or rad/s]:
/// u·vmax for u > 0, u·vmin for u < 0, 0 for u = 0 (u clamped to [−1, 1]).
double hydraulicCommandRate(const CompiledDrive& drive, double u);

/// The θ̇ a prescribed joint must have [rad/s or m/s]: 0 at a limit; q̇_cmd / (dq/dθ)
/// for a hydraulic drive with the relief closed (0 at a dead point of a T 1, where
/// dL/dθ = 0); for other joints, state.qd[i] unchanged. The integrator resets θ̇ to
/// it when a command, a relief valve or a limit changes.
double prescribedRate(const Model& model, const State& state, int i);

/// The θ̈ of a prescribed joint with the command held [rad/s^2 or m/s^2], from
/// state.qd[i]: 0, or −L''θ̇²/L' for a hydraulic T 1 joint with the relief closed.
double prescribedAcceleration(const Model& model, const State& state, int i);
/// The same with joint i's coordinate map at state.q[i] already computed.
double prescribedAcceleration(const Model& model, const State& state, int i, const CoordinateMap& map);

/// The servo's set-point in the modeler's coordinate for command u (clamped to [−1, 1]).
double servoSetPoint(const CompiledDrive& drive, double u);

/// The servo's error e = set-point − q at `state` (the integrand of State::servoIntegral);
/// 0 for a joint without a servo.
double servoError(const Model& model, const State& state, int i);

/// The drive's own force in the modeler's coordinate [N or N m] for a force-driven
/// drive (motor, pneumatic, servo, hydraulic with the relief open); 0 for a passive
/// joint and for a hydraulic drive with the relief closed (its force is what the
/// dynamics find). The law is applied whether or not the joint is at a limit.
double driveForceLaw(const Model& model, const State& state, int i);
/// The same with joint i's coordinate map at state.q[i] already computed.
double driveForceLaw(const Model& model, const State& state, int i, const CoordinateMap& map);

}  // namespace solver
