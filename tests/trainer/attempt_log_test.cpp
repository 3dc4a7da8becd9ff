// Recording tutorial attempts in the trainee records: a real SQLite file; a database
// that refuses (opened read-only, locked by another program for a whole attempt) loses
// nothing, nor does a kill in the middle: the attempt is in a pending file from its start,
// imported later with its operator's code; a bad pending file is moved aside, never
// blocking the others; a full disk is said, never an empty file taken for a record.

#include "tests/common/as_user.h"
#include "tests/common/components.h"
#include "trainer/training/attempt_log.h"
#include "trainer/training/runner.h"

#include <QCoreApplication>
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>

#include <sys/resource.h>

using namespace trainer;

namespace {

struct CarelessRun {
    std::shared_ptr<const Tutorial> tutorial;
    RunOutput out;
};

CarelessRun careless()
{
    // T0 with its extension slammed into the end stop: a limit bang (a penalty) and time up
    CarelessRun r;
    solver::Diagnostics d;
    r.tutorial = loadTutorial(std::string(PADROB_SOURCE_DIR) + "/resources/tutorials/t0_reach.tut", d);
    StationProfile profile;
    QString error;
    EXPECT_TRUE(tutorialProfile(*r.tutorial, {}, profile, &error));
    std::vector<AutopilotWaypoint> path;
    EXPECT_TRUE(parseAutopilotPath("3=1.2\n", path, &error));
    QTemporaryDir dir;
    EXPECT_TRUE(recordWithAutopilot(r.tutorial, path, profile, dir.filePath("x.log"), r.out, &error));
    return r;
}

std::shared_ptr<const Tutorial> t0()
{
    solver::Diagnostics d;
    return loadTutorial(std::string(PADROB_SOURCE_DIR) + "/resources/tutorials/t0_reach.tut", d);
}

std::vector<TutorialEvent> goals(int n)
{
    std::vector<TutorialEvent> events(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        events[std::size_t(i)].kind = TutorialEvent::Kind::GoalDone;
        events[std::size_t(i)].t = i;
        events[std::size_t(i)].detail = "g" + std::to_string(i);
    }
    return events;
}

std::string str(const QString& s) { return s.toStdString(); }

/// Another program's connection that holds the database locked while it lives.
class Locker {
public:
    explicit Locker(const QString& file)
    {
        QSqlDatabase db = QSqlDatabase::addDatabase("QSQLITE", "attempt-log-test-locker");
        db.setDatabaseName(file);
        m_ok = db.open() && QSqlQuery(db).exec("BEGIN EXCLUSIVE");
    }
    ~Locker()
    {
        {
            QSqlDatabase db = QSqlDatabase::database("attempt-log-test-locker", false);
            QSqlQuery(db).exec("ROLLBACK");
            db.close();
        }
        QSqlDatabase::removeDatabase("attempt-log-test-locker");
    }
    bool ok() const { return m_ok; }

private:
    bool m_ok = false;
};

constexpr const char* kDieEnv = "PADROB_ATTEMPT_LOG_CHILD_DIES";
constexpr const char* kFullEnv = "PADROB_ATTEMPT_LOG_CHILD_FULL";

}  // namespace

TEST(AttemptLog, AnAttemptIsRecordedAsItGoesWithItsEventsAndBreakdown)
{
    const CarelessRun run = careless();
    ASSERT_TRUE(run.tutorial);
    const std::vector<TutorialEvent>& events = run.out.result.events;
    ASSERT_GE(events.size(), 2u);
    QTemporaryDir dir;
    records::RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(dir.filePath("records.sqlite"), false, &error)) << error.toStdString();
    const qint64 op = db.addOperator("OP-7", "Ana Pérez", &error);
    ASSERT_GT(op, 0) << error.toStdString();
    AttemptLog log(&db, dir.filePath("pending"), "OP-7", "Ana Pérez", *run.tutorial, "es");
    ASSERT_GT(log.attemptId(), 0) << log.problem().toStdString();
    // mid-attempt: the first event is already in the database (a crash would keep it)
    log.update({events.begin(), events.begin() + 1});
    records::Attempt stored;
    ASSERT_TRUE(db.attempt(log.attemptId(), stored, &error));
    EXPECT_EQ(stored.status, records::AttemptStatus::Running);
    ASSERT_EQ(stored.events.size(), 1);
    EXPECT_EQ(stored.events[0].kind, "limit-bang");
    EXPECT_DOUBLE_EQ(stored.events[0].penalty, 2.0);
    EXPECT_EQ(stored.events[0].detail.toStdString(), events[0].detail);
    ASSERT_TRUE(log.finish(events, run.out.result, false)) << log.problem().toStdString();
    ASSERT_TRUE(db.attempt(log.attemptId(), stored, &error));
    EXPECT_EQ(stored.status, records::AttemptStatus::Finished);
    EXPECT_EQ(stored.tutorialId, "T0");
    EXPECT_EQ(stored.tutorialTitle, "Alcanzar un objetivo");
    EXPECT_EQ(stored.events.size(), qsizetype(events.size()));
    EXPECT_FALSE(stored.passed);
    EXPECT_NEAR(stored.score, run.out.result.score, 1e-9);
    ASSERT_EQ(stored.breakdown.size(), 4);
    EXPECT_EQ(stored.breakdown[3].key, "safety");
    EXPECT_DOUBLE_EQ(stored.breakdown[3].maxPoints, 30.0);
    EXPECT_TRUE(log.problem().isEmpty());
}

TEST(AttemptLog, ADatabaseThatRefusesLosesNothingThePendingFileIsImportedLater)
{
    const CarelessRun run = careless();
    ASSERT_TRUE(run.tutorial);
    QTemporaryDir dir;
    const QString file = dir.filePath("records.sqlite");
    QString error;
    qint64 op = 0;
    {
        records::RecordsDb db;
        ASSERT_TRUE(db.openSqlite(file, false, &error));
        op = db.addOperator("OP-9", "José Soto", &error);
    }
    const QString pending = dir.filePath("pending");
    {
        records::RecordsDb readOnly;
        ASSERT_TRUE(readOnly.openSqlite(file, true, &error)) << error.toStdString();
        AttemptLog log(&readOnly, pending, "OP-9", "José Soto", *run.tutorial, "en");
        EXPECT_EQ(log.attemptId(), 0);
        EXPECT_FALSE(log.problem().isEmpty());
        log.update(run.out.result.events);  // the attempt goes on
        EXPECT_FALSE(log.finish(run.out.result.events, run.out.result, false));
        EXPECT_TRUE(QFile::exists(log.pendingFile())) << log.problem().toStdString();
        EXPECT_TRUE(log.problem().contains(QDir::toNativeSeparators(log.pendingFile()))) << log.problem().toStdString();
    }
    records::RecordsDb db;
    ASSERT_TRUE(db.openSqlite(file, false, &error));
    EXPECT_EQ(AttemptLog::importPending(db, pending, &error), 1) << error.toStdString();
    EXPECT_TRUE(QDir(pending).entryList({"*.json"}, QDir::Files).isEmpty());
    QList<records::Attempt> list;
    ASSERT_TRUE(db.attemptsOf(op, list, true, &error));
    ASSERT_EQ(list.size(), 1);
    EXPECT_EQ(list[0].status, records::AttemptStatus::Finished);
    EXPECT_EQ(list[0].events.size(), qsizetype(run.out.result.events.size()));
    EXPECT_EQ(list[0].breakdown.size(), 4);
    EXPECT_EQ(list[0].tutorialTitle, "Reach a target");
    // nothing twice
    EXPECT_EQ(AttemptLog::importPending(db, pending, &error), 0);
}

// a records file locked by another program when the attempt starts, and the station killed
// (kill -9) in the middle of it: the attempt is not lost, nor its operator

TEST(AttemptLogChild, BeginsWhileTheDatabaseIsLockedAndIsKilled)
{
    const QString dir = qEnvironmentVariable(kDieEnv);
    if (dir.isEmpty()) GTEST_SKIP() << "a child process of AttemptLog.AKill…; runs only with " << kDieEnv << " set";
    const auto tutorial = t0();
    ASSERT_TRUE(tutorial);
    records::RecordsLocation where;
    where.sqlitePath = dir + "/records.sqlite";
    where.busyTimeoutMs = 100;
    records::RecordsDb db;
    QString error;
    db.open(where, &error);  // locked: open or not, the database refuses the attempt
    AttemptLog log(&db, dir + "/pending", "OP-5", "Rosa Díaz", *tutorial, "en");
    EXPECT_EQ(log.attemptId(), 0);
    log.update(goals(2));
    std::printf("pending %s\n", qPrintable(log.pendingFile()));
    std::fflush(stdout);
    const rlimit noCore{0, 0};
    setrlimit(RLIMIT_CORE, &noCore);
    std::raise(SIGKILL);
}

TEST(AttemptLog, AKillWhileTheDatabaseIsLockedLosesNeitherTheAttemptNorItsOperator)
{
    QTemporaryDir dir;
    const QString file = dir.filePath("records.sqlite");
    QString error;
    {
        records::RecordsDb db;
        ASSERT_TRUE(db.openSqlite(file, false, &error)) << str(error);
    }
    QString out;
    {
        Locker lock(file);  // for the whole life of the station
        ASSERT_TRUE(lock.ok());
        QProcess child;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(kDieEnv, dir.path());
        child.setProcessEnvironment(env);
        child.start(QCoreApplication::applicationFilePath(), {"--gtest_filter=AttemptLogChild.BeginsWhileTheDatabaseIsLockedAndIsKilled"});
        ASSERT_TRUE(child.waitForFinished(60000));
        out = QString::fromLocal8Bit(child.readAllStandardOutput() + child.readAllStandardError());
        ASSERT_EQ(child.exitStatus(), QProcess::CrashExit) << str(out);
    }
    ASSERT_TRUE(out.contains("pending " + dir.path())) << str(out);
    records::RecordsDb db;
    ASSERT_TRUE(db.openSqlite(file, false, &error)) << str(error);
    EXPECT_EQ(AttemptLog::importPending(db, dir.filePath("pending"), &error), 1) << str(error);
    EXPECT_TRUE(error.isEmpty()) << str(error);
    records::Operator op;
    ASSERT_TRUE(db.findOperator("OP-5", op, &error)) << "the operator's code was not carried: " << str(error);
    EXPECT_EQ(op.name, "Rosa Díaz");
    QList<records::Attempt> list;
    ASSERT_TRUE(db.attemptsOf(op.id, list, true, &error));
    ASSERT_EQ(list.size(), 1);
    EXPECT_EQ(list[0].status, records::AttemptStatus::Interrupted);
    EXPECT_EQ(list[0].tutorialId, "T0");
    ASSERT_EQ(list[0].events.size(), 2);
    EXPECT_EQ(list[0].events[1].detail, "g1");
    EXPECT_TRUE(QDir(dir.filePath("pending")).entryList({"*.json"}, QDir::Files).isEmpty());
}

TEST(AttemptLog, ADatabaseLockedForAWholeAttemptKeepsTheOperatorsCode)
{
    const auto tutorial = t0();
    ASSERT_TRUE(tutorial);
    QTemporaryDir dir;
    const QString file = dir.filePath("records.sqlite");
    records::RecordsLocation where;
    where.sqlitePath = file;
    where.busyTimeoutMs = 100;
    records::RecordsDb db;
    QString error;
    ASSERT_TRUE(db.open(where, &error)) << str(error);
    const std::vector<TutorialEvent> events = goals(3);
    {
        Locker lock(file);
        ASSERT_TRUE(lock.ok());
        AttemptLog log(&db, dir.filePath("pending"), "N-4", "Nico", *tutorial, "es");
        EXPECT_EQ(log.attemptId(), 0);
        EXPECT_FALSE(log.pendingFile().isEmpty()) << "nothing on the disk while the database refuses";
        log.update(events);
        TutorialResult result;
        result.time = 9;
        result.score = 64;
        result.stars = 1;
        EXPECT_FALSE(log.finish(events, result, false));
        ASSERT_TRUE(QFile::exists(log.pendingFile())) << str(log.problem());
        const QJsonObject o = QJsonDocument::fromJson([&] {
                                  QFile f(log.pendingFile());
                                  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
                              }()).object();
        EXPECT_EQ(o["code"].toString(), "N-4");
        EXPECT_EQ(o["events"].toArray().size(), 3);
    }
    EXPECT_EQ(AttemptLog::importPending(db, dir.filePath("pending"), &error), 1) << str(error);
    records::Operator op;
    ASSERT_TRUE(db.findOperator("N-4", op, &error)) << str(error);
    QList<records::Attempt> list;
    ASSERT_TRUE(db.attemptsOf(op.id, list, true, &error));
    ASSERT_EQ(list.size(), 1);
    EXPECT_EQ(list[0].status, records::AttemptStatus::Finished);
    EXPECT_DOUBLE_EQ(list[0].score, 64);
    EXPECT_EQ(list[0].events.size(), 3);
}

TEST(AttemptLog, ABadPendingFileIsMovedAsideAndTheOthersAreImported)
{
    const auto tutorial = t0();
    ASSERT_TRUE(tutorial);
    QTemporaryDir dir;
    const QString pending = dir.filePath("pending");
    {
        AttemptLog log(nullptr, pending, "Q-1", "Quim", *tutorial, "en");  // no database: pending only
        TutorialResult result;
        result.score = 40;
        EXPECT_FALSE(log.finish(goals(1), result, true));
        ASSERT_FALSE(log.pendingFile().isEmpty()) << str(log.problem());
    }
    // sorted first: a damaged file and another program's JSON
    auto put = [&](const QString& name, const QByteArray& bytes) {
        QFile f(QDir(pending).filePath(name));
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(bytes);
    };
    put("attempt-0-damaged.json", "{\"format\": \"padrob-pending-att");
    put("attempt-1-foreign.json", "{\"format\": \"something else\"}");
    records::RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(dir.filePath("records.sqlite"), false, &error)) << str(error);
    EXPECT_EQ(AttemptLog::importPending(db, pending, &error), 1) << str(error);
    EXPECT_TRUE(error.contains("attempt-0-damaged.json") && error.contains("attempt-1-foreign.json")) << str(error);
    EXPECT_TRUE(error.contains("quarantine")) << str(error);
    EXPECT_TRUE(QDir(pending).entryList({"*.json"}, QDir::Files).isEmpty());
    EXPECT_EQ(QDir(pending + "/quarantine").entryList({"*.json"}, QDir::Files).size(), 2);
    records::Operator op;
    ASSERT_TRUE(db.findOperator("Q-1", op, &error)) << str(error);
    QList<records::Attempt> list;
    ASSERT_TRUE(db.attemptsOf(op.id, list, true, &error));
    ASSERT_EQ(list.size(), 1);
    EXPECT_EQ(list[0].status, records::AttemptStatus::Aborted);
}

// a full disk: the child (this binary) in a private mount namespace on a small, full tmpfs

TEST(AttemptLogChild, KeepsAsideOnAFullDisk)
{
    const QString dir = qEnvironmentVariable(kFullEnv);
    if (dir.isEmpty()) GTEST_SKIP() << "a child process of AttemptLog.AFullDisk…; runs only with " << kFullEnv << " set";
    const auto tutorial = t0();
    ASSERT_TRUE(tutorial);
    {
        // fill the disk (the folder is made first: only the file has no room)
        ASSERT_TRUE(QDir().mkpath(dir + "/pending"));
        QFile filler(dir + "/filler");
        ASSERT_TRUE(filler.open(QIODevice::WriteOnly));
        const QByteArray block(4096, 'x');
        while (filler.write(block) == block.size() && filler.flush()) {
        }
    }
    AttemptLog log(nullptr, dir + "/pending", "F-1", "Fer", *tutorial, "en");
    EXPECT_TRUE(log.pendingFile().isEmpty());
    TutorialResult result;
    result.score = 70;
    EXPECT_FALSE(log.finish(goals(40), result, false));
    EXPECT_TRUE(log.pendingFile().isEmpty());
    EXPECT_TRUE(log.problem().contains("could not be saved aside") || log.problem().contains("cannot be kept aside"))
        << str(log.problem());
    // nothing that claims to be a record and is not one
    for (const QString& name : QDir(dir + "/pending").entryList(QDir::Files | QDir::Hidden)) {
        QFile f(dir + "/pending/" + name);
        ASSERT_TRUE(f.open(QIODevice::ReadOnly));
        EXPECT_FALSE(QJsonDocument::fromJson(f.readAll()).isNull()) << "a damaged pending file: " << str(name);
    }
    std::printf("problem: %s\n", qPrintable(log.problem()));
}

TEST(AttemptLog, AFullDiskIsSaidNeverAnEmptyFileTakenForARecord)
{
    QTemporaryDir dir;
    const QString small = dir.filePath("small");
    ASSERT_TRUE(QDir().mkpath(small));
    const padrob_test::TmpfsRun r = padrob_test::runOnSmallTmpfs(small, "64k", kFullEnv, "AttemptLogChild.KeepsAsideOnAFullDisk");
    if (!r.mounted) PADROB_NEEDS_COMPONENT(str(r.output));
    EXPECT_TRUE(r.passed) << str(r.output);
}
