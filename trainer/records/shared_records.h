#pragma once
// A training centre's records (docs/records.md, "A training centre: shared records,
// local journal, sync"): every station writes to the centre's PostgreSQL server, and a
// station that loses the server goes on recording and sends what it recorded when the
// server is back, without duplicates or losses.
//
// A station's SharedRecords writes everything first to its local journal, an SQLite
// records file (a RecordsDb, with the same crash safety: every call commits before it
// returns), and returns the journal's ids. sync() copies to the server what it lacks:
// operators by code, attempts by their uid, events by (attempt uid, seq); each copy
// is idempotent, so a sync repeated, or cut by a crash or a lost connection, never
// duplicates nor loses anything. The journal notes what the server has (tables
// sync_state and sync_operators), so a sync with nothing new costs one local query
// and one trivial query to the server.
//
// No threads inside: the station calls sync() periodically (e.g. once a second from
// its recorder thread). The recording calls never touch the server; sync() gives up
// connecting after the server's connect timeout and, after a failure, does not try
// again before `retryAfterS` has passed. The password is kept only in memory and in
// the server's connection; it is never written to the journal nor put in a message.
//
// Threads: like RecordsDb, used only from the thread that opened it.

#include "trainer/records/records_db.h"

#include <QElapsedTimer>
#include <QHash>

#include <functional>

namespace trainer::records {

/// Where a station's records go.
struct SharedLocation {
    QString journalPath;    ///< the station's SQLite journal ("" = RecordsDb::defaultSqlitePath())
    PostgresConfig server;  ///< the centre's server; not set = the journal only
    QString station;        ///< this station's name, stored with its attempts ("" = the host name)
    double retryAfterS = 5;      ///< after a failed sync, the next one waits this long [s]
    int eventsPerStep = 1000;    ///< events copied per server transaction
    int busyTimeoutMs = 2000;    ///< as RecordsLocation's
};

/// What waits to be sent to the server.
struct SyncBacklog {
    int operators = 0;
    int attempts = 0;  ///< attempts whose events or status the server lacks
    int events = 0;    ///< events the server lacks

    bool empty() const { return operators == 0 && attempts == 0 && events == 0; }
};

class SharedRecords : public AttemptRecorder {
public:
    SharedRecords();
    ~SharedRecords() override;  ///< close()s
    SharedRecords(const SharedRecords&) = delete;
    SharedRecords& operator=(const SharedRecords&) = delete;

    /// Opens (creating or upgrading) the journal and gives its old attempts a uid. The
    /// server is not contacted: sync() does that. False with `error` when the journal
    /// cannot be opened.
    bool open(const SharedLocation& where, QString* error = nullptr);
    /// Closes the journal (its attempts still running are recorded interrupted there,
    /// and reach the server at the next sync after it is opened again) and the server.
    void close();
    bool isOpen() const override;
    /// The station's name, as stored with its attempts.
    QString station() const;
    /// The journal (reads: the trainer's view of this station, the CSV export…).
    RecordsDb& journal();
    /// Running attempts of dead recorders the journal's open marked interrupted.
    int interruptedAtOpen() const;

    // recording: the journal, at once; ids are the journal's

    qint64 addOperator(const QString& code, const QString& name, QString* error = nullptr);
    /// The operator with `code` in the journal; when the journal has none and the
    /// server is online, the server's, copied into the journal (an operator registered
    /// at another station). False when there is none (`error` empty) or on failure.
    bool findOperator(const QString& code, Operator& out, QString* error = nullptr);
    qint64 operatorFor(const QString& code, const QString& name, QString* error = nullptr) override
    {
        return findOrAddOperator(*this, code, name, error);
    }
    /// The attempt gets the station's name (and a new uid unless `start.uid` is given).
    qint64 beginAttempt(const AttemptStart& start, QString* error = nullptr) override;
    bool appendEvents(qint64 attemptId, const QList<AttemptEvent>& events, QString* error = nullptr) override;
    bool finishAttempt(qint64 attemptId, const AttemptResult& result, QString* error = nullptr) override;
    bool findAttempt(const QString& uid, Attempt& out, QString* error = nullptr) const override;

    // the server

    /// Whether a server is configured.
    bool hasServer() const;
    /// Sends the server what it lacks. True when the server has everything of the
    /// journal (also when no server is configured: nothing to do). False with `error`
    /// when it cannot reach the server or the server refuses; what was sent stays sent.
    /// Within `retryAfterS` of a failure it returns false at once, with the same error.
    bool sync(QString* error = nullptr);
    /// Whether the last sync reached the server (false before the first).
    bool online() const;
    /// What waits to be sent (a query of the journal); empty on failure.
    SyncBacklog pending(QString* error = nullptr) const;
    /// For people, when a server is configured and the last sync failed: that the
    /// station records on its own and why; "" otherwise. Translated.
    QString offlineMessage() const;

    /// Tests: called after each transaction the server committed, before the journal
    /// notes it, with the number of such steps in this sync (a crash there must be safe).
    void setAfterServerStep(std::function<void(int step)> hook);

private:
    bool connectServer(QString* error);
    bool syncNow(QString* error);
    void dropServer();

    RecordsDb m_local;
    RecordsDb m_remote;
    SharedLocation m_where;
    bool m_online = false;
    QString m_lastError;   ///< of the last failed sync, "" after a good one
    QElapsedTimer m_sinceFailure;  ///< started at the last failure
    QHash<qint64, qint64> m_remoteOperator;  ///< journal operator id → server's (this connection)
    std::function<void(int)> m_afterStep;
};

}  // namespace trainer::records
