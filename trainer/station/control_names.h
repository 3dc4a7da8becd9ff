#pragma once
// The controls of a device as a person reads them (the mapping table, the channel
// bars, the HUD, the guides): a gamepad's axes and buttons by SDL's game-controller
// layout, translated ("Left stick X", "Right trigger", "Left shoulder", "Y"), never
// by their indices ("Axis 0", "9"); any other device's by the names it gives
// (AxisInfo::name, DeviceInfo::buttons), else "Axis n" / "Button n" (from 1).
// The indices are SDL's (SDL_GameControllerAxis, SDL_GameControllerButton; the
// gamepad enums in profile.h), which is how profiles store them.

#include "trainer/input/input_device.h"

#include <QString>

namespace trainer {

/// A gamepad's axis `axis` ("Left stick X" … "Right trigger"), "" beyond SDL's six.
QString gamepadAxisName(int axis);
/// A gamepad's button `button` ("A" … "Left shoulder" … "D-pad right", "Touchpad"), ""
/// beyond SDL's list.
QString gamepadButtonName(int button);
/// A short label of a gamepad's button for a small lamp ("A", "LB", "↑"), "" beyond.
QString gamepadButtonLabel(int button);

/// A profile's device name (an id or a kind key) names a gamepad: the kind "gamepad",
/// or `resolved` (the device it resolves to now, may be nullptr) is one.
bool isGamepad(const QString& deviceMatch, const DeviceInfo* resolved = nullptr);

/// Axis `axis` of `device` as a person reads it.
QString axisName(const DeviceInfo& device, int axis);
/// Button `button` of `device` as a person reads it.
QString buttonName(const DeviceInfo& device, int button);

}  // namespace trainer
