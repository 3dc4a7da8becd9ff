#pragma once
// Loading a model: read → decode → parse → check → analyse.
//
// A model with errors is never half-loaded: `topology` is only set when there are
// no errors, and callers must not simulate a model whose `ok()` is false.

#include "solver/compile/topology.h"
#include "solver/core/diagnostic.h"
#include "solver/model/model_spec.h"

#include <optional>
#include <string>
#include <string_view>

namespace solver {

struct LoadedModel {
    ModelSpec spec;
    Diagnostics diagnostics;
    std::optional<Topology> topology;  ///< set only when there are no errors
    bool ok() const { return !diagnostics.hasErrors(); }
};

/// Loads model text; `file` names it in diagnostics and is the base of mesh paths.
LoadedModel loadModelText(std::string_view text, const std::string& file = "<text>");

/// Reads and loads a file. An unreadable file, a directory or a file over the size
/// limit gives one "io-error" diagnostic (position 0:0) and no model.
LoadedModel loadModelFile(const std::string& path);

/// Largest model file read, in bytes.
inline constexpr std::size_t kMaxModelFileBytes = 16u * 1024u * 1024u;

}  // namespace solver
