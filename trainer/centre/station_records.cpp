#include "trainer/centre/station_records.h"

#include "trainer/training/attempt_log.h"

#include <chrono>

namespace trainer::centre {

StationRecords::StationRecords(records::SharedLocation where, QString pendingFolder, QString language, double syncEveryS)
    : m_pending(std::move(pendingFolder)), m_language(std::move(language))
{
    m_thread = std::thread([this, where, syncEveryS] { loop(where, syncEveryS); });
    std::unique_lock lock(m_mutex);
    m_idle.wait(lock, [&] { return m_opened; });
}

StationRecords::~StationRecords()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    if (m_thread.joinable()) m_thread.join();
}

void StationRecords::post(std::function<void()> f)
{
    {
        std::lock_guard lock(m_mutex);
        m_queue.push_back(std::move(f));
    }
    m_wake.notify_all();
}

void StationRecords::flush()
{
    std::unique_lock lock(m_mutex);
    m_idle.wait(lock, [&] { return m_queue.empty() && !m_busy; });
}

QString StationRecords::problem() const
{
    std::lock_guard lock(m_mutex);
    return m_problem.isEmpty() ? m_importProblem : m_problem;
}

int StationRecords::imported() const
{
    std::lock_guard lock(m_mutex);
    return m_imported;
}

void StationRecords::begin(std::shared_ptr<const Tutorial> tutorial, const QString& operatorCode)
{
    post([this, tutorial, operatorCode] {
        // without a journal (it could not be opened) the attempt goes to a pending file
        m_endProblem.clear();
        m_tutorial = tutorial;
        m_log = std::make_unique<AttemptLog>(m_db.get(), m_pending, operatorCode, operatorCode, *m_tutorial, m_language);
    });
}

void StationRecords::update(std::vector<TutorialEvent> events)
{
    post([this, events = std::move(events)] {
        if (m_log) m_log->update(events);
    });
}

void StationRecords::finish(std::vector<TutorialEvent> events, TutorialResult result, bool aborted)
{
    post([this, events = std::move(events), result = std::move(result), aborted] {
        if (!m_log) return;
        const bool recorded = m_log->finish(events, result, aborted);
        m_endProblem = m_log->problem();  // kept aside: said until the next attempt
        m_log.reset();
        m_tutorial.reset();
        if (recorded) importPending();  // the journal takes writes again: what waited goes in
    });
}

void StationRecords::importPending()
{
    if (!m_db) return;
    QString error;
    const int n = AttemptLog::importPending(*m_db, m_pending, &error);
    std::lock_guard lock(m_mutex);
    m_imported += n;
    m_importProblem = error;
}

void StationRecords::loop(records::SharedLocation where, double syncEveryS)
{
    {
        auto db = std::make_unique<records::SharedRecords>();
        QString error;
        const bool opened = db->open(where, &error);
        std::lock_guard lock(m_mutex);
        if (opened) {
            m_db = std::move(db);
        } else {
            m_openError = error;
        }
        m_opened = true;
        m_busy = true;  // (flush() waits for the import)
    }
    m_idle.notify_all();
    importPending();  // attempts kept aside by earlier runs
    {
        std::lock_guard lock(m_mutex);
        m_busy = false;
    }
    m_idle.notify_all();
    using clock = std::chrono::steady_clock;
    auto nextSync = clock::now();
    for (;;) {
        std::function<void()> job;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait_until(lock, nextSync, [&] { return m_stop || !m_queue.empty(); });
            if (!m_queue.empty()) {
                job = std::move(m_queue.front());
                m_queue.pop_front();
                m_busy = true;
            } else if (m_stop) {
                break;
            }
        }
        if (job) {
            job();
            std::lock_guard lock(m_mutex);
            m_busy = false;
            m_problem = m_log ? m_log->problem() : m_endProblem;
            if (m_queue.empty()) m_idle.notify_all();
        }
        if (m_db && m_db->hasServer() && clock::now() >= nextSync) {
            m_db->sync();
            m_offline.store(!m_db->online(), std::memory_order_relaxed);
            nextSync = clock::now() + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(syncEveryS));
        } else if (!m_db || !m_db->hasServer()) {
            nextSync = clock::now() + std::chrono::hours(1);
        }
    }
    // the end: what is left of an attempt is recorded as interrupted by the journal's
    // close; one last sync carries it
    m_log.reset();
    if (m_db && m_db->hasServer()) m_db->sync();
    m_db.reset();
    m_idle.notify_all();
}

}  // namespace trainer::centre
