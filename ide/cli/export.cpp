// `padrob export --mjcf MODEL`: the model as MuJoCo's MJCF (solver/io/mjcf.h), on
// standard output or written atomically to --out; --check loads it into MuJoCo and
// checks it follows Padrob's trajectory (builds with MuJoCo only).

#include "ide/cli/export.h"
#include "ide/cli/cli_io.h"

#ifdef PADROB_HAVE_MUJOCO
#include "ide/cli/mujoco_bench.h"
#endif
#include "solver/compile/compile.h"
#include "solver/io/mjcf.h"
#include "solver/model/load.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QSaveFile>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>

namespace ide::cli {

namespace {

constexpr int kOk = 0, kModelErrors = 1, kUsage = 2;

std::string tr(const char* s) { return QCoreApplication::translate("padrob-export", s).toStdString(); }


int usage(const std::string& message)
{
    return usageError("export", message, tr("Try 'padrob export --help'."));
}

#ifdef PADROB_HAVE_MUJOCO
/// What --check compares: seconds of simulated time, and the largest distance [m].
constexpr double kCheckSeconds = 0.2, kCheckTolerance = 1e-6;

std::string fmt(const char* format, double v)
{
    char buf[48];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}
#endif

/// Writes `text` to `path` through a temporary file renamed onto it (QSaveFile): the
/// target is replaced whole or left as it was. False with `error` set on failure.
bool writeAtomically(const std::string& path, const std::string& text, std::string& error)
{
    const QString qpath = QString::fromStdString(path);
    if (QFileInfo(qpath).isDir()) {
        error = tr("cannot write ") + path + tr(": it is a folder");
        return false;
    }
    QSaveFile file(qpath);
    if (!file.open(QIODevice::WriteOnly)) {
        error = tr("cannot create ") + path + ": " + file.errorString().toStdString();
        return false;
    }
    if (file.write(text.data(), static_cast<qint64>(text.size())) != static_cast<qint64>(text.size()) ||
        !file.commit()) {
        error = tr("cannot write ") + path + ": " + file.errorString().toStdString();
        return false;  // QSaveFile's destructor removes the temporary file
    }
    return true;
}

}  // namespace

std::string exportHelp()
{
    return tr("Usage: padrob export --mjcf MODEL [--out FILE] [--dt H] [--check]\n"
              "\n"
              "Writes a model without closed loops as MuJoCo's MJCF (XML). The bodies are posed\n"
              "with every joint at 0, so MuJoCo's qpos of each joint is Padrob's coordinate\n"
              "(the angle for T 0 and T 1 joints: a T 1 joint's length is not a coordinate in\n"
              "MuJoCo; the displacement for T 2); the keyframe \"initial\" holds the model's\n"
              "initial state. MuJoCo gets a passive model: drives, relief valves, limit\n"
              "impulses, applied forces and graphics are not exported (the file's header says\n"
              "so). Bodies MuJoCo would refuse (massless, or an inertia breaking I1 + I2 >= I3)\n"
              "get the nearest values it accepts, with the true ones in a comment there.\n"
              "\n"
              "  --mjcf        the format (required; the only one)\n"
              "  --out FILE    write the MJCF there (default: standard output); the file is\n"
              "                replaced whole or not at all\n"
              "  --dt H        the time step written in <option> [s] (default 0.001)\n"
              "  --check       load the MJCF into MuJoCo (when padrob was built with it), put\n"
              "                the true masses and inertias in, and check that MuJoCo and Padrob\n"
              "                follow the same trajectory for 0.2 s (RK4 at --dt, every joint\n"
              "                passive, no limits, the centres of mass within 1e-6 m); the\n"
              "                result goes to standard error\n"
              "\n"
              "Exit status: 0 success; 1 the model has errors, has closed loops, or MuJoCo\n"
              "disagrees (--check); 2 usage error, unreadable model, or --check in a padrob\n"
              "built without MuJoCo. On failure nothing is written.\n");
}

int runExport(const std::vector<std::string>& args)
{
    std::string modelPath, outPath;
    bool mjcf = false, check = false;
    double dt = 1e-3;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "-h" || a == "--help") {
            std::fputs(exportHelp().c_str(), stdout);
            return kOk;
        }
        if (a == "--mjcf") { mjcf = true; continue; }
        if (a == "--check") { check = true; continue; }
        if (a == "--out" || a == "--dt") {
            if (i + 1 >= args.size()) return usage(a + tr(" needs a value"));
            const std::string& v = args[++i];
            if (a == "--out") {
                if (v.empty()) return usage(tr("--out needs a file name"));
                outPath = v;
            } else {
                auto d = toNumber(v);
                if (!d || !(*d > 0)) return usage(tr("--dt must be a positive number of seconds, not '") + v + "'");
                dt = *d;
            }
            continue;
        }
        if (a.size() > 1 && a[0] == '-') return usage(tr("unknown option '") + a + "'");
        if (!modelPath.empty()) return usage(tr("give one model"));
        modelPath = a;
    }
    if (!mjcf) return usage(tr("give the format: --mjcf (the only one)"));
    if (modelPath.empty()) return usage(tr("no model given"));
#ifndef PADROB_HAVE_MUJOCO
    if (check) return usage(tr("--check needs MuJoCo, and this padrob was built without it"));
#endif

    // the model
    int status = kExitOk;
    std::shared_ptr<const solver::Model> model = loadAndCompile(modelPath, status);
    if (!model) return status;

    // the MJCF
    solver::MjcfOptions options;
    options.timestep = dt;
    options.source = modelPath;
    std::string error;
    const std::string xml = solver::toMjcf(*model, options, error);
    if (!error.empty()) {
        printErr("padrob export: " + modelPath + ": " + error + "\n");
        return kModelErrors;
    }

#ifdef PADROB_HAVE_MUJOCO
    if (check) {
        MujocoRun run;
        if (!runMujoco(*model, dt, 0, 0, kCheckSeconds, kCheckTolerance, run, error)) {
            printErr("padrob export: --check: " + error + "\n");
            return kModelErrors;
        }
        for (const std::string& n : run.notes) printErr(tr("note: ") + n + "\n");
        for (const std::string& a : run.adjustments) printErr(tr("set in MuJoCo after loading: ") + a + "\n");
        printErr(tr("MuJoCo agrees with Padrob over ") + fmt("%g", run.agreementSeconds) + tr(" s (RK4, dt ") +
                 fmt("%g", dt) + tr(" s): the centres of mass are at most ") + fmt("%.3g", run.maxPositionError) +
                 tr(" m apart") + "\n");
    }
#endif

    if (outPath.empty()) {
        if (std::fwrite(xml.data(), 1, xml.size(), stdout) != xml.size() || std::fflush(stdout) != 0) {
            printErr("padrob export: " + tr("cannot write to standard output") + "\n");
            return kUsage;
        }
        return kOk;
    }
    if (!writeAtomically(outPath, xml, error)) {
        printErr("padrob export: " + error + "\n");
        return kUsage;
    }
    return kOk;
}

}  // namespace ide::cli
