// The centre's DDS bus in one process: two participants on loopback, each topic with
// its QoS — announcements reach late joiners and say when a node leaves, states are
// the latest, events and commands all arrive in order, replies come back. And what a
// node without the centre's key says (or one over the limits) is dropped.
#include "centre_test_util.h"
#include "trainer/centre/bus.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>

#include <cmath>
#include <set>

using namespace trainer::centre;
using centre_test::waitFor;

namespace {

const CentreKey kKey = CentreKey::fromBytes(QByteArray(32, 'k'));

/// A node of the centre (the centre's key), or, with another key, a forger.
std::unique_ptr<Bus> open(unsigned reads, const CentreKey& key = kKey, bool checkWrites = true)
{
    BusOptions o = BusOptions::loopback(centre_test::domain());
    o.reads = reads;
    o.key = key;
    o.checkWrites = checkWrites;
    QString error;
    auto bus = Bus::open(o, &error);
    EXPECT_TRUE(bus) << error.toStdString();
    return bus;
}

/// A state of `station` as it is now.
State stateOf(const std::string& station, std::uint64_t seq, const std::string& status)
{
    State s;
    s.seq = seq;
    s.sentUs = wallUs();
    s.station = station;
    s.status = status;
    return s;
}

}  // namespace

TEST(CentreBus, EveryTopicCarriesItsMessagesWithTheirQos)
{
    const std::string name = centre_test::unique("station");
    auto station = open(TopicCommand);
    ASSERT_TRUE(station);
    Announce a;
    a.node = name;
    a.role = "station";
    a.model = "liner_manipulator";
    a.tutorials = {"t0_reach", "t1_wrist"};
    a.pid = 42;
    a.startedMs = 1234567890123ull;
    ASSERT_TRUE(station->announce(a));
    // the instructor joins after the announcement: transient-local brings it
    auto instructor = open(TopicAnnounce | TopicState | TopicEvent | TopicReply);
    ASSERT_TRUE(instructor);
    std::vector<Bus::Seen> seen;
    ASSERT_TRUE(waitFor([&] { return !seen.empty(); }, 10000, [&] {
        for (auto& s : instructor->takeAnnounces()) {
            if (s.announce.node == name) seen.push_back(s);
        }
    })) << "a late joiner gets the announcement";
    EXPECT_FALSE(seen[0].gone);
    EXPECT_EQ(seen[0].announce.model, "liner_manipulator");
    EXPECT_EQ(seen[0].announce.tutorials, (std::vector<std::string>{"t0_reach", "t1_wrist"}));
    EXPECT_EQ(seen[0].announce.pid, 42);
    EXPECT_EQ(seen[0].announce.startedMs, 1234567890123ull);

    // states: the reader keeps the latest per station
    State s;
    s.station = name;
    s.q = {0.1, -0.2, 0.3};
    s.commands = {0.5f, 0.f, -1.f};
    s.status = "running";
    s.faults = "power-cut";
    s.warnings = WarnFault;
    std::vector<State> states;
    ASSERT_TRUE(waitFor([&] { return !states.empty() && states.back().seq >= 3; }, 10000, [&] {
        s.seq++;
        s.simTime = 0.001 * double(s.seq);
        s.sentUs = wallUs();
        station->publish(s);
        for (auto& st : instructor->takeStates()) states.push_back(st);
    }));
    EXPECT_EQ(states.back().q, (std::vector<double>{0.1, -0.2, 0.3}));
    EXPECT_EQ(states.back().commands, (std::vector<float>{0.5f, 0.f, -1.f}));
    EXPECT_EQ(states.back().status, "running");
    EXPECT_EQ(states.back().faults, "power-cut");
    EXPECT_EQ(states.back().warnings, std::uint32_t(WarnFault));
    for (std::size_t i = 1; i < states.size(); ++i) EXPECT_GT(states[i].seq, states[i - 1].seq) << "never older";

    // events: every one, in order
    for (int i = 0; i < 100; ++i) {
        Event e;
        e.station = name;
        e.seq = std::uint64_t(i);
        e.kind = "hit";
        e.text = "Touched the wall at " + std::to_string(i) + " m/s";
        e.value = i;
        ASSERT_TRUE(station->publish(e));
    }
    std::vector<Event> events;
    ASSERT_TRUE(waitFor([&] { return events.size() >= 100; }, 10000, [&] {
        for (auto& e : instructor->takeEvents()) events.push_back(e);
    }));
    ASSERT_EQ(events.size(), 100u);
    for (int i = 0; i < 100; ++i) {
        EXPECT_EQ(events[std::size_t(i)].seq, std::uint64_t(i));
        EXPECT_EQ(events[std::size_t(i)].value, i);
    }
    EXPECT_TRUE(std::isnan(Event().value));

    // commands to the station, replies back
    std::vector<Command> commands;
    for (int i = 0; i < 10; ++i) {
        Command c;
        c.target = name;
        c.sender = "instructor";
        c.nonce = std::uint64_t(100 + i);
        c.kind = "pause";
        c.mac = "00";
        ASSERT_TRUE(instructor->send(c));
    }
    ASSERT_TRUE(waitFor([&] { return commands.size() >= 10; }, 10000, [&] {
        for (auto& c : station->takeCommands()) commands.push_back(c);
    }));
    ASSERT_EQ(commands.size(), 10u);
    for (int i = 0; i < 10; ++i) EXPECT_EQ(commands[std::size_t(i)].nonce, std::uint64_t(100 + i));
    EXPECT_TRUE(std::isnan(commands[0].value));
    ASSERT_TRUE(station->reply(centre_test::doneReply(name, "instructor", 105)));
    std::vector<Reply> replies;
    ASSERT_TRUE(waitFor([&] { return !replies.empty(); }, 10000, [&] {
        for (auto& x : instructor->takeReplies()) replies.push_back(x);
    }));
    EXPECT_EQ(replies[0].nonce, 105u);
    EXPECT_TRUE(replies[0].accepted);

    // the station leaves: its announcement is disposed
    ASSERT_TRUE(station->withdraw(name));
    bool gone = false;
    ASSERT_TRUE(waitFor([&] { return gone; }, 10000, [&] {
        for (auto& x : instructor->takeAnnounces()) gone = gone || (x.gone && x.withdrew && x.announce.node == name);
    }));
}

// Issue 23: a node without the key announced a fake station and sent states, events and
// replies that the instructor believed. Now each is dropped and counted: unsigned, signed
// with another key, stale; a bare dispose does not make a station "left".
TEST(CentreBus, WhatIsNotSignedWithTheCentresKeyIsDropped)
{
    const std::string real = centre_test::unique("real"), fake = centre_test::unique("fake");
    auto instructor = open(TopicAnnounce | TopicState | TopicEvent | TopicReply);
    auto station = open(TopicCommand);
    auto unsignedForger = open(TopicCommand, CentreKey());
    auto otherKeyForger = open(TopicCommand, CentreKey::fromBytes(QByteArray(32, 'x')));
    auto staleForger = open(TopicCommand);  // has the key, but replays an old state
    ASSERT_TRUE(instructor && station && unsignedForger && otherKeyForger && staleForger);
    Announce genuine;
    genuine.node = real;
    genuine.role = "station";
    genuine.model = "liner";
    ASSERT_TRUE(station->announce(genuine));
    for (Bus* forger : {unsignedForger.get(), otherKeyForger.get()}) {
        Announce a;
        a.node = fake;
        a.role = "station";
        ASSERT_TRUE(forger->announce(a));
    }
    std::set<std::string> announced, stated, evented;
    std::vector<Reply> replies;
    bool realGone = false;
    std::uint64_t seq = 0;
    auto pump = [&] {
        // one writer's state per pass: a reader keeps the last state per station, so
        // states written together would hide each other
        ++seq;
        State s = stateOf(real, seq, "running");  // the forgers' lie: it runs
        if (seq % 8 == 2) unsignedForger->publish(s);
        else if (seq % 8 == 4) otherKeyForger->publish(s);
        else if (seq % 8 == 6) {
            s.sentUs = wallUs() - 60'000'000;  // signed, but a minute old: replayed
            staleForger->publish(s);
        } else {
            s.status = "idle";
            station->publish(s);
        }
        for (Bus* forger : {unsignedForger.get(), otherKeyForger.get()}) {
            State f;
            f.station = fake;
            f.sentUs = wallUs();
            forger->publish(f);
            Event e;
            e.station = real;
            e.kind = "goal";
            forger->publish(e);
            forger->reply(centre_test::doneReply(real, "desk", 42));
        }
        for (auto& x : instructor->takeAnnounces()) {
            if (x.gone) realGone = realGone || x.announce.node == real;
            else announced.insert(x.announce.node);
        }
        for (auto& x : instructor->takeStates()) {
            stated.insert(x.station);
            EXPECT_EQ(x.status, "idle") << "only the station's own states";
        }
        for (auto& x : instructor->takeEvents()) evented.insert(x.station);
        for (auto& x : instructor->takeReplies()) replies.push_back(x);
    };
    ASSERT_TRUE(waitFor([&] { return announced.count(real) && stated.count(real); }, 10000, pump));
    // and the forgers' messages had time to arrive (they are written as often)
    ASSERT_TRUE(waitFor([&] { return instructor->dropped().badSignature >= 20 && instructor->dropped().stale >= 3; },
                        10000, pump))
        << instructor->dropped().badSignature << " " << instructor->dropped().stale;
    // a forger's "the station left": an unsigned leaving announcement and a bare dispose
    ASSERT_TRUE(unsignedForger->withdraw(real));
    QElapsedTimer t;
    t.start();
    waitFor([&] { return t.elapsed() > 500; }, 1000, pump);
    EXPECT_EQ(announced, std::set<std::string>{real}) << "no fake station";
    EXPECT_EQ(stated, std::set<std::string>{real});
    EXPECT_TRUE(evented.empty());
    EXPECT_TRUE(replies.empty()) << "no forged 'done'";
    EXPECT_FALSE(realGone) << "a forger cannot say the station left";
    // the station itself can
    ASSERT_TRUE(station->withdraw(real));
    ASSERT_TRUE(waitFor([&] { return realGone; }, 10000, pump));
}

// Issue 23: every string field has a bound. Over it, a message is refused when written,
// saying which field, and dropped when read (a hostile node that writes it anyway).
TEST(CentreBus, OverLongStringsAreRefusedWhenWrittenAndDroppedWhenRead)
{
    const std::string name = centre_test::unique("bounded");
    auto instructor = open(TopicAnnounce | TopicState | TopicReply);
    auto station = open(TopicCommand);
    auto hostile = open(TopicCommand, kKey, false);
    ASSERT_TRUE(instructor && station && hostile);
    Command c;
    c.target = name;
    c.sender = "desk";
    c.nonce = 1;
    c.issuedMs = 1;
    c.kind = "start";
    c.arg = "T0";
    c.arg2 = std::string(40, 'X');  // the operator's code
    kKey.sign(c);
    EXPECT_FALSE(instructor->send(c));
    EXPECT_TRUE(instructor->lastError().contains("operatorCode: 40 bytes, at most 32")) << instructor->lastError().toStdString();
    Announce a;
    a.node = std::string(65, 'n');
    EXPECT_FALSE(station->announce(a));
    EXPECT_TRUE(station->lastError().contains("node: 65 bytes, at most 64")) << station->lastError().toStdString();
    State big;
    big.station = name;
    big.faults = std::string(10000, 'f');
    EXPECT_FALSE(station->publish(big));
    EXPECT_TRUE(station->lastError().contains("faults")) << station->lastError().toStdString();
    Reply r;
    r.station = name;
    r.sender = std::string(1000, 's');
    EXPECT_FALSE(station->reply(r));

    // written anyway, signed with the right key: dropped on reading (under its own name:
    // a reader keeps the last state per station)
    big.station = name + "-big";
    State ok;
    ok.station = name;
    std::vector<State> states;
    std::vector<Command> commands;
    auto pump = [&] {
        ok.seq++;
        ok.sentUs = wallUs();
        big.sentUs = wallUs();
        station->publish(ok);
        hostile->publish(big);
        hostile->send(c);
        for (auto& x : instructor->takeStates()) states.push_back(x);
        for (auto& x : station->takeCommands()) commands.push_back(x);
    };
    ASSERT_TRUE(waitFor([&] { return instructor->dropped().tooLong >= 3 && station->dropped().tooLong >= 3 && !states.empty(); },
                        10000, pump));
    EXPECT_FALSE(states.empty()) << "the station's own states arrive";
    for (const State& s : states) EXPECT_TRUE(s.faults.empty());
    EXPECT_TRUE(commands.empty()) << "the over-long command never reaches the station";
}

TEST(CentreBus, ABadDomainIsRefusedWithAMessage)
{
    BusOptions o;
    o.domain = 300;
    QString error;
    EXPECT_FALSE(Bus::open(o, &error));
    EXPECT_TRUE(error.contains("0 to 232")) << error.toStdString();
}

// Issue 23 item 6: a station holding only its own node key cannot pass for another
// station — its states, events, replies and announcements in another's name are dropped
// by the instructor (the centre's key) — while a display given a station's key checks
// that station's messages and passes over the others'.
TEST(CentreBus, AStationWithItsOwnKeyCannotPassForAnother)
{
    const std::string one = centre_test::unique("one"), two = centre_test::unique("two");
    auto instructor = open(TopicAnnounce | TopicState | TopicEvent | TopicReply);
    auto stationOne = open(TopicCommand, kKey.forNode(one));
    auto stationTwo = open(TopicCommand, kKey.forNode(two));
    auto displayOfOne = open(TopicAnnounce | TopicState, kKey.forNode(one));
    ASSERT_TRUE(instructor && stationOne && stationTwo && displayOfOne);
    for (const auto& [bus, name] : {std::pair{stationOne.get(), one}, std::pair{stationTwo.get(), two}}) {
        Announce a;
        a.node = name;
        a.role = "station";
        ASSERT_TRUE(bus->announce(a));
    }
    // station two says it is one: unsigned, since its key does not cover one
    Announce fake;
    fake.node = one;
    fake.role = "station";
    fake.model = "fake";
    ASSERT_TRUE(stationTwo->announce(fake));  // not written: its key cannot sign it
    std::set<std::string> announced, displayed;
    std::vector<State> states;
    std::vector<Reply> replies;
    std::uint64_t seq = 0;
    auto pump = [&] {
        ++seq;
        State s = stateOf(one, seq, "idle");
        if (seq % 2) {
            s.status = "done";  // the forger's lie
            stationTwo->publish(s);
            Event e;
            e.station = one;
            e.kind = "goal";
            stationTwo->publish(e);
            stationTwo->reply(centre_test::doneReply(one, "desk", 42));
        } else {
            stationOne->publish(s);
            stationTwo->publish(stateOf(two, seq, "idle"));
        }
        for (auto& x : instructor->takeAnnounces()) {
            if (!x.gone) {
                announced.insert(x.announce.node);
                EXPECT_NE(x.announce.model, "fake");
            }
        }
        for (auto& x : instructor->takeStates()) states.push_back(x);
        for (auto& x : instructor->takeEvents()) ADD_FAILURE() << "a forged event of " << x.station;
        for (auto& x : instructor->takeReplies()) replies.push_back(x);
        for (auto& x : displayOfOne->takeStates()) {
            displayed.insert(x.station);
            EXPECT_EQ(x.status, "idle");
        }
        displayOfOne->takeAnnounces();
    };
    auto seen = [&](const std::string& station) {
        return std::any_of(states.begin(), states.end(), [&](const State& s) { return s.station == station; });
    };
    ASSERT_TRUE(waitFor([&] { return announced.count(one) && announced.count(two) && seen(one) && seen(two) && displayed.count(one); },
                        10000, pump));
    ASSERT_TRUE(waitFor([&] { return instructor->dropped().badSignature >= 20; }, 10000, pump))
        << instructor->dropped().badSignature;
    for (const State& s : states) EXPECT_EQ(s.status, "idle") << "only " << s.station << "'s own states";
    EXPECT_TRUE(replies.empty()) << "no forged 'done'";
    EXPECT_EQ(displayed, std::set<std::string>{one}) << "the display checks only its station's states";
}
