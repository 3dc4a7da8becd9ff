#pragma once
// StationEngine: devices → calibration → valve mapping and banks → one command
// u ∈ [−1, 1] per drive. Plain C++ with no thread or timer of its own: the Station
// (station.h) runs it in the input thread every millisecond; tests call update()
// with their own clock.
//
// Each update():
//  1. polls the providers (SDL hot-plug) and every device (never blocking);
//  2. calibrates every axis (the profile's calibration of that device and axis, or
//     the device's nominal range, flagged "not calibrated") and low-pass filters it;
//  3. switches banks on button presses (a bank's select buttons, the next-bank
//     button; on the press, not while held);
//  4. sums gain · sign · value over the live mappings (the "always" ones and the
//     active bank's) per drive, clamped to [−1, 1].
// A mapping is live only while its device is connected, its drive exists, and it has
// been armed: after the profile is set, after a bank switch and after its device
// (re)connects, a mapping waits until its lever is back at the centre (|value| <
// kArmThreshold) — a lever held off-centre never makes a valve jump open. A device
// that disconnects or stalls leaves its drives at 0: the valves close and the machine
// holds, with a warning, until it is back and its levers have been centred.
//
// update() allocates nothing once the devices and profile are set; state() builds a
// full picture for the UI (allocates; call it at display rate).

#include "trainer/input/input_device.h"
#include "trainer/station/calibration.h"
#include "trainer/station/profile.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <vector>

namespace trainer {

class InputRecorder;

struct ChannelState {
    double raw = 0.0;
    double value = 0.0;       ///< calibrated and filtered, [−1, 1]
    bool calibrated = false;  ///< false: the profile has no calibration for it; the device's nominal range is in use
    bool outOfRange = false;  ///< the raw reading is beyond the calibrated range
    /// The raw reading is far outside anything the device can read (its nominal range
    /// widened by kFaultMargin of its span, e.g. 65535 on a 10-bit box): a device fault.
    /// The channel reads 0 (its valves close), a warning says so, and its mappings wait
    /// for the lever at the centre once the readings are sane again.
    bool fault = false;
};

struct DeviceState {
    DeviceInfo info;
    DeviceStatus status = DeviceStatus::Disconnected;
    QString statusText;
    std::vector<ChannelState> channels;
    std::vector<std::uint8_t> buttons;
    std::uint64_t samples = 0;
    std::uint64_t dropped = 0;
    bool fromProfile = false;  ///< opened because the profile lists it
    bool replay = false;       ///< a replay of a log (it carries the recorded device's id)
};

struct MappingState {
    Mapping mapping;
    int bank = -1;          ///< −1: an "always" mapping
    int treeJoint = -1;     ///< −1: the model has no such drive
    QString deviceId;       ///< the device it resolved to ("" none)
    bool connected = false;
    bool armed = false;     ///< false: waiting for the lever to come back to centre
    double contribution = 0.0;
};

struct StationState {
    double time = 0.0;
    QString profileName;
    QList<DeviceState> devices;
    QStringList bankNames;
    int activeBank = 0;
    QList<MappingState> mappings;   ///< the profile's: the always ones, then every bank's
    std::vector<double> commands;   ///< one per tree joint
    QList<DriveInfo> drives;
    QList<ProfileIssue> profileIssues;
    /// For the operator (translated; the HUD): devices lost since they were connected,
    /// with the drives they hold, levers waiting for the centre, providers that failed.
    QStringList warnings;
    /// For the trainer setting up (the Station workspace): devices the profile uses
    /// that have not been connected yet (no gamepad, a port that cannot be opened),
    /// with what their drives do instead (the keyboard drives them, or they hold).
    QStringList setupWarnings;
    /// For the operator (the HUDs): the profile's devices that have never been
    /// connected, in one line with what drives instead ("" when all are there):
    /// "Serial DAQ console missing — the keyboard drives instead".
    QString devicesMissing;
    /// A device whose buttons switch banks (a bank's select button, the next-bank
    /// button) is connected: the bank is worth showing to the operator.
    bool bankSwitchConnected = false;
    /// How the operator switches banks with what is connected ("Y: next bank · Left
    /// shoulder: Boom"), "" when nothing can.
    QString bankSwitchHint;
};

class StationEngine {
public:
    static constexpr double kArmThreshold = 0.02;
    /// A raw reading beyond the device's nominal range by more than this fraction of
    /// the range's span is a device fault (ChannelState::fault).
    static constexpr double kFaultMargin = 0.1;
    /// Unless the profile maps the keyboard itself, its first kKeyboardPairs channels
    /// drive the model's drives in joint id order (a laptop always works).
    static constexpr int kKeyboardPairs = 9;

    StationEngine();
    ~StationEngine();
    StationEngine(const StationEngine&) = delete;
    StationEngine& operator=(const StationEngine&) = delete;

    /// The model's drives and the size of its command vector (tree joints). Mappings
    /// are re-resolved and disarmed.
    void setDrives(int treeJointCount, const QList<DriveInfo>& drives);
    /// Installs a profile: opens the devices it lists (serial ports, Comedi cards),
    /// closes the ones the previous profile opened and this one does not, selects the
    /// first bank, disarms every mapping. Returns the issues of StationProfile::check
    /// (errors in a mapping make that mapping ignored, never the station stop).
    QList<ProfileIssue> setProfile(const StationProfile& profile);
    const StationProfile& profile() const { return m_profile; }
    /// Changes one channel's calibration in the profile (the wizard's result).
    void setCalibration(const QString& device, int axis, const ChannelCalibration& c);

    void addProvider(std::unique_ptr<DeviceProvider> provider);
    /// A device the station polls (keyboard, replay, a serial port opened by hand).
    void addDevice(std::shared_ptr<InputDevice> device);
    void removeDevice(const QString& id);
    /// Removes that very device (a replay shares its id with the device it recorded).
    void removeDevice(const InputDevice* device);
    /// Devices of replays only: when true, every other device is ignored (a
    /// demonstration drives the machine, not the operator).
    void setReplayOnly(bool replayOnly);

    /// While holding (a lever being calibrated), every command is 0 and the warnings
    /// say so; afterwards every mapping waits for its lever at the centre again.
    void setHolding(bool holding);
    bool isHolding() const { return m_holding; }

    void selectBank(int bank);
    int activeBank() const { return m_activeBank; }

    /// One cycle at station time `now` [s]. True when the commands changed.
    bool update(double now);
    const std::vector<double>& commands() const { return m_commands; }
    StationState state() const;

    /// The device a profile name (id or kind) resolves to now, or nullptr.
    InputDevice* resolve(const QString& match) const;
    const std::vector<std::shared_ptr<InputDevice>>& devices() const { return m_devices; }

    /// Every sample read is also given to `recorder` (nullptr: stop).
    void setRecorder(InputRecorder* recorder) { m_recorder = recorder; }

private:
    struct Channel {
        double nominalMin = -1.0, nominalMax = 1.0;  ///< what the device says it reads (AxisInfo)
        ChannelCalibration calibration;
        LowPass filter;
        ChannelState state;
    };
    struct Device {
        std::vector<Channel> channels;
        std::vector<std::uint8_t> previousButtons;
        std::uint64_t lastCount = 0;
        double lastTime = -1.0;
        bool wasConnected = false;
        bool everConnected = false;
        bool fromProfile = false;
    };
    struct Live {
        Mapping mapping;
        int bank = -1;
        int treeJoint = -1;
        int device = -1;  ///< index into m_devices, −1 unresolved
        bool armed = false;
        double contribution = 0.0;
    };

    int indexOf(const QString& match) const;
    void rebuildLive();
    void refreshCalibrations();
    void disarmBank(int bank);
    bool ignored(const InputDevice& d) const;
    /// `l` is one of the keyboard's own mappings (not the profile's).
    bool isImplicitKeyboard(const Live& l) const;
    /// A profile's device name for a person: a kind key as the kind's name ("Gamepad"),
    /// an id as it is.
    static QString deviceName(const QString& match);

    std::vector<std::unique_ptr<DeviceProvider>> m_providers;
    std::vector<std::shared_ptr<InputDevice>> m_devices;
    std::vector<Device> m_state;  ///< parallel to m_devices
    std::vector<Live> m_live;
    StationProfile m_profile;
    QList<ProfileIssue> m_issues;
    QList<DriveInfo> m_drives;
    std::vector<double> m_commands;
    std::vector<double> m_lastCommands;
    int m_activeBank = 0;
    int m_implicitKeyboard = -1;  ///< index in m_live of the implicit keyboard mappings
    double m_now = 0.0;
    bool m_replayOnly = false;
    bool m_holding = false;
    InputRecorder* m_recorder = nullptr;
};

}  // namespace trainer
