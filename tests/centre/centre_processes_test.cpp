// The training centre as it runs: real `padrob station` processes on loopback, the
// instructor in this test process and in `padrob instructor` processes. State flows,
// commands act on their station only, faults reach the physics, unsigned, forged and
// replayed commands are refused, a killed station is seen as gone and comes back, a
// station that shuts down says so, and the attempt's record holds what the instructor did.
#include "tests/common/components.h"
#include "centre_test_util.h"
#include "trainer/centre/bus.h"
#include "trainer/centre/instructor_node.h"
#include "trainer/centre/signing.h"
#include "trainer/records/records_db.h"
#include "../trainer/local_postgres.h"

#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <limits>
#include <optional>

using namespace trainer::centre;
using centre_test::waitFor;

namespace {

const QString kTut0 = QStringLiteral(PADROB_SOURCE_DIR "/resources/tutorials/t0_reach.tut");
const QString kTut1 = QStringLiteral(PADROB_SOURCE_DIR "/resources/tutorials/t1_wrist.tut");

class Centre : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(dir.isValid());
        keyFile = dir.filePath("centre.key");
        QString error;
        ASSERT_TRUE(CentreKey::create(keyFile, &error)) << error.toStdString();
        ASSERT_TRUE(key.load(keyFile, &error));
        BusOptions o = BusOptions::loopback(domain);
        o.reads = TopicAnnounce | TopicState | TopicEvent | TopicReply;
        o.key = key;
        bus = Bus::open(o, &error);
        ASSERT_TRUE(bus) << error.toStdString();
        instructor = std::make_unique<InstructorNode>(*bus, "test-instructor", key, 1.0);
        clock.start();
    }
    void TearDown() override
    {
        for (auto& p : stations) {
            if (p->state() != QProcess::NotRunning) {
                p->kill();
                p->waitForFinished(5000);
            }
        }
    }
    QStringList net() const
    {
        return {"--domain", QString::number(domain), "--loopback", "--key", keyFile};
    }
    QProcess* startStation(const std::string& name, const QString& records = {})
    {
        auto p = std::make_unique<QProcess>();
        QStringList args{"station", kTut0, kTut1, "--name", QString::fromStdString(name), "--demo", "--for", "120"};
        args += net();
        if (!records.isEmpty()) args += QStringList{"--records", records};
        p->setProcessChannelMode(QProcess::ForwardedErrorChannel);
        p->start(PADROB_CLI, args);
        EXPECT_TRUE(p->waitForStarted(5000));
        stations.push_back(std::move(p));
        return stations.back().get();
    }
    double now() const { return double(clock.nsecsElapsed()) * 1e-9; }
    void poll() { instructor->poll(now()); }
    const StationView* view(const std::string& name) const
    {
        auto it = instructor->stations().find(name);
        return it == instructor->stations().end() ? nullptr : &it->second;
    }
    bool seenRunning(const std::string& name)
    {
        const StationView* v = view(name);
        return v && v->hasState && v->presence == "up" && !v->announce.model.empty();
    }
    /// Sends a command and waits for the reply.
    std::optional<Reply> command(const std::string& station, const std::string& kind, const std::string& arg = {},
                                 const std::string& arg2 = {}, double value = std::nan(""))
    {
        const std::uint64_t nonce = instructor->send(station, kind, arg, arg2, value);
        EXPECT_NE(nonce, 0u);
        waitFor([&] { return instructor->reply(nonce).has_value(); }, 10000, [&] { poll(); });
        return instructor->reply(nonce);
    }
    /// The station's state after `ms` more of them.
    State stateAfter(const std::string& name, int ms)
    {
        QElapsedTimer t;
        t.start();
        waitFor([&] { return t.elapsed() >= ms; }, ms + 100, [&] { poll(); });
        return view(name)->state;
    }

    QTemporaryDir dir;
    QString keyFile;
    CentreKey key;
    const int domain = centre_test::domain();
    std::unique_ptr<Bus> bus;
    std::unique_ptr<InstructorNode> instructor;
    std::vector<std::unique_ptr<QProcess>> stations;
    QElapsedTimer clock;
};

}  // namespace

TEST_F(Centre, TwoStationsStreamStateAndObeyOnlyTheirOwnSignedCommands)
{
    const std::string s1 = centre_test::unique("S1"), s2 = centre_test::unique("S2");
    const QString records1 = dir.filePath("s1.sqlite");
    QProcess* p1 = startStation(s1, records1);
    startStation(s2);
    ASSERT_TRUE(waitFor([&] { return seenRunning(s1) && seenRunning(s2); }, 20000, [&] { poll(); }))
        << "both stations are heard";
    EXPECT_EQ(view(s1)->announce.model, "liner_manipulator_fluid");  // T0 runs on the fluid-power machine
    EXPECT_EQ(view(s1)->announce.tutorials, (std::vector<std::string>{"T0", "T1"}));
    EXPECT_EQ(view(s1)->announce.modelHash.size(), 64u);
    EXPECT_EQ(view(s1)->state.status, "idle");
    EXPECT_EQ(view(s1)->state.q.size(), 9u) << "the liner manipulator's pose: 9 tree joints";

    // state at display rate
    const std::uint64_t seq0 = view(s1)->state.seq;
    const State after = stateAfter(s1, 1000);
    EXPECT_GE(after.seq - seq0, 45u) << "about 60 states a second";
    EXPECT_LE(after.seq - seq0, 75u);

    // start on S1 only
    auto r = command(s1, "start", "T0", "OP-17");
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->accepted) << r->message;
    State s = stateAfter(s1, 1500);
    EXPECT_EQ(s.status, "running");
    EXPECT_EQ(s.tutorial, "T0");
    EXPECT_EQ(s.operatorCode, "OP-17");
    EXPECT_GT(s.attemptTime, 1.0);
    EXPECT_LT(s.attemptTime, 2.5) << "real time";
    EXPECT_EQ(view(s2)->state.status, "idle") << "a command acts on its station only";

    // the demonstration moves the machine; pause freezes it and the attempt's clock
    r = command(s1, "pause");
    ASSERT_TRUE(r && r->accepted);
    const State p0 = stateAfter(s1, 200);
    const State p1s = stateAfter(s1, 500);
    EXPECT_EQ(p1s.status, "paused");
    EXPECT_EQ(p0.attemptTime, p1s.attemptTime);
    EXPECT_EQ(p0.q, p1s.q);
    r = command(s1, "resume");
    ASSERT_TRUE(r && r->accepted);
    const State resumed = stateAfter(s1, 500);
    EXPECT_EQ(resumed.status, "running");
    EXPECT_NEAR(resumed.attemptTime - p1s.attemptTime, 0.5, 0.35);

    // a power cut: every valve closes; the machine holds although the demo pushes the levers
    // (on T0's fluid-power machine it settles on its oil: it moves no more than a fraction
    // of a millimetre or milliradian)
    r = command(s1, "inject", "power-cut");
    ASSERT_TRUE(r && r->accepted) << (r ? r->message : "");
    const State cut0 = stateAfter(s1, 200);
    const State cut1 = stateAfter(s1, 600);
    EXPECT_EQ(cut1.faults, "power-cut");
    EXPECT_TRUE(cut1.warnings & WarnFault);
    for (float u : cut1.commands) EXPECT_EQ(u, 0.0f);
    ASSERT_EQ(cut0.q.size(), cut1.q.size());
    for (std::size_t j = 0; j < cut0.q.size(); ++j) EXPECT_NEAR(cut0.q[j], cut1.q[j], 5e-4) << "joint " << j;
    r = command(s1, "clear", "power-cut");
    ASSERT_TRUE(r && r->accepted);
    EXPECT_EQ(stateAfter(s1, 200).faults, "");
    // an unknown drive is refused with the list of drives
    r = command(s1, "inject", "hose-burst", "NO SUCH DRIVE");
    ASSERT_TRUE(r);
    EXPECT_FALSE(r->accepted);
    EXPECT_NE(r->message.find("LEVANTE PLUMA"), std::string::npos) << r->message;

    // a command under another key, a forged mac, a replay: refused, nothing happens
    CentreKey other = CentreKey::fromBytes(QByteArray(32, 'x'));
    InstructorNode intruder(*bus, "intruder", other);
    const std::uint64_t n = intruder.send(s1, "stop");
    waitFor([&] { return intruder.reply(n).has_value(); }, 10000, [&] { intruder.poll(now()); });
    ASSERT_TRUE(intruder.reply(n));
    EXPECT_FALSE(intruder.reply(n)->accepted);
    EXPECT_EQ(intruder.reply(n)->message, "bad-signature");
    // a replay: a command the station took (a pause, resumed since), sent again as it was
    Command pause;
    pause.target = s1;
    pause.sender = "replayer";
    pause.nonce = 1;
    pause.issuedMs = QDateTime::currentMSecsSinceEpoch();
    pause.kind = "pause";
    key.sign(pause);
    auto replyTo = [&](std::uint64_t nonce) {
        std::optional<Reply> got;
        waitFor([&] { return got.has_value(); }, 10000, [&] {
            for (Reply& x : bus->takeReplies())
                if (x.sender == "replayer" && x.nonce == nonce && x.station == s1) got = x;
        });
        return got;
    };
    ASSERT_TRUE(bus->send(pause));
    auto first = replyTo(1);
    ASSERT_TRUE(first && first->accepted) << (first ? first->message : "no reply");
    r = command(s1, "resume");
    ASSERT_TRUE(r && r->accepted);
    ASSERT_TRUE(bus->send(pause));
    auto again = replyTo(1);
    ASSERT_TRUE(again);
    EXPECT_EQ(again->message, "replay");
    EXPECT_EQ(stateAfter(s1, 200).status, "running") << "refused commands did nothing";

    // another instructor, as a separate process, starts T1 on S2
    QProcess cli;
    cli.start(PADROB_CLI, QStringList{"instructor", "send", QString::fromStdString(s2), "start", "T1", "OP-5", "--name",
                                      "desk-2"} + net());
    ASSERT_TRUE(cli.waitForFinished(20000));
    EXPECT_EQ(cli.exitCode(), 0) << cli.readAllStandardOutput().toStdString() << cli.readAllStandardError().toStdString();
    EXPECT_TRUE(cli.readAllStandardOutput().contains("start done"));
    const State s2run = stateAfter(s2, 500);
    EXPECT_EQ(s2run.status, "running");
    EXPECT_EQ(s2run.tutorial, "T1");

    // stop S1's attempt and shut S1 down: it says it leaves
    r = command(s1, "stop");
    ASSERT_TRUE(r && r->accepted);
    EXPECT_EQ(stateAfter(s1, 200).status, "ended");
    p1->terminate();
    ASSERT_TRUE(p1->waitForFinished(10000));
    EXPECT_EQ(p1->exitCode(), 0);
    ASSERT_TRUE(waitFor([&] { return view(s1)->presence == "left"; }, 5000, [&] { poll(); }));

    // S1's record: the attempt, aborted, with the instructor's actions in order
    trainer::records::RecordsDb db;
    QString error;
    ASSERT_TRUE(db.openSqlite(records1, true, &error)) << error.toStdString();
    trainer::records::Operator op;
    ASSERT_TRUE(db.findOperator("OP-17", op, &error)) << error.toStdString();
    QList<trainer::records::Attempt> attempts;
    ASSERT_TRUE(db.attemptsOf(op.id, attempts, true, &error));
    ASSERT_EQ(attempts.size(), 1);
    EXPECT_EQ(attempts[0].status, trainer::records::AttemptStatus::Aborted);
    QStringList kinds;
    for (const auto& e : attempts[0].events) {
        if (e.kind == "instructor" || e.kind == "fault" || e.kind == "fault-cleared") kinds << e.kind + "/" + e.detail;
    }
    EXPECT_EQ(kinds.join(" "), QString("instructor/start:test-instructor instructor/pause:test-instructor "
                                       "instructor/resume:test-instructor fault/power-cut "
                                       "fault-cleared/power-cut instructor/pause:replayer "
                                       "instructor/resume:test-instructor instructor/stop:test-instructor"))
        << kinds.join(" ").toStdString();
}

// Issue 23: a node without the key announced a fake station and answered "done" to a
// command that never reached a station, and `padrob instructor send` printed "done". Now
// the fake station is not heard and the forged reply is dropped: the command is not
// answered (exit 1). A forged "done" after a station's refusal does not replace it either.
TEST_F(Centre, AForgedReplyOrAFakeStationNeverMakesTheInstructorSayDone)
{
    const std::string ghost = centre_test::unique("ghost");
    for (const CentreKey& forgerKey : {CentreKey(), CentreKey::fromBytes(QByteArray(32, 'x'))}) {
        BusOptions o = BusOptions::loopback(domain);
        o.reads = TopicCommand;
        o.key = forgerKey;
        QString error;
        auto forger = Bus::open(o, &error);
        ASSERT_TRUE(forger) << error.toStdString();
        Announce fake;
        fake.node = ghost;
        fake.role = "station";
        fake.model = "liner_manipulator_fluid";
        ASSERT_TRUE(forger->announce(fake));
        QProcess cli;
        cli.start(PADROB_CLI, QStringList{"instructor", "send", QString::fromStdString(ghost), "stop", "--name", "desk-3",
                                          "--timeout", "4"} + net());
        ASSERT_TRUE(cli.waitForStarted(5000));
        int forged = 0;
        waitFor([&] { return cli.state() == QProcess::NotRunning; }, 20000, [&] {
            State s;
            s.station = ghost;
            s.sentUs = wallUs();
            forger->publish(s);
            for (const Command& c : forger->takeCommands()) {
                forger->reply(centre_test::doneReply(c.target, c.sender, c.nonce));
                ++forged;
            }
        });
        ASSERT_EQ(cli.state(), QProcess::NotRunning);
        const QString out = QString::fromUtf8(cli.readAllStandardOutput());
        const QString err = QString::fromUtf8(cli.readAllStandardError());
        EXPECT_EQ(cli.exitCode(), 1) << out.toStdString() << err.toStdString();
        EXPECT_FALSE(out.contains("done")) << out.toStdString();
        EXPECT_TRUE(err.contains("did not answer")) << err.toStdString();
        EXPECT_EQ(forged, 0) << "the fake station was not heard, so no command went to it";
        poll();
        EXPECT_EQ(view(ghost), nullptr) << "the instructor does not list the fake station";
    }

    // a real station refuses; a forger then answers the same command "done"
    const std::string s6 = centre_test::unique("S6");
    startStation(s6);
    ASSERT_TRUE(waitFor([&] { return seenRunning(s6); }, 20000, [&] { poll(); }));
    BusOptions o = BusOptions::loopback(domain);
    o.reads = TopicCommand;
    QString error;
    auto forger = Bus::open(o, &error);
    ASSERT_TRUE(forger) << error.toStdString();
    const std::uint64_t nonce = instructor->send(s6, "resume");
    ASSERT_NE(nonce, 0u);
    ASSERT_TRUE(waitFor([&] { return instructor->reply(nonce).has_value(); }, 10000, [&] { poll(); }));
    EXPECT_EQ(instructor->reply(nonce)->message, "not-paused");
    ASSERT_TRUE(forger->reply(centre_test::doneReply(s6, "test-instructor", nonce)));
    stateAfter(s6, 500);
    EXPECT_FALSE(instructor->reply(nonce)->accepted) << "the forged 'done' replaced the station's refusal";
    EXPECT_EQ(instructor->reply(nonce)->message, "not-paused");
    EXPECT_GE(bus->dropped().badSignature, 1u);
}

// Issue 23: a signed command with the nonce 2^64-1 locked out every later command under
// that sender's name ("replay"); two instructors on one computer share the default name.
// Now the other instructor's commands (its own process, the same name) are taken.
TEST_F(Centre, AHugeNonceLocksOutNoOtherInstructor)
{
    const std::string s7 = centre_test::unique("S7");
    startStation(s7);
    ASSERT_TRUE(waitFor([&] { return seenRunning(s7); }, 20000, [&] { poll(); }));
    Command huge;
    huge.target = s7;
    huge.sender = "desk";
    huge.nonce = std::numeric_limits<std::uint64_t>::max();
    huge.issuedMs = QDateTime::currentMSecsSinceEpoch();
    huge.kind = "start";
    huge.arg = "T0";
    huge.arg2 = "OP-1";
    key.sign(huge);
    ASSERT_TRUE(bus->send(huge));
    std::optional<Reply> got;
    ASSERT_TRUE(waitFor([&] { return got.has_value(); }, 10000, [&] {
        for (Reply& x : bus->takeReplies())
            if (x.sender == "desk" && x.nonce == huge.nonce && x.station == s7) got = x;
    }));
    ASSERT_TRUE(got->accepted) << got->message;
    for (const char* kind : {"pause", "resume"}) {
        QProcess cli;
        cli.start(PADROB_CLI, QStringList{"instructor", "send", QString::fromStdString(s7), kind, "--name", "desk"} + net());
        ASSERT_TRUE(cli.waitForFinished(20000));
        const QByteArray out = cli.readAllStandardOutput();
        EXPECT_EQ(cli.exitCode(), 0) << out.toStdString() << cli.readAllStandardError().toStdString();
        EXPECT_TRUE(out.contains(QByteArray(kind) + " done")) << out.toStdString();
    }
    EXPECT_EQ(stateAfter(s7, 300).status, "running");
}

// Issue 23: an operator's code over 32 bytes is refused by the instructor, saying so.
TEST_F(Centre, AnOverLongOperatorCodeIsRefusedWithAClearError)
{
    const std::string s8 = centre_test::unique("S8");
    startStation(s8);
    ASSERT_TRUE(waitFor([&] { return seenRunning(s8); }, 20000, [&] { poll(); }));
    QProcess cli;
    cli.start(PADROB_CLI, QStringList{"instructor", "send", QString::fromStdString(s8), "start", "T0",
                                      QString(40, 'X')} + net());
    ASSERT_TRUE(cli.waitForFinished(20000));
    EXPECT_EQ(cli.exitCode(), 2);
    const QString err = QString::fromUtf8(cli.readAllStandardError());
    EXPECT_TRUE(err.contains("operatorCode: 40 bytes, at most 32")) << err.toStdString();
    EXPECT_EQ(stateAfter(s8, 300).status, "idle") << "nothing started";
}

TEST_F(Centre, AKilledStationIsSeenGoneAndComesBack)
{
    const std::string name = centre_test::unique("S3");
    QProcess* p = startStation(name);
    ASSERT_TRUE(waitFor([&] { return seenRunning(name); }, 20000, [&] { poll(); }));
    const std::uint64_t started = view(name)->announce.startedMs;
    ::kill(static_cast<pid_t>(p->processId()), SIGKILL);
    p->waitForFinished(5000);
    QElapsedTimer t;
    t.start();
    ASSERT_TRUE(waitFor([&] { return view(name)->presence != "up"; }, 10000, [&] { poll(); }));
    EXPECT_LT(t.elapsed(), 3000) << "seen gone within the silence limit (1 s here)";
    EXPECT_EQ(view(name)->presence, "silent") << "killed, it could not say it left";
    startStation(name);
    ASSERT_TRUE(waitFor([&] { return seenRunning(name) && view(name)->announce.startedMs > started; }, 20000,
                        [&] { poll(); }))
        << "the same station, started again, is back";
    auto r = command(name, "start", "T0", "OP-1");
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->accepted) << "and takes commands: " << r->message;
}

// The centre's records: a station records into its journal and syncs to the centre's
// PostgreSQL server; the server goes down in the middle of an attempt, the attempt goes
// on (the state says the records are offline), and when the server is back every event
// is there exactly once. The password travels sealed and is never written in plain text.
TEST_F(Centre, ARecordsOutageLosesNothingAndDuplicatesNothing)
{
    padrob_test::LocalPostgres pg;
    QString why;
    if (!pg.start(why)) PADROB_NEEDS_COMPONENT("no PostgreSQL server for the test: " << why.toStdString());
    const trainer::records::PostgresConfig server = pg.config();
    // the password, sealed with the centre's key by `padrob centre seal`
    QProcess seal;
    seal.start(PADROB_CLI, QStringList{"centre", "seal", "--key", keyFile});
    ASSERT_TRUE(seal.waitForStarted(5000));
    seal.write(server.password.toUtf8() + "\n");
    seal.closeWriteChannel();
    ASSERT_TRUE(seal.waitForFinished(10000));
    ASSERT_EQ(seal.exitCode(), 0) << seal.readAllStandardError().toStdString();
    const QByteArray sealed = seal.readAllStandardOutput().trimmed();
    EXPECT_FALSE(sealed.contains(server.password.toUtf8()));
    const QString passwordFile = dir.filePath("records.password");
    {
        QFile f(passwordFile);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(sealed + "\n");
    }
    const std::string name = centre_test::unique("S4");
    const QString journal = dir.filePath("s4.sqlite");
    auto p = std::make_unique<QProcess>();
    p->setProcessChannelMode(QProcess::MergedChannels);
    p->start(PADROB_CLI, QStringList{"station", kTut0, "--name", QString::fromStdString(name), "--demo", "--for", "120",
                                     "--records", journal, "--records-server",
                                     server.user + "@" + server.host + ":5432/" + server.database, "--records-password",
                                     passwordFile} +
                             net());
    ASSERT_TRUE(p->waitForStarted(5000));
    QProcess* station = p.get();
    stations.push_back(std::move(p));
    ASSERT_TRUE(waitFor([&] { return seenRunning(name); }, 20000, [&] { poll(); })) << station->readAll().toStdString();
    auto r = command(name, "start", "T0", "OP-9");
    ASSERT_TRUE(r && r->accepted);
    const QString where = "station = '" + QString::fromStdString(name) + "'";
    {
        padrob_test::RawPostgres raw(server);
        ASSERT_TRUE(raw.ok());
        ASSERT_TRUE(waitFor([&] { return raw.scalar("SELECT count(*) FROM attempts WHERE " + where).toInt() == 1; }, 10000))
            << "the running attempt reaches the server";
        EXPECT_EQ(raw.scalar("SELECT status FROM attempts WHERE " + where).toString(), "running");
    }
    // the outage, mid-attempt: the instructor's actions go on and are recorded locally
    pg.stop();
    ASSERT_TRUE(waitFor([&] { return view(name)->state.warnings & WarnRecordsOffline; }, 15000, [&] { poll(); }))
        << "the station says its records are offline";
    EXPECT_EQ(view(name)->state.status, "running") << "the attempt goes on";
    ASSERT_TRUE(command(name, "inject", "power-cut")->accepted);
    ASSERT_TRUE(command(name, "clear", "power-cut")->accepted);
    ASSERT_TRUE(command(name, "pause")->accepted);
    ASSERT_TRUE(command(name, "resume")->accepted);
    stateAfter(name, 300);
    ASSERT_TRUE(command(name, "stop")->accepted);
    stateAfter(name, 1500);
    // the server comes back: the station syncs by itself
    ASSERT_TRUE(pg.resume(why)) << why.toStdString();
    padrob_test::RawPostgres raw(server);
    ASSERT_TRUE(raw.ok());
    ASSERT_TRUE(waitFor([&] { return raw.scalar("SELECT status FROM attempts WHERE " + where).toString() == "aborted"; },
                        20000, [&] { poll(); }))
        << "the attempt's end reached the server after the outage";
    ASSERT_TRUE(waitFor([&] { return !(view(name)->state.warnings & WarnRecordsOffline); }, 10000, [&] { poll(); }));
    station->terminate();
    ASSERT_TRUE(station->waitForFinished(10000));
    const QByteArray output = station->readAll();
    EXPECT_FALSE(output.contains(server.password.toUtf8()));

    // the server's copy equals the journal's: every event once, in order
    trainer::records::RecordsDb local;
    QString error;
    ASSERT_TRUE(local.openSqlite(journal, true, &error)) << error.toStdString();
    trainer::records::Operator op;
    ASSERT_TRUE(local.findOperator("OP-9", op, &error));
    QList<trainer::records::Attempt> attempts;
    ASSERT_TRUE(local.attemptsOf(op.id, attempts, true, &error));
    ASSERT_EQ(attempts.size(), 1);
    const auto& events = attempts[0].events;
    const QString attemptOnServer = "(SELECT id FROM attempts WHERE " + where + ")";
    EXPECT_EQ(raw.scalar("SELECT count(*) FROM attempts WHERE " + where).toInt(), 1) << "no duplicate attempt";
    EXPECT_EQ(raw.scalar("SELECT count(*) FROM attempt_events WHERE attempt_id = " + attemptOnServer).toInt(), events.size());
    EXPECT_EQ(raw.scalar("SELECT count(DISTINCT seq) FROM attempt_events WHERE attempt_id = " + attemptOnServer).toInt(),
              events.size());
    QStringList local_, remote;
    for (const auto& e : events) local_ << e.kind + "/" + e.detail;
    remote << raw.scalar("SELECT string_agg(kind || '/' || detail, ' ' ORDER BY seq) FROM attempt_events WHERE attempt_id = " +
                         attemptOnServer)
                  .toString();
    EXPECT_EQ(local_.join(" "), remote.join(" "));
    EXPECT_TRUE(local_.join(" ").contains("fault/power-cut")) << local_.join(" ").toStdString();
    EXPECT_TRUE(local_.join(" ").contains("instructor/pause:test-instructor"));
    // the journal holds no password
    QFile j(journal);
    ASSERT_TRUE(j.open(QIODevice::ReadOnly));
    EXPECT_FALSE(j.readAll().contains(server.password.toUtf8()));
}

// The operator's devices through a station profile: a profile the model does not have
// is refused before the station joins; one it has opens its devices (none plugged in
// here: the station still comes up, the levers at rest, and says what is missing).
TEST_F(Centre, AStationTakesItsOperatorsDevicesFromAProfile)
{
    QProcess bad;
    bad.start(PADROB_CLI, QStringList{"station", kTut0, "--name", "S-bad", "--profile", "No such profile"} + net());
    ASSERT_TRUE(bad.waitForFinished(20000));
    EXPECT_EQ(bad.exitCode(), 2);
    EXPECT_TRUE(bad.readAllStandardError().contains("No such profile"));

    const std::string name = centre_test::unique("S5");
    auto p = std::make_unique<QProcess>();
    p->start(PADROB_CLI, QStringList{"station", kTut0, "--name", QString::fromStdString(name), "--profile", "Gamepad",
                                     "--for", "60"} +
                             net());
    ASSERT_TRUE(p->waitForStarted(5000));
    QProcess* station = p.get();
    stations.push_back(std::move(p));
    ASSERT_TRUE(waitFor([&] { return seenRunning(name); }, 20000, [&] { poll(); }));
    auto r = command(name, "start", "T0", "OP-2");
    ASSERT_TRUE(r && r->accepted);
    const State s0 = stateAfter(name, 300), s1 = stateAfter(name, 700);
    EXPECT_EQ(s1.status, "running");
    EXPECT_GT(s1.attemptTime, s0.attemptTime);
    for (float u : s1.commands) EXPECT_EQ(u, 0.0f) << "no gamepad: the levers rest";
    station->terminate();
    ASSERT_TRUE(station->waitForFinished(10000));
    EXPECT_EQ(station->exitCode(), 0);
}

// Issue 23 item 6: a station given only its own node key (padrob centre key --node) is
// heard and obeyed as with the centre's key; the key refuses to serve under another name,
// and an instructor refuses it (it needs the centre's key).
TEST_F(Centre, AStationRunsOnItsOwnNodeKeyAndOnlyUnderItsName)
{
    const std::string name = centre_test::unique("N1");
    const QString nodeKey = dir.filePath("n1.key");
    QProcess make;
    make.start(PADROB_CLI, {"centre", "key", "--key", keyFile, "--node", QString::fromStdString(name), nodeKey});
    ASSERT_TRUE(make.waitForFinished(20000));
    ASSERT_EQ(make.exitCode(), 0) << make.readAllStandardError().toStdString();
    EXPECT_TRUE(make.readAllStandardOutput().contains(key.forNode(name).fingerprint().toLatin1()));
    CentreKey loaded;
    QString error;
    ASSERT_TRUE(loaded.load(nodeKey, &error)) << error.toStdString();
    EXPECT_EQ(loaded.node(), name);

    // the station on its own key: heard, and it obeys the instructor's command
    auto p = std::make_unique<QProcess>();
    p->setProcessChannelMode(QProcess::ForwardedErrorChannel);
    p->start(PADROB_CLI, {"station", kTut0, "--name", QString::fromStdString(name), "--demo", "--for", "60", "--domain",
                          QString::number(domain), "--loopback", "--key", nodeKey});
    ASSERT_TRUE(p->waitForStarted(5000));
    stations.push_back(std::move(p));
    ASSERT_TRUE(waitFor([&] { return seenRunning(name); }, 20000, [&] { poll(); }));
    auto r = command(name, "start", "T0", "OP-1");
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->accepted) << r->message;
    EXPECT_EQ(stateAfter(name, 500).status, "running");
    EXPECT_EQ(bus->dropped().badSignature, 0u) << "nothing of the station was refused";

    // the same key under another name, and as an instructor's: refused, saying why
    QProcess other;
    other.start(PADROB_CLI, {"station", kTut0, "--name", "someone-else", "--for", "1", "--domain",
                             QString::number(domain), "--loopback", "--key", nodeKey});
    ASSERT_TRUE(other.waitForFinished(20000));
    EXPECT_EQ(other.exitCode(), 2);
    const QString otherErr = QString::fromUtf8(other.readAllStandardError());
    EXPECT_TRUE(otherErr.contains(QString::fromStdString(name)) && otherErr.contains("someone-else") &&
                otherErr.contains("--node"))
        << otherErr.toStdString();
    QProcess desk;
    desk.start(PADROB_CLI, {"instructor", "list", "--wait", "0.1", "--domain", QString::number(domain), "--loopback",
                            "--key", nodeKey});
    ASSERT_TRUE(desk.waitForFinished(20000));
    EXPECT_EQ(desk.exitCode(), 2);
    EXPECT_TRUE(desk.readAllStandardError().contains("centre's key"));
    // a node key is never made from a node key, nor over an existing file
    QProcess again;
    again.start(PADROB_CLI, {"centre", "key", "--key", nodeKey, "--node", "N2", dir.filePath("n2.key")});
    ASSERT_TRUE(again.waitForFinished(20000));
    EXPECT_EQ(again.exitCode(), 2);
    EXPECT_FALSE(QFile::exists(dir.filePath("n2.key")));
}
