// A station's recorder (trainer/centre/station_records.h) when its own journal refuses:
// attempts kept aside in pending files, with the operator's code, said by problem(), and
// brought into the journal at the next start and after the next attempt it takes whole;
// `padrob station` says on stdout what it brought in.
#include "centre_test_util.h"
#include "trainer/centre/signing.h"
#include "trainer/centre/station_records.h"
#include "trainer/records/records_db.h"
#include "trainer/training/attempt_log.h"

#include <QDir>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace trainer;
using namespace trainer::centre;

namespace {

const std::string kTut0 = PADROB_SOURCE_DIR "/resources/tutorials/t0_reach.tut";

std::shared_ptr<const Tutorial> t0()
{
    solver::Diagnostics d;
    return loadTutorial(kTut0, d);
}

std::string str(const QString& s) { return s.toStdString(); }

TutorialResult scored(double score)
{
    TutorialResult r;
    r.time = 12;
    r.score = score;
    r.stars = 1;
    return r;
}

std::vector<TutorialEvent> goals(int n)
{
    std::vector<TutorialEvent> events(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        events[std::size_t(i)].kind = TutorialEvent::Kind::GoalDone;
        events[std::size_t(i)].t = i;
    }
    return events;
}

/// An attempt of `code` kept aside in `folder` (a station whose journal refused it).
void keptAside(const QString& folder, const QString& code, double score)
{
    const auto tutorial = t0();
    ASSERT_TRUE(tutorial);
    AttemptLog log(nullptr, folder, code, code, *tutorial, "en");
    EXPECT_FALSE(log.finish(goals(2), scored(score), false));
    ASSERT_FALSE(log.pendingFile().isEmpty()) << str(log.problem());
}

int attemptsOf(const QString& journal, const QString& code)
{
    records::RecordsDb db;
    QString error;
    records::Operator op;
    QList<records::Attempt> list;
    if (!db.openSqlite(journal, true, &error) || !db.findOperator(code, op, &error) || !db.attemptsOf(op.id, list, false, &error))
        return -1;
    return int(list.size());
}

}  // namespace

TEST(StationRecords, PendingAttemptsAreBroughtInAtTheStart)
{
    QTemporaryDir dir;
    const QString pending = dir.filePath("pending-attempts");
    keptAside(pending, "OP-3", 55);
    records::SharedLocation where;
    where.journalPath = dir.filePath("journal.sqlite");
    where.station = "bay-1";
    {
        StationRecords recorder(where, pending, "en");
        ASSERT_TRUE(recorder.ok()) << str(recorder.error());
        recorder.flush();
        EXPECT_EQ(recorder.imported(), 1);
        EXPECT_TRUE(recorder.problem().isEmpty()) << str(recorder.problem());
    }
    EXPECT_EQ(attemptsOf(where.journalPath, "OP-3"), 1) << "the operator's code came with the attempt";
    EXPECT_TRUE(QDir(pending).entryList({"*.json"}, QDir::Files).isEmpty());
}

TEST(StationRecords, AJournalLockedForAWholeAttemptIsSaidAndTheAttemptComesInAfterTheNextOne)
{
    const auto tutorial = t0();
    ASSERT_TRUE(tutorial);
    QTemporaryDir dir;
    const QString pending = dir.filePath("pending-attempts");
    records::SharedLocation where;
    where.journalPath = dir.filePath("journal.sqlite");
    where.station = "bay-2";
    where.busyTimeoutMs = 100;
    StationRecords recorder(where, pending, "en");
    ASSERT_TRUE(recorder.ok()) << str(recorder.error());
    {
        // another program holds the journal for the whole attempt
        QSqlDatabase other = QSqlDatabase::addDatabase("QSQLITE", "station-records-locker");
        other.setDatabaseName(where.journalPath);
        ASSERT_TRUE(other.open());
        QSqlQuery q(other);
        ASSERT_TRUE(q.exec("BEGIN EXCLUSIVE"));
        recorder.begin(tutorial, "OP-8");
        recorder.update(goals(1));
        recorder.finish(goals(2), scored(61), false);
        recorder.flush();
        EXPECT_FALSE(recorder.problem().isEmpty()) << "the station must say its journal refuses";
        EXPECT_EQ(QDir(pending).entryList({"*.json"}, QDir::Files).size(), 1);
        q.exec("ROLLBACK");
        q.finish();
        other.close();
    }
    QSqlDatabase::removeDatabase("station-records-locker");
    // the next attempt goes in, and the one kept aside after it
    recorder.begin(tutorial, "OP-8");
    recorder.finish(goals(1), scored(80), false);
    recorder.flush();
    EXPECT_TRUE(recorder.problem().isEmpty()) << str(recorder.problem());
    EXPECT_EQ(recorder.imported(), 1);
    EXPECT_TRUE(QDir(pending).entryList({"*.json"}, QDir::Files).isEmpty());
    EXPECT_EQ(attemptsOf(where.journalPath, "OP-8"), 2);
}

TEST(StationRecords, PadrobStationSaysWhatItBroughtIn)
{
    QTemporaryDir dir;
    const QString journal = dir.filePath("journal.sqlite");
    keptAside(dir.filePath("pending-attempts"), "OP-4", 47);
    const QString key = dir.filePath("centre.key");
    QString error;
    ASSERT_TRUE(CentreKey::create(key, &error)) << str(error);
    QProcess station;
    station.start(PADROB_CLI, {"station", QString::fromStdString(kTut0), "--name", "bay-3", "--for", "1.5", "--records",
                               journal, "--loopback", "--domain", QString::number(centre_test::domain()), "--key", key});
    ASSERT_TRUE(station.waitForFinished(60000));
    const QString out = QString::fromLocal8Bit(station.readAllStandardOutput());
    const QString err = QString::fromLocal8Bit(station.readAllStandardError());
    EXPECT_EQ(station.exitCode(), 0) << str(out + err);
    EXPECT_TRUE(out.contains("station bay-3: 1 pending attempt") && out.contains("recorded in the journal")) << str(out + err);
    EXPECT_EQ(attemptsOf(journal, "OP-4"), 1);
}
