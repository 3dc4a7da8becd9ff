#include "ide/cli/cli_io.h"

#include "ide/i18n/diagnostic_text.h"
#include "ide/i18n/language.h"
#include "solver/pipeline.h"

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

int usageError(const std::string& command, const std::string& message)
{
    printErr("padrob " + command + ": " + message + "\n" +
             fill(i18n::trStd("padrob", "Try 'padrob %1 --help'."), {command}) + "\n");
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

std::string fill(std::string_view tmpl, std::initializer_list<std::string_view> args)
{
    std::string out;
    out.reserve(tmpl.size());
    for (std::size_t k = 0; k < tmpl.size(); ++k) {
        if (tmpl[k] == '%' && k + 1 < tmpl.size() && tmpl[k + 1] >= '1' && tmpl[k + 1] <= '9') {
            const std::size_t n = static_cast<std::size_t>(tmpl[k + 1] - '1');
            if (n < args.size()) {
                out += *(args.begin() + n);
                ++k;
                continue;
            }
        }
        out += tmpl[k];
    }
    return out;
}

std::string num(double v, int digits)
{
    if (v == 0) return "0";
    char buf[64];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits);
    return std::string(buf, p);
}

std::string fixed(double v, int decimals)
{
    char buf[400];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
    if (ec != std::errc()) return num(v);
    return std::string(buf, p);
}

std::string pad(const std::string& s, std::size_t width, bool right)
{
    std::size_t chars = 0;
    for (unsigned char c : s) chars += (c & 0xC0) != 0x80;
    const std::string fill(chars < width ? width - chars : 0, ' ');
    return right ? fill + s : s + fill;
}

void printDiagnostic(std::FILE* f, const solver::Diagnostic& d)
{
    const std::string line = i18n::format(d) + "\n";
    std::fwrite(line.data(), 1, line.size(), f);
}

std::optional<solver::CompiledModel> loadScene(const std::string& path, int& status)
{
    solver::CompiledModel scene = solver::compileFile(path);
    if (scene.ok()) return scene;
    for (const solver::Diagnostic& d : scene.diagnostics)
        if (d.severity == solver::Severity::Error) printDiagnostic(stderr, d);
    status = scene.diagnostics.begin()->code == "io-error" ? kExitUsage : kExitModelErrors;
    return std::nullopt;
}

std::shared_ptr<const solver::Model> loadAndCompile(const std::string& path, int& status)
{
    return loadAndCompile(path, status, nullptr);
}

std::shared_ptr<const solver::Model> loadAndCompile(const std::string& path, int& status,
                                                    const std::function<std::string(solver::ModelSpec&)>& edit,
                                                    const solver::ModelSpec* scene)
{
    solver::CompiledModel compiled = solver::compileFile(path);
    if ((edit || scene) && compiled.ok()) {
        solver::ModelSpec spec = compiled.spec;
        if (const std::string why = edit ? edit(spec) : std::string(); !why.empty()) {
            printErr(why + "\n");
            status = kExitUsage;
            return nullptr;
        }
        compiled = solver::compileSpec(std::move(spec), scene);
        if (!compiled.ok()) {
            // the file is fine: the command line's values are what does not fit
            printErr(i18n::trStd("padrob", "the values given on the command line do not fit the model:") + "\n");
            for (const solver::Diagnostic& d : compiled.diagnostics)
                if (d.severity == solver::Severity::Error) printDiagnostic(stderr, d);
            status = kExitUsage;
            return nullptr;
        }
    }
    bool io = false;
    for (const solver::Diagnostic& d : compiled.diagnostics) {
        if (d.severity == solver::Severity::Error || d.code == "io-error") printDiagnostic(stderr, d);
        if (d.code == "io-error") io = true;
    }
    status = io ? kExitUsage : kExitModelErrors;
    if (io || !compiled.model) return nullptr;
    status = kExitOk;
    return compiled.model;
}

}  // namespace ide::cli
