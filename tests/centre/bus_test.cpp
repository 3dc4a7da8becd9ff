// The centre's DDS bus in one process: two participants on loopback, each topic with
// its QoS — announcements reach late joiners and say when a node leaves, states are
// the latest, events and commands all arrive in order, replies come back.
#include "centre_test_util.h"
#include "trainer/centre/bus.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace trainer::centre;
using centre_test::waitFor;

namespace {

std::unique_ptr<Bus> open(unsigned reads)
{
    BusOptions o = BusOptions::loopback(centre_test::domain());
    o.reads = reads;
    QString error;
    auto bus = Bus::open(o, &error);
    EXPECT_TRUE(bus) << error.toStdString();
    return bus;
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
    Reply r;
    r.station = name;
    r.sender = "instructor";
    r.nonce = 105;
    r.accepted = true;
    r.message = "done";
    ASSERT_TRUE(station->reply(r));
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

TEST(CentreBus, ABadDomainIsRefusedWithAMessage)
{
    BusOptions o;
    o.domain = 300;
    QString error;
    EXPECT_FALSE(Bus::open(o, &error));
    EXPECT_TRUE(error.contains("0 to 232")) << error.toStdString();
}
