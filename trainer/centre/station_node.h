#pragma once
// A training station on the centre's bus (docs/training-centre.md): it runs the
// attempt's simulation in real time, streams its state at display rate and its events
// reliably, announces itself, and acts on the instructor's signed commands — start,
// pause, resume, reset and stop a tutorial, inject and clear faults — each of which is
// written into the attempt's record.
//
// Headless (`padrob station`) it is the compute node of a station whose screens are
// display nodes (padrob-studio --display-of); the input is the station's devices through
// its profile, or, for a demonstration or a test, the tutorial's own demonstration.
//
// Single-threaded: tick() from one thread, every millisecond (run() does that).

#include "trainer/centre/bus.h"
#include "trainer/centre/signing.h"
#include "trainer/centre/station_protocol.h"
#include "trainer/records/shared_records.h"
#include "trainer/station/paced_loop.h"
#include "trainer/training/session.h"

#include <QString>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace trainer {
class StationEngine;
class InputLog;
}  // namespace trainer

namespace trainer::centre {

class StationRecords;

struct StationNodeOptions {
    std::string name;  ///< the station's node name, unique in the centre
    QString language = QStringLiteral("en");
    /// The tutorials the station runs (one model for all); the first is ready at start.
    std::vector<std::shared_ptr<const Tutorial>> tutorials;
    CentreKey key;             ///< commands signed with another key are refused
    double stateRate = 60.0;   ///< [Hz]
    /// The operator's input: the tutorial's own demonstration (replayed from the start of
    /// each attempt), else `input` (the station's devices through its profile: the
    /// commands per tree joint now; called every step, from the node's thread; it must
    /// be cheap and thread-safe), else nothing (the levers at rest).
    bool demoInput = false;
    std::function<std::vector<double>()> input;
    /// Where attempts are recorded: a local SQLite journal, synced to the centre's
    /// PostgreSQL server when one is set (docs/records.md); written in a recorder thread
    /// of the node's (station_records.h). Not recorded when `record` is false.
    bool record = false;
    records::SharedLocation records;
    QString pendingFolder;  ///< for records the journal itself refused (AttemptLog)
    /// Told (from the node's thread) what an operator at the station's console should
    /// know about its records: the journal refusing writes (and when it takes them again),
    /// pending attempts brought in. `padrob station` prints these on stdout.
    std::function<void(const QString&)> notice;
};

class StationNode {
public:
    /// False in ok() with error() when the options cannot work (no tutorials, models differ).
    StationNode(Bus& bus, StationNodeOptions options);
    ~StationNode();
    StationNode(const StationNode&) = delete;
    StationNode& operator=(const StationNode&) = delete;

    bool ok() const { return m_error.isEmpty(); }
    QString error() const { return m_error; }

    /// Announces the station, then ticks every millisecond in real time until `stop`;
    /// withdraws the announcement at the end.
    void run(const std::atomic<bool>& stop);
    /// One pass at wall-clock time `nowS` [s]: commands, the simulation steps due
    /// (PacedLoop: at most 10 ms of them, a lag over 50 ms dropped), state and events when due.
    void tick(double nowS);

    /// The status as published.
    StationStatus status() const { return m_status; }
    const TutorialSession* session() const { return m_session.get(); }
    /// The recorder (nullptr when not recording).
    StationRecords* records() const { return m_records.get(); }

private:
    void handle(const Command& c);
    bool start(const std::string& tutorialId, const std::string& operatorCode);
    void finishRecord(bool aborted);
    void instructorEvent(const Command& c, const std::string& what);
    void publishState(double nowS);
    void publishEvents();
    void noticeRecords();
    std::shared_ptr<const Tutorial> tutorial(const std::string& id) const;

    Bus& m_bus;
    StationNodeOptions m_o;
    QString m_error;
    CommandGuard m_guard;
    std::shared_ptr<const Tutorial> m_tutorial;
    std::unique_ptr<TutorialSession> m_session;
    std::unique_ptr<StationEngine> m_engine;
    std::shared_ptr<const InputLog> m_demo;
    std::unique_ptr<StationRecords> m_records;
    bool m_recording = false;  ///< an attempt's record is open
    QString m_recordsProblem;  ///< the last told (notice)
    int m_recordsImported = 0; ///< the last told (notice)
    std::vector<double> m_input;
    std::size_t m_published = 0;  ///< how many of the session's events went out
    StationStatus m_status = StationStatus::Idle;
    std::string m_operator;
    PacedLoop m_pacer;  ///< the simulation's real-time pacing while running
    double m_nextState = 0.0, m_nextRecord = 0.0, m_lastTick = -1.0;
    std::uint64_t m_stateSeq = 0, m_eventSeq = 0;
    Announce m_announce;
};

}  // namespace trainer::centre
