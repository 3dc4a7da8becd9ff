#include "trainer/centre/station_protocol.h"

#include <QString>
#include <QStringList>

#include <array>
#include <cmath>
#include <utility>

namespace trainer::centre {

namespace {

constexpr std::array<std::pair<CommandKind, const char*>, 7> kCommands{{
    {CommandKind::Start, "start"},
    {CommandKind::Pause, "pause"},
    {CommandKind::Resume, "resume"},
    {CommandKind::Reset, "reset"},
    {CommandKind::Stop, "stop"},
    {CommandKind::Inject, "inject"},
    {CommandKind::Clear, "clear"},
}};

constexpr std::array<std::pair<StationStatus, const char*>, 4> kStatuses{{
    {StationStatus::Idle, "idle"},
    {StationStatus::Running, "running"},
    {StationStatus::Paused, "paused"},
    {StationStatus::Ended, "ended"},
}};

/// The value of a wire word in `table`, or `unknown`.
template <class E, std::size_t N>
E fromWire(const std::array<std::pair<E, const char*>, N>& table, std::string_view wire, E unknown)
{
    for (const auto& [value, word] : table)
        if (wire == word) return value;
    return unknown;
}

/// The wire word of `value` in `table` ("" for one not there).
template <class E, std::size_t N>
const char* toWire(const std::array<std::pair<E, const char*>, N>& table, E value)
{
    for (const auto& [v, word] : table)
        if (v == value) return word;
    return "";
}

}  // namespace

CommandKind commandKind(std::string_view wire) { return fromWire(kCommands, wire, CommandKind::Unknown); }
const char* key(CommandKind k) { return toWire(kCommands, k); }
StationStatus stationStatus(std::string_view wire) { return fromWire(kStatuses, wire, StationStatus::Unknown); }
const char* key(StationStatus s) { return toWire(kStatuses, s); }

const char* key(Refusal r)
{
    switch (r) {
    case Refusal::UnknownTutorial: return "unknown-tutorial";
    case Refusal::NotRunning: return "not-running";
    case Refusal::NotPaused: return "not-paused";
    case Refusal::UnknownFault: return "unknown-fault";
    case Refusal::UnknownCommand: return "unknown-command";
    }
    return "unknown-command";
}

namespace {

bool faultOf(const Command& c, CommandKind k, FaultCommand* out)
{
    FaultCommand f;
    if (!Fault::fromKey(c.arg, &f.fault.kind)) return false;
    f.fault.drive = c.arg2;
    const bool worker = f.fault.kind == Fault::Kind::WorkerIn;
    if (k == CommandKind::Inject) {
        if (f.fault.kind == Fault::Kind::StuckValve) f.fault.opening = c.value;
        if (worker) {
            // arg2 "x,y,z" [m]: where the person walks to
            const QStringList xyz = QString::fromStdString(c.arg2).split(',');
            f.fault.drive.clear();
            if (xyz.size() == 3) f.fault.where = {xyz[0].toDouble(), xyz[1].toDouble(), xyz[2].toDouble()};
            f.fault.worker = std::isnan(c.value) ? 0 : static_cast<int>(c.value);
        }
    } else if (worker) {
        f.fault.drive.clear();
        f.worker = std::isnan(c.value) ? -1 : static_cast<int>(c.value);
    }
    *out = std::move(f);
    return true;
}

}  // namespace

bool refused(const Command& c, CommandKind k, StationStatus s, FaultCommand* fault, Refusal* why)
{
    switch (k) {
    case CommandKind::Unknown: *why = Refusal::UnknownCommand; return true;
    case CommandKind::Start:
    case CommandKind::Reset: return false;
    case CommandKind::Pause:
        *why = Refusal::NotRunning;
        return s != StationStatus::Running;
    case CommandKind::Resume:
        *why = Refusal::NotPaused;
        return s != StationStatus::Paused;
    case CommandKind::Inject:
    case CommandKind::Clear:
        if (!faultOf(c, k, fault)) {
            *why = Refusal::UnknownFault;
            return true;
        }
        [[fallthrough]];
    case CommandKind::Stop:
        *why = Refusal::NotRunning;
        return !attemptOn(s);
    }
    return false;
}

bool applyFault(TutorialSession& s, CommandKind k, const FaultCommand& f, QString* error)
{
    if (k == CommandKind::Inject) return s.inject(f.fault, error);
    return s.clearFault(f.fault.kind, f.fault.drive, error, f.worker);
}

State buildState(const StationSituation& x, std::uint64_t seq)
{
    State s;
    s.station = x.station;
    s.seq = seq;
    s.sentUs = wallUs();
    s.status = key(x.status);
    if (x.recordsOffline) s.warnings |= WarnRecordsOffline;
    if (x.recordsRefused) s.warnings |= WarnRecordsRefused;
    if (!x.tutorial) return s;
    const Tutorial& t = *x.tutorial;
    s.simTime = x.simTime;
    s.q.assign(x.q.begin(), x.q.end());
    s.commands.reserve(x.commands.size());
    for (double u : x.commands) s.commands.push_back(static_cast<float>(u));
    s.tutorial = t.spec.id;
    s.operatorCode = clip(x.operatorCode, limits::kOperatorCode);  // as typed at the station
    const SessionProgress& p = x.progress;
    s.attemptTime = p.t;
    s.goal = p.goal;
    s.goals = static_cast<int>(t.spec.goals.size());
    s.clearance = p.clearance;
    s.workerDistance = p.workerDistance;
    s.score = x.status == StationStatus::Idle ? 0.0 : x.score;
    s.endReason = clip(x.endReason, limits::kField);
    if (p.overload) s.warnings |= WarnOverload;
    if (p.nearWorker) s.warnings |= WarnNearWorker;
    if (p.clearance >= 0 && p.clearance < t.scoring().nearDistance) s.warnings |= WarnNearScene;
    for (const Fault& f : x.faults) {
        s.warnings |= WarnFault;
        s.faults += (s.faults.empty() ? "" : ",") + std::string(Fault::key(f.kind)) + (f.drive.empty() ? "" : ":" + f.drive);
    }
    s.faults = clip(s.faults, limits::kText);
    return s;
}

Event buildEvent(const std::string& station, std::uint64_t seq, const Tutorial& tutorial, const TutorialEvent& e,
                 const std::string& language)
{
    Event out;
    out.station = station;
    out.seq = seq;
    out.t = e.t;
    out.tutorial = tutorial.spec.id;
    out.kind = TutorialEvent::key(e.kind);
    out.text = clip(e.text(&tutorial, language).toStdString(), limits::kText);
    out.detail = clip(e.detail, limits::kField);
    out.value = e.value;
    out.penalty = e.penalty;
    return out;
}

}  // namespace trainer::centre
