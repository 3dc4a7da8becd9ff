#include "ide/cli/cli_io.h"

#include "solver/compile/compile.h"
#include "solver/model/load.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace ide::cli {

void printOut(const std::string& s)
{
    std::fwrite(s.data(), 1, s.size(), stdout);
}

void printErr(const std::string& s)
{
    std::fwrite(s.data(), 1, s.size(), stderr);
}

int usageError(const std::string& command, const std::string& message, const std::string& tryHelp)
{
    printErr("padrob " + command + ": " + message + "\n" + tryHelp + "\n");
    return kExitUsage;
}

std::optional<double> toNumber(const std::string& s)
{
    double v = 0;
    const char* b = s.data();
    if (!s.empty() && s[0] == '+') ++b;
    auto [p, ec] = std::from_chars(b, s.data() + s.size(), v);
    if (ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::shared_ptr<const solver::Model> loadAndCompile(const std::string& path, int& status)
{
    const solver::LoadedModel loaded = solver::loadModelFile(path);
    bool io = false;
    for (const solver::Diagnostic& d : loaded.diagnostics) {
        if (d.severity == solver::Severity::Error || d.code == "io-error") printErr(d.format() + "\n");
        if (d.code == "io-error") io = true;
    }
    status = io ? kExitUsage : kExitModelErrors;
    if (io || !loaded.ok()) return nullptr;
    solver::Diagnostics compileDiags(path);
    std::shared_ptr<const solver::Model> model = solver::compileLoaded(loaded, compileDiags);
    for (const solver::Diagnostic& d : compileDiags) printErr(d.format() + "\n");
    if (model) status = kExitOk;
    return model;
}

}  // namespace ide::cli
