// padrob — the headless front end: check, describe, simulate models, compute their
// inertias, time the solver (bench) and export to MJCF, and run tutorials. Exit codes:
// 0 success, 1 the model has errors (or a simulation failed), 2 usage error or
// unreadable file.

#include "ide/cli/bench.h"
#include "ide/cli/cli_io.h"
#include "ide/cli/export.h"
#include "ide/cli/inertia.h"
#include "ide/cli/info_report.h"
#include "ide/cli/simulate.h"
#include "ide/cli/tutorial.h"
#ifdef PADROB_HAVE_DDS
#include "ide/cli/centre.h"
#endif
#include "ide/i18n/language.h"
#include "solver/pipeline.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>
#include <clocale>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using i18n::trStd;
using ide::cli::fill;
using ide::cli::printDiagnostic;

constexpr int kOk = 0, kModelErrors = 1, kUsage = 2;

void print(std::FILE* f, const std::string& s) { std::fwrite(s.data(), 1, s.size(), f); }

std::string mainHelp()
{
    return trStd("padrob",
                 "Usage: padrob COMMAND [OPTIONS] [ARGS]\n"
                 "\n"
                 "Padrob builds real-time training simulators of machines from model files (.pad).\n"
                 "\n"
                 "Commands:\n"
                 "  check MODEL...        check models and print their problems\n"
                 "  info MODEL [--json]   describe a model: bodies, joints, chains, degrees of freedom\n"
                 "  simulate MODEL --time T [OPTIONS]\n"
                 "                        simulate a model and write its trajectory as CSV\n"
                 "  inertia MODEL [--body I] [--write]\n"
                 "                        compute bodies' mass and inertia from their solids\n"
                 "  bench MODEL [OPTIONS]  time the solver on a model (and MuJoCo, when built in)\n"
                 "  export --mjcf MODEL [--out FILE]\n"
                 "                        write a tree model as MuJoCo's MJCF\n"
                 "  tutorial FILE [--input LOG | --demo] [--json]\n"
                 "                        check a tutorial, or run it against an input log and score it\n"
                 "  station TUTORIAL... --name NAME\n"
                 "                        a training station without a window on the centre's network\n"
                 "  instructor list|watch|send\n"
                 "                        the training centre's stations: list, watch and command them\n"
                 "  centre key|seal|bench the training centre's key, sealed secrets, scale benchmark\n"
                 "\n"
                 "Options:\n"
                 "  -h, --help            show this help (or a command's: padrob COMMAND --help)\n"
                 "  --version             show the version\n"
                 "  --lang es|en          language of the messages, with any command (default: the\n"
                 "                        system's: LANGUAGE, LC_ALL, LC_MESSAGES or LANG)\n"
                 "\n"
                 "Exit status: 0 success, 1 the model has errors, 2 usage error or unreadable file.\n");
}

std::string checkHelp()
{
    return trStd("padrob",
                 "Usage: padrob check MODEL...\n"
                 "\n"
                 "Reads each model file and prints every problem found, one per line, as\n"
                 "  file:line:column: error|warning: message [hint]\n"
                 "(the format compilers use, so editors can jump to each problem), then a summary.\n"
                 "\n"
                 "Exit status: 0 when no model has errors (warnings are allowed), 1 when some model\n"
                 "has errors, 2 on a usage error or when a file cannot be read.\n");
}

std::string infoHelp()
{
    return trStd("padrob",
                 "Usage: padrob info MODEL [--json]\n"
                 "\n"
                 "Describes a model: its bodies (mass, inertia), joints (type, bodies, limits,\n"
                 "initial value, drive), the spanning tree from ground, the loop-closure joints,\n"
                 "the kinematic chains, the degrees of freedom and which coordinates are\n"
                 "independent or dependent, and the total mass.\n"
                 "\n"
                 "  --json   print one JSON object instead (format \"padrob-info\", version 1;\n"
                 "           documented in docs/cli.md)\n"
                 "\n"
                 "A model with errors is not described: its problems are printed as by\n"
                 "'padrob check' and the exit status is 1 (2 if the file cannot be read).\n");
}

bool isHelp(const std::string& a) { return a == "-h" || a == "--help"; }

/// Prints a model's diagnostics; returns the exit status it deserves.
int report(const solver::CompiledModel& m, std::FILE* f)
{
    bool io = false;
    for (const solver::Diagnostic& d : m.diagnostics) {
        printDiagnostic(f, d);
        if (d.code == "io-error") io = true;
    }
    if (io) return kUsage;
    return m.ok() ? kOk : kModelErrors;
}

/// The summary line of `padrob check` for one file: "FILE: ok", "FILE: ok (N warnings)",
/// "FILE: N errors, M warnings".
std::string checkSummary(const std::string& file, const solver::CompiledModel& m)
{
    const int errors = static_cast<int>(m.diagnostics.errorCount());
    const int warnings = static_cast<int>(m.diagnostics.warningCount());
    const std::string w = trStd("padrob", "%n warning(s)", nullptr, warnings);
    if (m.ok()) {
        return warnings > 0 ? fill(trStd("padrob", "%1: ok (%2)"), {file, w}) : fill(trStd("padrob", "%1: ok"), {file});
    }
    const std::string e = trStd("padrob", "%n error(s)", nullptr, errors);
    return warnings > 0 ? file + ": " + e + ", " + w : file + ": " + e;
}

int runCheck(const std::vector<std::string>& args)
{
    std::vector<std::string> files;
    for (const std::string& a : args) {
        if (isHelp(a)) {
            print(stdout, checkHelp());
            return kOk;
        }
        if (a.size() > 1 && a[0] == '-') return ide::cli::usageError("check", fill(trStd("padrob", "unknown option '%1'"), {a}));
        files.push_back(a);
    }
    if (files.empty()) return ide::cli::usageError("check", trStd("padrob", "no model given"));
    int status = kOk;
    for (const std::string& file : files) {
        solver::CompiledModel m = solver::compileFile(file);
        int s = report(m, stdout);
        status = std::max(status, s);
        if (s == kUsage) continue;
        print(stdout, checkSummary(file, m) + "\n");
    }
    return status;
}

int runInfo(const std::vector<std::string>& args)
{
    bool json = false;
    std::vector<std::string> files;
    for (const std::string& a : args) {
        if (isHelp(a)) {
            print(stdout, infoHelp());
            return kOk;
        }
        if (a == "--json") json = true;
        else if (a.size() > 1 && a[0] == '-') {
            return ide::cli::usageError("info", fill(trStd("padrob", "unknown option '%1'"), {a}));
        } else files.push_back(a);
    }
    if (files.empty()) return ide::cli::usageError("info", trStd("padrob", "no model given"));
    if (files.size() != 1) return ide::cli::usageError("info", trStd("padrob", "give one model"));
    solver::CompiledModel m = solver::compileFile(files[0]);
    if (!m.ok() || !m.topology) {
        int s = report(m, stderr);
        return s == kOk ? kModelErrors : s;
    }
    print(stdout, json ? ide::cli::infoJson(m) : ide::cli::infoText(m));
    if (!json) {
        for (const solver::Diagnostic& d : m.diagnostics) printDiagnostic(stderr, d);
    }
    return kOk;
}

/// Takes the global option --lang es|en (or --lang=es) out of `args`, wherever it is.
/// Returns false with `problem` set when it has no value or an unknown one; `lang` is ""
/// when it was not given.
bool takeLanguage(std::vector<std::string>& args, std::string& lang, std::string& problem)
{
    for (std::size_t i = 0; i < args.size();) {
        std::string value;
        if (args[i] == "--lang") {
            if (i + 1 >= args.size()) {
                problem = trStd("padrob", "--lang needs a value: es or en");
                return false;
            }
            value = args[i + 1];
            args.erase(args.begin() + static_cast<long>(i), args.begin() + static_cast<long>(i) + 2);
        } else if (args[i].rfind("--lang=", 0) == 0) {
            value = args[i].substr(7);
            args.erase(args.begin() + static_cast<long>(i));
        } else {
            ++i;
            continue;
        }
        if (!i18n::isLanguage(QString::fromStdString(value))) {
            problem = fill(trStd("padrob", "--lang must be es or en, not '%1'"), {value});
            return false;
        }
        lang = value;
    }
    return true;
}

}  // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName("padrob");
    QCoreApplication::setApplicationVersion(PADROB_VERSION);
    // Qt set the C library's locale from the environment: keep '.' in the numbers the C
    // functions write and read (printf in the solver's messages among them) under any
    // locale, es_CL's decimal comma included
    std::setlocale(LC_NUMERIC, "C");
    std::vector<std::string> args(argv + 1, argv + argc);
    std::string lang, langProblem;
    const bool langOk = takeLanguage(args, lang, langProblem);
    i18n::install(langOk && !lang.empty() ? QString::fromStdString(lang) : i18n::systemLanguage());
    // the texts in that language, every number still with '.' (docs/cli.md)
    QLocale::setDefault(QLocale::c());
    if (!langOk) {
        print(stderr, "padrob: " + langProblem + "\n" + trStd("padrob", "Try 'padrob --help'.") + "\n");
        return kUsage;
    }
    if (args.empty()) {
        print(stderr, mainHelp());
        return kUsage;
    }
    const std::string cmd = args[0];
    std::vector<std::string> rest(args.begin() + 1, args.end());
    if (isHelp(cmd)) {
        print(stdout, mainHelp());
        return kOk;
    }
    if (cmd == "--version" || cmd == "-V") {
        print(stdout, std::string("padrob ") + PADROB_VERSION + "\n");
        return kOk;
    }
    if (cmd == "check") return runCheck(rest);
    if (cmd == "info") return runInfo(rest);
    if (cmd == "simulate") return ide::cli::runSimulate(rest);
    if (cmd == "inertia") return ide::cli::runInertia(rest);
    if (cmd == "bench") return ide::cli::runBench(rest);
    if (cmd == "export") return ide::cli::runExport(rest);
    if (cmd == "tutorial") return ide::cli::runTutorial(rest);
#ifdef PADROB_HAVE_DDS
    if (cmd == "station") return ide::cli::runStation(rest);
    if (cmd == "instructor") return ide::cli::runInstructor(rest);
    if (cmd == "centre") return ide::cli::runCentre(rest);
#endif
    print(stderr, "padrob: " + fill(trStd("padrob", "unknown command '%1'"), {cmd}) + "\n" +
                      trStd("padrob", "Try 'padrob --help'.") + "\n");
    return kUsage;
}
