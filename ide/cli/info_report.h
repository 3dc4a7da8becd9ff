#pragma once
// `padrob info`: what a loaded model is — bodies, joints, the spanning tree and
// loop closures, chains, degrees of freedom, total mass — as text or as JSON
// (the JSON format is documented in docs/cli.md and is stable).

#include "solver/pipeline.h"

#include <string>

namespace ide::cli {

/// Human-readable report of a model that loaded without errors.
std::string infoText(const solver::CompiledModel& model);

/// JSON report (format "padrob-info", version 1) of a model that loaded without errors.
std::string infoJson(const solver::CompiledModel& model);

}  // namespace ide::cli
