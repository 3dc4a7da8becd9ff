#pragma once
// A device the test sets by hand: axes, buttons, status (trainer and studio tests).
#include "trainer/input/input_device.h"

namespace test {

class FakeDevice : public trainer::InputDevice {
public:
    FakeDevice(QString id, trainer::DeviceKind kind, int axes, int buttons, double min = -100, double rest = 0,
               double max = 100, QString name = {})
    {
        m_info.id = std::move(id);
        m_info.name = name.isEmpty() ? "Fake " + m_info.id : name;
        m_info.kind = kind;
        for (int a = 0; a < axes; ++a) m_info.axes.append({QString("Axis %1").arg(a + 1), min, rest, max});
        for (int b = 0; b < buttons; ++b) m_info.buttons.append(QString("Button %1").arg(b + 1));
        m_sample.axes.assign(std::size_t(axes), rest);
        m_sample.buttons.assign(std::size_t(buttons), 0);
    }
    const trainer::DeviceInfo& info() const override { return m_info; }
    void poll(double now) override
    {
        if (m_status != trainer::DeviceStatus::Connected) return;
        m_sample.time = now;
        ++m_sample.count;
    }
    const trainer::DeviceSample& sample() const override { return m_sample; }
    trainer::DeviceStatus status() const override { return m_status; }
    QString statusText() const override
    {
        return m_status == trainer::DeviceStatus::Connected ? QString() : QStringLiteral("unplugged");
    }

    void setAxis(int a, double v) { m_sample.axes[std::size_t(a)] = v; }
    void setButton(int b, bool down) { m_sample.buttons[std::size_t(b)] = down ? 1 : 0; }
    void setStatus(trainer::DeviceStatus s) { m_status = s; }

private:
    trainer::DeviceInfo m_info;
    trainer::DeviceSample m_sample;
    trainer::DeviceStatus m_status = trainer::DeviceStatus::Connected;
};

}  // namespace test
