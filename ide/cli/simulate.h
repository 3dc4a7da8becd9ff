#pragma once
// `padrob simulate MODEL --time T …` (docs/cli.md).

#include <string>
#include <vector>

namespace ide::cli {

std::string simulateHelp();
/// Runs the command; returns the exit status (0 ok, 1 model errors or a failed
/// simulation, 2 usage error or unreadable input).
int runSimulate(const std::vector<std::string>& args);

}  // namespace ide::cli
