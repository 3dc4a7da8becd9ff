#pragma once
// The instructor's side of the centre (docs/training-centre.md): which stations are on
// the network and what each is doing (its latest state, its events), and signed
// commands to them with their replies. Used by `padrob instructor` and by padrob-studio
// --instructor; single-threaded: poll() and send() from one thread.

#include "trainer/centre/bus.h"
#include "trainer/centre/signing.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace trainer::centre {

struct StationView {
    Announce announce;      ///< the latest announcement
    State state;            ///< the latest state (valid when hasState)
    bool hasState = false;
    double lastSeenS = -1;  ///< when the latest state or announcement arrived [s, the caller's clock]
    /// "up": states arriving; "silent": none for goneAfter (killed, unplugged, frozen);
    /// "left": it withdrew (shut down).
    std::string presence = "up";
    std::vector<Event> events;  ///< the latest (at most 500), oldest first
    double latencyMs = -1;      ///< of the latest state: received minus sent (wall clocks)
};

class InstructorNode {
public:
    InstructorNode(Bus& bus, std::string name, CentreKey key, double goneAfterS = 1.5);

    /// Announces the instructor (so stations and the log can name it).
    void announce();
    /// Takes what arrived at `nowS` [s]; marks silent stations.
    void poll(double nowS);
    const std::map<std::string, StationView>& stations() const { return m_stations; }

    /// Sends a signed command; returns its nonce (0 when it could not be sent: the Bus's
    /// lastError() says why, e.g. a field over the limits).
    std::uint64_t send(const std::string& station, const std::string& kind, const std::string& arg = {},
                       const std::string& arg2 = {}, double value = std::numeric_limits<double>::quiet_NaN());
    /// The reply to the command with `nonce`, once it has come: signed with the centre's
    /// key (the Bus checks it), from the station the command went to.
    std::optional<Reply> reply(std::uint64_t nonce) const;

    /// Called with each event as it arrives (after poll() stored it).
    std::vector<Event> takeNewEvents();

private:
    Bus& m_bus;
    std::string m_name;
    CentreKey m_key;
    double m_goneAfter;
    std::uint64_t m_nonce = 0;
    std::map<std::string, StationView> m_stations;
    std::map<std::uint64_t, std::string> m_sent;  // nonce → the station it went to
    std::map<std::uint64_t, Reply> m_replies;
    std::vector<Event> m_new;
};

}  // namespace trainer::centre
