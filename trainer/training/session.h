#pragma once
// One attempt at a tutorial: the simulation of its model, the operator's commands, and
// the checker that watches goals, grasping, collisions, overloads and time and scores
// the run (docs/training.md "Checking and scoring").
//
// A session owns its Simulation and its CollisionWorld: the Train workspace runs one in
// its solver thread, `padrob tutorial` and the tests run one in theirs, and a
// demonstration's ghost is a second session. Nothing here is shared but the Tutorial.
//
// Time steps are fixed (RK4, 1 ms by default). Every step: the commands (only the
// enabled drives; the rest held closed), the solver's events (relief valves opening are
// overloads; a drive banging into its limit is a limit bang), the grip, the current
// goal. Every `checkPeriod` (20 ms): clearances (FCL) against the scene and the people in it.

#include "solver/collision/collision_world.h"
#include "solver/integrate/simulation.h"
#include "trainer/training/faults.h"
#include "trainer/training/tutorial.h"

#include <QString>

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace trainer {

struct TutorialEvent {
    enum class Kind {
        GoalDone,     ///< detail: the goal's id
        Grasp,        ///< the load is in the claws
        MissedGrasp,  ///< the claws closed away from the load's grip
        Release,      ///< the load left the claws
        Drop,         ///< released out of place: it falls (penalty)
        Hit,          ///< touched the scene (penalty); detail: what
        HardHit,      ///< touched it too fast: the attempt ends
        NearMiss,     ///< closer than NEAR to the scene (no penalty)
        WorkerZone,   ///< inside a person's safety zone (penalty)
        WorkerHit,    ///< touched a person: the attempt ends
        Overload,     ///< a relief valve opened (penalty); detail: the drive
        LimitBang,    ///< a drive hit its end stop fast (penalty)
        Saturation,   ///< fluid power: the pump could not give what the valves asked (penalty as Overload); detail: the pump
        Cavitation,   ///< fluid power: a load ran ahead of the oil (penalty as Overload); detail: the drive
        TimeUp,       ///< the time limit: the attempt ends
        InputEnded,   ///< a replayed input ran out before the goals were done
        SolverError,  ///< the simulation failed (a loop locked…): the attempt ends
        Fault,        ///< the instructor injected a fault (no penalty); detail: Fault::key and its drive or person
        FaultCleared, ///< the instructor cleared one; detail as for Fault
        Instructor,   ///< the instructor started, paused, resumed, reset or stopped the attempt; detail: "pause:NAME"…
        Aborted,      ///< the operator or the trainer stopped it
    };
    Kind kind = Kind::GoalDone;
    double t = 0.0;        ///< [s]
    double value = 0.0;    ///< speed of a hit [m/s], distance [m], force [N]…
    double penalty = 0.0;  ///< points taken
    /// goal id, shape, drive name (as in the model); a PART's or WORKER's English name; faults:
    /// "hose-burst LEVANTE PLUMA", "stuck-valve EXTENSIÓN" (value: the opening), "worker-in the
    /// fitter" (the WORKER's English name, or "G id"), "power-cut"
    std::string detail;
    /// hits: the tutorial's PART touched; worker events (and a fault "worker-in"): the WORKER (−1 none)
    int subject = -1;
    /// SolverError: the solver's message, translatable (`detail` is its English); text()
    /// shows it in the current language. Empty for the other kinds and for events read back.
    solver::Text detailText;

    static const char* key(Kind k);  ///< stable name, e.g. "hit" (files, JSON, records)
    static QString label(Kind k);    ///< translated, e.g. "Hit"
    /// Translated sentence for the timeline; with the tutorial, parts and people are
    /// named in `language`.
    QString text(const Tutorial* tutorial = nullptr, const std::string& language = "en") const;
};

struct ScoreItem {
    std::string key;     ///< "time", "path", "smooth", "safety"
    double value = 0.0;  ///< the measure (s, %, m/s³, penalty points)
    double points = 0.0;
    double max = 0.0;
    /// What the work done made earnable: max × the share of the work done (time: max once
    /// every goal is done, else 0). Points short of it are what the operator lost.
    double earnable = 0.0;
    QString label() const;   ///< translated
    QString advice() const;  ///< what to improve, translated ("" when nothing earnable was lost)
};

struct TutorialResult {
    bool completed = false;  ///< every goal done
    bool passed = false;     ///< completed, no hard hit, score ≥ the pass mark
    bool ended = false;      ///< the attempt is over (completed, failed or stopped)
    std::string endReason;   ///< "completed", "time-up", "hard-hit", "worker-hit", "input-ended", "solver-error", "aborted"
    double time = 0.0;       ///< [s]
    double score = 0.0;      ///< 0–100
    int stars = 0;           ///< 0–3
    int goalsDone = 0;
    /// The share of the stage's work done, 0–1: the goals done, and of the current goal
    /// the way made towards its target (from where it started to its tolerance), over the
    /// number of goals. 1 when completed. Path, smoothness and safety earn their points
    /// in this proportion: an attempt that did nothing scores 0.
    double work = 0.0;
    std::vector<ScoreItem> breakdown;
    std::vector<TutorialEvent> events;
    // measures, for the debrief's comparison with the expert
    double pathLength = 0.0;      ///< of the tracked point [m]
    double idealLength = 0.0;     ///< straight lines between where the goals were done [m]
    double overshoot = 0.0;       ///< largest excursion past a target's tolerance after reaching it [m]
    double rmsJerk = 0.0;         ///< of the tracked point [m/s³]
    double penalties = 0.0;
    Eigen::Vector3d finalPoint = Eigen::Vector3d::Zero();  ///< where the tracked point ended [m]
    Eigen::Matrix3d finalAxes = Eigen::Matrix3d::Identity();  ///< the tracked body's axes then (columns, world)
    Eigen::Vector3d finalLoad = Eigen::Vector3d::Zero();   ///< the load's centre of mass then (GRIP) [m]
    int count(TutorialEvent::Kind k) const;
    /// Translated advice, most valuable first.
    QStringList improvements() const;
};

/// A snapshot every `sampleEvery` for plots and replays.
struct SessionSample {
    double t = 0.0;
    std::vector<double> q;            ///< θ per tree joint (a replay draws from these)
    std::vector<float> driveForce;    ///< per tree joint [N or N·m] (0 without a drive)
    std::vector<std::uint8_t> relief; ///< per tree joint: relief valve open
    Eigen::Vector3d track = Eigen::Vector3d::Zero();
    float clearance = 0.0f;           ///< to the scene [m] (∞ when not checked)
    bool grasped = false;
};

struct SessionOptions {
    double dt = 1e-3;            ///< RK4 step [s]
    double checkPeriod = 0.02;   ///< clearances [s] (a hit at 0.5 m/s is found within 1 cm)
    double sampleEvery = 0.02;   ///< samples [s]
    double jerkInterval = 0.05;  ///< finite-difference interval of the jerk [s]
};

/// What the HUD shows, updated every step.
struct SessionProgress {
    double t = 0.0;
    int goal = 0;              ///< index of the current goal; = goals.size() when all done
    double distance = -1.0;    ///< to the current goal's target [m] (−1: not positional)
    double dwell = 0.0;        ///< time held within tolerance so far [s]
    bool withinTolerance = false;
    /// REACH and PLACE: the distance is within the goal's TOL (the ALIGNs may not be).
    bool positioned = false;
    /// The current goal's ALIGN furthest from its direction: its error and its ANGTOL
    /// [rad] (−1, 0: the goal has no ALIGN).
    double angleError = -1.0;
    double angleTolerance = 0.0;
    bool grasped = false;
    double clearance = -1.0;   ///< to the scene [m] (−1: not checked)
    double workerDistance = -1.0;  ///< to the nearest person [m] (−1: none)
    bool nearWorker = false;
    bool overload = false;     ///< a relief valve is open now
    double penalties = 0.0;
    std::vector<int> hints;    ///< indices into the tutorial's hints that apply now
};

class TutorialSession {
public:
    TutorialSession(std::shared_ptr<const Tutorial> tutorial, const SessionOptions& options = {});
    ~TutorialSession();
    TutorialSession(const TutorialSession&) = delete;
    TutorialSession& operator=(const TutorialSession&) = delete;

    const Tutorial& tutorial() const { return *m_tutorial; }
    const solver::Simulation& simulation() const { return *m_sim; }
    double time() const;

    /// The operator's commands, one per tree joint (only enabled drives are used).
    void setCommands(std::span<const double> u);
    /// One step. False when the attempt has ended (then nothing more happens).
    bool step();
    /// Steps until `t` or the end. False when it has ended.
    bool advanceTo(double t);
    /// Ends the attempt now (reason "aborted", or "input-ended").
    void stop(TutorialEvent::Kind why);

    bool ended() const { return m_result.ended; }
    /// Why it ended ("" while it runs; TutorialResult::endReason).
    const std::string& endReason() const { return m_result.endReason; }
    const SessionProgress& progress() const { return m_progress; }
    const std::vector<TutorialEvent>& events() const { return m_result.events; }
    const std::vector<SessionSample>& samples() const { return m_samples; }
    /// The result so far (final once ended()).
    TutorialResult result() const;
    /// result().score, without copying the events (a running score for every frame).
    double score() const;
    /// Where the tracked point is now (TRACK, else the GRIP's tool point…) [m].
    Eigen::Vector3d trackPoint() const;

    // Faults the instructor injects (faults.h, docs/training.md). Between steps, on the
    // session's thread. Each inject and clear adds an event (Fault, FaultCleared) at the
    // time it happened; neither costs points (what follows is scored as usual).
    //  - HoseBurst: the drive's joint goes passive in the solver (Simulation::setDriveFault):
    //    the load sags under gravity until a limit; its lever does nothing. Cleared: the
    //    drive holds again where it is, and its lever acts.
    //  - StuckValve: the drive runs at the stuck opening whatever its lever says (q̇ = u·vmax).
    //  - WorkerIn: the WORKER's graphics move to `where` (workerOffset() for the viewer)
    //    and the checker measures the person there (at the next step). Cleared: back
    //    where the scene has them.
    //  - PowerCut: every command is 0 (the valves close, the machine holds; a relief valve
    //    can still open under an overload). It overrides a stuck valve; a burst hose still sags.
    // Injecting a fault that is active again (same kind and drive, or worker) replaces it.
    // Returns false with a translated `error` (may be nullptr), changing nothing, when the
    // attempt has ended, the drive is not one of the machine's hydraulic drives (the
    // message lists them), an opening is outside [−1, 1], the tutorial has no such worker…
    bool inject(const Fault& fault, QString* error = nullptr);
    /// Clears the active fault of that kind on that drive (HoseBurst, StuckValve; the name
    /// as inject() takes it) or of worker `worker` (WorkerIn; −1: every worker who walked
    /// in); PowerCut: power is back. False with a translated `error` when there is none.
    bool clearFault(Fault::Kind kind, const std::string& drive = {}, QString* error = nullptr, int worker = -1);
    /// Writes the instructor's action on the attempt into its events (Kind::Instructor,
    /// detail "ACTION:SENDER": "start:desk", "pause:desk"…; no points), at the time now.
    /// Works after the end too. Between steps, on the session's thread.
    void addInstructorEvent(const std::string& action, const std::string& sender);
    /// The faults active now, in the order they were injected (StuckValve with the
    /// opening used, drives by their names as the events give them).
    std::vector<Fault> activeFaults() const { return m_faults; }
    /// Per WORKER: where to draw the person now, as a transform of the graphics as the
    /// scene places them (identity unless the person walked in).
    const std::vector<Eigen::Isometry3d>& workerOffsets() const { return m_workerOffsets; }
    Eigen::Isometry3d workerOffset(int worker) const;
    /// Where WORKER `worker` stands now: its first graphic's POS moved by its offset (the
    /// reference Fault::where sets); the origin when the worker has no graphics.
    Eigen::Vector3d workerPosition(int worker) const;

private:
    /// The breakdown, score, pass and stars of `r` from its measures (completed, end
    /// reason, time, path and ideal lengths, RMS jerk, penalties) and the work done now
    /// (r.work, workDone()).
    void scoreInto(TutorialResult& r) const;
    /// The share of the work done now (TutorialResult::work); `approach`: the way made
    /// towards the current goal's target [m] (0 when it has none).
    double workDone(double* approach = nullptr) const;
    void handleSolverEvents(const std::vector<solver::SimulationEvent>& events, const std::vector<double>& qdBefore);
    void checkGrip();
    void checkGoal();
    void checkClearances();
    void track();
    void sample();
    void addEvent(TutorialEvent::Kind kind, double value, double penalty, std::string detail, int subject = -1);
    int partOf(int shape) const;
    void end(const std::string& reason, bool completed);
    void goalDone();
    std::string shapeName(int shape) const;
    std::string driveName(int joint) const;
    bool isClaw(int joint) const;
    /// The hydraulic drive named `name` (faults), or −1 with a translated `error` listing them.
    int findDrive(const std::string& name, QString* error) const;
    /// The first graphic's POS of WORKER w in the scene (the reference of Fault::where).
    Eigen::Vector3d workerAnchor(int w) const;
    void placeWorker(int w, const Eigen::Isometry3d& offset);

    std::shared_ptr<const Tutorial> m_tutorial;
    SessionOptions m_options;
    std::unique_ptr<solver::Simulation> m_sim;
    std::unique_ptr<solver::CollisionWorld> m_world;
    std::vector<std::vector<int>> m_workerShapes;  // per worker: shape indices
    std::vector<double> m_commands;
    std::vector<solver::SimulationEvent> m_simEvents;
    std::vector<double> m_qdBefore;
    long m_step = 0;
    TutorialResult m_result;
    SessionProgress m_progress;
    std::vector<SessionSample> m_samples;
    // grip
    bool m_grasped = false, m_wasClosed = false, m_wasOpen = true, m_fixed = false;
    bool m_loadResting = false;  // grasped, not yet lifted clear of what it lay on
    // released during a PLACE goal under CONTACT: the load settles by contact, and the goal
    // is decided once it has rested (kSettleStill) or after kSettleLimit (placed or dropped)
    bool m_settling = false;
    double m_settleStart = 0.0, m_stillSince = -1.0;
    // goal
    double m_goalStart = 0.0;
    double m_goalStartDistance = -1.0;  // to the current goal's target when it began [m] (−1: not yet, or none)
    bool m_enteredGoal = false;
    // collisions: an episode lasts while touching (re-armed when clear)
    bool m_touching = false, m_near = false;
    std::vector<char> m_inZone;
    std::vector<char> m_skip;  // bodies left out of the scene query
    // CONTACT: per body, the fastest approach of its contacts since the last clearance
    // check [m/s]: contact stops a hit within a step, before the check sees the touch
    std::vector<double> m_impact;
    void recordImpacts();
    double m_lastCheck = -1.0;
    // tracking
    std::vector<Eigen::Vector3d> m_jerkWindow;  // the last four positions at jerkInterval
    double m_lastJerkSample = -1.0;
    double m_jerkSquares = 0.0;
    long m_jerkCount = 0;
    Eigen::Vector3d m_lastTrack = Eigen::Vector3d::Zero();
    Eigen::Vector3d m_lastGoalPoint = Eigen::Vector3d::Zero();
    double m_lastSample = -1.0;
    std::vector<char> m_reliefOpen;
    // faults
    std::vector<Fault> m_faults;        // active, in the order injected
    std::vector<double> m_stuck;        // per tree joint: the stuck valve's opening (NaN: free)
    bool m_powerCut = false;
    std::vector<Eigen::Isometry3d> m_workerOffsets;  // per worker
};

}  // namespace trainer
