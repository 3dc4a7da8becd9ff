#pragma once
// Texts about joints, drives and bodies that the model tree and the joint sliders
// show a person: the joint type, limits and coordinates with their units (revolute
// joints in degrees, T 1 and T 2 joints in metres), a drive's summary, a mass.
// Every text is translated (context "studio::JointText") when it is asked for, and its
// numbers are written in the current locale (1,5 m in Spanish), without group separators
// (a reader who also edits the model, where '.' is the decimal point, does not take
// "2.500 kg" for two and a half). None of these texts goes into a model file.

#include "solver/spec/model_spec.h"

#include <QLocale>
#include <QString>

namespace studio::jointtext {

/// The current locale (QLocale()) without group separators: how these texts write numbers.
QLocale locale();

/// "revolute", "pivoted actuator" (T 1) or "prismatic" (T 2), translated.
QString typeName(solver::JointType type);

/// True when the joint's coordinate is a length [m] (T 1: the actuator's length,
/// T 2: the displacement); false for a revolute joint's angle [rad].
inline bool isLength(solver::JointType type) { return type != solver::JointType::Revolute; }

/// The unit a person reads the coordinate in: "°" for a revolute joint, "m" otherwise.
QString unit(solver::JointType type);

/// A coordinate (SI: rad or m) in the unit a person reads: "60.00°", "1.4640 m"
/// (Spanish: "60,00°", "1,4640 m").
QString coordinate(solver::JointType type, double q);

/// The joint's limits with units: "-65.0° … 65.0°", "0 … 0.9 m", "≥ 0.075 m",
/// or "unlimited".
QString limits(const solver::JointSpec& joint);

/// One line about a drive, with units for the joint's type, e.g.
/// "hydraulic 0.131 rad/s, 54 kN·m" or "motor T0 0.5 N·m, W0 10.47 rad/s".
QString drive(const solver::DriveSpec& drive, solver::JointType type);

/// A body's mass: "0.2 kg", or "massless".
QString mass(const solver::BodySpec& body);

/// `v` with `digits` significant digits, no exponent for everyday magnitudes, in the
/// current locale.
QString number(double v, int digits = 4);

/// A force or torque with an SI prefix: "54 kN·m", "1.54 MN", "500 N".
QString force(double v, solver::JointType type);

}  // namespace studio::jointtext
