#pragma once
// The training centre's bus: Eclipse Cyclone DDS with the topics of centre_topics.idl and a QoS
// chosen per topic (docs/training-centre.md):
//
//   topic             reliability   durability        history        who writes
//   padrob_Announce   reliable      transient-local   keep last 1    every node (disposed when it leaves)
//   padrob_State      best effort   volatile          keep last 1    stations, 60 Hz
//   padrob_Event      reliable      volatile          keep last 256  stations
//   padrob_Command    reliable      volatile          keep last 64   instructors
//   padrob_Reply      reliable      volatile          keep last 64   stations
//
// Every message but a command is signed and checked here, with the centre's key of
// BusOptions: the Bus signs the announcements, states, events and replies it writes, and
// drops (counting them, and saying so on stderr) those it reads that are unsigned, signed
// with another key or altered, stale (a state, an event or a leaving announcement sent
// more than 30 s from this node's clock) or over the limits of messages.h. Commands are
// signed by the instructor and checked by the station (CommandGuard), which replies why it
// refused one; the Bus drops only those over the limits. Without a key a Bus reads nothing
// but commands, and what it writes is heard by no node that has one.
//
// A Bus is one DDS participant on the centre's domain; open one per process (or per
// node in a test). Its calls may come from any thread (DDS is thread-safe); take*() of
// one topic from one thread at a time. No DDS type leaves bus.cpp.

#include "trainer/centre/messages.h"
#include "trainer/centre/signing.h"

#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

namespace trainer::centre {

enum Topic : unsigned {
    TopicAnnounce = 1,
    TopicState = 2,
    TopicEvent = 4,
    TopicCommand = 8,
    TopicReply = 16,
    AllTopics = 31,
};

/// Where the centre's nodes meet.
struct BusOptions {
    int domain = 0;           ///< DDS domain id, 0–232: one per centre (or per test)
    QStringList interfaces;   ///< network interfaces by name or address ("lo", "eth0"); empty = DDS's default
    QStringList peers;        ///< unicast discovery: addresses of the other machines (multicast off); empty = multicast
    int maxNodes = 120;       ///< nodes per machine with unicast discovery (DDS participant indices)
    /// The topics this node reads (Topic bits): a station reads only commands, a display
    /// announcements and states. Writers are made for every topic.
    unsigned reads = AllTopics;
    /// DDS Security (authentication, access control, encryption): the centre's PKI folder
    /// (padrob centre pki DIR) and this node's name in it (its identity in DIR/nodes/NAME).
    /// Empty = no DDS Security: such a node neither sees nor reaches the secured ones.
    QString securityDir;
    QString node;
    /// The centre's key: signs what this node writes and checks what it reads (above).
    CentreKey key;
    /// Refuse to write a message over the limits (messages.h). Off only in a test that
    /// plays a hostile node.
    bool checkWrites = true;
    /// Loopback only, unicast (the tests, a one-machine demonstration).
    static BusOptions loopback(int domain);
};

class Bus {
public:
    /// Joins the domain. nullptr with `error` (translated) when DDS refuses.
    static std::unique_ptr<Bus> open(const BusOptions& options, QString* error);
    ~Bus();
    Bus(const Bus&) = delete;
    Bus& operator=(const Bus&) = delete;

    /// Writes a message, signed with the key (announcements also stamped with sentMs,
    /// events with sentMs). False with lastError() when DDS refuses it or it is over the
    /// limits (lastError names the field: "operatorCode: 40 bytes, at most 32").
    bool announce(const Announce& a);
    /// Says the node has left: a signed announcement of role kRoleGone, then its Announce
    /// instance is disposed.
    bool withdraw(const std::string& node);
    bool publish(const State& s);
    bool publish(const Event& e);
    /// A command goes as it is: the instructor has signed it (InstructorNode::send).
    bool send(const Command& c);
    bool reply(const Reply& r);

    /// An Announce as read (signed with the key). `gone`: its node withdrew (`withdrew`:
    /// its signed leaving announcement) or no writer of it is left (its process died and
    /// DDS's lease ran out); only `node` is set then. A bare dispose is not believed (anyone
    /// can dispose an instance), so it is not reported.
    struct Seen {
        Announce announce;
        bool gone = false;
        bool withdrew = false;
    };
    std::vector<Seen> takeAnnounces();
    std::vector<State> takeStates();
    std::vector<Event> takeEvents();
    std::vector<Command> takeCommands();
    std::vector<Reply> takeReplies();

    /// How many readers of this node's commands DDS has matched: the stations' (only
    /// stations read commands). A command written before a station's reader is matched
    /// never reaches it (commands are volatile), so a new process waits for it.
    int commandReaders() const;

    /// Blocks until something arrives on a topic this Bus reads or `timeoutMs` passes.
    void wait(int timeoutMs);

    /// What DDS reported on the last failed call ("" none).
    QString lastError() const;

    /// What this Bus dropped on reading since it opened (see above).
    struct Dropped {
        std::uint64_t badSignature = 0;  ///< unsigned, another key's, or altered
        std::uint64_t stale = 0;         ///< sent more than 30 s from this clock
        std::uint64_t tooLong = 0;       ///< over the limits of messages.h
        std::uint64_t total() const { return badSignature + stale + tooLong; }
    };
    Dropped dropped() const;
    /// How far a state's, an event's or a leaving announcement's time may be from this
    /// node's clock [ms].
    static constexpr std::int64_t kMaxAgeMs = 30000;

private:
    Bus();
    struct Impl;
    std::unique_ptr<Impl> d;
};

}  // namespace trainer::centre
