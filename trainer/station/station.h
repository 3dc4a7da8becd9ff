#pragma once
// Station: the StationEngine running in an input thread of its own, every
// millisecond, so that reading devices never blocks the solver or the GUI.
//
// Threads: the Station object lives in its input thread (start() creates the thread
// and moves it there; the engine, its devices and SDL are created and polled only
// there). Every other thread talks to it in two ways only:
//  - post(f): f(engine) runs in the input thread before its next update (a queue of
//    our own under a mutex, drained every tick — not Qt's event queue, so
//    ThreadSanitizer sees the hand-over), for any change: a profile, a calibration, a
//    device, a bank;
//  - latest(): the newest StationState (a shared_ptr copied under a mutex held for that
//    copy), refreshed at kStateRate for displays.
// Commands: after each update that changed them, the engine's commands go to the sink
// given at construction (called in the input thread; SimulationRunner::setCommands is
// safe from any thread), so a lever reaches the solver within one station period
// (1 ms) plus the solver's next step.

#include "trainer/station/station_engine.h"

#include <QObject>

#include <chrono>
#include <functional>
#include <memory>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <span>

class QThread;
class QTimer;

namespace trainer {

class Station : public QObject {
    Q_OBJECT
public:
    using CommandSink = std::function<void(std::span<const double>)>;
    static constexpr int kPeriodMs = 1;
    static constexpr double kStateRate = 60.0;  ///< [Hz] latest() refresh

    explicit Station(CommandSink sink = {});
    ~Station() override;

    /// Starts the input thread (idempotent). `withSdl`: look for SDL joysticks there.
    void start(bool withSdl = true);
    /// Stops the thread after its current update; the engine and devices are destroyed
    /// in it. Called by the destructor. The station cannot be started again.
    void stop();
    bool isRunning() const;

    /// Runs `f` on the engine in the input thread (or at once when not started).
    void post(std::function<void(StationEngine&)> f);
    /// Runs `f` there and waits for it (for set-up and tests; never from the input thread).
    void call(std::function<void(StationEngine&)> f);

    /// Starts `recorder` writing to `path` and attaches it to the engine, in the input
    /// thread (where it is used). `profile` (optional): the profile in use then. False
    /// with `error` (the file cannot be written, or the station is not running).
    bool startRecording(InputRecorder& recorder, const QString& path, QString* error,
                        StationProfile* profile = nullptr);
    /// Detaches `recorder` and stops it, in the input thread (here when the thread has
    /// ended: nobody else uses it then). False with `error` when the log may be incomplete.
    bool stopRecording(InputRecorder& recorder, QString* error);

    /// The newest state; nullptr before the first update.
    std::shared_ptr<const StationState> latest() const;

    /// Seconds since the station was made (the engine's clock).
    double now() const;

private:
    void tick();
    /// Runs the posted work (input thread).
    void drain();
    void begin(bool withSdl);
    void finish();

    CommandSink m_sink;
    std::unique_ptr<StationEngine> m_engine;
    QThread* m_thread = nullptr;
    QTimer* m_timer = nullptr;
    std::chrono::steady_clock::time_point m_epoch;
    double m_lastPublish = -1.0;
    std::mutex m_postMutex;
    std::condition_variable m_posted;
    std::deque<std::function<void(StationEngine&)>> m_queue;
    std::uint64_t m_postCount = 0, m_doneCount = 0;  ///< under m_postMutex
    bool m_stopping = false;                         ///< under m_postMutex
    mutable std::mutex m_stateMutex;
    std::shared_ptr<const StationState> m_state;
};

}  // namespace trainer
