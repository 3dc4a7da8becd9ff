#pragma once
// How the operator drives a stage (issue 25, item 13): for each of its enabled drives,
// the controls of a station profile that move it and which way, derived from the
// profile's mappings (never written per tutorial):
//  - the keyboard: the profile's keyboard mappings, or else the pairs the station puts on
//    the model's first nine drives in joint id order (StationEngine::kKeyboardPairs);
//  - levers (serial DAQ, Comedi), a gamepad's sticks and triggers, a joystick's axes,
//    with their bank when they are in one.
// Which way: the key or the direction of a stick that gives the drive a positive
// command (+: the drive's coordinate grows: a cylinder extends, a joint turns its
// positive way) and the one that gives a negative one; and what + and − do to the
// machine at the stage's start (the claws' tip goes up or down, out or in, right or
// left; a claw closes or opens), from its kinematics. A control is named by one
// function, controlText(), so that the station's names of gamepad controls can take
// its place in one spot.

#include "trainer/station/profile.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace trainer {
struct Tutorial;
}

namespace studio {

struct DriveControls {
    trainer::DriveInfo drive;
    QStringList controls;  ///< controlText() of every control that moves it
    /// Which way + and − move the machine at the stage's start ("+ up / − down", "+ out /
    /// − in", "+ right / − left" for the claws' tip, "+ closes / − opens" for a claw;
    /// "" when the tip hardly moves: the head's roll), translated.
    QString direction;
    /// "C 2 LEVANTE PLUMA (+ up / − down): W + / S − · lever 2"
    QString text() const;
};

/// The stage's enabled drives (in joint id order), each with the controls of `profile`;
/// with `devices` (ids or kinds: "serial:autopilot", "serial", "keyboard"…), only the
/// controls of those devices (what a recorded input log drove).
QList<DriveControls> driveControls(const trainer::Tutorial& tutorial, const trainer::StationProfile& profile,
                                   const QStringList* devices = nullptr);

/// One control as the operator reads it, with its direction: "W + / S −", "lever 2",
/// "lever 8 reversed", "left stick up + / down −", "right trigger +" (translated), and
/// its bank ("… (bank Boom)") when `bank` is given.
QString controlText(const trainer::Mapping& mapping, const QString& bank = {});

/// The lines of driveControls() as HTML, one drive a line (the start screen, the attempt).
QString driveControlsHtml(const QList<DriveControls>& controls);

}  // namespace studio
