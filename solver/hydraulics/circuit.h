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

}  // namespace solver::hydraulics
