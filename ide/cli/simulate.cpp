// `padrob simulate`: runs a model headless and writes a CSV trajectory; the
// options (docs/cli.md, simulateHelp()) set the time, step, integrator, inputs,
// initial values, and welds made and released at given times (--weld, --release).

#include "ide/cli/simulate.h"
#include "ide/cli/cli_io.h"

#include "solver/dynamics/constraints.h"
#include "solver/integrate/simulation.h"
#include "solver/io/csv_writer.h"
#include "solver/io/input_table.h"
#include "trainer/input/input_log.h"
#include "trainer/station/profile_store.h"
#include "trainer/station/station_engine.h"
#include "solver/kinematics/kinematics.h"
#include "solver/pipeline.h"

#include "ide/i18n/diagnostic_text.h"
#include "ide/i18n/language.h"

#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

namespace ide::cli {

namespace {

constexpr int kOk = 0, kModelErrors = 1, kUsage = 2;

using i18n::trStd;

namespace {

/// A station engine that replays `logPath` through the profile `profileArg` (a file,
/// a name of the model's profiles, or "" for the one made for the model). nullptr and
/// `problem` when the log or profile cannot be used.
std::unique_ptr<trainer::StationEngine> replayStation(const solver::Model& m, const std::string& modelPath,
                                                      const std::string& logPath, const std::string& profileArg,
                                                      bool passive, std::string& problem)
{
    auto log = std::make_shared<trainer::InputLog>();
    QString error;
    if (!trainer::InputLog::load(QString::fromStdString(logPath), *log, &error)) {
        problem = error.toStdString();
        return nullptr;
    }
    const QString model = QString::fromStdString(modelPath);
    const QList<trainer::DriveInfo> drives = passive ? QList<trainer::DriveInfo>{} : trainer::drivesOf(m);
    trainer::StationProfile profile;
    QList<trainer::ProfileIssue> issues;
    if (!trainer::ProfileStore().resolve(model, QString::fromStdString(profileArg), drives, profile, issues)) {
        problem = issues.isEmpty() ? profileArg : issues.first().text().toStdString();
        return nullptr;
    }
    auto engine = std::make_unique<trainer::StationEngine>();
    engine->setDrives(m.nb, drives);
    engine->setReplayOnly(true);
    for (auto& d : trainer::replayDevices(log)) engine->addDevice(d);
    for (const trainer::ProfileIssue& i : engine->setProfile(profile)) {
        if (i.error) {
            problem = "--profile: " + i.text().toStdString();
            return nullptr;
        }
        printErr("padrob simulate: " + fill(trStd("padrob", "warning: %1"), {i.text().toStdString()}) + "\n");
    }
    return engine;
}

}  // namespace

int usage(const std::string& message)
{
    return usageError("simulate", message);
}

/// A number as the user would write it back: 6 significant digits, '.'.
std::string fmtNumber(double v) { return num(v, 6); }

std::optional<long> toInteger(const std::string& s)
{
    long v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
    return v;
}

/// A --weld or --release T:A:B: at time t, weld body b to body a (or release that weld).
struct WeldSwitch {
    bool weld = true;  ///< false: --release
    std::string text;  ///< T:A:B as given, for messages
    double t = 0;      ///< [s]
    long a = 0, b = 0;  ///< the modeler's body ids; 0 = the ground
    const char* option() const { return weld ? "--weld" : "--release"; }
    std::string prefix() const { return std::string(option()) + " '" + text + "': "; }
};

/// Parses T:A:B; nullopt with `problem` set when it is malformed or T is not ≥ 0
/// or A, B cannot be welded whatever the model (checked against the model later).
std::optional<WeldSwitch> parseWeldSwitch(bool weld, const std::string& text, std::string& problem)
{
    WeldSwitch w;
    w.weld = weld;
    w.text = text;
    const std::size_t c1 = text.find(':');
    const std::size_t c2 = c1 == std::string::npos ? std::string::npos : text.find(':', c1 + 1);
    const std::string ts = text.substr(0, c1);
    std::optional<long> a, b;
    if (c2 != std::string::npos && text.find(':', c2 + 1) == std::string::npos) {
        a = toInteger(text.substr(c1 + 1, c2 - c1 - 1));
        b = toInteger(text.substr(c2 + 1));
    }
    // the time: any number here (from_chars also reads inf and nan), judged below
    double t = 0;
    const char* tb = ts.data();
    if (!ts.empty() && ts[0] == '+') ++tb;
    auto [p, ec] = std::from_chars(tb, ts.data() + ts.size(), t);
    if (!a || !b || ts.empty() || ec != std::errc() || p != ts.data() + ts.size()) {
        problem = fill(weld ? trStd("padrob", "--weld takes T:A:B: a time [s] and two body ids, to weld body B to body A "
                                              "(0 = the ground), e.g. 0.5:0:2; not '%1'")
                            : trStd("padrob", "--release takes T:A:B: a time [s] and two body ids, to release the weld of "
                                              "body B to body A (0 = the ground), e.g. 1.5:0:2; not '%1'"),
                       {text});
        return std::nullopt;
    }
    if (!std::isfinite(t) || t < 0) {
        problem = w.prefix() + fill(trStd("padrob", "the time must be a finite number of seconds ≥ 0 (from the start), not '%1'"), {ts});
        return std::nullopt;
    }
    w.t = t;
    w.a = *a;
    w.b = *b;
    if (w.a == w.b) {
        problem = w.prefix() + (weld ? trStd("padrob", "cannot weld a body to itself: give two different bodies A and B")
                                     : trStd("padrob", "cannot release a body from itself: give the two bodies of a --weld"));
        return std::nullopt;
    }
    if (w.b == 0) {
        const std::string swapped = ts + ":" + std::to_string(w.b) + ":" + std::to_string(w.a);
        problem = w.prefix() +
                  fill(weld ? trStd("padrob", "the ground cannot be welded to a body: put the ground as A, '%1'")
                            : trStd("padrob", "the ground is never the welded body B: a weld to the ground is written "
                                              "with the ground as A, '%1'"),
                       {swapped});
        return std::nullopt;
    }
    return w;
}

}  // namespace

std::string simulateHelp()
{
    return trStd("padrob", "Usage: padrob simulate MODEL --time T [OPTIONS]\n"
              "\n"
              "Simulates the model for T seconds and writes its trajectory as CSV.\n"
              "\n"
              "  --time T              simulated time [s] (required, > 0)\n"
              "  --dt H                step [s] (default 0.001): the RK4 step, and how often the\n"
              "                        inputs are read and output rows may be written\n"
              "  --integrator M        rk4 (fixed step, the real-time integrator; default) or\n"
              "                        adaptive (error-controlled, for accuracy)\n"
              "  --rtol R              relative tolerance of the adaptive integrator (default 1e-8)\n"
              "  --input FILE.csv      operator commands: a column t and one column u<joint id> per\n"
              "                        drive, values in [-1, 1], held between rows\n"
              "  --input-log LOG       replay a recorded input log (raw device readings, from\n"
              "                        padrob-studio's Station workspace) through a station profile,\n"
              "                        with its timing; instead of --input\n"
              "  --profile P           the profile for --input-log: a .json file, or the name of one\n"
              "                        of the model's profiles (default: the one made for the model:\n"
              "                        keyboard pairs in order, gamepad in banks)\n"
              "  --set J=VALUE         initial coordinate of joint J (overrides QI; T 1: length)\n"
              "  --rate J=VALUE        initial rate of joint J (overrides VI)\n"
              "  --passive             ignore every drive (all joints passive)\n"
              "  --no-limits           ignore the joint limits LL/UL\n"
              "  --every N             write one row every N steps (default 1)\n"
              "  --out FILE.csv        write the CSV there (default: standard output)\n"
              "  --weld T:A:B          at time T [s] weld body B to body A (0 = the ground) at\n"
              "                        their relative pose then; repeatable\n"
              "  --release T:A:B       at time T [s] release the weld of body B to body A;\n"
              "                        repeatable\n"
              "  --scene FILE.pad      a scene (ground graphics only, e.g. a mill): under CONTACT\n"
              "                        the model's solids touch its solids too\n"
              "\n"
              "Columns: t; q<j> for every joint j in id order (loop-closing joints too;\n"
              "q<j>x q<j>y q<j>z for a free joint, T 3: its body's translation along B1's\n"
              "joint axes); qd<j> likewise; ang<j> (the angle, rad) for every\n"
              "pivoted-actuator (T 1) joint, whose q<j> is the length;\n"
              "x<i> y<i> z<i>, the world position of the centre of mass of every body i;\n"
              "F<j>, the force or torque of every drive; pA<j> pB<j>, the chamber pressures\n"
              "[Pa] of every fluid-power drive (CYL, HMOTOR) in joint id order, then pP<id>,\n"
              "the supply pressure of every pump; E, the mechanical energy (kinetic +\n"
              "gravitational) [J]. Events (limits hit and left, relief valves opening and\n"
              "closing, pumps saturating, cavitation, welds made and released, a closed loop\n"
              "locking up) are printed on standard error, one per line.\n"
              "\n"
              "Welds: the simulation stops exactly at each T (between output rows if T is not\n"
              "a multiple of --dt; the rows stay every --dt), makes or releases the weld and\n"
              "goes on; a row at T shows the state after it. Several at one T apply in the\n"
              "order given. B is never the ground (put the ground as A); a body other than\n"
              "the ground is in one weld at a time, and --release needs that weld in force\n"
              "at T (else the run fails, exit status 1).\n"
              "\n"
              "Exit status: 0 success; 1 the model has errors or the simulation failed;\n"
              "2 usage error or unreadable input. On failure no output file is left behind.\n");
}

int runSimulate(const std::vector<std::string>& args)
{
    std::string modelPath, inputPath, outPath, inputLogPath, profileArg, scenePath;
    std::optional<double> time;
    double dt = 1e-3, rtol = 1e-8;
    long every = 1;
    bool passive = false, noLimits = false, adaptive = false;
    std::vector<std::pair<std::string, std::string>> sets, rates;  // raw J=VALUE
    std::vector<WeldSwitch> switches;  // --weld and --release, in command-line order

    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::optional<std::string> {
            if (i + 1 >= args.size()) return std::nullopt;
            return args[++i];
        };
        if (a == "-h" || a == "--help") {
            std::fputs(simulateHelp().c_str(), stdout);
            return kOk;
        }
        if (a == "--passive") { passive = true; continue; }
        if (a == "--no-limits") { noLimits = true; continue; }
        const bool takesValue = a == "--time" || a == "--dt" || a == "--integrator" || a == "--rtol" || a == "--input" ||
                                a == "--input-log" || a == "--profile" ||
                                a == "--set" || a == "--rate" || a == "--every" || a == "--out" ||
                                a == "--weld" || a == "--release" || a == "--scene";
        if (takesValue) {
            auto v = value();
            if (!v) return usage(fill(trStd("padrob", "%1 needs a value"), {a}));
            if (a == "--time") {
                time = toNumber(*v);
                if (!time || !(*time > 0)) return usage(fill(trStd("padrob", "--time must be a positive number of seconds, not '%1'"), {*v}));
            } else if (a == "--dt") {
                auto d = toNumber(*v);
                if (!d || !(*d > 0)) return usage(fill(trStd("padrob", "--dt must be a positive number of seconds, not '%1'"), {*v}));
                dt = *d;
            } else if (a == "--rtol") {
                auto r = toNumber(*v);
                if (!r || !(*r > 0) || *r >= 1) return usage(fill(trStd("padrob", "--rtol must be a number between 0 and 1, not '%1'"), {*v}));
                rtol = *r;
            } else if (a == "--every") {
                auto n = toInteger(*v);
                if (!n || *n < 1) return usage(fill(trStd("padrob", "--every must be a whole number ≥ 1, not '%1'"), {*v}));
                every = *n;
            } else if (a == "--integrator") {
                if (*v == "rk4") adaptive = false;
                else if (*v == "adaptive") adaptive = true;
                else return usage(fill(trStd("padrob", "--integrator must be rk4 or adaptive, not '%1'"), {*v}));
            } else if (a == "--input") {
                inputPath = *v;
            } else if (a == "--input-log") {
                inputLogPath = *v;
            } else if (a == "--profile") {
                profileArg = *v;
            } else if (a == "--out") {
                outPath = *v;
            } else if (a == "--scene") {
                scenePath = *v;
            } else if (a == "--weld" || a == "--release") {
                std::string problem;
                auto w = parseWeldSwitch(a == "--weld", *v, problem);
                if (!w) return usage(problem);
                switches.push_back(*w);
            } else {
                const std::size_t eq = v->find('=');
                if (eq == std::string::npos) {
                    return usage(fill(trStd("padrob", "%1 takes J=VALUE (a joint id and a number), not '%2'"), {a, *v}));
                }
                (a == "--set" ? sets : rates).emplace_back(v->substr(0, eq), v->substr(eq + 1));
            }
            continue;
        }
        if (a.size() > 1 && a[0] == '-') return usage(fill(trStd("padrob", "unknown option '%1'"), {a}));
        if (!modelPath.empty()) return usage(trStd("padrob", "give one model"));
        modelPath = a;
    }
    if (modelPath.empty()) return usage(trStd("padrob", "no model given"));
    if (!time) return usage(trStd("padrob", "--time is required"));
    if (!inputPath.empty() && !inputLogPath.empty()) return usage(trStd("padrob", "--input and --input-log cannot be combined"));
    if (!profileArg.empty() && inputLogPath.empty()) return usage(trStd("padrob", "--profile goes with --input-log"));
    if (dt > *time) return usage(trStd("padrob", "--dt is longer than --time"));
    const double steps = std::ceil(*time / dt - 1e-9);
    if (steps > 1e9) return usage(trStd("padrob", "--time / --dt is more than 1e9 steps"));
    for (const WeldSwitch& w : switches) {
        if (w.t > *time) {
            return usage(w.prefix() + fill(trStd("padrob", "the time is after the end of the simulation (--time %1 s): "
                                                           "give a T between 0 and --time"),
                                           {fmtNumber(*time)}));
        }
    }

    // the model, with --set and --rate written into it as QI and VI: checked as the file's
    // own values are (limits, lengths a T 1 joint can reach, VI within VMAX, sizes)
    int status = kExitOk;
    const auto edit = [&](solver::ModelSpec& spec) -> std::string {
        for (const auto* list : {&sets, &rates}) {
            const char* option = list == &sets ? "--set" : "--rate";
            for (const auto& [js, vs] : *list) {
                auto id = toInteger(js);
                auto v = toNumber(vs);
                if (!id || !v || !std::isfinite(*v)) {
                    return "padrob simulate: " + fill(trStd("padrob", "%1 takes J=VALUE (a joint id and a number), not '%2'"),
                                                      {option, js + "=" + vs});
                }
                solver::JointSpec* joint = nullptr;
                for (solver::JointSpec& j : spec.joints)
                    if (*id >= INT_MIN && *id <= INT_MAX && j.id == static_cast<int>(*id)) joint = &j;
                if (!joint) return "padrob simulate: " + fill(trStd("padrob", "%1: the model has no joint %2"), {option, js});
                (list == &sets ? joint->qi : joint->vi) = *v;
            }
        }
        return {};
    };
    // --scene: its ground graphics are solids the model's touch (CONTACT, docs/contact.md)
    std::optional<solver::CompiledModel> scene;
    if (!scenePath.empty()) {
        int sceneStatus = kExitOk;
        scene = loadScene(scenePath, sceneStatus);
        if (!scene) return sceneStatus;
    }
    std::shared_ptr<const solver::Model> model =
        sets.empty() && rates.empty() && !scene ? loadAndCompile(modelPath, status)
                                                : loadAndCompile(modelPath, status, edit, scene ? &scene->spec : nullptr);
    if (!model) return status;
    const solver::Model& m = *model;

    // --weld / --release: the bodies must exist
    for (const WeldSwitch& w : switches) {
        for (long id : {w.a, w.b}) {
            if (id == 0 || (id >= INT_MIN && id <= INT_MAX && m.bodyIndex(static_cast<int>(id)) >= 0)) continue;
            std::vector<int> ids(m.bodyId.begin(), m.bodyId.end());
            std::sort(ids.begin(), ids.end());
            std::string list = trStd("padrob", "0 (the ground)");
            for (int i : ids) list += ", " + std::to_string(i);
            return usage(w.prefix() + fill(trStd("padrob", "the model has no body %1; its bodies are %2"), {std::to_string(id), list}));
        }
    }
    // applied in time order; at one time in command-line order
    std::stable_sort(switches.begin(), switches.end(), [](const WeldSwitch& x, const WeldSwitch& y) { return x.t < y.t; });

    // the input table, checked against the model's drives
    std::optional<solver::InputTable> inputs;
    std::vector<int> inputJoint;  // per input column: tree index
    if (!inputPath.empty()) {
        solver::Diagnostics diags(inputPath);
        inputs = solver::InputTable::readFile(inputPath, diags);
        if (inputs) {
            std::vector<int> drivenIds, jointIds;
            for (int j = 0; j < m.nb; ++j) {
                jointIds.push_back(m.jointId[j]);
                if (!passive && m.drive[j].type != solver::DriveType::None) drivenIds.push_back(m.jointId[j]);
            }
            solver::checkInputColumns(*inputs, drivenIds, jointIds, diags);
        }
        for (const solver::Diagnostic& d : diags) printDiagnostic(stderr, d);
        if (!inputs || diags.hasErrors()) return kUsage;
        for (std::size_t c = 0; c < inputs->columnCount(); ++c) inputJoint.push_back(m.jointIndex(inputs->jointId(c)));
    }

    // the input log, replayed through a station profile (trainer/): the station engine
    // runs on the simulated clock, one update per step
    std::unique_ptr<trainer::StationEngine> station;
    if (!inputLogPath.empty()) {
        std::string problem;
        station = replayStation(m, modelPath, inputLogPath, profileArg, passive, problem);
        if (!station) {
            printErr("padrob simulate: " + problem + "\n");
            return kUsage;
        }
    }

    // the output
    // (never onto a file this run reads: the model, its input table, log or profile)
    solver::CsvWriter out = outPath.empty() ? solver::CsvWriter()
                                            : solver::CsvWriter(outPath, {modelPath, inputPath, inputLogPath, profileArg});
    if (!out.ok()) {
        printErr("padrob simulate: " + i18n::text(out.errorText()).toStdString() + "\n");
        return kUsage;
    }
    // (a free joint's coordinates: one column group, at its slot 0; the massless bodies
    // between them: none)
    std::vector<int> joints, bodies;
    for (int j = 0; j < m.nb; ++j) {
        if (m.freeSlot[j] <= 0) joints.push_back(j);
        if (m.bodyId[j] >= 0) bodies.push_back(j);
    }
    std::sort(joints.begin(), joints.end(), [&](int a, int b) { return m.jointId[a] < m.jointId[b]; });
    std::sort(bodies.begin(), bodies.end(), [&](int a, int b) { return m.bodyId[a] < m.bodyId[b]; });
    // every joint in id order: tree joints (their coordinates) and loop-closing joints
    // (what they read at the loop's positions)
    struct JointColumn {
        int id = 0;
        int tree = -1;  // tree index, or −1
        int cut = -1;   // index in m.cuts, or −1
        solver::JointType type = solver::JointType::Revolute;
    };
    std::vector<JointColumn> jointColumns;
    for (int j : joints) jointColumns.push_back({m.jointId[j], j, -1, m.jointType[j]});
    for (std::size_t k = 0; k < m.cuts.size(); ++k) {
        jointColumns.push_back({m.cuts[k].jointId, -1, static_cast<int>(k), m.cuts[k].type});
    }
    std::sort(jointColumns.begin(), jointColumns.end(),
              [](const JointColumn& a, const JointColumn& b) { return a.id < b.id; });
    std::vector<std::string> header{"t"};
    // a free joint (T 3): three columns each, q<j>x, q<j>y, q<j>z (along B1's joint axes)
    for (const std::string prefix : {"q", "qd"}) {
        for (const JointColumn& c : jointColumns) {
            const std::string name = prefix + std::to_string(c.id);
            if (c.tree >= 0 && m.freeSlot[c.tree] == 0) {
                header.insert(header.end(), {name + "x", name + "y", name + "z"});
            } else {
                header.push_back(name);
            }
        }
    }
    for (const JointColumn& c : jointColumns) {
        if (c.type == solver::JointType::Actuator) header.push_back("ang" + std::to_string(c.id));
    }
    for (int b : bodies) {
        const std::string id = std::to_string(m.bodyId[b]);
        header.insert(header.end(), {"x" + id, "y" + id, "z" + id});
    }
    std::vector<int> driven;
    for (int j : joints) {
        if (!passive && m.drive[j].type != solver::DriveType::None) {
            driven.push_back(j);
            header.push_back("F" + std::to_string(m.jointId[j]));
        }
    }
    // fluid power: the chambers' pressures per CYL/HMOTOR drive (joint id order), then
    // every pump's supply pressure (pump id order)
    const bool fluidColumns = !passive;
    std::vector<int> pumpOrder(m.pumps.size());
    for (std::size_t p = 0; p < pumpOrder.size(); ++p) pumpOrder[p] = static_cast<int>(p);
    std::sort(pumpOrder.begin(), pumpOrder.end(), [&](int a, int b) { return m.pumps[a].id < m.pumps[b].id; });
    if (fluidColumns) {
        for (const solver::CompiledCircuit& c : m.circuits) {
            const std::string id = std::to_string(m.jointId[c.joint]);
            header.insert(header.end(), {"pA" + id, "pB" + id});
        }
        for (int p : pumpOrder) header.push_back("pP" + std::to_string(m.pumps[p].id));
    }
    header.push_back("E");
    out.writeHeader(header);

    // the simulation
    solver::SimulationOptions options;
    options.integrator.method = adaptive ? solver::IntegrationMethod::Adaptive : solver::IntegrationMethod::Rk4Fixed;
    options.integrator.step = dt;
    options.integrator.rtol = rtol;
    options.integrator.atol = rtol * 1e-2;
    options.drives = !passive;
    options.limits = !noLimits;
    solver::Simulation sim(model, options);

    std::vector<solver::SimulationEvent> events;
    std::vector<solver::CutReading> cutReadings;
    std::vector<solver::FreeJointMotion> freeMotion;
    auto writeRow = [&] {
        const solver::State& s = sim.state();
        const solver::Data& d = sim.data();
        out.add(s.t);
        cutReadings.clear();
        for (std::size_t k = 0; k < m.cuts.size(); ++k) cutReadings.push_back(solver::readCut(m, d, static_cast<int>(k)));
        freeMotion.clear();
        for (const JointColumn& c : jointColumns) {
            if (c.tree >= 0 && m.freeSlot[c.tree] == 0) {
                freeMotion.push_back(solver::freeJointMotion(m, d, s.q, s.qd, c.tree));
                for (int a = 0; a < 3; ++a) out.add(freeMotion.back().position[a]);
                continue;
            }
            out.add(c.tree >= 0 ? m.coordinate(c.tree, s.q[c.tree]) : cutReadings[static_cast<std::size_t>(c.cut)].q);
        }
        std::size_t nextFree = 0;
        for (const JointColumn& c : jointColumns) {
            if (c.tree >= 0 && m.freeSlot[c.tree] == 0) {
                for (int a = 0; a < 3; ++a) out.add(freeMotion[nextFree].velocity[a]);
                ++nextFree;
                continue;
            }
            out.add(c.tree >= 0 ? s.qd[c.tree] * m.coordinateRate(c.tree, s.q[c.tree])
                                : cutReadings[static_cast<std::size_t>(c.cut)].qd);
        }
        for (const JointColumn& c : jointColumns) {
            if (c.type != solver::JointType::Actuator) continue;
            out.add(c.tree >= 0 ? s.q[c.tree] : cutReadings[static_cast<std::size_t>(c.cut)].angle);
        }
        for (int b : bodies) {
            const Eigen::Vector3d c = solver::comPosition(m, d, b);
            out.add(c.x());
            out.add(c.y());
            out.add(c.z());
        }
        for (int j : driven) out.add(d.driveForce[j]);
        if (fluidColumns) {
            for (std::size_t c = 0; c < m.circuits.size(); ++c) {
                out.add(d.pressureA[static_cast<Eigen::Index>(c)]);
                out.add(d.pressureB[static_cast<Eigen::Index>(c)]);
            }
            for (int p : pumpOrder) out.add(d.supplyPressure[p]);
        }
        out.add(solver::mechanicalEnergy(m, d));
        out.endRow();
    };
    std::optional<solver::InputTable::Cursor> cursor;
    if (inputs) cursor.emplace(inputs->cursor());
    const long n = static_cast<long>(steps);
    std::string error;        // the solver's message in English
    solver::Text errorText;   // the same, translatable: what is printed
    std::string errorPrefix;  // "--weld 'T:A:B': " before a weld's or release's error
    // Prints the events; on failure drops the output and prints the error. Returns ok.
    auto report = [&](bool ok) {
        // whole rows before each event line when both streams go to one terminal
        if (!events.empty() && out.toStdout()) std::fflush(stdout);
        for (const solver::SimulationEvent& e : events) printErr(i18n::text(e.describeText(m)).toStdString() + "\n");
        events.clear();
        if (!ok) {
            out.abandon();
            printErr("padrob simulate: " + errorPrefix + i18n::text(errorText).toStdString() + "\n");
            if (error.rfind("the simulation failed at", 0) == 0) {
                printErr("padrob simulate: " +
                         (adaptive ? trStd("padrob", "the adaptive integrator failed too: check the model's masses, springs and forces")
                                   : fill(trStd("padrob", "run it again with a smaller --dt (now %1 s; e.g. --dt %2) or with "
                                                          "--integrator adaptive"),
                                          {fmtNumber(dt), fmtNumber(dt / 10)})) +
                         "\n");
            }
        }
        return ok;
    };
    // Makes and releases the welds due by time `now` (a switch within a billionth
    // of a step of a row's time applies there).
    const double tolerance = 1e-9 * dt;
    std::size_t nextSwitch = 0;
    auto applySwitches = [&](double now) {
        bool ok = true;
        while (ok && nextSwitch < switches.size() && switches[nextSwitch].t <= now + tolerance) {
            const WeldSwitch& w = switches[nextSwitch++];
            const int a = w.a == 0 ? -1 : m.bodyIndex(static_cast<int>(w.a));
            const int b = m.bodyIndex(static_cast<int>(w.b));
            ok = w.weld ? sim.weld(a, b, events, error, &errorText) : sim.release(a, b, events, error, &errorText);
            if (!ok) errorPrefix = w.prefix();
        }
        return report(ok);
    };
    for (long k = 0; k <= n; ++k) {
        const double t = std::min(*time, static_cast<double>(k) * dt);
        if (cursor) {
            cursor->seek(t);
            for (std::size_t c = 0; c < inputJoint.size(); ++c) sim.setCommand(inputJoint[c], cursor->value(c));
        }
        if (station) {
            station->update(t);
            const std::vector<double>& u = station->commands();
            for (int j = 0; j < m.nb; ++j) sim.setCommand(j, u[std::size_t(j)]);
        }
        if (!applySwitches(t)) return kModelErrors;
        if (k % every == 0 || k == n) writeRow();
        if (k == n) break;
        const double next = std::min(*time, static_cast<double>(k + 1) * dt);
        // a weld or release inside the step: stop exactly there
        while (nextSwitch < switches.size() && switches[nextSwitch].t < next - tolerance) {
            const double at = switches[nextSwitch].t;
            if (!report(sim.advanceTo(at, events, error, &errorText)) || !applySwitches(at)) return kModelErrors;
        }
        if (!report(sim.advanceTo(next, events, error, &errorText))) return kModelErrors;
    }
    if (!out.commit()) {
        printErr("padrob simulate: " + i18n::text(out.errorText()).toStdString() + "\n");
        return kUsage;
    }
    return kOk;
}

}  // namespace ide::cli
