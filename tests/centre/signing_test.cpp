// The centre's key: signed commands (forged, altered, stale and replayed ones refused)
// and sealed secrets.
#include "trainer/centre/signing.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

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
    Command older = c;
    older.nonce = 999;
    key.sign(older);
    EXPECT_FALSE(guard.accept(older, now, why));
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
