#pragma once
// SdlJoysticks: the SDL2 back end for joysticks and gamepads. It starts SDL's
// joystick and game-controller subsystems, follows hot-plug and hands each device
// out as an InputDevice (trainer/input/input_device.h).
//
// What a device looks like:
//   - a game controller (one SDL has a mapping for, SDL_IsGameController) is a
//     Gamepad with SDL's 6 standard axes in SDL order, named as SDL names them
//     ("leftx", "lefty", "rightx", "righty", "lefttrigger", "righttrigger"; sticks
//     −32768/0/32767, triggers rest at 0 and go to 32767), and the
//     SDL_CONTROLLER_BUTTON_* in order ("a", "b", "x", "y", "back", "guide",
//     "start", "leftstick", "rightstick", "leftshoulder", "rightshoulder", "dpup",
//     "dpdown", "dpleft", "dpright", "misc1", "paddle1" … "paddle4", "touchpad"),
//     all of them whether the pad has them or not (a missing one reads 0);
//   - any other joystick is a Joystick with "Axis 1" … "Axis N" (−32768/0/32767)
//     and "Button 1" … "Button M", then each hat as four buttons "Hat 1 up",
//     "Hat 1 right", "Hat 1 down", "Hat 1 left" (a diagonal presses two).
//   Axis and button names of a plain joystick are translated; a gamepad's are SDL's.
//   A device without axes is Connected but its statusText() says it cannot drive
//   a valve.
//
// Threads: SdlJoysticks and its devices are created, polled and destroyed in one
// thread (the station's input thread). SDL's event queue is process-wide, so one
// SdlJoysticks at a time per process: several in sequence are fine (SDL counts
// subsystem starts), two at once would take each other's plug/unplug events.
// Each cycle, poll the provider, then its devices: the provider's poll() pumps SDL,
// which updates every device's readings, and a device's poll() copies them. A
// device polled again without a provider poll in between pumps SDL itself (once
// per round of devices), so its readings are never stale.
//
// Identity: DeviceInfo::id is "sdl:" + SDL's GUID string of the device, with "#2",
// "#3"… for the second, third… device object with the same GUID (in the order they
// were found). A device that is unplugged and comes back (same GUID) is the same
// object again — the first disconnected one with that GUID — Connected, with the
// same id and fresh readings. SDL's GUID holds bus, vendor, product and version
// (or, without vendor and product, part of the name and its CRC), not a serial
// number: two identical pads swap ids if they come back in the other order.
//
// After the SdlJoysticks is destroyed its devices (which the station may still
// hold) are Disconnected for good and never touch SDL again.

#include "trainer/input/input_device.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

namespace trainer {

class SdlJoysticks : public DeviceProvider {
    Q_DECLARE_TR_FUNCTIONS(trainer::SdlJoysticks)

public:
    /// Starts SDL's joystick and game-controller subsystems (hints first: joystick
    /// events in the background, no signal handlers). When SDL cannot start,
    /// problem() says why and poll() finds nothing.
    SdlJoysticks();
    /// Closes every device (they become Disconnected) and stops the subsystems.
    ~SdlJoysticks() override;
    SdlJoysticks(const SdlJoysticks&) = delete;
    SdlJoysticks& operator=(const SdlJoysticks&) = delete;

    /// Pumps SDL's events (never blocks), opens devices that arrived, marks those
    /// that left Disconnected and brings back the ones that returned. The first call
    /// also picks up the devices already plugged in. Returns the devices seen for
    /// the first time; a returning device is not returned again. `now` [s] is the
    /// station's clock.
    std::vector<std::shared_ptr<InputDevice>> poll(double now) override;
    /// "" when SDL started; otherwise a translated message with SDL's error.
    QString problem() const override;

    /// Every device found so far, connected or not, in the order found.
    std::vector<std::shared_ptr<InputDevice>> devices() const;

private:
    class Device;    ///< one SDL joystick or gamepad (in the .cpp)
    struct Pump;     ///< SDL pump rounds, shared with the devices (in the .cpp)

    void attach(int deviceIndex, std::vector<std::shared_ptr<InputDevice>>& found);
    void detach(std::int32_t instanceId);

    bool m_started = false;       ///< the subsystems are ours to quit
    bool m_scanNeeded = true;     ///< enumerate SDL's devices in the next poll
    QString m_problem;
    std::shared_ptr<Pump> m_pump;
    std::vector<std::shared_ptr<Device>> m_devices;  ///< in the order found
};

}  // namespace trainer
