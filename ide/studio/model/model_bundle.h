#pragma once
// ModelBundle: one model that loaded and compiled without errors, shared read-only
// (std::shared_ptr<const ModelBundle>) by every part of padrob-studio: the
// viewport (graphics of the spec, frames of the compiled model), the model tree,
// the plots, the sliders and the solver thread. A model with errors never becomes
// a bundle: the widgets keep the last good one (DESIGN: nothing half-loaded).

#include "solver/core/model.h"
#include "solver/pipeline.h"

#include <QString>

#include <memory>

namespace studio {

struct ModelBundle {
    /// The model as written and compiled (solver/pipeline.h): statements with source
    /// positions, graphics (G), names, its topology (chains, loops, independent/dependent
    /// joints) and the compiled model. ok() is true.
    std::shared_ptr<const solver::CompiledModel> compiled;
    /// compiled->model: bodies and joints by tree index.
    std::shared_ptr<const solver::Model> model;
    /// The file it came from ("" when never saved): mesh paths are relative to its folder.
    QString filePath;
    /// Increases with every bundle made in this process: tells a new model from the same one.
    quint64 serial = 0;

    const solver::ModelSpec& spec() const { return compiled->spec; }
    const solver::Topology& topology() const { return *compiled->topology; }
};

/// Compiles `text` (named `filePath` in diagnostics and for mesh paths). On success
/// returns the bundle; on errors returns nullptr. Either way every diagnostic is
/// appended to `diagnostics`.
std::shared_ptr<const ModelBundle> makeBundle(const QString& text, const QString& filePath,
                                              solver::Diagnostics& diagnostics);

/// Reads and compiles the model file `filePath` (solver::compileFile: the size limit,
/// folders refused, encodings); as makeBundle otherwise.
std::shared_ptr<const ModelBundle> makeBundleFromFile(const QString& filePath, solver::Diagnostics& diagnostics);

/// A bundle of a model compiled elsewhere (a tutorial's, a scene built as a spec),
/// without compiling it again; nullptr when it has errors.
std::shared_ptr<const ModelBundle> makeBundle(std::shared_ptr<const solver::CompiledModel> compiled,
                                              const QString& filePath);

/// The model that runs in `scene`: under CONTACT its solids touch the scene's
/// (solver::compileSpec(spec, &scene), as the tutorials do; docs/contact.md), so it is
/// compiled again with them (the same bodies and joints); without CONTACT, or without a
/// scene, `model` itself. nullptr when it does not compile with the scene (its
/// diagnostics appended to `diagnostics`).
std::shared_ptr<const ModelBundle> bundleInScene(const std::shared_ptr<const ModelBundle>& model,
                                                 const ModelBundle* scene, solver::Diagnostics& diagnostics);

}  // namespace studio
