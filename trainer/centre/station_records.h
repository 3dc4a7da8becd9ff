#pragma once
// A station's recorder thread (docs/training-centre.md "Shared records"): the attempt's
// record is written and synced to the centre's server in a thread of its own, so that a
// slow disk or an unreachable server never stalls the real-time loop. It owns the
// SharedRecords (a Qt SQL connection lives in the thread that opened it) and the
// AttemptLog of the attempt being recorded; the station posts copies of what to write.

#include "trainer/records/shared_records.h"
#include "trainer/training/session.h"

#include <QString>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace trainer {
class AttemptLog;
}

namespace trainer::centre {

class StationRecords {
public:
    /// Opens the journal (and the server, when set) in the recorder thread and waits for
    /// it. ok() false with error() when the journal cannot be opened.
    StationRecords(records::SharedLocation where, QString pendingFolder, QString language, double syncEveryS = 1.0);
    ~StationRecords();  ///< writes what is queued, syncs once more, stops
    StationRecords(const StationRecords&) = delete;
    StationRecords& operator=(const StationRecords&) = delete;

    bool ok() const { return m_openError.isEmpty(); }
    QString error() const { return m_openError; }

    /// A new attempt of `operatorCode` (found or added) at `tutorial`.
    void begin(std::shared_ptr<const Tutorial> tutorial, const QString& operatorCode);
    /// The attempt's events so far (all of them; the log writes the new ones).
    void update(std::vector<TutorialEvent> events);
    /// The end of the attempt.
    void finish(std::vector<TutorialEvent> events, TutorialResult result, bool aborted);

    /// The centre's server is set and the last sync did not reach it.
    bool offline() const { return m_offline.load(std::memory_order_relaxed); }
    /// A problem writing the journal, or importing pending attempts into it (translated;
    /// "" none).
    QString problem() const;
    /// How many pending attempts (kept aside when the journal refused them) were brought
    /// into the journal: at the start, and after each attempt the journal took whole.
    int imported() const;
    /// Blocks until everything posted so far is written (tests).
    void flush();

private:
    void post(std::function<void()> f);
    void loop(records::SharedLocation where, double syncEveryS);
    void importPending();  // thread

    QString m_pending, m_language, m_openError;
    std::unique_ptr<records::SharedRecords> m_db;  // used only in the thread
    std::shared_ptr<const Tutorial> m_tutorial;    // of m_log (thread)
    std::unique_ptr<AttemptLog> m_log;             // thread
    QString m_endProblem;                          // thread: the last attempt's, once ended
    std::atomic<bool> m_offline{false};
    mutable std::mutex m_mutex;
    std::condition_variable m_wake, m_idle;
    std::deque<std::function<void()>> m_queue;
    bool m_stop = false, m_busy = false, m_opened = false;
    QString m_problem, m_importProblem;
    int m_imported = 0;
    std::thread m_thread;
};

}  // namespace trainer::centre
