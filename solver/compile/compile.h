#pragma once
// Compile: a checked ModelSpec → the immutable Model the solver runs
// (solver/core/model.h, whose header documents the numbering, coordinates and
// frames), with the global checks that need the geometry. Most callers want the
// whole pipeline instead (solver/pipeline.h: compileFile, compileText).
//
// What it does, in order:
//   1. the graph (analyzeTopology, topology.h): spanning tree, cut joints, chains,
//      bodies that ground does not reach;
//   2. T 1 joints: lengths reachable, not constant, no dead point inside the stroke;
//      the initial guess of every coordinate (QI, or the middle of a T 1 stroke);
//   3. a drive on a cut joint is an error "loop-joint-driven"; limits on one are
//      ignored with a warning "loop-joint-limits-ignored";
//   4. tree-order numbering: body i is the child of Topology::treeJoints[i], so
//      parents come before children; parent[i] is a tree index or −1 (ground);
//      joint frames X_pj/X_cj from the parent-side and child-side joint frames
//      (A normalised, R orthogonalised, T = A × R; kinematics/joint_geometry.h),
//      axisSign −1 for a joint the modeler wrote child → parent; bodies (mass,
//      centre of mass, inertia about it; a massless body gets zeros); T 1 length
//      laws and ends; drives (HYD by DriveSpec::hydraulic(), MOTOR T0/W0, PNEU F,
//      SERVO KP/KI/KD/FMAX with the set-point range [LL, UL]); forces (bodies and
//      joints as tree indices, DIR normalised, TABLE Q's joint as a tree index);
//      cut joints into Model::cuts; Model::lengthScale;
//   5. the initial configuration, on the compiled model with the one constraint
//      implementation (solver/dynamics/constraints.h): the rank of the loops, which
//      coordinates are dependent, the loops closed at QI by assembleLoops (an error
//      "loop-unsatisfiable" when they cannot be); θ0, and θ̇0 from VI;
//   6. limits on θ: LL/UL as written for T 0/T 2; for T 1 the lengths turned into
//      angles on θ0's monotonic branch of L(θ) (MODEL_LANGUAGE.md: θ0 is the angle
//      nearest to 0), ordered so that lower ≤ upper, since dL/dθ may be negative;
//   7. every joint (or loop) moves mass: the mass matrix of the compiled model at θ0
//      on the independent coordinates is not singular ("joint-moves-no-mass");
//   8. with CONTACT, the contact model (contact/contact_geometry.h): the shapes of the
//      graphics and of `scene`'s ground graphics, the pairs that never touch.

#include "solver/compile/topology.h"
#include "solver/core/diagnostic.h"
#include "solver/core/model.h"
#include "solver/spec/model_spec.h"

#include <memory>
#include <optional>

namespace solver {

struct CompileResult {
    /// The graph and the initial configuration; set only when there are no errors.
    std::optional<Topology> topology;
    /// The compiled model; set only when there are no errors.
    std::shared_ptr<const Model> model;
};

/// Compiles a spec that passed the local checks (solver/spec/validate.h) without
/// errors. Adds its diagnostics to `diags`; a model with any error (this stage's)
/// gets neither topology nor model: nothing is half-compiled. `scene` (may be null):
/// a scene whose ground graphics the model's solids touch under CONTACT.
CompileResult compileModel(const ModelSpec& spec, Diagnostics& diags, const ModelSpec* scene = nullptr);

}  // namespace solver
