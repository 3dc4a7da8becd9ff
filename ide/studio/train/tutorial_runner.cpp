#include "ide/studio/train/tutorial_runner.h"

#include "solver/core/data.h"
#include "solver/kinematics/kinematics.h"
#include "trainer/station/paced_loop.h"
#include "trainer/station/station_engine.h"

#include <QFile>
#include <QMetaObject>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <sstream>
#include <utility>

namespace studio {

struct TutorialRunner::Shared {
    std::mutex control;
    std::condition_variable wake;
    unsigned controlVersion = 0;  // every control call bumps it (under control)
    bool quit = false;
    std::unique_ptr<Run> pendingRun;
    bool pendingClose = false;
    bool stopRequest = false;
    bool seekRequest = false;
    double seekTo = 0.0;
    bool paused = false;
    double speed = 1.0;
    bool ghostChanged = false;
    std::shared_ptr<const trainer::InputLog> ghostLog;
    trainer::StationProfile ghostProfile;

    struct Task {
        SessionTask task;
        std::function<void(bool, const QString&)> done;
        long generation = 0;
    };
    std::vector<Task> tasks;  // under control

    std::mutex commandMutex;
    std::vector<double> commands;
    std::atomic<unsigned> commandVersion{0};

    mutable std::mutex frameMutex;
    std::shared_ptr<const TrainFrame> frame;
    long generation = 0;  // of the session whose frames are wanted (under frameMutex)

    /// Publishes `f` unless its session was replaced or closed meanwhile.
    void publish(std::shared_ptr<const TrainFrame> f)
    {
        std::lock_guard lock(frameMutex);
        if (f && f->generation != generation) return;
        frame = std::move(f);
    }
    /// From now on only frames of session `g` (GUI thread); `f` the first (or nullptr).
    void reset(long g, std::shared_ptr<const TrainFrame> f)
    {
        std::lock_guard lock(frameMutex);
        generation = g;
        frame = std::move(f);
    }
};

/// One session with its input (runner thread once handed over).
struct TutorialRunner::Run {
    long generation = 0;
    std::shared_ptr<const trainer::Tutorial> tutorial;
    std::shared_ptr<const ModelBundle> bundle;
    std::shared_ptr<const trainer::InputLog> log;
    trainer::StationProfile profile;
    std::unique_ptr<trainer::TutorialSession> session;
    std::unique_ptr<trainer::StationEngine> engine;
    std::shared_ptr<const trainer::RunOutput> output;
    double duration = 0.0;
    std::unique_ptr<Run> ghost;  ///< the expert beside the operator (setGhost), or nullptr

    /// (Re)builds the session at its start, and the engine replaying the log.
    bool build(QString* error)
    {
        session = std::make_unique<trainer::TutorialSession>(tutorial);
        output.reset();
        engine.reset();
        if (!log) return true;
        duration = log->duration() + kGrace;
        auto e = std::make_unique<trainer::StationEngine>();
        e->setDrives(tutorial->model->nb, trainer::drivesOf(*tutorial->model));
        trainer::StationProfile p = profile;
        p.devices.clear();  // nothing is opened: the log's devices stand in for them
        for (const trainer::ProfileIssue& i : e->setProfile(p)) {
            if (i.error) {
                if (error) *error = i.text();
                return false;
            }
        }
        e->setReplayOnly(true);
        for (auto& d : trainer::replayDevices(log)) e->addDevice(d);
        engine = std::move(e);
        return true;
    }

    /// One step with the log's commands (live commands are set by the caller).
    bool step()
    {
        if (engine) {
            engine->update(session->time());
            session->setCommands(engine->commands());
        }
        if (!session->step()) return false;
        if (log && session->time() > duration) session->stop(trainer::TutorialEvent::Kind::InputEnded);
        return !session->ended();
    }

    /// Brings the ghost to the session's time (it stops where its log ended).
    void syncGhost()
    {
        if (!ghost) return;
        while (!ghost->session->ended() && ghost->session->time() < session->time() - 1e-9)
            if (!ghost->step()) break;
    }

    std::shared_ptr<const TrainFrame> frame(bool paused, double speed)
    {
        auto f = std::make_shared<TrainFrame>();
        f->generation = generation;
        auto snap = captureSnapshot(session->simulation(), bundle);
        snap->timeStep = 1e-3;
        snap->step = long(std::lround(snap->t / snap->timeStep));
        snap->running = !paused && !session->ended();
        snap->speed = speed;
        f->snapshot = std::move(snap);
        f->progress = session->progress();
        f->events = session->events();
        f->paused = paused;
        f->speed = speed;
        f->duration = log ? duration : 0.0;
        f->ended = session->ended();
        f->faults = session->activeFaults();
        if (ghost) f->ghost = captureSnapshot(ghost->session->simulation(), bundle);
        if (!f->ended) f->score = session->score();
        if (f->ended) {
            if (!output) {
                auto o = std::make_shared<trainer::RunOutput>();
                o->result = session->result();
                o->samples = session->samples();
                output = std::move(o);
            }
            f->output = output;
            f->score = output->result.score;
        }
        return f;
    }
};

TutorialRunner::TutorialRunner(QObject* parent) : QObject(parent), m_shared(std::make_unique<Shared>())
{
    m_thread = std::thread([this] { loop(); });
}

TutorialRunner::~TutorialRunner()
{
    {
        std::lock_guard lock(m_shared->control);
        m_shared->quit = true;
        ++m_shared->controlVersion;
    }
    m_shared->wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
}

bool TutorialRunner::start(std::shared_ptr<const trainer::Tutorial> tutorial, std::shared_ptr<const ModelBundle> bundle,
                           std::shared_ptr<const trainer::InputLog> log, const trainer::StationProfile& profile,
                           bool paused, QString* error)
{
    auto run = std::make_unique<Run>();
    run->generation = ++m_generation;
    run->tutorial = std::move(tutorial);
    run->bundle = std::move(bundle);
    run->log = std::move(log);
    run->profile = profile;
    if (!run->build(error)) return false;
    m_paused = paused;
    m_active = true;
    m_hasGhost = false;
    const bool live = !run->log;
    m_shared->reset(run->generation, run->frame(paused, m_speed));
    {
        std::lock_guard lock(m_shared->commandMutex);
        m_shared->commands.assign(std::size_t(run->tutorial->model->nb), 0.0);
        m_shared->commandVersion.fetch_add(1, std::memory_order_release);
    }
    {
        std::lock_guard lock(m_shared->control);
        m_shared->pendingRun = std::move(run);
        m_shared->pendingClose = false;
        m_shared->stopRequest = false;
        m_shared->seekRequest = false;
        m_shared->ghostChanged = false;
        m_shared->ghostLog.reset();
        m_shared->paused = paused;
        m_shared->speed = m_speed;
        ++m_shared->controlVersion;
    }
    m_wantsCommands = live;
    m_shared->wake.notify_all();
    return true;
}

void TutorialRunner::stop()
{
    {
        std::lock_guard lock(m_shared->control);
        m_shared->stopRequest = true;
        ++m_shared->controlVersion;
    }
    m_wantsCommands = false;
    m_shared->wake.notify_all();
}

void TutorialRunner::close()
{
    ++m_generation;  // a finished() still queued is dropped
    {
        std::lock_guard lock(m_shared->control);
        m_shared->pendingRun.reset();
        m_shared->pendingClose = true;
        ++m_shared->controlVersion;
    }
    m_wantsCommands = false;
    m_active = false;
    m_hasGhost = false;
    m_shared->reset(m_generation, nullptr);
    m_shared->wake.notify_all();
}

void TutorialRunner::setPaused(bool paused)
{
    m_paused = paused;
    {
        std::lock_guard lock(m_shared->control);
        m_shared->paused = paused;
        ++m_shared->controlVersion;
    }
    m_shared->wake.notify_all();
}

void TutorialRunner::setGhost(std::shared_ptr<const trainer::InputLog> log, const trainer::StationProfile& profile)
{
    m_hasGhost = log && m_active;
    {
        std::lock_guard lock(m_shared->control);
        m_shared->ghostChanged = true;
        m_shared->ghostLog = m_hasGhost ? std::move(log) : nullptr;
        m_shared->ghostProfile = profile;
        ++m_shared->controlVersion;
    }
    m_shared->wake.notify_all();
}

void TutorialRunner::setSpeed(double speed)
{
    if (!std::isfinite(speed)) return;
    m_speed = std::clamp(speed, kMinSpeed, kMaxSpeed);
    {
        std::lock_guard lock(m_shared->control);
        m_shared->speed = m_speed;
        ++m_shared->controlVersion;
    }
    m_shared->wake.notify_all();
}

void TutorialRunner::seek(double t)
{
    if (!std::isfinite(t)) return;
    {
        std::lock_guard lock(m_shared->control);
        m_shared->seekRequest = true;
        m_shared->seekTo = std::max(0.0, t);
        ++m_shared->controlVersion;
    }
    m_shared->wake.notify_all();
}

void TutorialRunner::setCommands(std::span<const double> u)
{
    std::lock_guard lock(m_shared->commandMutex);
    auto& c = m_shared->commands;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const double v = i < u.size() ? u[i] : 0.0;
        c[i] = std::isfinite(v) ? std::clamp(v, -1.0, 1.0) : 0.0;
    }
    m_shared->commandVersion.fetch_add(1, std::memory_order_release);
}

void TutorialRunner::runInSession(SessionTask task, std::function<void(bool, const QString&)> done, long generation)
{
    {
        std::lock_guard lock(m_shared->control);
        m_shared->tasks.push_back({std::move(task), std::move(done), generation});
        ++m_shared->controlVersion;
    }
    m_shared->wake.notify_all();
}

std::shared_ptr<const TrainFrame> TutorialRunner::latest() const
{
    std::lock_guard lock(m_shared->frameMutex);
    return m_shared->frame;
}

void TutorialRunner::loop()
{
    Shared& sh = *m_shared;
    std::unique_ptr<Run> run;
    bool paused = false;
    double speed = 1.0;
    unsigned seenControl = 0;
    unsigned seenCommands = 0;
    std::vector<double> commands;
    trainer::PacedLoop pacer;  // lead 2 ms, batches ≤ 10 ms, a lag over 50 ms dropped
    bool endSignalled = false;

    const auto signalEnd = [&] {
        if (endSignalled || !run || !run->session->ended()) return;
        endSignalled = true;
        m_wantsCommands = false;
        QMetaObject::invokeMethod(
            this, [this, g = run->generation] {
                if (g == m_generation) emit finished();
            },
            Qt::QueuedConnection);
    };

    for (;;) {
        bool stopNow = false, seekNow = false, resync = false, ghostNow = false;
        double seekTo = 0.0;
        std::shared_ptr<const trainer::InputLog> ghostLog;
        trainer::StationProfile ghostProfile;
        std::vector<Shared::Task> tasks;
        {
            std::unique_lock lock(sh.control);
            if (sh.quit) return;
            if (sh.controlVersion != seenControl) {
                seenControl = sh.controlVersion;
                resync = true;
                if (sh.pendingClose) {
                    run.reset();
                    sh.pendingClose = false;
                }
                if (sh.pendingRun) {
                    run = std::move(sh.pendingRun);
                    endSignalled = false;
                    commands.clear();
                    seenCommands = 0;
                }
                stopNow = std::exchange(sh.stopRequest, false);
                seekNow = std::exchange(sh.seekRequest, false);
                seekTo = sh.seekTo;
                if (std::exchange(sh.ghostChanged, false)) {
                    ghostNow = true;
                    ghostLog = std::move(sh.ghostLog);
                    ghostProfile = sh.ghostProfile;
                }
                paused = sh.paused;
                speed = sh.speed;
                tasks = std::exchange(sh.tasks, {});
            }
        }
        // the instructor's work on the session, between two steps (before a stop: its
        // event comes before the end's)
        for (Shared::Task& t : tasks) {
            bool ok = false;
            QString error = QStringLiteral("not-running");
            if (run && (t.generation == 0 || t.generation == run->generation)) {
                error.clear();
                ok = t.task(*run->session, error);
            }
            if (t.done)
                QMetaObject::invokeMethod(
                    this, [done = std::move(t.done), ok, error] { done(ok, error); }, Qt::QueuedConnection);
        }
        if (run && ghostNow) {
            run->ghost.reset();
            if (ghostLog) {
                auto g = std::make_unique<Run>();
                g->generation = run->generation;
                g->tutorial = run->tutorial;
                g->bundle = run->bundle;
                g->log = std::move(ghostLog);
                g->profile = ghostProfile;
                if (g->build(nullptr)) run->ghost = std::move(g);
            }
            run->syncGhost();
        }
        if (run && stopNow && !run->session->ended()) {
            run->session->stop(trainer::TutorialEvent::Kind::Aborted);
            sh.publish(run->frame(paused, speed));
            signalEnd();
        }
        if (run && seekNow && run->log) {
            if (seekTo < run->session->time() - 1e-9) {
                run->build(nullptr);  // it built before, so it builds again
                if (run->ghost) run->ghost->build(nullptr);
                endSignalled = false;
            }
            while (run->session->time() < seekTo - 1e-9 && run->step()) {
                run->syncGhost();
            }
            run->syncGhost();
            sh.publish(run->frame(paused, speed));
            signalEnd();
        } else if (run && resync) {
            sh.publish(run->frame(paused, speed));
        }
        if (resync && run) pacer.anchor(run->session->time(), speed);

        if (!run || paused || run->session->ended()) {
            std::unique_lock lock(sh.control);
            sh.wake.wait(lock, [&] { return sh.quit || sh.controlVersion != seenControl; });
            continue;
        }

        // the steps due by now
        pacer.runDue([&] {
            if (!run->log) {
                const unsigned v = sh.commandVersion.load(std::memory_order_acquire);
                if (v != seenCommands) {
                    std::unique_lock lock(sh.commandMutex, std::try_to_lock);
                    if (lock.owns_lock()) {
                        commands = sh.commands;
                        seenCommands = v;
                    }
                }
                run->session->setCommands(commands);
            }
            const bool going = run->step();
            run->syncGhost();
            return going;
        });
        sh.publish(run->frame(paused, speed));
        signalEnd();

        std::unique_lock lock(sh.control);
        sh.wake.wait_until(lock, pacer.wake(), [&] { return sh.quit || sh.controlVersion != seenControl; });
    }
}

// ---------------------------------------------------------------- bundles and replays

std::shared_ptr<const ModelBundle> makeTutorialBundle(const trainer::Tutorial& tutorial, QString* error)
{
    // the tutorial compiled its model once when it was loaded: draw and run that one
    auto bundle = makeBundle(tutorial.compiled, QString::fromStdString(tutorial.modelFile));
    if (!bundle && error) {
        *error = QString::fromStdString(tutorial.modelFile);
        if (tutorial.compiled) {
            for (const solver::Diagnostic& d : tutorial.compiled->diagnostics) {
                if (d.severity == solver::Severity::Error) {
                    *error = QString::fromStdString(d.format());
                    break;
                }
            }
        }
    }
    return bundle;
}

std::shared_ptr<const ModelBundle> makeTutorialScene(const trainer::Tutorial& tutorial)
{
    // the tutorial's scene, with the targets added as graphics of the ground
    solver::ModelSpec spec;
    if (tutorial.scene) spec = tutorial.scene->spec;
    spec.file = tutorial.sceneFile.empty() ? std::string("<untitled>") : tutorial.sceneFile;
    auto add = [&](int id, solver::ShapeKind shape, std::vector<double> dims, const Eigen::Vector3d& at) {
        solver::GraphicSpec g;
        g.id = id;
        g.body = 0;
        g.shape = shape;
        g.dims = std::move(dims);
        g.position = at;
        g.hasPosition = true;
        g.color = Eigen::Vector3d(0.15, 0.75, 0.25);
        g.hasColor = true;
        spec.graphics.push_back(std::move(g));
        return &spec.graphics.back();
    };
    // the targets: green spheres as big as their tolerance (ids far above any scene's)
    int id = 900000;
    for (const trainer::Goal& g : tutorial.spec.goals) {
        if (g.kind != trainer::Goal::Kind::Reach && g.kind != trainer::Goal::Kind::Place) continue;
        const double r = std::max(0.03, g.kind == trainer::Goal::Kind::Reach ? g.tolerance : 0.1);
        add(id++, solver::ShapeKind::Sphere, {r}, g.target);
        // and a green arrow above it, pointing down at it: the target shows when the
        // sphere is inside something (a liner's edge, the mill's shell) or small at a distance
        add(id++, solver::ShapeKind::Cylinder, {0.015, 0.4}, g.target + Eigen::Vector3d(0, 0, r + 0.45));
        solver::GraphicSpec* cone =
            add(id++, solver::ShapeKind::Cone, {0.08, 0.2}, g.target + Eigen::Vector3d(0, 0, r + 0.25));
        cone->axis = Eigen::Vector3d(0, 0, -1);
        cone->hasAxis = true;
    }
    if (spec.graphics.empty() && spec.bodies.empty()) return nullptr;
    const QString path = QString::fromStdString(tutorial.sceneFile);
    return makeBundle(std::make_shared<const solver::CompiledModel>(solver::compileSpec(std::move(spec))), path);
}

std::shared_ptr<const Snapshot> snapshotFromSample(const trainer::SessionSample& sample,
                                                   std::shared_ptr<const ModelBundle> bundle)
{
    if (!bundle) return nullptr;
    const solver::Model& m = *bundle->model;
    Eigen::VectorXd q = Eigen::VectorXd::Zero(m.nb);
    for (int i = 0; i < m.nb && std::size_t(i) < sample.q.size(); ++i) q[i] = sample.q[std::size_t(i)];
    solver::Data data(m);
    solver::forwardKinematics(m, q, Eigen::VectorXd::Zero(m.nb), data);
    auto snap = std::make_shared<Snapshot>();
    snap->bundle = std::move(bundle);
    snap->t = sample.t;
    snap->timeStep = 1e-3;
    snap->step = long(std::lround(sample.t / 1e-3));
    snap->bodyPoses = data.X_wb;
    snap->theta = q;
    snap->q.resize(m.nb);
    snap->qd = Eigen::VectorXd::Zero(m.nb);
    snap->u = Eigen::VectorXd::Zero(m.nb);
    snap->driveForce = Eigen::VectorXd::Zero(m.nb);
    for (int i = 0; i < m.nb; ++i) {
        snap->q[i] = m.coordinate(i, q[i]);
        if (std::size_t(i) < sample.driveForce.size()) snap->driveForce[i] = sample.driveForce[std::size_t(i)];
    }
    snap->reactionJoint.assign(std::size_t(m.nb), solver::Vector6d::Zero());
    static const auto noEvents = std::make_shared<const std::vector<solver::SimulationEvent>>();
    snap->eventLog = noEvents;
    return snap;
}

}  // namespace studio
