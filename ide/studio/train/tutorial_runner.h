#pragma once
// TutorialRunner: runs one trainer::TutorialSession (an attempt at a tutorial, or its
// demonstration) in a thread of its own, paced to the wall clock, and publishes
// TrainFrames: an immutable Snapshot the viewport draws, a copy of the session's
// progress (the HUD), its events so far and, once it has ended, the result and the
// samples. The GUI never touches the session (as SimulationRunner, ide/studio/sim/).
//
// Input:
//  - live (an attempt): the station's input thread writes the operator's commands with
//    setCommands() while wantsCommands() is true (MainWindow routes the station's sink
//    here then); the solver copies them at the start of a step (try_lock: never waits);
//  - an input log (a demonstration, or a test driving an attempt): a headless
//    trainer::StationEngine with ReplayDevices inside the runner thread, its clock the
//    session's time, mapped by the tutorial's station profile — exactly what
//    `padrob tutorial --demo` and trainer::runTutorialWithLog do.
//
// Pacing: simulated time τ = τ₀ + speed·(wall − w₀), speed 0.25 … 4; (τ₀, w₀) move to
// now on every control change and when more than 50 ms behind (a heavy model runs
// slower, never jumps). pause() holds the session; seek(t) (logs only) goes to time t
// off-clock: forward by stepping as fast as it can, backward by building the session
// again from the start (a run is deterministic, so the same input gives the same state).
//
// Threads: every method is called from the GUI thread except setCommands() (any
// thread); signals are emitted in the GUI thread (queued from the runner thread).

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/snapshot.h"
#include "trainer/input/input_log.h"
#include "trainer/station/profile.h"
#include "trainer/training/runner.h"
#include "trainer/training/session.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <functional>
#include <memory>
#include <span>
#include <thread>
#include <vector>

namespace studio {

/// What the runner publishes: immutable once published.
struct TrainFrame {
    long generation = 0;                      ///< increases with every start()
    std::shared_ptr<const Snapshot> snapshot; ///< the machine now (bundle: the tutorial's model)
    trainer::SessionProgress progress;        ///< what the HUD shows
    std::vector<trainer::TutorialEvent> events;  ///< every event so far, oldest first
    bool paused = false;
    double speed = 1.0;
    double duration = 0.0;  ///< with an input log: its length plus the grace [s] (the scrub range); 0 live
    bool ended = false;
    /// The result and samples, once ended (nullptr before).
    std::shared_ptr<const trainer::RunOutput> output;
    /// The ghost's machine now (setGhost; nullptr without one): the same bundle.
    std::shared_ptr<const Snapshot> ghost;
    /// The faults the instructor injected that are active now (TutorialSession::activeFaults).
    std::vector<trainer::Fault> faults;
    /// The score as it stands (TutorialSession::score(), the result's score): what the attempt would
    /// score now while it runs, its result once ended.
    double score = 0.0;
};

class TutorialRunner : public QObject {
    Q_OBJECT
public:
    static constexpr double kMinSpeed = 0.25;
    static constexpr double kMaxSpeed = 4.0;
    static constexpr double kGrace = 3.0;  ///< after a log runs out [s] (as runTutorialWithLog)

    explicit TutorialRunner(QObject* parent = nullptr);
    /// Stops the thread after its current step and joins it.
    ~TutorialRunner() override;
    TutorialRunner(const TutorialRunner&) = delete;
    TutorialRunner& operator=(const TutorialRunner&) = delete;

    /// A new session of `tutorial` drawn with `bundle` (its model, as makeTutorialBundle
    /// gives), running at once (or paused with `paused`). `log` nullptr: live commands
    /// (setCommands); else the log is replayed through `profile`. False with `error` when
    /// the profile cannot drive the model. Replaces any session there was.
    bool start(std::shared_ptr<const trainer::Tutorial> tutorial, std::shared_ptr<const ModelBundle> bundle,
               std::shared_ptr<const trainer::InputLog> log, const trainer::StationProfile& profile,
               bool paused = false, QString* error = nullptr);
    /// Ends the attempt now (TutorialSession::stop(Aborted)): a result is published and
    /// finished() emitted.
    void stop();
    /// Drops the session without a result (leaving the page); latest() becomes nullptr.
    void close();
    bool isActive() const { return m_active; }

    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    /// Simulated seconds per wall-clock second, clamped to kMinSpeed … kMaxSpeed.
    void setSpeed(double speed);
    double speed() const { return m_speed; }
    /// With an input log: to simulated time `t` (off-clock); the pause state stays.
    void seek(double t);

    /// A ghost for the session running: a second TutorialSession of the same tutorial
    /// driven by `log` through `profile` (the expert's demonstration), stepped in the
    /// runner thread in step with the session (built and brought to the session's time
    /// at once when set during a run; rebuilt by a backward seek), published as
    /// TrainFrame::ghost. nullptr drops it. start() and close() drop it too.
    void setGhost(std::shared_ptr<const trainer::InputLog> log, const trainer::StationProfile& profile);
    bool hasGhost() const { return m_hasGhost; }

    /// The operator's commands, one per tree joint (any thread); used by a live session.
    void setCommands(std::span<const double> u);
    /// A live session is running: the station's commands belong here (any thread).
    bool wantsCommands() const { return m_wantsCommands.load(std::memory_order_relaxed); }

    /// The newest frame; nullptr without a session.
    std::shared_ptr<const TrainFrame> latest() const;

    /// Work on the session itself (the training centre's instructor: inject / clear a
    /// fault, write an instructor event): `task` runs in the runner thread between two
    /// steps (paused too) on the session of generation `generation` (0: whichever runs
    /// then), and a frame is published after it. `done` (may be empty) gets the task's
    /// result in the GUI thread: false with the task's `error`, or "not-running" when
    /// that session is gone or was never handed over. Thread-safe.
    using SessionTask = std::function<bool(trainer::TutorialSession& session, QString& error)>;
    void runInSession(SessionTask task, std::function<void(bool ok, const QString& error)> done = {},
                      long generation = 0);
    /// The generation of the session start() made last (TrainFrame::generation).
    long generation() const { return m_generation; }

signals:
    /// The session ended (completed, failed or stopped): latest()->output holds the result.
    void finished();

private:
    struct Shared;
    struct Run;
    void loop();

    std::unique_ptr<Shared> m_shared;
    std::thread m_thread;
    long m_generation = 0;
    bool m_active = false;
    bool m_paused = false;
    bool m_hasGhost = false;
    double m_speed = 1.0;
    std::atomic<bool> m_wantsCommands{false};
};

/// The tutorial's model as a bundle for the viewport (read from its file again); nullptr
/// with `error`.
std::shared_ptr<const ModelBundle> makeTutorialBundle(const trainer::Tutorial& tutorial, QString* error = nullptr);
/// The scene drawn around it: the tutorial's scene's ground graphics plus a green sphere
/// (radius: the tolerance) at every Reach goal's target (Place: 0.1 m) with a green
/// arrow above it pointing down at it; nullptr when there is nothing to draw.
std::shared_ptr<const ModelBundle> makeTutorialScene(const trainer::Tutorial& tutorial);
/// A snapshot of the machine at a recorded sample (a replay: poses by forward kinematics
/// from SessionSample::q; no dynamics).
std::shared_ptr<const Snapshot> snapshotFromSample(const trainer::SessionSample& sample,
                                                   std::shared_ptr<const ModelBundle> bundle);

}  // namespace studio
