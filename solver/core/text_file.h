#pragma once
// Reading a whole text file with the checks every reader needs (missing, a folder,
// not a regular file, too large, unreadable), so the model loader and the input
// table report these the same way: one "io-error" diagnostic without position.

#include "solver/core/diagnostic.h"

#include <cstdint>
#include <optional>
#include <string>

namespace solver {

/// Reads `path` whole. On failure adds one "io-error" diagnostic (no position, the
/// file named `path`) to `diags` and returns nullopt. `fileKind` names what the file
/// should be, with its article (trText("Diagnostics", "a model file")); `extension` its
/// usual ending (".pad"); `tooLargeHint` says what to do with a file over `maxBytes`.
std::optional<std::string> readTextFile(const std::string& path, std::uintmax_t maxBytes, const Text& fileKind,
                                        const std::string& extension, const Text& tooLargeHint,
                                        Diagnostics& diags);

}  // namespace solver
