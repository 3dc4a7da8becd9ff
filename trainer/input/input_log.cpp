#include "trainer/input/input_log.h"

#include "solver/core/diagnostic.h"

#include "trainer/io/read_file.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>

namespace trainer {

namespace {

/// A field of the log as shown in a message (control characters escaped).
QString escapedField(const QByteArray& field)
{
    return QString::fromStdString(solver::escapeControls(field.toStdString()));
}

/// The translation context of this file's messages (lupdate reads Tr::tr).
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(trainer::InputLog)
};

constexpr const char* kMagic = "# padrob input log 1";

bool kindFromKey(const QString& key, DeviceKind& kind)
{
    for (DeviceKind k : {DeviceKind::Joystick, DeviceKind::Gamepad, DeviceKind::SerialDaq, DeviceKind::Comedi,
                         DeviceKind::Keyboard, DeviceKind::Replay})
        if (kindKey(k) == key) {
            kind = k;
            return true;
        }
    return false;
}

QByteArray deviceJson(const DeviceInfo& info)
{
    QJsonArray axes, buttons;
    for (const AxisInfo& a : info.axes)
        axes.append(QJsonObject{{"name", a.name}, {"min", a.rawMin}, {"rest", a.rawRest}, {"max", a.rawMax}});
    for (const QString& b : info.buttons) buttons.append(b);
    return QJsonDocument(QJsonObject{{"id", info.id},
                                     {"name", info.name},
                                     {"kind", kindKey(info.kind)},
                                     {"axes", axes},
                                     {"buttons", buttons}})
        .toJson(QJsonDocument::Compact);
}

}  // namespace

bool InputLog::load(const QString& path, InputLog& out, QString* error)
{
    const std::optional<QByteArray> text =
        readLimitedFile(path, kMaxInputLogBytes, solver::trText("Tutorials", "an input log"), ".log",
                        solver::trText("Tutorials", "an input log is a text file that padrob writes while a run is recorded; check that this is one"), error);
    if (!text || !parse(*text, out, error)) {
        if (error) *error = path + ": " + *error;  // every reason names the file
        return false;
    }
    return true;
}

bool InputLog::parse(const QByteArray& text, InputLog& out, QString* error)
{
    InputLog log;
    const QList<QByteArray> lines = text.split('\n');
    auto fail = [&](int line, const QString& what) {
        if (error) *error = Tr::tr("line %1: %2").arg(line).arg(what);
        return false;
    };
    if (lines.isEmpty() || lines[0].trimmed() != kMagic)
        return fail(1, Tr::tr("not a Padrob input log (the first line must be “%1”)").arg(kMagic));
    double lastTime = 0.0;
    for (int n = 1; n < lines.size(); ++n) {
        const QByteArray line = lines[n].trimmed();
        const int lineNo = n + 1;
        if (line.isEmpty()) continue;
        if (line.startsWith("#device ")) {
            const int space = line.indexOf(' ', 8);
            bool ok = false;
            const int index = line.mid(8, space - 8).toInt(&ok);
            if (!ok || index != log.devices.size())
                return fail(lineNo, Tr::tr("devices must be numbered 0, 1, 2… in order"));
            QJsonParseError perr;
            const QJsonDocument doc = QJsonDocument::fromJson(line.mid(space + 1), &perr);
            if (perr.error != QJsonParseError::NoError || !doc.isObject())
                return fail(lineNo, Tr::tr("the device description is not valid JSON (%1)").arg(perr.errorString()));
            const QJsonObject o = doc.object();
            DeviceInfo info;
            info.id = o.value("id").toString();
            info.name = o.value("name").toString();
            if (info.id.isEmpty() || !kindFromKey(o.value("kind").toString(), info.kind))
                return fail(lineNo, Tr::tr("a device needs an “id” and a known “kind”"));
            for (const QJsonValue& a : o.value("axes").toArray()) {
                const QJsonObject ao = a.toObject();
                info.axes.append({ao.value("name").toString(), ao.value("min").toDouble(-1.0),
                                  ao.value("rest").toDouble(0.0), ao.value("max").toDouble(1.0)});
            }
            for (const QJsonValue& b : o.value("buttons").toArray()) info.buttons.append(b.toString());
            log.devices.append(info);
            continue;
        }
        if (line.startsWith('#')) continue;
        const QList<QByteArray> fields = line.split(',');
        bool ok = false;
        LoggedSample s;
        s.time = fields.value(0).toDouble(&ok);
        if (!ok || !std::isfinite(s.time) || s.time < lastTime)
            return fail(lineNo, Tr::tr("the time must be a number that never goes back"));
        const QByteArray deviceField = fields.value(1).trimmed();
        if (deviceField.isEmpty())
            return fail(lineNo, Tr::tr("the device number (the second field, after the time) is missing"));
        s.device = deviceField.toInt(&ok);
        if (!ok || s.device < 0 || s.device >= log.devices.size())
            return fail(lineNo, Tr::tr("device %1 is not described above this line").arg(escapedField(deviceField)));
        const DeviceInfo& info = log.devices[s.device];
        const int expected = 2 + int(info.axes.size()) + int(info.buttons.size());
        if (fields.size() != expected)
            return fail(lineNo, Tr::tr("%1 values where device %2 has %3 axes and %4 buttons")
                                    .arg(fields.size() - 2)
                                    .arg(s.device)
                                    .arg(info.axes.size())
                                    .arg(info.buttons.size()));
        for (int a = 0; a < info.axes.size(); ++a) {
            const double v = fields[2 + a].toDouble(&ok);
            if (!ok || !std::isfinite(v)) return fail(lineNo, Tr::tr("axis %1 is not a number").arg(a + 1));
            s.axes.push_back(v);
        }
        for (int b = 0; b < info.buttons.size(); ++b) {
            const QByteArray& f = fields[2 + int(info.axes.size()) + b];
            if (f != "0" && f != "1") return fail(lineNo, Tr::tr("button %1 must be 0 or 1").arg(b + 1));
            s.buttons.push_back(f == "1" ? 1 : 0);
        }
        lastTime = s.time;
        log.samples.push_back(std::move(s));
    }
    out = std::move(log);
    return true;
}

InputRecorder::~InputRecorder()
{
    stop();
}

bool InputRecorder::start(const QString& path, double now, QString* error)
{
    stop();
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        if (error) *error = Tr::tr("cannot write %1: %2").arg(path, m_file.errorString());
        return false;
    }
    m_file.write(kMagic);
    m_file.write("\n");
    m_index.clear();
    m_origin = now;
    m_lastFlush = now;
    m_lines = 0;
    return true;
}

void InputRecorder::record(double now, const InputDevice& device, const DeviceSample& sample)
{
    if (!m_file.isOpen()) return;
    const DeviceInfo& info = device.info();
    auto it = m_index.find(info.id);
    if (it == m_index.end()) {
        it = m_index.insert(info.id, int(m_index.size()));
        m_file.write("#device " + QByteArray::number(*it) + ' ' + deviceJson(info) + '\n');
    }
    QByteArray line = QByteArray::number(std::max(0.0, now - m_origin), 'f', 6);
    line += ',';
    line += QByteArray::number(*it);
    for (int a = 0; a < info.axes.size(); ++a) {
        line += ',';
        line += QByteArray::number(std::size_t(a) < sample.axes.size() ? sample.axes[std::size_t(a)] : 0.0, 'g', 10);
    }
    for (int b = 0; b < info.buttons.size(); ++b)
        line += (std::size_t(b) < sample.buttons.size() && sample.buttons[std::size_t(b)]) ? ",1" : ",0";
    line += '\n';
    m_file.write(line);
    ++m_lines;
    if (now - m_lastFlush > 0.5) {  // a crash loses at most half a second of input
        m_file.flush();
        m_lastFlush = now;
    }
}

bool InputRecorder::stop(QString* error)
{
    if (!m_file.isOpen()) return true;
    const bool ok = m_file.flush() && m_file.error() == QFileDevice::NoError;
    if (!ok && error) *error = Tr::tr("cannot write %1: %2").arg(m_file.fileName(), m_file.errorString());
    m_file.close();
    return ok;
}

ReplayDevice::ReplayDevice(std::shared_ptr<const InputLog> log, int device) : m_log(std::move(log)), m_device(device)
{
    if (m_log && device >= 0 && device < m_log->devices.size()) {
        m_info = m_log->devices[device];
        m_info.name = QCoreApplication::translate("trainer::InputLog", "Replay of %1").arg(m_info.name);
    }
    m_sample.axes.resize(std::size_t(m_info.axes.size()));
    for (int a = 0; a < m_info.axes.size(); ++a) m_sample.axes[std::size_t(a)] = m_info.axes[a].rawRest;
    m_sample.buttons.assign(std::size_t(m_info.buttons.size()), 0);
}

void ReplayDevice::start(double now, double from)
{
    m_started = true;
    m_origin = now;
    m_lastNow = now;
    m_from = std::max(0.0, from);
    m_next = 0;
}

void ReplayDevice::setSpeed(double speed)
{
    if (!std::isfinite(speed) || speed <= 0.0) return;
    m_from = position();
    m_origin = m_lastNow;
    m_speed = speed;
}

void ReplayDevice::setPaused(bool paused)
{
    if (paused == m_paused) return;
    m_from = position();
    m_origin = m_lastNow;
    m_paused = paused;
}

double ReplayDevice::position() const
{
    if (!m_started) return 0.0;
    return m_paused ? m_from : m_from + (m_lastNow - m_origin) * m_speed;
}

bool ReplayDevice::finished() const
{
    return m_log && position() >= m_log->duration() && m_next >= m_log->samples.size();
}

void ReplayDevice::poll(double now)
{
    if (!m_log) return;
    if (!m_started) start(now);
    m_lastNow = now;
    const double t = position();
    // seeking back: replay from the start up to t
    const auto& samples = m_log->samples;
    if (m_next > 0 && samples[m_next - 1].time > t) m_next = 0;
    const LoggedSample* newest = nullptr;
    while (m_next < samples.size() && samples[m_next].time <= t) {
        if (samples[m_next].device == m_device) newest = &samples[m_next];
        ++m_next;
    }
    if (!newest) return;
    std::copy(newest->axes.begin(), newest->axes.end(), m_sample.axes.begin());
    std::copy(newest->buttons.begin(), newest->buttons.end(), m_sample.buttons.begin());
    m_sample.time = now;
    ++m_sample.count;
}

std::vector<std::shared_ptr<ReplayDevice>> replayDevices(std::shared_ptr<const InputLog> log)
{
    std::vector<std::shared_ptr<ReplayDevice>> out;
    if (!log) return out;
    for (int i = 0; i < log->devices.size(); ++i) out.push_back(std::make_shared<ReplayDevice>(log, i));
    return out;
}

}  // namespace trainer
