#include "trainer/training/runner.h"

#include "trainer/station/profile_store.h"
#include "trainer/station/station_engine.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace trainer {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(TutorialRunner)
};

/// The engine a headless run uses: the profile without the devices it would open (no
/// serial port or card is touched), the model's drives.
std::unique_ptr<StationEngine> headlessEngine(const Tutorial& t, const StationProfile& profile, QString* error)
{
    auto engine = std::make_unique<StationEngine>();
    engine->setDrives(t.model->nb, drivesOf(*t.model));
    StationProfile p = profile;
    p.devices.clear();
    for (const ProfileIssue& i : engine->setProfile(p)) {
        if (i.error) {
            if (error) *error = i.text();
            return nullptr;
        }
    }
    return engine;
}

/// A virtual valve console: the autopilot's levers (raw 0 … 1023, rest 511.5, as the
/// serial DAQ box reads them).
class AutopilotConsole : public InputDevice {
public:
    explicit AutopilotConsole(int levers)
    {
        m_info.id = QStringLiteral("serial:autopilot");
        m_info.name = Tr::tr("Autopilot console");
        m_info.kind = DeviceKind::SerialDaq;
        for (int i = 0; i < levers; ++i) m_info.axes.append({Tr::tr("Lever %1").arg(i + 1), 0.0, kRest, kMax});
        m_sample.axes.assign(std::size_t(levers), kRest);
        m_next = m_sample.axes;
    }
    static constexpr double kMax = 1023.0, kRest = 511.5;
    /// Lever `axis` at `u` in [−1, 1].
    void set(int axis, double u)
    {
        m_next[std::size_t(axis)] = std::round(kRest + std::clamp(u, -1.0, 1.0) * (kMax - kRest));
    }
    void reset() { m_next.assign(m_sample.axes.size(), kRest); }
    const DeviceInfo& info() const override { return m_info; }
    void poll(double now) override
    {
        if (m_next != m_sample.axes || m_sample.time < 0) {
            m_sample.axes = m_next;
            m_sample.time = now;
            ++m_sample.count;
        }
    }
    const DeviceSample& sample() const override { return m_sample; }
    DeviceStatus status() const override { return DeviceStatus::Connected; }

private:
    DeviceInfo m_info;
    DeviceSample m_sample;
    std::vector<double> m_next;
};

/// The rate of joint j's drive at full lever towards err's side, in the modeler's
/// coordinate [m/s or rad/s]: HYD's VMAX/VMIN, a motor's no-load speed, a fluid-power
/// drive's valve flow over the area (or displacement) it fills (its compensated speed).
double fullLeverRate(const solver::Model& m, int j, double err)
{
    const solver::CompiledDrive& d = m.drive[std::size_t(j)];
    if (d.type == solver::DriveType::Motor) return d.w0;
    if (d.type == solver::DriveType::FluidPower && d.circuit >= 0 && std::size_t(d.circuit) < m.circuits.size()) {
        const solver::CompiledCircuit& c = m.circuits[std::size_t(d.circuit)];
        const double area = err > 0 ? c.areaA : c.areaB;
        return area > 0 ? c.qn / area : 0.0;
    }
    return err > 0 ? d.vmax : (d.vmin > 0 ? d.vmin : d.vmax);
}

/// How near joint j must come to its target in waypoint w: its tol=, else 1 mm or 0.2°.
double waypointTolerance(const solver::Model& m, const AutopilotWaypoint& w, int j)
{
    if (w.tolerance > 0) return w.tolerance;
    return m.jointType[std::size_t(j)] != solver::JointType::Revolute ? 1e-3 : 0.2 * std::numbers::pi / 180.0;
}

/// The least lever that still moves joint j towards its target: a HYD drive's 12 %
/// (past a real valve's dead band); a fluid-power drive's opening whose run-on after
/// the decision to stop (the lever returning at `leverRate`, then the spool's lag τ)
/// is half the tolerance, top·(u²/(2·leverRate) + u·τ) = tol/2, within 0.6 … 12 %
/// (0.6 %: three counts of a 10-bit lever).
double leastLever(const solver::Model& m, int j, double top, double tol, double leverRate)
{
    constexpr double kDeadBand = 0.12;
    const solver::CompiledDrive& d = m.drive[std::size_t(j)];
    if (d.type != solver::DriveType::FluidPower || d.circuit < 0 || !(top > 0)) return kDeadBand;
    const double tau = m.circuits[std::size_t(d.circuit)].tau;
    const double a = top / (2.0 * leverRate), b = top * tau, c = 0.5 * tol;
    const double u = (-b + std::sqrt(b * b + 4.0 * a * c)) / (2.0 * a);
    return std::clamp(u, 0.006, kDeadBand);
}

/// How far the lever of joint j may be open `way` from where it must stop: proportional
/// to the way left (full lever `approach` seconds of full speed away), and no more than
/// what the lever, returning at `leverRate` (then the spool's lag), stops within it.
double approachLever(const solver::Model& m, int j, double way, double top, double approach, double leverRate)
{
    if (!(top > 0)) return 1.0;
    double u = way / (top * approach);
    const solver::CompiledDrive& d = m.drive[std::size_t(j)];
    const double tau = d.type == solver::DriveType::FluidPower && d.circuit >= 0 ? m.circuits[std::size_t(d.circuit)].tau : 0.0;
    // run-on from lever u: top·(u²/(2·leverRate) + u·τ) = way
    const double a = top / (2.0 * leverRate), b = top * tau;
    u = std::min(u, (-b + std::sqrt(b * b + 4.0 * a * way)) / (2.0 * a));
    return std::min(u, 1.0);
}

/// Joint j's range in the modeler's coordinate (T 1: lengths), ±∞ without limits.
std::pair<double, double> coordinateRange(const solver::Model& m, int j)
{
    const double lo = m.lower[std::size_t(j)], hi = m.upper[std::size_t(j)];
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
        // one-sided: only prismatic and revolute joints keep their coordinate as θ
        if (m.jointType[std::size_t(j)] == solver::JointType::Actuator)
            return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
        return {lo, hi};
    }
    const double a = m.coordinate(j, lo), b = m.coordinate(j, hi);
    return {std::min(a, b), std::max(a, b)};
}

}  // namespace

bool tutorialProfile(const Tutorial& t, const QString& override, StationProfile& out, QString* error)
{
    if (override.isEmpty()) {
        out = t.profile;
        return true;
    }
    QList<ProfileIssue> issues;
    if (!ProfileStore().resolve(QString::fromStdString(t.modelFile), override, drivesOf(*t.model), out, issues)) {
        if (error) *error = issues.isEmpty() ? override : issues.first().text();
        return false;
    }
    return true;
}

bool runTutorialWithLog(std::shared_ptr<const Tutorial> tutorial, std::shared_ptr<const InputLog> log,
                        const StationProfile& profile, RunOutput& out, QString* error, double grace)
{
    std::unique_ptr<StationEngine> engine = headlessEngine(*tutorial, profile, error);
    if (!engine) return false;
    engine->setReplayOnly(true);
    for (auto& d : replayDevices(log)) engine->addDevice(d);
    TutorialSession session(tutorial);
    const double end = log->duration() + grace;
    while (!session.ended()) {
        engine->update(session.time());
        session.setCommands(engine->commands());
        if (!session.step()) break;
        if (session.time() > end) session.stop(TutorialEvent::Kind::InputEnded);
    }
    out.result = session.result();
    out.samples = session.samples();
    return true;
}

bool parseAutopilotPath(const QString& text, std::vector<AutopilotWaypoint>& out, QString* error)
{
    std::vector<AutopilotWaypoint> path;
    const QStringList lines = text.split('\n');
    for (int n = 0; n < lines.size(); ++n) {
        QString line = lines[n];
        if (const qsizetype hash = line.indexOf('#'); hash >= 0) line.truncate(hash);
        line = line.trimmed();
        if (line.isEmpty()) continue;
        AutopilotWaypoint w;
        w.line = n + 1;
        for (const QString& item : line.split(QRegularExpression("\\s+"), Qt::SkipEmptyParts)) {
            const qsizetype eq = item.indexOf('=');
            auto fail = [&](const QString& why) {
                if (error) *error = Tr::tr("line %1: %2").arg(n + 1).arg(why);
                return false;
            };
            if (eq <= 0) return fail(Tr::tr("expected id=value, found \"%1\"").arg(item));
            const QString key = item.left(eq).toLower();
            QString value = item.mid(eq + 1).toLower();
            int leverJoint = 0;  // lever=id:fraction
            if (key == "lever" && value.contains(':')) {
                bool isId = false;
                leverJoint = value.section(':', 0, 0).toInt(&isId);
                if (!isId) return fail(Tr::tr("\"%1\" is not a joint id").arg(value.section(':', 0, 0)));
                value = value.section(':', 1);
            }
            double scale = 1.0;
            if (value.endsWith("deg")) {
                value.chop(3);
                scale = std::numbers::pi / 180.0;
            }
            bool ok = false;
            const double v = value.toDouble(&ok) * scale;
            if (!ok || !std::isfinite(v)) return fail(Tr::tr("\"%1\" is not a number").arg(item.mid(eq + 1)));
            if (key == "wait") {
                if (v < 0) return fail(Tr::tr("wait must not be negative"));
                w.wait = v;
            } else if (key == "tol") {
                if (v <= 0) return fail(Tr::tr("tol must be greater than 0"));
                w.tolerance = v;
            } else if (key == "ramp") {
                if (!(v > 0)) return fail(Tr::tr("ramp must be greater than 0"));
                w.ramp = v;
            } else if (key == "stall") {
                if (!(v > 0)) return fail(Tr::tr("stall must be greater than 0"));
                w.stall = v;
            } else if (key == "lever") {
                if (!(v > 0 && v <= 1)) return fail(Tr::tr("lever must be greater than 0 and at most 1"));
                if (leverJoint != 0)
                    w.jointLever.emplace_back(leverJoint, v);
                else
                    w.lever = v;
            } else {
                bool isId = false;
                const int id = key.toInt(&isId);
                if (!isId) return fail(Tr::tr("\"%1\" is not a joint id, wait, tol, lever, ramp or stall").arg(key));
                w.targets.emplace_back(id, v);
            }
        }
        if ((w.lever > 0 || w.ramp > 0 || w.stall > 0 || !w.jointLever.empty()) && w.targets.empty()) {
            if (error) *error = Tr::tr("line %1: lever=, ramp= and stall= go with joint targets").arg(n + 1);
            return false;
        }
        path.push_back(std::move(w));
    }
    out = std::move(path);
    return true;
}

bool recordWithAutopilot(std::shared_ptr<const Tutorial> tutorial, const std::vector<AutopilotWaypoint>& path,
                         const StationProfile& profile, const QString& logPath, RunOutput& out, QString* error,
                         CameraPath* camera)
{
    const Tutorial& t = *tutorial;
    const solver::Model& m = *t.model;
    // every drive a target moves needs a lever of the console in the profile
    struct Lever {
        int axis = -1;
        double factor = 1.0;  // u = factor · lever
    };
    std::vector<Lever> lever(std::size_t(m.nb));
    int axes = 0;
    QList<Mapping> maps = profile.always;
    if (!profile.banks.isEmpty()) maps += profile.banks.first().mappings;
    for (const Mapping& mp : maps) {
        const bool console = mp.device == "serial" || mp.device.startsWith("serial:");
        const int j = m.jointIndex(mp.drive);
        if (!console || j < 0 || mp.gain == 0 || lever[std::size_t(j)].axis >= 0) continue;
        lever[std::size_t(j)] = {mp.axis, mp.gain * mp.sign};
        axes = std::max(axes, mp.axis + 1);
    }
    // the fluid-power sections each lever opens, for the pumps' flow (docs/hydraulics.md)
    struct Feed {
        int axis = -1;
        double factor = 1.0;
        int pump = -1;
        double qn = 0;  // [m^3/s] at full opening
    };
    std::vector<Feed> feeds;
    for (int j = 0; j < m.nb; ++j) {
        const solver::CompiledDrive& d = m.drive[std::size_t(j)];
        if (d.type != solver::DriveType::FluidPower || lever[std::size_t(j)].axis < 0 || !t.enabled[std::size_t(j)]) continue;
        if (d.circuit < 0 || std::size_t(d.circuit) >= m.circuits.size()) continue;
        const solver::CompiledCircuit& c = m.circuits[std::size_t(d.circuit)];
        feeds.push_back({lever[std::size_t(j)].axis, lever[std::size_t(j)].factor, c.pump, c.qn});
    }
    for (const AutopilotWaypoint& w : path) {
        for (const auto& [id, most] : w.jointLever) {
            if (m.jointIndex(id) < 0) {
                if (error) *error = Tr::tr("line %1: the model has no joint %2").arg(w.line).arg(id);
                return false;
            }
        }
        for (const auto& [id, value] : w.targets) {
            const int j = m.jointIndex(id);
            if (j < 0) {
                if (error) *error = Tr::tr("line %1: the model has no joint %2").arg(w.line).arg(id);
                return false;
            }
            if (lever[std::size_t(j)].axis < 0) {
                if (error) *error = Tr::tr("line %1: the profile \"%2\" gives joint %3 no lever of a serial console").arg(w.line).arg(profile.name).arg(id);
                return false;
            }
            if (!t.enabled[std::size_t(j)]) {
                if (error) *error = Tr::tr("line %1: joint %2's drive is not enabled in this tutorial").arg(w.line).arg(id);
                return false;
            }
        }
    }
    std::unique_ptr<StationEngine> engine = headlessEngine(t, profile, error);
    if (!engine) return false;
    auto console = std::make_shared<AutopilotConsole>(axes);
    engine->addDevice(console);
    InputRecorder recorder;
    if (!recorder.start(logPath, 0.0, error)) return false;
    engine->setRecorder(&recorder);

    TutorialSession session(tutorial);
    constexpr double kSettle = 0.3;     // levers centred at the start (the station arms them)
    constexpr double kLeverRate = 2.0;  // full travel in 0.5 s: no jerk (a waypoint's ramp= changes it)
    double leverRate = kLeverRate;      // the waypoint's, kept while the levers return after it
    constexpr double kApproach = 0.6;   // [s] of full speed from the target the lever starts closing
    constexpr double kPumpShare = 0.95; // of a pump's flow the levers may ask for together
    constexpr double kStopSpeed = 0.3;  // of full speed a joint not aimed at meets its end stop with
    constexpr double kAtStop = 5e-4;    // [m or rad] on its stop: the lever no longer eased
    constexpr double kNear = 5.0;       // within this many tolerances of its target a joint may be swinging about it
    constexpr double kStill = 0.25;     // [s] arrived: within tolerance, and moving less than it in this long
    std::vector<double> levers(std::size_t(axes), 0.0);
    std::vector<char> scaled(std::size_t(axes), 0);
    // the speed each joint has shown per unit of command, towards + and −: a load that
    // runs ahead of its oil (lowering without a counterbalance valve) moves faster than
    // the valve's flow says, and the lever must close sooner
    std::vector<double> shownUp(std::size_t(m.nb), -1.0), shownDown(std::size_t(m.nb), -1.0);  // −1: not seen yet
    std::vector<double> steadyU(std::size_t(m.nb), 0.0);  // each command, followed over 0.15 s
    std::vector<double> lastSign(std::size_t(m.nb), 0.0);  // the way each joint was last pushed
    // each joint's speed, its peaks held and fading over 0.5 s: a load swinging on its oil
    // passes through zero speed twice a cycle without having settled
    std::vector<double> swing(std::size_t(m.nb), 0.0);
    auto shown = [&](int j, double dir) { return dir > 0 ? shownUp[std::size_t(j)] : shownDown[std::size_t(j)]; };
    std::size_t next = 0;
    std::size_t wayStarted = std::size_t(-1);  // the waypoint being flown
    double wayEase = 1.0;                      // its levers' easing (lever=), held until it is reached
    std::vector<double> wayAsked(std::size_t(m.nb), 0.0);  // the most each joint's lever has asked in it
    std::vector<double> stallAt(std::size_t(m.nb), 0.0);   // stall=: where its joints were when they last moved
    double stallSince = 0.0;                               // and when
    auto markStall = [&](const AutopilotWaypoint& w, double now) {
        const solver::State& st = session.simulation().state();
        for (const auto& [id, value] : w.targets) {
            const int j = m.jointIndex(id);
            stallAt[std::size_t(j)] = m.coordinate(j, st.q[j]);
        }
        stallSince = now;
    };
    double waitUntil = kSettle;
    bool waiting = true;
    const double dt = 1e-3;
    double nextCamera = 0.0;
    Eigen::Vector3d look = Eigen::Vector3d::Zero();
    constexpr double kReadPeriod = 0.02;
    double lastRead = -1.0;
    while (!session.ended()) {
        const double now = session.time();
        std::vector<double> want(std::size_t(axes), 0.0);
        if (waiting) {
            if (now >= waitUntil) waiting = false;
        }
        if (!waiting && next < path.size()) {
            const AutopilotWaypoint& w = path[next];
            if (next != wayStarted) {
                wayStarted = next;
                markStall(w, now);
                wayEase = 1.0;
                std::fill(wayAsked.begin(), wayAsked.end(), 0.0);
            }
            if (!w.targets.empty()) leverRate = w.ramp > 0 ? 1.0 / w.ramp : kLeverRate;
            if (w.targets.empty()) {
                waitUntil = now + w.wait;
                waiting = true;
                ++next;
            } else {
                bool arrived = true;
                const solver::State& st = session.simulation().state();
                // the joints this waypoint moves: their command (before easing) and the
                // least lever that still moves each one
                struct Aim {
                    int joint;
                    double least;
                    double asked;  // its lever before easing
                };
                std::vector<Aim> aims;
                for (const auto& [id, value] : w.targets) {
                    const int j = m.jointIndex(id);
                    const double q = m.coordinate(j, st.q[j]);
                    const double tol = waypointTolerance(m, w, j);
                    const double err = value - q;
                    // a fluid-power joint rides on its oil: it may overshoot and swing about
                    // the target (a HYD joint stops when its lever closes)
                    const bool swings = m.drive[std::size_t(j)].type == solver::DriveType::FluidPower;
                    if (std::abs(err) <= tol) {
                        // there, and settling (its lever closed): not merely passing through
                        if (swings && swing[std::size_t(j)] * kStill > tol) arrived = false;
                        continue;
                    }
                    arrived = false;
                    const double top = std::max(fullLeverRate(m, j, err), shown(j, err));
                    double u = approachLever(m, j, std::abs(err), top, kApproach, leverRate);
                    if (err < 0) u = -u;
                    // not chasing a swing: near the target, the other way only once the
                    // joint has settled (a load bouncing on its oil overshoots it; pushing
                    // back at once feeds the swing)
                    double& last = lastSign[std::size_t(j)];
                    if (swings && u * last < 0 && std::abs(err) < kNear * tol && swing[std::size_t(j)] * kStill > tol) u = 0.0;
                    if (u == 0.0) continue;
                    last = u > 0 ? 1.0 : -1.0;
                    const Lever& lv = lever[std::size_t(j)];
                    want[std::size_t(lv.axis)] = u / lv.factor;
                    aims.push_back({j, leastLever(m, j, top, tol, leverRate), std::abs(u)});
                }
                // a lever that also moves joints this waypoint does not aim (one lever,
                // both claws): eased as such a joint nears its end stop, so that it
                // arrives at under a third of its speed (not a limit bang)
                for (int j = 0; j < m.nb && !arrived; ++j) {
                    const Lever& lv = lever[std::size_t(j)];
                    if (lv.axis < 0 || !t.enabled[std::size_t(j)]) continue;
                    double& wa = want[std::size_t(lv.axis)];
                    const double u = wa * lv.factor;  // joint j's command
                    if (u == 0.0) continue;
                    bool aimed = false;
                    for (const auto& target : w.targets) aimed = aimed || m.jointIndex(target.first) == j;
                    if (aimed) continue;
                    const auto [lo, hi] = coordinateRange(m, j);
                    const double q = m.coordinate(j, st.q[j]);
                    const double way = u > 0 ? hi - q : q - lo;  // to the stop it moves towards
                    if (!std::isfinite(way) || way <= kAtStop) continue;
                    const double top = std::max(fullLeverRate(m, j, u), shown(j, u));
                    if (!(top > 0)) continue;
                    const double most = std::max(approachLever(m, j, way, top, kApproach, leverRate), kStopSpeed);
                    if (std::abs(u) > most) wa *= most / std::abs(u);
                }
                // a gentle move (lever=): the levers eased together, each keeping its share
                // so that the joints still arrive together, until none (or that joint's)
                // opens further than asked; the easing holds until the waypoint is reached
                // (else the others would surge when the slowest arrives)
                auto cap = [&](int j) {
                    double most = w.lever > 0 ? w.lever : 1.0;
                    for (const auto& [id, c] : w.jointLever) {
                        if (m.jointIndex(id) == j) most = std::min(most, c);
                    }
                    return most;
                };
                double ease = wayEase;
                for (const Aim& a : aims) {
                    double& first = wayAsked[std::size_t(a.joint)];
                    first = std::max(first, a.asked);  // the most it has asked in this waypoint
                    const double most = cap(a.joint);
                    if (first > most) ease = std::min(ease, most / first);
                }
                wayEase = ease;
                // each lever at most its share (ease × where it began): the joints keep
                // moving in step at a steady pace, then close in on the target together
                for (const Aim& a : aims) {
                    const Lever& lv = lever[std::size_t(a.joint)];
                    double& wa = want[std::size_t(lv.axis)];
                    const double u = wa * lv.factor;
                    // never below the least lever that still moves it (within its cap), so
                    // that it finishes
                    const double least = std::min(a.least, cap(a.joint));
                    const double most = std::max(ease * wayAsked[std::size_t(a.joint)], least);
                    const double v = std::max(std::min(std::abs(u), most), least);
                    wa = (u > 0 ? v : -v) / lv.factor;
                }
                // stall=: pushed against something, its joints have stopped short of their
                // targets (each moved less than its tolerance for that long): reached
                if (!arrived && w.stall > 0) {
                    bool moved = false;
                    for (const auto& [id, value] : w.targets) {
                        const int j = m.jointIndex(id);
                        moved = moved || std::abs(m.coordinate(j, st.q[j]) - stallAt[std::size_t(j)]) > waypointTolerance(m, w, j);
                    }
                    if (moved) {
                        markStall(w, now);
                    } else if (now - stallSince >= w.stall) {
                        arrived = true;
                    }
                }
                if (arrived) {
                    waitUntil = now + std::max(w.wait, 0.2);
                    waiting = true;
                    ++next;
                }
            }
        } else if (!waiting && next >= path.size()) {
            // the path is flown: let the tutorial finish (a dwell) or end it
            if (now > waitUntil + 2.0) break;
        }
        const bool read = now >= lastRead + kReadPeriod - 1e-9;
        if (read) lastRead = now;
        for (int a = 0; a < axes; ++a) {
            double& l = levers[std::size_t(a)];
            const double target = want[std::size_t(a)];
            l += std::clamp(target - l, -leverRate * dt, leverRate * dt);
        }
        // a careful operator does not ask a pump for more than it gives: the levers that
        // share one are eased back together (each keeps its share, so the joints still
        // move in step) to what the pump delivers, with a margin
        for (std::size_t p = 0; p < m.pumps.size(); ++p) {
            double demand = 0;
            for (const Feed& f : feeds) {
                if (f.pump == int(p)) demand += f.qn * std::min(1.0, std::abs(f.factor * levers[std::size_t(f.axis)]));
            }
            const double budget = kPumpShare * m.pumps[p].qmax;
            if (!(demand > budget)) continue;
            std::fill(scaled.begin(), scaled.end(), 0);
            for (const Feed& f : feeds) {
                if (f.pump != int(p) || scaled[std::size_t(f.axis)]) continue;
                scaled[std::size_t(f.axis)] = 1;
                levers[std::size_t(f.axis)] *= budget / demand;
            }
        }
        // the console is read at 50 Hz, in whole ADC counts, as the DAQ box sends them
        if (read) {
            for (int a = 0; a < axes; ++a) console->set(a, levers[std::size_t(a)]);
        }
        engine->update(now);
        session.setCommands(engine->commands());
        session.step();
        {
            const solver::State& st = session.simulation().state();
            for (int j = 0; j < m.nb; ++j) {
                const double speed = std::abs(st.qd[j] * m.coordinateRate(j, st.q[j]));
                swing[std::size_t(j)] = std::max(speed, swing[std::size_t(j)] * (1.0 - dt / 0.5));
                const double u = st.u[j];
                double& us = steadyU[std::size_t(j)];
                us += (u - us) * dt / 0.15;
                // learnt only while the lever is held (a joint lags a lever that moves)
                if (lever[std::size_t(j)].axis < 0 || std::abs(u) < 0.05 || std::abs(u - us) > 0.1 * std::abs(u)) continue;
                const double rate = st.qd[j] * m.coordinateRate(j, st.q[j]);
                if (rate * u <= 0) continue;
                double& g = u > 0 ? shownUp[std::size_t(j)] : shownDown[std::size_t(j)];
                if (g < 0) g = std::abs(rate / u);
                g += (std::abs(rate / u) - g) * dt / 0.3;  // smoothed over 0.3 s
            }
        }
        if (camera && now >= nextCamera - 1e-9) {
            nextCamera = now + 0.5;
            const Eigen::Vector3d p = session.trackPoint();
            look = camera->empty() ? p : Eigen::Vector3d(look + 0.3 * (p - look));
            const double heading = std::atan2(look.y(), look.x());
            camera->add({now, look, Eigen::Vector2d(look.x(), look.y()).norm() + 4.5,
                         heading + std::numbers::pi + 0.6, 0.5});
        }
    }
    engine->setRecorder(nullptr);
    // the last line marks the end of the run: a log holds changes only, and the levers
    // may have been held since the last one
    recorder.record(session.time(), *console, console->sample());
    if (!recorder.stop(error)) return false;
    out.result = session.result();
    out.samples = session.samples();
    return true;
}

}  // namespace trainer
