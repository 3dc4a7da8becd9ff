// The centre's key: signed commands (forged, altered, stale and replayed ones refused)
// and sealed secrets.
#include "trainer/centre/signing.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace trainer::centre;

namespace {

CentreKey keyOf(char fill) { return CentreKey::fromBytes(QByteArray(32, fill)); }

Command command()
{
    Command c;
    c.target = "station-1";
    c.sender = "instructor";
    c.nonce = 1000;
    c.issuedMs = QDateTime::currentMSecsSinceEpoch();
    c.kind = "inject";
    c.arg = "hose-burst";
    c.arg2 = "Boom";
    c.value = 0.25;
    return c;
}

}  // namespace

TEST(CentreSigning, ASignedCommandVerifiesAndEveryAlteredFieldFails)
{
    const CentreKey key = keyOf('k');
    Command c = command();
    key.sign(c);
    EXPECT_EQ(c.mac.size(), 64u);
    EXPECT_TRUE(key.verify(c));
    EXPECT_FALSE(keyOf('x').verify(c)) << "another centre's key";
    auto altered = [&](auto change) {
        Command d = c;
        change(d);
        return key.verify(d);
    };
    EXPECT_FALSE(altered([](Command& d) { d.target = "station-2"; }));
    EXPECT_FALSE(altered([](Command& d) { d.sender = "someone"; }));
    EXPECT_FALSE(altered([](Command& d) { d.nonce += 1; }));
    EXPECT_FALSE(altered([](Command& d) { d.issuedMs += 1; }));
    EXPECT_FALSE(altered([](Command& d) { d.kind = "clear"; }));
    EXPECT_FALSE(altered([](Command& d) { d.arg = "power-cut"; }));
    EXPECT_FALSE(altered([](Command& d) { d.arg2 = "Wrist"; }));
    EXPECT_FALSE(altered([](Command& d) { d.value = 0.5; }));
    EXPECT_FALSE(altered([](Command& d) { d.mac[0] = d.mac[0] == 'a' ? 'b' : 'a'; }));
    EXPECT_FALSE(altered([](Command& d) { d.mac.clear(); }));
    // fields cannot be shifted into each other: "ab"+"c" differs from "a"+"bc"
    Command e = c, f = c;
    e.arg = "ab";
    e.arg2 = "c";
    f.arg = "a";
    f.arg2 = "bc";
    EXPECT_NE(signedBytes(e), signedBytes(f));
    EXPECT_FALSE(CentreKey().verify(c)) << "no key verifies nothing";
}

TEST(CentreSigning, TheGuardRefusesForgedStaleAndReplayedCommands)
{
    const CentreKey key = keyOf('k');
    CommandGuard guard(key, 30000);
    const std::int64_t now = QDateTime::currentMSecsSinceEpoch();
    std::string why;
    Command c = command();
    c.issuedMs = now;
    key.sign(c);
    EXPECT_TRUE(guard.accept(c, now, why)) << why;
    EXPECT_FALSE(guard.accept(c, now, why));
    EXPECT_EQ(why, "replay");
    // a lower nonce never accepted is no replay: nothing but the very command is refused
    Command older = c;
    older.nonce = 999;
    key.sign(older);
    EXPECT_TRUE(guard.accept(older, now, why)) << why;
    EXPECT_FALSE(guard.accept(older, now + 1000, why));
    EXPECT_EQ(why, "replay");
    Command next = c;
    next.nonce = 1001;
    key.sign(next);
    EXPECT_TRUE(guard.accept(next, now, why)) << why;
    // another sender has its own nonces
    Command other = c;
    other.sender = "instructor-2";
    other.nonce = 5;
    key.sign(other);
    EXPECT_TRUE(guard.accept(other, now, why)) << why;
    Command stale = c;
    stale.nonce = 2000;
    stale.issuedMs = now - 31000;
    key.sign(stale);
    EXPECT_FALSE(guard.accept(stale, now, why));
    EXPECT_EQ(why, "stale");
    stale.issuedMs = now + 31000;
    key.sign(stale);
    EXPECT_FALSE(guard.accept(stale, now, why));
    EXPECT_EQ(why, "stale");
    Command forged = c;
    forged.nonce = 3000;
    keyOf('f').sign(forged);
    EXPECT_FALSE(guard.accept(forged, now, why));
    EXPECT_EQ(why, "bad-signature");
    // a refused command does not use up its nonce: the genuine one still goes
    key.sign(forged);
    EXPECT_TRUE(guard.accept(forged, now, why)) << why;
    CommandGuard keyless{CentreKey()};
    EXPECT_FALSE(keyless.accept(c, now, why));
    EXPECT_EQ(why, "no-key");
    // over the limits: refused before anything else
    Command longCode = c;
    longCode.nonce = 4000;
    longCode.kind = "start";
    longCode.arg = "T0";
    longCode.arg2 = std::string(limits::kOperatorCode + 1, 'X');
    key.sign(longCode);
    EXPECT_FALSE(guard.accept(longCode, now, why));
    EXPECT_EQ(why, "too-long");
}

// Issue 23: a signed nonce of 2^64-1 shut out every later command under that sender's name
// (two instructors on one computer share the default name instructor@HOST), for as long as
// the station ran. Now only the very command is remembered, and only while it is fresh.
TEST(CentreSigning, AHugeNonceLocksOutNoInstructor)
{
    const CentreKey key = keyOf('k');
    CommandGuard guard(key, 30000);
    const std::int64_t now = QDateTime::currentMSecsSinceEpoch();
    std::string why;
    Command huge = command();
    huge.sender = "instructor@desk";
    huge.nonce = std::numeric_limits<std::uint64_t>::max();
    huge.issuedMs = now;
    key.sign(huge);
    ASSERT_TRUE(guard.accept(huge, now, why)) << why;
    // another instructor under the same name, with its clock's nonce
    Command other = command();
    other.sender = "instructor@desk";
    other.nonce = std::uint64_t(now) * 1000u;
    other.issuedMs = now + 10;
    key.sign(other);
    EXPECT_TRUE(guard.accept(other, now + 10, why)) << why;
    Command next = other;
    next.nonce += 1;
    key.sign(next);
    EXPECT_TRUE(guard.accept(next, now + 20, why)) << why;
    // the huge one replayed: refused while fresh, stale after; forgotten either way
    EXPECT_FALSE(guard.accept(huge, now + 1000, why));
    EXPECT_EQ(why, "replay");
    EXPECT_FALSE(guard.accept(huge, now + 31000, why));
    EXPECT_EQ(why, "stale");
    Command later = other;
    later.nonce = 7;
    later.issuedMs = now + 31000;
    key.sign(later);
    EXPECT_TRUE(guard.accept(later, now + 31000, why)) << why;
    EXPECT_EQ(guard.remembered(), 1u) << "only the commands of the last 30 s are kept";
}

TEST(CentreSigning, TheGuardsMemoryIsBoundedAndDrains)
{
    const CentreKey key = keyOf('k');
    CommandGuard guard(key, 30000, 3);
    const std::int64_t now = QDateTime::currentMSecsSinceEpoch();
    std::string why;
    Command c = command();
    c.issuedMs = now;
    for (std::uint64_t n = 1; n <= 3; ++n) {
        c.nonce = n;
        key.sign(c);
        ASSERT_TRUE(guard.accept(c, now, why)) << why;
    }
    c.nonce = 4;
    key.sign(c);
    EXPECT_FALSE(guard.accept(c, now, why));
    EXPECT_EQ(why, "busy");
    c.issuedMs = now + 31000;
    key.sign(c);
    EXPECT_TRUE(guard.accept(c, now + 31000, why)) << "the full memory drains as its commands go stale: " << why;
}

// Every topic's messages are signed, and a message altered in any field, signed with
// another key, or as another topic's, does not verify.
TEST(CentreSigning, AnnouncementsStatesEventsAndRepliesAreSigned)
{
    const CentreKey key = keyOf('k'), other = keyOf('x');
    Announce a;
    a.node = "station-1";
    a.role = "station";
    a.model = "liner";
    a.tutorials = {"T0", "T1"};
    a.startedMs = 5;
    a.sentMs = 6;
    State s;
    s.station = "station-1";
    s.seq = 3;
    s.q = {0.1, 0.2};
    s.commands = {0.5f};
    s.status = "running";
    s.operatorCode = "OP-1";
    Event e;
    e.station = "station-1";
    e.kind = "goal";
    e.text = "Goal reached";
    e.sentMs = 9;
    Reply r;
    r.station = "station-1";
    r.sender = "desk";
    r.nonce = 77;
    r.accepted = false;
    r.message = "not-paused";
    key.sign(a);
    key.sign(s);
    key.sign(e);
    key.sign(r);
    EXPECT_TRUE(key.verify(a) && key.verify(s) && key.verify(e) && key.verify(r));
    EXPECT_FALSE(other.verify(a) || other.verify(s) || other.verify(e) || other.verify(r)) << "another key";
    EXPECT_FALSE(CentreKey().verify(s)) << "no key verifies nothing";
    Announce a2 = a;
    a2.tutorials.push_back("T2");
    EXPECT_FALSE(key.verify(a2));
    a2 = a;
    a2.tutorials = {"T0,T1"};
    EXPECT_FALSE(key.verify(a2)) << "the list is signed entry by entry";
    a2 = a;
    a2.role = kRoleGone;
    EXPECT_FALSE(key.verify(a2)) << "no one else can say a node left";
    State s2 = s;
    s2.q[1] = 0.3;
    EXPECT_FALSE(key.verify(s2));
    s2 = s;
    s2.status = "paused";
    EXPECT_FALSE(key.verify(s2));
    s2 = s;
    s2.operatorCode = "OP-2";
    EXPECT_FALSE(key.verify(s2));
    Event e2 = e;
    e2.sentMs = 10;
    EXPECT_FALSE(key.verify(e2));
    Reply r2 = r;
    r2.accepted = true;
    EXPECT_FALSE(key.verify(r2)) << "a refusal cannot be turned into 'done'";
    r2 = r;
    r2.message = "done";
    EXPECT_FALSE(key.verify(r2));
    r2 = r;
    r2.nonce = 78;
    EXPECT_FALSE(key.verify(r2));
    // one topic's signature is no other's: a command's mac on a reply of the same bytes
    Reply unsigned_ = r;
    unsigned_.mac.clear();
    EXPECT_FALSE(key.verify(unsigned_));
    Command c;
    key.sign(c);
    Reply fromCommand = r;
    fromCommand.mac = c.mac;
    EXPECT_FALSE(key.verify(fromCommand));
}

TEST(CentreSigning, EveryStringAndSequenceHasABound)
{
    Announce a;
    a.node = std::string(limits::kName, 'n');
    EXPECT_EQ(limitProblem(a), "");
    a.node += 'n';
    EXPECT_EQ(limitProblem(a), "node: 65 bytes, at most 64");
    a.node = "station\n1";
    a.node[7] = '\n';
    EXPECT_EQ(limitProblem(a), "node: a control character");
    a.node = "s";
    a.tutorials.assign(limits::kTutorials + 1, "T");
    EXPECT_EQ(limitProblem(a), "tutorials: 65 entries, at most 64");
    State s;
    s.operatorCode = std::string(33, 'X');
    EXPECT_EQ(limitProblem(s), "operatorCode: 33 bytes, at most 32");
    s.operatorCode = "OP\x07";
    EXPECT_EQ(limitProblem(s), "operatorCode: a control character");
    s.operatorCode.clear();
    s.faults = std::string(limits::kText + 1, 'f');
    EXPECT_NE(limitProblem(s).find("faults"), std::string::npos);
    s.faults.clear();
    s.q.assign(limits::kJoints + 1, 0.0);
    EXPECT_EQ(limitProblem(s), "q: 257 entries, at most 256");
    Event e;
    e.text = std::string(limits::kText + 1, 't');
    EXPECT_NE(limitProblem(e).find("text"), std::string::npos);
    Command c;
    c.kind = "start";
    c.arg2 = std::string(33, 'X');
    EXPECT_EQ(limitProblem(c), "operatorCode: 33 bytes, at most 32");
    c.kind = "inject";
    EXPECT_EQ(limitProblem(c), "") << "an inject's second argument is a drive, up to 256 bytes";
    c.sender = std::string(100000, 's');
    EXPECT_EQ(limitProblem(c), "sender: 100000 bytes, at most 64");
    Reply r;
    r.message = std::string(limits::kText + 1, 'm');
    EXPECT_NE(limitProblem(r).find("message"), std::string::npos);
    // what a node says of its own is cut to fit, never inside a character
    EXPECT_EQ(clip("abc", 5), "abc");
    EXPECT_EQ(clip("a\xc3\xb1" "b", 2), "a");
    EXPECT_EQ(clip("a\xc3\xb1" "b", 3), "a\xc3\xb1");
}

TEST(CentreSigning, SealedSecretsOpenOnlyWithTheirKeyAndUnaltered)
{
    const CentreKey key = keyOf('k');
    const QString password = QStringLiteral("s3cret-contraseña");
    const QString sealed = key.seal(password);
    EXPECT_FALSE(sealed.contains(password));
    EXPECT_FALSE(QByteArray::fromBase64(sealed.toLatin1()).contains(password.toUtf8()));
    EXPECT_NE(sealed, key.seal(password)) << "a fresh nonce each time";
    QString out;
    ASSERT_TRUE(key.unseal(sealed, out));
    EXPECT_EQ(out, password);
    EXPECT_FALSE(keyOf('x').unseal(sealed, out));
    QByteArray bytes = QByteArray::fromBase64(sealed.toLatin1());
    bytes[20] = static_cast<char>(bytes[20] ^ 1);
    EXPECT_FALSE(key.unseal(QString::fromLatin1(bytes.toBase64()), out));
    EXPECT_FALSE(key.unseal(QStringLiteral("bm90IHNlYWxlZA=="), out));
}

TEST(CentreSigning, KeyFilesAreMadeOwnerOnlyAndCheckedWhenRead)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath("centre.key");
    QString error;
    ASSERT_TRUE(CentreKey::create(path, &error)) << error.toStdString();
    EXPECT_EQ(QFile(path).permissions() & (QFileDevice::ReadGroup | QFileDevice::ReadOther), QFileDevice::Permissions());
    CentreKey a, b;
    ASSERT_TRUE(a.load(path, &error)) << error.toStdString();
    EXPECT_TRUE(a.isSet());
    EXPECT_FALSE(CentreKey::create(path, &error)) << "never replaced";
    EXPECT_TRUE(error.contains("never overwritten"));
    const QString other = dir.filePath("other.key");
    ASSERT_TRUE(CentreKey::create(other, &error));
    ASSERT_TRUE(b.load(other, &error));
    EXPECT_NE(a.fingerprint(), b.fingerprint()) << "random keys";
    Command c = command();
    a.sign(c);
    EXPECT_TRUE(a.verify(c));
    EXPECT_FALSE(b.verify(c));
    // readable by others: refused, saying how to fix it
    QFile::setPermissions(path, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ReadOther);
    EXPECT_FALSE(CentreKey().load(path, &error));
    EXPECT_TRUE(error.contains("chmod 600")) << error.toStdString();
    // malformed
    const QString bad = dir.filePath("bad.key");
    {
        QFile f(bad);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly, QFileDevice::ReadOwner | QFileDevice::WriteOwner));
        f.write("0123456789abcdef\n");
    }
    EXPECT_FALSE(CentreKey().load(bad, &error));
    EXPECT_TRUE(error.contains("64 hexadecimal digits")) << error.toStdString();
    EXPECT_FALSE(CentreKey().load(dir.filePath("missing.key"), &error));
}

// Issue 23 item 6: a station given only its own node key signs only its own messages and
// checks only the commands for it, so it cannot pass for another station; the centre's
// key (the instructors') derives every node key and checks everything.
TEST(CentreSigning, ANodeKeyCoversOnlyItsNode)
{
    const CentreKey centre = keyOf('k');
    const CentreKey s1 = centre.forNode("station-1"), s2 = centre.forNode("station-2");
    ASSERT_TRUE(s1.isSet() && s2.isSet());
    EXPECT_EQ(s1.node(), "station-1");
    EXPECT_TRUE(centre.node().empty());
    EXPECT_NE(s1.fingerprint(), s2.fingerprint());
    EXPECT_NE(s1.fingerprint(), centre.fingerprint()) << "a node key is not the centre's";
    EXPECT_FALSE(s1.forNode("station-2").isSet()) << "a node key derives no other";
    EXPECT_EQ(s1.forNode("station-1").fingerprint(), s1.fingerprint());
    EXPECT_FALSE(keyOf('x').forNode("station-1").verify([&] {
        State s;
        s.station = "station-1";
        s1.sign(s);
        return s;
    }())) << "another centre's node key";

    // station-1's own messages: signed by its key, believed by the centre's
    State st;
    st.station = "station-1";
    st.status = "running";
    s1.sign(st);
    EXPECT_EQ(st.mac.size(), 64u);
    EXPECT_TRUE(centre.verify(st));
    EXPECT_TRUE(s1.verify(st));
    EXPECT_FALSE(s2.verify(st)) << "another station's key does not cover it";
    Reply r;
    r.station = "station-1";
    r.sender = "desk";
    r.nonce = 7;
    r.accepted = true;
    s1.sign(r);
    EXPECT_TRUE(centre.verify(r));
    Announce a;
    a.node = "station-1";
    a.role = "station";
    s1.sign(a);
    EXPECT_TRUE(centre.verify(a));

    // station-2 passing for station-1: it cannot sign (the mac is left empty), and what it
    // signs as itself does not verify once the station is changed
    State forged;
    forged.station = "station-1";
    forged.status = "done";
    s2.sign(forged);
    EXPECT_TRUE(forged.mac.empty());
    EXPECT_FALSE(centre.verify(forged));
    forged.station = "station-2";
    s2.sign(forged);
    EXPECT_TRUE(centre.verify(forged));
    forged.station = "station-1";
    EXPECT_FALSE(centre.verify(forged)) << "a signature is the signer's node's";
    Reply fakeDone = r;
    fakeDone.mac.clear();
    s2.sign(fakeDone);
    EXPECT_FALSE(centre.verify(fakeDone));
    Announce fakeStation = a;
    s2.sign(fakeStation);
    EXPECT_FALSE(centre.verify(fakeStation));

    // commands: the instructor signs with the centre's key; station-1's key checks those
    // for it, and signs none for station-2
    Command c = command();
    centre.sign(c);
    EXPECT_TRUE(s1.verify(c));
    EXPECT_FALSE(s2.verify(c));
    Command toOther = command();
    toOther.target = "station-2";
    s1.sign(toOther);
    EXPECT_TRUE(toOther.mac.empty());
    std::string why;
    CommandGuard guard2(s2);
    toOther.mac = std::string(64, 'a');
    EXPECT_FALSE(guard2.accept(toOther, QDateTime::currentMSecsSinceEpoch(), why));
    EXPECT_EQ(why, "bad-signature");
    centre.sign(toOther);
    EXPECT_TRUE(guard2.accept(toOther, QDateTime::currentMSecsSinceEpoch(), why)) << why;
}

TEST(CentreSigning, NodeKeyFilesNameTheirNode)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QString error;
    const QString centrePath = dir.filePath("centre.key"), nodePath = dir.filePath("station-1.key");
    ASSERT_TRUE(CentreKey::create(centrePath, &error));
    CentreKey centre;
    ASSERT_TRUE(centre.load(centrePath, &error));
    ASSERT_TRUE(centre.createNodeKey("station-1", nodePath, &error)) << error.toStdString();
    EXPECT_EQ(QFile(nodePath).permissions() & (QFileDevice::ReadGroup | QFileDevice::ReadOther), QFileDevice::Permissions());
    CentreKey node;
    ASSERT_TRUE(node.load(nodePath, &error)) << error.toStdString();
    EXPECT_EQ(node.node(), "station-1");
    EXPECT_EQ(node.fingerprint(), centre.forNode("station-1").fingerprint());
    State s;
    s.station = "station-1";
    node.sign(s);
    EXPECT_TRUE(centre.verify(s));
    // never replaced; a node key makes no node keys; names are bounded
    EXPECT_FALSE(centre.createNodeKey("station-1", nodePath, &error));
    EXPECT_TRUE(error.contains("never overwritten")) << error.toStdString();
    EXPECT_FALSE(node.createNodeKey("station-2", dir.filePath("s2.key"), &error));
    EXPECT_TRUE(error.contains("centre's key")) << error.toStdString();
    EXPECT_FALSE(centre.createNodeKey("two words", dir.filePath("s3.key"), &error));
    EXPECT_FALSE(centre.createNodeKey(std::string(65, 'n'), dir.filePath("s4.key"), &error));
    EXPECT_FALSE(QFile::exists(dir.filePath("s2.key")) || QFile::exists(dir.filePath("s3.key")));
    // a node key file without its node's name is refused, saying how to make one
    const QString bad = dir.filePath("bad.key");
    {
        QFile f(bad);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly, QFileDevice::ReadOwner | QFileDevice::WriteOwner));
        f.write("padrob-node-key \n" + QByteArray(64, 'a') + "\n");
    }
    EXPECT_FALSE(CentreKey().load(bad, &error));
    EXPECT_TRUE(error.contains("--node NAME")) << error.toStdString();
    // a huge file is not read whole, and is no key
    const QString huge = dir.filePath("huge.key");
    {
        QFile f(huge);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly, QFileDevice::ReadOwner | QFileDevice::WriteOwner));
        f.write(QByteArray(1 << 20, 'a'));
    }
    EXPECT_FALSE(CentreKey().load(huge, &error));
}
