#include "trainer/centre/instructor_node.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QSysInfo>

namespace trainer::centre {

InstructorNode::InstructorNode(Bus& bus, std::string name, CentreKey key, double goneAfterS)
    : m_bus(bus), m_name(std::move(name)), m_key(std::move(key)), m_goneAfter(goneAfterS)
{
    // nonces grow across restarts: start from the clock (µs), then count
    m_nonce = static_cast<std::uint64_t>(QDateTime::currentMSecsSinceEpoch()) * 1000u;
}

void InstructorNode::announce()
{
    Announce a;
    a.node = m_name;
    a.role = "instructor";
    a.host = QSysInfo::machineHostName().toStdString();
    a.pid = static_cast<int>(QCoreApplication::applicationPid());
    a.startedMs = static_cast<std::uint64_t>(QDateTime::currentMSecsSinceEpoch());
    m_bus.announce(a);
}

void InstructorNode::poll(double nowS)
{
    for (State& st : m_bus.takeStates()) {
        StationView& v = m_stations[st.station];
        if (v.announce.node.empty()) v.announce.node = st.station;
        // the station's clock and ours: the same machine, or synchronised (NTP/PTP) in a centre
        v.latencyMs = (static_cast<double>(wallUs()) - static_cast<double>(st.sentUs)) / 1000.0;
        v.state = std::move(st);
        v.hasState = true;
        v.lastSeenS = nowS;
        // a state sent just before the station withdrew may arrive after the withdrawal:
        // only a new announcement brings a station that left back
        if (v.presence != "left") v.presence = "up";
    }
    for (Bus::Seen& s : m_bus.takeAnnounces()) {
        if (s.gone) {
            auto it = m_stations.find(s.announce.node);
            // withdrawn: it left; no writer left (killed, and DDS's lease ran out): silent
            if (it != m_stations.end()) it->second.presence = s.withdrew ? "left" : "silent";
            continue;
        }
        if (s.announce.role != "station") continue;
        StationView& v = m_stations[s.announce.node];
        v.announce = std::move(s.announce);
        v.presence = "up";
        v.lastSeenS = nowS;
    }
    for (Event& e : m_bus.takeEvents()) {
        StationView& v = m_stations[e.station];
        if (v.announce.node.empty()) v.announce.node = e.station;
        v.events.push_back(e);
        if (v.events.size() > 500) v.events.erase(v.events.begin(), v.events.begin() + 100);
        m_new.push_back(std::move(e));
    }
    for (Reply& r : m_bus.takeReplies()) {
        // the answer to one of our commands, from the station it went to (the Bus has
        // checked the signature)
        const auto sent = m_sent.find(r.nonce);
        if (r.sender == m_name && sent != m_sent.end() && sent->second == r.station && !m_replies.count(r.nonce))
            m_replies[r.nonce] = std::move(r);
    }
    for (auto& [name, v] : m_stations) {
        if (v.presence == "up" && v.lastSeenS >= 0 && nowS - v.lastSeenS > m_goneAfter) v.presence = "silent";
    }
}

std::uint64_t InstructorNode::send(const std::string& station, const std::string& kind, const std::string& arg,
                                   const std::string& arg2, double value)
{
    Command c;
    c.target = station;
    c.sender = m_name;
    c.nonce = ++m_nonce;
    c.issuedMs = QDateTime::currentMSecsSinceEpoch();
    c.kind = kind;
    c.arg = arg;
    c.arg2 = arg2;
    c.value = value;
    m_key.sign(c);
    if (!m_bus.send(c)) return 0;
    m_sent[c.nonce] = station;
    if (m_sent.size() > 4096) m_sent.erase(m_sent.begin());  // the oldest: long answered or lost
    return c.nonce;
}

std::optional<Reply> InstructorNode::reply(std::uint64_t nonce) const
{
    auto it = m_replies.find(nonce);
    if (it == m_replies.end()) return std::nullopt;
    return it->second;
}

std::vector<Event> InstructorNode::takeNewEvents() { return std::exchange(m_new, {}); }

}  // namespace trainer::centre
