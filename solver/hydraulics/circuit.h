#pragma once
// The fluid-power part of one evaluation (docs/hydraulics.md): every pump's operating
// point, then every circuit's valve flows, relief flows, chamber pressure rates and
// spool rate, into Data's fluid-power fields (fluidRate: d/dt State::fluid). The drive
// force each circuit puts on its joint is drives.h's driveForceLaw (actuator.h). The
// joints' rates in the modeler's coordinate are q̇ = dq/dθ·θ̇ (Data::dq is not needed:
// the coordinate maps are taken here). No allocation; nothing when there are no circuits.

#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/core/state.h"

namespace solver::hydraulics {

void evaluateHydraulics(const Model& model, const State& state, Data& data);

/// The number of equal sub-steps the real-time RK4 step h needs at the state `data`
/// was last evaluated at, so that the stiffest fluid mode stays well inside its
/// stability region and the oil spring is resolved (docs/hydraulics.md "Real time"):
///   n = ⌈max(λ·h / 1.8, ω·h / 0.6)⌉ (at most kMaxSubsteps), λ = Data::fluidDecay,
///   ω = √(oil stiffness / effective mass) with the effective mass of each driven
///   joint from the articulated-body inertia D (Data::D, in the modeler's coordinate).
int substeps(const Model& model, const State& state, const Data& data, double h);
inline constexpr int kMaxSubsteps = 64;

/// The oil spring's ω·h the fixed step is kept at or below (by inertiaFloor, then by
/// substeps).
inline constexpr double kOilSpringStep = 0.6;

/// With Data::oilSpringStep = h > 0, evaluateHydraulics sets each fluid-power joint's
/// Data::inertiaFloor to k·(h/kOilSpringStep)², k its oil stiffness there: the least
/// inertia along q for its oil spring to stay resolved at the fixed step. The dynamics
/// add the difference as an armature where the joint's own articulated inertia is
/// below it: an actuator's moving mass (piston, rod, oil) that a model of light parts
/// (a 2 kg claw) leaves out, and without which a 1 ms step would need a dozen
/// sub-steps for a kilohertz oscillation nobody feels.

}  // namespace solver::hydraulics
