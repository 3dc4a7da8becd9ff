#include "trainer/centre/signing.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>
#include <QMessageAuthenticationCode>
#include <QRandomGenerator>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

namespace trainer::centre {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(CentreKey)
};

/// The first line of a node's key file, before the node's name.
const QByteArray kNodeKeyTag("padrob-node-key ");

/// A name a node key file can hold: 1 to limits::kName bytes, no spaces or control characters.
bool validNodeName(const std::string& node)
{
    return !node.empty() && node.size() <= limits::kName &&
           std::none_of(node.begin(), node.end(), [](char c) { return static_cast<unsigned char>(c) <= ' '; });
}

void put(QByteArray& out, const std::string& s)
{
    const quint32 n = static_cast<quint32>(s.size());
    out.append(reinterpret_cast<const char*>(&n), sizeof n);
    out.append(s.data(), static_cast<qsizetype>(s.size()));
}

template <typename T>
void putValue(QByteArray& out, T v)
{
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

QByteArray hmac(const QByteArray& key, const QByteArray& data)
{
    return QMessageAuthenticationCode::hash(data, key, QCryptographicHash::Sha256);
}

bool sameBytes(const QByteArray& a, const QByteArray& b)
{
    if (a.size() != b.size()) return false;
    unsigned char diff = 0;
    for (qsizetype i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
    return diff == 0;
}

/// Keys derived from the centre's key, one per purpose.
QByteArray derive(const QByteArray& key, const char* purpose) { return hmac(key, QByteArray("padrob-centre:") + purpose); }

QByteArray keystream(const QByteArray& encKey, const QByteArray& nonce, qsizetype length)
{
    QByteArray out;
    for (quint32 block = 0; out.size() < length; ++block) {
        QByteArray in = nonce;
        putValue(in, block);
        out += hmac(encKey, in);
    }
    out.truncate(length);
    return out;
}

/// A double as signed: NaN has many bit patterns, so one is signed for all.
void putDouble(QByteArray& out, double v) { putValue(out, std::isnan(v) ? std::numeric_limits<double>::quiet_NaN() : v); }

template <typename T>
void putSequence(QByteArray& out, const std::vector<T>& v)
{
    putValue(out, static_cast<quint32>(v.size()));
    for (const T& x : v) {
        if constexpr (std::is_same_v<T, std::string>) put(out, x);
        else if constexpr (std::is_floating_point_v<T>) putDouble(out, static_cast<double>(x));
        else putValue(out, x);
    }
}

// the key of each topic's signatures, derived from the centre's key
const char* purposeOf(const Command&) { return "command"; }
const char* purposeOf(const Announce&) { return "announce"; }
const char* purposeOf(const State&) { return "state"; }
const char* purposeOf(const Event&) { return "event"; }
const char* purposeOf(const Reply&) { return "reply"; }

template <typename M>
QByteArray macOf(const QByteArray& key, const M& m)
{
    return hmac(derive(key, purposeOf(m)), signedBytes(m)).toHex();
}

}  // namespace

QByteArray signedBytes(const Command& c)
{
    QByteArray out("padrob-command-v1");
    put(out, c.target);
    put(out, c.sender);
    putValue(out, c.nonce);
    putValue(out, c.issuedMs);
    put(out, c.kind);
    put(out, c.arg);
    put(out, c.arg2);
    putDouble(out, c.value);
    return out;
}

QByteArray signedBytes(const Announce& a)
{
    QByteArray out("padrob-announce-v1");
    put(out, a.node);
    put(out, a.role);
    put(out, a.host);
    putValue(out, static_cast<qint32>(a.pid));
    put(out, a.model);
    put(out, a.modelHash);
    putSequence(out, a.tutorials);
    put(out, a.language);
    putValue(out, a.startedMs);
    putValue(out, a.sentMs);
    return out;
}

QByteArray signedBytes(const State& s)
{
    QByteArray out("padrob-state-v1");
    put(out, s.station);
    putValue(out, s.seq);
    putValue(out, s.sentUs);
    putDouble(out, s.simTime);
    putSequence(out, s.q);
    putSequence(out, s.commands);
    put(out, s.tutorial);
    put(out, s.status);
    put(out, s.operatorCode);
    putDouble(out, s.attemptTime);
    putDouble(out, s.score);
    putValue(out, static_cast<qint32>(s.goal));
    putValue(out, static_cast<qint32>(s.goals));
    putDouble(out, s.clearance);
    putDouble(out, s.workerDistance);
    putValue(out, s.warnings);
    put(out, s.faults);
    put(out, s.endReason);
    return out;
}

QByteArray signedBytes(const Event& e)
{
    QByteArray out("padrob-event-v1");
    put(out, e.station);
    putValue(out, e.seq);
    putDouble(out, e.t);
    put(out, e.tutorial);
    put(out, e.kind);
    put(out, e.text);
    put(out, e.detail);
    putDouble(out, e.value);
    putDouble(out, e.penalty);
    putValue(out, e.sentMs);
    return out;
}

QByteArray signedBytes(const Reply& r)
{
    QByteArray out("padrob-reply-v1");
    put(out, r.station);
    put(out, r.sender);
    putValue(out, r.nonce);
    putValue(out, static_cast<quint8>(r.accepted ? 1 : 0));
    put(out, r.message);
    return out;
}

bool CentreKey::load(const QString& path, QString* error)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error) *error = Tr::tr("Cannot read the centre's key file %1: %2.").arg(path, f.errorString());
        return false;
    }
    const QFileInfo info(path);
    if (info.permissions() & (QFileDevice::ReadGroup | QFileDevice::ReadOther | QFileDevice::WriteGroup |
                              QFileDevice::WriteOther)) {
        if (error) {
            *error = Tr::tr("The centre's key file %1 can be read by other users: make it readable by its owner only "
                            "(chmod 600 %1).")
                         .arg(path);
        }
        return false;
    }
    // a key file is a line or two: what is longer is not one (and is not read whole)
    QByteArray text = f.read(4096).trimmed();
    std::string node;
    if (text.startsWith(kNodeKeyTag)) {
        const qsizetype eol = text.indexOf('\n');
        node = text.mid(kNodeKeyTag.size(), eol < 0 ? -1 : eol - kNodeKeyTag.size()).trimmed().toStdString();
        text = eol < 0 ? QByteArray() : text.mid(eol + 1).trimmed();
        if (!validNodeName(node)) {
            if (error) {
                *error = Tr::tr("The node key file %1 must name its node on its first line ('%2 NAME', a name of at "
                                "most %3 bytes without spaces); make one with 'padrob centre key --key CENTRE-KEY "
                                "--node NAME FILE'.")
                             .arg(path, QString::fromLatin1(kNodeKeyTag.trimmed()))
                             .arg(limits::kName);
            }
            return false;
        }
    }
    const QByteArray bytes = QByteArray::fromHex(text);
    if (text.size() != 64 || bytes.size() != 32 || bytes.toHex() != text.toLower()) {
        if (error) {
            *error = Tr::tr("The centre's key file %1 must hold 64 hexadecimal digits (32 bytes); make one with "
                            "'padrob centre key FILE'.")
                         .arg(path);
        }
        return false;
    }
    m_key = bytes;
    m_node = node;
    return true;
}

namespace {

bool writeKeyFile(const QString& path, const QByteArray& content, QString* error)
{
    if (QFileInfo::exists(path) || QFileInfo(path).isSymLink()) {
        if (error) *error = Tr::tr("%1 exists already: a centre's key is never overwritten.").arg(path);
        return false;
    }
    QFile f(path);
    // created owner-only before anything is written, and on the disk before we say so
    if (!f.open(QIODevice::WriteOnly | QIODevice::NewOnly, QFileDevice::ReadOwner | QFileDevice::WriteOwner) ||
        f.write(content) != content.size() || !f.flush() || ::fsync(f.handle()) != 0) {
        if (error) *error = Tr::tr("Cannot write the centre's key file %1: %2.").arg(path, f.errorString());
        return false;
    }
    return true;
}

}  // namespace

bool CentreKey::create(const QString& path, QString* error)
{
    QByteArray bytes(32, Qt::Uninitialized);
    QRandomGenerator::system()->fillRange(reinterpret_cast<quint32*>(bytes.data()), 8);
    return writeKeyFile(path, bytes.toHex() + "\n", error);
}

bool CentreKey::createNodeKey(const std::string& node, const QString& path, QString* error) const
{
    if (!isSet() || !m_node.empty()) {
        if (error) *error = Tr::tr("A node's key is made from the centre's key, not from another node's key.");
        return false;
    }
    if (!validNodeName(node)) {
        if (error) *error = Tr::tr("A node's name has 1 to %1 bytes and no spaces.").arg(limits::kName);
        return false;
    }
    return writeKeyFile(path, kNodeKeyTag + QByteArray::fromStdString(node) + "\n" + scopeKey(node).toHex() + "\n", error);
}

CentreKey CentreKey::forNode(const std::string& node) const
{
    CentreKey k;
    if (!coversNode(node)) return k;
    k.m_key = scopeKey(node);
    k.m_node = node;
    return k;
}

QByteArray CentreKey::scopeKey(const std::string& scope) const
{
    if (!coversNode(scope)) return {};
    if (!m_node.empty()) return m_key;
    return hmac(m_key, QByteArray("padrob-centre:node:") + QByteArray::fromStdString(scope));
}

CentreKey CentreKey::fromBytes(const QByteArray& bytes)
{
    CentreKey k;
    if (bytes.size() == 32) k.m_key = bytes;
    return k;
}

QString CentreKey::fingerprint() const
{
    return QString::fromLatin1(QCryptographicHash::hash(m_key, QCryptographicHash::Sha256).toHex().left(8));
}

// a message is signed with the key of the node it is about (signing.h)
template <class M>
std::string CentreKey::macFor(const M& m) const
{
    return covers(m) ? macOf(scopeKey(scopeOf(m)), m).toStdString() : std::string();
}

template <class M>
bool CentreKey::verifyMac(const M& m) const
{
    return covers(m) && sameBytes(QByteArray::fromStdString(macFor(m)), QByteArray::fromStdString(m.mac));
}

void CentreKey::sign(Command& c) const { c.mac = macFor(c); }
void CentreKey::sign(Announce& a) const { a.mac = macFor(a); }
void CentreKey::sign(State& s) const { s.mac = macFor(s); }
void CentreKey::sign(Event& e) const { e.mac = macFor(e); }
void CentreKey::sign(Reply& r) const { r.mac = macFor(r); }

bool CentreKey::verify(const Command& c) const { return verifyMac(c); }
bool CentreKey::verify(const Announce& a) const { return verifyMac(a); }
bool CentreKey::verify(const State& s) const { return verifyMac(s); }
bool CentreKey::verify(const Event& e) const { return verifyMac(e); }
bool CentreKey::verify(const Reply& r) const { return verifyMac(r); }

bool CentreKey::mayServe(const std::string& name, const QString& path, QString* error) const
{
    if (m_node.empty() || m_node == name) return true;
    if (error) {
        *error = Tr::tr("%1 is node %2's key, not %3's: give %3 its own (padrob centre key --key CENTRE-KEY --node %3 "
                        "FILE) or the centre's key.")
                     .arg(path, QString::fromStdString(m_node), QString::fromStdString(name));
    }
    return false;
}

bool CentreKey::isCentreKey(const QString& path, QString* error) const
{
    if (m_node.empty()) return true;
    if (error) {
        *error = Tr::tr("%1 is node %2's key: an instructor needs the centre's key, which signs the commands for every "
                        "station and checks what each says.")
                     .arg(path, QString::fromStdString(m_node));
    }
    return false;
}

QString CentreKey::seal(const QString& secret) const
{
    QByteArray nonce(16, Qt::Uninitialized);
    QRandomGenerator::system()->fillRange(reinterpret_cast<quint32*>(nonce.data()), 4);
    const QByteArray plain = secret.toUtf8();
    QByteArray cipher = plain;
    const QByteArray ks = keystream(derive(m_key, "seal-encrypt"), nonce, plain.size());
    for (qsizetype i = 0; i < cipher.size(); ++i) cipher[i] = static_cast<char>(cipher[i] ^ ks[i]);
    const QByteArray tag = hmac(derive(m_key, "seal-mac"), nonce + cipher);
    return QString::fromLatin1((nonce + cipher + tag).toBase64());
}

bool CentreKey::unseal(const QString& sealed, QString& secret) const
{
    const QByteArray all = QByteArray::fromBase64(sealed.toLatin1());
    if (!isSet() || all.size() < 16 + 32) return false;
    const QByteArray nonce = all.left(16), cipher = all.mid(16, all.size() - 48), tag = all.right(32);
    if (!sameBytes(tag, hmac(derive(m_key, "seal-mac"), nonce + cipher))) return false;
    QByteArray plain = cipher;
    const QByteArray ks = keystream(derive(m_key, "seal-encrypt"), nonce, cipher.size());
    for (qsizetype i = 0; i < plain.size(); ++i) plain[i] = static_cast<char>(plain[i] ^ ks[i]);
    secret = QString::fromUtf8(plain);
    return true;
}

bool CommandGuard::accept(const Command& c, std::int64_t nowMs, std::string& why)
{
    if (!m_key.isSet()) {
        why = "no-key";
        return false;
    }
    if (!limitProblem(c).empty()) {
        why = "too-long";
        return false;
    }
    if (!m_key.verify(c)) {
        why = "bad-signature";
        return false;
    }
    if (c.issuedMs < nowMs - m_maxAgeMs || c.issuedMs > nowMs + m_maxAgeMs) {
        why = "stale";
        return false;
    }
    // forget what would be refused as stale anyway
    std::erase_if(m_seen, [&](const auto& seen) { return seen.second < nowMs - m_maxAgeMs; });
    const auto id = std::make_pair(c.sender, c.nonce);
    if (m_seen.count(id)) {
        why = "replay";
        return false;
    }
    if (m_seen.size() >= m_maxRemembered) {
        why = "busy";
        return false;
    }
    m_seen.emplace(id, c.issuedMs);
    return true;
}

}  // namespace trainer::centre
