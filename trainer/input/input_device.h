#pragma once
// InputDevice: one interface for everything an operator moves — SDL joysticks and
// gamepads, the serial DAQ box, Comedi cards, the keyboard, and the replay of a
// recorded input log. A device has axes (raw readings in the device's own units:
// SDL −32768…32767, a 10-bit ADC 0…1023, keys −1/0/+1) and buttons (pressed or not).
// Calibration, mapping and banks live above it (trainer/station/): a device only
// reports what it reads and whether it is there.
//
// Threads: a device is created, polled and destroyed in one thread (the station's
// input thread; a test's own thread). poll() never blocks: it takes what has
// arrived since the last call and returns.
//
// Identity: DeviceInfo::id is stable across runs and re-plugging, so a profile saved
// with a device finds it again: "sdl:<GUID>" ("sdl:<GUID>#2" for the second of two
// identical joysticks), "serial:<port name>", "comedi:<device file>", "keyboard",
// "replay:<log file name>".

#include <QList>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <memory>
#include <vector>

namespace trainer {

enum class DeviceKind { Joystick, Gamepad, SerialDaq, Comedi, Keyboard, Replay };

/// Nominal range of an axis, used until the channel is calibrated: the reading at
/// full travel each way and at rest (a stick rests at mid-travel, a trigger at its
/// minimum).
struct AxisInfo {
    QString name;           ///< e.g. "leftx", "Axis 3", "A0"
    double rawMin = -1.0;
    double rawRest = 0.0;
    double rawMax = 1.0;
};

struct DeviceInfo {
    QString id;             ///< stable identity (see above)
    QString name;           ///< as the device names itself, e.g. "Xbox 360 Controller"
    DeviceKind kind = DeviceKind::Joystick;
    QList<AxisInfo> axes;
    QStringList buttons;    ///< button names ("a", "leftshoulder", "Button 3", "hat0 up")
    /// The name is Padrob's, not the device's own ("DAQ console on /dev/ttyUSB0" for a
    /// console that sends no name): displayName() gives it in the language of now.
    bool namedByPadrob = false;
};

enum class DeviceStatus {
    Connected,     ///< reading
    Disconnected,  ///< unplugged (or not yet found): its readings are void
    Stalled,       ///< connected but no sample for longer than the device allows
    Failed,        ///< cannot be opened or read (statusText() says why)
};

/// What a device reads now. When not connected the values are those of the last
/// good sample; the station ignores them.
struct DeviceSample {
    std::vector<double> axes;           ///< raw, one per DeviceInfo::axes
    std::vector<std::uint8_t> buttons;  ///< 1 pressed, one per DeviceInfo::buttons
    double time = -1.0;                 ///< [s] station clock of the newest sample (−1: none yet)
    std::uint64_t count = 0;            ///< samples received so far
};

class InputDevice {
public:
    virtual ~InputDevice() = default;

    virtual const DeviceInfo& info() const = 0;
    /// Reads what has arrived (never blocks). `now` [s] is the station's clock
    /// (steady, monotonic; tests pass their own).
    virtual void poll(double now) = 0;
    virtual const DeviceSample& sample() const = 0;
    virtual DeviceStatus status() const = 0;
    /// Why the status is what it is, for a person (translated); "" when connected and well.
    virtual QString statusText() const { return {}; }
    /// Number of readings dropped as corrupt (a serial line with a bad checksum…).
    virtual std::uint64_t droppedSamples() const { return 0; }
    /// True for the replay of a recorded log: it takes the recorded device's id and
    /// kind so the same profile applies, and the station can tell it apart.
    virtual bool isReplay() const { return false; }
};

/// A back end that finds devices and follows hot-plug (SDL). Polled in the same
/// thread as the devices.
class DeviceProvider {
public:
    virtual ~DeviceProvider() = default;
    /// Handles plug/unplug since the last call. Returns the devices seen for the first
    /// time (the caller keeps them; the provider keeps a share to update their
    /// status). A device that returns after being unplugged is the same object again:
    /// it goes back to Connected, with the same id.
    virtual std::vector<std::shared_ptr<InputDevice>> poll(double now) = 0;
    /// A message when the back end itself cannot work (SDL failed to start); "" if fine.
    virtual QString problem() const { return {}; }
};

QString kindName(DeviceKind kind);  ///< translated, e.g. "Gamepad"
/// The device's name as the GUI shows it: the names Padrob gives (the keyboard's, a
/// serial console's without a name of its own) in the language of now, every other
/// device's as it names itself.
QString displayName(const DeviceInfo& info);
/// The kind as profiles name it: "gamepad", "joystick", "serial", "comedi", "keyboard", "replay".
QString kindKey(DeviceKind kind);

}  // namespace trainer
