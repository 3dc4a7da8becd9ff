#include "ide/studio/app/frame_bench.h"

#include "ide/paths/paths.h"

#include "ide/studio/app/main_window.h"
#include "ide/studio/sim/simulation_runner.h"
#include "ide/studio/view/scene_file.h"
#include "ide/studio/view/viewport.h"
#include "ide/studio/view/viewport_layout.h"
#include "trainer/input/keyboard_device.h"
#include "trainer/station/profile.h"
#include "trainer/station/station.h"

#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QTextStream>
#include <QThread>
#include <QTimer>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <thread>
#include <vector>

#include <time.h>
#include <unistd.h>

namespace studio {

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kPresses = 60;             // key presses timed for the latency
constexpr double kSinePeriod = 8.0;      // [s] of the drives' commands
constexpr double kSineAmplitude = 0.6;   // of the commands (u in −1 … 1)

/// Seconds since this process started (its start time in /proc/self/stat, clock ticks
/// since boot, against CLOCK_BOOTTIME; 10 ms resolution), or −1 when unknown.
double secondsSinceProcessStart()
{
    QFile f(QStringLiteral("/proc/self/stat"));
    if (!f.open(QIODevice::ReadOnly)) return -1;
    const QByteArray stat = f.readAll();
    // "pid (comm) state ppid …": the command may hold spaces; field 22 is starttime
    const int close = stat.lastIndexOf(')');
    if (close < 0) return -1;
    const QList<QByteArray> fields = stat.mid(close + 2).split(' ');
    if (fields.size() < 20) return -1;
    bool ok = false;
    const double ticks = fields[19].toDouble(&ok);
    const long hz = sysconf(_SC_CLK_TCK);
    timespec now{};
    if (!ok || hz <= 0 || clock_gettime(CLOCK_BOOTTIME, &now) != 0) return -1;
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec) - ticks / double(hz);
}

/// CPU time this process has used, all its threads together [ms].
double processCpuMillis()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

/// Runs the event loop for `ms` milliseconds (timers fire, windows draw).
void wait(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

/// Runs the event loop until `done` (checked every 2 ms) or `timeoutMs`; false on timeout.
bool waitFor(const std::function<bool()>& done, int timeoutMs)
{
    QElapsedTimer clock;
    clock.start();
    while (!done()) {
        if (clock.elapsed() > timeoutMs) return false;
        wait(2);
    }
    return true;
}

/// Nearest-rank percentile `p` (0 … 1) of sorted `v`; 0 when empty.
double percentile(const std::vector<double>& sorted, double p)
{
    if (sorted.empty()) return 0;
    const auto n = sorted.size();
    const auto rank = std::clamp<std::size_t>(std::size_t(std::ceil(p * double(n))), 1, n);
    return sorted[rank - 1];
}

QJsonObject summary(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return QJsonObject{{"median", percentile(v, 0.5)},
                       {"p90", percentile(v, 0.9)},
                       {"p99", percentile(v, 0.99)},
                       {"max", v.empty() ? 0.0 : v.back()}};
}

QJsonObject periods(const StepPeriodHistogram& h, double nominalMicros)
{
    return QJsonObject{{"steps", double(h.count)},
                       {"nominal_us", nominalMicros},
                       {"median_us", h.median()},
                       {"p99_us", h.percentile(0.99)},
                       {"p999_us", h.percentile(0.999)},
                       {"min_us", h.minMicros},
                       {"max_us", h.maxMicros},
                       {"max_jitter_us", h.maxJitter(nominalMicros)}};
}

QString fmt(double v, int decimals = 1)
{
    return QString::number(v, 'f', decimals);
}

/// Frame times of the screens of a ViewportLayout: every frame's drawing time (Viewport::frameTimed), per screen.
class FrameLog : public QObject {
public:
    explicit FrameLog(ViewportLayout* layout) : m_layout(layout)
    {
        for (int i = 0; i < layout->screens(); ++i) {
            m_ms.emplace_back();
            connect(layout->viewport(i), &Viewport::frameTimed, this, [this, i](double ms) {
                m_ms[std::size_t(i)].push_back(ms);
                if (i == 0) m_ends.push_back(Clock::now());
            });
        }
    }
    void clear()
    {
        for (auto& v : m_ms) v.clear();
        m_ends.clear();
    }
    /// Frames every screen has drawn.
    std::size_t frames() const
    {
        std::size_t n = m_ends.size();
        for (const auto& v : m_ms) n = std::min(n, v.size());
        return n;
    }
    /// Time to draw frame k: its drawing times summed over the screens [ms].
    std::vector<double> renderMillis() const
    {
        std::vector<double> out(frames(), 0.0);
        for (const auto& v : m_ms) {
            for (std::size_t k = 0; k < out.size(); ++k) out[k] += v[k];
        }
        return out;
    }
    /// Time between the ends of consecutive frames of the first screen [ms].
    std::vector<double> intervals() const
    {
        std::vector<double> out;
        for (std::size_t k = 1; k < m_ends.size(); ++k)
            out.push_back(std::chrono::duration<double, std::milli>(m_ends[k] - m_ends[k - 1]).count());
        return out;
    }

private:
    ViewportLayout* m_layout;
    std::vector<std::vector<double>> m_ms;
    std::vector<Clock::time_point> m_ends;
};

}  // namespace

int runFrameBench(const FrameBenchOptions& o)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    const int frames = std::max(1, o.frames);
    // settings of its own: the user's layout, recent files and last scene stay as they are
    QCoreApplication::setApplicationName(QStringLiteral("padrob-studio-bench"));

    const QString model = QFileInfo(o.modelPath.isEmpty() ? paths::defaultModel() : o.modelPath).absoluteFilePath();
    if (!QFileInfo(model).isFile()) {
        err << QCoreApplication::translate("studio::FrameBench", "Cannot read the model %1.")
                   .arg(QDir::toNativeSeparators(model))
            << Qt::endl;
        return 1;
    }
    QJsonObject result{{"model", model}, {"frames", frames}};

    // ---- start-up: the window, the model, the scene, and its first frame
    MainWindow window;
    window.resize(1920, 1080);
    window.move(0, 0);
    for (QDockWidget* d : window.findChildren<QDockWidget*>()) d->hide();  // the 3D view fills the window
    ViewportLayout* layout = window.viewports();
    QString sceneFile;
    bool wantScene = false;
    if (!o.scenePath.isEmpty()) {
        const SceneFile scene = loadSceneFile(o.scenePath);
        if (scene.bundle) {
            wantScene = true;
            sceneFile = QFileInfo(o.scenePath).absoluteFilePath();
        } else {
            result.insert("scene_error", scene.error);
            err << scene.error << Qt::endl;
        }
    }
    result.insert("scene", sceneFile);
    double startupProcess = -1, startupMain = -1;
    QMetaObject::Connection first = QObject::connect(layout->viewport(0), &Viewport::frameTimed, &window, [&](double) {
        Viewport* v = layout->viewport(0);
        if (startupMain >= 0 || !window.bundle() || v->bundle() != window.bundle() || (wantScene && !v->scene()))
            return;
        startupMain = 1e-6 * double(o.sinceMain.nsecsElapsed());
        startupProcess = 1e3 * secondsSinceProcessStart();
    });
    window.show();
    if (!window.openFile(model)) return 1;  // (said in a message box)
    if (wantScene) window.loadScene(sceneFile);
    if (!waitFor([&] { return startupMain >= 0; }, 60000)) {
        err << QCoreApplication::translate("studio::FrameBench", "The model %1 was not drawn (does it have errors?).")
                   .arg(QDir::toNativeSeparators(model))
            << Qt::endl;
        return 1;
    }
    QObject::disconnect(first);
    result.insert("startup_ms", startupProcess >= 0 ? startupProcess : startupMain);
    result.insert("startup_from_main_ms", startupMain);
    result.insert("window", QJsonObject{{"width", window.width()}, {"height", window.height()}});
    result.insert("cpus", QThread::idealThreadCount());
    {
        const Viewport* v = layout->viewport(0);
        result.insert("renderer", v->renderer());
        // where the light is computed (Viewport::setLighting, --lighting)
        result.insert("lighting", v->lightsPerVertex() ? QStringLiteral("vertex") : QStringLiteral("pixel"));
    }

    // ---- the simulation, every drive following a slow sine
    SimulationRunner* runner = window.runner();
    const std::shared_ptr<const ModelBundle> bundle = window.bundle();
    const QList<trainer::DriveInfo> drives = trainer::drivesOf(*bundle->model);
    QElapsedTimer simClock;
    simClock.start();
    QTimer sines;
    sines.setInterval(10);
    QObject::connect(&sines, &QTimer::timeout, &window, [&] {
        const double t = 1e-3 * double(simClock.elapsed());
        for (int k = 0; k < drives.size(); ++k) {
            const double phase = 2 * std::numbers::pi * (t / kSinePeriod) + 0.9 * k;
            runner->setCommand(drives[k].treeJoint, kSineAmplitude * std::sin(phase));
        }
    });
    sines.start();
    window.run();
    if (!waitFor([&] { return runner->latest() && runner->latest()->running; }, 5000)) {
        err << QCoreApplication::translate("studio::FrameBench", "The simulation does not run.") << Qt::endl;
        return 1;
    }
    const double nominal = 1e6 * runner->timeStep();
    StepPeriodHistogram all;
    auto failed = [&] {
        const auto s = runner->latest();
        return !s || !s->error.empty();
    };

    // ---- frames: one view, then three
    QJsonObject views;
    QStringList lines;
    std::vector<int> layouts;
    if (o.views == 0 || o.views == 1) layouts.push_back(1);
    if (o.views == 0 || o.views == 3) layouts.push_back(3);
    for (int n : layouts) {
        layout->setScreens(n);
        FrameLog log(layout);
        // warm-up: every screen made its context, uploaded and drew a few frames
        if (!waitFor([&] { return log.frames() >= 3; }, 30000)) {
            err << QCoreApplication::translate("studio::FrameBench", "The %n view(s) do not draw.", nullptr, n)
                << Qt::endl;
            return 1;
        }
        const QSize size = layout->viewport(0)->size();

        // paced: the window's 60 Hz poll timer draws each new snapshot
        log.clear();
        runner->resetStepPeriods();
        waitFor([&] { return log.frames() >= std::size_t(frames) + 1; }, frames * 500 + 10000);
        const StepPeriodHistogram pacedPeriods = runner->stepPeriods();
        const std::vector<double> pacedRender = log.renderMillis();
        const std::vector<double> pacedInterval = log.intervals();
        all.merge(pacedPeriods);

        // unpaced: new poses and a frame on every screen, back to back (drawn and
        // swapped to its window before renderNow() returns)
        log.clear();
        runner->resetStepPeriods();
        wait(5);
        std::vector<double> frameMs;
        std::vector<double> cpuMs;  // the process's CPU time per frame (all threads: GUI, llvmpipe, solver)
        for (int k = 0; k < frames; ++k) {
            const double c0 = processCpuMillis();
            const auto t0 = Clock::now();
            layout->setSnapshot(runner->latest());
            layout->renderNow();
            frameMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
            cpuMs.push_back(processCpuMillis() - c0);
        }
        const StepPeriodHistogram unpacedPeriods = runner->stepPeriods();
        const std::vector<double> unpacedRender = log.renderMillis();
        all.merge(unpacedPeriods);
        QCoreApplication::processEvents();
        if (failed()) break;

        const QJsonObject paced{{"frames", int(pacedRender.size())},
                                {"interval_ms", summary(pacedInterval)},
                                {"render_ms", summary(pacedRender)},
                                {"solver", periods(pacedPeriods, nominal)}};
        const QJsonObject frameSummary = summary(frameMs);
        const double fps = frameSummary["median"].toDouble() > 0 ? 1000 / frameSummary["median"].toDouble() : 0;
        const QJsonObject unpaced{{"frames", int(frameMs.size())},
                                  {"frame_ms", frameSummary},
                                  {"render_ms", summary(unpacedRender)},
                                  {"cpu_ms", summary(cpuMs)},
                                  {"fps", fps},
                                  {"solver", periods(unpacedPeriods, nominal)}};
        views.insert(QString::number(n), QJsonObject{{"viewport", QJsonObject{{"width", size.width()},
                                                                               {"height", size.height()}}},
                                                     {"paced", paced},
                                                     {"unpaced", unpaced}});
        auto ms = [](const QJsonObject& s) {
            return QStringLiteral("median %1 ms, 99% %2 ms").arg(fmt(s["median"].toDouble()), fmt(s["p99"].toDouble()));
        };
        lines << QStringLiteral("%1 view(s) of %2 x %3:").arg(n).arg(size.width()).arg(size.height())
              << QStringLiteral("  paced (60 Hz): interval %1; drawing %2; solver period median %3 us, 99.9% %4 us, "
                                "max %5 us")
                     .arg(ms(paced["interval_ms"].toObject()), ms(paced["render_ms"].toObject()),
                          fmt(pacedPeriods.median()), fmt(pacedPeriods.percentile(0.999)),
                          fmt(pacedPeriods.maxMicros, 0))
              << QStringLiteral("  back to back: frame %1 (%2 frames/s); drawing %3; CPU time per frame (all "
                                "threads) %4; solver period median %5 us, 99.9% %6 us, max %7 us")
                     .arg(ms(frameSummary), fmt(fps), ms(unpaced["render_ms"].toObject()),
                          ms(unpaced["cpu_ms"].toObject()), fmt(unpacedPeriods.median()),
                          fmt(unpacedPeriods.percentile(0.999)), fmt(unpacedPeriods.maxMicros, 0));
    }
    result.insert("views", views);

    // ---- latency: key presses through the station while the window draws at 60 Hz
    sines.stop();
    QJsonObject latency;
    std::vector<double> micros;
    int timeouts = 0;
    if (!drives.isEmpty() && !failed()) {
        const trainer::DriveInfo drive = drives.front();
        trainer::StationProfile profile;
        profile.name = QStringLiteral("frame bench");
        profile.always.append({QStringLiteral("keyboard"), 0, drive.jointId, 1.0, 1});
        profile.banks.append({QStringLiteral("-"), {}, {}});
        window.station()->call([&](trainer::StationEngine& e) { e.setProfile(profile); });
        waitFor(
            [&] {
                const auto st = window.station()->latest();
                return st && st->profileName == profile.name && st->warnings.isEmpty();
            },
            3000);
        trainer::KeyboardDevice* keys = window.keyboardDevice();
        std::atomic<bool> done{false};
        std::thread presser([&] {
            for (int i = 0; i < kPresses; ++i) {
                const bool press = i % 2 == 0;
                std::this_thread::sleep_for(std::chrono::milliseconds(8 + (7 * i) % 13));  // the machine runs a little
                const auto t0 = Clock::now();
                keys->setKeys(0, press, false);
                for (;;) {
                    const auto s = runner->latest();
                    const double u = s && s->u.size() > drive.treeJoint ? s->u[drive.treeJoint] : 0.0;
                    if (press ? u > 0.5 : std::abs(u) < 1e-9) break;
                    if (Clock::now() - t0 > std::chrono::seconds(2)) {
                        ++timeouts;
                        break;
                    }
                    std::this_thread::sleep_for(std::chrono::microseconds(50));
                }
                micros.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
            }
            keys->setKeys(0, false, false);
            done = true;
        });
        runner->resetStepPeriods();
        waitFor([&] { return done.load(); }, 600000);
        presser.join();
        all.merge(runner->stepPeriods());
    }
    latency = summary(micros);
    latency.insert("presses", int(micros.size()));
    latency.insert("timeouts", timeouts);
    result.insert("latency_us", latency);

    // ---- the solver over the whole run
    const std::shared_ptr<const Snapshot> last = runner->latest();
    window.pause();
    QJsonObject solver = periods(all, nominal);
    solver.insert("overruns", double(last->overruns));
    solver.insert("dropped_s", last->droppedSeconds);
    solver.insert("step_compute_us_median", last->stepMicros);
    solver.insert("real_time_factor", last->realTimeFactor);
    solver.insert("simulated_s", last->t);
    if (!last->error.empty()) solver.insert("error", QString::fromStdString(last->error));
    result.insert("solver", solver);

    if (o.json) {
        out << QJsonDocument(result).toJson(QJsonDocument::Indented);
    } else {
        out << "padrob-studio frame bench: " << QFileInfo(model).fileName()
            << (sceneFile.isEmpty() ? QString() : " in " + QFileInfo(sceneFile).fileName()) << ", window "
            << window.width() << " x " << window.height() << ", " << frames << " frames per measurement, "
            << result["renderer"].toString() << ", " << QThread::idealThreadCount() << " CPUs, lit "
            << (result["lighting"].toString() == "vertex" ? "at the vertices" : "at every pixel") << "\n";
        if (result.contains("scene_error")) out << "scene not used: " << result["scene_error"].toString() << "\n";
        out << "start-up to the first drawn frame: " << fmt(result["startup_ms"].toDouble(), 0)
            << " ms from the process's start (" << fmt(startupMain, 0) << " ms from main)\n";
        for (const QString& l : lines) out << l << "\n";
        out << "solver step period over the run (" << all.count << " steps, nominal " << fmt(nominal, 0)
            << " us): median " << fmt(all.median()) << " us, 99% " << fmt(all.percentile(0.99)) << " us, 99.9% "
            << fmt(all.percentile(0.999)) << " us, max " << fmt(all.maxMicros, 0) << " us (max jitter "
            << fmt(all.maxJitter(nominal), 0) << " us); overruns " << last->overruns << ", dropped "
            << fmt(last->droppedSeconds, 3) << " s\n";
        out << "input-to-solver latency (" << micros.size() << " key presses: keyboard device -> station -> runner "
            << "-> snapshot): median " << fmt(latency["median"].toDouble(), 0) << " us, 90% "
            << fmt(latency["p90"].toDouble(), 0) << " us, max " << fmt(latency["max"].toDouble(), 0) << " us"
            << (timeouts > 0 ? QStringLiteral(" (%1 never arrived)").arg(timeouts) : QString()) << "\n";
    }
    out.flush();
    if (!last->error.empty()) {
        err << QString::fromStdString(last->error) << Qt::endl;
        return 1;
    }
    return 0;
}

int saveScreenshot(MainWindow& window, const QString& file)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    // the first frame of the 3D view that shows the window's model
    bool drawn = false;
    Viewport* view = window.viewports()->viewport(0);
    const QMetaObject::Connection first = QObject::connect(view, &Viewport::frameTimed, &window, [&](double) {
        drawn = drawn || (window.bundle() && view->bundle() == window.bundle());
    });
    const bool shown = waitFor([&] { return drawn; }, 60000);
    QObject::disconnect(first);
    if (!shown) {
        err << QCoreApplication::translate("studio::FrameBench", "No model was drawn (does it have errors?).")
            << Qt::endl;
        return 1;
    }
    const std::shared_ptr<const ModelBundle> bundle = window.bundle();
    if (!window.grab().save(file)) {
        err << QCoreApplication::translate("studio::FrameBench", "Cannot write %1.").arg(QDir::toNativeSeparators(file))
            << Qt::endl;
        return 1;
    }
    out << QCoreApplication::translate("studio::FrameBench", "%1 drawn; the window saved to %2.")
               .arg(QDir::toNativeSeparators(bundle->filePath), QDir::toNativeSeparators(file))
        << Qt::endl;
    return 0;
}

}  // namespace studio
