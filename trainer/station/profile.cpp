#include "trainer/station/profile.h"

#include "solver/core/model.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QLocale>
#include <QSet>

#include <algorithm>
#include <cmath>

namespace trainer {

namespace {

/// The translation context of this file's messages (lupdate reads Tr::tr).
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(trainer::StationProfile)
};

QJsonObject mappingJson(const Mapping& m)
{
    return {{"device", m.device}, {"axis", m.axis}, {"drive", m.drive}, {"gain", m.gain}, {"sign", m.sign}};
}

QJsonObject buttonJson(const ButtonRef& b)
{
    return {{"device", b.device}, {"button", b.button}};
}

/// Reads typed values out of JSON objects, collecting the first type error with its path.
class Reader {
public:
    explicit Reader(QList<ProfileIssue>& issues) : m_issues(issues) {}

    bool fail(const QString& where, const QString& message)
    {
        m_issues.append({where, message, true});
        return false;
    }

    bool string(const QJsonObject& o, const QString& where, const char* key, QString& out, bool required)
    {
        const QJsonValue v = o.value(key);
        if (v.isUndefined()) return required ? fail(where, Tr::tr("“%1” is missing").arg(key)) : true;
        if (!v.isString()) return fail(where, Tr::tr("“%1” must be a text").arg(key));
        out = v.toString();
        return true;
    }
    bool integer(const QJsonObject& o, const QString& where, const char* key, int& out, bool required)
    {
        const QJsonValue v = o.value(key);
        if (v.isUndefined()) return required ? fail(where, Tr::tr("“%1” is missing").arg(key)) : true;
        const double d = v.toDouble(std::nan(""));
        if (!v.isDouble() || d != std::floor(d) || std::abs(d) > 1e9)
            return fail(where, Tr::tr("“%1” must be a whole number").arg(key));
        out = int(d);
        return true;
    }
    bool number(const QJsonObject& o, const QString& where, const char* key, double& out)
    {
        const QJsonValue v = o.value(key);
        if (v.isUndefined()) return true;
        if (!v.isDouble()) return fail(where, Tr::tr("“%1” must be a number").arg(key));
        out = v.toDouble();
        return true;
    }
    bool array(const QJsonObject& o, const QString& where, const char* key, QJsonArray& out)
    {
        const QJsonValue v = o.value(key);
        if (v.isUndefined()) return true;
        if (!v.isArray()) return fail(where, Tr::tr("“%1” must be a list").arg(key));
        out = v.toArray();
        return true;
    }
    bool object(const QJsonValue& v, const QString& where, QJsonObject& out)
    {
        if (!v.isObject()) return fail(where, Tr::tr("must be an object { … }"));
        out = v.toObject();
        return true;
    }
    bool mapping(const QJsonValue& v, const QString& where, Mapping& m)
    {
        QJsonObject o;
        return object(v, where, o) && string(o, where, "device", m.device, true) &&
               integer(o, where, "axis", m.axis, true) && integer(o, where, "drive", m.drive, true) &&
               number(o, where, "gain", m.gain) && integer(o, where, "sign", m.sign, false);
    }
    bool button(const QJsonValue& v, const QString& where, ButtonRef& b)
    {
        QJsonObject o;
        return object(v, where, o) && string(o, where, "device", b.device, true) &&
               integer(o, where, "button", b.button, true);
    }

private:
    QList<ProfileIssue>& m_issues;
};

/// "line 3, column 14" of a byte offset.
QString position(const QByteArray& text, int offset)
{
    int line = 1, column = 1;
    for (int i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return Tr::tr("line %1, column %2").arg(line).arg(column);
}

}  // namespace

QList<DriveInfo> drivesOf(const solver::Model& model)
{
    QList<DriveInfo> out;
    for (int i = 0; i < model.nb; ++i) {
        if (model.drive[std::size_t(i)].type == solver::DriveType::None) continue;
        out.append({i, model.jointId[std::size_t(i)], QString::fromStdString(model.jointName[std::size_t(i)])});
    }
    std::sort(out.begin(), out.end(), [](const DriveInfo& a, const DriveInfo& b) { return a.jointId < b.jointId; });
    return out;
}

QString DriveInfo::label() const
{
    return name.isEmpty() ? QStringLiteral("C %1").arg(jointId) : QStringLiteral("C %1 %2").arg(jointId).arg(name);
}

const ChannelCalibration* StationProfile::calibration(const QString& device, int axis) const
{
    for (const CalibrationEntry& e : calibrations)
        if (e.device == device && e.axis == axis) return &e.calibration;
    return nullptr;
}

QString StationProfile::localized(const QString& text, const QString& language) const
{
    const QString lang = language.isEmpty() ? QLocale::languageToCode(QLocale().language()) : language;
    return translations.value(lang).value(text, text);
}

void StationProfile::setCalibration(const QString& device, int axis, const ChannelCalibration& c)
{
    for (CalibrationEntry& e : calibrations) {
        if (e.device == device && e.axis == axis) {
            e.calibration = c;
            return;
        }
    }
    calibrations.append({device, axis, c});
}

QByteArray StationProfile::toJson() const
{
    QJsonObject root{{"format", kFormat}, {"version", kVersion}, {"name", name}, {"model", model}};
    if (!description.isEmpty()) root["description"] = description;
    QJsonArray devs;
    for (const DeviceSetting& d : devices) {
        QJsonObject o{{"id", d.id}};
        if (d.id.startsWith("serial:")) o["baud"] = d.baud;
        devs.append(o);
    }
    root["devices"] = devs;
    QJsonArray cals;
    for (const CalibrationEntry& e : calibrations) {
        QJsonObject o{{"device", e.device}, {"axis", e.axis}};
        const QJsonObject c = e.calibration.toJson();
        for (auto it = c.begin(); it != c.end(); ++it) o[it.key()] = it.value();
        cals.append(o);
    }
    root["calibrations"] = cals;
    QJsonArray always;
    for (const Mapping& m : this->always) always.append(mappingJson(m));
    root["always"] = always;
    QJsonArray bankArray;
    for (const Bank& b : banks) {
        QJsonArray select, maps;
        for (const ButtonRef& s : b.select) select.append(buttonJson(s));
        for (const Mapping& m : b.mappings) maps.append(mappingJson(m));
        bankArray.append(QJsonObject{{"name", b.name}, {"select", select}, {"mappings", maps}});
    }
    root["banks"] = bankArray;
    if (nextBank.isSet()) root["nextBank"] = buttonJson(nextBank);
    if (!translations.isEmpty()) {
        QJsonObject languages;
        for (auto lang = translations.begin(); lang != translations.end(); ++lang) {
            QJsonObject texts;
            for (auto t = lang->begin(); t != lang->end(); ++t) texts[t.key()] = t.value();
            languages[lang.key()] = texts;
        }
        root["translations"] = languages;
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool StationProfile::fromJson(const QByteArray& json, StationProfile& out, QList<ProfileIssue>& issues)
{
    QJsonParseError perr;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &perr);
    if (perr.error != QJsonParseError::NoError) {
        issues.append({position(json, perr.offset),
                       Tr::tr("not a valid profile file (%1); fix the JSON or import the profile again")
                           .arg(perr.errorString()),
                       true});
        return false;
    }
    if (!doc.isObject()) {
        issues.append({{}, Tr::tr("not a station profile: the file must hold one JSON object"), true});
        return false;
    }
    const QJsonObject root = doc.object();
    if (root.value("format").toString() != kFormat) {
        issues.append({"format", Tr::tr("not a station profile (“format” must be \"%1\")").arg(kFormat), true});
        return false;
    }
    Reader r(issues);
    int version = 0;
    if (!r.integer(root, "version", "version", version, true)) return false;
    if (version > kVersion) {
        issues.append({"version",
                       Tr::tr("made by a newer Padrob (profile version %1; this one reads up to %2). Update Padrob "
                           "or use a profile saved by this version.")
                           .arg(version)
                           .arg(kVersion),
                       true});
        return false;
    }
    if (version < 1) return r.fail("version", Tr::tr("the version must be 1 or more"));

    StationProfile p;
    if (!r.string(root, "name", "name", p.name, true) || !r.string(root, "model", "model", p.model, false) ||
        !r.string(root, "description", "description", p.description, false))
        return false;
    QJsonArray devs, cals, always, banks;
    if (!r.array(root, "devices", "devices", devs) || !r.array(root, "calibrations", "calibrations", cals) ||
        !r.array(root, "always", "always", always) || !r.array(root, "banks", "banks", banks))
        return false;
    for (int i = 0; i < devs.size(); ++i) {
        const QString where = QStringLiteral("devices[%1]").arg(i);
        QJsonObject o;
        DeviceSetting d;
        if (!r.object(devs[i], where, o) || !r.string(o, where, "id", d.id, true) ||
            !r.integer(o, where, "baud", d.baud, false))
            return false;
        p.devices.append(d);
    }
    for (int i = 0; i < cals.size(); ++i) {
        const QString where = QStringLiteral("calibrations[%1]").arg(i);
        QJsonObject o;
        CalibrationEntry e;
        if (!r.object(cals[i], where, o) || !r.string(o, where, "device", e.device, true) ||
            !r.integer(o, where, "axis", e.axis, true))
            return false;
        QString why;
        if (!ChannelCalibration::fromJson(o, e.calibration, &why)) return r.fail(where, why);
        p.calibrations.append(e);
    }
    for (int i = 0; i < always.size(); ++i) {
        Mapping m;
        if (!r.mapping(always[i], QStringLiteral("always[%1]").arg(i), m)) return false;
        p.always.append(m);
    }
    for (int i = 0; i < banks.size(); ++i) {
        const QString where = QStringLiteral("banks[%1]").arg(i);
        QJsonObject o;
        Bank b;
        QJsonArray select, maps;
        if (!r.object(banks[i], where, o) || !r.string(o, where, "name", b.name, false) ||
            !r.array(o, where, "select", select) || !r.array(o, where, "mappings", maps))
            return false;
        for (int j = 0; j < select.size(); ++j) {
            ButtonRef s;
            if (!r.button(select[j], where + QStringLiteral(".select[%1]").arg(j), s)) return false;
            b.select.append(s);
        }
        for (int j = 0; j < maps.size(); ++j) {
            Mapping m;
            if (!r.mapping(maps[j], where + QStringLiteral(".mappings[%1]").arg(j), m)) return false;
            b.mappings.append(m);
        }
        p.banks.append(b);
    }
    if (root.contains("nextBank") && !r.button(root.value("nextBank"), "nextBank", p.nextBank)) return false;
    if (root.contains("translations")) {
        QJsonObject languages;
        if (!r.object(root.value("translations"), "translations", languages)) return false;
        for (auto lang = languages.begin(); lang != languages.end(); ++lang) {
            const QString where = "translations." + lang.key();
            QJsonObject texts;
            if (!r.object(lang.value(), where, texts)) return false;
            for (auto t = texts.begin(); t != texts.end(); ++t) {
                if (!t.value().isString())
                    return r.fail(where, Tr::tr("“%1” must be translated by a text").arg(t.key()));
                p.translations[lang.key()][t.key()] = t.value().toString();
            }
        }
    }
    out = p;
    return true;
}

QList<ProfileIssue> StationProfile::check(const QList<DriveInfo>& drives) const
{
    QList<ProfileIssue> issues;
    QSet<int> ids;
    for (const DriveInfo& d : drives) ids.insert(d.jointId);
    auto checkMapping = [&](const Mapping& m, const QString& where) {
        if (m.device.isEmpty()) issues.append({where, Tr::tr("the mapping names no device"), true});
        if (m.axis < 0) issues.append({where, Tr::tr("the axis must be 0 or more"), true});
        if (m.sign != 1 && m.sign != -1) issues.append({where, Tr::tr("the sign must be 1 or -1"), true});
        if (!std::isfinite(m.gain) || m.gain < 0.0 || m.gain > Mapping::kMaxGain)
            issues.append({where, Tr::tr("the gain must be between 0 and %1").arg(Mapping::kMaxGain), true});
        if (!ids.contains(m.drive))
            issues.append({where,
                           Tr::tr("drive C %1 is not in this model (or has no D statement); this mapping is ignored")
                               .arg(m.drive),
                           false});
    };
    for (int i = 0; i < always.size(); ++i) checkMapping(always[i], QStringLiteral("always[%1]").arg(i));
    for (int i = 0; i < banks.size(); ++i) {
        const Bank& b = banks[i];
        for (int j = 0; j < b.mappings.size(); ++j)
            checkMapping(b.mappings[j], QStringLiteral("banks[%1].mappings[%2]").arg(i).arg(j));
        for (int j = 0; j < b.select.size(); ++j)
            if (!b.select[j].isSet())
                issues.append({QStringLiteral("banks[%1].select[%2]").arg(i).arg(j),
                               Tr::tr("a bank button needs a device and a button number"), true});
    }
    for (int i = 0; i < calibrations.size(); ++i)
        if (!calibrations[i].calibration.isValid())
            issues.append({QStringLiteral("calibrations[%1]").arg(i), calibrations[i].calibration.problem(), true});
    for (int i = 0; i < devices.size(); ++i) {
        const DeviceSetting& d = devices[i];
        if (!d.id.startsWith("serial:") && !d.id.startsWith("comedi:"))
            issues.append({QStringLiteral("devices[%1]").arg(i),
                           Tr::tr("“%1”: only serial DAQ ports (serial:…) and Comedi cards (comedi:…) are listed here")
                               .arg(d.id),
                           true});
        else if (d.id.startsWith("serial:") && d.baud <= 0)
            issues.append({QStringLiteral("devices[%1]").arg(i), Tr::tr("the baud rate must be positive"), true});
    }
    // read from a file: the file too, so that the one to fix is named
    if (!source.isEmpty())
        for (ProfileIssue& i : issues) i.where = i.where.isEmpty() ? source : source + ": " + i.where;
    return issues;
}

StationProfile StationProfile::defaultFor(const QString& model, const QList<DriveInfo>& drives)
{
    StationProfile p;
    p.name = Tr::tr("Keyboard and gamepad");
    p.model = model;
    p.description = Tr::tr("Made by Padrob for this model: key pairs Q/A, W/S, … on the drives in order, and a "
                        "two-stick gamepad in banks of four drives, switched with the shoulder buttons.");
    for (int i = 0; i < drives.size() && i < 9; ++i) p.always.append({"keyboard", i, drives[i].jointId, 1.0, 1});
    const int sticks[4] = {gamepad::LeftX, gamepad::LeftY, gamepad::RightX, gamepad::RightY};
    for (int first = 0; first < drives.size(); first += 4) {
        Bank b;
        b.name = Tr::tr("Bank %1").arg(first / 4 + 1);
        for (int k = 0; k < 4 && first + k < drives.size(); ++k)
            // stick forward is −y in SDL: pushing forward drives the valve positive
            b.mappings.append({"gamepad", sticks[k], drives[first + k].jointId, 1.0, (k % 2) ? -1 : 1});
        p.banks.append(b);
    }
    if (p.banks.isEmpty()) p.banks.append(Bank{Tr::tr("Bank 1"), {}, {}});
    if (p.banks.size() > 1) p.nextBank = {"gamepad", gamepad::RightShoulder};
    for (int axis : sticks) {
        ChannelCalibration c{-32768, 0, 32767, 0.08, 0.08};
        p.calibrations.append({"gamepad", axis, c});
    }
    return p;
}

}  // namespace trainer
