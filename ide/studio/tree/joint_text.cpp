#include "ide/studio/tree/joint_text.h"

#include <QCoreApplication>

#include <cmath>
#include <numbers>

namespace studio::jointtext {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("studio::JointText", text); }

double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

/// A limit value in the joint's unit, short form: "-65.0°", "0.9 m".
QString limitValue(solver::JointType type, double v)
{
    if (isLength(type)) return tr("%1 m").arg(number(v));
    return tr("%1°").arg(QString::number(degrees(v), 'f', 1));
}

/// The rate unit of a joint's coordinate.
QString rateUnit(solver::JointType type) { return isLength(type) ? tr("m/s") : tr("rad/s"); }

}  // namespace

QString typeName(solver::JointType type)
{
    switch (type) {
    case solver::JointType::Revolute: return tr("revolute");
    case solver::JointType::Actuator: return tr("pivoted actuator");
    case solver::JointType::Prismatic: return tr("prismatic");
    }
    return {};
}

QString unit(solver::JointType type) { return isLength(type) ? tr("m") : tr("°"); }

QString coordinate(solver::JointType type, double q)
{
    if (isLength(type)) return tr("%1 m").arg(QString::number(q, 'f', 4));
    return tr("%1°").arg(QString::number(degrees(q), 'f', 2));
}

QString limits(const solver::JointSpec& joint)
{
    if (joint.ll && joint.ul) {
        return tr("%1 … %2").arg(limitValue(joint.type, *joint.ll), limitValue(joint.type, *joint.ul));
    }
    if (joint.ll) return tr("≥ %1").arg(limitValue(joint.type, *joint.ll));
    if (joint.ul) return tr("≤ %1").arg(limitValue(joint.type, *joint.ul));
    return tr("unlimited");
}

QString number(double v, int digits)
{
    const double a = std::abs(v);
    if (v == 0) return QStringLiteral("0");
    if (a >= 1e-3 && a < 1e6) {
        // fixed notation with `digits` significant digits, trailing zeros dropped
        const int before = a >= 1 ? static_cast<int>(std::floor(std::log10(a))) + 1 : 0;
        const int leadingZeros = a < 1 ? -static_cast<int>(std::floor(std::log10(a))) - 1 : 0;
        const int decimals = std::max(0, digits - before + leadingZeros);
        QString s = QString::number(v, 'f', decimals);
        if (s.contains(QLatin1Char('.'))) {
            while (s.endsWith(QLatin1Char('0'))) s.chop(1);
            if (s.endsWith(QLatin1Char('.'))) s.chop(1);
        }
        return s;
    }
    return QString::number(v, 'g', digits);
}

QString force(double v, solver::JointType type)
{
    const bool torque = type == solver::JointType::Revolute;
    const double a = std::abs(v);
    if (std::isinf(v)) return tr("unlimited");
    if (a >= 1e6) return torque ? tr("%1 MN·m").arg(number(v / 1e6, 3)) : tr("%1 MN").arg(number(v / 1e6, 3));
    if (a >= 1e4) return torque ? tr("%1 kN·m").arg(number(v / 1e3, 3)) : tr("%1 kN").arg(number(v / 1e3, 3));
    return torque ? tr("%1 N·m").arg(number(v, 4)) : tr("%1 N").arg(number(v, 4));
}

QString drive(const solver::DriveSpec& d, solver::JointType type)
{
    switch (d.kind) {
    case solver::DriveKind::Hydraulic: {
        const solver::DriveSpec::Hydraulic h = d.hydraulic();
        QString speed = h.vmin == h.vmax ? tr("%1 %2").arg(number(h.vmax, 3), rateUnit(type))
                                         : tr("+%1/-%2 %3").arg(number(h.vmax, 3), number(h.vmin, 3), rateUnit(type));
        QString relief;
        if (std::isfinite(h.fmax) || std::isfinite(h.fmin)) {
            relief = h.fmax == h.fmin ? force(h.fmax, type)
                                      : tr("+%1/-%2").arg(force(h.fmax, type), force(h.fmin, type));
            return tr("hydraulic %1, relief %2").arg(speed, relief);
        }
        return tr("hydraulic %1").arg(speed);
    }
    case solver::DriveKind::Motor:
        return tr("motor T0 %1, W0 %2 rad/s")
            .arg(force(d.param("T0").value_or(0), solver::JointType::Revolute), number(d.param("W0").value_or(0)));
    case solver::DriveKind::Pneumatic:
        return tr("pneumatic %1").arg(force(d.param("F").value_or(0), type));
    case solver::DriveKind::Servo: {
        QString s = tr("servo KP %1, KI %2, KD %3")
                        .arg(number(d.param("KP").value_or(0)), number(d.param("KI").value_or(0)),
                             number(d.param("KD").value_or(0)));
        if (auto f = d.param("FMAX")) s = tr("%1, FMAX %2").arg(s, force(*f, type));
        return s;
    }
    }
    return {};
}

QString mass(const solver::BodySpec& body)
{
    if (!body.hasMass) return tr("massless");
    return tr("%1 kg").arg(number(body.mass));
}

}  // namespace studio::jointtext
