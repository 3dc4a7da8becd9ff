// `padrob export --mjcf MODEL`: the model as MuJoCo's MJCF (solver/io/mjcf.h), on
// standard output or written atomically to --out; --check loads it into MuJoCo and
// checks it follows Padrob's trajectory (builds with MuJoCo only).

#include "ide/cli/export.h"
#include "ide/cli/cli_io.h"

#ifdef PADROB_HAVE_MUJOCO
#include "ide/cli/mujoco_bench.h"
#endif
#include "solver/io/mjcf.h"
#include "solver/pipeline.h"

#include "ide/i18n/diagnostic_text.h"
#include "ide/i18n/language.h"
#include "solver/core/output_file.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>

namespace ide::cli {

namespace {

constexpr int kOk = 0, kModelErrors = 1, kUsage = 2;

using i18n::trStd;

int usage(const std::string& message)
{
    return usageError("export", message);
}

#ifdef PADROB_HAVE_MUJOCO
/// What --check compares: seconds of simulated time, and the largest distance [m].
constexpr double kCheckSeconds = 0.2, kCheckTolerance = 1e-6;
/// With CONTACT: the run with contacts side by side, reported (docs/contact.md) [s].
constexpr double kContactCheckSeconds = 1.0;
#endif

}  // namespace

std::string exportHelp()
{
    return trStd("padrob", "Usage: padrob export --mjcf MODEL [--scene FILE] [--out FILE] [--dt H] [--check]\n"
              "\n"
              "Writes a model without closed loops as MuJoCo's MJCF (XML). The bodies are posed\n"
              "with every joint at 0, so MuJoCo's qpos of each joint is Padrob's coordinate\n"
              "(the angle for T 0 and T 1 joints: a T 1 joint's length is not a coordinate in\n"
              "MuJoCo; the displacement for T 2); the keyframe \"initial\" holds the model's\n"
              "initial state. MuJoCo gets a passive model: drives, relief valves, limit\n"
              "impulses and applied forces are not exported (the file's header says so). With\n"
              "CONTACT the graphics become geoms (a TUBE a ring of boxes; CONE, PRISM and MESH\n"
              "their convex hulls; NOCONTACT ones visual only) and contacts are on, with MuJoCo's\n"
              "law set to approximate Padrob's; without CONTACT there are no geoms and contacts\n"
              "are off. Bodies MuJoCo would refuse (massless, or an inertia breaking I1 + I2 >= I3)\n"
              "get the nearest values it accepts, with the true ones in a comment there.\n"
              "\n"
              "  --mjcf        the format (required; the only one)\n"
              "  --out FILE    write the MJCF there (default: standard output); the file is\n"
              "                replaced whole or not at all\n"
              "  --dt H        the time step written in <option> [s] (default 0.001)\n"
              "  --scene FILE  with CONTACT: the scene's ground graphics (e.g. a mill) as world\n"
              "                geoms, and the solids overlapping them at the start excluded\n"
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
    std::string modelPath, outPath, scenePath;
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
        if (a == "--out" || a == "--dt" || a == "--scene") {
            if (i + 1 >= args.size()) return usage(fill(trStd("padrob", "%1 needs a value"), {a}));
            const std::string& v = args[++i];
            if (a == "--scene") {
                if (v.empty()) return usage(trStd("padrob", "--scene needs a file name"));
                scenePath = v;
            } else if (a == "--out") {
                if (v.empty()) return usage(trStd("padrob", "--out needs a file name"));
                outPath = v;
            } else {
                auto d = toNumber(v);
                if (!d || !(*d > 0)) return usage(fill(trStd("padrob", "--dt must be a positive number of seconds, not '%1'"), {v}));
                dt = *d;
            }
            continue;
        }
        if (a.size() > 1 && a[0] == '-') return usage(fill(trStd("padrob", "unknown option '%1'"), {a}));
        if (!modelPath.empty()) return usage(trStd("padrob", "give one model"));
        modelPath = a;
    }
    if (!mjcf) return usage(trStd("padrob", "give the format: --mjcf (the only one)"));
    if (modelPath.empty()) return usage(trStd("padrob", "no model given"));
#ifndef PADROB_HAVE_MUJOCO
    if (check) return usage(trStd("padrob", "--check needs MuJoCo, and this padrob was built without it"));
#endif

    // the scene: with CONTACT its ground graphics are world geoms
    std::optional<solver::CompiledModel> scene;
    if (!scenePath.empty()) {
        int sceneStatus = kExitOk;
        scene = loadScene(scenePath, sceneStatus);
        if (!scene) return sceneStatus;
    }

    // the model (its spec for the geoms)
    int status = kExitOk;
    solver::ModelSpec spec;
    auto keepSpec = [&](solver::ModelSpec& s) {
        spec = s;
        return std::string();
    };
    std::shared_ptr<const solver::Model> model = loadAndCompile(modelPath, status, keepSpec, scene ? &scene->spec : nullptr);
    if (!model) return status;
    if (scene && !model->contact) {
        printErr(fill(trStd("padrob", "note: %1"), {trStd("padrob", "the model has no CONTACT: no geoms, and the scene is not exported")}) +
                 "\n");
    }

    // the MJCF
    solver::MjcfOptions options;
    options.timestep = dt;
    options.source = modelPath;
    options.spec = &spec;
    options.scene = scene ? &scene->spec : nullptr;
    std::string error;
    const std::string xml = solver::toMjcf(*model, options, error);
    if (!error.empty()) {
        printErr("padrob export: " + modelPath + ": " + error + "\n");
        return kModelErrors;
    }

#ifdef PADROB_HAVE_MUJOCO
    if (check) {
        MujocoRun run;
        if (!runMujoco(*model, dt, 0, 0, kCheckSeconds, kCheckTolerance, run, error, model->contact ? &options : nullptr,
                       kContactCheckSeconds)) {
            printErr("padrob export: --check: " + error + "\n");
            return kModelErrors;
        }
        for (const std::string& n : run.notes) printErr(fill(trStd("padrob", "note: %1"), {n}) + "\n");
        for (const std::string& a : run.adjustments) printErr(fill(trStd("padrob", "set in MuJoCo after loading: %1"), {a}) + "\n");
        printErr(fill(trStd("padrob", "MuJoCo agrees with Padrob over %1 s (RK4, dt %2 s): the centres of mass are at "
                                      "most %3 m apart"),
                      {num(run.agreementSeconds), num(dt), num(run.maxPositionError, 3)}) +
                 "\n");
        if (run.contactLoaded) {
            printErr(fill(trStd("padrob", "MuJoCo loads the export with its %1 geoms and contacts on"), {std::to_string(run.geoms)}) +
                     "\n");
            printErr(fill(trStd("padrob", "with contacts over %1 s (every joint passive, no limits): the centres of mass are "
                                          "at most %2 m apart; at the end:"),
                          {num(run.contactSeconds), num(run.contactMaxDistance, 3)}) +
                     "\n");
            if (!run.contactFailure.empty()) printErr(fill(trStd("padrob", "note: %1"), {run.contactFailure}) + "\n");
            auto xyz = [](const Eigen::Vector3d& v) { return num(v.x(), 9) + " " + num(v.y(), 9) + " " + num(v.z(), 9); };
            for (const MujocoRun::BodyEnd& b : run.contactEnd) {
                printErr(fill(trStd("padrob", "  body %1: Padrob %2, MuJoCo %3"), {b.body, xyz(b.padrob), xyz(b.mujoco)}) + "\n");
            }
        }
    }
#endif

    if (outPath.empty()) {
        if (std::fwrite(xml.data(), 1, xml.size(), stdout) != xml.size() || std::fflush(stdout) != 0) {
            printErr("padrob export: " + trStd("padrob", "cannot write to standard output") + "\n");
            return kUsage;
        }
        return kOk;
    }
    // replaced whole or left as it was, never the model itself (solver/core/output_file.h)
    solver::Text writeError;
    if (!solver::writeWholeFile(outPath, xml, {modelPath}, writeError)) {
        printErr("padrob export: " + i18n::text(writeError).toStdString() + "\n");
        return kUsage;
    }
    return kOk;
}

}  // namespace ide::cli
