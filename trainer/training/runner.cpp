#include "trainer/training/runner.h"

#include "trainer/station/profile_store.h"
#include "trainer/station/station_engine.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
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
            } else {
                bool isId = false;
                const int id = key.toInt(&isId);
                if (!isId) return fail(Tr::tr("\"%1\" is not a joint id, wait or tol").arg(key));
                w.targets.emplace_back(id, v);
            }
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
    for (const AutopilotWaypoint& w : path) {
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
    constexpr double kLeverRate = 2.0;  // full travel in 0.5 s: no jerk
    constexpr double kApproach = 0.6;   // [s] of full speed from the target the lever starts closing
    std::vector<double> levers(std::size_t(axes), 0.0);
    std::size_t next = 0;
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
            if (w.targets.empty()) {
                waitUntil = now + w.wait;
                waiting = true;
                ++next;
            } else {
                bool arrived = true;
                for (const auto& [id, value] : w.targets) {
                    const int j = m.jointIndex(id);
                    const double q = m.coordinate(j, session.simulation().state().q[j]);
                    const solver::CompiledDrive& d = m.drive[std::size_t(j)];
                    const bool linear = m.jointType[std::size_t(j)] != solver::JointType::Revolute;
                    const double tol = w.tolerance > 0 ? w.tolerance : (linear ? 1e-3 : 0.2 * std::numbers::pi / 180.0);
                    const double err = value - q;
                    if (std::abs(err) <= tol) continue;
                    arrived = false;
                    const double top = d.type == solver::DriveType::Motor ? d.w0 : (err > 0 ? d.vmax : (d.vmin > 0 ? d.vmin : d.vmax));
                    double u = top > 0 ? err / (top * kApproach) : (err > 0 ? 1.0 : -1.0);
                    u = std::clamp(u, -1.0, 1.0);
                    if (std::abs(u) < 0.12) u = u > 0 ? 0.12 : -0.12;  // past the dead band
                    const Lever& lv = lever[std::size_t(j)];
                    want[std::size_t(lv.axis)] = u / lv.factor;
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
            l += std::clamp(target - l, -kLeverRate * dt, kLeverRate * dt);
            // the console is read at 50 Hz, in whole ADC counts, as the DAQ box sends them
            if (read) console->set(a, l);
        }
        engine->update(now);
        session.setCommands(engine->commands());
        session.step();
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
