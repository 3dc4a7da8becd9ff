// MuJoCo side by side with Padrob (mujoco_bench.h): export, load from memory, put the
// true mass properties in, check agreement step by step, then time mj_step and
// mj_forward. Built only with MuJoCo (PADROB_HAVE_MUJOCO).

#include "ide/cli/mujoco_bench.h"

#include "ide/cli/cli_io.h"
#include "ide/i18n/language.h"
#include "solver/integrate/simulation.h"
#include "solver/io/mjcf.h"
#include "solver/kinematics/kinematics.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

namespace ide::cli {

namespace {

/// MuJoCo's side runs passive and without limits: Padrob's the same, RK4 at `dt`.
solver::SimulationOptions passiveRk4(double dt)
{
    solver::SimulationOptions o;
    o.integrator.method = solver::IntegrationMethod::Rk4Fixed;
    o.integrator.step = dt;
    o.drives = false;
    o.limits = false;
    return o;
}

using i18n::trStd;

struct ModelDeleter {
    void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
    void operator()(mjData* d) const { mj_deleteData(d); }
};
struct VfsDeleter {
    void operator()(mjVFS* v) const
    {
        mj_deleteVFS(v);
        delete v;
    }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

/// MuJoCo's warnings (a global handler) collected instead of printed to standard
/// output and MUJOCO_LOG.TXT, for the life of this object.
class WarningCatcher {
public:
    WarningCatcher() : m_previous(mju_user_warning)
    {
        s_messages.clear();
        mju_user_warning = &collect;
    }
    ~WarningCatcher() { mju_user_warning = m_previous; }
    WarningCatcher(const WarningCatcher&) = delete;
    WarningCatcher& operator=(const WarningCatcher&) = delete;
    const std::vector<std::string>& messages() const { return s_messages; }

private:
    static void collect(const char* message) { s_messages.emplace_back(message); }
    static inline std::vector<std::string> s_messages;
    void (*m_previous)(const char*);
};

/// `v` as %g with `digits` significant digits, '.' whatever the locale.
std::string fmt(double v, int digits = 6) { return num(v, digits); }

std::string quoted(const std::string& name) { return name.empty() ? std::string() : " \"" + name + "\""; }

std::string vec3(const double* v) { return fmt(v[0]) + " " + fmt(v[1]) + " " + fmt(v[2]); }

/// Loads MJCF text from memory (a one-file VFS). nullptr with `error` set on failure.
ModelPtr loadFromMemory(const std::string& xml, std::string& error)
{
    static const char* const kName = "padrob_export.xml";
    std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
    mj_defaultVFS(vfs.get());
    if (mj_makeEmptyFileVFS(vfs.get(), kName, static_cast<int>(xml.size())) != 0) {
        error = trStd("padrob", "MuJoCo's virtual file system refused the MJCF");
        return nullptr;
    }
    const int file = mj_findFileVFS(vfs.get(), kName);
    std::memcpy(vfs->filedata[file], xml.data(), xml.size());
    char message[1024] = "";
    ModelPtr m(mj_loadXML(kName, vfs.get(), message, sizeof message));
    if (!m) error = fill(trStd("padrob", "MuJoCo refused the exported MJCF: %1"), {message});
    return m;
}

/// Puts the true mass properties into a loaded export where it wrote placeholders (in
/// body id order), each change into `adjustments`, and the constants derived from them.
/// False with `error` when a body or joint of the export is missing.
bool putTrueMasses(const solver::Model& model, mjModel* m, mjData* d, std::vector<int>& mjBody,
                   std::vector<std::string>& adjustments, std::string& error)
{
    const solver::MjcfNames names = solver::mjcfNames(model);
    mjBody.assign(static_cast<std::size_t>(model.nb), -1);
    for (int i = 0; i < model.nb; ++i) {
        if (model.bodyId[i] < 0) continue;  // a free joint's massless bodies: not exported
        // (a free body's joint: the free joint's, named at its first coordinate)
        const int jointAt = model.freeSlot[i] > 0 ? i - model.freeSlot[i] : i;
        mjBody[i] = mj_name2id(m, mjOBJ_BODY, names.body[i].c_str());
        const int joint = mj_name2id(m, mjOBJ_JOINT, names.joint[jointAt].c_str());
        if (mjBody[i] < 0 || joint < 0) {
            error = fill(trStd("padrob", "MuJoCo's model has no body '%1' or joint '%2'"), {names.body[i], names.joint[jointAt]});
            return false;
        }
    }
    std::vector<int> byId(static_cast<std::size_t>(model.nb));
    for (int i = 0; i < model.nb; ++i) byId[i] = i;
    std::sort(byId.begin(), byId.end(), [&](int a, int b) { return model.bodyId[a] < model.bodyId[b]; });
    bool changed = false;
    for (int i : byId) {
        if (mjBody[i] < 0) continue;
        const solver::MjcfInertial p = solver::mjcfInertial(model, i);
        if (!p.placeholder()) continue;
        const int b = mjBody[i];
        std::string change = "body " + std::to_string(model.bodyId[i]) + quoted(model.bodyName[i]) + " (MJCF " +
                             names.body[i] + "):";
        if (p.placeholderMass) {
            change += " mass " + fmt(m->body_mass[b]) + " -> " + fmt(p.mass) + " kg;";
        }
        if (p.placeholderInertia) {
            change += " principal moments " + vec3(m->body_inertia + 3 * b) + " -> " + vec3(p.principal.data()) +
                      " kg m^2" + (p.diagonal ? " (body axes)" : " (about the principal axes, body_iquat)");
        } else {
            change.pop_back();
        }
        if (p.placeholderMass) m->body_mass[b] = p.mass;
        if (p.placeholderInertia) {
            // the export wrote these about the same axes (identity when diagonal), so
            // MuJoCo's body_sameframe and body_simple still hold
            for (int k = 0; k < 3; ++k) m->body_inertia[3 * b + k] = p.principal[k];
            const Eigen::Quaterniond& q = p.principalAxes;
            const double iquat[4] = {q.w(), q.x(), q.y(), q.z()};
            std::memcpy(m->body_iquat + 4 * b, iquat, sizeof iquat);
        }
        adjustments.push_back(change);
        changed = true;
    }
    // the constants derived from them (subtree masses, inverse weights, mean inertia)
    if (changed) mj_setConst(m, d);
    return true;
}

/// An export loaded into MuJoCo with the true masses put in (putTrueMasses).
struct Loaded {
    ModelPtr model;
    DataPtr data;
    std::vector<int> mjBody;  ///< per tree index: MuJoCo's body id, −1 not exported
};

/// Exports `model` with `options`, loads it and puts the true masses in; false with `error`.
bool loadExport(const solver::Model& model, const solver::MjcfOptions& options, Loaded& out,
                std::vector<std::string>& adjustments, std::string& error)
{
    const std::string xml = solver::toMjcf(model, options, error);
    if (xml.empty()) return false;
    out.model = loadFromMemory(xml, error);
    if (!out.model) return false;
    out.data.reset(mj_makeData(out.model.get()));
    if (!out.data) {
        error = trStd("padrob", "MuJoCo could not allocate its data");
        return false;
    }
    return putTrueMasses(model, out.model.get(), out.data.get(), out.mjBody, adjustments, error);
}

/// The export with geoms and contacts (runMujoco's `contacts`): loaded, the true masses
/// put in, `steps` mj_step calls timed `runs` times after a warm-up run.
bool timeContacts(const solver::Model& model, solver::MjcfOptions options, double dt, int steps, int runs,
                  double contactSeconds, const std::shared_ptr<solver::Model>& passive, MujocoRun& out, std::string& error)
{
    options.timestep = dt;
    Loaded loaded;
    std::vector<std::string> adjustments;  // the same as the agreement's export's
    if (!loadExport(model, options, loaded, adjustments, error)) return false;
    mjModel* m = loaded.model.get();
    mjData* d = loaded.data.get();
    const std::vector<int>& mjBody = loaded.mjBody;
    out.contactLoaded = true;
    out.geoms = m->ngeom;
    const int key = mj_name2id(m, mjOBJ_KEY, "initial");
    m->opt.disableflags |= mjDSBL_LIMIT;

    // side by side with contacts (Padrob's passive model, its contacts kept)
    if (contactSeconds > 0) {
        if (key >= 0) mj_resetDataKeyframe(m, d, key);
        else mj_resetData(m, d);
        solver::Simulation sim(passive, passiveRk4(dt));
        std::vector<solver::SimulationEvent> events;
        long n = std::lround(contactSeconds / dt);
        for (long k = 1; k <= n; ++k) {
            std::string why;
            if (!sim.advanceTo(static_cast<double>(k) * dt, events, why)) {
                // reported, not judged (as the distances): the timing still runs
                out.contactFailure = fill(trStd("padrob", "Padrob failed: %1"), {why});
                n = k - 1;
                break;
            }
            mj_step(m, d);
            mj_kinematics(m, d);
            for (int i = 0; i < model.nb; ++i) {
                if (mjBody[i] < 0) continue;
                const Eigen::Vector3d p = solver::comPosition(*passive, sim.data(), i);
                const double distance = (p - Eigen::Map<const Eigen::Vector3d>(d->xipos + 3 * mjBody[i])).norm();
                out.contactMaxDistance = std::max(out.contactMaxDistance, distance);
            }
        }
        for (int i = 0; i < model.nb; ++i) {
            if (mjBody[i] < 0) continue;
            out.contactEnd.push_back({std::to_string(model.bodyId[i]) + quoted(model.bodyName[i]),
                                      solver::comPosition(*passive, sim.data(), i),
                                      Eigen::Map<const Eigen::Vector3d>(d->xipos + 3 * mjBody[i])});
        }
        out.contactSeconds = static_cast<double>(n) * dt;
    }

    using Clock = std::chrono::steady_clock;
    if (steps == 0 || runs == 0) return true;
    for (int r = -1; r < runs; ++r) {
        if (key >= 0) mj_resetDataKeyframe(m, d, key);
        else mj_resetData(m, d);
        long contactsSeen = 0;
        const Clock::time_point t0 = Clock::now();
        for (int s = 0; s < steps; ++s) {
            mj_step(m, d);
            contactsSeen += d->ncon;
        }
        const Clock::time_point t1 = Clock::now();
        if (r >= 0) out.contactStepMicros.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count() / steps);
        out.meanContacts = static_cast<double>(contactsSeen) / steps;
    }
    return true;
}

}  // namespace

bool runMujoco(const solver::Model& model, double dt, int steps, int runs, double agreementSeconds, double tolerance,
               MujocoRun& out, std::string& error, const solver::MjcfOptions* contacts, double contactSeconds)
{
    out = MujocoRun{};
    error.clear();
    if (!(dt > 0) || !std::isfinite(dt) || steps < 0 || runs < 0 || !(agreementSeconds >= 0) ||
        !std::isfinite(agreementSeconds) || !(tolerance >= 0)) {
        error = "runMujoco: bad arguments";
        return false;
    }
    WarningCatcher warnings;

    // export and load; the export's ids and the true mass properties where it wrote placeholders
    solver::MjcfOptions options;
    options.timestep = dt;
    Loaded loaded;
    if (!loadExport(model, options, loaded, out.adjustments, error)) return false;
    mjModel* m = loaded.model.get();
    mjData* d = loaded.data.get();
    const std::vector<int>& mjBody = loaded.mjBody;
    m->opt.disableflags |= mjDSBL_LIMIT;

    // what Padrob's side leaves out so that both integrate the same equations
    auto padrobModel = std::make_shared<solver::Model>(model);
    int driven = 0, limited = 0;
    for (int i = 0; i < model.nb; ++i) {
        driven += model.drive[i].type != solver::DriveType::None;
        limited += std::isfinite(model.lower[i]) || std::isfinite(model.upper[i]);
    }
    if (driven > 0) {
        out.notes.push_back(trStd("padrob", "every joint passive in both: the model's %n drive(s) are not exported", nullptr, driven));
    }
    if (limited > 0) {
        out.notes.push_back(trStd("padrob", "joint limits off in both (%n joint(s) have them)", nullptr, limited));
    }
    if (!model.forces.empty()) {
        const int forces = static_cast<int>(model.forces.size());
        out.notes.push_back(trStd("padrob", "Padrob runs without the model's %n applied force(s) (F): they are not exported",
                                  nullptr, forces));
        padrobModel->forces.clear();
    }
    if (model.contact) {
        out.notes.push_back(trStd("padrob", "the agreement is checked without contacts (MuJoCo's export there has no geoms)"));
        padrobModel->contact = nullptr;
    }
    solver::Simulation sim(padrobModel, passiveRk4(dt));
    sim.evaluate();

    const int key = mj_name2id(m, mjOBJ_KEY, "initial");
    auto reset = [&] {
        if (key >= 0) mj_resetDataKeyframe(m, d, key);
        else mj_resetData(m, d);
    };
    reset();
    mj_forward(m, d);

    // agreement, step by step
    const long n = std::lround(agreementSeconds / dt);
    std::vector<solver::SimulationEvent> events;
    for (long k = 0; k <= n; ++k) {
        if (k > 0) {
            if (!sim.advanceTo(static_cast<double>(k) * dt, events, error)) {
                error = fill(trStd("padrob", "Padrob failed: %1"), {error});
                return false;
            }
            mj_step(m, d);
            mj_kinematics(m, d);  // mj_step leaves the positions of the step's start
        }
        for (int i = 0; i < model.nb; ++i) {
            if (mjBody[i] < 0) continue;
            const Eigen::Vector3d p = solver::comPosition(*padrobModel, sim.data(), i);
            const Eigen::Map<const Eigen::Vector3d> q(d->xipos + 3 * mjBody[i]);
            const double distance = (p - q).norm();
            if (distance > out.maxPositionError || !std::isfinite(distance)) out.maxPositionError = distance;
            if (!(distance <= tolerance)) {
                out.agreementSeconds = static_cast<double>(k) * dt;
                error = fill(trStd("padrob", "MuJoCo and Padrob disagree: the centre of mass of body %1 is %2 m apart at "
                                             "t = %3 s (tolerance %4 m; Padrob %5, MuJoCo %6)"),
                             {std::to_string(model.bodyId[i]) + quoted(model.bodyName[i]), fmt(distance, 3),
                              fmt(static_cast<double>(k) * dt), fmt(tolerance), vec3(p.data()), vec3(q.data())});
                return false;
            }
        }
    }
    out.agreementSeconds = static_cast<double>(n) * dt;

    // timing: a warm-up run (r = −1), then `runs` runs from the initial state
    using Clock = std::chrono::steady_clock;
    auto timeRuns = [&](void (*call)(const mjModel*, mjData*), std::vector<double>& micros) {
        if (steps == 0) return;
        for (int r = -1; r < runs; ++r) {
            reset();
            const Clock::time_point t0 = Clock::now();
            for (int s = 0; s < steps; ++s) call(m, d);
            const Clock::time_point t1 = Clock::now();
            if (r >= 0) micros.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count() / steps);
        }
    };
    if (runs > 0) {
        timeRuns(&mj_step, out.stepMicros);
        timeRuns(&mj_forward, out.forwardMicros);
    }
    if (contacts) {
        auto withContacts = std::make_shared<solver::Model>(*padrobModel);
        withContacts->contact = model.contact;
        if (!timeContacts(model, *contacts, dt, steps, runs, contactSeconds, withContacts, out, error)) return false;
    }
    for (int w = 0; w < mjNWARNING; ++w) {
        if (d->warning[w].number > 0) {
            const int times = d->warning[w].number;
            out.notes.push_back(fill(trStd("padrob", "MuJoCo warned %n time(s): %1", nullptr, times),
                                     {warnings.messages().empty() ? "warning " + std::to_string(w) : warnings.messages().front()}));
        }
    }
    return true;
}

}  // namespace ide::cli
