#pragma once
// TrainStation: padrob-studio's Train workspace as a station of the training centre
// (docs/training-centre.md, "The Train workspace as a station"; padrob-studio
// --station-name NAME --centre-key FILE [NETWORK]).
//
//  - It announces the station (role "station"; the model of the attempt's tutorial by
//    its file's base name and the SHA-256 of the file's bytes; the ids of the course's
//    tutorials on that model), again when an attempt on another model starts, and
//    withdraws the announcement when it is destroyed.
//  - It publishes the State at 60 Hz, built from the TrainFrames the workspace already
//    gets (status idle / running / paused / ended), in a small thread of its own (a slow
//    GUI, e.g. software GL, does not slow the stream), and every new TutorialEvent as an
//    Event (GUI thread), its text in the UI language.
//  - It acts on the instructor's signed Commands (CommandGuard; refusals with the codes
//    of StationNode): start, pause, resume, reset, stop, inject, clear. Faults and the
//    instructor's events reach the session through TutorialRunner::runInSession, in the
//    runner's thread between two steps; each action is in the attempt's events, hence
//    in its record.
//
// The workspace is reached through Host (the Train page's adapter: forPage(); a test
// may give its own). Everything but the state's publisher runs in the GUI thread; DDS
// writes never wait.

#include "ide/studio/train/centre_link.h"
#include "ide/studio/train/tutorial_runner.h"
#include "trainer/centre/bus.h"
#include "trainer/centre/signing.h"
#include "trainer/centre/station_protocol.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <optional>
#include <string>
#include <vector>

class QTimer;

namespace trainer {
struct Tutorial;
}  // namespace trainer

namespace studio {

class TrainPage;

struct TrainStationOptions {
    QString name;     ///< the station's node name, unique in the centre
    QString keyFile;  ///< the centre's key ("" none: every command is refused, no-key)
    trainer::centre::BusOptions network;
    double stateRate = 60.0;  ///< [Hz]
};

class TrainStation : public QObject {
    Q_OBJECT
public:
    /// What the station needs of the Train workspace.
    class Host {
    public:
        virtual ~Host() = default;
        virtual std::vector<std::shared_ptr<const trainer::Tutorial>> tutorials() const = 0;
        virtual QString language() const = 0;
        /// The live attempt's newest frame; nullptr without a live attempt.
        virtual std::shared_ptr<const TrainFrame> attemptFrame() const = 0;
        /// The runner's newest frame, whatever it runs (any thread).
        virtual std::shared_ptr<const TrainFrame> latestFrame() const = 0;
        /// The live attempt's tutorial and operator (valid with attemptFrame()).
        virtual std::shared_ptr<const trainer::Tutorial> attemptTutorial() const = 0;
        virtual QString attemptOperator() const = 0;
        /// Starts an attempt as if the trainee had chosen it; its session's generation
        /// (TutorialRunner::generation) or 0 when it could not start.
        virtual long startAttempt(const QString& tutorialId, const QString& operatorCode) = 0;
        virtual void setPaused(bool paused) = 0;
        /// Ends the live attempt as aborted (as the trainee's Stop).
        virtual void stopAttempt() = 0;
        virtual void runInSession(TutorialRunner::SessionTask task,
                                  std::function<void(bool, const QString&)> done, long generation) = 0;
        virtual void setLink(CentreLink link, const QString& name, const QString& detail) = 0;
    };

    /// Opens the bus and loads the key (a failure is shown by the host, never fatal),
    /// announces the station and starts ticking. `host` must outlive the station.
    TrainStation(Host* host, TrainStationOptions options, QObject* parent = nullptr);
    /// Withdraws the announcement.
    ~TrainStation() override;
    /// The station of the Train page `page` (its runner and indicator).
    static std::unique_ptr<TrainStation> forPage(TrainPage* page, TrainStationOptions options);

    bool online() const { return m_bus != nullptr; }
    bool hasKey() const { return m_hasKey; }
    /// Why the bus or the key failed ("" when all is well).
    QString problem() const { return m_problem; }
    const trainer::centre::Announce& announcement() const { return m_announce; }
    trainer::centre::StationStatus status() const;

    /// One pass (the timer calls it): the attempt, commands, a pending start, events.
    void tick();
    /// The state as it would be published now (any thread).
    trainer::centre::State buildState();
    /// Acts on one command (after the guard) and replies (now, or when the session has done it).
    void handle(const trainer::centre::Command& c);

protected:
    /// Stops the timer and the publisher and withdraws (once; the destructor calls it).
    void shutdown();

private:
    struct Attempt {
        std::shared_ptr<const TrainFrame> frame;
        std::shared_ptr<const trainer::Tutorial> tutorial;
        std::string operatorCode;
    };
    struct PendingStart {
        std::string tutorial, operatorCode, sender;
        trainer::centre::CommandKind action = trainer::centre::CommandKind::Start;
    };
    void reply(const trainer::centre::Command& c, bool accepted, const std::string& message);
    bool doStart(const PendingStart& p);
    void instructorEvent(trainer::centre::CommandKind kind, const std::string& sender, long generation);
    void announceFor(const trainer::Tutorial* tutorial);
    void publishEvents();
    std::shared_ptr<const trainer::Tutorial> findTutorial(const std::string& id) const;

    Host* m_host;
    TrainStationOptions m_o;
    std::unique_ptr<trainer::centre::Bus> m_bus;
    std::unique_ptr<trainer::centre::CommandGuard> m_guard;
    bool m_hasKey = false;
    QString m_problem;
    QTimer* m_timer = nullptr;
    trainer::centre::Announce m_announce;
    std::string m_announcedModel;  ///< modelFile of the announcement
    std::optional<Attempt> m_attempt;  ///< the live attempt, or the last one
    std::optional<PendingStart> m_pending;  ///< waits for the running attempt to end
    long m_generation = -1;            ///< of the attempt whose events are published
    std::size_t m_publishedEvents = 0;
    std::uint64_t m_eventSeq = 0;
    // the state's publisher thread: what it needs of the attempt (set by tick())
    struct Published {
        std::optional<Attempt> attempt;
        bool live = false;
    };
    void publishLoop();
    std::mutex m_publishMutex;
    std::condition_variable m_publishWake;
    Published m_published;
    bool m_quit = false;
    std::uint64_t m_stateSeq = 0;  ///< publisher thread
    std::thread m_publisher;
};

}  // namespace studio
