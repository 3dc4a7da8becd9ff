#pragma once
// The centre's key and what it protects (docs/training-centre.md "Security"):
//  - every message: each node signs what it writes with HMAC-SHA256 under a key derived
//    from the centre's key, one per topic (commands, announcements, states, events,
//    replies); the Bus signs and checks announcements, states, events and replies itself
//    (bus.h), and drops what a node without the key sent;
//  - commands: a station acts only on a command whose signature checks, that was issued
//    within `maxAgeMs` of its clock, and that it has not already accepted (the same
//    sender and nonce) within that time (no replays); nothing is remembered longer, so no
//    nonce, however high, shuts anyone out;
//  - secrets at rest (the records database's password): sealed with a key derived from
//    the centre's key (HMAC-SHA256 in counter mode as the keystream, encrypt-then-MAC),
//    so a settings file never holds them in plain text.
// The key is 32 random bytes kept in a file (64 hex digits) readable by its owner only.

#include "trainer/centre/messages.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <map>
#include <string>
#include <utility>

namespace trainer::centre {

class CentreKey {
public:
    CentreKey() = default;
    /// Reads a key file: 64 hex digits (whitespace around them ignored). False with
    /// `error` (translated) when it is missing, malformed, or readable by others.
    bool load(const QString& path, QString* error);
    /// Writes a new random key to `path` (mode 0600; refuses to replace a file).
    static bool create(const QString& path, QString* error);
    static CentreKey fromBytes(const QByteArray& bytes);

    bool isSet() const { return m_key.size() == 32; }
    /// A short fingerprint for people (never the key): the first 8 hex digits of SHA-256(key).
    QString fingerprint() const;

    /// Signs a message (sets its mac) with this key's key for its topic.
    void sign(Command& c) const;
    void sign(Announce& a) const;
    void sign(State& s) const;
    void sign(Event& e) const;
    void sign(Reply& r) const;
    /// Whether the message's mac is this key's signature of it (constant-time comparison);
    /// false without a key.
    bool verify(const Command& c) const;
    bool verify(const Announce& a) const;
    bool verify(const State& s) const;
    bool verify(const Event& e) const;
    bool verify(const Reply& r) const;

    /// Seals a secret: base64 of nonce ‖ ciphertext ‖ tag.
    QString seal(const QString& secret) const;
    /// Opens a sealed secret. False when it was not sealed with this key or was altered.
    bool unseal(const QString& sealed, QString& secret) const;

private:
    QByteArray m_key;
};

/// A station's guard against forged, stale and replayed commands.
///
/// The replay memory is the station's, for the centre's key: the commands it accepted in
/// the last maxAgeMs, by (sender, nonce). A command is a replay only if exactly that
/// sender and nonce were accepted; an older one is stale anyway. So a nonce of 2^64-1
/// locks out nobody, not even its sender (the old rule, "above the sender's last nonce",
/// let one signed command shut out every instructor using that name for good).
class CommandGuard {
public:
    explicit CommandGuard(CentreKey key, std::int64_t maxAgeMs = 30000, std::size_t maxRemembered = 65536)
        : m_key(std::move(key)), m_maxAgeMs(maxAgeMs), m_maxRemembered(maxRemembered)
    {
    }
    /// Checks `c` at wall-clock time `nowMs`; on success remembers it. False with `why`,
    /// a code for the reply, when it must be refused: "no-key" (this station has none),
    /// "too-long" (a field over its bound: messages.h limits), "bad-signature", "stale"
    /// (issued more than maxAgeMs before or after now), "replay" (this sender's nonce was
    /// accepted within maxAgeMs), "busy" (maxRemembered commands in maxAgeMs: only a
    /// holder of the key can send that many, and they are forgotten within maxAgeMs).
    bool accept(const Command& c, std::int64_t nowMs, std::string& why);

    /// How many accepted commands are remembered now.
    std::size_t remembered() const { return m_seen.size(); }

private:
    CentreKey m_key;
    std::int64_t m_maxAgeMs;
    std::size_t m_maxRemembered;
    std::map<std::pair<std::string, std::uint64_t>, std::int64_t> m_seen;  // (sender, nonce) → issuedMs
};

/// The bytes a message's signature covers: a tag of its topic and version, then every
/// field but the mac, strings and sequences length-prefixed.
QByteArray signedBytes(const Command& c);
QByteArray signedBytes(const Announce& a);
QByteArray signedBytes(const State& s);
QByteArray signedBytes(const Event& e);
QByteArray signedBytes(const Reply& r);

}  // namespace trainer::centre
