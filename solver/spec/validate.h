#pragma once
// Checks that relate a model's statements to each other and check their values
// (MODEL_LANGUAGE.md "Checks"): duplicate ids, references to undefined bodies and
// joints, joint lines, axes, limits, initial values, masses and inertias, drives,
// forces and graphics. The checks that need the model's geometry as a whole
// (connectivity, T 1 reach, loops, mass moved) are in solver/compile/topology.h.

#include "solver/core/diagnostic.h"
#include "solver/spec/model_spec.h"

namespace solver {

/// Tolerance on |A·R| (after normalising) above which A and R are "not perpendicular".
inline constexpr double kPerpendicularTolerance = 1e-6;

/// Most bodies and most joints a model may have (a real-time simulator of more
/// would not run in real time; the checks stay fast below it).
inline constexpr std::size_t kMaxBodies = 10000;
inline constexpr std::size_t kMaxJoints = 10000;

/// Adds the diagnostics of every check to `diags`. Statements the parser marked
/// incomplete are skipped where their values would only produce follow-up noise.
/// `baseDir` resolves MESH paths (empty: mesh files are not looked for).
void validateModel(const ModelSpec& spec, Diagnostics& diags, const std::string& baseDir = {});

}  // namespace solver
