// padrob — the headless front end: check, describe, simulate models, compute their
// inertias, time the solver (bench) and export to MJCF, and run tutorials. Exit codes:
// 0 success, 1 the model has errors (or a simulation failed), 2 usage error or
// unreadable file.

#include "ide/cli/bench.h"
#include "ide/cli/export.h"
#include "ide/cli/inertia.h"
#include "ide/cli/info_report.h"
#include "ide/cli/simulate.h"
#include "ide/cli/tutorial.h"
#include "solver/model/load.h"

#include <QCoreApplication>

#include <cstdio>
#include <string>
#include <vector>

namespace {

std::string tr(const char* s) { return QCoreApplication::translate("padrob", s).toStdString(); }

constexpr int kOk = 0, kModelErrors = 1, kUsage = 2;

void print(std::FILE* f, const std::string& s) { std::fwrite(s.data(), 1, s.size(), f); }

std::string mainHelp()
{
    return tr("Usage: padrob COMMAND [OPTIONS] [ARGS]\n"
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
              "\n"
              "Options:\n"
              "  -h, --help            show this help (or a command's: padrob COMMAND --help)\n"
              "  --version             show the version\n"
              "\n"
              "Exit status: 0 success, 1 the model has errors, 2 usage error or unreadable file.\n");
}

std::string checkHelp()
{
    return tr("Usage: padrob check MODEL...\n"
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
    return tr("Usage: padrob info MODEL [--json]\n"
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
int report(const solver::LoadedModel& m, std::FILE* f)
{
    bool io = false;
    for (const solver::Diagnostic& d : m.diagnostics) {
        print(f, d.format() + "\n");
        if (d.code == "io-error") io = true;
    }
    if (io) return kUsage;
    return m.ok() ? kOk : kModelErrors;
}

int runCheck(const std::vector<std::string>& args)
{
    std::vector<std::string> files;
    for (const std::string& a : args) {
        if (isHelp(a)) {
            print(stdout, checkHelp());
            return kOk;
        }
        if (a.size() > 1 && a[0] == '-') {
            print(stderr, tr("padrob check: unknown option '") + a + "'\n" + tr("Try 'padrob check --help'.") + "\n");
            return kUsage;
        }
        files.push_back(a);
    }
    if (files.empty()) {
        print(stderr, tr("padrob check: no model given") + "\n" + tr("Try 'padrob check --help'.") + "\n");
        return kUsage;
    }
    int status = kOk;
    for (const std::string& file : files) {
        solver::LoadedModel m = solver::loadModelFile(file);
        int s = report(m, stdout);
        status = std::max(status, s);
        if (s == kUsage) continue;
        std::string summary = file + ": ";
        if (m.ok()) summary += tr("ok");
        else summary += std::to_string(m.diagnostics.errorCount()) + " " + tr(m.diagnostics.errorCount() == 1 ? "error" : "errors");
        if (m.diagnostics.warningCount() > 0) {
            summary += (m.ok() ? " (" : ", ") + std::to_string(m.diagnostics.warningCount()) + " " +
                       tr(m.diagnostics.warningCount() == 1 ? "warning" : "warnings") + (m.ok() ? ")" : "");
        }
        print(stdout, summary + "\n");
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
            print(stderr, tr("padrob info: unknown option '") + a + "'\n" + tr("Try 'padrob info --help'.") + "\n");
            return kUsage;
        } else files.push_back(a);
    }
    if (files.size() != 1) {
        print(stderr, tr(files.empty() ? "padrob info: no model given" : "padrob info: give one model") + std::string("\n") +
                          tr("Try 'padrob info --help'.") + "\n");
        return kUsage;
    }
    solver::LoadedModel m = solver::loadModelFile(files[0]);
    if (!m.ok() || !m.topology) {
        int s = report(m, stderr);
        return s == kOk ? kModelErrors : s;
    }
    print(stdout, json ? ide::cli::infoJson(m) : ide::cli::infoText(m));
    if (!json) {
        for (const solver::Diagnostic& d : m.diagnostics) print(stderr, d.format() + "\n");
    }
    return kOk;
}

}  // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName("padrob");
    QCoreApplication::setApplicationVersion(PADROB_VERSION);
    std::vector<std::string> args(argv + 1, argv + argc);
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
    print(stderr, tr("padrob: unknown command '") + cmd + "'\n" + tr("Try 'padrob --help'.") + "\n");
    return kUsage;
}
