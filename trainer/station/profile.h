#pragma once
// Station profiles: how a station's devices drive a model's valves. A profile names
// the devices to open (serial DAQ ports, Comedi cards; SDL joysticks and the keyboard
// are found by themselves), the calibration of each channel, and the valve mapping:
// channel → drive with gain and sign, grouped in banks switched by buttons.
// Format (JSON, documented in docs/station.md):
//
//   { "format": "padrob-station-profile", "version": 1, "name": "Gamepad",
//     "model": "liner_manipulator", "description": "…",
//     "devices":  [ { "id": "serial:/dev/ttyACM0", "baud": 115200 } ],
//     "calibrations": [ { "device": "gamepad", "axis": 0, "min": -32768, "centre": 0,
//                          "max": 32767, "deadBandLow": 0.1, … } ],
//     "always": [ <mapping>… ],                  (active in every bank)
//     "banks": [ { "name": "Boom", "select": [ { "device": "gamepad", "button": 9 } ],
//                  "mappings": [ { "device": "gamepad", "axis": 1, "drive": 2,
//                                  "gain": 1.0, "sign": -1 } ] } ],
//     "nextBank": { "device": "gamepad", "button": 4 },
//     "translations": { "es": { "Gamepad": "Mando", "Boom": "Pluma", "…": "…" } } }
//
// "translations" (optional) gives, per language code, the texts a person reads (the
// name, the description, the bank names) in that language, keyed by the text as it is
// written in the profile: the GUI shows localized(text), and a text with no entry
// (a bank renamed in a copy, a description edited) is shown as written. The name
// stays the profile's identity (files, settings, tutorials name profiles by it).
//
// A device is named by its id ("sdl:<GUID>", "serial:/dev/ttyACM0", "keyboard", …) or
// by a kind, which matches the first connected device of that kind: "gamepad",
// "joystick", "serial", "comedi". Axes and buttons are 0-based indices into the
// device's lists. A drive is the joint id (C id) of a joint with a D statement.

#include "trainer/station/calibration.h"

#include <QByteArray>
#include <QJsonObject>
#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

namespace solver {
struct Model;
}

namespace trainer {

/// A drive of the model, as the station knows it.
struct DriveInfo {
    int treeJoint = 0;  ///< index in the solver's command vector
    int jointId = 0;    ///< C id in the model
    QString name;       ///< NAME, "" when unnamed
    /// "C 2 LEVANTE PLUMA" / "C 2"
    QString label() const;
};

/// The drives of a compiled model (joints with a D statement), in joint id order.
QList<DriveInfo> drivesOf(const solver::Model& model);

struct Mapping {
    QString device;     ///< device id or kind (see above)
    int axis = 0;
    int drive = 0;      ///< joint id
    double gain = 1.0;  ///< 0 … kMaxGain
    int sign = 1;       ///< +1 or −1
    static constexpr double kMaxGain = 10.0;
    bool operator==(const Mapping&) const = default;
};

struct ButtonRef {
    QString device;
    int button = -1;    ///< −1: none
    bool isSet() const { return !device.isEmpty() && button >= 0; }
    bool operator==(const ButtonRef&) const = default;
};

struct Bank {
    QString name;
    QList<ButtonRef> select;  ///< any of these buttons selects the bank
    QList<Mapping> mappings;
    bool operator==(const Bank&) const = default;
};

/// A device the station opens because the profile says so (SDL devices and the
/// keyboard are found without it).
struct DeviceSetting {
    QString id;           ///< "serial:<port>" or "comedi:<file>"
    int baud = 115200;    ///< serial only
    bool operator==(const DeviceSetting&) const = default;
};

struct CalibrationEntry {
    QString device;
    int axis = 0;
    ChannelCalibration calibration;
    bool operator==(const CalibrationEntry&) const = default;
};

/// One problem found in a profile: where (a JSON path such as "banks[1].mappings[0]")
/// and what, translated.
struct ProfileIssue {
    QString where;
    QString message;
    bool error = true;  ///< false: a warning (the profile loads, that part is ignored)
    QString text() const { return where.isEmpty() ? message : where + ": " + message; }
};

struct StationProfile {
    static constexpr int kVersion = 1;
    static constexpr const char* kFormat = "padrob-station-profile";

    QString name;
    QString model;        ///< model file base name, e.g. "liner_manipulator"
    QString description;
    QList<DeviceSetting> devices;
    QList<CalibrationEntry> calibrations;
    QList<Mapping> always;
    QList<Bank> banks;    ///< at least one when there is anything to map
    ButtonRef nextBank;
    /// language code ("es") → text as written → the text in that language
    QMap<QString, QMap<QString, QString>> translations;
    /// The file it was read from ("" when made in code): named in check()'s issues.
    /// Not saved, and not compared by ==.
    QString source;

    /// `text` (the name, the description or a bank's name as written) in `language`
    /// ("" = the language of the default QLocale, i.e. the GUI's), else as written.
    QString localized(const QString& text, const QString& language = {}) const;

    /// The calibration of (device, axis) if the profile has one, else nullptr.
    const ChannelCalibration* calibration(const QString& device, int axis) const;
    /// Sets (or adds) the calibration of (device, axis).
    void setCalibration(const QString& device, int axis, const ChannelCalibration& c);

    QByteArray toJson() const;
    /// Parses a profile. False with `issues` (errors) when it cannot be read: not JSON
    /// (line and column given), another format, a newer version than kVersion, a wrong
    /// type anywhere. Never a half-read profile: on failure `out` is untouched.
    static bool fromJson(const QByteArray& json, StationProfile& out, QList<ProfileIssue>& issues);

    /// Checks the profile against a model's drives: a mapping to a drive the model does
    /// not have, or to a drive that is not driven, is a warning (that mapping is
    /// ignored); bad gains and signs are errors. Returns the issues (empty: all good).
    QList<ProfileIssue> check(const QList<DriveInfo>& drives) const;

    /// A profile for any model: the keyboard's key pairs one to one on the first nine
    /// drives (always), and a two-stick gamepad in banks of four stick axes (left x,
    /// left y, right x, right y), selected by the shoulder buttons (next bank) .
    static StationProfile defaultFor(const QString& model, const QList<DriveInfo>& drives);

    bool operator==(const StationProfile& o) const
    {
        return name == o.name && model == o.model && description == o.description && devices == o.devices &&
               calibrations == o.calibrations && always == o.always && banks == o.banks && nextBank == o.nextBank &&
               translations == o.translations;
    }
};

/// SDL game-controller button and axis indices used by shipped profiles.
namespace gamepad {
enum Axis { LeftX = 0, LeftY, RightX, RightY, LeftTrigger, RightTrigger };
enum Button { A = 0, B, X, Y, Back, Guide, Start, LeftStick, RightStick, LeftShoulder, RightShoulder,
              DpadUp, DpadDown, DpadLeft, DpadRight };
}  // namespace gamepad

}  // namespace trainer
