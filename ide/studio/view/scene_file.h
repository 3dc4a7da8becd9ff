#pragma once
// Scene files: a model file whose ground graphics (G … B 0) are drawn around the
// model in the viewport (ViewportLayout::setScene), e.g. resources/scenes/sag_mill.pad,
// the SAG mill the liner manipulator works in. Any model file will do; only its
// ground graphics are drawn (never simulated, highlighted or framed by Fit All).

#include "ide/studio/model/model_bundle.h"

#include <QString>

#include <memory>

namespace studio {

/// A scene file as read: its bundle, or why it cannot be used.
struct SceneFile {
    std::shared_ptr<const ModelBundle> bundle;  ///< nullptr when it cannot be used
    QString error;  ///< why not (translated; the first diagnostics, one a line)
    QString note;   ///< something to know when it loaded (graphics on moving bodies not drawn)
};

/// Reads, loads and compiles `path` as a scene. It fails when the file cannot be read,
/// has errors, or has no ground graphics to draw.
SceneFile loadSceneFile(const QString& path);

}  // namespace studio
