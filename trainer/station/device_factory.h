#pragma once
// Opens the devices a station profile lists: "serial:<port>" (the serial DAQ console,
// at the setting's baud rate) and "comedi:<file>" (a Comedi card, when the build has
// comedilib). The device is created in the calling thread, which must be the thread
// that polls it.

#include "trainer/input/input_device.h"
#include "trainer/station/profile.h"

#include <memory>

namespace trainer {

/// The device, or nullptr with `why` (translated) when this build or id cannot make it.
/// A device that exists but cannot be opened yet (a port not plugged in) is returned
/// and reports Failed/Disconnected itself, retrying.
std::shared_ptr<InputDevice> openDevice(const DeviceSetting& setting, QString* why = nullptr);

}  // namespace trainer
