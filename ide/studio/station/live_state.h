#pragma once
// What the Station workspace's widgets share: the station's newest state (read, never
// written: changes go through Station::post), a device of that state, the calibration
// a profile gives a channel (chosen as the engine chooses it: by id, then by kind),
// and the words and colours of a device's status.

#include "trainer/station/station.h"

#include <QColor>
#include <QString>

#include <memory>

namespace studio {

/// The station's newest state: latest() while its thread runs; when it is not started
/// (tests, before start) the engine's state() taken now through call(). nullptr when
/// there is no station or no state yet.
std::shared_ptr<const trainer::StationState> stationState(trainer::Station* station);

/// The device `id` of `state` (a replay when `replay`), or nullptr.
const trainer::DeviceState* findDevice(const trainer::StationState& state, const QString& id, bool replay = false);

/// The name under which `profile` calibrates (device, axis): the device's id when it has
/// an entry for it, else its kind key when that has one, else "".
QString calibrationKey(const trainer::StationProfile& profile, const trainer::DeviceInfo& device, int axis);

/// The calibration the engine uses for (device, axis): the profile's (when valid), else
/// the axis's nominal range (captured false).
trainer::ChannelCalibration channelCalibration(const trainer::StationProfile& profile,
                                               const trainer::DeviceInfo& device, int axis);

/// The HUDs' bank line (HTML): "Bank: <b>Boom</b> (1 of 2) · Y: next bank", how to
/// switch with what is connected; "" when the profile has one bank or no device that
/// switches banks is connected (a bank the operator cannot change is noise).
QString hudBankLine(const trainer::StationState& state);
/// The HUDs' station warnings (plain text): the profile's devices that are missing and
/// what drives instead, then the operator's warnings (devices lost, levers to centre…).
QStringList hudWarnings(const trainer::StationState& state);

/// "Connected", "Disconnected", "Stalled", "Failed" (translated).
QString statusName(trainer::DeviceStatus status);
/// Green, grey, amber, red.
QColor statusColor(trainer::DeviceStatus status);

/// The warning colours of the workspace (amber for "look at this", red for "broken").
QColor amberColor();
QColor redColor();

}  // namespace studio
