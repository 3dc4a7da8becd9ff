#pragma once
// Trainee records (docs/records.md): operators, their attempts at tutorials, each
// attempt's score breakdown and event log, in an SQLite file (the default:
// <AppDataLocation>/records.sqlite) or on a PostgreSQL server shared by several
// stations. One class, RecordsDb, on Qt SQL; the SQL is the same for both back ends
// except the id column type, the transaction start and the liveness locks.
//
// Crash safety: every call that writes is one transaction, committed before it returns
// (SQLite in WAL mode with synchronous=FULL), so nothing is ever half-written.
// beginAttempt() commits the attempt as "running"; a process that dies during the
// attempt leaves it so, with the events it had committed, and the next open() marks it
// "interrupted". An attempt being recorded by a live RecordsDb (this process or
// another) is never marked: its owner holds a lock (a QLockFile next to the SQLite
// file, an advisory lock on PostgreSQL) that dies with it.
//
// Errors: calls return false / 0 and, when `error` is given, a sentence for people
// (English, through tr()) saying what failed and what to do: the database in use by
// another program, read-only, disk full, not a records database, from a newer Padrob,
// a missing PostgreSQL driver, a server that refuses the connection. The password of
// a PostgreSQL connection is never logged nor put in a message. After an error the
// object stays open and usable for reads where the database allows.
//
// Threads: a RecordsDb has its own uniquely named QSqlDatabase connection and is used
// only from the thread that opened it (calls from another thread fail with an error).
// Several may be open in one process, one per thread, on the same database.

#include <QDateTime>
#include <QHash>
#include <QList>
#include <QString>

#include <limits>
#include <memory>

namespace trainer::records {

/// A trainee. `code` is the operator's id as a trainer types it (badge number,
/// national id…), unique in the database.
struct Operator {
    qint64 id = 0;
    QString code;
    QString name;
    QDateTime created;  ///< UTC

    bool operator==(const Operator&) const = default;
};

enum class AttemptStatus {
    Running,      ///< begun, not finished yet (or its process is alive and recording)
    Finished,     ///< finished and scored
    Aborted,      ///< stopped by the operator or trainer, scored as far as it went
    Interrupted,  ///< its process stopped (crash, power cut) during the attempt
};
/// "running", "finished", "aborted", "interrupted": the values stored in the database.
QString statusName(AttemptStatus status);
/// The status named `name`; false when it is none of statusName()'s values.
bool statusFromName(const QString& name, AttemptStatus& status);

/// One line of an attempt's score: what was measured and what it earned
/// (trainer::ScoreItem of training/session.h, with its label as shown).
struct ScoreItem {
    QString key;    ///< stable id of the criterion ("time", "path", "smooth", "safety"…)
    QString label;  ///< what the trainee saw, in the attempt's language
    double value = 0;      ///< the measure, in the criterion's own unit (s, %, m/s³, points)
    double points = 0;     ///< its contribution to the score
    double maxPoints = 0;  ///< the most it could have contributed (0 = no maximum)

    bool operator==(const ScoreItem&) const = default;
};

/// Something that happened during an attempt.
struct AttemptEvent {
    AttemptEvent() = default;
    AttemptEvent(double t_, QString kind_, QString text_, double value_ = std::numeric_limits<double>::quiet_NaN(),
                 double penalty_ = 0, QString detail_ = {})
        : t(t_), kind(std::move(kind_)), text(std::move(text_)), value(value_), penalty(penalty_), detail(std::move(detail_))
    {
    }
    double t = 0;  ///< time since the attempt began [s]
    QString kind;  ///< "step", "hint", "collision", "limit"… (the tutorial runner's vocabulary)
    QString text;
    /// a number that goes with it (an impact speed, a step index…); NaN = none, stored as NULL
    double value = std::numeric_limits<double>::quiet_NaN();
    double penalty = 0;  ///< points the event cost
    QString detail;      ///< what it concerns: a goal's id, a shape, a drive (as the model names it)
    /// its index within the attempt (0, 1, 2…); < 0 = appendEvents() assigns it (the
    /// number of events already stored plus its place in the batch)
    int seq = -1;
};

/// What beginAttempt() records.
struct AttemptStart {
    qint64 operatorId = 0;
    QString tutorialId;     ///< the tutorial's stable id
    QString tutorialTitle;  ///< its title as shown (in `language`)
    QString language;       ///< the UI language of the attempt ("en", "es"…)
    QDateTime started;      ///< invalid = now; stored in UTC to the millisecond
    QString uid{};          ///< the attempt's unique id (a UUID); "" = a new one (QUuid)
    /// the station whose local journal owns the attempt (SharedRecords); "" = recorded
    /// directly in this database (docs/records.md, "A training centre")
    QString station{};
};

/// What finishAttempt() records.
struct AttemptResult {
    AttemptStatus status = AttemptStatus::Finished;  ///< Finished, Aborted or Interrupted (a pending record that never ended)
    double durationS = 0;  ///< [s]
    double score = 0;      ///< 0…100
    int stars = 0;         ///< 0…3
    bool passed = false;
    QList<ScoreItem> breakdown;  ///< keys unique within the attempt
};

/// An attempt as stored.
struct Attempt {
    qint64 id = 0;
    qint64 operatorId = 0;
    QString tutorialId;
    QString tutorialTitle;
    QDateTime started;  ///< UTC
    double durationS = 0;  ///< [s]; 0 while running or interrupted
    double score = 0;      ///< 0…100; 0 while running or interrupted
    int stars = 0;         ///< 0…3
    bool passed = false;
    AttemptStatus status = AttemptStatus::Running;
    QString language;
    QString uid;      ///< unique in the database and across a centre's stations ("" = an old attempt)
    QString station;  ///< the station whose journal owns it ("" = none)
    QList<ScoreItem> breakdown;  ///< in the order given to finishAttempt()
    QList<AttemptEvent> events;  ///< in the order appended (by seq)
};

/// Whether an attempt of that status has a score (finished, or stopped by the operator or
/// the trainer); running and interrupted ones have none.
inline bool hasScore(AttemptStatus s)
{
    return s == AttemptStatus::Finished || s == AttemptStatus::Aborted;
}

/// One tutorial in an operator's progress: the best of the attempts that have a score
/// (hasScore: the Train course shows it, and it is the best the Records view lists).
struct TutorialProgress {
    QString tutorialId;
    QString tutorialTitle;  ///< the title of the latest attempt
    int attempts = 0;       ///< of every status
    double bestScore = 0;   ///< 0…100
    int bestStars = 0;      ///< 0…3
    bool passed = false;    ///< at least one finished attempt passed
    QDateTime lastAttempt;  ///< UTC
};

/// An operator with their progress, for the trainer's view.
struct OperatorProgress {
    Operator op;
    int attempts = 0;          ///< of every status, every tutorial
    int tutorialsPassed = 0;   ///< tutorials with a passed, finished attempt
    QDateTime lastAttempt;     ///< UTC; invalid when there is none
    QList<TutorialProgress> tutorials;  ///< by tutorial id
};

/// A PostgreSQL server. The password is kept only in memory and in the connection.
struct PostgresConfig {
    QString host;  ///< name, address, or a Unix socket folder ("/run/postgresql"); "" = libpq's default
    int port = 5432;
    QString database;  ///< required: the records' database (one of their own is best)
    QString user;
    QString password;
    int connectTimeoutS = 5;  ///< give up connecting after this many seconds

    /// Whether a server is configured (a database name is given).
    bool isSet() const { return !database.isEmpty(); }
    /// "user@host:port/database", never the password (for messages and the UI).
    QString describe() const;
};

/// Where the records are.
struct RecordsLocation {
    PostgresConfig postgres;  ///< used when set (isSet()); the SQLite file otherwise
    QString sqlitePath;       ///< "" = RecordsDb::defaultSqlitePath()
    bool readOnly = false;    ///< only read: no upgrade, no writes (SQLite opens read-only)
    int busyTimeoutMs = 2000; ///< how long to wait for another program's lock before giving up
};

/// What records an attempt as it happens: a RecordsDb, or a station's SharedRecords
/// (its local journal first, the centre's server when it can). AttemptLog uses this.
class AttemptRecorder {
public:
    virtual ~AttemptRecorder() = default;
    virtual bool isOpen() const = 0;
    virtual qint64 beginAttempt(const AttemptStart& start, QString* error = nullptr) = 0;
    virtual bool appendEvents(qint64 attemptId, const QList<AttemptEvent>& events, QString* error = nullptr) = 0;
    virtual bool finishAttempt(qint64 attemptId, const AttemptResult& result, QString* error = nullptr) = 0;
    /// The attempt with `uid`, with breakdown and events. False when there is none
    /// (`error` empty) or on failure.
    virtual bool findAttempt(const QString& uid, Attempt& out, QString* error = nullptr) const = 0;
    /// The id of the operator with `code`, added (named `name`, or the code when empty)
    /// when there is none. 0 on failure (`error`).
    virtual qint64 operatorFor(const QString& code, const QString& name, QString* error = nullptr) = 0;
};

/// operatorFor() of a records object with findOperator() and addOperator().
template <class Records>
qint64 findOrAddOperator(Records& db, const QString& code, const QString& name, QString* error)
{
    Operator op;
    QString e;
    if (db.findOperator(code, op, &e)) return op.id;
    if (e.isEmpty()) return db.addOperator(code, name.trimmed().isEmpty() ? code : name, error);
    if (error) *error = e;
    return 0;
}

class SharedRecords;

class RecordsDb : public AttemptRecorder {
public:
    RecordsDb();
    ~RecordsDb() override;  ///< close()s
    RecordsDb(const RecordsDb&) = delete;
    RecordsDb& operator=(const RecordsDb&) = delete;

    /// <AppDataLocation>/records.sqlite (e.g. ~/.local/share/padrob/records.sqlite).
    static QString defaultSqlitePath();
    /// The schema version this Padrob reads and writes (the last migration's number).
    static int schemaVersion();

    /// Opens (creating or upgrading unless read-only) the records at `where`. On an
    /// open database: marks attempts left running by dead processes interrupted
    /// (interruptedAtOpen()). False with `error` when it cannot: the database is
    /// then closed and, when it was refused (newer schema, not a records database),
    /// untouched.
    bool open(const RecordsLocation& where, QString* error = nullptr);
    /// open() on an SQLite file ("" = the default path).
    bool openSqlite(const QString& path = {}, bool readOnly = false, QString* error = nullptr);
    /// open() on a PostgreSQL server.
    bool openPostgres(const PostgresConfig& server, QString* error = nullptr);
    /// Closes; attempts of this object still running are recorded as interrupted.
    void close();

    bool isOpen() const override;
    bool isPostgres() const;
    bool isReadOnly() const;
    /// The file path, or "user@host:port/database" (never the password).
    QString where() const;
    /// How many running attempts of dead processes open() marked interrupted.
    int interruptedAtOpen() const;

    // operators

    /// Adds an operator; `code` is trimmed and must be new and non-empty. Returns the
    /// id, 0 on failure (`error`: e.g. the code is taken).
    qint64 addOperator(const QString& code, const QString& name, QString* error = nullptr);
    /// Changes an operator's name.
    bool renameOperator(qint64 operatorId, const QString& name, QString* error = nullptr);
    /// The operator with `code` (trimmed). False when there is none (`error` empty)
    /// or on failure (`error` says why).
    bool findOperator(const QString& code, Operator& out, QString* error = nullptr) const;
    qint64 operatorFor(const QString& code, const QString& name, QString* error = nullptr) override
    {
        return findOrAddOperator(*this, code, name, error);
    }

    // attempts (the recording side)

    /// Records a new attempt as running and commits it. Returns its id, 0 on failure.
    /// The attempt gets `start.uid`, or a new UUID when it is empty (a uid already in
    /// the database is refused).
    qint64 beginAttempt(const AttemptStart& start, QString* error = nullptr) override;
    /// Appends events to an attempt: the whole batch is committed or none of it.
    /// Each call costs a disk sync: append in batches (e.g. once a second), not per event.
    /// Events with seq < 0 get the next indexes; a seq already stored fails the batch.
    bool appendEvents(qint64 attemptId, const QList<AttemptEvent>& events, QString* error = nullptr) override;
    /// Records the result (status, score, breakdown) in one transaction; the attempt
    /// then no longer counts as running.
    bool finishAttempt(qint64 attemptId, const AttemptResult& result, QString* error = nullptr) override;
    bool findAttempt(const QString& uid, Attempt& out, QString* error = nullptr) const override;

    // queries (the trainer's view)

    /// Every operator (by code) with their progress.
    bool progress(QList<OperatorProgress>& out, QString* error = nullptr) const;
    /// An operator's attempts, newest first, with breakdown and (when `withEvents`) events.
    bool attemptsOf(qint64 operatorId, QList<Attempt>& out, bool withEvents = true, QString* error = nullptr) const;
    /// One attempt with breakdown and events. False when there is none or on failure.
    bool attempt(qint64 attemptId, Attempt& out, QString* error = nullptr) const;
    /// Writes every attempt (by operator code, then start) to a CSV file: a header,
    /// one row per attempt, RFC 4180 (comma, CRLF, "quoted" where needed, UTF-8),
    /// replacing `path` only once it is complete (QSaveFile). Each tutorial has one
    /// title in the whole file: `titles[tutorial id]` (the exporting program's language)
    /// when given, else the title its newest attempt was recorded with. An aborted
    /// attempt's status is "stopped", as the studio names it. `rows`: how many attempts.
    bool exportCsv(const QString& path, QString* error = nullptr, const QHash<QString, QString>& titles = {},
                   int* rows = nullptr) const;

private:
    friend class SharedRecords;
    // replication (SharedRecords, docs/records.md "A training centre") -------------------

    /// An attempt of the journal not yet (entirely) on the server.
    struct Unsynced {
        qint64 attemptId = 0;
        Operator op;  ///< its operator (the journal's id)
        QString uid;
        QString station;
        AttemptStatus status = AttemptStatus::Running;
        int events = 0;        ///< events in the journal (the next seq)
        int syncedEvents = 0;  ///< of which the server has seq < syncedEvents
        QString syncedStatus;  ///< the status the server had at the last sync ("" = it has no copy)
    };
    /// Journal: attempts whose events or status the server lacks, and operators it lacks.
    bool unsynced(QList<Unsynced>& attempts, QList<Operator>& operators, QString* error) const;
    /// Journal: the server has the attempt's events with seq < `events` and `status`.
    bool noteSynced(qint64 attemptId, int events, AttemptStatus status, QString* error);
    /// Journal: the server has the operator.
    bool noteOperatorSynced(qint64 operatorId, QString* error);
    /// An attempt without its events.
    bool attemptHead(qint64 attemptId, Attempt& out, QString* error) const;
    /// Journal: gives attempts without a uid (recorded before schema 3) one.
    bool giveUids(QString* error);
    /// The attempt's events with seq >= `fromSeq`, at most `limit`, by seq.
    bool eventsOf(qint64 attemptId, int fromSeq, int limit, QList<AttemptEvent>& out, QString* error) const;
    /// Server: the id of the operator with `op.code`, added (with op's name and
    /// creation) when absent; 0 on failure.
    qint64 ensureOperator(const Operator& op, QString* error);
    /// Server, one transaction: the attempt `a.uid` inserted if absent (for `operatorId`),
    /// `events` (with their seq) inserted where absent, and, when `a.status` is not
    /// running, its result and breakdown when the server's copy is running (or
    /// interrupted, for a finished or aborted one). Idempotent.
    bool mergeAttempt(const Attempt& a, qint64 operatorId, const QList<AttemptEvent>& events, QString* error);
    /// Whether the database still answers (a trivial query).
    bool check(QString* error) const;

    struct Impl;
    std::unique_ptr<Impl> d;
};

}  // namespace trainer::records
