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
//
// Node keys: every signature is made with a key of the node the message is about — the
// station a state, event or reply comes from, the station a command is for, the node an
// announcement announces — derived from the centre's key (K_node = HMAC(K, node)). The
// centre's key derives every node's key, so the instructors that hold it sign and check
// everything. A station given only its own node key (padrob centre key --node NAME) signs
// only its own messages and checks only the commands for it: it cannot pass for another
// station, forge another's replies, or command one.

#include "trainer/centre/messages.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <map>
#include <string>
#include <utility>

namespace trainer::centre {

/// The node a message is about, whose key signs it: a command's target station; a
/// state's, event's or reply's station; an announcement's node.
inline const std::string& scopeOf(const Command& c) { return c.target; }
inline const std::string& scopeOf(const Announce& a) { return a.node; }
inline const std::string& scopeOf(const State& s) { return s.station; }
inline const std::string& scopeOf(const Event& e) { return e.station; }
inline const std::string& scopeOf(const Reply& r) { return r.station; }

class CentreKey {
public:
    CentreKey() = default;
    /// Reads a key file: the centre's key (64 hex digits) or a node's key (a first line
    /// "padrob-node-key NAME", then 64 hex digits); whitespace around them is ignored. False
    /// with `error` (translated) when it is missing, malformed, or readable by others.
    bool load(const QString& path, QString* error);
    /// Writes a new random centre key to `path` (mode 0600; refuses to replace a file).
    static bool create(const QString& path, QString* error);
    /// Writes node `node`'s key, derived from this centre key, to `path` (mode 0600;
    /// refuses to replace a file, and a node key cannot derive others).
    bool createNodeKey(const std::string& node, const QString& path, QString* error) const;
    static CentreKey fromBytes(const QByteArray& bytes);

    bool isSet() const { return m_key.size() == 32; }
    /// The node this key belongs to; empty for the centre's key (which covers every node).
    const std::string& node() const { return m_node; }
    /// This key's node key for `node`: derived from the centre's key, or this node key
    /// itself when it is `node`'s; an unset key otherwise.
    CentreKey forNode(const std::string& node) const;
    /// A short fingerprint for people (never the key): the first 8 hex digits of SHA-256(key).
    QString fingerprint() const;

    /// Whether this key can sign and check the message: the centre's key can every one;
    /// a node key only those about its node (scopeOf).
    template <class M>
    bool covers(const M& m) const
    {
        return coversNode(scopeOf(m));
    }
    /// Whether this key may serve as node `name`'s: the centre's key may serve any node, a
    /// node key only its own. False with `error` (translated: the key file `path`, whose
    /// key it is, and how to make `name`'s) otherwise.
    bool mayServe(const std::string& name, const QString& path, QString* error) const;
    /// Whether this is the centre's key, as an instructor needs (it signs the commands for
    /// every station). False with `error` (translated, naming the file `path`) for a node key.
    bool isCentreKey(const QString& path, QString* error) const;

    /// Signs a message (sets its mac) with its node's key for its topic; a message this
    /// key does not cover is left unsigned (an empty mac, which every reader drops).
    void sign(Command& c) const;
    void sign(Announce& a) const;
    void sign(State& s) const;
    void sign(Event& e) const;
    void sign(Reply& r) const;
    /// Whether the message's mac is its node's signature of it (constant-time comparison);
    /// false without a key or when this key does not cover it.
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
    bool coversNode(const std::string& n) const { return isSet() && (m_node.empty() || n == m_node); }
    /// The key of `scope`'s signatures (empty when not covered).
    QByteArray scopeKey(const std::string& scope) const;
    /// The message's signature under its node's key; empty when this key does not cover it.
    template <class M>
    std::string macFor(const M& m) const;
    template <class M>
    bool verifyMac(const M& m) const;

    QByteArray m_key;
    std::string m_node;  ///< empty: the centre's key
};

/// A station's guard against forged, stale and replayed commands.
///
/// The replay memory is the station's: the commands it accepted in the last maxAgeMs, by
/// (sender, nonce). Only a holder of the centre's key (an instructor) or of this station's
/// node key can sign a command for it. A command is a replay only if exactly that
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
