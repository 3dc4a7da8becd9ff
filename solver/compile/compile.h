#pragma once
// Compile: a loaded ModelSpec and its Topology → the immutable Model the solver
// runs (solver/core/model.h, whose header documents the numbering, coordinates and
// frames).
//
// What it does, in order:
//   1. tree-order numbering: body i is the child of Topology::treeJoints[i], so
//      parents come before children; parent[i] is a tree index or −1 (ground);
//   2. joint frames: X_pj/X_cj from the parent-side and child-side joint frames
//      (A normalised, R orthogonalised, T = A × R; joint_geometry.h), axisSign −1
//      for a joint the modeler wrote child → parent (Topology::reversed);
//   3. bodies: mass, centre of mass (CG, or the frame origin) and inertia tensor
//      about it; a massless body gets zeros;
//   4. T 1 joints: the length law L²(θ) and the actuator ends CL1/CL2;
//   5. limits on θ: LL/UL as written for T 0/T 2; for T 1 the lengths are turned
//      into angles on θ0's monotonic branch of L(θ) (the branch rule of
//      MODEL_LANGUAGE.md: θ0 is the angle nearest to 0) and ordered so that
//      lower ≤ upper, since dL/dθ may be negative;
//   6. drives (DriveSpec → CompiledDrive): HYD by DriveSpec::hydraulic(), MOTOR
//      T0/W0, PNEU F, SERVO KP/KI/KD/FMAX with the set-point range [LL, UL]
//      ([−π, π] without limits; for T 1 without limits, the reachable lengths);
//   7. forces (ForceSpec → CompiledForce): bodies and joints as tree indices (−1 =
//      ground), DIR normalised, TABLE Q's joint as a tree index;
//   8. initial θ from Topology::theta0, θ̇ from VI (T 1: θ̇ = VI / (dL/dθ)).
//
//   9. loop-closure (cut) joints into Model::cuts (their two bodies and frames),
//      dependent coordinates flagged, Model::lengthScale the largest distance of a
//      joint point from its body's origin. A drive on a cut joint is an error
//      "loop-joint-driven" (nullptr); limits on one are ignored with a warning
//      "loop-joint-limits-ignored".

#include "solver/compile/topology.h"
#include "solver/core/diagnostic.h"
#include "solver/core/model.h"
#include "solver/model/load.h"
#include "solver/model/model_spec.h"

#include <memory>

namespace solver {

/// Compiles a model that loaded without errors (spec checked, `topology` from
/// analyzeTopology). Returns nullptr, after adding its errors to `diags`, when the
/// model cannot be simulated.
std::shared_ptr<const Model> compileModel(const ModelSpec& spec, const Topology& topology,
                                          Diagnostics& diags);

/// compileModel on a LoadedModel. A model that did not load (errors, no topology)
/// gives nullptr and adds nothing to `diags`: its errors are in loaded.diagnostics.
std::shared_ptr<const Model> compileLoaded(const LoadedModel& loaded, Diagnostics& diags);

}  // namespace solver
