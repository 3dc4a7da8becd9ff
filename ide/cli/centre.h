#pragma once
// padrob station / padrob instructor / padrob centre: the training centre's headless
// nodes (docs/training-centre.md).

#include <string>
#include <vector>

namespace ide::cli {

int runStation(const std::vector<std::string>& args);
int runInstructor(const std::vector<std::string>& args);
int runCentre(const std::vector<std::string>& args);

}  // namespace ide::cli
