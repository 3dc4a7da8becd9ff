#pragma once
// The pipeline: model text → the immutable Model the solver runs, in one entry
// point that every front end uses (padrob, padrob-studio, tutorials, the centre,
// the benchmarks and the tests):
//
//   file ──readTextFile──▶ bytes            solver/core/text_file.h   (size limit, folders refused)
//        ──decode──▶ UTF-8 text             solver/pipeline.cpp       (Latin-1 with a warning, binary refused)
//        ──parseModel──▶ ModelSpec          solver/parse/parser.h     (statements, source positions)
//        ──validateModel──▶ (checks)        solver/spec/validate.h    (references, values, local geometry)
//        ──compileModel──▶ Model            solver/compile/compile.h  (graph, numbering, frames, loops
//                                                                      closed at QI, mass check)
//
// A model with errors is never half-compiled: `topology` and `model` are only set
// when there are no errors, and nothing may simulate a CompiledModel whose ok() is
// false. Diagnostics are sorted by position.

#include "solver/compile/topology.h"
#include "solver/core/diagnostic.h"
#include "solver/core/model.h"
#include "solver/spec/model_spec.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace solver {

/// A model as loaded and compiled: what was written, what is wrong with it, and,
/// without errors, what the solver runs.
struct CompiledModel {
    ModelSpec spec;                      ///< as written (with source positions)
    Diagnostics diagnostics;             ///< every stage's, sorted by position
    std::optional<Topology> topology;    ///< set only when there are no errors
    std::shared_ptr<const Model> model;  ///< set only when there are no errors
    bool ok() const { return !diagnostics.hasErrors(); }
};

/// Compiles model text; `file` names it in diagnostics and is the base of mesh paths.
CompiledModel compileText(std::string_view text, const std::string& file = "<text>");

/// Reads and compiles a file. An unreadable file, a directory or a file over the size
/// limit gives one "io-error" diagnostic (position 0:0) and no model.
CompiledModel compileFile(const std::string& path);

/// Checks and compiles a spec built or changed in code (spec.file names it, and its
/// folder is the base of mesh paths): validate, then compile, as for text. With
/// CONTACT, the model's solids also touch `scene`'s ground graphics (may be null: a
/// `--scene` file or a tutorial's scene, already parsed; its meshes relative to its file).
CompiledModel compileSpec(ModelSpec spec, const ModelSpec* scene = nullptr);

/// Largest model file read, in bytes.
inline constexpr std::size_t kMaxModelFileBytes = 16u * 1024u * 1024u;

}  // namespace solver
