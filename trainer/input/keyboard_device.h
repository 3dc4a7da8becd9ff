#pragma once
// KeyboardDevice: the keyboard as a station device, for a laptop with no hardware.
// Each channel is a pair of keys: the first held gives +1, the second −1, both or
// neither 0 (raw values −1/0/+1, nominal range −1…1, already "calibrated"). The key
// events arrive in the GUI thread (studio::KeyboardInput) and are read by the station
// in its input thread: press()/release() are thread-safe (atomics), poll() reads them.

#include "trainer/input/input_device.h"

#include <QStringList>

#include <array>
#include <atomic>

namespace trainer {

class KeyboardDevice : public InputDevice {
public:
    static constexpr int kMaxChannels = 16;

    /// `pairs`: the key pairs' names as shown ("Q / A", …), one channel each (at most
    /// kMaxChannels).
    explicit KeyboardDevice(const QStringList& pairs);

    /// Any thread: the state of channel `channel`'s keys.
    void setKeys(int channel, bool plus, bool minus);
    void releaseAll();

    const DeviceInfo& info() const override { return m_info; }
    void poll(double now) override;
    const DeviceSample& sample() const override { return m_sample; }
    DeviceStatus status() const override { return DeviceStatus::Connected; }

private:
    DeviceInfo m_info;
    DeviceSample m_sample;
    std::array<std::atomic<int>, kMaxChannels> m_keys{};  ///< −1, 0, +1
    std::atomic<unsigned> m_version{0};
    unsigned m_seen = ~0u;
};

}  // namespace trainer
