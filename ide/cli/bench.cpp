// `padrob bench`: times the solver on a model (docs/cli.md, docs/performance.md).
//
// Method: every figure is the median of R timed runs (default 5) after one warm-up
// run, with the fastest and slowest run beside it; a run times a whole loop with
// std::chrono::steady_clock and divides by its count. Each RK4 run starts a new
// Simulation from the model's initial state (not timed), so the runs repeat the same
// trajectory. The figures:
//  - forward dynamics: forwardKinematics + applyForces + hybridDynamics (which
//    includes the joint reactions) at the initial state, after the mode rules, with
//    the command 0.5 on every drive;
//  - RK4 step: Simulation::advanceTo(t + dt) with every drive commanded by a slow
//    sine (each drive its own phase; the command is set before every step, as the
//    station does every millisecond, so valves open and close, and each new command
//    restarts the integrator), limits and relief valves watched as events. The
//    integrator's stages compute θ̈ only; every step ends with a whole evaluation
//    (reactions, drive forces, the event functions), so data() holds them after
//    every step;
//  - passive RK4 step: the same ODE without drives and limits (what MuJoCo is
//    compared on: the same equations, no events);
//  - the reference: the thesis's Newton–Euler system A·X = B (solver/reference/
//    newton_euler.h), assembled and LU-solved per evaluation, and a classic RK4 over
//    it (4 solves + the update; modes, commands and applied loads held, no events);
//  - scaling: generated chains and trees (bench/generate.h) of 10 … 1000
//    bodies, RK4 steps as above, and the exponent p of time ∝ n^p by least squares
//    on log–log.
// Allocations in the step loop are not counted here (that needs the global operator
// new replaced): tests/alloc/step_allocation_test.cpp checks them.

#include "ide/cli/bench.h"
#include "ide/cli/cli_io.h"

#include "ide/cli/json_writer.h"
#include "solver/contact/contact_forces.h"
#include "solver/dynamics/applied_forces.h"
#include "solver/dynamics/forward_dynamics.h"
#include "solver/integrate/simulation.h"
#include "solver/io/mjcf.h"
#include "solver/kinematics/kinematics.h"
#include "bench/generate.h"
#include "solver/pipeline.h"
#include "solver/reference/newton_euler.h"
#ifdef PADROB_HAVE_MUJOCO
#include "ide/cli/mujoco_bench.h"
#endif

#include "ide/i18n/language.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace ide::cli {

namespace {

constexpr int kOk = 0, kModelErrors = 1, kUsage = 2;

using i18n::trStd;

int usage(const std::string& message)
{
    return usageError("bench", message);
}

std::optional<long> toInteger(const std::string& s)
{
    long v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
    return v;
}

/// v with `digits` significant digits (%g), for the table; '.' whatever the locale.
std::string fmt(double v, int digits = 3)
{
    if (!std::isfinite(v)) return "-";
    if (std::abs(v) >= std::pow(10.0, digits)) return fixed(v, 0);  // no exponent for large values
    return num(v, digits);
}

// ---- timing -----------------------------------------------------------------

using Clock = std::chrono::steady_clock;

double microsSince(Clock::time_point t0)
{
    return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
}

/// The runs of one figure [µs per unit] and their median, fastest and slowest.
struct Figure {
    std::vector<double> runs;
    double median = NAN, min = NAN, max = NAN;
    bool ok() const { return !runs.empty(); }
};

Figure summarize(std::vector<double> runs)
{
    Figure f;
    f.runs = runs;
    if (runs.empty()) return f;
    std::sort(runs.begin(), runs.end());
    const std::size_t n = runs.size();
    f.median = n % 2 == 1 ? runs[n / 2] : 0.5 * (runs[n / 2 - 1] + runs[n / 2]);
    f.min = runs.front();
    f.max = runs.back();
    return f;
}

/// One warm-up run, then `runs` timed ones. `once` returns a run's time per unit
/// [µs], or nullopt when it failed (then the figure is empty).
Figure measure(int runs, const std::function<std::optional<double>()>& once)
{
    if (!once()) return {};
    std::vector<double> v;
    for (int r = 0; r < runs; ++r) {
        const std::optional<double> t = once();
        if (!t) return {};
        v.push_back(*t);
    }
    return summarize(std::move(v));
}

// ---- what is timed ---------------------------------------------------------

constexpr double kCommandAmplitude = 0.8;  // of the sine on every drive
constexpr double kCommandFrequency = 0.5;  // [Hz]
constexpr double kForwardCommand = 0.5;    // on every drive, for the forward dynamics
constexpr int kReferenceEvaluations = 1000;  // most reference solves per run
constexpr int kReferenceSteps = 250;         // most reference RK4 steps per run
constexpr int kScalingSizes[] = {10, 30, 100, 300, 1000};
#ifdef PADROB_HAVE_MUJOCO
constexpr double kMujocoAgreementSeconds = 1.0;  // simulated time both engines must agree over
constexpr double kMujocoTolerance = 1e-3;        // [m], body positions
#endif

std::vector<int> drivenJoints(const solver::Model& m)
{
    std::vector<int> out;
    for (int j = 0; j < m.nb; ++j) {
        if (m.drive[j].type != solver::DriveType::None) out.push_back(j);
    }
    return out;
}

/// The operator of the RK4 runs: u = A sin(2π f t + φ) on every drive, phases spread
/// evenly over the drives.
struct SineCommands {
    std::vector<int> joints;
    std::vector<double> phase;
    explicit SineCommands(const solver::Model& m) : joints(drivenJoints(m))
    {
        for (std::size_t k = 0; k < joints.size(); ++k) {
            phase.push_back(2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(joints.size()));
        }
    }
    /// The commands at time t [s].
    void apply(solver::Simulation& sim, double t) const
    {
        const double wt = 2 * std::numbers::pi * kCommandFrequency * t;
        for (std::size_t k = 0; k < joints.size(); ++k) sim.setCommand(joints[k], kCommandAmplitude * std::sin(wt + phase[k]));
    }
};

/// When the commands are held, they are the sine's values at this time [s] (a
/// quarter period: the first drive at its full amplitude), set once before the steps.
constexpr double kHeldCommandTime = 0.25 / kCommandFrequency;

struct StepOptions {
    double dt = 1e-3;
    int steps = 5000;
    bool adaptive = false;
    bool commanded = true;  ///< the sine set before every step; false: held (kHeldCommandTime)
    bool passive = false;   ///< no drives, no limits (the ODE MuJoCo is compared on)
    /// With a scene: every this many steps the run starts again from the initial state
    /// (kSceneEpisode), so that the machine works about its starting pose; 0: never.
    int episode = 0;
};

/// --scene's episodes [steps]: 0.5 s at 1 ms, the arm about the liner on its cart.
constexpr int kSceneEpisode = 500;

solver::SimulationOptions simulationOptions(const StepOptions& o)
{
    solver::SimulationOptions s;
    s.integrator.method = o.adaptive ? solver::IntegrationMethod::Adaptive : solver::IntegrationMethod::Rk4Fixed;
    s.integrator.step = o.dt;
    s.integrator.rtol = 1e-8;
    s.integrator.atol = 1e-10;
    s.drives = !o.passive;
    s.limits = !o.passive;
    return s;
}

/// The contact phase of a run (CONTACT): its time per step [µs] (applyContacts and
/// updateContactAnchors, timed inside: solver/contact/contact_forces.h) and the mean
/// number of contact points at a step's end.
struct ContactProbe {
    double micros = NAN;
    double points = NAN;
};

/// The steps of one run. `events` gets the number of events in the run; on a failed
/// simulation `error` is set and nullopt returned. With `probe` the contact phase is
/// timed too (the clock's own cost, about 50 ns per evaluation, is in the whole step).
std::optional<double> stepRun(const std::shared_ptr<const solver::Model>& model, const StepOptions& o, long& events,
                              std::string& error, ContactProbe* probe = nullptr)
{
    const SineCommands commands(*model);
    std::vector<solver::SimulationEvent> ev;
    ev.reserve(64);
    events = 0;
    long points = 0;
    double micros = 0, contactSeconds = 0;
    const int episode = o.episode > 0 ? o.episode : o.steps;
    for (int first = 0; first < o.steps; first += episode) {
        // a new simulation from the initial state (not timed)
        solver::Simulation sim(model, simulationOptions(o));
        if (probe) solver::setContactTiming(sim.data(), true);
        if (!o.passive && !o.commanded) commands.apply(sim, kHeldCommandTime);
        const int n = std::min(episode, o.steps - first);
        const auto t0 = Clock::now();
        for (int k = 0; k < n; ++k) {
            const double t = k * o.dt;
            if (!o.passive && o.commanded) commands.apply(sim, t);
            if (!sim.advanceTo((k + 1) * o.dt, ev, error)) {
                error = fill(trStd("padrob", "the simulation failed: %1"), {error});
                return std::nullopt;
            }
            events += static_cast<long>(ev.size());
            ev.clear();
            if (probe) points += static_cast<long>(sim.data().contacts.size());
        }
        micros += microsSince(t0);
        if (probe) contactSeconds += solver::contactSeconds(sim.data());
    }
    if (probe) {
        probe->micros = contactSeconds * 1e6 / o.steps;
        probe->points = static_cast<double>(points) / o.steps;
    }
    return micros / o.steps;
}

/// The state the forward dynamics are timed at: the initial state with kForwardCommand
/// on every drive, after the simulation's mode rules (prescribed rates set).
solver::State forwardState(const std::shared_ptr<const solver::Model>& model, double dt)
{
    StepOptions o;
    o.dt = dt;
    solver::Simulation sim(model, simulationOptions(o));
    for (int j : drivenJoints(*model)) sim.setCommand(j, kForwardCommand);
    std::vector<solver::SimulationEvent> ev;
    std::string error;
    sim.advanceTo(0.0, ev, error);  // the mode rules only: no time passes
    return sim.state();
}

struct ModelFigures {
    int bodies = 0, drives = 0, cuts = 0;
    Figure forward;           ///< µs per evaluation
    Figure step;              ///< µs per RK4 step, or per simulated ms (adaptive)
    Figure held;              ///< µs per RK4 step, commands held
    Figure passive;           ///< µs per passive RK4 step
    Figure reference;         ///< µs per reference solve
    Figure referenceStep;     ///< µs per reference RK4 step
    int referenceEvaluations = 0, referenceSteps = 0;
    double referenceDifference = NAN;  ///< |θ̈ − θ̈_ref|∞ / max(|θ̈_ref|∞, 1e-12)
    long events = 0;                   ///< in the last RK4 run
    bool contact = false;              ///< the model has CONTACT (its own or added for a scene)
    Figure contactStep;                ///< µs of the contact phase per RK4 step (commanded)
    double contactPoints = NAN;        ///< mean contact points at a step's end, last run
#ifdef PADROB_HAVE_MUJOCO
    Figure mujocoContactStep;          ///< µs per mj_step with the geoms and contacts

    bool mujocoTried = false;
    bool mujocoOk = false;
    std::string mujocoError;
    MujocoRun mujoco;
    Figure mujocoStep, mujocoForward;
#endif
};

/// Every figure of one model; false with `error` when a simulation fails.
/// `contacts` (with CONTACT and a scene): the export options with the specs, for MuJoCo's
/// side with geoms.
bool benchModel(const std::shared_ptr<const solver::Model>& model, const StepOptions& so, int runs, bool mujoco,
                ModelFigures& f, std::string& error, const solver::MjcfOptions* contacts = nullptr)
{
    const solver::Model& m = *model;
    f.bodies = m.nb;
    f.drives = static_cast<int>(drivenJoints(m).size());
    f.cuts = static_cast<int>(m.cuts.size());

    // forward dynamics
    const solver::State state = forwardState(model, so.dt);
    solver::Data data(m);
    const int evaluations = so.steps;
    f.forward = measure(runs, [&]() -> std::optional<double> {
        const auto t0 = Clock::now();
        for (int k = 0; k < evaluations; ++k) {
            solver::forwardKinematics(m, state, data);
            solver::applyForces(m, state, data);
            solver::hybridDynamics(m, state, data);
        }
        return microsSince(t0) / evaluations;
    });

    // steps with drives, limits and reactions
    f.step = measure(runs, [&]() { return stepRun(model, so, f.events, error); });
    if (!f.step.ok()) return false;
    // the contact phase of the same steps, timed inside them (separate runs: the whole
    // step above is timed without the clock in the contact phase)
    f.contact = m.contact != nullptr;
    if (f.contact && !so.adaptive) {
        std::vector<double> contactRuns;
        ContactProbe probe;
        long ignored = 0;
        const Figure timed = measure(runs, [&]() -> std::optional<double> {
            const std::optional<double> t = stepRun(model, so, ignored, error, &probe);
            if (t) contactRuns.push_back(probe.micros);
            return t;
        });
        if (!timed.ok()) return false;
        contactRuns.erase(contactRuns.begin());  // the warm-up run
        f.contactStep = summarize(contactRuns);
        f.contactPoints = probe.points;
    }
    if (!so.adaptive) {
        long ignored = 0;
        StepOptions held = so;
        held.commanded = false;
        f.held = measure(runs, [&]() { return stepRun(model, held, ignored, error); });
        if (!f.held.ok()) return false;
        StepOptions passive = so;
        passive.passive = true;
        f.passive = measure(runs, [&]() { return stepRun(model, passive, ignored, error); });
        if (!f.passive.ok()) return false;
    }

    // the reference system at the same state, with the same applied loads
    solver::reference::NewtonEulerSystem system(m);
    solver::forwardKinematics(m, state, data);
    solver::applyForces(m, state, data);
    solver::hybridDynamics(m, state, data);
    {
        const solver::reference::NewtonEulerResult& r = system.solve(state, data.fext, data.tauExt, false);
        const double scale = std::max(r.qdd.lpNorm<Eigen::Infinity>(), 1e-12);
        f.referenceDifference = (data.qdd - r.qdd).lpNorm<Eigen::Infinity>() / scale;
    }
    f.referenceEvaluations = std::min(so.steps, kReferenceEvaluations);
    f.reference = measure(runs, [&]() -> std::optional<double> {
        const auto t0 = Clock::now();
        for (int k = 0; k < f.referenceEvaluations; ++k) system.solve(state, data.fext, data.tauExt, false);
        return microsSince(t0) / f.referenceEvaluations;
    });
    f.referenceSteps = std::min(so.steps, kReferenceSteps);
    solver::reference::Rk4Work work;
    f.referenceStep = measure(runs, [&]() -> std::optional<double> {
        solver::State s = state;
        const auto t0 = Clock::now();
        for (int k = 0; k < f.referenceSteps; ++k) {
            solver::reference::rk4Step(system, s, data.fext, data.tauExt, so.dt, work);
        }
        return microsSince(t0) / f.referenceSteps;
    });

#ifdef PADROB_HAVE_MUJOCO
    // MuJoCo on the same ODE (trees only)
    if (mujoco && m.cuts.empty() && so.adaptive) {
        f.mujocoTried = true;
        f.mujocoError = trStd("padrob", "not compared with --integrator adaptive (MuJoCo is timed with RK4 at dt)");
    } else if (mujoco && m.cuts.empty()) {
        f.mujocoTried = true;
        f.mujocoOk = runMujoco(m, so.dt, so.steps, runs, kMujocoAgreementSeconds, kMujocoTolerance, f.mujoco,
                               f.mujocoError, contacts);
        if (f.mujocoOk) {
            f.mujocoStep = summarize(f.mujoco.stepMicros);
            f.mujocoContactStep = summarize(f.mujoco.contactStepMicros);
            f.mujocoForward = summarize(f.mujoco.forwardMicros);
            f.mujocoOk = f.mujocoStep.ok() && f.mujocoForward.ok();
            if (!f.mujocoOk) f.mujocoError = trStd("padrob", "no timings");
        }
    }
#else
    (void)mujoco;
    (void)contacts;
#endif
    return true;
}

// ---- scaling ---------------------------------------------------------------

struct ScalingPoint {
    int bodies = 0;
    int steps = 0;
    Figure held, commanded;             ///< µs per RK4 step, commands held / set every step
    long heldEvents = 0, commandedEvents = 0;  ///< in the last run
};

struct Scaling {
    std::vector<ScalingPoint> chain, tree;
    double chainExponent = NAN, treeExponent = NAN;                     ///< commands held
    double chainCommandedExponent = NAN, treeCommandedExponent = NAN;  ///< commands set every step
};

/// p of t ∝ n^p: the least-squares slope of log t against log n.
double fitExponent(const std::vector<ScalingPoint>& points, bool commanded)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (const ScalingPoint& p : points) {
        const Figure& f = commanded ? p.commanded : p.held;
        if (!f.ok() || !(f.median > 0)) continue;
        const double x = std::log(static_cast<double>(p.bodies)), y = std::log(f.median);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        ++n;
    }
    if (n < 2) return NAN;
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// Steps per run for n bodies: about as much work per run as `steps` steps of ten
/// bodies, between 20 and `steps`.
int scalingSteps(int steps, int n)
{
    const long s = static_cast<long>(steps) * 10 / n;
    return static_cast<int>(std::clamp<long>(s, std::min(20, steps), steps));
}

bool benchScaling(const StepOptions& so, int runs, Scaling& out, std::string& error)
{
    for (bool tree : {false, true}) {
        std::vector<ScalingPoint>& points = tree ? out.tree : out.chain;
        for (int n : kScalingSizes) {
            const std::string text = tree ? bench::treeModelText(n) : bench::chainModelText(n);
            std::shared_ptr<const solver::Model> model =
                solver::compileText(text, tree ? "tree.pad" : "chain.pad").model;
            if (!model) {
                error = fill(trStd("padrob", "generated model of %1 bodies does not compile"), {std::to_string(n)});
                return false;
            }
            ScalingPoint p;
            p.bodies = n;
            StepOptions o = so;
            o.steps = scalingSteps(so.steps, n);
            p.steps = o.steps;
            o.commanded = false;
            p.held = measure(runs, [&]() { return stepRun(model, o, p.heldEvents, error); });
            o.commanded = true;
            if (p.held.ok()) p.commanded = measure(runs, [&]() { return stepRun(model, o, p.commandedEvents, error); });
            if (!p.held.ok() || !p.commanded.ok()) {
                error = fill(tree ? trStd("padrob", "tree of %1 bodies: %2") : trStd("padrob", "chain of %1 bodies: %2"),
                             {std::to_string(n), error});
                return false;
            }
            points.push_back(p);
        }
    }
    out.chainExponent = fitExponent(out.chain, false);
    out.treeExponent = fitExponent(out.tree, false);
    out.chainCommandedExponent = fitExponent(out.chain, true);
    out.treeCommandedExponent = fitExponent(out.tree, true);
    return true;
}

// ---- the machine -------------------------------------------------------------

std::string cpuModel()
{
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0) {
            const std::size_t c = line.find(':');
            if (c != std::string::npos) {
                std::string s = line.substr(c + 1);
                s.erase(0, s.find_first_not_of(" \t"));
                return s;
            }
        }
    }
    return "unknown";  // the JSON's "cpu" too
}

int cores() { return static_cast<int>(std::thread::hardware_concurrency()); }

// ---- output ------------------------------------------------------------------

struct Options {
    std::string model;
    std::string scene;         ///< --scene FILE ("" none)
    bool contactAdded = false; ///< the model had no CONTACT: added for the scene
    StepOptions step;
    int runs = 5;
    bool json = false, scaling = false, mujoco = true;
};

/// The same figure per simulated millisecond (adaptive runs).
Figure perMillisecond(Figure f, double dt)
{
    const double scale = 1e-3 / dt;
    f.median *= scale;
    f.min *= scale;
    f.max *= scale;
    return f;
}

void writeFigure(JsonWriter& j, const std::string& key, const Figure& f)
{
    j.key(key).num(f.median);
    j.key(key + "_min").num(f.min);
    j.key(key + "_max").num(f.max);
}

std::string jsonReport(const Options& o, const ModelFigures* mf, const Scaling* sc)
{
    JsonWriter j;
    j.beginObject();
    j.key("format").str("padrob-bench");
    j.key("version").integer(1);
    j.key("machine").beginObject();
    j.key("cpu").str(cpuModel());
    j.key("cores").integer(cores());
    j.endObject();
    j.key("integrator").str(o.step.adaptive ? "adaptive" : "rk4");
    j.key("dt").num(o.step.dt);
    j.key("steps").integer(o.step.steps);
    j.key("runs").integer(o.runs);
    if (mf) {
        const ModelFigures& f = *mf;
        j.key("model").str(o.model);
        j.key("bodies").integer(f.bodies);
        j.key("drives").integer(f.drives);
        j.key("loop_closures").integer(f.cuts);
        writeFigure(j, "forward_dynamics_us", f.forward);
        j.key("forward_evaluations_per_second").num(1e6 / f.forward.median);
        if (o.step.adaptive) {
            writeFigure(j, "adaptive_us_per_ms", perMillisecond(f.step, o.step.dt));
        } else {
            writeFigure(j, "rk4_step_us", f.step);
            j.key("steps_per_second").num(1e6 / f.step.median);
        }
        j.key("realtime_factor").num(o.step.dt * 1e6 / f.step.median);
        j.key("realtime_factor_min").num(o.step.dt * 1e6 / f.step.max);
        j.key("realtime_factor_max").num(o.step.dt * 1e6 / f.step.min);
        j.key("events").integer(f.events);
        if (f.held.ok()) writeFigure(j, "held_rk4_step_us", f.held);
        if (f.passive.ok()) writeFigure(j, "passive_rk4_step_us", f.passive);
        writeFigure(j, "reference_forward_us", f.reference);
        writeFigure(j, "reference_rk4_step_us", f.referenceStep);
        j.key("reference_evaluations").integer(f.referenceEvaluations);
        j.key("reference_steps").integer(f.referenceSteps);
        j.key("reference_forward_ratio").num(f.reference.median / f.forward.median);
        if (!o.step.adaptive) j.key("reference_rk4_ratio").num(f.referenceStep.median / f.step.median);
        j.key("reference_qdd_difference").num(f.referenceDifference);
        j.key("allocations_counted").boolean(false);
        if (!o.scene.empty()) j.key("scene").str(o.scene);
        if (f.contact && f.contactStep.ok()) {
            j.key("contact_source").str(o.contactAdded ? "added" : "model");
            writeFigure(j, "contact_us", f.contactStep);
            j.key("contact_points").num(f.contactPoints);
        }
#ifdef PADROB_HAVE_MUJOCO
        if (f.mujocoTried && f.mujocoOk) {
            writeFigure(j, "mujoco_rk4_step_us", f.mujocoStep);
            writeFigure(j, "mujoco_forward_us", f.mujocoForward);
            if (f.mujocoContactStep.ok()) {
                // the whole step against mj_step on the same scene with its geoms
                writeFigure(j, "mujoco_contact_rk4_step_us", f.mujocoContactStep);
                j.key("mujoco_geoms").integer(f.mujoco.geoms);
                j.key("mujoco_contacts").num(f.mujoco.meanContacts);
                j.key("ratio_vs_mujoco").num(f.step.median / f.mujocoContactStep.median);
            } else {
                j.key("ratio_vs_mujoco").num(f.step.median / f.mujocoStep.median);
            }
            j.key("passive_ratio_vs_mujoco").num(f.passive.median / f.mujocoStep.median);
            j.key("mujoco_max_position_error_m").num(f.mujoco.maxPositionError);
            j.key("mujoco_agreement_s").num(f.mujoco.agreementSeconds);
            j.key("mujoco_adjustments").beginArray();
            for (const std::string& a : f.mujoco.adjustments) j.str(a);
            j.endArray();
        } else if (f.mujocoTried) {
            j.key("mujoco_error").str(f.mujocoError);
        }
#endif
    }
    if (sc) {
        j.key("scaling").beginObject();
        for (bool tree : {false, true}) {
            j.key(tree ? "tree" : "chain").beginArray();
            for (const ScalingPoint& p : tree ? sc->tree : sc->chain) {
                j.beginObject();
                j.key("bodies").integer(p.bodies);
                j.key("steps").integer(p.steps);
                writeFigure(j, "rk4_step_us", p.held);
                j.key("events").integer(p.heldEvents);
                writeFigure(j, "commanded_rk4_step_us", p.commanded);
                j.key("commanded_events").integer(p.commandedEvents);
                j.endObject();
            }
            j.endArray();
        }
        j.key("chain_exponent").num(sc->chainExponent);
        j.key("tree_exponent").num(sc->treeExponent);
        j.key("chain_commanded_exponent").num(sc->chainCommandedExponent);
        j.key("tree_commanded_exponent").num(sc->treeCommandedExponent);
        j.endObject();
    }
    j.endObject();
    return j.text() + "\n";
}

constexpr std::size_t kLabelWidth = 40, kMedianWidth = 10, kRangeWidth = 20;

/// One row of the table: label, median, min – max, and a remark (a label too long for its
/// column keeps one blank before the median).
std::string row(const std::string& label, const Figure& f, const std::string& remark)
{
    return pad("  " + label, kLabelWidth - 1) + " " + pad(fmt(f.median), kMedianWidth) +
           pad(fmt(f.min) + " – " + fmt(f.max), kRangeWidth) + remark + "\n";
}

std::string textReport(const Options& o, const ModelFigures* mf, const Scaling* sc)
{
    std::string t;
    t += fill(trStd("padrob", "machine: %1, %2 cores"), {cpuModel(), std::to_string(cores())}) + "\n";
    t += trStd("padrob", "each figure: the median of %n run(s) after a warm-up run, and the fastest – slowest run", nullptr,
               o.runs) +
         "\n";
    if (mf) {
        const ModelFigures& f = *mf;
        const double dtMicros = o.step.dt * 1e6;
        t += fill(trStd("padrob", "model: %1 (bodies: %2, drives: %3, loop closures: %4)"),
                  {o.model, std::to_string(f.bodies), std::to_string(f.drives), std::to_string(f.cuts)}) +
             "\n";
        if (!o.scene.empty()) {
            t += fill(o.contactAdded ? trStd("padrob", "scene: %1; CONTACT added (the model has none): MU 0.5, E 0")
                                     : trStd("padrob", "scene: %1; the model's CONTACT"),
                      {o.scene}) +
                 "\n";
        }
        t += fill(trStd("padrob", "steps: %1 of dt = %2 ms, %3"),
                  {std::to_string(o.step.steps), fmt(o.step.dt * 1e3, 6),
                   o.step.adaptive ? trStd("padrob", "adaptive integrator (Dormand–Prince 5(4), rtol 1e-8)") : trStd("padrob", "RK4")}) +
             "\n\n";
        t += pad("  " + trStd("padrob", "[µs]"), kLabelWidth) + pad(trStd("padrob", "median"), kMedianWidth) +
             trStd("padrob", "min – max") + "\n";
        t += row(trStd("padrob", "forward dynamics, per evaluation"), f.forward,
                 fill(trStd("padrob", "%1 evaluations/s"), {fmt(1e6 / f.forward.median, 4)}));
        const std::string realtime =
            fill(trStd("padrob", "realtime factor %1 (%2 – %3)"),
                 {fmt(dtMicros / f.step.median, 4), fmt(dtMicros / f.step.max, 4), fmt(dtMicros / f.step.min, 4)});
        if (o.step.adaptive) {
            t += row(trStd("padrob", "adaptive, per simulated ms"), perMillisecond(f.step, o.step.dt), realtime);
        } else {
            t += row(trStd("padrob", "RK4 step"), f.step, fill(trStd("padrob", "%1 steps/s, %2"), {fmt(1e6 / f.step.median, 4), realtime}));
            t += row(trStd("padrob", "RK4 step, commands held"), f.held, trStd("padrob", "no restart after a new command"));
            t += row(trStd("padrob", "RK4 step, passive, no limits"), f.passive, trStd("padrob", "no drives, no events"));
        }
        if (f.contactStep.ok()) {
            t += row(trStd("padrob", "contact phase, per RK4 step"), f.contactStep,
                     fill(trStd("padrob", "%1 contact points at a step's end (mean)"), {fmt(f.contactPoints)}));
        }
        t += row(trStd("padrob", "reference N–E system, per solve"), f.reference,
                 fill(trStd("padrob", "×%1 Padrob's forward dynamics"), {fmt(f.reference.median / f.forward.median)}));
        t += row(trStd("padrob", "reference RK4 step"), f.referenceStep,
                 o.step.adaptive ? std::string()
                                 : fill(trStd("padrob", "×%1 Padrob's RK4 step"), {fmt(f.referenceStep.median / f.step.median)}));
#ifdef PADROB_HAVE_MUJOCO
        if (f.mujocoTried && f.mujocoOk) {
            t += row(trStd("padrob", "MuJoCo RK4 step (passive, no limits)"), f.mujocoStep,
                     fill(trStd("padrob", "Padrob / MuJoCo %1 (passive %2)"),
                          {fmt(f.step.median / f.mujocoStep.median), fmt(f.passive.median / f.mujocoStep.median)}));
            t += row(trStd("padrob", "MuJoCo forward (mj_forward)"), f.mujocoForward,
                     fill(trStd("padrob", "Padrob / MuJoCo %1"), {fmt(f.forward.median / f.mujocoForward.median)}));
            if (f.mujocoContactStep.ok()) {
                t += row(trStd("padrob", "MuJoCo RK4 step, geoms and contacts"), f.mujocoContactStep,
                         fill(trStd("padrob", "Padrob / MuJoCo %1 (%2 geoms, %3 contacts)"),
                              {fmt(f.step.median / f.mujocoContactStep.median), std::to_string(f.mujoco.geoms),
                               fmt(f.mujoco.meanContacts)}));
            }
        }
#endif
        t += "\n";
        t += fill(trStd("padrob", "Steps: every drive commanded by a sine (amplitude 0.8, 0.5 Hz, phases spread) set before every\n"
                                  "step (held: set once), limits and relief valves watched as events, the joint reactions computed\n"
                                  "at every step's end. Events in one run: %1."),
                  {std::to_string(f.events)}) +
             "\n";
        t += fill(trStd("padrob", "Reference: the thesis's Newton–Euler system A·X = B (eq. 2.8–2.11), dense LU, %1 solves\n"
                                  "and %2 RK4 steps per run, modes and commands held, no events; its θ̈ differs from Padrob's\n"
                                  "by %3 (relative)."),
                  {std::to_string(f.referenceEvaluations), std::to_string(f.referenceSteps), fmt(f.referenceDifference, 2)}) +
             "\n";
#ifdef PADROB_HAVE_MUJOCO
        if (f.mujocoTried && f.mujocoOk) {
            const std::string within = fmt(f.mujoco.maxPositionError, 2), over = fmt(f.mujoco.agreementSeconds);
            t += f.mujoco.adjustments.empty()
                     ? fill(trStd("padrob", "MuJoCo: the same trajectory within %1 m over %2 s."), {within, over})
                     : fill(trStd("padrob", "MuJoCo: the same trajectory within %1 m over %2 s; adjusted for MuJoCo:"), {within, over});
            t += "\n";
            for (const std::string& a : f.mujoco.adjustments) t += "  " + a + "\n";
        }
#endif
        t += trStd("padrob", "Allocations in the step loop: not counted here (tests/alloc counts them).") + "\n";
    }
    if (sc) {
        t += "\n" + trStd("padrob", "scaling: µs per RK4 step (median) of generated models: drives on every 3rd joint,\n"
                                    "limits on all; commands held, or set every step") +
             "\n";
        const std::size_t w = 18;
        t += pad("  " + trStd("padrob", "bodies"), 10) + pad(trStd("padrob", "chain, held"), w) + pad(trStd("padrob", "chain, commanded"), w) +
             pad(trStd("padrob", "tree, held"), w) + trStd("padrob", "tree, commanded") + "\n";
        for (std::size_t k = 0; k < sc->chain.size() && k < sc->tree.size(); ++k) {
            t += pad("  " + pad(std::to_string(sc->chain[k].bodies), 7, true), 10) + pad(fmt(sc->chain[k].held.median), w) +
                 pad(fmt(sc->chain[k].commanded.median), w) + pad(fmt(sc->tree[k].held.median), w) +
                 fmt(sc->tree[k].commanded.median) + "\n";
        }
        t += pad("  p", 10) + pad(fmt(sc->chainExponent), w) + pad(fmt(sc->chainCommandedExponent), w) +
             pad(fmt(sc->treeExponent), w) + fmt(sc->treeCommandedExponent) + "\n";
        t += trStd("padrob", "  p: time ∝ n^p by least squares on log–log (p ≈ 1 is linear)") + "\n";
    }
    return t;
}

}  // namespace

std::string benchHelp()
{
    return trStd("padrob", "Usage: padrob bench MODEL [--scene FILE] [OPTIONS]\n"
              "       padrob bench --scaling [OPTIONS]\n"
              "\n"
              "Times the solver on a model: forward dynamics, RK4 steps with drives, limits and\n"
              "joint reactions, the real-time factor, and the thesis's reference Newton–Euler\n"
              "system A·X = B; with MuJoCo built in, MuJoCo on the same tree side by side.\n"
              "Each figure is the median of R runs after one warm-up run, with the fastest and\n"
              "slowest run (the machine is noisy); times in µs per evaluation or per step.\n"
              "\n"
              "  --steps N             steps per timed run (default 5000); the forward dynamics\n"
              "                        are timed over N evaluations, the reference over\n"
              "                        min(N, 1000) solves and min(N, 250) steps\n"
              "  --runs R              timed runs per figure (default 5)\n"
              "  --dt H                step [s] (default 0.001)\n"
              "  --integrator M        rk4 (default) or adaptive (Dormand–Prince 5(4), rtol 1e-8:\n"
              "                        time per simulated millisecond)\n"
              "  --json                print one JSON object (format \"padrob-bench\", version 1)\n"
              "  --scaling             also time generated chains and binary trees of 10, 30, 100,\n"
              "                        300 and 1000 bodies and fit time ∝ n^p (MODEL may then be\n"
              "                        left out)\n"
              "  --no-mujoco           skip the comparison with MuJoCo\n"
              "  --scene FILE          run the model in a scene (its ground graphics) with contacts:\n"
              "                        the model's CONTACT, or CONTACT (MU 0.5, E 0) added when it\n"
              "                        has none; also times the contact phase per step (contact_us)\n"
              "                        and MuJoCo on the export with the geoms (ratio_vs_mujoco)\n"
              "\n"
              "The RK4 steps command every drive with a slow sine, set before every step (so\n"
              "valves open and close and every step restarts the integrator, as at the station),\n"
              "watch limits and relief valves, and compute the joint reactions at every\n"
              "step's end; they are also timed with the commands held, and passive without\n"
              "limits. The real-time factor is dt / step time.\n"
              "\n"
              "Exit status: 0 success; 1 the model has errors or a simulation failed;\n"
              "2 usage error or unreadable model.\n");
}

int runBench(const std::vector<std::string>& args)
{
    Options o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "-h" || a == "--help") {
            printOut(benchHelp());
            return kOk;
        }
        if (a == "--json") { o.json = true; continue; }
        if (a == "--scaling") { o.scaling = true; continue; }
        if (a == "--no-mujoco") { o.mujoco = false; continue; }
        if (a == "--scene") {
            if (i + 1 >= args.size() || args[i + 1].empty()) return usage(fill(trStd("padrob", "%1 needs a value"), {a}));
            o.scene = args[++i];
            continue;
        }
        if (a == "--steps" || a == "--runs" || a == "--dt" || a == "--integrator") {
            if (i + 1 >= args.size()) return usage(fill(trStd("padrob", "%1 needs a value"), {a}));
            const std::string& v = args[++i];
            if (a == "--steps" || a == "--runs") {
                const std::optional<long> n = toInteger(v);
                const long most = a == "--steps" ? 100000000L : 1000L;
                if (!n || *n < 1 || *n > most) {
                    return usage(fill(trStd("padrob", "%1 must be a whole number from 1 to %2, not '%3'"),
                                      {a, std::to_string(most), v}));
                }
                (a == "--steps" ? o.step.steps : o.runs) = static_cast<int>(*n);
            } else if (a == "--dt") {
                const std::optional<double> d = toNumber(v);
                if (!d || !(*d > 0) || *d > 1) {
                    return usage(fill(trStd("padrob", "--dt must be a number of seconds above 0 and at most 1, not '%1'"), {v}));
                }
                o.step.dt = *d;
            } else {
                if (v == "rk4") o.step.adaptive = false;
                else if (v == "adaptive") o.step.adaptive = true;
                else return usage(fill(trStd("padrob", "--integrator must be rk4 or adaptive, not '%1'"), {v}));
            }
            continue;
        }
        if (a.size() > 1 && a[0] == '-') return usage(fill(trStd("padrob", "unknown option '%1'"), {a}));
        if (!o.model.empty()) return usage(trStd("padrob", "give one model"));
        o.model = a;
    }
    if (o.model.empty() && !o.scaling) return usage(trStd("padrob", "no model given"));
    if (!o.scene.empty() && o.model.empty()) return usage(trStd("padrob", "--scene needs a model"));
    if (!o.scene.empty()) o.step.episode = static_cast<int>(std::lround(kSceneEpisode * 1e-3 / o.step.dt));

    // the scene: its ground graphics touch the model's solids (CONTACT)
    std::optional<solver::CompiledModel> scene;
    if (!o.scene.empty()) {
        int sceneStatus = kExitOk;
        scene = loadScene(o.scene, sceneStatus);
        if (!scene) return sceneStatus;
    }

    // the model (with a scene: with CONTACT, added when it has none)
    std::shared_ptr<const solver::Model> model;
    solver::ModelSpec spec;
    if (!o.model.empty()) {
        int status = kExitOk;
        auto withContact = [&](solver::ModelSpec& s) {
            if (!s.contact) {
                s.contact = solver::ContactSpec{};
                o.contactAdded = true;
            }
            spec = s;
            return std::string();
        };
        model = scene ? loadAndCompile(o.model, status, withContact, &scene->spec) : loadAndCompile(o.model, status);
        if (!model) return status;
        if (model->nb == 0) {
            printErr("padrob bench: " + fill(trStd("padrob", "%1: the model has no moving body: nothing to time"), {o.model}) + "\n");
            return kModelErrors;
        }
    }

    std::string error;
    ModelFigures figures;
    solver::MjcfOptions contactExport;
    contactExport.source = o.model;
    contactExport.spec = &spec;
    contactExport.scene = scene ? &scene->spec : nullptr;
    if (model && !benchModel(model, o.step, o.runs, o.mujoco, figures, error, scene ? &contactExport : nullptr)) {
        printErr("padrob bench: " + o.model + ": " + error + "\n");
        return kModelErrors;
    }
#ifdef PADROB_HAVE_MUJOCO
    if (model && figures.mujocoTried && !figures.mujocoOk) {
        printErr("padrob bench: " + fill(trStd("padrob", "MuJoCo: %1"), {figures.mujocoError}) + "\n");
    }
#endif
    Scaling scaling;
    if (o.scaling) {
        StepOptions so = o.step;
        so.adaptive = false;  // the scaling is of the real-time integrator
        if (!benchScaling(so, o.runs, scaling, error)) {
            printErr("padrob bench: " + fill(trStd("padrob", "scaling: %1"), {error}) + "\n");
            return kModelErrors;
        }
    }
    const ModelFigures* mf = model ? &figures : nullptr;
    const Scaling* sc = o.scaling ? &scaling : nullptr;
    printOut(o.json ? jsonReport(o, mf, sc) : textReport(o, mf, sc));
    return kOk;
}

}  // namespace ide::cli
