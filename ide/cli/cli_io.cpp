#include "ide/cli/cli_io.h"

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

}  // namespace ide::cli
