#pragma once
// `padrob tutorial FILE [--input LOG | --demo | --autopilot PATH --record OUT] [--json]`
// (docs/cli.md, docs/training.md).

#include <string>
#include <vector>

namespace ide::cli {

/// Exit status: 0 checked fine or passed, 1 failed, 2 bad input.
int runTutorial(const std::vector<std::string>& args);

}  // namespace ide::cli
