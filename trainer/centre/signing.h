#pragma once
// The centre's key and what it protects (docs/training-centre.md "Security"):
//  - commands: an instructor signs each with HMAC-SHA256 under the centre's key; a
//    station acts only on a command whose signature checks, that was issued within
//    the last `maxAgeMs` by the clock, and whose nonce is higher than every nonce it has
//    already accepted from that sender (no replays);
//  - secrets at rest (the records database's password): sealed with a key derived from
//    the centre's key (HMAC-SHA256 in counter mode as the keystream, encrypt-then-MAC),
//    so a settings file never holds them in plain text.
// The key is 32 random bytes kept in a file (64 hex digits) readable by its owner only.

#include "trainer/centre/messages.h"

#include <QByteArray>
#include <QHash>
#include <QString>

#include <cstdint>

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

    /// Signs `c` (sets c.mac) with this key.
    void sign(Command& c) const;
    /// Whether c.mac is this key's signature of `c` (constant-time comparison).
    bool verify(const Command& c) const;

    /// Seals a secret: base64 of nonce ‖ ciphertext ‖ tag.
    QString seal(const QString& secret) const;
    /// Opens a sealed secret. False when it was not sealed with this key or was altered.
    bool unseal(const QString& sealed, QString& secret) const;

private:
    QByteArray m_key;
};

/// A station's guard against forged, stale and replayed commands.
class CommandGuard {
public:
    explicit CommandGuard(CentreKey key, std::int64_t maxAgeMs = 30000) : m_key(std::move(key)), m_maxAgeMs(maxAgeMs) {}
    /// Checks `c` at wall-clock time `nowMs`; on success remembers its nonce. False with
    /// `why`, a code for the reply, when it must be refused: "no-key" (this station has
    /// none), "bad-signature", "stale" (issued more than maxAgeMs before or after now),
    /// "replay" (a nonce not above the sender's last accepted one).
    bool accept(const Command& c, std::int64_t nowMs, std::string& why);

private:
    CentreKey m_key;
    std::int64_t m_maxAgeMs;
    QHash<QString, std::uint64_t> m_lastNonce;  // per sender
};

/// The bytes a command's signature covers (every field but the mac, length-prefixed).
QByteArray signedBytes(const Command& c);

}  // namespace trainer::centre
