#pragma once
// Recording an attempt in the trainee records (trainer/records) as it happens: the
// attempt row when it starts, its events in committed batches while it runs (a crash
// loses nothing recorded before it: the attempt is found `interrupted` with them), the
// score breakdown when it ends.
//
// When the database refuses (locked by another program, read-only, full, gone), the
// attempt goes on: what could not be written is kept and tried again at the next
// update, and at the end, if the database still refuses, the whole record is written to
// a pending file (JSON, in `pendingFolder`) that importPending() brings into the
// database the next time it can. problem() says what happened, for the HUD.
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
    /// Begins the attempt of `operatorId` at `tutorial` (nullptr db: pending file only);
    /// `db` is a RecordsDb or a station's SharedRecords; `tutorial` must outlive the log.
    AttemptLog(records::AttemptRecorder* db, QString pendingFolder, qint64 operatorId, const Tutorial& tutorial,
               const QString& language);
    /// Writes the events not written yet (call every few hundred milliseconds).
    void update(const std::vector<TutorialEvent>& events);
    /// Writes the rest and the result. False when it went to the pending file instead.
    bool finish(const std::vector<TutorialEvent>& events, const TutorialResult& result, bool aborted);
    qint64 attemptId() const { return m_attempt; }
    /// The attempt's unique id (given before it is begun in the database).
    QString attemptUid() const { return m_start.uid; }
    /// Why the database could not be written ("" when it could), translated.
    QString problem() const { return m_problem; }
    /// The pending file written by finish() ("" none).
    QString pendingFile() const { return m_pendingFile; }

    /// Moves every pending file of `folder` into `db` (each in its own attempt, or
    /// completing the attempt with its uid that the database had begun; then deleted).
    /// Returns how many; a file that cannot be read is left and named in `error`.
    static int importPending(records::AttemptRecorder& db, const QString& folder, QString* error = nullptr);

private:
    bool ensureBegun();
    records::AttemptRecorder* m_db;
    const Tutorial* m_tutorial;  ///< outlives the log (the attempt's)
    QString m_folder;
    records::AttemptStart m_start;
    qint64 m_attempt = 0;
    std::size_t m_written = 0;
    QString m_problem;
    QString m_pendingFile;
};

}  // namespace trainer
