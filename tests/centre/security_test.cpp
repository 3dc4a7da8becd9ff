// DDS Security on the centre's bus: the PKI that `padrob centre pki` makes, nodes with
// identities from it exchanging states and commands (in this process, and with a real
// `padrob station --security` process), a node with a missing or foreign certificate
// refused at Bus::open, and intruders — one without DDS Security, one with an identity from
// another centre's CA, both holding the right centre key — that neither see the secured
// station's state nor get a command through to it.
#include "centre_test_util.h"
#include "trainer/centre/bus.h"
#include "trainer/centre/instructor_node.h"
#include "trainer/centre/pki.h"
#include "trainer/centre/signing.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

using namespace trainer::centre;
using centre_test::waitFor;

namespace {

const QString kTut0 = QStringLiteral(PADROB_SOURCE_DIR "/resources/tutorials/t0_reach.tut");

class Security : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(tmp.isValid());
        pkiDir = tmp.filePath("pki");
        QString error;
        ASSERT_TRUE(pki::createCentre(pkiDir, &error)) << error.toStdString();
        keyFile = tmp.filePath("centre.key");
        ASSERT_TRUE(CentreKey::create(keyFile, &error)) << error.toStdString();
        ASSERT_TRUE(key.load(keyFile, &error)) << error.toStdString();
    }
    BusOptions secured(const std::string& node, unsigned reads) const
    {
        BusOptions o = BusOptions::loopback(domain);
        o.securityDir = pkiDir;
        o.node = QString::fromStdString(node);
        o.reads = reads;
        o.key = key;
        return o;
    }
    /// This test binary as an intruder (IntruderHelper below) for `seconds`: its counts on stdout.
    QString intrude(const std::string& station, const QString& securityDir = {}, const QString& node = {})
    {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("PADROB_INTRUDER_STATION", QString::fromStdString(station));
        env.insert("PADROB_INTRUDER_DOMAIN", QString::number(domain));
        env.insert("PADROB_INTRUDER_KEY", keyFile);
        env.insert("PADROB_INTRUDER_SECURITY", securityDir);
        env.insert("PADROB_INTRUDER_NODE", node);
        p.setProcessEnvironment(env);
        p.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        p.start(QCoreApplication::applicationFilePath(), {"--gtest_filter=IntruderHelper.*"});
        EXPECT_TRUE(p.waitForFinished(30000));
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        const qsizetype at = out.indexOf("INTRUDER ");
        return at < 0 ? out : out.mid(at).section('\n', 0, 0);
    }

    QTemporaryDir tmp;
    QString pkiDir, keyFile;
    CentreKey key;
    const int domain = centre_test::domain();
};

}  // namespace

TEST_F(Security, PkiFilesAndTheirModes)
{
    QString error;
    ASSERT_TRUE(pki::issueNode(pkiDir, "node-1", &error)) << error.toStdString();
    const pki::NodeFiles f = pki::nodeFiles(pkiDir, "node-1");
    for (const QString& file : f.all()) EXPECT_TRUE(QFileInfo(file).isFile()) << file.toStdString();
    const auto owner = QFileDevice::ReadOwner | QFileDevice::WriteOwner;
    for (const QString& k : {pkiDir + "/identity_ca.key", pkiDir + "/permissions_ca.key", f.privateKey}) {
        EXPECT_EQ(QFile(k).permissions() & ~(owner | QFileDevice::ReadUser | QFileDevice::WriteUser), QFileDevice::Permissions())
            << k.toStdString() << " is the owner's only";
    }
    QFile gov(f.governance);
    ASSERT_TRUE(gov.open(QIODevice::ReadOnly));
    const QByteArray g = gov.readAll();
    EXPECT_TRUE(g.contains("multipart/signed")) << "S/MIME signed";
    EXPECT_TRUE(g.contains("<data_protection_kind>ENCRYPT</data_protection_kind>"));
    EXPECT_TRUE(pki::checkNode(pkiDir, "node-1", &error)) << error.toStdString();
    EXPECT_FALSE(pki::issueNode(pkiDir, "node-1", &error)) << "never replaced";
    EXPECT_FALSE(pki::createCentre(pkiDir, &error)) << "never replaced";
    EXPECT_FALSE(pki::issueNode(pkiDir, "bad name,CN=x", &error));
}

TEST_F(Security, ANodeWithoutAValidIdentityCannotOpenTheBus)
{
    QString error;
    // no identity issued
    EXPECT_FALSE(Bus::open(secured("nobody", AllTopics), &error));
    EXPECT_TRUE(error.contains("identity.pem") && error.contains("padrob centre pki")) << error.toStdString();
    // an identity from another centre's CA, copied in
    const QString other = tmp.filePath("other");
    ASSERT_TRUE(pki::createCentre(other, &error));
    ASSERT_TRUE(pki::issueNode(other, "rogue", &error));
    ASSERT_TRUE(QDir().mkpath(pkiDir + "/nodes/rogue"));
    for (const char* f : {"identity.pem", "identity.key", "permissions.p7s"})
        ASSERT_TRUE(QFile::copy(other + "/nodes/rogue/" + f, pkiDir + "/nodes/rogue/" + f));
    error.clear();
    EXPECT_FALSE(Bus::open(secured("rogue", AllTopics), &error));
    EXPECT_TRUE(error.contains("identity.pem") && error.contains("not issued by")) << error.toStdString();
    // a forged permissions document (the node's own, re-signed by the other centre): DDS refuses it
    ASSERT_TRUE(pki::issueNode(pkiDir, "forged", &error));
    QFile::remove(pkiDir + "/nodes/forged/permissions.p7s");
    ASSERT_TRUE(QFile::copy(other + "/nodes/rogue/permissions.p7s", pkiDir + "/nodes/forged/permissions.p7s"));
    error.clear();
    EXPECT_FALSE(Bus::open(secured("forged", AllTopics), &error));
    EXPECT_TRUE(error.contains("DDS Security")) << error.toStdString();
}

TEST_F(Security, SecuredNodesInOneProcessExchangeStatesAndCommands)
{
    const std::string st = centre_test::unique("sec-a"), in = centre_test::unique("sec-b");
    QString error;
    ASSERT_TRUE(pki::issueNode(pkiDir, QString::fromStdString(st), &error)) << error.toStdString();
    ASSERT_TRUE(pki::issueNode(pkiDir, QString::fromStdString(in), &error)) << error.toStdString();
    auto station = Bus::open(secured(st, TopicCommand), &error);
    ASSERT_TRUE(station) << error.toStdString();
    auto instructor = Bus::open(secured(in, TopicState | TopicReply), &error);
    ASSERT_TRUE(instructor) << error.toStdString();
    State s;
    s.station = st;
    s.status = "idle";
    std::vector<State> states;
    std::vector<Command> commands;
    Command c;
    c.target = st;
    c.sender = in;
    c.kind = "pause";
    ASSERT_TRUE(waitFor([&] { return !states.empty() && !commands.empty(); }, 8000, [&] {
        s.sentUs = wallUs();
        station->publish(s);
        instructor->send(c);
        for (State& x : instructor->takeStates()) states.push_back(x);
        for (Command& x : station->takeCommands()) commands.push_back(x);
    })) << "states " << states.size() << ", commands " << commands.size();
    EXPECT_EQ(states.front().station, st);
    EXPECT_EQ(commands.front().kind, "pause");
}

TEST_F(Security, IntrudersNeitherSeeNorCommandASecuredStation)
{
    const std::string st = centre_test::unique("sec-station"), in = centre_test::unique("sec-instructor");
    QString error;
    ASSERT_TRUE(pki::issueNode(pkiDir, QString::fromStdString(in), &error)) << error.toStdString();
    // the station's identity from the command line, as a centre's administrator makes it
    QProcess make;
    make.start(PADROB_CLI, {"centre", "pki", pkiDir, "--node", QString::fromStdString(st)});
    ASSERT_TRUE(make.waitForFinished(20000));
    ASSERT_EQ(make.exitCode(), 0) << make.readAllStandardError().toStdString();

    QProcess station;
    station.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    station.start(PADROB_CLI, {"station", kTut0, "--name", QString::fromStdString(st), "--demo", "--for", "90", "--domain",
                               QString::number(domain), "--loopback", "--key", keyFile, "--security", pkiDir});
    ASSERT_TRUE(station.waitForStarted(5000));
    struct Kill {
        QProcess& p;
        ~Kill()
        {
            p.kill();
            p.waitForFinished(5000);
        }
    } kill{station};

    auto bus = Bus::open(secured(in, TopicAnnounce | TopicState | TopicEvent | TopicReply), &error);
    ASSERT_TRUE(bus) << error.toStdString();
    InstructorNode instructor(*bus, in, key, 1.0);
    QElapsedTimer clock;
    clock.start();
    auto poll = [&] { instructor.poll(double(clock.nsecsElapsed()) * 1e-9); };
    auto view = [&]() -> const StationView* {
        auto it = instructor.stations().find(st);
        return it == instructor.stations().end() ? nullptr : &it->second;
    };
    ASSERT_TRUE(waitFor([&] { return view() && view()->hasState; }, 20000, poll)) << "the secured instructor hears the station";
    const std::uint64_t nonce = instructor.send(st, "start", "T0", "OP-1");
    ASSERT_TRUE(waitFor([&] { return instructor.reply(nonce).has_value(); }, 10000, poll));
    EXPECT_TRUE(instructor.reply(nonce)->accepted) << instructor.reply(nonce)->message;
    ASSERT_TRUE(waitFor([&] { return view()->state.status == "running"; }, 5000, poll));

    // without DDS Security, with the centre's key: sees nothing, its pauses never arrive
    EXPECT_EQ(intrude(st).toStdString(), "INTRUDER states=0 replies=0");
    // with an identity of another centre's PKI (valid there): the same
    const QString other = tmp.filePath("other");
    ASSERT_TRUE(pki::createCentre(other, &error));
    ASSERT_TRUE(pki::issueNode(other, "rogue", &error));
    EXPECT_EQ(intrude(st, other, "rogue").toStdString(), "INTRUDER states=0 replies=0");
    EXPECT_TRUE(waitFor([&] { return view()->presence == "up"; }, 3000, poll)) << "still heard by the secured instructor";
    EXPECT_EQ(view()->state.status, "running") << "the station never paused";

    // the control: the same helper with an identity of this centre hears the station, and
    // its pauses are answered and obeyed
    const QString friendName = QString::fromStdString(centre_test::unique("sec-friend"));
    ASSERT_TRUE(pki::issueNode(pkiDir, friendName, &error)) << error.toStdString();
    const QString control = intrude(st, pkiDir, friendName);
    EXPECT_TRUE(control.startsWith("INTRUDER states=") && !control.contains("states=0") && !control.contains("replies=0"))
        << control.toStdString();
    EXPECT_TRUE(waitFor([&] { return view()->state.status == "paused"; }, 3000, poll)) << view()->state.status;
}

// Run by IntrudersNeitherSeeNorCommandASecuredStation in a process of its own (Cyclone has
// one domain per process): for 4 s it listens and sends signed pause commands to the station.
TEST(IntruderHelper, Intrude)
{
    const QByteArray station = qgetenv("PADROB_INTRUDER_STATION");
    if (station.isEmpty()) GTEST_SKIP() << "run by Security.IntrudersNeitherSeeNorCommandASecuredStation";
    BusOptions o = BusOptions::loopback(qEnvironmentVariableIntValue("PADROB_INTRUDER_DOMAIN"));
    o.securityDir = qEnvironmentVariable("PADROB_INTRUDER_SECURITY");
    o.node = qEnvironmentVariable("PADROB_INTRUDER_NODE");
    o.reads = TopicState | TopicReply | TopicAnnounce;
    QString error;
    CentreKey key;
    ASSERT_TRUE(key.load(qEnvironmentVariable("PADROB_INTRUDER_KEY"), &error));
    o.key = key;  // it even holds the centre's key: DDS Security still keeps it out
    auto bus = Bus::open(o, &error);
    ASSERT_TRUE(bus) << error.toStdString();
    InstructorNode intruder(*bus, "intruder", key, 1.0);
    int states = 0, replies = 0;
    std::vector<std::uint64_t> nonces;
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 4000) {
        if (nonces.size() < 20) nonces.push_back(intruder.send(station.toStdString(), "pause"));
        bus->wait(100);
        for (const State& s : bus->takeStates()) states += s.station == station.toStdString();
        for (const Reply& r : bus->takeReplies()) replies += r.station == station.toStdString();
        bus->takeAnnounces();
    }
    std::printf("INTRUDER states=%d replies=%d\n", states, replies);
    std::fflush(stdout);
}
