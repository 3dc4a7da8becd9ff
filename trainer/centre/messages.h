#pragma once
// The training centre's messages as plain C++ values (docs/training-centre.md). They
// mirror centre_topics.idl one to one; only bus.cpp converts them to and from DDS samples.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace trainer::centre {

/// The wall clock in µs since the epoch (UTC): State::sentUs, latencies.
std::uint64_t wallUs();

/// Bounds on every string and sequence a message carries [bytes of UTF-8, entries].
/// A Bus refuses to write a message over them (saying which field), and drops and counts
/// one it reads over them (limitProblem). Names and operator codes must also be free of
/// control characters.
namespace limits {
inline constexpr std::size_t kName = 64;          ///< node names: node, station, target, sender
inline constexpr std::size_t kOperatorCode = 32;  ///< an operator's code
inline constexpr std::size_t kWord = 64;          ///< role, status, kind, tutorial id, language, fault key
inline constexpr std::size_t kField = 256;        ///< host, model, model hash, command arguments, detail, end
inline constexpr std::size_t kText = 2048;        ///< event text, reply message, faults, the tutorial list
inline constexpr std::size_t kMac = 64;           ///< a hex HMAC-SHA256
inline constexpr std::size_t kJoints = 256;       ///< State::q and State::commands
inline constexpr std::size_t kTutorials = 64;     ///< Announce::tutorials
}  // namespace limits

/// A node says who it is (stations, instructors, displays). Reliable, transient-local.
struct Announce {
    std::string node;       ///< unique in the centre
    std::string role;       ///< "station", "instructor", "display"
    std::string host;
    int pid = 0;
    std::string model;      ///< stations: the model's name
    std::string modelHash;  ///< stations: SHA-256 (hex) of the model file's text
    std::vector<std::string> tutorials;  ///< stations: the tutorial ids they run
    std::string language;
    std::uint64_t startedMs = 0;
    std::uint64_t sentMs = 0;  ///< when this announcement was written [ms since the epoch, UTC]
    std::string mac;           ///< hex HMAC-SHA256 of the rest (signing.h)
};

/// Announce::role of a node's last announcement, written (signed) as it leaves.
inline constexpr const char* kRoleGone = "gone";

/// Bits of State::warnings.
enum StateWarning : std::uint32_t {
    WarnOverload = 1,        ///< a relief valve is open
    WarnNearWorker = 2,      ///< inside a person's safety zone
    WarnNearScene = 4,       ///< closer than the near-miss distance to the scene
    WarnFault = 8,           ///< an injected fault is active
    WarnRecordsOffline = 16, ///< the centre's records database is out of reach (recording locally)
    WarnRecordsRefused = 32, ///< the station's own journal refuses writes (attempts kept in pending files)
};

/// A station's state at display rate. Best effort: a lost one is replaced by the next.
struct State {
    std::string station;
    std::uint64_t seq = 0;
    std::uint64_t sentUs = 0;  ///< wall clock when sent [µs since the epoch, UTC]
    double simTime = 0;
    std::vector<double> q;        ///< θ per tree joint
    std::vector<float> commands;  ///< valve openings applied, per tree joint
    std::string tutorial;
    std::string status;           ///< "idle", "running", "paused", "ended" (StationStatus, station_protocol.h)
    std::string operatorCode;
    double attemptTime = 0;
    double score = 0;
    int goal = 0;
    int goals = 0;
    double clearance = -1;
    double workerDistance = -1;
    std::uint32_t warnings = 0;
    std::string faults;           ///< "hose-burst:Boom,power-cut"
    std::string endReason;
    std::string mac;              ///< hex HMAC-SHA256 of the rest (signing.h)
};

/// Something that happened at a station (tutorial events, the instructor's actions).
struct Event {
    std::string station;
    std::uint64_t seq = 0;
    double t = 0;
    std::string tutorial;
    std::string kind;
    std::string text;
    std::string detail;
    double value = std::numeric_limits<double>::quiet_NaN();
    double penalty = 0;
    std::uint64_t sentMs = 0;  ///< when sent [ms since the epoch, UTC]: an old one replayed is dropped
    std::string mac;           ///< hex HMAC-SHA256 of the rest (signing.h)
};

/// An instructor's command to a station, signed (signing.h).
struct Command {
    std::string target;
    std::string sender;
    std::uint64_t nonce = 0;
    std::int64_t issuedMs = 0;
    std::string kind;  ///< "start", "pause", "resume", "reset", "stop", "inject", "clear" (CommandKind)
    std::string arg;
    std::string arg2;
    double value = std::numeric_limits<double>::quiet_NaN();
    std::string mac;   ///< hex HMAC-SHA256 of the rest
};

/// What a station did with a command.
struct Reply {
    std::string station;
    std::string sender;
    std::uint64_t nonce = 0;
    bool accepted = false;
    std::string message;
    std::string mac;  ///< hex HMAC-SHA256 of the rest (signing.h)
};

/// `s` cut to at most `max` bytes on a UTF-8 character's boundary: what a node says of its
/// own (an event's text, a reply's sentence, a code typed at the station) fits the limits.
std::string clip(const std::string& s, std::size_t max);

/// What is wrong with a message's sizes ("" nothing): the first field over its bound
/// (limits), or a name or operator code with a control character, as
/// "operatorCode: 40 bytes, at most 32".
std::string limitProblem(const Announce& a);
std::string limitProblem(const State& s);
std::string limitProblem(const Event& e);
std::string limitProblem(const Command& c);
std::string limitProblem(const Reply& r);

}  // namespace trainer::centre
