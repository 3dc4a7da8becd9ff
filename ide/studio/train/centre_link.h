#pragma once
// How the Train workspace stands on the training centre's network, as its indicator
// shows it (TrainPage::setCentreLink) and the station part says it (TrainStation).

namespace studio {

enum class CentreLink {
    Off,     ///< not a station of the centre
    Online,  ///< on the network, with its key
    NoKey,   ///< on the network without a usable key: every command is refused
    Failed,  ///< DDS refused to join
};

}  // namespace studio
