// Recording tutorial attempts in the trainee records: a real SQLite file; a database
// that refuses (opened read-only) loses nothing: the attempt goes to a pending file that
// is imported later.

#include "trainer/training/attempt_log.h"
#include "trainer/training/runner.h"

#include <QDir>
#include <QTemporaryDir>

#include <gtest/gtest.h>

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
    AttemptLog log(&db, dir.filePath("pending"), op, *run.tutorial, "es");
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
        AttemptLog log(&readOnly, pending, op, *run.tutorial, "en");
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
