#include "trainer/station/control_names.h"

#include "trainer/station/profile.h"

#include <QCoreApplication>

namespace trainer {

namespace {

/// The translation context of the controls' names (lupdate reads Tr::tr).
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(trainer::Gamepad)
};

}  // namespace

QString gamepadAxisName(int axis)
{
    switch (axis) {
    case gamepad::LeftX: return Tr::tr("Left stick X");
    case gamepad::LeftY: return Tr::tr("Left stick Y");
    case gamepad::RightX: return Tr::tr("Right stick X");
    case gamepad::RightY: return Tr::tr("Right stick Y");
    case gamepad::LeftTrigger: return Tr::tr("Left trigger");
    case gamepad::RightTrigger: return Tr::tr("Right trigger");
    default: return {};
    }
}

QString gamepadButtonName(int button)
{
    switch (button) {
    case gamepad::A: return QStringLiteral("A");
    case gamepad::B: return QStringLiteral("B");
    case gamepad::X: return QStringLiteral("X");
    case gamepad::Y: return QStringLiteral("Y");
    case gamepad::Back: return Tr::tr("Back");
    case gamepad::Guide: return Tr::tr("Guide");
    case gamepad::Start: return Tr::tr("Start");
    case gamepad::LeftStick: return Tr::tr("Left stick press");
    case gamepad::RightStick: return Tr::tr("Right stick press");
    case gamepad::LeftShoulder: return Tr::tr("Left shoulder");
    case gamepad::RightShoulder: return Tr::tr("Right shoulder");
    case gamepad::DpadUp: return Tr::tr("D-pad up");
    case gamepad::DpadDown: return Tr::tr("D-pad down");
    case gamepad::DpadLeft: return Tr::tr("D-pad left");
    case gamepad::DpadRight: return Tr::tr("D-pad right");
    case gamepad::DpadRight + 1: return Tr::tr("Misc");
    case gamepad::DpadRight + 2:
    case gamepad::DpadRight + 3:
    case gamepad::DpadRight + 4:
    case gamepad::DpadRight + 5: return Tr::tr("Paddle %1").arg(button - gamepad::DpadRight - 1);
    case gamepad::DpadRight + 6: return Tr::tr("Touchpad");
    default: return {};
    }
}

QString gamepadButtonLabel(int button)
{
    switch (button) {
    case gamepad::LeftStick: return Tr::tr("LS", "left stick pressed, on a small lamp");
    case gamepad::RightStick: return Tr::tr("RS", "right stick pressed, on a small lamp");
    case gamepad::LeftShoulder: return Tr::tr("LB", "left shoulder button, on a small lamp");
    case gamepad::RightShoulder: return Tr::tr("RB", "right shoulder button, on a small lamp");
    case gamepad::DpadUp: return QStringLiteral("↑");
    case gamepad::DpadDown: return QStringLiteral("↓");
    case gamepad::DpadLeft: return QStringLiteral("←");
    case gamepad::DpadRight: return QStringLiteral("→");
    case gamepad::DpadRight + 2:
    case gamepad::DpadRight + 3:
    case gamepad::DpadRight + 4:
    case gamepad::DpadRight + 5: return QStringLiteral("P%1").arg(button - gamepad::DpadRight - 1);
    default: return gamepadButtonName(button);
    }
}

bool isGamepad(const QString& deviceMatch, const DeviceInfo* resolved)
{
    return deviceMatch == kindKey(DeviceKind::Gamepad) || (resolved && resolved->kind == DeviceKind::Gamepad);
}

QString axisName(const DeviceInfo& device, int axis)
{
    if (device.kind == DeviceKind::Gamepad) {
        const QString name = gamepadAxisName(axis);
        if (!name.isEmpty()) return name;
    }
    if (axis >= 0 && axis < device.axes.size() && !device.axes[axis].name.isEmpty()) return device.axes[axis].name;
    return Tr::tr("Axis %1").arg(axis + 1);
}

QString buttonName(const DeviceInfo& device, int button)
{
    if (device.kind == DeviceKind::Gamepad) {
        const QString name = gamepadButtonName(button);
        if (!name.isEmpty()) return name;
    }
    if (button >= 0 && button < device.buttons.size() && !device.buttons[button].isEmpty()) return device.buttons[button];
    return Tr::tr("Button %1").arg(button + 1);
}

}  // namespace trainer
