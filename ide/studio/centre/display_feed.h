#pragma once
// What a display node shows of a station on the training centre's bus, without any GL
// (docs/studio.md "Training centre"): the station's machine model, found by its
// Announce in the bundled models folder and checked against the station's hash; the
// scene of the tutorial it runs; and the machine's pose at any moment, interpolated
// from the State stream.
//
// States arrive at about 60 Hz, best effort, with network jitter. StateBuffer keeps the
// latest ones and draws the pose a fixed delay (kDelay, about two state periods) behind
// the newest, interpolating θ linearly by simulated time, so a frame at the screen's
// rate always falls between two states that have arrived. The station's simulated time
// is mapped to this computer's clock by the smallest transit seen (arrival minus
// simulated time): a late state does not drag the picture back, a pause, a restart or a
// station fallen behind re-anchors it at once, and the pose never steps back.

#include "ide/studio/model/model_bundle.h"
#include "trainer/centre/messages.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace trainer {
struct Tutorial;
}

namespace studio {

/// The latest states of one station and the pose to draw between them.
class StateBuffer {
public:
    /// How far behind the newest state the pose is drawn [s]: two periods at 60 Hz.
    static constexpr double kDelay = 0.033;
    /// A state this much later than the clock mapping expects re-anchors it [s] (a
    /// station that fell behind real time, a network stall).
    static constexpr double kReanchor = 0.25;
    /// States kept (about a second at 60 Hz).
    static constexpr std::size_t kKeep = 64;

    /// A state `seq` at simulated time `simTime` [s] with pose `q` (θ per tree joint),
    /// received at `arrivalS` [s, the caller's clock]. A duplicate is ignored (false);
    /// a lower seq (the station restarted) or an earlier simulated time (a new attempt)
    /// starts the buffer afresh.
    bool push(std::uint64_t seq, double simTime, std::vector<double> q, double arrivalS);
    /// θ to draw at `nowS` [s, the caller's clock]: at simulated time playTime(nowS),
    /// linear between the two states around it, the newest when none is newer. False
    /// when there is no state.
    bool sample(double nowS, std::vector<double>& q) const;
    /// θ at simulated time `simTime`: exact at a state's time, linear between two, the
    /// oldest before and the newest after them. False when there is no state.
    bool at(double simTime, std::vector<double>& q) const;
    /// The simulated time drawn at `nowS`.
    double playTime(double nowS) const { return nowS - m_offset - kDelay; }

    void clear();
    bool empty() const { return m_states.empty(); }
    std::size_t size() const { return m_states.size(); }
    std::uint64_t latestSeq() const { return m_states.empty() ? 0 : m_states.back().seq; }
    double latestSimTime() const { return m_states.empty() ? 0.0 : m_states.back().simTime; }
    /// When the newest state arrived [s] (−1 none yet).
    double lastArrival() const { return m_lastArrival; }
    /// How many times the buffer started afresh (restarts, new attempts).
    int restarts() const { return m_restarts; }

private:
    struct Sample {
        std::uint64_t seq = 0;
        double simTime = 0;
        std::vector<double> q;
    };
    std::deque<Sample> m_states;  ///< by simulated time, oldest first
    double m_offset = 0;          ///< arrival minus simulated time of the least delayed state [s]
    double m_lastArrival = -1;
    bool m_stood = false;  ///< the newest state's simulated time stood still
    int m_restarts = 0;
};

/// One station as a display node sees it: model, scene, state, presence.
class DisplayFeed {
    Q_DECLARE_TR_FUNCTIONS(studio::DisplayFeed)
public:
    /// No state for this long and the station is "silent" [s].
    static constexpr double kSilentAfter = 1.5;
    enum class Presence {
        Waiting,  ///< nothing heard from it yet
        Up,       ///< states arriving
        Silent,   ///< none for kSilentAfter (killed, unplugged, frozen)
        Left,     ///< it withdrew (shut down)
    };

    explicit DisplayFeed(std::string station = {});

    /// Follows another station (forgets everything of the last one).
    void setStation(const std::string& station);
    const std::string& station() const { return m_station; }

    /// The station announced itself: loads its model when it is another one (other
    /// nodes' announcements are ignored).
    void announce(const trainer::centre::Announce& a);
    /// The station withdrew its announcement (it shut down): it stays "left" until it
    /// announces itself again.
    void withdraw(const std::string& node);
    /// A state arrived at `nowS` (other stations' are ignored, and any after a
    /// withdrawal): the pose buffer, the latest values, the tutorial's scene when it changes.
    void push(const trainer::centre::State& s, double nowS);

    Presence presence(double nowS) const;
    /// θ to draw at `nowS` (StateBuffer::sample). False before any state, or when it
    /// does not fit the model (another number of joints).
    bool pose(double nowS, std::vector<double>& q) const;

    /// The station's model (nullptr until announced, or when it cannot be used: see problem()).
    std::shared_ptr<const ModelBundle> bundle() const { return m_bundle; }
    /// The scene of the tutorial the station runs (nullptr: none, or not found here).
    std::shared_ptr<const ModelBundle> scene() const { return m_scene; }
    /// Why the machine cannot be shown (translated; "" when it can).
    QString problem() const { return m_problem; }

    bool hasAnnounce() const { return m_hasAnnounce; }
    const trainer::centre::Announce& lastAnnounce() const { return m_announce; }
    bool hasState() const { return m_hasState; }
    /// The latest state (its q is in the buffer, not here).
    const trainer::centre::State& latest() const { return m_latest; }
    const StateBuffer& buffer() const { return m_buffer; }

    /// The bundled model file named `model` whose bytes' SHA-256 (hex) is `hash` (any
    /// hash when it is ""). "" with `error` (translated) when there is no such file here,
    /// the name is not a plain model name, or the file differs.
    static QString findModel(const std::string& model, const std::string& hash, QString* error);
    /// SHA-256 (lower-case hex) of a file's bytes, "" when it cannot be read.
    static QString fileHash(const QString& path);

private:
    void loadModel();
    void loadScene(const std::string& tutorialId);

    std::string m_station;
    trainer::centre::Announce m_announce;
    bool m_hasAnnounce = false;
    trainer::centre::State m_latest;
    bool m_hasState = false;
    bool m_left = false;
    StateBuffer m_buffer;
    std::string m_modelKey;  ///< model + hash loaded (or tried)
    std::shared_ptr<const ModelBundle> m_bundle;
    QString m_problem;
    std::string m_sceneFor;  ///< tutorial id the scene is for
    bool m_sceneKnown = false;  ///< m_sceneFor is set
    std::shared_ptr<const ModelBundle> m_scene;
    std::map<std::string, QString> m_tutorialFiles;  ///< id → file, read once
    bool m_tutorialsRead = false;
};

}  // namespace studio
