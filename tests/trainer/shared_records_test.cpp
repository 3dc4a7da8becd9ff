// A training centre's records (trainer/records/shared_records.h, docs/records.md "A
// training centre"): stations journal locally in real SQLite files and sync to a real
// throwaway PostgreSQL server (LocalPostgres), which is stopped and started again for
// outages; a station that dies (this binary re-run as a child that calls std::abort())
// during an attempt or in the middle of a sync. Also the schema's step 3 on an old file,
// and AttemptLog recording through a station.
#include "tests/common/components.h"
#include "local_postgres.h"
#include "trainer/records/shared_records.h"
#include "trainer/training/attempt_log.h"
#include "trainer/training/tutorial.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include <sys/resource.h>

using namespace trainer::records;
using padrob_test::LocalPostgres;
using padrob_test::RawPostgres;

namespace {

constexpr const char* kChildMode = "PADROB_SHARED_CHILD";
constexpr const char* kChildJournal = "PADROB_SHARED_JOURNAL";
constexpr const char* kChildServer = "PADROB_SHARED_PGHOST";

std::string str(const QString& s)
{
    return s.toStdString();
}

/// `n` events numbered from `from`: t = from + i, text "e<number>".
QList<AttemptEvent> numbered(int from, int n)
{
    QList<AttemptEvent> list;
    for (int i = from; i < from + n; ++i)
        list.append({double(i), "step", QStringLiteral("e%1").arg(i), 0.5 * i, i % 3 == 0 ? 1.0 : 0.0,
                     QStringLiteral("goal-%1").arg(i)});
    return list;
}

const AttemptResult kResult{AttemptStatus::Finished, 95.5, 87.5, 3, true,
                            {{"time", "Time", 95.5, 40, 50}, {"safety", "Safety", 2, -12.5, 0}}};

SharedLocation stationAt(const QString& journal, const PostgresConfig& server, const QString& name)
{
    SharedLocation w;
    w.journalPath = journal;
    w.server = server;
    w.server.connectTimeoutS = 2;
    w.station = name;
    w.retryAfterS = 0;
    return w;
}

/// Rows on the server: operators, attempts, events, score lines.
struct Rows {
    int operators = -1, attempts = -1, events = -1, scores = -1;
    bool operator==(const Rows&) const = default;
};

Rows rowsOn(const PostgresConfig& c)
{
    RawPostgres raw(c);
    Rows r;
    if (!raw.ok()) return r;
    r.operators = raw.scalar("SELECT COUNT(*) FROM operators").toInt();
    r.attempts = raw.scalar("SELECT COUNT(*) FROM attempts").toInt();
    r.events = raw.scalar("SELECT COUNT(*) FROM attempt_events").toInt();
    r.scores = raw.scalar("SELECT COUNT(*) FROM attempt_scores").toInt();
    return r;
}

std::ostream& operator<<(std::ostream& o, const Rows& r)
{
    return o << r.operators << " operators, " << r.attempts << " attempts, " << r.events << " events, " << r.scores
             << " score lines";
}

/// The server's copy of the attempt `uid` (through a RecordsDb of its own).
bool onServer(const PostgresConfig& c, const QString& uid, Attempt& out, QString* error = nullptr)
{
    RecordsDb view;
    return view.openPostgres(c, error) && view.findAttempt(uid, out, error);
}

/// Events `from`…`from + n - 1` of numbered(), in order, each once, with their seq.
void expectNumbered(const QList<AttemptEvent>& got, int n)
{
    ASSERT_EQ(got.size(), n);
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(got[i].seq, i);
        EXPECT_EQ(got[i].text, QStringLiteral("e%1").arg(i)) << "event " << i;
        EXPECT_EQ(got[i].t, double(i));
        EXPECT_EQ(got[i].detail, QStringLiteral("goal-%1").arg(i));
    }
}

/// This binary re-run as a child (SharedRecordsChild.*) in `mode`; its output.
QString runChild(const QString& mode, const QString& journal, const QString& serverHost, QProcess::ExitStatus& how)
{
    QProcess child;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(kChildMode, mode);
    env.insert(kChildJournal, journal);
    env.insert(kChildServer, serverHost);
    child.setProcessEnvironment(env);
    child.start(QCoreApplication::applicationFilePath(), {"--gtest_filter=SharedRecordsChild.RecordsOrSyncsAndDies"});
    if (!child.waitForFinished(60000)) return "the child did not finish";
    how = child.exitStatus();
    return QString::fromLocal8Bit(child.readAllStandardOutput() + child.readAllStandardError());
}

}  // namespace

// the station's recorder, dying ----------------------------------------------------------

TEST(SharedRecordsChild, RecordsOrSyncsAndDies)
{
    const QString mode = qEnvironmentVariable(kChildMode);
    if (mode.isEmpty())
        GTEST_SKIP() << "a child process of SharedRecordsPostgres.*; runs only with " << kChildMode << " set";
    PostgresConfig server;
    server.host = qEnvironmentVariable(kChildServer);
    server.database = "postgres";
    server.user = "padrob";
    SharedLocation where = stationAt(qEnvironmentVariable(kChildJournal), server, "crashing-station");
    where.eventsPerStep = 10;
    SharedRecords st;
    QString error;
    ASSERT_TRUE(st.open(where, &error)) << str(error);
    const rlimit noCore{0, 0};
    setrlimit(RLIMIT_CORE, &noCore);
    if (mode == "record") {
        // begins an attempt, records 5 events, syncs (the server shows it running) and dies
        const qint64 op = st.addOperator("C-1", "Crash", &error);
        ASSERT_GT(op, 0) << str(error);
        const qint64 id = st.beginAttempt({op, "crash", "Crash", "en", {}}, &error);
        ASSERT_GT(id, 0) << str(error);
        ASSERT_TRUE(st.appendEvents(id, numbered(0, 5), &error)) << str(error);
        ASSERT_TRUE(st.sync(&error)) << str(error);
        Attempt a;
        ASSERT_TRUE(st.journal().attempt(id, a, &error)) << str(error);
        std::printf("attempt %s recorded\n", qPrintable(a.uid));
        std::fflush(stdout);
        std::abort();
    }
    // "sync": dies after the server committed the third step (the operator, then two
    // chunks of 10 events), before the journal noted it
    st.setAfterServerStep([](int step) {
        if (step < 3) return;
        std::printf("died after step %d\n", step);
        std::fflush(stdout);
        std::abort();
    });
    st.sync(&error);
    std::printf("the sync ended: %s\n", qPrintable(error));
}

// on a real server -------------------------------------------------------------------------

TEST(SharedRecordsPostgres, OnlineAnAttemptReachesTheServerOnceWithItsEventsInOrder)
{
    LocalPostgres server;
    QString why;
    if (!server.start(why)) PADROB_NEEDS_COMPONENT("no PostgreSQL server for the test: " << str(why));
    QTemporaryDir dir;
    SharedRecords st;
    QString error;
    ASSERT_TRUE(st.open(stationAt(dir.filePath("station.sqlite"), server.config(), "bay-1"), &error)) << str(error);
    EXPECT_FALSE(st.online());  // not tried yet
    EXPECT_FALSE(st.offlineMessage().isEmpty());
    ASSERT_TRUE(st.sync(&error)) << str(error);
    EXPECT_TRUE(st.online());
    EXPECT_TRUE(st.offlineMessage().isEmpty());

    const qint64 op = st.addOperator("A-17", "Ana Pérez", &error);
    ASSERT_GT(op, 0) << str(error);
    const qint64 id = st.beginAttempt({op, "liner.basics", "Liner: basics", "es", {}}, &error);
    ASSERT_GT(id, 0) << str(error);
    ASSERT_TRUE(st.appendEvents(id, numbered(0, 10), &error)) << str(error);
    ASSERT_TRUE(st.sync(&error)) << str(error);
    Attempt a, there;
    ASSERT_TRUE(st.journal().attempt(id, a, &error)) << str(error);
    EXPECT_EQ(a.station, "bay-1");
    EXPECT_EQ(a.uid.size(), 36) << str(a.uid);  // a UUID
    // the instructor sees it live
    ASSERT_TRUE(onServer(server.config(), a.uid, there, &error)) << str(error);
    EXPECT_EQ(there.status, AttemptStatus::Running);
    EXPECT_EQ(there.events.size(), 10);
    EXPECT_EQ(there.station, "bay-1");

    ASSERT_TRUE(st.appendEvents(id, numbered(10, 15), &error)) << str(error);
    ASSERT_TRUE(st.finishAttempt(id, kResult, &error)) << str(error);
    EXPECT_EQ(st.pending().attempts, 1);
    EXPECT_EQ(st.pending().events, 15);
    ASSERT_TRUE(st.sync(&error)) << str(error);
    EXPECT_TRUE(st.pending().empty());

    ASSERT_TRUE(onServer(server.config(), a.uid, there, &error)) << str(error);
    EXPECT_EQ(there.status, AttemptStatus::Finished);
    EXPECT_EQ(there.tutorialId, "liner.basics");
    EXPECT_EQ(there.tutorialTitle, "Liner: basics");
    EXPECT_EQ(there.language, "es");
    EXPECT_EQ(there.started, a.started);
    EXPECT_EQ(there.score, 87.5);
    EXPECT_EQ(there.stars, 3);
    EXPECT_TRUE(there.passed);
    EXPECT_EQ(there.durationS, 95.5);
    EXPECT_EQ(there.breakdown, kResult.breakdown);
    expectNumbered(there.events, 25);
    RawPostgres raw(server.config());
    ASSERT_TRUE(raw.ok());
    EXPECT_EQ(raw.scalar("SELECT COUNT(*) FROM attempts WHERE uid = '" + a.uid + "'").toInt(), 1);
    EXPECT_EQ(raw.scalar("SELECT code || '/' || name FROM operators").toString(), "A-17/Ana Pérez");
    EXPECT_EQ(raw.scalar("SELECT COUNT(*) FROM sync_state").toInt(), 0);  // the journal's bookkeeping only
}

TEST(SharedRecordsPostgres, AnOutageRecordsLocallyAndTheSyncAfterItDuplicatesAndLosesNothing)
{
    LocalPostgres server;
    QString why;
    if (!server.start(why)) PADROB_NEEDS_COMPONENT("no PostgreSQL server for the test: " << str(why));
    QTemporaryDir dir;
    SharedRecords st;
    QString error;
    ASSERT_TRUE(st.open(stationAt(dir.filePath("station.sqlite"), server.config(), "bay-2"), &error)) << str(error);
    const qint64 op = st.addOperator("O-1", "Omar", &error);
    const qint64 id = st.beginAttempt({op, "t1", "T1", "en", {}}, &error);
    ASSERT_GT(id, 0) << str(error);
    ASSERT_TRUE(st.appendEvents(id, numbered(0, 10), &error)) << str(error);
    ASSERT_TRUE(st.sync(&error)) << str(error);
    Attempt local;
    ASSERT_TRUE(st.journal().attempt(id, local, &error));

    server.stop();  // mid-attempt
    ASSERT_TRUE(st.appendEvents(id, numbered(10, 10), &error)) << str(error);  // no error for the operator
    QElapsedTimer timer;
    timer.start();
    EXPECT_FALSE(st.sync(&error));
    EXPECT_LT(timer.elapsed(), 3000) << "a gone server must not block the station";
    EXPECT_FALSE(error.isEmpty());
    EXPECT_FALSE(st.online());
    EXPECT_TRUE(st.offlineMessage().contains("records on its own")) << str(st.offlineMessage());
    ASSERT_TRUE(st.appendEvents(id, numbered(20, 5), &error)) << str(error);
    ASSERT_TRUE(st.finishAttempt(id, kResult, &error)) << str(error);
    const qint64 second = st.beginAttempt({op, "t2", "T2", "en", {}}, &error);  // all offline
    ASSERT_TRUE(st.appendEvents(second, numbered(0, 3), &error)) << str(error);
    ASSERT_TRUE(st.finishAttempt(second, {AttemptStatus::Aborted, 3, 10, 0, false, {}}, &error)) << str(error);
    EXPECT_FALSE(st.sync(&error));
    const SyncBacklog waiting = st.pending();
    EXPECT_EQ(waiting.attempts, 2);
    EXPECT_EQ(waiting.events, 15 + 3);

    ASSERT_TRUE(server.resume(why)) << str(why);
    ASSERT_TRUE(st.sync(&error)) << str(error);
    EXPECT_TRUE(st.online());
    EXPECT_TRUE(st.pending().empty());
    Attempt there;
    ASSERT_TRUE(onServer(server.config(), local.uid, there, &error)) << str(error);
    EXPECT_EQ(there.status, AttemptStatus::Finished);
    EXPECT_EQ(there.breakdown, kResult.breakdown);
    expectNumbered(there.events, 25);
    Attempt secondLocal;
    ASSERT_TRUE(st.journal().attempt(second, secondLocal, &error));
    ASSERT_TRUE(onServer(server.config(), secondLocal.uid, there, &error)) << str(error);
    EXPECT_EQ(there.status, AttemptStatus::Aborted);
    expectNumbered(there.events, 3);
    const Rows rows = rowsOn(server.config());
    EXPECT_EQ(rows, (Rows{1, 2, 28, 2}));
    // again: nothing changes
    ASSERT_TRUE(st.sync(&error)) << str(error);
    EXPECT_EQ(rowsOn(server.config()), rows);
}

TEST(SharedRecordsPostgres, AfterAFailureTheNextTryWaitsRetryAfter)
{
    LocalPostgres server;
    QString why;
    if (!server.start(why)) PADROB_NEEDS_COMPONENT("no PostgreSQL server for the test: " << str(why));
    QTemporaryDir dir;
    SharedLocation where = stationAt(dir.filePath("station.sqlite"), server.config(), "bay-3");
    where.retryAfterS = 1.5;
    SharedRecords st;
    QString error, first;
    ASSERT_TRUE(st.open(where, &error)) << str(error);
    server.stop();
    EXPECT_FALSE(st.sync(&first));
    ASSERT_TRUE(server.resume(why)) << str(why);
    QElapsedTimer timer;
    timer.start();
    EXPECT_FALSE(st.sync(&error));  // too soon: not even tried, though the server is back
    EXPECT_LT(timer.elapsed(), 100);
    EXPECT_EQ(error, first);
    QThread::msleep(1600);
    EXPECT_TRUE(st.sync(&error)) << str(error);
    EXPECT_TRUE(st.online());
}

TEST(SharedRecordsPostgres, ACrashInTheMiddleOfASyncLeavesNothingTwiceNorMissing)
{
    LocalPostgres server;
    QString why;
    if (!server.start(why)) PADROB_NEEDS_COMPONENT("no PostgreSQL server for the test: " << str(why));
    QTemporaryDir dir;
    const QString journal = dir.filePath("station.sqlite");
    QString uid, error;
    {
        // recorded with the server away (no server configured at all)
        SharedRecords st;
        ASSERT_TRUE(st.open(stationAt(journal, {}, "crashing-station"), &error)) << str(error);
        const qint64 op = st.addOperator("K-9", "Kim", &error);
        const qint64 id = st.beginAttempt({op, "t", "T", "en", {}}, &error);
        ASSERT_TRUE(st.appendEvents(id, numbered(0, 20), &error)) << str(error);
        ASSERT_TRUE(st.appendEvents(id, numbered(20, 15), &error)) << str(error);
        ASSERT_TRUE(st.finishAttempt(id, kResult, &error)) << str(error);
        Attempt a;
        ASSERT_TRUE(st.journal().attempt(id, a, &error));
        uid = a.uid;
        EXPECT_TRUE(st.sync(&error));  // no server: nothing to do
    }
    QProcess::ExitStatus how = QProcess::NormalExit;
    const QString out = runChild("sync", journal, server.config().host, how);
    ASSERT_EQ(how, QProcess::CrashExit) << str(out);
    ASSERT_TRUE(out.contains("died after step 3")) << str(out);

    // the server committed two chunks; the journal noted only the first
    Attempt there;
    ASSERT_TRUE(onServer(server.config(), uid, there, &error)) << str(error);
    EXPECT_EQ(there.status, AttemptStatus::Running);  // the result comes with the last events
    expectNumbered(there.events, 20);

    SharedRecords st;
    ASSERT_TRUE(st.open(stationAt(journal, server.config(), "crashing-station"), &error)) << str(error);
    EXPECT_EQ(st.pending().events, 25);  // what the journal knows the server lacks
    ASSERT_TRUE(st.sync(&error)) << str(error);
    ASSERT_TRUE(onServer(server.config(), uid, there, &error)) << str(error);
    EXPECT_EQ(there.status, AttemptStatus::Finished);
    expectNumbered(there.events, 35);
    const Rows rows = rowsOn(server.config());
    EXPECT_EQ(rows, (Rows{1, 1, 35, 2}));
    ASSERT_TRUE(st.sync(&error)) << str(error);
    EXPECT_EQ(rowsOn(server.config()), rows);
}

TEST(SharedRecordsPostgres, AStationsRunningAttemptIsInterruptedOnlyByThatStation)
{
    LocalPostgres server;
    QString why;
    if (!server.start(why)) PADROB_NEEDS_COMPONENT("no PostgreSQL server for the test: " << str(why));
    QTemporaryDir dir;
    const QString journal = dir.filePath("station.sqlite");
    QProcess::ExitStatus how = QProcess::NormalExit;
    const QString out = runChild("record", journal, server.config().host, how);
    ASSERT_EQ(how, QProcess::CrashExit) << str(out);
    const QRegularExpressionMatch m = QRegularExpression("attempt ([0-9a-f-]{36}) recorded").match(out);
    ASSERT_TRUE(m.hasMatch()) << str(out);
    const QString uid = m.captured(1);

    // the station is gone and holds no session on the server: other opens leave its
    // attempt alone (it may be recording offline)
    QString error;
    {
        RecordsDb desk;
        ASSERT_TRUE(desk.openPostgres(server.config(), &error)) << str(error);
        EXPECT_EQ(desk.interruptedAtOpen(), 0);
        Attempt there;
        ASSERT_TRUE(desk.findAttempt(uid, there, &error)) << str(error);
        EXPECT_EQ(there.status, AttemptStatus::Running);
        EXPECT_EQ(there.station, "crashing-station");
        expectNumbered(there.events, 5);
    }
    SharedRecords other;  // another station syncing meanwhile
    ASSERT_TRUE(other.open(stationAt(dir.filePath("other.sqlite"), server.config(), "bay-9"), &error));
    ASSERT_TRUE(other.sync(&error)) << str(error);
    Attempt there;
    ASSERT_TRUE(onServer(server.config(), uid, there, &error)) << str(error);
    EXPECT_EQ(there.status, AttemptStatus::Running);

    // the station starts again: its journal marks the attempt, its sync tells the server
    SharedRecords st;
    ASSERT_TRUE(st.open(stationAt(journal, server.config(), "crashing-station"), &error)) << str(error);
    EXPECT_EQ(st.interruptedAtOpen(), 1);
    ASSERT_TRUE(st.sync(&error)) << str(error);
    ASSERT_TRUE(onServer(server.config(), uid, there, &error)) << str(error);
    EXPECT_EQ(there.status, AttemptStatus::Interrupted);
    expectNumbered(there.events, 5);

    // a recorder on the server itself (station "") still loses a dead session's attempt
    RecordsDb direct;
    ASSERT_TRUE(direct.openPostgres(server.config(), &error)) << str(error);
    Operator op;
    ASSERT_TRUE(direct.findOperator("C-1", op, &error)) << str(error);
    const qint64 live = direct.beginAttempt({op.id, "direct", "Direct", "en", {}}, &error);
    ASSERT_GT(live, 0) << str(error);
    {
        RawPostgres raw(server.config());
        raw.scalar("SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE application_name = 'padrob'");
    }
    direct.close();
    RecordsDb desk;
    ASSERT_TRUE(desk.openPostgres(server.config(), &error)) << str(error);
    EXPECT_EQ(desk.interruptedAtOpen(), 1);
    Attempt a;
    ASSERT_TRUE(desk.attempt(live, a, &error));
    EXPECT_EQ(a.status, AttemptStatus::Interrupted);
}

TEST(SharedRecordsPostgres, TwoStationsWithTheSameOperatorMakeOneOperatorRow)
{
    LocalPostgres server;
    QString why;
    if (!server.start(why)) PADROB_NEEDS_COMPONENT("no PostgreSQL server for the test: " << str(why));
    QTemporaryDir dir;
    SharedRecords one, two, three;
    QString error;
    ASSERT_TRUE(one.open(stationAt(dir.filePath("one.sqlite"), server.config(), "bay-1"), &error)) << str(error);
    ASSERT_TRUE(two.open(stationAt(dir.filePath("two.sqlite"), server.config(), "bay-2"), &error)) << str(error);
    QStringList uids;
    for (SharedRecords* st : {&one, &two}) {
        const qint64 op = st->addOperator("B-5", "Bea", &error);  // each on its own, before any sync
        ASSERT_GT(op, 0) << str(error);
        const qint64 id = st->beginAttempt({op, "t", "T", "en", {}}, &error);
        ASSERT_TRUE(st->appendEvents(id, numbered(0, 4), &error)) << str(error);
        ASSERT_TRUE(st->finishAttempt(id, kResult, &error)) << str(error);
        Attempt a;
        ASSERT_TRUE(st->journal().attempt(id, a, &error));
        uids << a.uid;
    }
    ASSERT_TRUE(one.sync(&error)) << str(error);
    ASSERT_TRUE(two.sync(&error)) << str(error);
    ASSERT_TRUE(one.sync(&error)) << str(error);
    EXPECT_EQ(rowsOn(server.config()), (Rows{1, 2, 8, 4}));
    RecordsDb desk;
    ASSERT_TRUE(desk.openPostgres(server.config(), &error)) << str(error);
    Operator op;
    ASSERT_TRUE(desk.findOperator("B-5", op, &error)) << str(error);
    QList<Attempt> list;
    ASSERT_TRUE(desk.attemptsOf(op.id, list, true, &error)) << str(error);
    ASSERT_EQ(list.size(), 2);
    QStringList stations = {list[0].station, list[1].station}, got = {list[0].uid, list[1].uid};
    stations.sort();
    got.sort();
    uids.sort();
    EXPECT_EQ(stations, QStringList({"bay-1", "bay-2"}));
    EXPECT_EQ(got, uids);

    // a third station finds the operator registered elsewhere, once it is online
    ASSERT_TRUE(three.open(stationAt(dir.filePath("three.sqlite"), server.config(), "bay-3"), &error));
    Operator found;
    EXPECT_FALSE(three.findOperator("B-5", found, &error));  // offline (never synced): not known here
    EXPECT_TRUE(error.isEmpty()) << str(error);
    ASSERT_TRUE(three.sync(&error)) << str(error);
    ASSERT_TRUE(three.findOperator("B-5", found, &error)) << str(error);
    EXPECT_EQ(found.name, "Bea");
    const qint64 id = three.beginAttempt({found.id, "t", "T", "en", {}}, &error);
    ASSERT_TRUE(three.finishAttempt(id, kResult, &error)) << str(error);
    ASSERT_TRUE(three.sync(&error)) << str(error);
    EXPECT_EQ(rowsOn(server.config()), (Rows{1, 3, 8, 6}));
}

TEST(SharedRecordsPostgres, ThePasswordIsInNoMessageNorInTheJournal)
{
    LocalPostgres server;
    QString why;
    if (!server.start(why)) PADROB_NEEDS_COMPONENT("no PostgreSQL server for the test: " << str(why));
    QTemporaryDir dir;
    const QString journal = dir.filePath("station.sqlite");
    PostgresConfig config = server.config();
    const QString secret = QStringLiteral("Sup3r-Secret-Pässword!");
    config.password = secret;  // trust authentication: accepted and ignored
    QStringList messages;
    QString error;
    {
        SharedRecords st;
        ASSERT_TRUE(st.open(stationAt(journal, config, "bay-7"), &error)) << str(error);
        messages << st.offlineMessage();
        ASSERT_TRUE(st.sync(&error)) << str(error);
        const qint64 op = st.addOperator("P-1", "Pia", &error);
        const qint64 id = st.beginAttempt({op, "t", "T", "en", {}}, &error);
        ASSERT_TRUE(st.appendEvents(id, numbered(0, 3), &error)) << str(error);
        server.stop();
        EXPECT_FALSE(st.sync(&error));
        messages << error << st.offlineMessage();
        ASSERT_TRUE(st.finishAttempt(id, kResult, &error)) << str(error);
        ASSERT_TRUE(server.resume(why)) << str(why);
        ASSERT_TRUE(st.sync(&error)) << str(error);
    }
    {
        SharedLocation wrong = stationAt(dir.filePath("wrong.sqlite"), config, "bay-8");
        wrong.server.database = "no_such_records";
        SharedRecords st;
        ASSERT_TRUE(st.open(wrong, &error)) << str(error);
        EXPECT_FALSE(st.sync(&error));
        EXPECT_TRUE(error.contains("no_such_records")) << str(error);
        messages << error << st.offlineMessage();
    }
    for (const QString& m : messages) {
        EXPECT_FALSE(m.contains(secret)) << str(m);
        EXPECT_FALSE(m.contains("Sup3r")) << str(m);
    }
    EXPECT_GE(messages.join("").size(), 100);
    for (const QString& file : QDir(dir.path()).entryList(QDir::Files)) {
        QFile f(dir.filePath(file));
        ASSERT_TRUE(f.open(QIODevice::ReadOnly));
        const QByteArray bytes = f.readAll();
        EXPECT_FALSE(bytes.contains(secret.toUtf8())) << str(file);
        EXPECT_FALSE(bytes.contains("Sup3r")) << str(file);
    }
    EXPECT_EQ(rowsOn(server.config()), (Rows{1, 1, 3, 2}));
}

// without a server --------------------------------------------------------------------

TEST(SharedRecords, WithoutItsServerAStationRecordsAndAttemptLogSeesNoProblem)
{
    QTemporaryDir dir;
    QTemporaryDir empty;  // a socket folder with no server in it
    PostgresConfig gone;
    gone.host = empty.path();
    gone.database = "records";
    gone.user = "trainer";
    SharedRecords st;
    QString error;
    ASSERT_TRUE(st.open(stationAt(dir.filePath("station.sqlite"), gone, "bay-4"), &error)) << str(error);
    EXPECT_FALSE(st.sync(&error));
    EXPECT_FALSE(st.online());
    EXPECT_TRUE(st.offlineMessage().contains("trainer@" + empty.path())) << str(st.offlineMessage());

    solver::Diagnostics diags;
    const auto tutorial = trainer::loadTutorial(std::string(PADROB_SOURCE_DIR) + "/resources/tutorials/t0_reach.tut", diags);
    ASSERT_TRUE(tutorial);
    ASSERT_GT(st.addOperator("L-1", "Lia", &error), 0) << str(error);
    trainer::AttemptLog log(&st, dir.filePath("pending"), "L-1", "Lia", *tutorial, "en");
    ASSERT_GT(log.attemptId(), 0) << str(log.problem());
    std::vector<trainer::TutorialEvent> events(3);
    for (int i = 0; i < 3; ++i) {
        events[i].kind = trainer::TutorialEvent::Kind::GoalDone;
        events[i].t = i;
        events[i].detail = "g" + std::to_string(i);
    }
    log.update({events.begin(), events.begin() + 2});
    EXPECT_TRUE(log.problem().isEmpty()) << str(log.problem());
    trainer::TutorialResult result;
    result.time = 12;
    result.score = 70;
    result.stars = 2;
    result.passed = true;
    EXPECT_TRUE(log.finish(events, result, false)) << str(log.problem());
    EXPECT_TRUE(log.pendingFile().isEmpty());
    Attempt a;
    ASSERT_TRUE(st.findAttempt(log.attemptUid(), a, &error)) << str(error);
    EXPECT_EQ(a.id, log.attemptId());
    EXPECT_EQ(a.status, AttemptStatus::Finished);
    EXPECT_EQ(a.station, "bay-4");
    ASSERT_EQ(a.events.size(), 3);
    EXPECT_EQ(a.events[2].seq, 2);
    EXPECT_EQ(st.pending().attempts, 1);
    EXPECT_EQ(st.pending().events, 3);
    EXPECT_EQ(st.pending().operators, 1);
}

TEST(SharedRecords, APendingFileCompletesTheAttemptTheDatabaseHadBegunNeverASecondOne)
{
    solver::Diagnostics diags;
    const auto tutorial = trainer::loadTutorial(std::string(PADROB_SOURCE_DIR) + "/resources/tutorials/t0_reach.tut", diags);
    ASSERT_TRUE(tutorial);
    QTemporaryDir dir;
    const QString file = dir.filePath("records.sqlite");
    RecordsLocation where;
    where.sqlitePath = file;
    where.busyTimeoutMs = 100;
    RecordsDb db;
    QString error;
    ASSERT_TRUE(db.open(where, &error)) << str(error);
    const qint64 op = db.addOperator("M-1", "Mar", &error);
    std::vector<trainer::TutorialEvent> events(5);
    for (int i = 0; i < 5; ++i) events[i].t = i, events[i].detail = "g" + std::to_string(i);
    trainer::AttemptLog log(&db, dir.filePath("pending"), "M-1", "Mar", *tutorial, "en");
    ASSERT_GT(log.attemptId(), 0);
    log.update({events.begin(), events.begin() + 2});  // begun, two events in the database
    ASSERT_TRUE(log.problem().isEmpty()) << str(log.problem());
    {
        // another program locks the database until the end of the attempt
        QSqlDatabase other = QSqlDatabase::addDatabase("QSQLITE", "shared-test-locker");
        other.setDatabaseName(file);
        ASSERT_TRUE(other.open());
        QSqlQuery q(other);
        ASSERT_TRUE(q.exec("BEGIN EXCLUSIVE"));
        trainer::TutorialResult result;
        result.time = 5;
        result.score = 50;
        EXPECT_FALSE(log.finish(events, result, true));
        EXPECT_TRUE(QFile::exists(log.pendingFile())) << str(log.problem());
        q.exec("ROLLBACK");
        q.finish();
        other.close();
    }
    QSqlDatabase::removeDatabase("shared-test-locker");
    EXPECT_EQ(trainer::AttemptLog::importPending(db, dir.filePath("pending"), &error), 1) << str(error);
    QList<Attempt> list;
    ASSERT_TRUE(db.attemptsOf(op, list, true, &error));
    ASSERT_EQ(list.size(), 1);  // the begun one, completed
    EXPECT_EQ(list[0].id, log.attemptId());
    EXPECT_EQ(list[0].status, AttemptStatus::Aborted);
    ASSERT_EQ(list[0].events.size(), 5);
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(list[0].events[i].seq, i);
        EXPECT_EQ(list[0].events[i].detail, QStringLiteral("g%1").arg(i));
    }
}

TEST(SharedRecords, SchemaStepThreeGivesOldEventsTheirIndexAndTheJournalGivesOldAttemptsAUid)
{
    QTemporaryDir dir;
    const QString path = dir.filePath("old.sqlite");
    {
        // a file of schema version 2, as Padrob wrote it before step 3
        QSqlDatabase raw = QSqlDatabase::addDatabase("QSQLITE", "shared-test-v2");
        raw.setDatabaseName(path);
        ASSERT_TRUE(raw.open());
        QSqlQuery q(raw);
        const QStringList sql = {
            "CREATE TABLE records_schema (version INTEGER PRIMARY KEY, applied TEXT NOT NULL, description TEXT NOT NULL)",
            "CREATE TABLE operators (id INTEGER PRIMARY KEY AUTOINCREMENT, code TEXT NOT NULL UNIQUE, name TEXT NOT "
            "NULL, created TEXT NOT NULL)",
            "CREATE TABLE attempts (id INTEGER PRIMARY KEY AUTOINCREMENT, operator_id BIGINT NOT NULL REFERENCES "
            "operators (id) ON DELETE CASCADE, tutorial TEXT NOT NULL, tutorial_title TEXT NOT NULL, started TEXT NOT "
            "NULL, duration_s DOUBLE PRECISION NOT NULL DEFAULT 0, score DOUBLE PRECISION NOT NULL DEFAULT 0, stars "
            "INTEGER NOT NULL DEFAULT 0, passed INTEGER NOT NULL DEFAULT 0, status TEXT NOT NULL, language TEXT NOT "
            "NULL)",
            "CREATE TABLE attempt_scores (attempt_id BIGINT NOT NULL, seq INTEGER NOT NULL, key TEXT NOT NULL, label "
            "TEXT NOT NULL, value DOUBLE PRECISION NOT NULL, points DOUBLE PRECISION NOT NULL, max_points DOUBLE "
            "PRECISION NOT NULL, PRIMARY KEY (attempt_id, key))",
            "CREATE TABLE attempt_events (id INTEGER PRIMARY KEY AUTOINCREMENT, attempt_id BIGINT NOT NULL, t DOUBLE "
            "PRECISION NOT NULL, kind TEXT NOT NULL, text TEXT NOT NULL, value DOUBLE PRECISION, penalty DOUBLE "
            "PRECISION NOT NULL DEFAULT 0, detail TEXT NOT NULL DEFAULT '')",
            "INSERT INTO records_schema VALUES (1, '2025-01-01T00:00:00.000Z', 'one'), (2, "
            "'2025-01-02T00:00:00.000Z', 'two')",
            "INSERT INTO operators VALUES (1, 'OLD', 'Old', '2025-01-01T00:00:00.000Z')",
            "INSERT INTO attempts (id, operator_id, tutorial, tutorial_title, started, status, language) VALUES"
            " (1, 1, 'a', 'A', '2025-01-01T10:00:00.000Z', 'finished', 'en'),"
            " (2, 1, 'b', 'B', '2025-01-01T11:00:00.000Z', 'interrupted', 'en')",
            // interleaved: 1, 2, 1, 2, 1
            "INSERT INTO attempt_events (attempt_id, t, kind, text) VALUES (1, 0, 'k', 'a0'), (2, 0, 'k', 'b0'),"
            " (1, 1, 'k', 'a1'), (2, 1, 'k', 'b1'), (1, 2, 'k', 'a2')",
        };
        for (const QString& s : sql) ASSERT_TRUE(q.exec(s)) << str(s);
        q.finish();
        raw.close();
    }
    QSqlDatabase::removeDatabase("shared-test-v2");
    QString error;
    {
        RecordsDb db;
        ASSERT_TRUE(db.openSqlite(path, false, &error)) << str(error);
        Attempt a;
        ASSERT_TRUE(db.attempt(1, a, &error)) << str(error);
        EXPECT_TRUE(a.uid.isEmpty());
        EXPECT_TRUE(a.station.isEmpty());
        ASSERT_EQ(a.events.size(), 3);
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(a.events[i].seq, i);
            EXPECT_EQ(a.events[i].text, QStringLiteral("a%1").arg(i));
        }
        ASSERT_TRUE(db.attempt(2, a, &error)) << str(error);
        ASSERT_EQ(a.events.size(), 2);
        EXPECT_EQ(a.events[1].seq, 1);
        ASSERT_TRUE(db.appendEvents(2, {{2, "k", "b2"}}, &error)) << str(error);
        ASSERT_TRUE(db.attempt(2, a, &error)) << str(error);
        ASSERT_EQ(a.events.size(), 3);
        EXPECT_EQ(a.events[2].seq, 2);
        // a repeated index is refused, the whole batch
        AttemptEvent again(3, "k", "again");
        again.seq = 1;
        EXPECT_FALSE(db.appendEvents(2, {{3, "k", "b3"}, again}, &error));
        ASSERT_TRUE(db.attempt(2, a, &error)) << str(error);
        EXPECT_EQ(a.events.size(), 3);
    }
    SharedRecords st;
    ASSERT_TRUE(st.open(stationAt(path, {}, "bay-5"), &error)) << str(error);
    Attempt one, two;
    ASSERT_TRUE(st.journal().attempt(1, one, &error));
    ASSERT_TRUE(st.journal().attempt(2, two, &error));
    EXPECT_EQ(one.uid.size(), 36);
    EXPECT_EQ(two.uid.size(), 36);
    EXPECT_NE(one.uid, two.uid);
    EXPECT_EQ(st.pending().attempts, 2);  // they go to the server too
    EXPECT_EQ(st.pending().events, 6);
}
