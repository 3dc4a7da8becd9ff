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
        TimeUp,       ///< the time limit: the attempt ends
        InputEnded,   ///< a replayed input ran out before the goals were done
        SolverError,  ///< the simulation failed (a loop locked…): the attempt ends
        Aborted,      ///< the operator or the trainer stopped it
    };
    Kind kind = Kind::GoalDone;
    double t = 0.0;        ///< [s]
    double value = 0.0;    ///< speed of a hit [m/s], distance [m], force [N]…
    double penalty = 0.0;  ///< points taken
    std::string detail;    ///< goal id, shape, drive name (as in the model); a PART's or WORKER's English name
    int subject = -1;      ///< hits: the tutorial's PART touched; worker events: the WORKER (−1 none)
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
    QString label() const;   ///< translated
    QString advice() const;  ///< what to improve, translated ("" when full marks)
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
    const SessionProgress& progress() const { return m_progress; }
    const std::vector<TutorialEvent>& events() const { return m_result.events; }
    const std::vector<SessionSample>& samples() const { return m_samples; }
    /// The result so far (final once ended()).
    TutorialResult result() const;
    /// Where the tracked point is now (TRACK, else the GRIP's tool point…) [m].
    Eigen::Vector3d trackPoint() const;

private:
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
    // goal
    double m_goalStart = 0.0;
    bool m_enteredGoal = false;
    // collisions: an episode lasts while touching (re-armed when clear)
    bool m_touching = false, m_near = false;
    std::vector<char> m_inZone;
    std::vector<char> m_skip;  // bodies left out of the scene query
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
};

}  // namespace trainer
