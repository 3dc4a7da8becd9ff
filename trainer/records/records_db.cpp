#include "trainer/records/records_db.h"

#include "solver/core/output_file.h"
#include "trainer/io/read_file.h"
#include "trainer/io/user_folders.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QLockFile>
#include <QSet>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QThread>
#include <QUrl>
#include <QUuid>
#include <QVariant>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <vector>

namespace trainer::records {

namespace {

/// The translation context of this file's messages (lupdate reads Tr::tr).
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(trainer::records::RecordsDb)
};

/// The first key of PostgreSQL advisory locks on attempts ("PADR"); the second is the
/// attempt id modulo 2^31. Key (kLockClass, 0) serialises schema upgrades.
constexpr int kLockClass = 0x50414452;

/// One numbered step of the schema. Its statements run in order, in the upgrade's
/// transaction; "%ID%" stands for the back end's auto-increment key column.
struct Migration {
    int version;
    const char* description;
    QStringList statements;
};

/// Every step, in order, numbered 1, 2, 3… Never edit a published step: add one.
const QList<Migration>& migrations()
{
    static const QList<Migration> steps = {
        {1,
         "operators, attempts, score breakdowns, events",
         {
             "CREATE TABLE records_schema (version INTEGER PRIMARY KEY, applied TEXT NOT NULL,"
             " description TEXT NOT NULL)",
             "CREATE TABLE operators (id %ID%, code TEXT NOT NULL UNIQUE, name TEXT NOT NULL,"
             " created TEXT NOT NULL)",
             "CREATE TABLE attempts (id %ID%,"
             " operator_id BIGINT NOT NULL REFERENCES operators (id) ON DELETE CASCADE,"
             " tutorial TEXT NOT NULL, tutorial_title TEXT NOT NULL, started TEXT NOT NULL,"
             " duration_s DOUBLE PRECISION NOT NULL DEFAULT 0,"
             " score DOUBLE PRECISION NOT NULL DEFAULT 0 CHECK (score >= 0 AND score <= 100),"
             " stars INTEGER NOT NULL DEFAULT 0 CHECK (stars >= 0 AND stars <= 3),"
             " passed INTEGER NOT NULL DEFAULT 0 CHECK (passed IN (0, 1)),"
             " status TEXT NOT NULL CHECK (status IN ('running', 'finished', 'aborted', 'interrupted')),"
             " language TEXT NOT NULL)",
             "CREATE INDEX attempts_by_operator ON attempts (operator_id, started)",
             "CREATE INDEX attempts_running ON attempts (status) WHERE status = 'running'",
             "CREATE TABLE attempt_scores ("
             " attempt_id BIGINT NOT NULL REFERENCES attempts (id) ON DELETE CASCADE,"
             " seq INTEGER NOT NULL, key TEXT NOT NULL, label TEXT NOT NULL,"
             " value DOUBLE PRECISION NOT NULL, points DOUBLE PRECISION NOT NULL,"
             " max_points DOUBLE PRECISION NOT NULL, PRIMARY KEY (attempt_id, key))",
             "CREATE TABLE attempt_events (id %ID%,"
             " attempt_id BIGINT NOT NULL REFERENCES attempts (id) ON DELETE CASCADE,"
             " t DOUBLE PRECISION NOT NULL, kind TEXT NOT NULL, text TEXT NOT NULL,"
             " value DOUBLE PRECISION)",
             "CREATE INDEX attempt_events_by_attempt ON attempt_events (attempt_id, id)",
         }},
        {2,
         "events: the points they cost and what they concern (a goal, a shape, a drive)",
         {
             "ALTER TABLE attempt_events ADD COLUMN penalty DOUBLE PRECISION NOT NULL DEFAULT 0",
             "ALTER TABLE attempt_events ADD COLUMN detail TEXT NOT NULL DEFAULT ''",
         }},
        {3,
         "a training centre: attempts get a unique id and their station, events their index; a station's "
         "journal notes what the centre's server has",
         {
             "ALTER TABLE attempts ADD COLUMN uid TEXT",
             "ALTER TABLE attempts ADD COLUMN station TEXT NOT NULL DEFAULT ''",
             "ALTER TABLE attempt_events ADD COLUMN seq INTEGER",
             // old events: their index within their attempt, in the order appended
             "UPDATE attempt_events SET seq = r.n FROM (SELECT id,"
             " ROW_NUMBER() OVER (PARTITION BY attempt_id ORDER BY id) - 1 AS n FROM attempt_events) AS r"
             " WHERE r.id = attempt_events.id",
             "CREATE UNIQUE INDEX attempts_by_uid ON attempts (uid)",
             "CREATE UNIQUE INDEX attempt_events_by_seq ON attempt_events (attempt_id, seq)",
             "CREATE TABLE sync_state ("
             " attempt_id BIGINT PRIMARY KEY REFERENCES attempts (id) ON DELETE CASCADE,"
             " events INTEGER NOT NULL, status TEXT NOT NULL)",
             "CREATE TABLE sync_operators ("
             " operator_id BIGINT PRIMARY KEY REFERENCES operators (id) ON DELETE CASCADE)",
         }},
    };
    return steps;
}

/// Our tables: a database holding any of them without records_schema is not ours.
const QStringList& ourTables()
{
    static const QStringList names = {"records_schema", "operators", "attempts", "attempt_scores",
                                      "attempt_events", "sync_state", "sync_operators"};
    return names;
}

/// Timestamps are ISO 8601 text in UTC to the millisecond ("2025-03-01T09:30:00.250Z"):
/// the same in both back ends, and text order is time order.
QString toDb(const QDateTime& t)
{
    return t.toUTC().toString(Qt::ISODateWithMs);
}

QDateTime fromDb(const QVariant& v)
{
    QDateTime t = QDateTime::fromString(v.toString(), Qt::ISODateWithMs);
    return t.isValid() ? t.toUTC() : QDateTime();
}

/// NaN (no value) is stored as NULL.
QVariant nullableDouble(double x)
{
    return std::isnan(x) ? QVariant() : QVariant(x);
}

double doubleOrNaN(const QVariant& v)
{
    return v.isNull() ? std::numeric_limits<double>::quiet_NaN() : v.toDouble();
}

QString number(double x)
{
    return QString::number(x, 'g', QLocale::FloatingPointShortest);
}

/// One CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break.
QString csvField(const QString& s)
{
    if (!s.contains(',') && !s.contains('"') && !s.contains('\n') && !s.contains('\r')) return s;
    QString q = s;
    q.replace('"', "\"\"");
    return '"' + q + '"';
}

QString nextConnectionName()
{
    static std::atomic<quint64> counter{0};
    return QStringLiteral("padrob-records-%1").arg(++counter);
}

/// A transaction that rolls back unless committed. SQLite's starts with BEGIN
/// IMMEDIATE: it takes the write lock first (waiting up to the busy timeout), so it
/// never fails half-way for want of it.
class Transaction {
public:
    Transaction(const QSqlDatabase& db, bool sqlite) : m_db(db), m_sqlite(sqlite) {}
    ~Transaction()
    {
        if (m_open) rollback();
    }
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;

    bool begin()
    {
        QSqlQuery q(m_db);
        if (!q.exec(m_sqlite ? "BEGIN IMMEDIATE" : "BEGIN")) {
            m_error = q.lastError();
            return false;
        }
        m_open = true;
        return true;
    }
    bool commit()
    {
        QSqlQuery q(m_db);
        if (!q.exec("COMMIT")) {
            m_error = q.lastError();
            rollback();
            return false;
        }
        m_open = false;
        return true;
    }
    void rollback()
    {
        // fails harmlessly when the database already rolled back (SQLITE_FULL does)
        QSqlQuery q(m_db);
        q.exec("ROLLBACK");
        m_open = false;
    }
    QSqlError error() const { return m_error; }

private:
    QSqlDatabase m_db;
    bool m_sqlite;
    bool m_open = false;
    QSqlError m_error;
};

/// Prepares `sql` with `?` placeholders, binds `args` in order and runs it.
bool run(QSqlQuery& q, const QString& sql, const QVariantList& args = {})
{
    q.setForwardOnly(true);
    if (!q.prepare(sql)) return false;
    for (const QVariant& a : args) q.addBindValue(a);
    return q.exec();
}

}  // namespace

QString statusName(AttemptStatus status)
{
    switch (status) {
    case AttemptStatus::Running: return QStringLiteral("running");
    case AttemptStatus::Finished: return QStringLiteral("finished");
    case AttemptStatus::Aborted: return QStringLiteral("aborted");
    case AttemptStatus::Interrupted: return QStringLiteral("interrupted");
    }
    return {};
}

bool statusFromName(const QString& name, AttemptStatus& status)
{
    for (AttemptStatus s : {AttemptStatus::Running, AttemptStatus::Finished, AttemptStatus::Aborted,
                            AttemptStatus::Interrupted}) {
        if (statusName(s) == name) {
            status = s;
            return true;
        }
    }
    return false;
}

QString PostgresConfig::describe() const
{
    QString s = user.isEmpty() ? QString() : user + '@';
    s += host.isEmpty() ? QStringLiteral("localhost") : host;
    if (port > 0) s += ':' + QString::number(port);
    return s + '/' + database;
}

// ---------------------------------------------------------------------------------------

struct RecordsDb::Impl {
    QString connection;  ///< the QSqlDatabase connection's name; "" = closed
    bool postgres = false;
    bool readOnly = false;
    int busyTimeoutMs = 2000;
    QString where;       ///< for messages: the file, or user@host:port/database
    QString sqlitePath;  ///< absolute
    QString password;    ///< only to keep it out of messages
    QThread* thread = nullptr;
    int interruptedAtOpen = 0;
    /// attempts this object is recording, with their liveness lock: a QLockFile
    /// (SQLite) or a session advisory lock (PostgreSQL, no object needed)
    std::map<qint64, std::unique_ptr<QLockFile>> running;

    QSqlDatabase db() const { return QSqlDatabase::database(connection, false); }
    bool sqlite() const { return !postgres; }

    // errors --------------------------------------------------------------------------

    /// The driver's own text, without the password.
    QString driverText(const QSqlError& e) const
    {
        QString t = (e.databaseText().isEmpty() ? e.text() : e.databaseText()).simplified();  // one line
        if (!password.isEmpty()) t.replace(password, QStringLiteral("********"));
        return t;
    }

    /// Why `e` happened, for people.
    QString reason(const QSqlError& e) const
    {
        const QString native = e.nativeErrorCode();
        const QString busy = Tr::tr("the records database is in use by another program, which has kept it "
                                    "locked for over %1 s; close that program or try again")
                                 .arg(number(busyTimeoutMs / 1000.0));
        if (sqlite()) {
            bool ok = false;
            const int code = native.toInt(&ok) & 0xff;  // the primary code of an extended one
            if (ok) {
                switch (code) {
                case 5:  // SQLITE_BUSY
                case 6:  // SQLITE_LOCKED
                    return busy;
                case 8:  // SQLITE_READONLY
                    return Tr::tr("the records database %1 is read-only (check the permissions of the file "
                                  "and of its folder)")
                        .arg(where);
                case 13:  // SQLITE_FULL
                    return Tr::tr("the disk holding the records database %1 is full; free some space (nothing "
                                  "of this step was recorded)")
                        .arg(where);
                case 11:  // SQLITE_CORRUPT
                    return Tr::tr("the records database %1 is damaged (%2); keep a copy of the file and "
                                  "restore it from a backup")
                        .arg(where, driverText(e));
                case 26:  // SQLITE_NOTADB
                    return Tr::tr("the file is not a records database (not an SQLite database, or a damaged "
                                  "one)");
                case 14:  // SQLITE_CANTOPEN
                    return Tr::tr("SQLite cannot open the file %1 (does its folder exist, and may Padrob "
                                  "write there?)")
                        .arg(where);
                case 10:  // SQLITE_IOERR
                    return Tr::tr("the disk reported an error on %1 (%2)").arg(where, driverText(e));
                default: break;
                }
            }
        } else {
            if (native == "55P03" || native == "40P01" || native == "40001") return busy;
            if (native == "53100")
                return Tr::tr("the PostgreSQL server's disk is full; ask its administrator to free some "
                              "space (nothing of this step was recorded)");
            if (native == "25006")
                return Tr::tr("the records database %1 is open read-only").arg(where);
            if (native == "42501")
                return Tr::tr("the PostgreSQL user may not do this on %1 (%2); ask the server's "
                              "administrator for the rights")
                    .arg(where, driverText(e));
            if (native.startsWith("08") || native == "57P01" || native == "57P02" || native == "57P03")
                return Tr::tr("lost the connection to the PostgreSQL server %1 (%2)").arg(where, driverText(e));
        }
        return driverText(e);
    }

    /// Sets `*error` to "what: reason" and returns false.
    bool fail(QString* error, const QString& what, const QString& why) const
    {
        if (error) *error = Tr::tr("%1: %2").arg(what, why);
        return false;
    }
    bool fail(QString* error, const QString& what, const QSqlError& e) const
    {
        return fail(error, what, reason(e));
    }

    /// Whether a call may go on (open, right thread, writable when it writes).
    bool usable(bool writes, const QString& what, QString* error) const
    {
        if (connection.isEmpty()) return fail(error, what, Tr::tr("the records database is not open"));
        if (QThread::currentThread() != thread)
            return fail(error, what,
                        Tr::tr("the records database was opened in another thread (each thread needs a "
                               "RecordsDb of its own)"));
        if (writes && readOnly)
            return fail(error, what, Tr::tr("the records database %1 is open read-only").arg(where));
        return true;
    }

    // opening -------------------------------------------------------------------------

    bool openSqlite(const QString& file, QString* error);
    bool openPostgres(const PostgresConfig& server, QString* error);
    // the helpers take the caller's query: on PostgreSQL it must outlive the
    // transaction, or freeing its prepared statement in an aborted one warns
    bool readVersion(QSqlQuery& q, int& version, const QString& what, QString* error) const;
    bool prepareSchema(QString* error);
    bool upgrade(QSqlQuery& q, int from, const QString& what, QString* error);
    bool markInterrupted(QSqlQuery& q, const QString& what, QString* error);

    QString lockFolder() const { return sqlitePath + "-running"; }
    QString lockPath(qint64 attemptId) const
    {
        return lockFolder() + QStringLiteral("/attempt-%1.lock").arg(attemptId);
    }
    std::unique_ptr<QLockFile> makeLock(qint64 attemptId) const
    {
        auto lock = std::make_unique<QLockFile>(lockPath(attemptId));
        lock->setStaleLockTime(0);  // stale only when its process is gone, never by age
        return lock;
    }
    /// Takes the liveness lock of an attempt being begun (inside its transaction).
    void holdAttempt(qint64 attemptId)
    {
        if (postgres) {
            QSqlQuery q(db());
            run(q,
                "SELECT pg_advisory_lock(CAST(? AS INTEGER),"
                " CAST(MOD(CAST(? AS BIGINT), 2147483648) AS INTEGER))",
                {kLockClass, attemptId});
            running[attemptId] = nullptr;
            return;
        }
        // without the lock (a lock folder we cannot write) the attempt is still
        // recorded; another RecordsDb opening meanwhile would mark it interrupted, and
        // finishAttempt() puts it right
        QDir().mkpath(lockFolder());
        auto lock = makeLock(attemptId);
        if (lock->tryLock(0)) running[attemptId] = std::move(lock);
        else running[attemptId] = nullptr;
    }
    void releaseAttempt(qint64 attemptId)
    {
        const auto it = running.find(attemptId);
        if (it == running.end()) return;
        if (postgres) {
            QSqlQuery q(db());
            run(q,
                "SELECT pg_advisory_unlock(CAST(? AS INTEGER),"
                " CAST(MOD(CAST(? AS BIGINT), 2147483648) AS INTEGER))",
                {kLockClass, attemptId});
        }
        running.erase(it);  // QLockFile's destructor unlocks and removes the file
    }

    // reading -------------------------------------------------------------------------

    bool loadAttempts(const QString& filter, const QVariant& arg, bool withEvents, QList<Attempt>& out,
                      const QString& what, QString* error) const;
};

bool RecordsDb::Impl::openSqlite(const QString& file, QString* error)
{
    sqlitePath = QFileInfo(file.isEmpty() ? defaultSqlitePath() : file).absoluteFilePath();
    where = QDir::toNativeSeparators(sqlitePath);
    const QString what = Tr::tr("cannot open the records database %1").arg(where);
    if (!QSqlDatabase::isDriverAvailable("QSQLITE"))
        return fail(error, what,
                    Tr::tr("the SQLite driver of Qt (QSQLITE) is not installed (on Debian: the package "
                           "libqt6sql6-sqlite)"));

    // check the file ourselves first: a file that is not SQLite is refused untouched
    const QFileInfo fi(sqlitePath);
    const QString folder = fi.absolutePath();
    if (fi.exists()) {
        if (!fi.isFile()) return fail(error, what, Tr::tr("it is a folder, not a file"));
        QFile f(sqlitePath);
        if (!f.open(QIODevice::ReadOnly)) return fail(error, what, f.errorString());
        const QByteArray head = f.read(16);
        if (!head.isEmpty() && head != QByteArray("SQLite format 3\0", 16))
            return fail(error, what, Tr::tr("the file is not a records database (not an SQLite database)"));
    } else if (readOnly) {
        return fail(error, what, Tr::tr("there is no such file"));
    }
    if (!readOnly) {
        if (!QFileInfo::exists(folder) && !QDir().mkpath(folder))
            return fail(error, what, Tr::tr("cannot create its folder %1").arg(QDir::toNativeSeparators(folder)));
        if (fi.exists() && !fi.isWritable())
            return fail(error, what,
                        Tr::tr("the file is read-only (check its permissions, or open the records read-only)"));
        if (!QFileInfo(folder).isWritable())
            return fail(error, what,
                        Tr::tr("its folder %1 is read-only, and SQLite writes its journal there (check the "
                               "folder's permissions, or open the records read-only)")
                            .arg(QDir::toNativeSeparators(folder)));
    }

    QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", connection);
    QStringList options{QStringLiteral("QSQLITE_BUSY_TIMEOUT=%1").arg(busyTimeoutMs)};
    if (readOnly) {
        options << "QSQLITE_OPEN_READONLY";
        // a WAL database needs its -shm file; in a read-only folder without one, read
        // the file as immutable (no locks: nobody can write there either)
        if (!QFileInfo(folder).isWritable() && !QFileInfo::exists(sqlitePath + "-shm")) {
            options << "QSQLITE_OPEN_URI";
            db.setDatabaseName(QUrl::fromLocalFile(sqlitePath).toString(QUrl::FullyEncoded) + "?immutable=1");
        }
    }
    if (db.databaseName().isEmpty()) db.setDatabaseName(sqlitePath);
    db.setConnectOptions(options.join(';'));
    if (!db.open()) return fail(error, what, db.lastError());
    QSqlQuery q(db);
    // per connection: foreign keys, and a commit is on disk before it returns (WAL +
    // FULL: every commit syncs the log; docs/records.md says why not NORMAL)
    for (const char* pragma : {"PRAGMA foreign_keys = ON", "PRAGMA synchronous = FULL"})
        if (!q.exec(pragma)) return fail(error, what, q.lastError());
    return true;
}

bool RecordsDb::Impl::openPostgres(const PostgresConfig& server, QString* error)
{
    where = server.describe();
    password = server.password;
    const QString what = Tr::tr("cannot open the records database %1").arg(where);
    const QString missing = Tr::tr("the PostgreSQL driver of Qt (QPSQL) is not installed (on Debian: the "
                                   "package libqt6sql6-psql); until it is, use the records file on this "
                                   "computer");
    if (!QSqlDatabase::isDriverAvailable("QPSQL")) return fail(error, what, missing);
    QSqlDatabase db = QSqlDatabase::addDatabase("QPSQL", connection);
    if (!db.isValid()) return fail(error, what, missing);
    if (!server.host.isEmpty()) db.setHostName(server.host);
    if (server.port > 0) db.setPort(server.port);
    db.setDatabaseName(server.database);
    if (!server.user.isEmpty()) db.setUserName(server.user);
    if (!server.password.isEmpty()) db.setPassword(server.password);
    db.setConnectOptions(QStringLiteral("connect_timeout=%1;application_name=padrob")
                             .arg(std::max(1, server.connectTimeoutS)));
    if (!db.open())
        return fail(error, what,
                    Tr::tr("the PostgreSQL server did not accept the connection (%1)")
                        .arg(driverText(db.lastError())));
    QSqlQuery q(db);
    // a lock held by another session makes a statement fail after the busy timeout,
    // as SQLite's does; notices (e.g. of the upgrade) stay out of the log
    const QStringList settings = {
        QStringLiteral("SET lock_timeout = %1").arg(std::max(1, busyTimeoutMs)),
        QStringLiteral("SET client_min_messages = warning"),
        QStringLiteral("SET default_transaction_read_only = %1").arg(readOnly ? "on" : "off")};
    for (const QString& s : settings)
        if (!q.exec(s)) return fail(error, what, q.lastError());
    return true;
}

bool RecordsDb::Impl::readVersion(QSqlQuery& q, int& version, const QString& what, QString* error) const
{
    // our tables present: SQLite's file must hold nothing else; a PostgreSQL database
    // may hold other applications' tables
    const bool ok = sqlite() ? run(q, "SELECT name FROM sqlite_master WHERE type = 'table' AND name NOT LIKE 'sqlite%'")
                             : run(q, "SELECT table_name FROM information_schema.tables"
                                      " WHERE table_schema = current_schema()");
    if (!ok) return fail(error, what, q.lastError());
    QStringList tables;
    while (q.next()) tables << q.value(0).toString();
    if (q.lastError().isValid()) return fail(error, what, q.lastError());
    q.finish();
    if (!tables.contains("records_schema")) {
        const bool foreign = sqlite() ? !tables.isEmpty()
                                      : std::any_of(tables.begin(), tables.end(),
                                                    [](const QString& t) { return ourTables().contains(t); });
        if (foreign)
            return fail(error, what,
                        Tr::tr("it holds other tables, not Padrob's records (left untouched)"));
        version = 0;
        return true;
    }
    if (!run(q, "SELECT MAX(version) FROM records_schema") || !q.next()) return fail(error, what, q.lastError());
    version = q.value(0).toInt();
    q.finish();
    return true;
}

bool RecordsDb::Impl::prepareSchema(QString* error)
{
    const QString what = Tr::tr("cannot open the records database %1").arg(where);
    const int current = RecordsDb::schemaVersion();
    auto newer = [&](int version) {
        return fail(error, what,
                    Tr::tr("it has schema version %1, newer than this Padrob's (%2); open it with a newer "
                           "Padrob (it was left untouched)")
                        .arg(version)
                        .arg(current));
    };

    // first only read: a database we refuse is left exactly as it was
    QSqlQuery q(db());
    int version = 0;
    if (!readVersion(q, version, what, error)) return false;
    if (version > current) return newer(version);
    if (readOnly) {
        if (version == current) return true;
        return fail(error, what,
                    version == 0 ? Tr::tr("it holds no records yet, and it is open read-only")
                                 : Tr::tr("it has the older schema version %1 and this Padrob needs %2; open "
                                          "it once with write access to upgrade it")
                                       .arg(version)
                                       .arg(current));
    }

    if (sqlite()) {
        // write-ahead log: a commit appends to the -wal file, readers are not blocked,
        // and a crash loses at most the transaction in progress (persistent in the file)
        if (!run(q, "PRAGMA journal_mode") || !q.next()) return fail(error, what, q.lastError());
        if (q.value(0).toString().compare("wal", Qt::CaseInsensitive) != 0) {
            q.finish();
            if (!run(q, "PRAGMA journal_mode = WAL") || !q.next()) return fail(error, what, q.lastError());
            if (q.value(0).toString().compare("wal", Qt::CaseInsensitive) != 0)
                return fail(error, what, Tr::tr("SQLite refused the write-ahead log (journal mode %1)")
                                             .arg(q.value(0).toString()));
        }
        q.finish();
    }

    // then upgrade and mark dead attempts, in one transaction
    Transaction tx(db(), sqlite());
    if (!tx.begin()) return fail(error, what, tx.error());
    if (postgres) {
        // one upgrade at a time across stations (SQLite's BEGIN IMMEDIATE does that)
        if (!run(q, "SELECT pg_advisory_xact_lock(CAST(? AS INTEGER), 0)", {kLockClass}))
            return fail(error, what, q.lastError());
        q.finish();
    }
    if (!readVersion(q, version, what, error)) return false;  // another program may have upgraded it
    if (version > current) return newer(version);
    if (version < current && !upgrade(q, version, what, error)) return false;
    const int before = interruptedAtOpen;
    if (!markInterrupted(q, what, error)) return false;
    if (!tx.commit()) {
        interruptedAtOpen = before;
        return fail(error, what, tx.error());
    }
    return true;
}

bool RecordsDb::Impl::upgrade(QSqlQuery& q, int from, const QString& what, QString* error)
{
    const QString id = sqlite() ? QStringLiteral("INTEGER PRIMARY KEY AUTOINCREMENT")
                                : QStringLiteral("BIGINT GENERATED BY DEFAULT AS IDENTITY PRIMARY KEY");
    for (const Migration& m : migrations()) {
        if (m.version <= from) continue;
        for (QString sql : m.statements) {
            sql.replace("%ID%", id);
            if (!q.exec(sql))
                return fail(error, what,
                            Tr::tr("the upgrade to schema version %1 failed (%2)")
                                .arg(m.version)
                                .arg(reason(q.lastError())));
        }
        if (!run(q, "INSERT INTO records_schema (version, applied, description) VALUES (?, ?, ?)",
                 {m.version, toDb(QDateTime::currentDateTimeUtc()), QString::fromLatin1(m.description)}))
            return fail(error, what, q.lastError());
    }
    return true;
}

bool RecordsDb::Impl::markInterrupted(QSqlQuery& q, const QString& what, QString* error)
{
    if (postgres) {
        // a running attempt whose recorder is alive has its session's advisory lock;
        // one of a station's journal (station <> '') has none: only that station's
        // sync marks it (docs/records.md, "A training centre")
        if (!run(q, "UPDATE attempts SET status = 'interrupted' WHERE status = 'running' AND station = ''"
                    " AND pg_try_advisory_xact_lock(CAST(? AS INTEGER), CAST(MOD(id, 2147483648) AS INTEGER))",
                 {kLockClass}))
            return fail(error, what, q.lastError());
        interruptedAtOpen += std::max(0, q.numRowsAffected());
        return true;
    }
    if (!run(q, "SELECT id FROM attempts WHERE status = 'running'")) return fail(error, what, q.lastError());
    QList<qint64> ids;
    while (q.next()) ids << q.value(0).toLongLong();
    q.finish();
    if (ids.isEmpty()) return true;
    // a running attempt whose recorder is alive has its QLockFile; a dead process's
    // lock is stale, a missing one means the same. Held until the transaction ends.
    QDir().mkpath(lockFolder());
    std::vector<std::unique_ptr<QLockFile>> dead;
    for (qint64 id : ids) {
        auto lock = makeLock(id);
        if (!lock->tryLock(0)) continue;
        if (!run(q, "UPDATE attempts SET status = 'interrupted' WHERE id = ? AND status = 'running'", {id}))
            return fail(error, what, q.lastError());
        dead.push_back(std::move(lock));
        ++interruptedAtOpen;
    }
    return true;
}

bool RecordsDb::Impl::loadAttempts(const QString& filter, const QVariant& arg, bool withEvents,
                                   QList<Attempt>& out, const QString& what, QString* error) const
{
    QList<Attempt> list;
    QHash<qint64, qsizetype> index;
    QSqlQuery q(db());
    if (!run(q,
             "SELECT a.id, a.operator_id, a.tutorial, a.tutorial_title, a.started, a.duration_s, a.score,"
             " a.stars, a.passed, a.status, a.language, a.uid, a.station FROM attempts a WHERE " +
                 filter + " ORDER BY a.started DESC, a.id DESC",
             {arg}))
        return fail(error, what, q.lastError());
    while (q.next()) {
        Attempt a;
        a.id = q.value(0).toLongLong();
        a.operatorId = q.value(1).toLongLong();
        a.tutorialId = q.value(2).toString();
        a.tutorialTitle = q.value(3).toString();
        a.started = fromDb(q.value(4));
        a.durationS = q.value(5).toDouble();
        a.score = q.value(6).toDouble();
        a.stars = q.value(7).toInt();
        a.passed = q.value(8).toInt() != 0;
        if (!statusFromName(q.value(9).toString(), a.status)) a.status = AttemptStatus::Interrupted;
        a.language = q.value(10).toString();
        a.uid = q.value(11).toString();
        a.station = q.value(12).toString();
        index.insert(a.id, list.size());
        list.append(a);
    }
    if (q.lastError().isValid()) return fail(error, what, q.lastError());
    q.finish();
    if (list.isEmpty()) {
        out.clear();
        return true;
    }

    if (!run(q,
             "SELECT s.attempt_id, s.key, s.label, s.value, s.points, s.max_points FROM attempt_scores s"
             " JOIN attempts a ON a.id = s.attempt_id WHERE " +
                 filter + " ORDER BY s.attempt_id, s.seq",
             {arg}))
        return fail(error, what, q.lastError());
    while (q.next()) {
        const auto it = index.constFind(q.value(0).toLongLong());
        if (it == index.constEnd()) continue;
        list[*it].breakdown.append({q.value(1).toString(), q.value(2).toString(), q.value(3).toDouble(),
                                    q.value(4).toDouble(), q.value(5).toDouble()});
    }
    if (q.lastError().isValid()) return fail(error, what, q.lastError());
    q.finish();

    if (withEvents) {
        if (!run(q,
                 "SELECT e.attempt_id, e.t, e.kind, e.text, e.value, e.penalty, e.detail, e.seq"
                 " FROM attempt_events e JOIN attempts a ON a.id = e.attempt_id WHERE " +
                     filter + " ORDER BY e.attempt_id, e.seq, e.id",
                 {arg}))
            return fail(error, what, q.lastError());
        while (q.next()) {
            const auto it = index.constFind(q.value(0).toLongLong());
            if (it == index.constEnd()) continue;
            AttemptEvent e(q.value(1).toDouble(), q.value(2).toString(), q.value(3).toString(),
                           doubleOrNaN(q.value(4)), q.value(5).toDouble(), q.value(6).toString());
            e.seq = q.value(7).toInt();
            list[*it].events.append(e);
        }
        if (q.lastError().isValid()) return fail(error, what, q.lastError());
    }
    out = std::move(list);
    return true;
}

// ---------------------------------------------------------------------------------------

RecordsDb::RecordsDb() : d(std::make_unique<Impl>()) {}

RecordsDb::~RecordsDb()
{
    close();
}

QString RecordsDb::defaultSqlitePath()
{
    return userFolders::recordsDatabase();
}

int RecordsDb::schemaVersion()
{
    return migrations().last().version;
}

bool RecordsDb::open(const RecordsLocation& where, QString* error)
{
    close();
    d->thread = QThread::currentThread();
    d->readOnly = where.readOnly;
    d->busyTimeoutMs = std::max(0, where.busyTimeoutMs);
    d->interruptedAtOpen = 0;
    d->password.clear();
    d->sqlitePath.clear();
    d->postgres = where.postgres.isSet();
    d->connection = nextConnectionName();
    const bool ok = (d->postgres ? d->openPostgres(where.postgres, error) : d->openSqlite(where.sqlitePath, error)) &&
                    d->prepareSchema(error);
    if (!ok) close();
    return ok;
}

bool RecordsDb::openSqlite(const QString& path, bool readOnly, QString* error)
{
    RecordsLocation where;
    where.sqlitePath = path;
    where.readOnly = readOnly;
    return open(where, error);
}

bool RecordsDb::openPostgres(const PostgresConfig& server, QString* error)
{
    RecordsLocation where;
    where.postgres = server;
    return open(where, error);
}

void RecordsDb::close()
{
    if (d->connection.isEmpty()) return;
    const bool ownThread = QThread::currentThread() == d->thread;
    if (ownThread) {
        QSqlDatabase db = d->db();
        if (db.isOpen() && !d->running.empty()) {
            // still running: the recording stopped without a result
            Transaction tx(db, d->sqlite());
            if (tx.begin()) {
                QSqlQuery q(db);
                for (const auto& [id, lock] : d->running)
                    run(q, "UPDATE attempts SET status = 'interrupted' WHERE id = ? AND status = 'running'", {id});
                q.finish();
                tx.commit();
            }
        }
        d->running.clear();  // file locks removed; PostgreSQL's go with the session
        if (db.isValid()) db.close();
    }
    d->running.clear();
    QSqlDatabase::removeDatabase(d->connection);
    d->connection.clear();
    d->password.clear();
}

bool RecordsDb::isOpen() const
{
    return !d->connection.isEmpty();
}

bool RecordsDb::isPostgres() const
{
    return isOpen() && d->postgres;
}

bool RecordsDb::isReadOnly() const
{
    return isOpen() && d->readOnly;
}

QString RecordsDb::where() const
{
    return isOpen() ? d->where : QString();
}

int RecordsDb::interruptedAtOpen() const
{
    return d->interruptedAtOpen;
}

// operators --------------------------------------------------------------------------

qint64 RecordsDb::addOperator(const QString& code, const QString& name, QString* error)
{
    const QString c = code.trimmed();
    const QString what = Tr::tr("cannot add the operator “%1”").arg(c);
    if (!d->usable(true, what, error)) return 0;
    if (c.isEmpty()) return d->fail(error, what, Tr::tr("an operator needs an id")), 0;
    QSqlQuery q(d->db());  // before the transaction: it outlives it
    Transaction tx(d->db(), d->sqlite());
    if (!tx.begin()) return d->fail(error, what, tx.error()), 0;
    if (!run(q, "SELECT name FROM operators WHERE code = ?", {c})) return d->fail(error, what, q.lastError()), 0;
    if (q.next())
        return d->fail(error, what, Tr::tr("the id is taken already, by “%1”").arg(q.value(0).toString())), 0;
    q.finish();
    if (!run(q, "INSERT INTO operators (code, name, created) VALUES (?, ?, ?) RETURNING id",
             {c, name.trimmed(), toDb(QDateTime::currentDateTimeUtc())}) ||
        !q.next())
        return d->fail(error, what, q.lastError()), 0;
    const qint64 id = q.value(0).toLongLong();
    q.finish();
    if (!tx.commit()) return d->fail(error, what, tx.error()), 0;
    return id;
}

bool RecordsDb::renameOperator(qint64 operatorId, const QString& name, QString* error)
{
    const QString what = Tr::tr("cannot rename the operator");
    if (!d->usable(true, what, error)) return false;
    QSqlQuery q(d->db());  // before the transaction: it outlives it
    Transaction tx(d->db(), d->sqlite());
    if (!tx.begin()) return d->fail(error, what, tx.error());
    if (!run(q, "UPDATE operators SET name = ? WHERE id = ?", {name.trimmed(), operatorId}))
        return d->fail(error, what, q.lastError());
    if (q.numRowsAffected() != 1) return d->fail(error, what, Tr::tr("there is no operator %1").arg(operatorId));
    return tx.commit() || d->fail(error, what, tx.error());
}

bool RecordsDb::findOperator(const QString& code, Operator& out, QString* error) const
{
    const QString what = Tr::tr("cannot look the operator up");
    if (error) error->clear();
    if (!d->usable(false, what, error)) return false;
    QSqlQuery q(d->db());
    if (!run(q, "SELECT id, code, name, created FROM operators WHERE code = ?", {code.trimmed()}))
        return d->fail(error, what, q.lastError());
    if (!q.next()) return q.lastError().isValid() ? d->fail(error, what, q.lastError()) : false;
    out = {q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(), fromDb(q.value(3))};
    return true;
}

// attempts ---------------------------------------------------------------------------

qint64 RecordsDb::beginAttempt(const AttemptStart& start, QString* error)
{
    const QString what = Tr::tr("cannot record the start of the attempt");
    if (!d->usable(true, what, error)) return 0;
    if (start.tutorialId.isEmpty()) return d->fail(error, what, Tr::tr("the tutorial has no id")), 0;
    const QDateTime started = start.started.isValid() ? start.started : QDateTime::currentDateTimeUtc();
    const QString uid = start.uid.isEmpty() ? QUuid::createUuid().toString(QUuid::WithoutBraces) : start.uid;
    QSqlQuery q(d->db());  // before the transaction: it outlives it
    Transaction tx(d->db(), d->sqlite());
    if (!tx.begin()) return d->fail(error, what, tx.error()), 0;
    if (!run(q, "SELECT id FROM operators WHERE id = ?", {start.operatorId}))
        return d->fail(error, what, q.lastError()), 0;
    if (!q.next()) return d->fail(error, what, Tr::tr("there is no operator %1").arg(start.operatorId)), 0;
    q.finish();
    if (!run(q, "SELECT id FROM attempts WHERE uid = ?", {uid})) return d->fail(error, what, q.lastError()), 0;
    if (q.next()) return d->fail(error, what, Tr::tr("there is an attempt with the id %1 already").arg(uid)), 0;
    q.finish();
    if (!run(q,
             "INSERT INTO attempts (operator_id, tutorial, tutorial_title, started, status, language, uid, station)"
             " VALUES (?, ?, ?, ?, 'running', ?, ?, ?) RETURNING id",
             {start.operatorId, start.tutorialId, start.tutorialTitle, toDb(started), start.language, uid,
              start.station.isNull() ? QString::fromLatin1("") : start.station}) ||
        !q.next())
        return d->fail(error, what, q.lastError()), 0;
    const qint64 id = q.value(0).toLongLong();
    q.finish();
    // the liveness lock before the commit: nobody sees the attempt running without it
    d->holdAttempt(id);
    if (!tx.commit()) {
        d->releaseAttempt(id);
        return d->fail(error, what, tx.error()), 0;
    }
    return id;
}

bool RecordsDb::appendEvents(qint64 attemptId, const QList<AttemptEvent>& events, QString* error)
{
    const QString what = Tr::tr("cannot record the attempt's events");
    if (!d->usable(true, what, error)) return false;
    if (events.isEmpty()) return true;
    for (const AttemptEvent& e : events)
        if (!std::isfinite(e.t)) return d->fail(error, what, Tr::tr("an event has no valid time"));
    QSqlQuery q(d->db());  // before the transaction: it outlives it
    Transaction tx(d->db(), d->sqlite());
    if (!tx.begin()) return d->fail(error, what, tx.error());
    if (!run(q, "SELECT id FROM attempts WHERE id = ?", {attemptId})) return d->fail(error, what, q.lastError());
    if (!q.next()) return d->fail(error, what, Tr::tr("there is no attempt %1").arg(attemptId));
    q.finish();
    // the next index: how many the attempt has (its indexes are 0, 1, 2…)
    if (!run(q, "SELECT COALESCE(MAX(seq), -1) + 1 FROM attempt_events WHERE attempt_id = ?", {attemptId}) ||
        !q.next())
        return d->fail(error, what, q.lastError());
    const qint64 next = q.value(0).toLongLong();
    q.finish();
    if (!q.prepare("INSERT INTO attempt_events (attempt_id, t, kind, text, value, penalty, detail, seq)"
                   " VALUES (?, ?, ?, ?, ?, ?, ?, ?)"))
        return d->fail(error, what, q.lastError());
    for (qsizetype i = 0; i < events.size(); ++i) {
        const AttemptEvent& e = events[i];
        q.bindValue(7, e.seq >= 0 ? qint64(e.seq) : next + i);
        q.bindValue(0, attemptId);
        q.bindValue(1, e.t);
        q.bindValue(2, e.kind);
        q.bindValue(3, e.text);
        q.bindValue(4, nullableDouble(e.value));
        q.bindValue(5, std::isfinite(e.penalty) ? e.penalty : 0.0);
        q.bindValue(6, e.detail.isNull() ? QString::fromLatin1("") : e.detail);  // a null QString binds NULL
        if (!q.exec()) return d->fail(error, what, q.lastError());
    }
    q.finish();
    return tx.commit() || d->fail(error, what, tx.error());
}

bool RecordsDb::finishAttempt(qint64 attemptId, const AttemptResult& r, QString* error)
{
    const QString what = Tr::tr("cannot record the attempt's result");
    if (!d->usable(true, what, error)) return false;
    if (r.status == AttemptStatus::Running)
        return d->fail(error, what, Tr::tr("an attempt ends finished, aborted or interrupted, not %1").arg(statusName(r.status)));
    if (!(r.score >= 0 && r.score <= 100))
        return d->fail(error, what, Tr::tr("the score %1 is not within 0…100").arg(number(r.score)));
    if (r.stars < 0 || r.stars > 3)
        return d->fail(error, what, Tr::tr("%1 stars is not within 0…3").arg(r.stars));
    if (!(r.durationS >= 0) || !std::isfinite(r.durationS))
        return d->fail(error, what, Tr::tr("the duration %1 s is not valid").arg(number(r.durationS)));
    QSet<QString> keys;
    for (const ScoreItem& s : r.breakdown) {
        if (s.key.isEmpty() || keys.contains(s.key))
            return d->fail(error, what, Tr::tr("the score breakdown has an empty or repeated key “%1”").arg(s.key));
        if (!std::isfinite(s.value) || !std::isfinite(s.points) || !std::isfinite(s.maxPoints))
            return d->fail(error, what, Tr::tr("the score item “%1” has no valid value or points").arg(s.key));
        keys.insert(s.key);
    }

    QSqlQuery q(d->db());  // before the transaction: it outlives it
    Transaction tx(d->db(), d->sqlite());
    if (!tx.begin()) return d->fail(error, what, tx.error());
    if (!run(q, "UPDATE attempts SET duration_s = ?, score = ?, stars = ?, passed = ?, status = ? WHERE id = ?",
             {r.durationS, r.score, r.stars, r.passed ? 1 : 0, statusName(r.status), attemptId}))
        return d->fail(error, what, q.lastError());
    if (q.numRowsAffected() != 1) return d->fail(error, what, Tr::tr("there is no attempt %1").arg(attemptId));
    if (!run(q, "DELETE FROM attempt_scores WHERE attempt_id = ?", {attemptId}))
        return d->fail(error, what, q.lastError());
    if (!q.prepare("INSERT INTO attempt_scores (attempt_id, seq, key, label, value, points, max_points)"
                   " VALUES (?, ?, ?, ?, ?, ?, ?)"))
        return d->fail(error, what, q.lastError());
    for (qsizetype i = 0; i < r.breakdown.size(); ++i) {
        const ScoreItem& s = r.breakdown[i];
        q.bindValue(0, attemptId);
        q.bindValue(1, int(i));
        q.bindValue(2, s.key);
        q.bindValue(3, s.label);
        q.bindValue(4, s.value);
        q.bindValue(5, s.points);
        q.bindValue(6, s.maxPoints);
        if (!q.exec()) return d->fail(error, what, q.lastError());
    }
    q.finish();
    if (!tx.commit()) return d->fail(error, what, tx.error());
    d->releaseAttempt(attemptId);
    return true;
}

// queries ----------------------------------------------------------------------------

bool RecordsDb::progress(QList<OperatorProgress>& out, QString* error) const
{
    const QString what = Tr::tr("cannot read the operators' progress");
    if (!d->usable(false, what, error)) return false;
    QList<OperatorProgress> list;
    QHash<qint64, qsizetype> index;
    QSqlQuery q(d->db());
    if (!run(q, "SELECT id, code, name, created FROM operators")) return d->fail(error, what, q.lastError());
    while (q.next()) {
        OperatorProgress p;
        p.op = {q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(), fromDb(q.value(3))};
        list.append(p);
    }
    if (q.lastError().isValid()) return d->fail(error, what, q.lastError());
    q.finish();
    // by code, the same on both back ends (their collations differ)
    std::sort(list.begin(), list.end(), [](const OperatorProgress& a, const OperatorProgress& b) {
        const int c = a.op.code.compare(b.op.code, Qt::CaseInsensitive);
        return c != 0 ? c < 0 : a.op.code < b.op.code;
    });
    for (qsizetype i = 0; i < list.size(); ++i) index.insert(list[i].op.id, i);

    // per operator and tutorial; the best of the attempts with a score (finished or
    // stopped: what the Records view lists with one), passed only by a finished one
    if (!run(q,
             "SELECT a.operator_id, a.tutorial, COUNT(*),"
             " MAX(CASE WHEN a.status IN ('finished', 'aborted') THEN a.score ELSE 0 END),"
             " MAX(CASE WHEN a.status IN ('finished', 'aborted') THEN a.stars ELSE 0 END),"
             " MAX(CASE WHEN a.status = 'finished' THEN a.passed ELSE 0 END),"
             " MAX(a.started),"
             " (SELECT b.tutorial_title FROM attempts b WHERE b.operator_id = a.operator_id"
             "  AND b.tutorial = a.tutorial ORDER BY b.started DESC, b.id DESC LIMIT 1)"
             " FROM attempts a GROUP BY a.operator_id, a.tutorial"))
        return d->fail(error, what, q.lastError());
    while (q.next()) {
        const auto it = index.constFind(q.value(0).toLongLong());
        if (it == index.constEnd()) continue;
        OperatorProgress& p = list[*it];
        TutorialProgress t;
        t.tutorialId = q.value(1).toString();
        t.attempts = q.value(2).toInt();
        t.bestScore = q.value(3).toDouble();
        t.bestStars = q.value(4).toInt();
        t.passed = q.value(5).toInt() != 0;
        t.lastAttempt = fromDb(q.value(6));
        t.tutorialTitle = q.value(7).toString();
        p.attempts += t.attempts;
        p.tutorialsPassed += t.passed ? 1 : 0;
        if (!p.lastAttempt.isValid() || t.lastAttempt > p.lastAttempt) p.lastAttempt = t.lastAttempt;
        p.tutorials.append(t);
    }
    if (q.lastError().isValid()) return d->fail(error, what, q.lastError());
    for (OperatorProgress& p : list)
        std::sort(p.tutorials.begin(), p.tutorials.end(),
                  [](const TutorialProgress& a, const TutorialProgress& b) { return a.tutorialId < b.tutorialId; });
    out = std::move(list);
    return true;
}

bool RecordsDb::attemptsOf(qint64 operatorId, QList<Attempt>& out, bool withEvents, QString* error) const
{
    const QString what = Tr::tr("cannot read the operator's attempts");
    if (!d->usable(false, what, error)) return false;
    return d->loadAttempts("a.operator_id = ?", operatorId, withEvents, out, what, error);
}

bool RecordsDb::attempt(qint64 attemptId, Attempt& out, QString* error) const
{
    const QString what = Tr::tr("cannot read the attempt");
    if (error) error->clear();
    if (!d->usable(false, what, error)) return false;
    QList<Attempt> list;
    if (!d->loadAttempts("a.id = ?", attemptId, true, list, what, error)) return false;
    if (list.isEmpty()) return false;
    out = list.first();
    return true;
}

bool RecordsDb::exportCsv(const QString& path, QString* error, const QHash<QString, QString>& titles, int* rows) const
{
    if (rows) *rows = 0;
    const QString what = Tr::tr("cannot export the records to %1").arg(QDir::toNativeSeparators(path));
    if (!d->usable(false, what, error)) return false;

    // each attempt's breakdown as "key=points/max; key=points" (no "/max" when 0)
    QHash<qint64, QStringList> breakdowns;
    QSqlQuery q(d->db());
    if (!run(q, "SELECT attempt_id, key, points, max_points FROM attempt_scores ORDER BY attempt_id, seq"))
        return d->fail(error, what, q.lastError());
    while (q.next()) {
        QString item = q.value(1).toString() + '=' + number(q.value(2).toDouble());
        if (q.value(3).toDouble() != 0) item += '/' + number(q.value(3).toDouble());
        breakdowns[q.value(0).toLongLong()].append(item);
    }
    if (q.lastError().isValid()) return d->fail(error, what, q.lastError());
    q.finish();

    struct Row {
        QString code;
        QDateTime started;
        qint64 id;
        QString tutorial;
        QStringList fields;
    };
    QList<Row> list;
    // one title per tutorial in the whole file: the caller's (the export's language), else
    // the one its newest attempt was recorded with
    QHash<QString, QString> title = titles;
    QHash<QString, QDateTime> titleFrom;
    if (!run(q, "SELECT a.id, o.code, o.name, a.tutorial, a.tutorial_title, a.started, a.duration_s, a.score,"
                " a.stars, a.passed, a.status, a.language FROM attempts a JOIN operators o ON o.id = a.operator_id"))
        return d->fail(error, what, q.lastError());
    while (q.next()) {
        const qint64 id = q.value(0).toLongLong();
        const QDateTime started = fromDb(q.value(5));
        const QString tutorial = q.value(3).toString();
        if (!titles.contains(tutorial) && (!titleFrom.contains(tutorial) || started > titleFrom.value(tutorial))) {
            title[tutorial] = q.value(4).toString();
            titleFrom[tutorial] = started;
        }
        // the status as the studio names it: an attempt aborted (stopped) is "stopped"
        const QString status = q.value(10).toString() == QLatin1String("aborted") ? QStringLiteral("stopped")
                                                                                   : q.value(10).toString();
        const QStringList fields = {QString::number(id),
                                    q.value(1).toString(),
                                    q.value(2).toString(),
                                    tutorial,
                                    QString(),  // the title, below
                                    toDb(started),
                                    number(q.value(6).toDouble()),
                                    number(q.value(7).toDouble()),
                                    QString::number(q.value(8).toInt()),
                                    q.value(9).toInt() != 0 ? QStringLiteral("1") : QStringLiteral("0"),
                                    status,
                                    q.value(11).toString(),
                                    breakdowns.value(id).join("; ")};
        list.append({q.value(1).toString(), started, id, tutorial, fields});
    }
    if (q.lastError().isValid()) return d->fail(error, what, q.lastError());
    std::sort(list.begin(), list.end(), [](const Row& a, const Row& b) {
        if (a.code != b.code) return a.code < b.code;
        if (a.started != b.started) return a.started < b.started;
        return a.id < b.id;
    });

    QByteArray text = "attempt,operator_code,operator_name,tutorial_id,tutorial_title,started_utc,duration_s,"
                      "score,stars,passed,status,language,breakdown\r\n";
    for (Row& r : list) {
        r.fields[4] = title.value(r.tutorial);
        QStringList quoted;
        for (const QString& f : r.fields) quoted << csvField(f);
        text += quoted.join(',').toUtf8() + "\r\n";
    }
    // durably (fsynced, then renamed over the old file), never over the records file itself
    solver::Text werr;
    if (!solver::writeWholeFile(QFile::encodeName(path).toStdString(), std::string_view(text.constData(), std::size_t(text.size())),
                                {QFile::encodeName(d->sqlitePath).toStdString()}, werr))
        return d->fail(error, what, translated(werr));
    if (rows) *rows = int(list.size());
    return true;
}

bool RecordsDb::findAttempt(const QString& uid, Attempt& out, QString* error) const
{
    const QString what = Tr::tr("cannot read the attempt");
    if (error) error->clear();
    if (!d->usable(false, what, error)) return false;
    if (uid.isEmpty()) return false;
    QList<Attempt> list;
    if (!d->loadAttempts("a.uid = ?", uid, true, list, what, error)) return false;
    if (list.isEmpty()) return false;
    out = list.first();
    return true;
}

// replication (SharedRecords) --------------------------------------------------------

bool RecordsDb::unsynced(QList<Unsynced>& attempts, QList<Operator>& operators, QString* error) const
{
    const QString what = Tr::tr("cannot read what the centre's server lacks");
    if (!d->usable(false, what, error)) return false;
    QSqlQuery q(d->db());
    // one index probe per attempt (MAX(seq) by attempt_events_by_seq): cheap when
    // nothing changed
    if (!run(q, "SELECT x.id, x.operator_id, x.uid, x.station, x.status, x.n, x.synced_events, x.synced_status,"
                " o.code, o.name, o.created"
                " FROM (SELECT a.id, a.operator_id, a.uid, a.station, a.status, s.events AS synced_events,"
                "  s.status AS synced_status,"
                "  (SELECT COALESCE(MAX(e.seq) + 1, 0) FROM attempt_events e WHERE e.attempt_id = a.id) AS n"
                "  FROM attempts a LEFT JOIN sync_state s ON s.attempt_id = a.id WHERE a.uid IS NOT NULL) x"
                " JOIN operators o ON o.id = x.operator_id"
                " WHERE x.synced_status IS NULL OR x.synced_status <> x.status OR x.synced_events < x.n"
                " ORDER BY x.id"))
        return d->fail(error, what, q.lastError());
    QList<Unsynced> list;
    while (q.next()) {
        Unsynced u;
        u.attemptId = q.value(0).toLongLong();
        u.op = {q.value(1).toLongLong(), q.value(8).toString(), q.value(9).toString(), fromDb(q.value(10))};
        u.uid = q.value(2).toString();
        u.station = q.value(3).toString();
        if (!statusFromName(q.value(4).toString(), u.status)) u.status = AttemptStatus::Interrupted;
        u.events = q.value(5).toInt();
        u.syncedEvents = q.value(6).isNull() ? 0 : q.value(6).toInt();
        u.syncedStatus = q.value(7).toString();
        list.append(u);
    }
    if (q.lastError().isValid()) return d->fail(error, what, q.lastError());
    q.finish();
    QList<Operator> ops;
    if (!run(q, "SELECT id, code, name, created FROM operators o"
                " WHERE NOT EXISTS (SELECT 1 FROM sync_operators s WHERE s.operator_id = o.id) ORDER BY id"))
        return d->fail(error, what, q.lastError());
    while (q.next())
        ops.append({q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(), fromDb(q.value(3))});
    if (q.lastError().isValid()) return d->fail(error, what, q.lastError());
    attempts = std::move(list);
    operators = std::move(ops);
    return true;
}

bool RecordsDb::noteSynced(qint64 attemptId, int events, AttemptStatus status, QString* error)
{
    const QString what = Tr::tr("cannot note what the centre's server has");
    if (!d->usable(true, what, error)) return false;
    QSqlQuery q(d->db());
    if (!run(q, "INSERT INTO sync_state (attempt_id, events, status) VALUES (?, ?, ?) ON CONFLICT (attempt_id)"
                " DO UPDATE SET events = excluded.events, status = excluded.status",
             {attemptId, events, statusName(status)}))
        return d->fail(error, what, q.lastError());
    return true;
}

bool RecordsDb::noteOperatorSynced(qint64 operatorId, QString* error)
{
    const QString what = Tr::tr("cannot note what the centre's server has");
    if (!d->usable(true, what, error)) return false;
    QSqlQuery q(d->db());
    if (!run(q, "INSERT INTO sync_operators (operator_id) VALUES (?) ON CONFLICT (operator_id) DO NOTHING",
             {operatorId}))
        return d->fail(error, what, q.lastError());
    return true;
}

bool RecordsDb::attemptHead(qint64 attemptId, Attempt& out, QString* error) const
{
    const QString what = Tr::tr("cannot read the attempt");
    if (!d->usable(false, what, error)) return false;
    QList<Attempt> list;
    if (!d->loadAttempts("a.id = ?", attemptId, false, list, what, error)) return false;
    if (list.isEmpty()) return d->fail(error, what, Tr::tr("there is no attempt %1").arg(attemptId));
    out = list.first();
    return true;
}

bool RecordsDb::giveUids(QString* error)
{
    const QString what = Tr::tr("cannot give the old attempts their unique ids");
    if (!d->usable(true, what, error)) return false;
    QSqlQuery q(d->db());  // before the transaction: it outlives it
    Transaction tx(d->db(), d->sqlite());
    if (!tx.begin()) return d->fail(error, what, tx.error());
    if (!run(q, "SELECT id FROM attempts WHERE uid IS NULL")) return d->fail(error, what, q.lastError());
    QList<qint64> ids;
    while (q.next()) ids << q.value(0).toLongLong();
    q.finish();
    for (qint64 id : ids)
        if (!run(q, "UPDATE attempts SET uid = ? WHERE id = ?", {QUuid::createUuid().toString(QUuid::WithoutBraces), id}))
            return d->fail(error, what, q.lastError());
    q.finish();
    return tx.commit() || d->fail(error, what, tx.error());
}

bool RecordsDb::eventsOf(qint64 attemptId, int fromSeq, int limit, QList<AttemptEvent>& out, QString* error) const
{
    const QString what = Tr::tr("cannot read the attempt's events");
    if (!d->usable(false, what, error)) return false;
    QSqlQuery q(d->db());
    if (!run(q, "SELECT t, kind, text, value, penalty, detail, seq FROM attempt_events"
                " WHERE attempt_id = ? AND seq >= ? ORDER BY seq LIMIT ?",
             {attemptId, fromSeq, limit}))
        return d->fail(error, what, q.lastError());
    QList<AttemptEvent> list;
    while (q.next()) {
        AttemptEvent e(q.value(0).toDouble(), q.value(1).toString(), q.value(2).toString(), doubleOrNaN(q.value(3)),
                       q.value(4).toDouble(), q.value(5).toString());
        e.seq = q.value(6).toInt();
        list.append(e);
    }
    if (q.lastError().isValid()) return d->fail(error, what, q.lastError());
    out = std::move(list);
    return true;
}

qint64 RecordsDb::ensureOperator(const Operator& op, QString* error)
{
    const QString c = op.code.trimmed();
    const QString what = Tr::tr("cannot add the operator “%1”").arg(c);
    if (!d->usable(true, what, error)) return 0;
    if (c.isEmpty()) return d->fail(error, what, Tr::tr("an operator needs an id")), 0;
    QSqlQuery q(d->db());
    // the name of an operator the database has already stays (a rename at the
    // trainer's desk is not undone by a station's older copy)
    if (!run(q, "INSERT INTO operators (code, name, created) VALUES (?, ?, ?) ON CONFLICT (code) DO NOTHING",
             {c, op.name.trimmed(), toDb(op.created.isValid() ? op.created : QDateTime::currentDateTimeUtc())}))
        return d->fail(error, what, q.lastError()), 0;
    q.finish();
    if (!run(q, "SELECT id FROM operators WHERE code = ?", {c}) || !q.next())
        return d->fail(error, what, q.lastError()), 0;
    return q.value(0).toLongLong();
}

bool RecordsDb::mergeAttempt(const Attempt& a, qint64 operatorId, const QList<AttemptEvent>& events, QString* error)
{
    const QString what = Tr::tr("cannot copy the attempt %1").arg(a.uid);
    if (!d->usable(true, what, error)) return false;
    if (a.uid.isEmpty()) return d->fail(error, what, Tr::tr("the attempt has no unique id"));
    const bool ended = a.status != AttemptStatus::Running;
    auto writeBreakdown = [&](QSqlQuery& q, qint64 id) {
        if (!run(q, "DELETE FROM attempt_scores WHERE attempt_id = ?", {id})) return false;
        if (!q.prepare("INSERT INTO attempt_scores (attempt_id, seq, key, label, value, points, max_points)"
                       " VALUES (?, ?, ?, ?, ?, ?, ?)"))
            return false;
        for (qsizetype i = 0; i < a.breakdown.size(); ++i) {
            const ScoreItem& s = a.breakdown[i];
            q.bindValue(0, id);
            q.bindValue(1, int(i));
            q.bindValue(2, s.key);
            q.bindValue(3, s.label);
            q.bindValue(4, s.value);
            q.bindValue(5, s.points);
            q.bindValue(6, s.maxPoints);
            if (!q.exec()) return false;
        }
        return true;
    };

    QSqlQuery q(d->db());  // before the transaction: it outlives it
    Transaction tx(d->db(), d->sqlite());
    if (!tx.begin()) return d->fail(error, what, tx.error());
    const QVariantList result = {a.durationS, a.score, a.stars, a.passed ? 1 : 0, statusName(a.status)};
    if (!run(q,
             "INSERT INTO attempts (operator_id, tutorial, tutorial_title, started, language, uid, station,"
             " duration_s, score, stars, passed, status) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"
             " ON CONFLICT (uid) DO NOTHING RETURNING id",
             QVariantList{operatorId, a.tutorialId, a.tutorialTitle, toDb(a.started), a.language, a.uid,
                          a.station.isNull() ? QString::fromLatin1("") : a.station} +
                 result))
        return d->fail(error, what, q.lastError());
    qint64 id = 0;
    if (q.next()) {  // new here
        id = q.value(0).toLongLong();
        q.finish();
        if (ended && !writeBreakdown(q, id)) return d->fail(error, what, q.lastError());
    } else {
        if (q.lastError().isValid()) return d->fail(error, what, q.lastError());
        q.finish();
        if (!run(q, "SELECT id, status FROM attempts WHERE uid = ?", {a.uid}) || !q.next())
            return d->fail(error, what, q.lastError());
        id = q.value(0).toLongLong();
        const QString there = q.value(1).toString();
        q.finish();
        // a result replaces "running", and a finished or aborted attempt "interrupted"
        // (it was wrongly marked); nothing undoes a result
        const bool update = ended && (there == QLatin1String("running") ||
                                      (there == QLatin1String("interrupted") && a.status != AttemptStatus::Interrupted));
        if (update) {
            if (!run(q, "UPDATE attempts SET duration_s = ?, score = ?, stars = ?, passed = ?, status = ? WHERE id = ?",
                     result + QVariantList{id}) ||
                !writeBreakdown(q, id))
                return d->fail(error, what, q.lastError());
        }
    }
    if (!events.isEmpty()) {
        if (!q.prepare("INSERT INTO attempt_events (attempt_id, seq, t, kind, text, value, penalty, detail)"
                       " VALUES (?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT (attempt_id, seq) DO NOTHING"))
            return d->fail(error, what, q.lastError());
        for (const AttemptEvent& e : events) {
            if (e.seq < 0) return d->fail(error, what, Tr::tr("an event has no index"));
            q.bindValue(0, id);
            q.bindValue(1, e.seq);
            q.bindValue(2, e.t);
            q.bindValue(3, e.kind);
            q.bindValue(4, e.text);
            q.bindValue(5, nullableDouble(e.value));
            q.bindValue(6, std::isfinite(e.penalty) ? e.penalty : 0.0);
            q.bindValue(7, e.detail.isNull() ? QString::fromLatin1("") : e.detail);
            if (!q.exec()) return d->fail(error, what, q.lastError());
        }
    }
    q.finish();
    return tx.commit() || d->fail(error, what, tx.error());
}

bool RecordsDb::check(QString* error) const
{
    const QString what = Tr::tr("cannot reach the records database");
    if (!d->usable(false, what, error)) return false;
    QSqlQuery q(d->db());
    if (!run(q, "SELECT 1") || !q.next()) return d->fail(error, what, q.lastError());
    return true;
}

}  // namespace trainer::records
