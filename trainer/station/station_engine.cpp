#include "trainer/station/station_engine.h"

#include "trainer/input/input_log.h"
#include "trainer/station/control_names.h"
#include "trainer/station/device_factory.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace trainer {

namespace {

/// The translation context of this file's messages (lupdate reads Tr::tr).
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(trainer::StationEngine)
};

bool isConnected(const InputDevice& d)
{
    return d.status() == DeviceStatus::Connected;
}

}  // namespace

StationEngine::StationEngine() = default;
StationEngine::~StationEngine() = default;

void StationEngine::setDrives(int treeJointCount, const QList<DriveInfo>& drives)
{
    m_drives = drives;
    m_commands.assign(std::size_t(std::max(0, treeJointCount)), 0.0);
    m_issues = m_profile.check(m_drives);
    rebuildLive();
}

QList<ProfileIssue> StationEngine::setProfile(const StationProfile& profile)
{
    m_profile = profile;
    m_issues = m_profile.check(m_drives);
    // devices the profile lists: open the new ones, close those no longer listed
    for (std::size_t i = m_devices.size(); i-- > 0;) {
        if (!m_state[i].fromProfile) continue;
        const QString id = m_devices[i]->info().id;
        const bool listed = std::any_of(profile.devices.begin(), profile.devices.end(),
                                        [&](const DeviceSetting& s) { return s.id == id; });
        if (!listed) {
            m_devices.erase(m_devices.begin() + std::ptrdiff_t(i));
            m_state.erase(m_state.begin() + std::ptrdiff_t(i));
        }
    }
    for (int i = 0; i < profile.devices.size(); ++i) {
        const DeviceSetting& s = profile.devices[i];
        const bool present = std::any_of(m_devices.begin(), m_devices.end(),
                                         [&](const auto& d) { return d->info().id == s.id; });
        if (present) continue;
        QString why;
        if (auto device = openDevice(s, &why)) {
            addDevice(std::move(device));
            m_state.back().fromProfile = true;
        } else {
            m_issues.append({QStringLiteral("devices[%1]").arg(i), why, false});
        }
    }
    m_activeBank = 0;
    refreshCalibrations();
    rebuildLive();
    return m_issues;
}

void StationEngine::setCalibration(const QString& device, int axis, const ChannelCalibration& c)
{
    m_profile.setCalibration(device, axis, c);
    refreshCalibrations();
}

void StationEngine::addProvider(std::unique_ptr<DeviceProvider> provider)
{
    if (provider) m_providers.push_back(std::move(provider));
}

void StationEngine::addDevice(std::shared_ptr<InputDevice> device)
{
    if (!device) return;
    m_devices.push_back(std::move(device));
    m_state.emplace_back();
    refreshCalibrations();
    rebuildLive();
}

void StationEngine::removeDevice(const QString& id)
{
    for (std::size_t i = 0; i < m_devices.size(); ++i) {
        if (m_devices[i]->info().id != id) continue;
        m_devices.erase(m_devices.begin() + std::ptrdiff_t(i));
        m_state.erase(m_state.begin() + std::ptrdiff_t(i));
        rebuildLive();
        return;
    }
}

void StationEngine::removeDevice(const InputDevice* device)
{
    for (std::size_t i = 0; i < m_devices.size(); ++i) {
        if (m_devices[i].get() != device) continue;
        m_devices.erase(m_devices.begin() + std::ptrdiff_t(i));
        m_state.erase(m_state.begin() + std::ptrdiff_t(i));
        rebuildLive();
        return;
    }
}

void StationEngine::setReplayOnly(bool replayOnly)
{
    if (m_replayOnly == replayOnly) return;
    m_replayOnly = replayOnly;
    rebuildLive();
}

bool StationEngine::isImplicitKeyboard(const Live& l) const
{
    return m_implicitKeyboard >= 0 && &l - m_live.data() >= m_implicitKeyboard;
}

QString StationEngine::deviceName(const QString& match)
{
    for (DeviceKind k : {DeviceKind::Gamepad, DeviceKind::Joystick, DeviceKind::SerialDaq, DeviceKind::Comedi,
                         DeviceKind::Keyboard})
        if (kindKey(k) == match) return kindName(k);
    return match;
}

bool StationEngine::ignored(const InputDevice& d) const
{
    return m_replayOnly != d.isReplay();
}

int StationEngine::indexOf(const QString& match) const
{
    int firstOfKind = -1;
    for (std::size_t i = 0; i < m_devices.size(); ++i) {
        const InputDevice& d = *m_devices[i];
        if (ignored(d)) continue;
        if (d.info().id == match) return int(i);
        if (kindKey(d.info().kind) == match) {
            if (isConnected(d)) return int(i);
            if (firstOfKind < 0) firstOfKind = int(i);
        }
    }
    return firstOfKind;
}

InputDevice* StationEngine::resolve(const QString& match) const
{
    const int i = indexOf(match);
    return i < 0 ? nullptr : m_devices[std::size_t(i)].get();
}

void StationEngine::refreshCalibrations()
{
    for (std::size_t i = 0; i < m_devices.size(); ++i) {
        const DeviceInfo& info = m_devices[i]->info();
        Device& dev = m_state[i];
        dev.channels.resize(std::size_t(info.axes.size()));
        for (int a = 0; a < info.axes.size(); ++a) {
            Channel& ch = dev.channels[std::size_t(a)];
            ch.nominalMin = std::min(info.axes[a].rawMin, info.axes[a].rawMax);
            ch.nominalMax = std::max(info.axes[a].rawMin, info.axes[a].rawMax);
            const ChannelCalibration* c = m_profile.calibration(info.id, a);
            if (!c) c = m_profile.calibration(kindKey(info.kind), a);
            if (c && c->isValid()) {
                ch.calibration = *c;
            } else {
                const AxisInfo& ax = info.axes[a];
                ch.calibration = ChannelCalibration{};
                ch.calibration.rawMin = ax.rawMin;
                ch.calibration.rawCentre = ax.rawRest;
                ch.calibration.rawMax = ax.rawMax;
                ch.calibration.captured = false;
                if (!ch.calibration.isValid()) ch.calibration = ChannelCalibration{-1.0, 0.0, 1.0};
            }
            // keys give exactly −1/0/+1: nothing to calibrate
            ch.state.calibrated = (c && c->isValid()) || info.kind == DeviceKind::Keyboard;
        }
    }
}

void StationEngine::rebuildLive()
{
    m_live.clear();
    auto add = [&](const Mapping& m, int bank) {
        Live l;
        l.mapping = m;
        l.bank = bank;
        for (const DriveInfo& d : m_drives)
            if (d.jointId == m.drive && d.treeJoint >= 0 && std::size_t(d.treeJoint) < m_commands.size())
                l.treeJoint = d.treeJoint;
        const bool valid = (m.sign == 1 || m.sign == -1) && std::isfinite(m.gain) && m.gain >= 0.0 &&
                           m.gain <= Mapping::kMaxGain && m.axis >= 0;
        if (!valid) l.treeJoint = -1;
        l.device = indexOf(m.device);
        m_live.push_back(l);
    };
    for (const Mapping& m : m_profile.always) add(m, -1);
    for (int b = 0; b < m_profile.banks.size(); ++b)
        for (const Mapping& m : m_profile.banks[b].mappings) add(m, b);
    // the keyboard always works: its key pairs on the drives in order, unless the
    // profile maps the keyboard itself
    const auto mapsKeyboard = [](const QList<Mapping>& list) {
        return std::any_of(list.begin(), list.end(),
                           [](const Mapping& m) { return m.device == QLatin1String("keyboard"); });
    };
    bool keyboardMapped = mapsKeyboard(m_profile.always);
    for (const Bank& b : m_profile.banks) keyboardMapped = keyboardMapped || mapsKeyboard(b.mappings);
    if (!keyboardMapped) {
        m_implicitKeyboard = int(m_live.size());
        for (int k = 0; k < m_drives.size() && k < kKeyboardPairs; ++k)
            add({QStringLiteral("keyboard"), k, m_drives[k].jointId, 1.0, 1}, -1);
    } else {
        m_implicitKeyboard = -1;
    }
    std::fill(m_commands.begin(), m_commands.end(), 0.0);
}

void StationEngine::setHolding(bool holding)
{
    if (holding == m_holding) return;
    m_holding = holding;
    for (Live& l : m_live) l.armed = false;
}

void StationEngine::disarmBank(int bank)
{
    for (Live& l : m_live)
        if (l.bank == bank) l.armed = false;
}

void StationEngine::selectBank(int bank)
{
    if (bank < 0 || bank >= m_profile.banks.size() || bank == m_activeBank) return;
    disarmBank(m_activeBank);
    m_activeBank = bank;
    disarmBank(bank);
}

bool StationEngine::update(double now)
{
    m_now = now;
    bool devicesChanged = false;
    for (auto& provider : m_providers) {
        for (auto& device : provider->poll(now)) {
            m_devices.push_back(std::move(device));
            m_state.emplace_back();
            devicesChanged = true;
        }
    }
    if (devicesChanged) refreshCalibrations();

    // read and calibrate
    int requestedBank = -1;
    for (std::size_t i = 0; i < m_devices.size(); ++i) {
        InputDevice& d = *m_devices[i];
        Device& dev = m_state[i];
        d.poll(now);
        if (std::size_t(d.info().axes.size()) != dev.channels.size()) {
            refreshCalibrations();  // the device learnt its channel count (a DAQ's identification)
            devicesChanged = true;
        }
        const bool connected = isConnected(d);
        if (connected && !dev.wasConnected) {
            devicesChanged = true;  // (re)connected: its mappings must be re-armed
            for (Live& l : m_live)
                if (l.device == int(i)) l.armed = false;
            for (Channel& ch : dev.channels) ch.filter.reset();
        }
        dev.wasConnected = connected;
        dev.everConnected = dev.everConnected || connected;
        const DeviceSample& s = d.sample();
        if (m_recorder && s.count != dev.lastCount) m_recorder->record(now, d, s);
        const double dt = dev.lastTime < 0.0 ? 0.0 : now - dev.lastTime;
        dev.lastTime = now;
        dev.lastCount = s.count;
        for (std::size_t a = 0; a < dev.channels.size(); ++a) {
            Channel& ch = dev.channels[a];
            const double raw = a < s.axes.size() ? s.axes[a] : ch.calibration.rawCentre;
            ch.state.raw = raw;
            const double margin = kFaultMargin * (ch.nominalMax - ch.nominalMin);
            const bool fault = !std::isfinite(raw) || raw < ch.nominalMin - margin || raw > ch.nominalMax + margin;
            if (fault && !ch.state.fault) {
                // a broken sensor or wire, never a lever pushed fully: that valve closes
                for (Live& l : m_live)
                    if (l.device == int(i) && l.mapping.axis == int(a)) l.armed = false;
                ch.filter.reset();
            }
            ch.state.fault = fault;
            ch.state.outOfRange = fault || (ch.state.calibrated && ch.calibration.outOfRange(raw));
            ch.state.value = fault ? 0.0 : ch.filter.update(ch.calibration.apply(raw), ch.calibration.filterHz, dt);
        }
        // bank buttons: on the press
        if (connected && !ignored(d)) {
            const std::size_t nb = s.buttons.size();
            if (dev.previousButtons.size() != nb) dev.previousButtons.assign(nb, 0);
            for (std::size_t b = 0; b < nb; ++b) {
                if (!s.buttons[b] || dev.previousButtons[b]) continue;
                const auto matches = [&](const ButtonRef& r) {
                    return r.button == int(b) && indexOf(r.device) == int(i);
                };
                if (matches(m_profile.nextBank) && !m_profile.banks.isEmpty())
                    requestedBank = (m_activeBank + 1) % int(m_profile.banks.size());
                for (int k = 0; k < m_profile.banks.size(); ++k)
                    for (const ButtonRef& r : m_profile.banks[k].select)
                        if (matches(r)) requestedBank = k;
            }
            std::copy(s.buttons.begin(), s.buttons.end(), dev.previousButtons.begin());
        }
    }
    if (devicesChanged) {
        for (Live& l : m_live) {
            const int resolved = indexOf(l.mapping.device);
            if (resolved != l.device) l.armed = false;
            l.device = resolved;
        }
    }
    if (requestedBank >= 0) selectBank(requestedBank);

    // map
    bool changed = false;
    for (double& u : m_commands) u = 0.0;
    for (Live& l : m_live) {
        l.contribution = 0.0;
        if (l.treeJoint < 0 || l.device < 0 || m_holding) continue;
        if (l.bank >= 0 && l.bank != m_activeBank) continue;
        const InputDevice& d = *m_devices[std::size_t(l.device)];
        const Device& dev = m_state[std::size_t(l.device)];
        if (!isConnected(d) || std::size_t(l.mapping.axis) >= dev.channels.size()) {
            l.armed = false;
            continue;
        }
        const double v = dev.channels[std::size_t(l.mapping.axis)].state.value;
        if (dev.channels[std::size_t(l.mapping.axis)].state.fault) continue;  // disarmed: the centre again after it
        if (!l.armed) {
            if (std::abs(v) >= kArmThreshold) continue;
            l.armed = true;
        }
        l.contribution = l.mapping.gain * l.mapping.sign * v;
        m_commands[std::size_t(l.treeJoint)] += l.contribution;
    }
    for (double& u : m_commands) u = std::clamp(u, -1.0, 1.0);
    if (m_commands != m_lastCommands) {
        changed = true;
        m_lastCommands = m_commands;
    }
    return changed;
}

StationState StationEngine::state() const
{
    StationState st;
    st.time = m_now;
    st.profileName = m_profile.name;
    st.activeBank = m_activeBank;
    for (const Bank& b : m_profile.banks) st.bankNames.append(m_profile.localized(b.name));  // in the GUI's language
    st.commands = m_commands;
    st.drives = m_drives;
    st.profileIssues = m_issues;
    for (std::size_t i = 0; i < m_devices.size(); ++i) {
        const InputDevice& d = *m_devices[i];
        const Device& dev = m_state[i];
        DeviceState ds;
        ds.info = d.info();
        ds.status = d.status();
        ds.statusText = d.statusText();
        for (const Channel& ch : dev.channels) ds.channels.push_back(ch.state);
        ds.buttons = d.sample().buttons;
        ds.samples = d.sample().count;
        ds.dropped = d.droppedSamples();
        ds.fromProfile = dev.fromProfile;
        ds.replay = d.isReplay();
        st.devices.append(ds);
    }
    auto driveLabel = [&](int treeJoint) {
        for (const DriveInfo& d : m_drives)
            if (d.treeJoint == treeJoint) return d.label();
        return QString();
    };
    QStringList waiting;
    for (const Live& l : m_live) {
        if (isImplicitKeyboard(l)) break;  // not the profile's
        MappingState ms;
        ms.mapping = l.mapping;
        ms.bank = l.bank;
        ms.treeJoint = l.treeJoint;
        ms.armed = l.armed;
        ms.contribution = l.contribution;
        if (l.device >= 0) {
            const InputDevice& d = *m_devices[std::size_t(l.device)];
            ms.deviceId = d.info().id;
            ms.connected = isConnected(d);
        }
        st.mappings.append(ms);
        const bool active = l.bank < 0 || l.bank == m_activeBank;
        if (active && ms.connected && !l.armed && l.treeJoint >= 0) waiting.append(driveLabel(l.treeJoint));
    }
    // the drives the active mappings of device i (of its channel `axis`; −1 any) hold
    const auto heldBy = [&](std::size_t i, int axis) {
        QStringList held;
        for (const Live& l : m_live)
            if (l.device == int(i) && (axis < 0 || l.mapping.axis == axis) && l.treeJoint >= 0 &&
                (l.bank < 0 || l.bank == m_activeBank) && !isImplicitKeyboard(l))
                held.append(driveLabel(l.treeJoint));
        held.removeDuplicates();
        return held;
    };
    // the drives a key pair drives now (the keyboard's own mappings — a laptop always
    // works — or the profile's): they do not hold when the profile's device is
    // missing, and the warnings say so
    QStringList byKeys;
    for (const Live& l : m_live) {
        if (l.treeJoint < 0 || l.device < 0 || (l.bank >= 0 && l.bank != m_activeBank)) continue;
        const InputDevice& d = *m_devices[std::size_t(l.device)];
        if (d.info().kind == DeviceKind::Keyboard && isConnected(d) && !ignored(d) &&
            std::size_t(l.mapping.axis) < m_state[std::size_t(l.device)].channels.size())  // a key pair there is
            byKeys.append(driveLabel(l.treeJoint));
    }
    // what the drives of a missing device do: hold, or follow the keyboard
    const auto instead = [&](const QStringList& held) {
        QStringList closed, keys;
        for (const QString& d : held) (byKeys.contains(d) ? keys : closed).append(d);
        QStringList parts;
        if (!closed.isEmpty()) parts << Tr::tr("valves closed, holding %1").arg(closed.join(", "));
        if (!keys.isEmpty()) parts << Tr::tr("the keyboard drives %1 instead").arg(keys.join(", "));
        return parts.join(QStringLiteral("; "));
    };
    QStringList missingNames, missingHeld;
    for (std::size_t i = 0; i < m_devices.size(); ++i) {
        const InputDevice& d = *m_devices[i];
        if (ignored(d)) continue;
        if (!isConnected(d)) {
            // a device gone: which drives it holds
            const QStringList held = heldBy(i, -1);
            if (held.isEmpty()) continue;
            const QString why = d.statusText().isEmpty() ? Tr::tr("not connected") : d.statusText();
            (m_state[i].everConnected ? st.warnings : st.setupWarnings)
                .append(Tr::tr("%1: %2 — %3").arg(displayName(d.info()), why, instead(held)));
            if (!m_state[i].everConnected) {
                missingNames.append(displayName(d.info()));
                missingHeld += held;
            }
            continue;
        }
        // channels whose readings cannot be: a device fault, their valves closed
        const Device& dev = m_state[i];
        for (std::size_t a = 0; a < dev.channels.size(); ++a) {
            const Channel& ch = dev.channels[a];
            if (!ch.state.fault) continue;
            const QStringList held = heldBy(i, int(a));
            const QString axis = a < std::size_t(d.info().axes.size()) ? d.info().axes[int(a)].name : QString::number(a + 1);
            st.warnings.append(Tr::tr("%1, %2: device fault, it reads %3 where it can read only %4…%5 — valve closed%6")
                                   .arg(d.info().name, axis, QString::number(ch.state.raw, 'g', 10),
                                        QString::number(ch.nominalMin, 'g', 10), QString::number(ch.nominalMax, 'g', 10),
                                        held.isEmpty() ? QString() : Tr::tr(", holding %1").arg(held.join(", "))));
        }
    }
    // mappings whose device is not there at all
    QStringList missing;
    for (const Live& l : m_live)
        if (l.device < 0 && l.treeJoint >= 0 && (l.bank < 0 || l.bank == m_activeBank) && !isImplicitKeyboard(l))
            missing.append(l.mapping.device);
    missing.removeDuplicates();
    for (const QString& m : missing) {
        QStringList held;
        for (const Live& l : m_live)
            if (l.device < 0 && l.treeJoint >= 0 && (l.bank < 0 || l.bank == m_activeBank) && l.mapping.device == m)
                held.append(driveLabel(l.treeJoint));
        held.removeDuplicates();
        const QString name = deviceName(m);
        st.setupWarnings.append(Tr::tr("No %1 found — %2").arg(name, instead(held)));
        missingNames.append(name);
        missingHeld += held;
    }
    // the operator's line: what is missing and what drives instead
    missingHeld.removeDuplicates();
    if (!missingNames.isEmpty()) {
        const auto keys = std::count_if(missingHeld.begin(), missingHeld.end(),
                                        [&](const QString& d) { return byKeys.contains(d); });
        const QString what = keys == missingHeld.size() ? Tr::tr("the keyboard drives instead")
                             : keys == 0              ? Tr::tr("its valves are closed, the machine holds")
                                                      : Tr::tr("the keyboard drives %1 of its %n drive(s), the rest hold",
                                                               nullptr, int(missingHeld.size()))
                                                            .arg(keys);
        st.devicesMissing = Tr::tr("%1 missing — %2").arg(missingNames.join(", "), what);
    }
    // banks: worth showing when a device that switches them is connected
    const auto connectedButton = [&](const ButtonRef& r) -> const InputDevice* {
        if (!r.isSet()) return nullptr;
        const int i = indexOf(r.device);
        return i >= 0 && isConnected(*m_devices[std::size_t(i)]) ? m_devices[std::size_t(i)].get() : nullptr;
    };
    QStringList hints;
    if (m_profile.banks.size() > 1) {
        if (const InputDevice* d = connectedButton(m_profile.nextBank))
            hints << Tr::tr("%1: next bank").arg(buttonName(d->info(), m_profile.nextBank.button));
        for (const Bank& b : m_profile.banks)
            for (const ButtonRef& r : b.select)
                if (const InputDevice* d = connectedButton(r)) hints << QStringLiteral("%1: %2").arg(buttonName(d->info(), r.button), b.name);
    }
    st.bankSwitchConnected = !hints.isEmpty();
    st.bankSwitchHint = hints.join(QStringLiteral(" · "));
    if (m_holding) st.warnings.append(Tr::tr("Calibrating: every valve is held closed"));
    waiting.removeDuplicates();
    if (!waiting.isEmpty())
        st.warnings.append(Tr::tr("Bring the lever to centre to take over: %1").arg(waiting.join(", ")));
    for (const auto& p : m_providers)
        if (!p->problem().isEmpty()) st.warnings.append(p->problem());
    return st;
}

}  // namespace trainer
