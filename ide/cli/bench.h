#pragma once
// `padrob bench MODEL …` (docs/cli.md, docs/performance.md): timings of the solver on a
// model — forward dynamics, RK4 steps with drives, limits and reactions, the real-time
// factor at 1 ms, the thesis's reference Newton–Euler system, scaling with the number
// of bodies, and MuJoCo side by side when the build has it.

#include <string>
#include <vector>

namespace ide::cli {

std::string benchHelp();
/// Runs the command; returns the exit status (0 ok, 1 model errors or a failed run,
/// 2 usage error or unreadable input).
int runBench(const std::vector<std::string>& args);

}  // namespace ide::cli
