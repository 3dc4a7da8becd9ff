#pragma once
// SimulationRunner: runs one solver::Simulation in its own thread at a fixed step
// (classic RK4, 1 ms by default), paced to the wall clock, and publishes Snapshots.
//
// Threads (DESIGN "The application"; STYLE habit 9):
//  - The runner is a QObject of the GUI thread: every method below is called there
//    (except setCommand/setCommands, safe from any thread: the station's input thread
//    writes the operator's commands) and every signal is emitted there (the solver
//    thread posts them, queued).
//  - The solver thread owns the Simulation. setBundle() and reset() build the new
//    Simulation in the GUI thread, publish its initial snapshot at once and hand it
//    over; from then on only the solver thread touches it.
//  - Neither side waits for the other: control calls set a few fields under a mutex
//    that the solver holds only to read them between batches (never during a step);
//    commands are written into a small buffer that the solver copies at the start of
//    each step when they changed (try_lock: if the GUI holds it at that instant the
//    step uses the previous commands); latest() copies a shared_ptr under a mutex held
//    for that copy only. (GCC 12's std::atomic<std::shared_ptr> is not lock-free
//    either — a lock bit in the pointer — and its load() releases that bit with
//    relaxed order, which ThreadSanitizer reports as a race.)
//
// Pacing: simulated time τ follows the wall clock w as τ = τ₀ + speed·(w − w₀). A
// step's deadline is the wall time at which its end is due. The solver wakes when
// the next step is due to start — 2 ms before its deadline, but at least 1 ms after
// the previous wake-up was planned (so at speed > 1 the steps come in batches of a
// millisecond's worth, and a late wake-up does not shift the schedule) — runs every
// step due by then, publishes one snapshot, and sleeps on a condition variable
// (steady clock) until the next wake-up or a control call: a paused runner uses no
// CPU. A step that ends after its deadline is an overrun. When more than 50 ms
// behind, the solver stops catching up (the lag is added to droppedSeconds and
// (τ₀, w₀) move to now): a model too heavy for real time runs slower, publishing
// every 10 ms, but simulated time never jumps.
//
// Determinism: step k (k = 1, 2, …) is advanceTo(k · timeStep) with the commands read
// just before it, so a run is exactly the same as a plain Simulation advanced step by
// step with the same commands, whatever the pacing.
//
// Step periods: besides the Snapshot's figures over the last second, the solver
// counts every paced step's period (the wall-clock interval between the ends of
// consecutive steps: 1 ms at speed 1) in a fixed-size histogram (StepPeriodHistogram)
// of relaxed atomics that only it writes: no lock and no allocation in the loop.
// stepPeriods() reads it (percentiles, max jitter), resetStepPeriods() starts again.
//
// Failure: when advanceTo() fails (a non-finite state, chattering, a loop locking
// up) the runner publishes a snapshot of the last good state with `error` set,
// pauses, and emits failed(). It then stays stopped (start() and stepOnce() do
// nothing) until reset() or setBundle().

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/snapshot.h"

#include <QObject>
#include <QString>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <thread>
#include <vector>

namespace studio {

/// Step periods [µs] as a histogram of fixed size: 1 µs bins below 5 ms, 100 µs bins
/// below 100 ms and one bin for longer periods; the shortest and the longest exactly.
/// A plain value (about 24 kB): SimulationRunner::stepPeriods() returns a copy.
struct StepPeriodHistogram {
    static constexpr int kFineBins = 5000;   ///< [0, 5 ms) by 1 µs
    static constexpr int kCoarseBins = 950;  ///< [5 ms, 100 ms) by 100 µs
    static constexpr int kBins = kFineBins + kCoarseBins + 1;  ///< and [100 ms, ∞)

    std::array<std::uint32_t, kBins> counts{};
    long count = 0;          ///< periods counted (the sum of counts)
    double minMicros = 0;    ///< the shortest period [µs] (0 when none)
    double maxMicros = 0;    ///< the longest period [µs] (0 when none)

    /// The bin of a period [µs] (negative and NaN periods go to bin 0).
    static int bin(double micros);
    /// A bin's lower edge and width [µs] (the last bin: from 100 ms, width 0).
    static double binLow(int bin);
    static double binWidth(int bin);

    void add(double micros);
    /// Adds `other`'s periods (counts, shortest, longest).
    void merge(const StepPeriodHistogram& other);
    /// The period that a fraction `p` (0 … 1) of the periods do not exceed [µs]: the
    /// middle of its bin, within [minMicros, maxMicros]; 0 when empty.
    double percentile(double p) const;
    double median() const { return percentile(0.5); }
    /// The largest deviation of any period from `nominalMicros` [µs]; 0 when empty.
    double maxJitter(double nominalMicros) const;
};

class SimulationRunner : public QObject {
    Q_OBJECT
public:
    static constexpr double kMinSpeed = 0.1;
    static constexpr double kMaxSpeed = 4.0;
    static constexpr double kDefaultTimeStep = 1e-3;  ///< [s]

    explicit SimulationRunner(QObject* parent = nullptr);
    /// Stops the solver thread (after its current step) and joins it.
    ~SimulationRunner() override;
    SimulationRunner(const SimulationRunner&) = delete;
    SimulationRunner& operator=(const SimulationRunner&) = delete;

    /// A new Simulation of `bundle` at the model's initial state, paused; commands back
    /// to 0. nullptr: no model (latest() then returns nullptr). Emits bundleChanged(),
    /// and stateChanged(false) when it was running.
    void setBundle(std::shared_ptr<const ModelBundle> bundle);
    std::shared_ptr<const ModelBundle> bundle() const { return m_bundle; }

    /// The fixed step [s] (clamped to 1e-5 … 0.05), used from the next setBundle() or
    /// reset(). Default kDefaultTimeStep.
    void setTimeStep(double seconds);
    double timeStep() const { return m_timeStep; }

    /// Runs, paced to the wall clock. Nothing without a model or after a failure.
    void start();
    /// Stops after the current step; the solver then publishes a snapshot with running false.
    void pause();
    /// While paused: one more step (queued: several calls give as many steps).
    void stepOnce();
    /// While paused: the state's coordinates become `theta` (θ per tree joint, dim nb or
    /// nq — a free joint's base orientation is kept), at rest (θ̇ = 0), as the joint
    /// sliders set them (a pose whose loops close: JointSliders makes it; the loops are
    /// closed again around it). Sent like the commands: the solver thread takes it
    /// before its next step (Simulation::setInitial) and publishes a snapshot with
    /// poseEdits one higher; time and commands are kept, and run() continues from there.
    /// Returns false, sending nothing, while running, without a model, after a failure
    /// or when `theta` is too short; a new model or reset() drops a pose not yet taken.
    bool setPositions(const Eigen::VectorXd& theta);

    /// Back to the model's initial state (a new Simulation), paused; keeps the commands
    /// and the speed. Emits restarted(), and stateChanged(false) when it was running.
    void reset();
    bool isRunning() const;

    /// Simulated seconds per wall-clock second, clamped to kMinSpeed … kMaxSpeed.
    void setSpeed(double speed);
    double speed() const;

    /// Command u in [−1, 1] (clamped; NaN → 0) of tree joint `treeJoint`, read by the
    /// next step. Out-of-range joints are ignored. setCommand() and setCommands() may
    /// be called from any thread (the station's input thread calls setCommands).
    void setCommand(int treeJoint, double u);
    /// All commands at once (element i for tree joint i; missing ones 0): one input
    /// snapshot, read whole by the next step.
    void setCommands(std::span<const double> u);
    /// The commands as last written (dim nb).
    std::vector<double> commands() const;

    /// Pushes body `treeBody` (tree index) with the mouse from the next step: its point
    /// `localPoint` (body frame [m]) pulled toward the world point `target` [m]
    /// (solver::Simulation::setPush), sent to the solver thread as the commands are;
    /// replaced by the next call, ended by clearPush(), a new model or reset(). A body
    /// out of range or a coordinate that is not finite: no push.
    void setPush(int treeBody, const Eigen::Vector3d& localPoint, const Eigen::Vector3d& target);
    void clearPush();
    /// The push as last written (body −1: none).
    solver::Push push() const;

    /// The newest snapshot (never blocks on the solver); nullptr without a model.
    std::shared_ptr<const Snapshot> latest() const;

    /// The periods of the paced steps since resetStepPeriods() (or since the runner
    /// was made), of every model and run; the first step of a run has none. A step
    /// being counted while this reads may be missed. At speed 1 the nominal period is
    /// timeStep(); at speed s the steps come in batches (see "Pacing").
    StepPeriodHistogram stepPeriods() const;
    /// Counts from zero again: the solver clears the histogram before its next step is
    /// counted; until then stepPeriods() is empty.
    void resetStepPeriods();

signals:
    /// Started, paused (by pause(), reset(), setBundle() or a failure).
    void stateChanged(bool running);
    /// The simulation failed or a loop locked up; it is paused, the snapshot of the
    /// last good state (with Snapshot::error) stays. The message says when and where.
    void failed(const QString& message);
    /// setBundle() installed a new model (or none).
    void bundleChanged();
    /// reset() went back to the initial state.
    void restarted();

private:
    struct Shared;
    class Worker;

    /// Builds a Simulation of m_bundle, publishes its initial snapshot and hands it to
    /// the solver thread. False (and failed() emitted) when the Simulation cannot be made.
    bool install(bool keepCommands);
    void emitFromSolver(long generation, bool stopped, const QString& message);

    std::shared_ptr<const ModelBundle> m_bundle;
    double m_timeStep = kDefaultTimeStep;
    std::unique_ptr<Shared> m_shared;
    std::thread m_thread;
};

}  // namespace studio
