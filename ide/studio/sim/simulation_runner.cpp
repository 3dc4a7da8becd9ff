#include "ide/studio/sim/simulation_runner.h"

#include "ide/i18n/diagnostic_text.h"
#include "solver/integrate/simulation.h"
#include "trainer/station/paced_loop.h"

#include <QMetaObject>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <limits>
#include <mutex>
#include <string>
#include <utility>

#include <pthread.h>
#include <time.h>

namespace studio {

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kStatsPeriod = 0.1; // statistics refreshed this often [s]
constexpr double kStatsWindow = 1.0; // over the last [s]
constexpr std::size_t kStepSamples = 1 << 15;  // ring of step timings

/// CPU time the calling thread has used [s], or −1 when the platform cannot tell.
double threadCpuSeconds()
{
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec ts{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) == 0) return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
#endif
    return -1;
}

/// Median of `v` (reordered); 0 when empty.
double median(std::vector<float>& v)
{
    if (v.empty()) return 0;
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

}  // namespace

// ---- state shared by the GUI thread and the solver thread ----------------------

struct SimulationRunner::Shared {
    // control: written by the GUI (and by the solver when it fails), read by the
    // solver between batches; every change bumps controlVersion and notifies `wake`
    std::mutex control;
    std::condition_variable wake;
    std::atomic<unsigned> controlVersion{0};
    bool stop = false;
    bool hasSimulation = false;
    bool running = false;
    bool failed = false;     // the current simulation failed: stays stopped until replaced
    int stepRequests = 0;    // stepOnce() calls not yet done
    double speed = 1;
    bool pending = false;    // a new simulation (or none) to take over
    std::unique_ptr<solver::Simulation> pendingSimulation;
    std::shared_ptr<const ModelBundle> pendingBundle;
    double pendingStep = kDefaultTimeStep;
    long pendingGeneration = 0;
    bool posePending = false;  // setPositions(): a pose for the solver to take
    Eigen::VectorXd pose;

    // commands: the newest input snapshot
    std::mutex commandMutex;
    std::vector<double> commands;
    solver::Push push;  // the mouse's push (body −1: none)
    std::atomic<unsigned> commandVersion{0};

    // snapshots: `latest` is replaced only by the generation it belongs to, so that a
    // step of a replaced simulation cannot overwrite the new one's first snapshot
    mutable std::mutex snapshotMutex;
    std::shared_ptr<const Snapshot> latest;
    long publishGeneration = 0;

    // step periods: written by the solver thread only (relaxed atomics, no lock, no
    // allocation), read by the GUI; a reset is requested by the GUI and done by the
    // solver (done == requested: the histogram holds only periods counted since)
    std::array<std::atomic<std::uint32_t>, StepPeriodHistogram::kBins> periodCounts{};
    std::atomic<double> periodMin{std::numeric_limits<double>::infinity()};
    std::atomic<double> periodMax{0.0};
    std::atomic<unsigned> periodResetRequested{0};
    std::atomic<unsigned> periodResetDone{0};

    void bump() { controlVersion.fetch_add(1, std::memory_order_release); }

    void publish(std::shared_ptr<const Snapshot> snapshot, long generation)
    {
        {
            std::lock_guard lock(snapshotMutex);
            if (generation != publishGeneration) return;
            latest.swap(snapshot);
        }
        // the replaced snapshot (in `snapshot`) is freed here, outside the lock
    }
};

// ---- the solver thread ---------------------------------------------------------

class SimulationRunner::Worker {
public:
    explicit Worker(SimulationRunner& runner) : m_runner(runner), m_shared(*runner.m_shared)
    {
        m_stepSamples.resize(kStepSamples);
        m_scratch.reserve(kStepSamples);
        m_events.reserve(64);
    }

    void run()
    {
        std::unique_lock lock(m_shared.control);
        while (!m_shared.stop) {
            if (m_shared.pending) adopt();
            const bool setPose = std::exchange(m_shared.posePending, false);
            if (setPose) m_pose.swap(m_shared.pose);
            const bool wantRun = m_shared.running && m_sim && !m_failed;
            const int steps = std::exchange(m_shared.stepRequests, 0);
            const double speed = m_shared.speed;
            const unsigned version = m_shared.controlVersion.load(std::memory_order_acquire);
            lock.unlock();
            m_retired.reset();  // a replaced simulation is freed outside the lock

            Clock::time_point wakeAt = Clock::time_point::max();
            if (setPose && m_sim && !m_failed) applyPose();
            if (m_sim && !m_failed) {
                if (wantRun) {
                    if (!m_running) beginRun(speed);
                    else if (speed != m_pacer.speed()) anchor(speed);
                    wakeAt = runBatch(version);
                } else {
                    if (m_running) {
                        // paused: say so with the state where it stopped
                        m_running = false;
                        publish();
                    }
                    bool stepped = false;
                    for (int i = 0; i < steps && !m_failed; ++i) stepped = doStep(false);
                    if (stepped && !m_failed) publish();
                }
            }

            lock.lock();
            auto changed = [&] {
                return m_shared.stop || m_shared.controlVersion.load(std::memory_order_acquire) != version;
            };
            if (wakeAt == Clock::time_point::max()) {
                m_shared.wake.wait(lock, changed);
            } else {
                m_shared.wake.wait_until(lock, wakeAt, changed);
            }
        }
    }

private:
    struct StepSample {
        double end = 0;       // wall time the step ended [s since m_epoch]
        float compute = 0;    // its compute time [µs]
        float period = -1;    // since the previous step's end [µs]; −1 for the first of a run
    };
    struct RateSample {
        double wall = 0, sim = 0, cpu = -1;
    };

    SimulationRunner& m_runner;
    Shared& m_shared;
    const Clock::time_point m_epoch = Clock::now();

    std::unique_ptr<solver::Simulation> m_sim, m_retired;
    std::shared_ptr<const ModelBundle> m_bundle;
    long m_generation = 0;
    double m_h = kDefaultTimeStep;
    long m_step = 0;
    long m_poseEdits = 0;
    Eigen::VectorXd m_pose;  // the pose setPositions() sent
    bool m_failed = false;
    bool m_running = false;
    bool m_pullCommands = true;
    unsigned m_commandVersion = 0;

    // pacing (lead 2 ms, batches at least 1 ms apart and at most 10 ms long, a lag over
    // 50 ms dropped: PacedLoopOptions' defaults), on this thread's clock
    trainer::PacedLoop m_pacer = makePacer(kDefaultTimeStep);

    // events
    std::vector<solver::SimulationEvent> m_events;  // since the last snapshot
    std::shared_ptr<const std::vector<solver::SimulationEvent>> m_eventLog;
    long m_eventCount = 0;
    std::string m_error;         // why the simulation failed, in English (Snapshot::error)
    solver::Text m_errorText;    // the same, translatable (shown to the user)

    // statistics
    std::vector<StepSample> m_stepSamples;  // ring
    std::size_t m_stepHead = 0, m_stepCount = 0;
    double m_lastStepEnd = -1;
    std::vector<float> m_scratch;
    unsigned m_periodReset = 0;  // the last reset of the shared period histogram done
    std::deque<RateSample> m_rates;
    double m_lastStats = -1e9;
    double m_realTimeFactor = 0, m_stepMicros = 0, m_periodMicros = 0, m_periodMaxMicros = 0, m_cpuLoad = -1;

    double now() const { return std::chrono::duration<double>(Clock::now() - m_epoch).count(); }
    Clock::time_point toClock(double wall) const
    {
        return m_epoch + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(wall));
    }
    /// The pacing of a run with step `h`, on this thread's clock (now()).
    trainer::PacedLoop makePacer(double h)
    {
        trainer::PacedLoopOptions o;
        o.step = h;
        return trainer::PacedLoop(o, [this] { return now(); });
    }

    /// Takes over the simulation setBundle() or reset() built (control lock held).
    void adopt()
    {
        m_retired = std::exchange(m_sim, std::move(m_shared.pendingSimulation));
        m_bundle = std::move(m_shared.pendingBundle);
        m_h = m_shared.pendingStep;
        m_generation = m_shared.pendingGeneration;
        m_shared.pending = false;
        m_step = 0;
        m_poseEdits = 0;
        m_failed = false;
        m_running = false;
        m_pullCommands = true;
        m_pacer = makePacer(m_h);
        m_events.clear();
        m_eventLog = std::make_shared<const std::vector<solver::SimulationEvent>>();
        m_eventCount = 0;
        m_error.clear();
        m_errorText = {};
        clearStatistics();
        m_realTimeFactor = m_stepMicros = m_periodMicros = m_periodMaxMicros = 0;
        m_cpuLoad = -1;
    }

    void clearStatistics()
    {
        m_stepHead = m_stepCount = 0;
        m_lastStepEnd = -1;
        m_rates.clear();
        m_lastStats = -1e9;
    }

    /// The pose setPositions() sent becomes the state (at rest; the loops close around
    /// it), published at once.
    void applyPose()
    {
        const int nb = m_sim->model().nb;
        if (m_pose.size() < nb) return;
        for (int j = 0; j < nb; ++j) m_sim->setInitial(j, m_pose[j], 0.0);
        ++m_poseEdits;
        publish();
    }

    /// From paused to running: simulated time starts following the wall clock from here.
    void beginRun(double speed)
    {
        m_running = true;
        clearStatistics();
        m_realTimeFactor = 0;
        anchor(speed);
        m_rates.push_back({now(), m_sim->state().t, threadCpuSeconds()});
        m_lastStats = m_rates.back().wall;
    }

    void anchor(double speed) { m_pacer.anchor(double(m_step) * m_h, speed); }

    /// Runs the steps due now (or until the controls change), publishes, and returns
    /// when the next batch is due.
    Clock::time_point runBatch(unsigned version)
    {
        bool stepped = false, failed = false;
        m_pacer.runDue([&] {
            if (m_shared.controlVersion.load(std::memory_order_acquire) != version) return false;
            if (!doStep(true)) {
                failed = true;
                return false;
            }
            stepped = true;
            return true;
        });
        if (failed) return Clock::time_point::max();
        if (stepped) publish();
        return toClock(m_pacer.wakeAt());
    }

    /// Reads the newest commands when they changed (never waits for the GUI).
    void pullCommands()
    {
        if (!m_pullCommands && m_shared.commandVersion.load(std::memory_order_acquire) == m_commandVersion) return;
        std::unique_lock lock(m_shared.commandMutex, std::try_to_lock);
        if (!lock.owns_lock()) return;  // the GUI is writing: next step
        m_commandVersion = m_shared.commandVersion.load(std::memory_order_relaxed);
        m_pullCommands = false;
        const int nb = m_sim->model().nb;
        const auto& u = m_shared.commands;
        for (int i = 0; i < nb; ++i) m_sim->setCommand(i, std::size_t(i) < u.size() ? u[std::size_t(i)] : 0.0);
        const solver::Push& p = m_shared.push;
        if (p.body < 0 || !m_sim->setPush(p.body, p.point, p.target)) m_sim->clearPush();
    }

    /// One step; false (and the failure handled) when the simulation failed.
    bool doStep(bool paced)
    {
        pullCommands();
        const double t0 = now();
        const bool ok = m_sim->advanceTo(double(m_step + 1) * m_h, m_events, m_error, &m_errorText);
        const double t1 = now();
        if (!ok) {
            fail();
            return false;
        }
        ++m_step;
        StepSample& s = m_stepSamples[m_stepHead];
        s.end = t1;
        s.compute = float((t1 - t0) * 1e6);
        s.period = m_lastStepEnd >= 0 ? float((t1 - m_lastStepEnd) * 1e6) : -1.0f;
        m_stepHead = (m_stepHead + 1) % kStepSamples;
        m_stepCount = std::min(m_stepCount + 1, kStepSamples);
        m_lastStepEnd = paced ? t1 : -1;
        if (s.period >= 0) countPeriod(double(s.period));
        return true;
    }

    /// Counts a step period in the shared histogram (clearing it first when the GUI
    /// asked). Only this thread writes it: plain loads and stores of relaxed atomics.
    void countPeriod(double micros)
    {
        const unsigned reset = m_shared.periodResetRequested.load(std::memory_order_acquire);
        if (reset != m_periodReset) {
            for (auto& c : m_shared.periodCounts) c.store(0, std::memory_order_relaxed);
            m_shared.periodMin.store(std::numeric_limits<double>::infinity(), std::memory_order_relaxed);
            m_shared.periodMax.store(0.0, std::memory_order_relaxed);
            m_periodReset = reset;
            m_shared.periodResetDone.store(reset, std::memory_order_release);
        }
        auto& c = m_shared.periodCounts[std::size_t(StepPeriodHistogram::bin(micros))];
        c.store(c.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
        if (micros < m_shared.periodMin.load(std::memory_order_relaxed))
            m_shared.periodMin.store(micros, std::memory_order_relaxed);
        if (micros > m_shared.periodMax.load(std::memory_order_relaxed))
            m_shared.periodMax.store(micros, std::memory_order_relaxed);
    }

    /// Medians over the last second, refreshed every kStatsPeriod.
    void refreshStatistics()
    {
        const double t = now();
        if (t - m_lastStats < kStatsPeriod) return;
        m_lastStats = t;
        const double from = t - kStatsWindow;
        m_scratch.clear();
        float periodMax = 0;
        for (std::size_t i = 0; i < m_stepCount; ++i) {
            const StepSample& s = m_stepSamples[(m_stepHead + kStepSamples - 1 - i) % kStepSamples];
            if (s.end < from) break;
            m_scratch.push_back(s.compute);
        }
        if (!m_scratch.empty()) m_stepMicros = median(m_scratch);
        m_scratch.clear();
        for (std::size_t i = 0; i < m_stepCount; ++i) {
            const StepSample& s = m_stepSamples[(m_stepHead + kStepSamples - 1 - i) % kStepSamples];
            if (s.end < from) break;
            if (s.period >= 0) {
                m_scratch.push_back(s.period);
                periodMax = std::max(periodMax, s.period);
            }
        }
        if (!m_scratch.empty()) {
            m_periodMicros = median(m_scratch);
            m_periodMaxMicros = periodMax;
        }
        if (m_running) {
            m_rates.push_back({t, m_sim->state().t, threadCpuSeconds()});
            while (m_rates.size() > 2 && m_rates[1].wall <= from) m_rates.pop_front();
            const RateSample& a = m_rates.front();
            const RateSample& b = m_rates.back();
            if (b.wall - a.wall > 0.05) {
                m_realTimeFactor = (b.sim - a.sim) / (b.wall - a.wall);
                m_cpuLoad = a.cpu >= 0 && b.cpu >= 0 ? (b.cpu - a.cpu) / (b.wall - a.wall) : -1;
            }
        }
    }

    std::shared_ptr<Snapshot> makeSnapshot()
    {
        auto snap = captureSnapshot(*m_sim, m_bundle);
        snap->step = m_step;
        snap->poseEdits = m_poseEdits;
        snap->timeStep = m_h;
        if (!m_events.empty()) {
            auto log = std::make_shared<std::vector<solver::SimulationEvent>>();
            const std::size_t keep = kSnapshotEventLog - std::min(kSnapshotEventLog, m_events.size());
            const std::size_t old = m_eventLog->size();
            log->reserve(std::min(kSnapshotEventLog, old + m_events.size()));
            log->insert(log->end(), m_eventLog->begin() + std::ptrdiff_t(old - std::min(old, keep)), m_eventLog->end());
            const std::size_t skip = m_events.size() - std::min(kSnapshotEventLog, m_events.size());
            log->insert(log->end(), m_events.begin() + std::ptrdiff_t(skip), m_events.end());
            m_eventCount += long(m_events.size());
            m_eventLog = std::move(log);
            snap->events = std::move(m_events);
            m_events.clear();
        }
        snap->eventLog = m_eventLog;
        snap->eventCount = m_eventCount;
        refreshStatistics();
        snap->running = m_running;
        snap->speed = m_running ? m_pacer.speed() : speedRequested();
        snap->realTimeFactor = m_running ? m_realTimeFactor : 0;
        snap->stepMicros = m_stepMicros;
        snap->stepPeriodMicros = m_periodMicros;
        snap->stepPeriodMaxMicros = m_periodMaxMicros;
        snap->cpuLoad = m_cpuLoad;
        snap->overruns = m_pacer.overruns();
        snap->droppedSeconds = m_pacer.droppedSeconds();
        return snap;
    }

    double speedRequested()
    {
        std::lock_guard lock(m_shared.control);
        return m_shared.speed;
    }

    void publish() { m_shared.publish(makeSnapshot(), m_generation); }

    /// The simulation failed: publish the last good state with the error, stop, tell the GUI.
    void fail()
    {
        m_failed = true;
        m_running = false;
        m_sim->evaluate();  // data at the state the simulation kept (the last good one)
        auto snap = makeSnapshot();
        snap->error = m_error;
        m_shared.publish(std::move(snap), m_generation);
        {
            std::lock_guard lock(m_shared.control);
            if (!m_shared.pending) {  // (else the GUI replaced this simulation already)
                m_shared.running = false;
                m_shared.failed = true;
                m_shared.bump();
            }
        }
        const QString message =
            SimulationRunner::tr("The simulation stopped: %1").arg(i18n::text(m_errorText));
        SimulationRunner* runner = &m_runner;
        const long generation = m_generation;
        QMetaObject::invokeMethod(
            runner, [runner, generation, message] { runner->emitFromSolver(generation, true, message); },
            Qt::QueuedConnection);
    }
};

// ---- the GUI side ----------------------------------------------------------------

SimulationRunner::SimulationRunner(QObject* parent) : QObject(parent), m_shared(std::make_unique<Shared>())
{
    m_thread = std::thread([this] {
        Worker worker(*this);
        worker.run();
    });
#if defined(__linux__)
    pthread_setname_np(m_thread.native_handle(), "padrob-solver");
#endif
}

SimulationRunner::~SimulationRunner()
{
    {
        std::lock_guard lock(m_shared->control);
        m_shared->stop = true;
        m_shared->bump();
    }
    m_shared->wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
}

void SimulationRunner::setBundle(std::shared_ptr<const ModelBundle> bundle)
{
    const bool wasRunning = isRunning();
    m_bundle = std::move(bundle);
    install(false);
    if (wasRunning) emit stateChanged(false);
    emit bundleChanged();
}

void SimulationRunner::setTimeStep(double seconds)
{
    m_timeStep = std::isfinite(seconds) ? std::clamp(seconds, 1e-5, 0.05) : kDefaultTimeStep;
}

bool SimulationRunner::install(bool keepCommands)
{
    std::unique_ptr<solver::Simulation> sim;
    std::shared_ptr<Snapshot> snap;
    QString problem;
    if (m_bundle) {
        try {
            solver::SimulationOptions options;
            options.integrator.method = solver::IntegrationMethod::Rk4Fixed;
            options.integrator.step = m_timeStep;
            sim = std::make_unique<solver::Simulation>(m_bundle->model, options);
            sim->evaluate();
            snap = captureSnapshot(*sim, m_bundle);
            snap->timeStep = m_timeStep;
            snap->speed = speed();
        } catch (const std::exception& e) {
            sim.reset();
            snap.reset();
            problem = tr("The simulation cannot start: %1").arg(QString::fromStdString(e.what()));
        }
    }
    const std::size_t nb = sim ? std::size_t(sim->model().nb) : 0;
    {
        std::lock_guard lock(m_shared->commandMutex);
        if (!keepCommands) m_shared->commands.assign(nb, 0.0);
        m_shared->commands.resize(nb, 0.0);
        m_shared->push = solver::Push{};  // a new simulation: nothing pushed
        m_shared->commandVersion.fetch_add(1, std::memory_order_release);
    }
    // publish first, under the new generation: from here on nothing of the old
    // simulation can replace it
    long generation = 0;
    {
        std::lock_guard lock(m_shared->snapshotMutex);
        generation = ++m_shared->publishGeneration;
        m_shared->latest = snap;
    }
    {
        std::lock_guard lock(m_shared->control);
        m_shared->hasSimulation = sim != nullptr;
        m_shared->running = false;
        m_shared->failed = false;
        m_shared->stepRequests = 0;
        m_shared->posePending = false;  // a pose of the simulation replaced
        m_shared->pending = true;
        m_shared->pendingSimulation = std::move(sim);
        m_shared->pendingBundle = snap ? m_bundle : nullptr;
        m_shared->pendingStep = m_timeStep;
        m_shared->pendingGeneration = generation;
        m_shared->bump();
    }
    m_shared->wake.notify_all();
    if (!problem.isEmpty()) {
        emit failed(problem);
        return false;
    }
    return true;
}

void SimulationRunner::emitFromSolver(long generation, bool stopped, const QString& message)
{
    {
        std::lock_guard lock(m_shared->snapshotMutex);
        if (generation != m_shared->publishGeneration) return;  // replaced since: old news
    }
    if (stopped) emit stateChanged(false);
    emit failed(message);
}

void SimulationRunner::start()
{
    {
        std::lock_guard lock(m_shared->control);
        if (!m_shared->hasSimulation || m_shared->failed || m_shared->running) return;
        m_shared->running = true;
        m_shared->bump();
    }
    m_shared->wake.notify_all();
    emit stateChanged(true);
}

void SimulationRunner::pause()
{
    {
        std::lock_guard lock(m_shared->control);
        if (!m_shared->running) return;
        m_shared->running = false;
        m_shared->bump();
    }
    m_shared->wake.notify_all();
    emit stateChanged(false);
}

void SimulationRunner::stepOnce()
{
    {
        std::lock_guard lock(m_shared->control);
        if (!m_shared->hasSimulation || m_shared->failed || m_shared->running) return;
        ++m_shared->stepRequests;
        m_shared->bump();
    }
    m_shared->wake.notify_all();
}

bool SimulationRunner::setPositions(const Eigen::VectorXd& theta)
{
    if (!m_bundle || theta.size() < m_bundle->model->nb) return false;
    {
        std::lock_guard lock(m_shared->control);
        if (!m_shared->hasSimulation || m_shared->failed || m_shared->running) return false;
        m_shared->pose = theta;
        m_shared->posePending = true;
        m_shared->bump();
    }
    m_shared->wake.notify_all();
    return true;
}

void SimulationRunner::reset()
{
    const bool wasRunning = isRunning();
    install(true);
    if (wasRunning) emit stateChanged(false);
    emit restarted();
}

bool SimulationRunner::isRunning() const
{
    std::lock_guard lock(m_shared->control);
    return m_shared->running;
}

void SimulationRunner::setSpeed(double speed)
{
    const double s = std::isfinite(speed) ? std::clamp(speed, kMinSpeed, kMaxSpeed) : 1.0;
    {
        std::lock_guard lock(m_shared->control);
        if (m_shared->speed == s) return;
        m_shared->speed = s;
        m_shared->bump();
    }
    m_shared->wake.notify_all();
}

double SimulationRunner::speed() const
{
    std::lock_guard lock(m_shared->control);
    return m_shared->speed;
}

void SimulationRunner::setCommand(int treeJoint, double u)
{
    u = std::isfinite(u) ? std::clamp(u, -1.0, 1.0) : 0.0;
    std::lock_guard lock(m_shared->commandMutex);
    if (treeJoint < 0 || std::size_t(treeJoint) >= m_shared->commands.size()) return;
    if (m_shared->commands[std::size_t(treeJoint)] == u) return;
    m_shared->commands[std::size_t(treeJoint)] = u;
    m_shared->commandVersion.fetch_add(1, std::memory_order_release);
}

void SimulationRunner::setCommands(std::span<const double> u)
{
    std::lock_guard lock(m_shared->commandMutex);
    std::vector<double>& c = m_shared->commands;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const double v = i < u.size() ? u[i] : 0.0;
        c[i] = std::isfinite(v) ? std::clamp(v, -1.0, 1.0) : 0.0;
    }
    m_shared->commandVersion.fetch_add(1, std::memory_order_release);
}

void SimulationRunner::setPush(int treeBody, const Eigen::Vector3d& localPoint, const Eigen::Vector3d& target)
{
    std::lock_guard lock(m_shared->commandMutex);
    solver::Push& p = m_shared->push;
    if (p.body == treeBody && p.point == localPoint && p.target == target) return;
    p.body = treeBody;
    p.point = localPoint;
    p.target = target;
    m_shared->commandVersion.fetch_add(1, std::memory_order_release);
}

void SimulationRunner::clearPush()
{
    std::lock_guard lock(m_shared->commandMutex);
    if (m_shared->push.body < 0) return;
    m_shared->push = solver::Push{};
    m_shared->commandVersion.fetch_add(1, std::memory_order_release);
}

solver::Push SimulationRunner::push() const
{
    std::lock_guard lock(m_shared->commandMutex);
    return m_shared->push;
}

std::vector<double> SimulationRunner::commands() const
{
    std::lock_guard lock(m_shared->commandMutex);
    return m_shared->commands;
}

std::shared_ptr<const Snapshot> SimulationRunner::latest() const
{
    std::lock_guard lock(m_shared->snapshotMutex);
    return m_shared->latest;
}

StepPeriodHistogram SimulationRunner::stepPeriods() const
{
    StepPeriodHistogram h;
    const unsigned reset = m_shared->periodResetRequested.load(std::memory_order_acquire);
    if (m_shared->periodResetDone.load(std::memory_order_acquire) != reset) return h;  // nothing since
    for (int b = 0; b < StepPeriodHistogram::kBins; ++b) {
        const auto k = std::size_t(b);
        h.counts[k] = m_shared->periodCounts[k].load(std::memory_order_relaxed);
        h.count += long(h.counts[k]);
    }
    if (h.count > 0) {
        h.minMicros = m_shared->periodMin.load(std::memory_order_relaxed);
        h.maxMicros = m_shared->periodMax.load(std::memory_order_relaxed);
        if (!std::isfinite(h.minMicros)) h.minMicros = h.maxMicros;  // read between a count and its min
    }
    return h;
}

void SimulationRunner::resetStepPeriods()
{
    m_shared->periodResetRequested.fetch_add(1, std::memory_order_release);
}

// ---- StepPeriodHistogram -----------------------------------------------------------

int StepPeriodHistogram::bin(double micros)
{
    if (!(micros > 0)) return 0;
    if (micros < kFineBins) return int(micros);
    const double coarse = (micros - kFineBins) / 100.0;
    if (coarse < kCoarseBins) return kFineBins + int(coarse);
    return kBins - 1;
}

double StepPeriodHistogram::binLow(int b)
{
    if (b < kFineBins) return double(b);
    return kFineBins + 100.0 * double(b - kFineBins);
}

double StepPeriodHistogram::binWidth(int b)
{
    if (b < kFineBins) return 1.0;
    return b < kBins - 1 ? 100.0 : 0.0;
}

void StepPeriodHistogram::add(double micros)
{
    ++counts[std::size_t(bin(micros))];
    minMicros = count == 0 ? micros : std::min(minMicros, micros);
    maxMicros = count == 0 ? micros : std::max(maxMicros, micros);
    ++count;
}

void StepPeriodHistogram::merge(const StepPeriodHistogram& other)
{
    if (other.count == 0) return;
    for (std::size_t b = 0; b < counts.size(); ++b) counts[b] += other.counts[b];
    minMicros = count == 0 ? other.minMicros : std::min(minMicros, other.minMicros);
    maxMicros = count == 0 ? other.maxMicros : std::max(maxMicros, other.maxMicros);
    count += other.count;
}

double StepPeriodHistogram::percentile(double p) const
{
    if (count == 0) return 0;
    // the rank of the period asked for (1-based), then the bin holding it
    const double rank = std::max(1.0, std::ceil(std::clamp(p, 0.0, 1.0) * double(count)));
    if (rank >= double(count)) return maxMicros;
    double seen = 0;
    for (int b = 0; b < kBins; ++b) {
        seen += counts[std::size_t(b)];
        if (seen >= rank) return std::clamp(binLow(b) + 0.5 * binWidth(b), minMicros, maxMicros);
    }
    return maxMicros;
}

double StepPeriodHistogram::maxJitter(double nominalMicros) const
{
    if (count == 0) return 0;
    return std::max(maxMicros - nominalMicros, nominalMicros - minMicros);
}

}  // namespace studio
