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
// A Bus is one DDS participant on the centre's domain; open one per process (or per
// node in a test). Its calls may come from any thread (DDS is thread-safe); take*() of
// one topic from one thread at a time. No DDS type leaves bus.cpp.

#include "trainer/centre/messages.h"

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

    bool announce(const Announce& a);
    /// Says the node has left (its Announce instance is disposed).
    bool withdraw(const std::string& node);
    bool publish(const State& s);
    bool publish(const Event& e);
    bool send(const Command& c);
    bool reply(const Reply& r);

    /// An Announce as read. `gone`: its node withdrew (`withdrew`: it disposed its
    /// announcement on leaving) or no writer of it is left (its process died and DDS's
    /// lease ran out); only `node` is set then.
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

private:
    Bus();
    struct Impl;
    std::unique_ptr<Impl> d;
};

}  // namespace trainer::centre
