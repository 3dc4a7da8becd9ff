#pragma once
// The station's side of the centre's protocol, in one place (docs/training-centre.md):
// what an instructor's command asks, typed and decoded once from the wire; what a
// station says it is doing; why it refuses; and the State and Event it publishes. Both
// stations use it: `padrob station` (StationNode, headless) and padrob-studio's Train
// workspace (studio::TrainStation), so they answer the same commands with the same
// words and publish the same state (the running score included).

#include "trainer/centre/messages.h"
#include "trainer/training/faults.h"
#include "trainer/training/session.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace trainer::centre {

/// What a Command asks (Command::kind on the wire).
enum class CommandKind { Start, Pause, Resume, Reset, Stop, Inject, Clear, Unknown };
/// The kind of a wire word; Unknown for any other.
CommandKind commandKind(std::string_view wire);
/// The wire word ("start", …; "" for Unknown).
const char* key(CommandKind k);

/// What a station is doing (State::status on the wire).
enum class StationStatus { Idle, Running, Paused, Ended, Unknown };
StationStatus stationStatus(std::string_view wire);
/// "idle", "running", "paused", "ended" ("" for Unknown).
const char* key(StationStatus s);
/// An attempt is on (running or paused): it can be paused, resumed, stopped, faulted.
inline bool attemptOn(StationStatus s) { return s == StationStatus::Running || s == StationStatus::Paused; }

/// Why a station refuses a command (Reply::message on the wire; the guard's codes,
/// CommandGuard, come before these).
enum class Refusal { UnknownTutorial, NotRunning, NotPaused, UnknownFault, UnknownCommand };
/// "unknown-tutorial", "not-running", "not-paused", "unknown-fault", "unknown-command".
const char* key(Refusal r);
/// Reply::message of a command done.
inline constexpr const char* kDone = "done";

/// The fault an inject or clear command names: arg the fault's key, arg2 the drive (or,
/// for worker-in, "x,y,z" [m] where the person walks to), value the stuck opening or the
/// worker's index.
struct FaultCommand {
    Fault fault;
    int worker = -1;  ///< clear worker-in: which person (−1 all)
};

/// Whether a station in status `s` refuses command `c` of kind `k`, and why: an unknown
/// command; inject or clear naming an unknown fault (`fault` is set otherwise); pause
/// without a running attempt, resume without a paused one, stop, inject and clear
/// without one on. Start and reset are refused later only if their tutorial is unknown.
bool refused(const Command& c, CommandKind k, StationStatus s, FaultCommand* fault, Refusal* why);

/// Carries out a fault command on a session: inject, or clear. False with `error`.
bool applyFault(TutorialSession& s, CommandKind k, const FaultCommand& f, QString* error);

/// What a station knows of its attempt at one instant: all the state builder needs.
struct StationSituation {
    std::string station;
    StationStatus status = StationStatus::Idle;
    /// The tutorial of the attempt (or the one ready, idle); nullptr: nothing to tell.
    const Tutorial* tutorial = nullptr;
    std::string operatorCode;
    double simTime = 0;
    std::span<const double> q;         ///< θ per tree joint
    std::span<const double> commands;  ///< the valve openings applied, per tree joint
    SessionProgress progress;
    /// The score as it stands (TutorialSession::score(), the result's score: while the attempt runs,
    /// what it would score now; its result once ended).
    double score = 0;
    std::string endReason;
    std::span<const Fault> faults;  ///< active now
    bool recordsOffline = false;    ///< WarnRecordsOffline
    bool recordsRefused = false;    ///< WarnRecordsRefused
};

/// The State a station publishes (its seq and send time set; the bus signs it).
State buildState(const StationSituation& s, std::uint64_t seq);

/// The Event a station publishes for one of its attempt's events, its text in `language`.
Event buildEvent(const std::string& station, std::uint64_t seq, const Tutorial& tutorial, const TutorialEvent& e,
                 const std::string& language);

}  // namespace trainer::centre
