#pragma once
// Parser of the model language (docs/model-language.md): text → ModelSpec.
//
// The parser checks what one statement can tell on its own (keywords, numbers,
// options, what a statement requires); the checks that relate statements to each
// other are in solver/spec/validate.h. All problems are collected.

#include "solver/core/diagnostic.h"
#include "solver/spec/model_spec.h"

#include <string_view>

namespace solver::parse {

/// Parses `text` (UTF-8) into a spec. Diagnostics are added to `diags`, whose
/// file name they carry. `spec.file` is left to the caller.
ModelSpec parseModel(std::string_view text, Diagnostics& diags);

}  // namespace solver::parse
