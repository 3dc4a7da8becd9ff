#pragma once
// Where Padrob's bundled files are: the models, the tutorials, the scenes and the docs.
//
// One rule for every program (padrob, padrob-studio) and every place, installed or built:
// the data is at ../share/padrob beside the executable's folder, the documentation at
// ../share/doc/padrob. An install (cmake --install, the .deb) puts the files there; a
// build tree has the same layout, its share/padrob/models, share/padrob/resources and
// share/doc/padrob being links into the source tree, made at configure time
// (ide/CMakeLists.txt). No path of the source tree is compiled into a program, so an
// installed one can never read the source tree, and a moved install still finds its files
// (docs/packaging.md).

#include <QString>

namespace paths {

// Every path is found from the executable's folder (<prefix>/bin), and is canonical (links
// resolved) when it exists.

/// <prefix>/share/padrob/models: the .pad models and their station profiles (NAME.station/).
QString modelsDir();
/// <prefix>/share/padrob/resources/tutorials: the tutorials, their demonstrations and
/// camera paths (a tutorial names its model as ../../models/NAME.pad).
QString tutorialsDir();
/// <prefix>/share/padrob/resources/scenes: the scenes drawn around a model (the SAG mill, a yard).
QString scenesDir();
/// <prefix>/share/doc/padrob: the documentation (model-language.md, the guides).
QString docsDir();
/// The model a program opens when given none: the fluid-power liner manipulator.
QString defaultModel();

}  // namespace paths
