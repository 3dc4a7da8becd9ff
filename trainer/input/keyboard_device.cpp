#include "trainer/input/keyboard_device.h"

#include <QCoreApplication>

#include <algorithm>

namespace trainer {

KeyboardDevice::KeyboardDevice(const QStringList& pairs)
{
    m_info.id = QStringLiteral("keyboard");
    m_info.name = QCoreApplication::translate("trainer::KeyboardDevice", "Keyboard");
    m_info.kind = DeviceKind::Keyboard;
    for (int i = 0; i < pairs.size() && i < kMaxChannels; ++i) m_info.axes.append({pairs[i], -1.0, 0.0, 1.0});
    m_sample.axes.assign(std::size_t(m_info.axes.size()), 0.0);
    for (auto& k : m_keys) k.store(0, std::memory_order_relaxed);
}

void KeyboardDevice::setKeys(int channel, bool plus, bool minus)
{
    if (channel < 0 || channel >= m_info.axes.size()) return;
    m_keys[std::size_t(channel)].store(int(plus) - int(minus), std::memory_order_relaxed);
    m_version.fetch_add(1, std::memory_order_release);
}

void KeyboardDevice::releaseAll()
{
    for (auto& k : m_keys) k.store(0, std::memory_order_relaxed);
    m_version.fetch_add(1, std::memory_order_release);
}

void KeyboardDevice::poll(double now)
{
    const unsigned version = m_version.load(std::memory_order_acquire);
    if (version == m_seen) return;
    m_seen = version;
    for (std::size_t i = 0; i < m_sample.axes.size(); ++i)
        m_sample.axes[i] = m_keys[i].load(std::memory_order_relaxed);
    m_sample.time = now;
    ++m_sample.count;
}

}  // namespace trainer
