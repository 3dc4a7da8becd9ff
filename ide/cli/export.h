#pragma once
// `padrob export --mjcf MODEL [--out FILE] [--dt H] [--check]` (docs/cli.md): a tree
// model without loops as MuJoCo's MJCF (solver/io/mjcf.h), for MuJoCo users and for
// `padrob bench`'s side-by-side comparison. --out writes through a temporary file
// renamed onto the target (QSaveFile): nothing half-written is ever left. --check
// loads the MJCF into MuJoCo in this process and checks it follows Padrob for 0.2 s
// (runMujoco, ide/cli/mujoco_bench.h); in a padrob built without MuJoCo it is a usage
// error (exit 2).

#include <string>
#include <vector>

namespace ide::cli {

std::string exportHelp();
/// Runs the command; returns the exit status (0 ok, 1 model errors or a model that
/// cannot be exported, 2 usage error or unreadable input).
int runExport(const std::vector<std::string>& args);

}  // namespace ide::cli
