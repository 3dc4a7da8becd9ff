#include "trainer/input/input_device.h"

#include <QCoreApplication>

namespace trainer {

QString kindName(DeviceKind kind)
{
    switch (kind) {
    case DeviceKind::Joystick: return QCoreApplication::translate("trainer::InputDevice", "Joystick");
    case DeviceKind::Gamepad: return QCoreApplication::translate("trainer::InputDevice", "Gamepad");
    case DeviceKind::SerialDaq: return QCoreApplication::translate("trainer::InputDevice", "Serial DAQ console");
    case DeviceKind::Comedi: return QCoreApplication::translate("trainer::InputDevice", "Comedi DAQ card");
    case DeviceKind::Keyboard: return QCoreApplication::translate("trainer::InputDevice", "Keyboard");
    case DeviceKind::Replay: return QCoreApplication::translate("trainer::InputDevice", "Replay");
    }
    return {};
}

QString displayName(const DeviceInfo& info)
{
    // (KeyboardDevice names itself in the language of its start)
    if (info.kind == DeviceKind::Keyboard) return QCoreApplication::translate("trainer::KeyboardDevice", "Keyboard");
    if (info.kind == DeviceKind::SerialDaq && info.namedByPadrob && info.id.startsWith(QLatin1String("serial:")))
        return QCoreApplication::translate("trainer::SerialDaq", "DAQ console on %1").arg(info.id.mid(7));
    return info.name;
}

QString kindKey(DeviceKind kind)
{
    switch (kind) {
    case DeviceKind::Joystick: return QStringLiteral("joystick");
    case DeviceKind::Gamepad: return QStringLiteral("gamepad");
    case DeviceKind::SerialDaq: return QStringLiteral("serial");
    case DeviceKind::Comedi: return QStringLiteral("comedi");
    case DeviceKind::Keyboard: return QStringLiteral("keyboard");
    case DeviceKind::Replay: return QStringLiteral("replay");
    }
    return {};
}

}  // namespace trainer
