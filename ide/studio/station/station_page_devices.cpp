// StationPage's devices (serial consoles added and removed, input recorded and replayed)
// and their calibration. The rest of the page is in station_page.cpp.

#include "ide/studio/station/station_page.h"

#include "ide/studio/station/calibration_wizard.h"
#include "ide/studio/station/channel_bars.h"
#include "ide/studio/station/live_state.h"
#include "trainer/input/input_log.h"

#include <QFileInfo>
#include <QTreeWidget>

namespace studio {

// ---- devices -------------------------------------------------------------------

bool StationPage::addSerialConsole(const trainer::DeviceSetting& settingIn)
{
    trainer::DeviceSetting setting = settingIn;
    if (setting.id.isEmpty()) {
        const auto answer = askSerialConsole();
        if (!answer) return false;
        setting = *answer;
    }
    if (!setting.id.startsWith(QLatin1String("serial:")) || setting.id.size() <= 7) {
        tell(tr("Add serial console"), tr("“%1” is not a serial port (serial:/dev/…)").arg(setting.id));
        return false;
    }
    const auto same = std::find_if(m_doc.edit().devices.begin(), m_doc.edit().devices.end(),
                                   [&](const trainer::DeviceSetting& d) { return d.id == setting.id; });
    if (same != m_doc.edit().devices.end()) {
        if (*same == setting) return true;
        // another baud rate: the device is opened again
        m_doc.edit().devices.erase(same);
        const trainer::StationProfile p = m_doc.edit();
        if (m_station) m_station->post([p](trainer::StationEngine& e) { e.setProfile(p); });
    }
    m_doc.edit().devices.append(setting);
    setDirty(true);
    install(true);
    selectDevice(setting.id);
    return true;
}

bool StationPage::removeSelectedDevice()
{
    if (m_selectedReplay) return false;
    const auto it = std::find_if(m_doc.edit().devices.begin(), m_doc.edit().devices.end(),
                                 [&](const trainer::DeviceSetting& d) { return d.id == m_selectedId; });
    if (it == m_doc.edit().devices.end()) return false;
    m_doc.edit().devices.erase(it);
    setDirty(true);
    install(true);
    return true;
}

void StationPage::selectDevice(const QString& id, bool replay)
{
    m_selectedId = id;
    m_selectedReplay = replay;
    {
        const QSignalBlocker block(m_devices);
        for (int i = 0; i < m_devices->topLevelItemCount(); ++i) {
            QTreeWidgetItem* item = m_devices->topLevelItem(i);
            if (item->data(NameColumn, kNameRole).toString() == id &&
                item->data(NameColumn, kReplayRole).toBool() == replay)
                m_devices->setCurrentItem(item);
        }
    }
    m_channels->setDevice(m_state ? findDevice(*m_state, id, replay) : nullptr, m_doc.edit());
    updateButtons();
}

bool StationPage::startRecording(const QString& fileIn)
{
    if (m_recorder || !m_station) return false;
    const QString file = fileIn.isEmpty() ? askSaveFile(tr("Record input"), tr("Padrob input logs (*.log);;All files (*)"),
                                                        QStringLiteral("input.log"))
                                          : fileIn;
    if (file.isEmpty()) return false;
    if (QFileInfo::exists(file) && !ask(tr("Record input"), tr("%1 exists already. Replace it?").arg(file))) return false;
    auto recorder = std::make_unique<trainer::InputRecorder>();
    QString error;
    if (!m_station->startRecording(*recorder, file, &error)) {
        tell(tr("Record input"), tr("Cannot record to %1: %2").arg(file, error));
        return false;
    }
    m_recorder = std::move(recorder);
    m_recordFile = file;
    m_recordClock.start();
    updateButtons();
    return true;
}

bool StationPage::stopRecording()
{
    if (!m_recorder) return false;
    QString error;
    const bool ok = m_station ? m_station->stopRecording(*m_recorder, &error) : m_recorder->stop(&error);
    m_recorder.reset();
    updateButtons();
    if (!ok) tell(tr("Record input"), tr("The log %1 may be incomplete: %2").arg(m_recordFile, error));
    return ok;
}

bool StationPage::startReplay(const QString& fileIn)
{
    if (!m_station || isReplaying()) return false;
    const QString file =
        fileIn.isEmpty() ? askOpenFile(tr("Replay a log"), tr("Padrob input logs (*.log);;All files (*)")) : fileIn;
    if (file.isEmpty()) return false;
    auto log = std::make_shared<trainer::InputLog>();
    QString error;
    if (!trainer::InputLog::load(file, *log, &error)) {
        tell(tr("Replay a log"), tr("Cannot replay %1: %2").arg(QFileInfo(file).fileName(), error));
        return false;
    }
    if (log->devices.isEmpty()) {
        tell(tr("Replay a log"), tr("%1 has no devices to replay").arg(QFileInfo(file).fileName()));
        return false;
    }
    m_replays = trainer::replayDevices(log);
    m_replayFile = file;
    const auto devices = m_replays;
    m_station->post([devices](trainer::StationEngine& e) {
        for (const auto& d : devices) e.addDevice(d);
        e.setReplayOnly(true);
    });
    updateButtons();
    refresh();
    return true;
}

void StationPage::stopReplay()
{
    if (!isReplaying()) return;
    auto devices = std::move(m_replays);
    m_replays.clear();
    if (m_station)
        m_station->post([devices](trainer::StationEngine& e) {
            for (const auto& d : devices) e.removeDevice(d.get());
            e.setReplayOnly(false);
        });
    if (m_selectedReplay) selectDevice({});
    updateButtons();
    refresh();
}

// ---- calibration ---------------------------------------------------------------

CalibrationWizard* StationPage::calibrate(int axis)
{
    if (!m_state) refresh();
    const trainer::DeviceState* d = m_state ? findDevice(*m_state, m_selectedId, m_selectedReplay) : nullptr;
    if (!d || axis < 0 || axis >= d->info.axes.size()) return nullptr;
    if (d->info.kind == trainer::DeviceKind::Keyboard) return nullptr;  // digital: a ramp instead (setKeyRamp)
    if (m_wizard) m_wizard->close();
    auto* wizard = new CalibrationWizard(m_station, d->info, d->replay, axis, channelCalibration(m_doc.edit(), d->info, axis),
                                         calibrationKey(m_doc.edit(), d->info, axis), this);
    wizard->setAttribute(Qt::WA_DeleteOnClose);
    const QString id = d->info.id;
    connect(wizard, &CalibrationWizard::calibrationReady, this,
            [this, id](const QString& match, int a, const trainer::ChannelCalibration& c) {
                // kept for "any gamepad": this device's own entry would still win over it
                if (match != id) {
                    const auto before = m_doc.edit().calibrations.size();
                    m_doc.edit().calibrations.removeIf(
                        [&](const trainer::CalibrationEntry& entry) { return entry.device == id && entry.axis == a; });
                    if (m_doc.edit().calibrations.size() != before) {
                        m_doc.edit().setCalibration(match, a, c);
                        setDirty(true);
                        install(true);
                        return;
                    }
                }
                applyCalibration(match, a, c);
            });
    // the lever being calibrated must not move the machine: valves held while the wizard is open
    if (m_station) m_station->post([](trainer::StationEngine& e) { e.setHolding(true); });
    connect(wizard, &QObject::destroyed, this, [station = QPointer<trainer::Station>(m_station)] {
        if (station) station->post([](trainer::StationEngine& e) { e.setHolding(false); });
    });
    m_wizard = wizard;
    wizard->open();
    return wizard;
}

void StationPage::setKeyRamp(int axis, double seconds)
{
    if (!m_state) refresh();
    const trainer::DeviceState* d = m_state ? findDevice(*m_state, m_selectedId, m_selectedReplay) : nullptr;
    if (!d || d->info.kind != trainer::DeviceKind::Keyboard || axis < 0 || axis >= d->info.axes.size()) return;
    trainer::ChannelCalibration c = channelCalibration(m_doc.edit(), d->info, axis);
    c.filterHz = ChannelPanel::rampFilterHz(seconds);
    applyCalibration(d->info.id, axis, c);
}

void StationPage::applyCalibration(const QString& deviceMatch, int axis, const trainer::ChannelCalibration& calibration)
{
    m_doc.edit().setCalibration(deviceMatch, axis, calibration);
    setDirty(true);
    if (m_station)
        m_station->post([deviceMatch, axis, calibration](trainer::StationEngine& e) {
            e.setCalibration(deviceMatch, axis, calibration);
        });
    emit profileChanged(m_doc.edit());
    refresh();
}

}  // namespace studio
