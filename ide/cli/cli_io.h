#pragma once
// What the `padrob` commands share: output, the usage error, reading and writing numbers,
// filling translated templates.
//
// Texts a person reads are written i18n::trStd("padrob", "…") at the place they are used
// (one context for the whole CLI; lupdate reads the literal there), sentences as one
// template with %1, %2… filled by fill(), counts as plurals (trStd(…, nullptr, n) with %n).
// Numbers are written with '.' in both languages (scripts read them, and commands take
// them with '.'): num() and fixed() do not depend on the locale.

#include "solver/core/diagnostic.h"
#include "solver/core/model.h"
#include "solver/pipeline.h"
#include "solver/spec/model_spec.h"

#include <cstdio>
#include <initializer_list>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace ide::cli {

inline constexpr int kExitOk = 0, kExitModelErrors = 1, kExitUsage = 2;

void printOut(const std::string& s);
void printErr(const std::string& s);
/// Prints "padrob COMMAND: MESSAGE" and "Try 'padrob COMMAND --help'." (translated) on
/// standard error; returns kExitUsage.
int usageError(const std::string& command, const std::string& message);
/// A finite number that is the whole of `s` ('.' as the decimal point, whatever the
/// locale; a leading '+' allowed), else nullopt.
std::optional<double> toNumber(const std::string& s);

/// `tmpl` with %1 … %9 replaced by `args` in one pass (a value that holds "%2" is left
/// as it is); a %N without an argument stays.
std::string fill(std::string_view tmpl, std::initializer_list<std::string_view> args);
/// `v` with `digits` significant digits, shortest form ("0" for zero, "1e-08"), '.'
/// whatever the locale.
std::string num(double v, int digits = 6);
/// `v` with `decimals` digits after the '.', whatever the locale.
std::string fixed(double v, int decimals);
/// `s` padded with blanks to `width` characters (code points, not bytes: translated texts
/// hold accents), left-aligned, or right-aligned when `right`.
std::string pad(const std::string& s, std::size_t width, bool right = false);

/// Prints a diagnostic on `f` as "file:line:col: error: message [hint]" in the current
/// language (i18n::format).
void printDiagnostic(std::FILE* f, const solver::Diagnostic& d);

/// Reads and compiles a scene file (`--scene`: ground graphics), printing its errors on
/// standard error. Nothing with `status` kExitUsage (unreadable) or kExitModelErrors.
std::optional<solver::CompiledModel> loadScene(const std::string& path, int& status);

/// Loads and compiles the model file `path`, printing its errors (and an unreadable
/// file's io-error) on standard error. nullptr with `status` kExitUsage (unreadable) or
/// kExitModelErrors (errors in the model) when it cannot.
std::shared_ptr<const solver::Model> loadAndCompile(const std::string& path, int& status);
/// The same, with the spec changed by `edit` before it is checked and compiled (command-line
/// overrides such as --set and --rate: checked as if they were written in the file). `edit`
/// returns "" or a usage error (e.g. a joint the model lacks), printed with status kExitUsage.
/// With `scene`, the model's solids touch the scene's ground graphics under CONTACT
/// (solver::compileSpec).
std::shared_ptr<const solver::Model> loadAndCompile(const std::string& path, int& status,
                                                    const std::function<std::string(solver::ModelSpec&)>& edit,
                                                    const solver::ModelSpec* scene = nullptr);

}  // namespace ide::cli
