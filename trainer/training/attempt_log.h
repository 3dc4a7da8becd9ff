#pragma once
// Recording an attempt in the trainee records (trainer/records) as it happens: the
// attempt row when it starts, its events in committed batches while it runs (a crash
// loses nothing recorded before it: the attempt is found `interrupted` with them), the
// score breakdown when it ends.
//
// Nothing of an attempt is lost when the database refuses (locked by another program,
// read-only, full, gone) or the process dies: a pending file (JSON, `padrob-pending-
// attempt` version 2, in `pendingFolder`) holds whatever the database does not. It is
// written when the attempt starts, before the database is asked (fsynced, its size
// checked), removed as soon as the database holds the attempt and every event, and
// rewritten with all the events whenever the database refuses them, and with the result
// at the end. The attempt goes on meanwhile; problem() says what happened, for the HUD.
// importPending() brings pending files into a database at the next start: a file with a
// result as that attempt, one without (the process died) as an interrupted attempt with
// its events. The file names the operator by code (ids differ between databases).
//
// A station of a training centre records through a records::SharedRecords: its local
// journal first (a lost server is no problem of the attempt: sync() sends it later),
// so the pending file is only for a journal that itself refuses (e.g. a full disk).
// Each attempt has a uid from its start, kept in the pending file: importPending()
// completes an attempt the database had begun instead of adding a second one.

#include "trainer/records/records_db.h"
#include "trainer/training/session.h"

#include <QString>

#include <vector>

namespace trainer {

/// The records' form of a tutorial's events and breakdown.
QList<records::AttemptEvent> toRecordEvents(const std::vector<TutorialEvent>& events, std::size_t from = 0,
                                           const Tutorial* tutorial = nullptr, const std::string& language = "en");
records::AttemptResult toRecordResult(const TutorialResult& result, bool aborted);

class AttemptLog {
public:
    /// Begins the attempt of the operator with `operatorCode` (found, or added named
    /// `operatorName`) at `tutorial`; `db` is a RecordsDb or a station's SharedRecords
    /// (nullptr: the pending file only); `tutorial` must outlive the log.
    AttemptLog(records::AttemptRecorder* db, QString pendingFolder, const QString& operatorCode,
               const QString& operatorName, const Tutorial& tutorial, const QString& language);
    AttemptLog(const AttemptLog&) = delete;
    AttemptLog& operator=(const AttemptLog&) = delete;
    /// Writes the events not written yet (call every few hundred milliseconds).
    void update(const std::vector<TutorialEvent>& events);
    /// Writes the rest and the result. False when it went to the pending file instead.
    bool finish(const std::vector<TutorialEvent>& events, const TutorialResult& result, bool aborted);
    qint64 attemptId() const { return m_attempt; }
    /// The attempt's unique id (given before it is begun in the database).
    QString attemptUid() const { return m_start.uid; }
    /// Why the database could not be written ("" when it could), translated.
    QString problem() const { return m_problem; }
    /// The pending file that holds what the database does not ("" when it holds all).
    QString pendingFile() const { return m_pendingOnDisk ? m_pendingFile : QString(); }

    /// Moves every pending file of `folder` into `db` (each in its own attempt, or
    /// completing the attempt with its uid that the database had begun; then deleted).
    /// A file that is not a pending attempt (damaged, foreign, an unknown operator) is
    /// moved to `folder`/quarantine and named in `error`, and the others go on; when the
    /// database refuses, the rest wait for the next time. Returns how many were imported.
    static int importPending(records::AttemptRecorder& db, const QString& folder, QString* error = nullptr);

private:
    bool ensureBegun();
    /// Writes the pending file durably: the start, `events` and, when given, the result.
    bool writePending(const std::vector<TutorialEvent>& events, const TutorialResult* result, bool aborted);
    /// The database holds the attempt and every event: the pending file goes.
    void dropPending();

    records::AttemptRecorder* m_db;
    const Tutorial* m_tutorial;  ///< outlives the log (the attempt's)
    QString m_folder;
    QString m_operatorCode, m_operatorName;
    records::AttemptStart m_start;
    qint64 m_attempt = 0;
    std::size_t m_written = 0;       ///< events the database holds
    std::size_t m_pendingEvents = 0; ///< events in the pending file
    bool m_pendingOnDisk = false;
    QString m_problem;
    QString m_pendingFile;
};

}  // namespace trainer
