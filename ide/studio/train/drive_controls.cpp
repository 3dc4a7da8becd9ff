#include "ide/studio/train/drive_controls.h"

#include "ide/studio/sim/keyboard_input.h"
#include "trainer/station/station_engine.h"
#include "trainer/training/tutorial.h"

#include <QCoreApplication>

#include <algorithm>

namespace studio {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(DriveControls)
};

bool isKeyboard(const trainer::Mapping& m)
{
    return m.device == QLatin1String("keyboard");
}

/// A gamepad's axis and which way of it gives +: "left stick up", "right trigger".
QString gamepadAxis(int axis, int sign)
{
    using namespace trainer::gamepad;
    // SDL: a stick's x grows to the right, its y downwards; a trigger from 0 pressed in
    const bool up = sign < 0;
    switch (axis) {
    case LeftX: return sign > 0 ? Tr::tr("left stick right + / left −") : Tr::tr("left stick left + / right −");
    case LeftY: return up ? Tr::tr("left stick up + / down −") : Tr::tr("left stick down + / up −");
    case RightX: return sign > 0 ? Tr::tr("right stick right + / left −") : Tr::tr("right stick left + / right −");
    case RightY: return up ? Tr::tr("right stick up + / down −") : Tr::tr("right stick down + / up −");
    case LeftTrigger: return sign > 0 ? Tr::tr("left trigger +") : Tr::tr("left trigger −");
    case RightTrigger: return sign > 0 ? Tr::tr("right trigger +") : Tr::tr("right trigger −");
    default: break;
    }
    return Tr::tr("gamepad axis %1").arg(axis + 1);
}

}  // namespace

QString controlText(const trainer::Mapping& m, const QString& bank)
{
    QString text;
    if (isKeyboard(m)) {
        // the pair's first key gives +1 (KeyboardDevice), the mapping's sign may turn it
        const QStringList keys = KeyboardInput::pairNames().value(m.axis).split(QStringLiteral(" / "));
        const QString plus = keys.value(m.sign > 0 ? 0 : 1), minus = keys.value(m.sign > 0 ? 1 : 0);
        text = Tr::tr("%1 + / %2 −", "the key giving the drive +, the one giving −").arg(plus, minus);
    } else if (m.device == QLatin1String("gamepad") || m.device.startsWith(QLatin1String("sdl:"))) {
        text = gamepadAxis(m.axis, m.sign);
    } else if (m.device == QLatin1String("joystick")) {
        text = m.sign > 0 ? Tr::tr("joystick axis %1").arg(m.axis + 1) : Tr::tr("joystick axis %1 reversed").arg(m.axis + 1);
    } else {
        // a lever of the console (serial DAQ, Comedi): levers are numbered from 1
        text = m.sign > 0 ? Tr::tr("lever %1").arg(m.axis + 1) : Tr::tr("lever %1 reversed").arg(m.axis + 1);
    }
    return bank.isEmpty() ? text : Tr::tr("%1 (bank %2)").arg(text, bank);
}

QString DriveControls::text() const
{
    return Tr::tr("%1: %2").arg(drive.label(), controls.isEmpty() ? Tr::tr("no control") : controls.join(QStringLiteral(" · ")));
}

QList<DriveControls> driveControls(const trainer::Tutorial& t, const trainer::StationProfile& profile,
                                   const QStringList* devices)
{
    const QList<trainer::DriveInfo> drives = trainer::drivesOf(*t.model);
    // the mappings with their bank's name ("" always)
    QList<std::pair<trainer::Mapping, QString>> mappings;
    for (const trainer::Mapping& m : profile.always) mappings.append({m, QString()});
    for (const trainer::Bank& b : profile.banks)
        for (const trainer::Mapping& m : b.mappings) mappings.append({m, profile.banks.size() > 1 ? b.name : QString()});
    // the keyboard always works: the station's own pairs unless the profile maps it
    const bool keyboardMapped =
        std::any_of(mappings.begin(), mappings.end(), [](const auto& m) { return isKeyboard(m.first); });
    if (!keyboardMapped)
        for (int k = 0; k < drives.size() && k < trainer::StationEngine::kKeyboardPairs; ++k)
            mappings.append({trainer::Mapping{QStringLiteral("keyboard"), k, drives[k].jointId, 1.0, 1}, QString()});
    QList<DriveControls> out;
    for (const trainer::DriveInfo& d : drives) {
        if (std::size_t(d.treeJoint) >= t.enabled.size() || !t.enabled[std::size_t(d.treeJoint)]) continue;
        DriveControls c{d, {}};
        // the keyboard first (every station has one), then the profile's devices
        for (const bool keys : {true, false})
            for (const auto& [m, bank] : mappings)
                if (m.drive == d.jointId && isKeyboard(m) == keys && (!devices || devices->contains(m.device)))
                    c.controls.append(controlText(m, bank));
        c.controls.removeDuplicates();
        out.append(c);
    }
    return out;
}

QString driveControlsHtml(const QList<DriveControls>& controls)
{
    QStringList lines;
    for (const DriveControls& c : controls) lines << c.text().toHtmlEscaped();
    return lines.join(QStringLiteral("<br>"));
}

}  // namespace studio
