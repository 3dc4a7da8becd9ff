#include "ide/studio/station/live_state.h"

#include <QCoreApplication>

namespace studio {

std::shared_ptr<const trainer::StationState> stationState(trainer::Station* station)
{
    if (!station) return nullptr;
    if (station->isRunning()) return station->latest();
    std::shared_ptr<const trainer::StationState> state;
    station->call([&](trainer::StationEngine& e) { state = std::make_shared<const trainer::StationState>(e.state()); });
    return state;
}

const trainer::DeviceState* findDevice(const trainer::StationState& state, const QString& id, bool replay)
{
    for (const trainer::DeviceState& d : state.devices)
        if (d.info.id == id && d.replay == replay) return &d;
    return nullptr;
}

QString hudBankLine(const trainer::StationState& state)
{
    if (state.bankNames.size() < 2 || !state.bankSwitchConnected) return {};
    QString line = QCoreApplication::translate("studio::StationHud", "Bank: <b>%1</b> (%2 of %3)")
                       .arg(state.bankNames.value(state.activeBank).toHtmlEscaped())
                       .arg(state.activeBank + 1)
                       .arg(state.bankNames.size());
    if (!state.bankSwitchHint.isEmpty()) line += QStringLiteral(" · ") + state.bankSwitchHint.toHtmlEscaped();
    return line;
}

QStringList hudWarnings(const trainer::StationState& state)
{
    QStringList lines;
    if (!state.devicesMissing.isEmpty()) lines << state.devicesMissing;
    lines += state.warnings;
    return lines;
}

QString calibrationKey(const trainer::StationProfile& profile, const trainer::DeviceInfo& device, int axis)
{
    if (const auto* c = profile.calibration(device.id, axis); c && c->isValid()) return device.id;
    const QString kind = trainer::kindKey(device.kind);
    if (const auto* c = profile.calibration(kind, axis); c && c->isValid()) return kind;
    return {};
}

trainer::ChannelCalibration channelCalibration(const trainer::StationProfile& profile,
                                               const trainer::DeviceInfo& device, int axis)
{
    const QString key = calibrationKey(profile, device, axis);
    if (!key.isEmpty()) return *profile.calibration(key, axis);
    trainer::ChannelCalibration c;
    if (axis >= 0 && axis < device.axes.size()) {
        const trainer::AxisInfo& a = device.axes[axis];
        c.rawMin = a.rawMin;
        c.rawCentre = a.rawRest;
        c.rawMax = a.rawMax;
    }
    c.captured = false;
    if (!c.isValid()) c = trainer::ChannelCalibration{-1.0, 0.0, 1.0};
    return c;
}

QString statusName(trainer::DeviceStatus status)
{
    switch (status) {
    case trainer::DeviceStatus::Connected: return QCoreApplication::translate("studio::StationPage", "Connected");
    case trainer::DeviceStatus::Disconnected: return QCoreApplication::translate("studio::StationPage", "Disconnected");
    case trainer::DeviceStatus::Stalled: return QCoreApplication::translate("studio::StationPage", "Stalled");
    case trainer::DeviceStatus::Failed: return QCoreApplication::translate("studio::StationPage", "Failed");
    }
    return {};
}

QColor statusColor(trainer::DeviceStatus status)
{
    switch (status) {
    case trainer::DeviceStatus::Connected: return QColor(0x2e, 0x7d, 0x32);
    case trainer::DeviceStatus::Disconnected: return QColor(0x75, 0x75, 0x75);
    case trainer::DeviceStatus::Stalled: return amberColor();
    case trainer::DeviceStatus::Failed: return redColor();
    }
    return {};
}

QColor amberColor() { return QColor(0xc7, 0x7c, 0x02); }
QColor redColor() { return QColor(0xc6, 0x28, 0x28); }

}  // namespace studio
