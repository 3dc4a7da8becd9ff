// Trainee records (trainer/records/records_db.h) on real SQLite files in temporary
// folders: round trip, progress, CSV, migrations, refusals that leave the file
// untouched (newer schema, not a database), a locked and a read-only database, a full
// disk (a small tmpfs in a private mount namespace, when we may mount one), and a
// process that dies during an attempt (this binary re-run as a child that calls
// std::abort()). The same round trip runs on a throwaway PostgreSQL server when the
// QPSQL driver and the server programs are installed; otherwise it is skipped, saying why.
#include "tests/common/as_user.h"
#include "tests/common/components.h"
#include "local_postgres.h"
#include "trainer/records/records_db.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <thread>

#include <pwd.h>
#include <sys/resource.h>
#include <unistd.h>

using namespace trainer::records;
using padrob_test::LocalPostgres;
using padrob_test::RawPostgres;

namespace {

constexpr const char* kCrashEnv = "PADROB_RECORDS_CRASH_DB";
constexpr const char* kFullEnv = "PADROB_RECORDS_FULL_DB";
const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string str(const QString& s)
{
    return s.toStdString();
}

QDateTime utc(int y, int mo, int d, int h, int mi, int s, int ms)
{
    return QDateTime(QDate(y, mo, d), QTime(h, mi, s, ms), Qt::UTC);
}

QByteArray bytesOf(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool sameEvent(const AttemptEvent& a, const AttemptEvent& b)
{
    const bool value = (std::isnan(a.value) && std::isnan(b.value)) || a.value == b.value;
    return a.t == b.t && a.kind == b.kind && a.text == b.text && value;
}

void expectEvents(const QList<AttemptEvent>& got, const QList<AttemptEvent>& want)
{
    ASSERT_EQ(got.size(), want.size());
    for (qsizetype i = 0; i < got.size(); ++i)
        EXPECT_TRUE(sameEvent(got[i], want[i])) << "event " << i << ": " << str(got[i].kind) << " " << str(got[i].text);
}

/// A plain QSQLITE connection of the test's own, to look at or tamper with a file.
class RawSqlite {
public:
    explicit RawSqlite(const QString& path)
    {
        static int n = 0;
        m_name = QStringLiteral("records-test-raw-%1").arg(++n);
        QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", m_name);
        db.setDatabaseName(path);
        db.setConnectOptions("QSQLITE_BUSY_TIMEOUT=0");
        m_ok = db.open();
    }
    ~RawSqlite()
    {
        {
            QSqlDatabase db = QSqlDatabase::database(m_name, false);
            db.close();
        }
        QSqlDatabase::removeDatabase(m_name);
    }
    bool ok() const { return m_ok; }
    bool exec(const QString& sql)
    {
        QSqlQuery q(QSqlDatabase::database(m_name, false));
        return q.exec(sql);
    }
    QVariant scalar(const QString& sql)
    {
        QSqlQuery q(QSqlDatabase::database(m_name, false));
        return q.exec(sql) && q.next() ? q.value(0) : QVariant();
    }

private:
    QString m_name;
    bool m_ok = false;
};

/// The sample records: Ana (two attempts at the basics: finished, then aborted), José
/// (one attempt at the grip, left running), Carla (none).
struct Sample {
    qint64 ana = 0, jose = 0, carla = 0;
    qint64 a1 = 0, a2 = 0, a3 = 0;
    QList<AttemptEvent> events1 = {{0.5, "step", "Levante la pluma", 1},
                                   {2.25, "collision", "garra, suelo", 0.73},
                                   {3.0, "hint", "Despacio \"por favor\"", kNaN}};
    QList<ScoreItem> breakdown1 = {
        {"time", "Tiempo", 95.5, 40, 50}, {"safety", "Seguridad", 1, -12.5, 0}, {"goals", "Objetivos", 4, 60, 60}};
};

/// Writes the sample through `db` and checks that it reads back exactly.
void writeAndReadBack(RecordsDb& db, Sample& s)
{
    QString error;
    s.ana = db.addOperator("  A-17 ", "Ana Pérez", &error);
    ASSERT_GT(s.ana, 0) << str(error);
    s.jose = db.addOperator("B-02", "José \"Pepe\" Núñez, jr.", &error);
    ASSERT_GT(s.jose, 0) << str(error);
    s.carla = db.addOperator("C-33", "Carla", &error);
    ASSERT_GT(s.carla, 0) << str(error);
    EXPECT_EQ(db.addOperator("A-17", "Someone else", &error), 0);
    EXPECT_TRUE(error.contains("taken already") && error.contains("Ana Pérez")) << str(error);
    EXPECT_EQ(db.addOperator("  ", "No id", &error), 0);
    EXPECT_TRUE(error.contains("needs an id")) << str(error);

    Operator op;
    ASSERT_TRUE(db.findOperator("A-17", op, &error)) << str(error);
    EXPECT_EQ(op.id, s.ana);
    EXPECT_EQ(op.code, "A-17");
    EXPECT_EQ(op.name, "Ana Pérez");
    EXPECT_TRUE(op.created.isValid());
    EXPECT_EQ(op.created.timeSpec(), Qt::UTC);
    EXPECT_LE(std::abs(op.created.secsTo(QDateTime::currentDateTimeUtc())), 60);
    EXPECT_FALSE(db.findOperator("Z-99", op, &error));
    EXPECT_TRUE(error.isEmpty()) << str(error);
    ASSERT_TRUE(db.renameOperator(s.carla, "Carla Ríos", &error)) << str(error);

    // attempt 1: finished, events in two batches
    s.a1 = db.beginAttempt({s.ana, "liner.basics", "Liner: basics", "es", utc(2025, 3, 1, 9, 30, 0, 250)}, &error);
    ASSERT_GT(s.a1, 0) << str(error);
    ASSERT_TRUE(db.appendEvents(s.a1, s.events1.mid(0, 2), &error)) << str(error);
    ASSERT_TRUE(db.appendEvents(s.a1, s.events1.mid(2), &error)) << str(error);
    ASSERT_TRUE(db.appendEvents(s.a1, {}, &error)) << str(error);
    ASSERT_TRUE(db.finishAttempt(s.a1, {AttemptStatus::Finished, 95.5, 87.5, 3, true, s.breakdown1}, &error))
        << str(error);
    // attempt 2: aborted, under a newer title
    s.a2 = db.beginAttempt({s.ana, "liner.basics", "Liner: the basics", "en", utc(2025, 3, 2, 14, 0, 5, 0)}, &error);
    ASSERT_GT(s.a2, 0) << str(error);
    const AttemptResult r2{AttemptStatus::Aborted, 12, 20, 0, false, {{"time", "Time", 12, 20, 0}}};
    ASSERT_TRUE(db.finishAttempt(s.a2, r2, &error)) << str(error);
    // attempt 3: left running
    s.a3 = db.beginAttempt({s.jose, "liner.grip", "Grip,\nthen lift", "en", utc(2025, 3, 1, 10, 0, 0, 1)}, &error);
    ASSERT_GT(s.a3, 0) << str(error);
    ASSERT_TRUE(db.appendEvents(s.a3, {{0.125, "step", "Abra la garra", 0}}, &error)) << str(error);

    QList<Attempt> list;
    ASSERT_TRUE(db.attemptsOf(s.ana, list, true, &error)) << str(error);
    ASSERT_EQ(list.size(), 2);
    EXPECT_EQ(list[0].id, s.a2);  // newest first
    EXPECT_EQ(list[1].id, s.a1);
    const Attempt& a1 = list[1];
    EXPECT_EQ(a1.operatorId, s.ana);
    EXPECT_EQ(a1.tutorialId, "liner.basics");
    EXPECT_EQ(a1.tutorialTitle, "Liner: basics");
    EXPECT_EQ(a1.started, utc(2025, 3, 1, 9, 30, 0, 250));
    EXPECT_EQ(a1.started.timeSpec(), Qt::UTC);
    EXPECT_EQ(a1.durationS, 95.5);
    EXPECT_EQ(a1.score, 87.5);
    EXPECT_EQ(a1.stars, 3);
    EXPECT_TRUE(a1.passed);
    EXPECT_EQ(a1.status, AttemptStatus::Finished);
    EXPECT_EQ(a1.language, "es");
    EXPECT_EQ(a1.breakdown, s.breakdown1);
    expectEvents(a1.events, s.events1);
    EXPECT_EQ(list[0].status, AttemptStatus::Aborted);
    EXPECT_EQ(list[0].tutorialTitle, "Liner: the basics");
    EXPECT_TRUE(list[0].events.isEmpty());

    ASSERT_TRUE(db.attemptsOf(s.ana, list, false, &error)) << str(error);
    EXPECT_TRUE(list[1].events.isEmpty());  // without events…
    EXPECT_EQ(list[1].breakdown, s.breakdown1);  // …but with the breakdown

    Attempt a3;
    ASSERT_TRUE(db.attempt(s.a3, a3, &error)) << str(error);
    EXPECT_EQ(a3.status, AttemptStatus::Running);
    EXPECT_EQ(a3.tutorialTitle, "Grip,\nthen lift");
    EXPECT_EQ(a3.score, 0);
    ASSERT_EQ(a3.events.size(), 1);
    EXPECT_EQ(a3.events[0].t, 0.125);
    EXPECT_FALSE(db.attempt(9999, a3, &error));
    EXPECT_TRUE(error.isEmpty()) << str(error);
    ASSERT_TRUE(db.attemptsOf(s.carla, list, true, &error)) << str(error);
    EXPECT_TRUE(list.isEmpty());
}

void expectProgress(RecordsDb& db, const Sample& s)
{
    QList<OperatorProgress> p;
    QString error;
    ASSERT_TRUE(db.progress(p, &error)) << str(error);
    ASSERT_EQ(p.size(), 3);
    EXPECT_EQ(p[0].op.code, "A-17");
    EXPECT_EQ(p[0].attempts, 2);
    EXPECT_EQ(p[0].tutorialsPassed, 1);
    EXPECT_EQ(p[0].lastAttempt, utc(2025, 3, 2, 14, 0, 5, 0));
    ASSERT_EQ(p[0].tutorials.size(), 1);
    const TutorialProgress& t = p[0].tutorials[0];
    EXPECT_EQ(t.tutorialId, "liner.basics");
    EXPECT_EQ(t.tutorialTitle, "Liner: the basics");  // the latest attempt's
    EXPECT_EQ(t.attempts, 2);
    EXPECT_EQ(t.bestScore, 87.5);  // better than the stopped attempt's 20; stopped, it cannot pass
    EXPECT_EQ(t.bestStars, 3);
    EXPECT_TRUE(t.passed);
    EXPECT_EQ(t.lastAttempt, utc(2025, 3, 2, 14, 0, 5, 0));

    EXPECT_EQ(p[1].op.id, s.jose);
    EXPECT_EQ(p[1].attempts, 1);
    EXPECT_EQ(p[1].tutorialsPassed, 0);
    ASSERT_EQ(p[1].tutorials.size(), 1);
    EXPECT_EQ(p[1].tutorials[0].bestScore, 0);
    EXPECT_FALSE(p[1].tutorials[0].passed);
    EXPECT_EQ(p[1].lastAttempt, utc(2025, 3, 1, 10, 0, 0, 1));

    EXPECT_EQ(p[2].op.name, "Carla Ríos");
    EXPECT_EQ(p[2].attempts, 0);
    EXPECT_FALSE(p[2].lastAttempt.isValid());
    EXPECT_TRUE(p[2].tutorials.isEmpty());
}

/// The sample as CSV, attempt 3 with `status3`.
/// The sample as CSV. Attempts 1 and 2 of liner.basics were recorded in Spanish and in
/// English with different titles: the file gives one, the newest attempt's, unless the
/// exporting program gives `basicsTitle`. Attempt 2, aborted, is "stopped".
QByteArray expectedCsv(const QString& status3, const QString& basicsTitle = QStringLiteral("Liner: the basics"))
{
    return QStringLiteral(
               "attempt,operator_code,operator_name,tutorial_id,tutorial_title,started_utc,duration_s,score,stars,"
               "passed,status,language,breakdown\r\n"
               "1,A-17,Ana Pérez,liner.basics,%2,2025-03-01T09:30:00.250Z,95.5,87.5,3,1,finished,es,"
               "time=40/50; safety=-12.5; goals=60/60\r\n"
               "2,A-17,Ana Pérez,liner.basics,%2,2025-03-02T14:00:05.000Z,12,20,0,0,stopped,en,"
               "time=20\r\n"
               "3,B-02,\"José \"\"Pepe\"\" Núñez, jr.\",liner.grip,\"Grip,\nthen lift\",2025-03-01T10:00:00.001Z,"
               "0,0,0,0,%1,en,\r\n")
        .arg(status3, basicsTitle)
        .toUtf8();
}

/// A fresh records file in `dir` holding the sample (attempt 3 left running, then
/// interrupted by close()).
QString sampleFile(const QTemporaryDir& dir, Sample& s)
{
    const QString path = dir.filePath("records.sqlite");
    RecordsDb db;
    QString error;
    EXPECT_TRUE(db.openSqlite(path, false, &error)) << str(error);
    writeAndReadBack(db, s);
    return path;
}

}  // namespace

// ---------------------------------------------------------------------------------------

TEST(Records, RoundTripOfOperatorsAttemptsBreakdownsAndEvents)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath("records.sqlite");
    Sample s;
    {
        RecordsDb db;
        QString error;
        ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
        EXPECT_TRUE(db.isOpen());
        EXPECT_FALSE(db.isPostgres());
        EXPECT_FALSE(db.isReadOnly());
        EXPECT_EQ(db.where(), QDir::toNativeSeparators(path));
        ASSERT_NO_FATAL_FAILURE(writeAndReadBack(db, s));
    }  // closed with attempt 3 running: recorded as interrupted

    RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
    EXPECT_EQ(db.interruptedAtOpen(), 0);  // close() did it
    Attempt a;
    ASSERT_TRUE(db.attempt(s.a3, a, &error)) << str(error);
    EXPECT_EQ(a.status, AttemptStatus::Interrupted);
    ASSERT_EQ(a.events.size(), 1);
    ASSERT_TRUE(db.attempt(s.a1, a, &error)) << str(error);
    EXPECT_EQ(a.breakdown, s.breakdown1);
    expectEvents(a.events, s.events1);
    // nothing left locked
    EXPECT_TRUE(QDir(path + "-running").entryList(QDir::Files).isEmpty());
}

TEST(Records, ProgressPerOperatorAndTutorial)
{
    QTemporaryDir dir;
    Sample s;
    RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(dir.filePath("r.sqlite"), false, &error)) << str(error);
    ASSERT_NO_FATAL_FAILURE(writeAndReadBack(db, s));
    expectProgress(db, s);
}

TEST(Records, TheBestScoreIsOfEveryAttemptWithAScoreAsTheRecordsListThem)
{
    // issue 25: two stopped attempts (38 and 50) listed with their scores while the
    // course said "best 0 of 100"
    QTemporaryDir dir;
    RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(dir.filePath("r.sqlite"), false, &error)) << str(error);
    const qint64 op = db.addOperator("guest", "Guest", &error);
    ASSERT_GT(op, 0) << str(error);
    for (const double score : {38.0, 50.0}) {
        const qint64 a = db.beginAttempt({op, "T0", "Reach", "en", QDateTime::currentDateTimeUtc()}, &error);
        ASSERT_GT(a, 0) << str(error);
        ASSERT_TRUE(db.finishAttempt(a, {AttemptStatus::Aborted, 10, score, 0, false, {}}, &error)) << str(error);
    }
    ASSERT_GT(db.beginAttempt({op, "T0", "Reach", "en", QDateTime::currentDateTimeUtc()}, &error), 0);  // running
    QList<Attempt> list;
    ASSERT_TRUE(db.attemptsOf(op, list, false, &error)) << str(error);
    double listed = 0;
    for (const Attempt& a : list)
        if (hasScore(a.status)) listed = std::max(listed, a.score);
    QList<OperatorProgress> p;
    ASSERT_TRUE(db.progress(p, &error)) << str(error);
    ASSERT_EQ(p.size(), 1);
    ASSERT_EQ(p[0].tutorials.size(), 1);
    EXPECT_EQ(p[0].tutorials[0].attempts, 3);
    EXPECT_EQ(p[0].tutorials[0].bestScore, 50.0);
    EXPECT_EQ(p[0].tutorials[0].bestScore, listed);
    EXPECT_FALSE(p[0].tutorials[0].passed);
}

TEST(Records, CsvExportIsRfc4180)
{
    QTemporaryDir dir;
    Sample s;
    RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(dir.filePath("r.sqlite"), false, &error)) << str(error);
    ASSERT_NO_FATAL_FAILURE(writeAndReadBack(db, s));
    const QString csv = dir.filePath("out/records.csv");
    EXPECT_FALSE(db.exportCsv(csv, &error));  // no such folder
    EXPECT_TRUE(error.contains("cannot export")) << str(error);
    ASSERT_TRUE(QDir().mkpath(dir.filePath("out")));
    int rows = -1;
    ASSERT_TRUE(db.exportCsv(csv, &error, {}, &rows)) << str(error);
    EXPECT_EQ(rows, 3);
    EXPECT_EQ(bytesOf(csv), expectedCsv("running"));
    EXPECT_EQ(QDir(dir.filePath("out")).entryList(QDir::Files), QStringList{"records.csv"});  // no temporary left
    // the exporting program's titles (its language) for the tutorials it knows
    ASSERT_TRUE(db.exportCsv(csv, &error, {{"liner.basics", "Coraza: lo básico"}}, &rows)) << str(error);
    EXPECT_EQ(bytesOf(csv), expectedCsv("running", "Coraza: lo básico"));
}

TEST(Records, MigratesANewOrEmptyFileAndReopensWithoutChange)
{
    QTemporaryDir dir;
    ASSERT_GE(RecordsDb::schemaVersion(), 1);
    const QString fresh = dir.filePath("sub/folder/records.sqlite");  // the folders are created
    const QString empty = dir.filePath("empty.sqlite");
    {
        QFile f(empty);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    }
    for (const QString& path : {fresh, empty}) {
        SCOPED_TRACE(str(path));
        QString error;
        {
            RecordsDb db;
            ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
            ASSERT_GT(db.addOperator("X1", "Xavier", &error), 0) << str(error);
        }
        auto check = [&] {
            RawSqlite raw(path);
            ASSERT_TRUE(raw.ok());
            EXPECT_EQ(raw.scalar("SELECT COUNT(*) FROM records_schema").toInt(), RecordsDb::schemaVersion());
            EXPECT_EQ(raw.scalar("SELECT MIN(version) FROM records_schema").toInt(), 1);
            EXPECT_EQ(raw.scalar("SELECT MAX(version) FROM records_schema").toInt(), RecordsDb::schemaVersion());
            EXPECT_EQ(raw.scalar("PRAGMA journal_mode").toString(), "wal");
            EXPECT_EQ(raw.scalar("SELECT COUNT(*) FROM operators").toInt(), 1);
            for (const char* index : {"attempts_by_operator", "attempts_running", "attempt_events_by_attempt"})
                EXPECT_EQ(raw.scalar(QStringLiteral("SELECT COUNT(*) FROM sqlite_master WHERE type = 'index' AND "
                                                    "name = '%1'")
                                         .arg(index))
                              .toInt(),
                          1)
                    << index;
        };
        check();
        RecordsDb db;  // re-open: nothing to migrate, the data is there
        ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
        Operator op;
        EXPECT_TRUE(db.findOperator("X1", op, &error)) << str(error);
        db.close();
        check();
    }
}

TEST(Records, NewerSchemaIsRefusedAndTheFileLeftUntouched)
{
    QTemporaryDir dir;
    const QString path = dir.filePath("records.sqlite");
    {
        RecordsDb db;
        ASSERT_TRUE(db.openSqlite(path));
        ASSERT_GT(db.addOperator("1", "One"), 0);
    }
    const int newer = RecordsDb::schemaVersion() + 1;
    {
        RawSqlite raw(path);
        ASSERT_TRUE(raw.exec(QStringLiteral("INSERT INTO records_schema VALUES (%1, '2031-01-01T00:00:00.000Z', "
                                            "'from the future')")
                                 .arg(newer)));
    }
    const QByteArray before = bytesOf(path);
    ASSERT_FALSE(before.isEmpty());
    ASSERT_FALSE(QFileInfo::exists(path + "-wal"));
    for (bool readOnly : {false, true}) {
        RecordsDb db;
        QString error;
        EXPECT_FALSE(db.openSqlite(path, readOnly, &error));
        EXPECT_FALSE(db.isOpen());
        EXPECT_TRUE(error.contains(QStringLiteral("schema version %1").arg(newer))) << str(error);
        EXPECT_TRUE(error.contains(QStringLiteral("(%1)").arg(RecordsDb::schemaVersion()))) << str(error);
        EXPECT_TRUE(error.contains("newer")) << str(error);
        EXPECT_TRUE(error.contains("untouched")) << str(error);
    }
    EXPECT_EQ(bytesOf(path), before);
}

TEST(Records, LockedDatabaseGivesAClearMessageWithinTheTimeout)
{
    QTemporaryDir dir;
    const QString path = dir.filePath("records.sqlite");
    RecordsDb db;  // opened before the other program locks the file
    QString error;
    ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
    const qint64 op = db.addOperator("L", "Locked");
    ASSERT_GT(op, 0);

    RawSqlite other(path);
    ASSERT_TRUE(other.exec("BEGIN EXCLUSIVE"));
    ASSERT_TRUE(other.exec("INSERT INTO operators (code, name, created) VALUES ('O', 'Other', 'x')"));

    QElapsedTimer timer;
    timer.start();
    EXPECT_EQ(db.beginAttempt({op, "t", "T", "en", {}}, &error), 0);
    const qint64 waited = timer.elapsed();
    EXPECT_TRUE(error.contains("in use by another program")) << str(error);
    EXPECT_TRUE(error.contains("2 s")) << str(error);
    EXPECT_GE(waited, 1500);  // the default busy timeout is 2 s
    EXPECT_LT(waited, 6000);
    // still usable for reads (WAL: the other program's writer does not block them)
    QList<OperatorProgress> p;
    EXPECT_TRUE(db.progress(p, &error)) << str(error);
    EXPECT_EQ(p.size(), 1);

    // opening while it is locked: refused after the (here shorter) timeout
    RecordsLocation where;
    where.sqlitePath = path;
    where.busyTimeoutMs = 300;
    RecordsDb late;
    timer.restart();
    EXPECT_FALSE(late.open(where, &error));
    EXPECT_TRUE(error.contains("in use by another program")) << str(error);
    EXPECT_LT(timer.elapsed(), 3000);

    ASSERT_TRUE(other.exec("ROLLBACK"));
    EXPECT_GT(db.beginAttempt({op, "t", "T", "en", {}}, &error), 0) << str(error);  // and works again
    EXPECT_TRUE(late.open(where, &error)) << str(error);
}

TEST(Records, ReadOnlyFileIsRefusedWithAClearMessage)
{
    if (geteuid() == 0) {
        // root writes whatever the modes say: the test runs as an ordinary user
        const padrob_test::UserRun r = padrob_test::runAsUser({"--gtest_filter=Records.ReadOnlyFileIsRefusedWithAClearMessage"});
        ASSERT_TRUE(r.ran) << str(r.output);
        EXPECT_EQ(r.exitCode, 0) << str(r.output);
        EXPECT_TRUE(r.output.contains("[  PASSED  ] 1 test")) << str(r.output);
        return;
    }
    QTemporaryDir dir;
    Sample s;
    const QString path = sampleFile(dir, s);
    const QString folder = dir.filePath("ro");
    ASSERT_TRUE(QDir().mkpath(folder));
    const QString ro = folder + "/records.sqlite";
    ASSERT_TRUE(QFile::rename(path, ro));
    // the file read-only (and, at first, its folder)
    const auto r = QFileDevice::ReadOwner | QFileDevice::ReadGroup | QFileDevice::ReadOther;
    const auto rx = r | QFileDevice::ExeOwner | QFileDevice::ExeGroup | QFileDevice::ExeOther;
    ASSERT_TRUE(QFile::setPermissions(ro, r));
    struct Restore {
        QString folder, file;
        ~Restore()
        {
            QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
            QFile::setPermissions(file, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        }
    } restore{folder, ro};
    {
        QFile probe(ro);
        ASSERT_FALSE(probe.open(QIODevice::ReadWrite)) << "the read-only file can be written: chmod had no effect";
    }
    const QByteArray before = bytesOf(ro);
    RecordsDb db;
    QString error;
    QList<OperatorProgress> p;
    // file and folder read-only
    ASSERT_TRUE(QFile::setPermissions(folder, rx));
    EXPECT_FALSE(db.openSqlite(ro, false, &error));
    EXPECT_TRUE(error.contains("read-only")) << str(error);
    // a WAL database in a read-only folder, without its -shm file: read as immutable
    ASSERT_FALSE(QFileInfo::exists(ro + "-shm"));
    ASSERT_TRUE(db.openSqlite(ro, true, &error)) << str(error);
    EXPECT_TRUE(db.progress(p, &error)) << str(error);
    EXPECT_EQ(p.size(), 3);
    db.close();
    // the file only
    ASSERT_TRUE(QFile::setPermissions(folder, rx | QFileDevice::WriteOwner));
    EXPECT_FALSE(db.openSqlite(ro, false, &error));
    EXPECT_TRUE(error.contains("the file is read-only")) << str(error);
    ASSERT_TRUE(db.openSqlite(ro, true, &error)) << str(error);
    EXPECT_TRUE(db.progress(p, &error)) << str(error);
    EXPECT_EQ(p.size(), 3);
    db.close();
    EXPECT_EQ(bytesOf(ro), before);
}

TEST(Records, ReadOnlyOpenReadsButNeverWrites)
{
    QTemporaryDir dir;
    Sample s;
    const QString path = sampleFile(dir, s);
    const QByteArray before = bytesOf(path);
    RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(path, true, &error)) << str(error);
    EXPECT_TRUE(db.isReadOnly());
    expectProgress(db, s);
    EXPECT_EQ(db.addOperator("N", "New", &error), 0);
    EXPECT_TRUE(error.contains("open read-only")) << str(error);
    EXPECT_EQ(db.beginAttempt({s.ana, "t", "T", "en", {}}, &error), 0);
    EXPECT_TRUE(error.contains("open read-only")) << str(error);
    EXPECT_FALSE(db.finishAttempt(s.a3, {}, &error));
    EXPECT_TRUE(error.contains("open read-only")) << str(error);
    db.close();
    EXPECT_EQ(bytesOf(path), before);

    EXPECT_FALSE(db.openSqlite(dir.filePath("missing.sqlite"), true, &error));
    EXPECT_TRUE(error.contains("no such file")) << str(error);
    EXPECT_FALSE(QFileInfo::exists(dir.filePath("missing.sqlite")));
}

TEST(Records, CorruptOrForeignFilesAreRefusedUntouched)
{
    QTemporaryDir dir;
    auto write = [&](const QString& name, const QByteArray& data) {
        const QString path = dir.filePath(name);
        QFile f(path);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(data);
        return path;
    };
    QByteArray noise(64 * 1024, '\0');
    QRandomGenerator rng(42);
    for (char& c : noise) c = char(rng.bounded(256));
    QByteArray damaged = noise;
    damaged.replace(0, 16, QByteArray("SQLite format 3\0", 16));
    const QString random = write("random.sqlite", noise);
    const QString headed = write("damaged.sqlite", damaged);
    const QString folder = dir.filePath("a-folder.sqlite");
    ASSERT_TRUE(QDir().mkpath(folder));
    const QString foreign = dir.filePath("foreign.sqlite");
    {
        RawSqlite raw(foreign);
        ASSERT_TRUE(raw.exec("CREATE TABLE recipes (name TEXT)"));
    }

    struct Case {
        QString path;
        QString says;
    };
    for (const Case& c : {Case{random, "not a records database"}, Case{headed, "records database"},
                          Case{foreign, "not Padrob's records"}, Case{folder, "folder"}}) {
        SCOPED_TRACE(str(c.path));
        const QByteArray before = bytesOf(c.path);
        for (bool readOnly : {false, true}) {
            RecordsDb db;
            QString error;
            EXPECT_FALSE(db.openSqlite(c.path, readOnly, &error));
            EXPECT_TRUE(error.contains(c.says)) << str(error);
            EXPECT_TRUE(error.contains(QDir::toNativeSeparators(c.path))) << str(error);
        }
        EXPECT_EQ(bytesOf(c.path), before);
    }
}

TEST(Records, MisuseIsRefusedNotACrash)
{
    QTemporaryDir dir;
    RecordsDb db;
    QString error;
    QList<OperatorProgress> p;
    EXPECT_FALSE(db.progress(p, &error));
    EXPECT_TRUE(error.contains("not open")) << str(error);
    EXPECT_EQ(db.addOperator("x", "y", &error), 0);
    EXPECT_TRUE(error.contains("not open")) << str(error);

    ASSERT_TRUE(db.openSqlite(dir.filePath("r.sqlite"), false, &error)) << str(error);
    const qint64 op = db.addOperator("M", "Misuse");
    EXPECT_EQ(db.beginAttempt({op + 100, "t", "T", "en", {}}, &error), 0);
    EXPECT_TRUE(error.contains("no operator")) << str(error);
    EXPECT_EQ(db.beginAttempt({op, "", "T", "en", {}}, &error), 0);
    EXPECT_TRUE(error.contains("no id")) << str(error);
    const qint64 a = db.beginAttempt({op, "t", "T", "en", {}}, &error);
    ASSERT_GT(a, 0) << str(error);
    EXPECT_FALSE(db.appendEvents(a + 100, {{1, "k", "t", 0}}, &error));
    EXPECT_TRUE(error.contains("no attempt")) << str(error);
    EXPECT_FALSE(db.appendEvents(a, {{kNaN, "k", "t", 0}}, &error));
    EXPECT_FALSE(db.finishAttempt(a, {AttemptStatus::Finished, 1, 101, 1, true, {}}, &error));
    EXPECT_TRUE(error.contains("101")) << str(error);
    EXPECT_FALSE(db.finishAttempt(a, {AttemptStatus::Finished, 1, 50, 4, true, {}}, &error));
    EXPECT_FALSE(db.finishAttempt(a, {AttemptStatus::Running, 1, 50, 1, true, {}}, &error));
    EXPECT_FALSE(db.finishAttempt(a, {AttemptStatus::Finished, -1, 50, 1, true, {}}, &error));
    const QList<ScoreItem> twice = {{"k", "K", 1, 1, 0}, {"k", "K", 2, 2, 0}};
    EXPECT_FALSE(db.finishAttempt(a, {AttemptStatus::Finished, 1, 50, 1, true, twice}, &error));
    EXPECT_TRUE(error.contains("repeated")) << str(error);
    EXPECT_FALSE(db.finishAttempt(a + 100, {AttemptStatus::Finished, 1, 50, 1, true, {}}, &error));
    EXPECT_TRUE(error.contains("no attempt")) << str(error);
    // none of it half-written: the attempt is as it was
    Attempt got;
    ASSERT_TRUE(db.attempt(a, got, &error)) << str(error);
    EXPECT_EQ(got.status, AttemptStatus::Running);
    EXPECT_TRUE(got.events.isEmpty());
    EXPECT_TRUE(got.breakdown.isEmpty());
    // a finished attempt can be scored again (the breakdown is replaced, not appended)
    ASSERT_TRUE(db.finishAttempt(a, {AttemptStatus::Finished, 1, 50, 1, true, {{"k", "K", 1, 1, 0}}}, &error));
    ASSERT_TRUE(db.finishAttempt(a, {AttemptStatus::Finished, 1, 60, 2, true, {{"j", "J", 2, 2, 2}}}, &error));
    ASSERT_TRUE(db.attempt(a, got, &error)) << str(error);
    EXPECT_EQ(got.score, 60);
    EXPECT_EQ(got.breakdown, (QList<ScoreItem>{{"j", "J", 2, 2, 2}}));

    // used from another thread: refused
    std::thread([&] {
        QString e;
        EXPECT_FALSE(db.progress(p, &e));
        EXPECT_TRUE(e.contains("another thread")) << str(e);
    }).join();
}

TEST(Records, OneConnectionPerThreadAndLiveAttemptsAreNotInterrupted)
{
    QTemporaryDir dir;
    const QString path = dir.filePath("records.sqlite");
    RecordsDb recorder;
    QString error;
    ASSERT_TRUE(recorder.openSqlite(path, false, &error)) << str(error);
    const qint64 op = recorder.addOperator("T", "Threads");
    const qint64 live = recorder.beginAttempt({op, "live", "Live", "en", {}}, &error);
    ASSERT_GT(live, 0) << str(error);

    // a trainer's view in another thread opens the same file meanwhile
    std::thread([&] {
        RecordsDb view;
        QString e;
        ASSERT_TRUE(view.openSqlite(path, false, &e)) << str(e);
        EXPECT_EQ(view.interruptedAtOpen(), 0);
        Attempt a;
        ASSERT_TRUE(view.attempt(live, a, &e)) << str(e);
        EXPECT_EQ(a.status, AttemptStatus::Running);
        // and records an attempt of its own
        const qint64 mine = view.beginAttempt({op, "other", "Other", "en", {}}, &e);
        ASSERT_GT(mine, 0) << str(e);
        EXPECT_TRUE(view.finishAttempt(mine, {AttemptStatus::Finished, 3, 70, 2, true, {}}, &e)) << str(e);
    }).join();

    ASSERT_TRUE(recorder.appendEvents(live, {{1, "step", "still here", 1}}, &error)) << str(error);
    ASSERT_TRUE(recorder.finishAttempt(live, {AttemptStatus::Finished, 5, 90, 3, true, {}}, &error)) << str(error);
    QList<Attempt> list;
    ASSERT_TRUE(recorder.attemptsOf(op, list, true, &error)) << str(error);
    ASSERT_EQ(list.size(), 2);
    for (const Attempt& a : list) EXPECT_EQ(a.status, AttemptStatus::Finished);
}

// the crash: the child (this binary, filtered to RecordsChild.*) dies mid-attempt

TEST(RecordsChild, BeginsAnAttemptAndDies)
{
    const QString path = qEnvironmentVariable(kCrashEnv);
    if (path.isEmpty())
        GTEST_SKIP() << "a child process of Records.CrashDuringAnAttempt…; runs only with " << kCrashEnv << " set";
    RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
    Operator op;
    ASSERT_TRUE(db.findOperator("7", op, &error)) << str(error);
    const qint64 id = db.beginAttempt({op.id, "crash", "Crash", "en", {}}, &error);
    ASSERT_GT(id, 0) << str(error);
    int committed = 0;
    for (int batch = 0; batch < 5; ++batch) {
        QList<AttemptEvent> events;
        for (int i = 0; i < 10; ++i)
            events.append({committed + i * 0.01, "tick", QString::number(committed + i), 1.0 * i});
        ASSERT_TRUE(db.appendEvents(id, events, &error)) << str(error);
        committed += 10;
    }
    std::printf("attempt %lld committed %d\n", static_cast<long long>(id), committed);
    std::fflush(stdout);

    // die while another connection (another thread) writes a big batch to the attempt
    std::atomic<bool> writing{false};
    std::thread([&] {
        RecordsDb other;
        QString e;
        if (!other.openSqlite(path, false, &e)) return;
        QList<AttemptEvent> many;
        for (int i = 0; i < 20000; ++i) many.append({100.0 + i, "bulk", "b", 0});
        writing = true;
        other.appendEvents(id, many, &e);
    }).detach();
    while (!writing) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const rlimit noCore{0, 0};
    setrlimit(RLIMIT_CORE, &noCore);
    std::abort();
}

TEST(Records, CrashDuringAnAttemptLeavesItInterruptedWithItsCommittedEvents)
{
    QTemporaryDir dir;
    const QString path = dir.filePath("records.sqlite");
    qint64 done = 0;
    {
        RecordsDb db;
        QString error;
        ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
        const qint64 op = db.addOperator("7", "Crash test");
        done = db.beginAttempt({op, "before", "Before", "en", {}}, &error);
        const AttemptResult r{AttemptStatus::Finished, 2, 75, 2, true, {{"k", "K", 1, 75, 100}}};
        ASSERT_TRUE(db.finishAttempt(done, r, &error)) << str(error);
    }

    QProcess child;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(kCrashEnv, path);
    child.setProcessEnvironment(env);
    child.start(QCoreApplication::applicationFilePath(), {"--gtest_filter=RecordsChild.BeginsAnAttemptAndDies"});
    ASSERT_TRUE(child.waitForFinished(60000));
    const QString out = QString::fromLocal8Bit(child.readAllStandardOutput() + child.readAllStandardError());
    ASSERT_EQ(child.exitStatus(), QProcess::CrashExit) << str(out);
    const QRegularExpressionMatch m = QRegularExpression("attempt (\\d+) committed (\\d+)").match(out);
    ASSERT_TRUE(m.hasMatch()) << str(out);
    const qint64 id = m.captured(1).toLongLong();
    const int committed = m.captured(2).toInt();
    EXPECT_TRUE(QFileInfo::exists(path + "-running/attempt-" + m.captured(1) + ".lock"));  // the dead owner's

    RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
    EXPECT_EQ(db.interruptedAtOpen(), 1);
    Attempt a;
    ASSERT_TRUE(db.attempt(id, a, &error)) << str(error);
    EXPECT_EQ(a.status, AttemptStatus::Interrupted);
    // every committed event, and the big batch entirely or not at all
    ASSERT_TRUE(a.events.size() == committed || a.events.size() == committed + 20000) << a.events.size();
    for (int i = 0; i < committed; ++i) EXPECT_EQ(a.events[i].text, QString::number(i));
    ASSERT_TRUE(db.attempt(done, a, &error)) << str(error);
    EXPECT_EQ(a.status, AttemptStatus::Finished);
    EXPECT_EQ(a.breakdown.size(), 1);
    EXPECT_FALSE(QFileInfo::exists(path + "-running/attempt-" + m.captured(1) + ".lock"));
    db.close();
    ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
    EXPECT_EQ(db.interruptedAtOpen(), 0);
}

// the full disk: the child (this binary) runs in a private mount namespace on a small tmpfs

TEST(RecordsChild, FillsTheDiskUntilFull)
{
    const QString folder = qEnvironmentVariable(kFullEnv);
    if (folder.isEmpty())
        GTEST_SKIP() << "a child process of Records.DiskFull…; runs only with " << kFullEnv << " set";
    const QString path = folder + "/records.sqlite";
    RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
    const qint64 op = db.addOperator("F", "Full");
    const qint64 id = db.beginAttempt({op, "full", "Full", "en", {}}, &error);
    ASSERT_GT(id, 0) << str(error);
    const QList<AttemptEvent> batch(50, AttemptEvent{1.0, "note", QString(1000, 'x'), 1.0});
    qsizetype committed = 0;
    for (int i = 0; i < 1000 && db.appendEvents(id, batch, &error); ++i) committed += batch.size();
    ASSERT_FALSE(error.isEmpty()) << "the disk never filled up";
    EXPECT_TRUE(error.contains("is full")) << str(error);
    EXPECT_TRUE(error.contains("cannot record the attempt's events")) << str(error);
    EXPECT_GT(committed, 0);
    // reads still work, and the failed batch left nothing behind
    Attempt a;
    ASSERT_TRUE(db.attempt(id, a, &error)) << str(error);
    EXPECT_EQ(a.events.size(), committed);
    QList<OperatorProgress> p;
    EXPECT_TRUE(db.progress(p, &error)) << str(error);
    std::printf("full after %lld events: %s\n", static_cast<long long>(committed), qPrintable(error));
}

TEST(Records, DiskFullIsReportedAndReadsStillWork)
{
    QTemporaryDir dir;
    const QString small = dir.filePath("small");
    ASSERT_TRUE(QDir().mkpath(small));
    // the child gets the folder; its records file is records.sqlite there
    const padrob_test::TmpfsRun r =
        padrob_test::runOnSmallTmpfs(small, "384k", kFullEnv, "RecordsChild.FillsTheDiskUntilFull");
    if (!r.mounted) PADROB_NEEDS_COMPONENT(str(r.output));
    EXPECT_TRUE(r.passed) << str(r.output);
}

// PostgreSQL ------------------------------------------------------------------------------

TEST(RecordsPostgres, SameRoundTripOnAThrowawayServer)
{
    QElapsedTimer timer;
    timer.start();
    LocalPostgres server;
    QString why;
    if (!server.start(why)) PADROB_NEEDS_COMPONENT("no PostgreSQL server for the test: " << str(why));
    const PostgresConfig config = server.config();

    Sample s;
    QString error;
    {
        RecordsDb db;
        ASSERT_TRUE(db.openPostgres(config, &error)) << str(error);
        EXPECT_TRUE(db.isPostgres());
        EXPECT_EQ(db.where(), "padrob@" + config.host + ":5432/postgres");
        ASSERT_NO_FATAL_FAILURE(writeAndReadBack(db, s));
        expectProgress(db, s);
        QTemporaryDir dir;
        ASSERT_TRUE(db.exportCsv(dir.filePath("pg.csv"), &error)) << str(error);
        EXPECT_EQ(bytesOf(dir.filePath("pg.csv")), expectedCsv("running"));  // the same bytes as SQLite's

        // a second connection meanwhile: the live attempt stays running
        RecordsDb view;
        ASSERT_TRUE(view.openPostgres(config, &error)) << str(error);
        EXPECT_EQ(view.interruptedAtOpen(), 0);
    }  // attempt 3 interrupted by close()

    // the schema and a re-open
    {
        RawPostgres raw(config);
        ASSERT_TRUE(raw.ok());
        EXPECT_EQ(raw.scalar("SELECT MAX(version) FROM records_schema").toInt(), RecordsDb::schemaVersion());
        EXPECT_EQ(raw.scalar("SELECT status FROM attempts WHERE id = 3").toString(), "interrupted");
    }

    // a recorder whose session dies (as a crashed station's would) loses its attempt
    RecordsDb recorder;
    ASSERT_TRUE(recorder.openPostgres(config, &error)) << str(error);
    const qint64 live = recorder.beginAttempt({s.carla, "pg", "PG", "en", {}}, &error);
    ASSERT_GT(live, 0) << str(error);
    ASSERT_TRUE(recorder.appendEvents(live, {{1, "step", "one", 1}, {2, "step", "two", 2}}, &error)) << str(error);
    {
        RecordsDb view;
        ASSERT_TRUE(view.openPostgres(config, &error)) << str(error);
        EXPECT_EQ(view.interruptedAtOpen(), 0);  // its recorder is alive
    }
    {
        RawPostgres raw(config);
        ASSERT_TRUE(raw.ok());
        raw.scalar("SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE application_name = 'padrob'");
    }
    EXPECT_FALSE(recorder.appendEvents(live, {{3, "step", "three", 3}}, &error));  // a message, no crash
    EXPECT_FALSE(error.isEmpty());
    recorder.close();
    {
        RecordsDb view;
        ASSERT_TRUE(view.openPostgres(config, &error)) << str(error);
        EXPECT_EQ(view.interruptedAtOpen(), 1);
        Attempt a;
        ASSERT_TRUE(view.attempt(live, a, &error)) << str(error);
        EXPECT_EQ(a.status, AttemptStatus::Interrupted);
        EXPECT_EQ(a.events.size(), 2);
    }

    // a wrong database: a clear message, never the password
    PostgresConfig wrong = config;
    wrong.database = "no_such_records";
    RecordsDb db;
    EXPECT_FALSE(db.openPostgres(wrong, &error));
    EXPECT_TRUE(error.contains("no_such_records")) << str(error);
    EXPECT_FALSE(error.contains(config.password)) << str(error);
    server.stop();
    EXPECT_LT(timer.elapsed(), 15000) << "the PostgreSQL test should take under 15 s";
}

TEST(RecordsPostgres, UnreachableServerOrMissingDriverGivesAClearMessage)
{
    QTemporaryDir dir;  // a socket folder with no server in it
    PostgresConfig c;
    c.host = dir.path();
    c.database = "records";
    c.user = "trainer";
    c.password = "Sup3r-Secret!";
    RecordsDb db;
    QString error;
    EXPECT_FALSE(db.openPostgres(c, &error));
    EXPECT_FALSE(db.isOpen());
    EXPECT_FALSE(error.contains(c.password)) << str(error);
    EXPECT_TRUE(error.contains("trainer@" + dir.path())) << str(error);
    if (QSqlDatabase::isDriverAvailable("QPSQL"))
        EXPECT_TRUE(error.contains("did not accept the connection")) << str(error);
    else
        EXPECT_TRUE(error.contains("libqt6sql6-psql")) << str(error);
}
