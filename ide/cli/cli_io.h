#pragma once
// What the `padrob` commands share: output, the usage error, reading numbers.

#include "solver/core/model.h"

#include <memory>
#include <optional>
#include <string>

namespace ide::cli {

inline constexpr int kExitOk = 0, kExitModelErrors = 1, kExitUsage = 2;

void printOut(const std::string& s);
void printErr(const std::string& s);
/// Prints "padrob COMMAND: MESSAGE" and `tryHelp` (the command's translated "Try 'padrob
/// COMMAND --help'.") on standard error; returns kExitUsage.
int usageError(const std::string& command, const std::string& message, const std::string& tryHelp);
/// A finite number that is the whole of `s` ('.' as the decimal point, whatever the
/// locale; a leading '+' allowed), else nullopt.
std::optional<double> toNumber(const std::string& s);

/// Loads and compiles the model file `path`, printing its errors (and an unreadable
/// file's io-error) on standard error. nullptr with `status` kExitUsage (unreadable) or
/// kExitModelErrors (errors in the model) when it cannot.
std::shared_ptr<const solver::Model> loadAndCompile(const std::string& path, int& status);

}  // namespace ide::cli
