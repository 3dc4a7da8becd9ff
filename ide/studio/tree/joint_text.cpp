#include "ide/studio/tree/joint_text.h"

#include <QCoreApplication>
#include <QLocale>

#include <cmath>
#include <numbers>

namespace studio::jointtext {

namespace {

// the translation context of the texts below (lupdate and QCoreApplication::translate
// both see "studio::JointText")
struct JointText {
    Q_DECLARE_TR_FUNCTIONS(studio::JointText)
};

double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

/// `v` with `decimals` decimals in the current locale, without group separators.
QString fixed(double v, int decimals) { return locale().toString(v, 'f', decimals); }

/// A limit value in the joint's unit, short form: "-65.0°", "0.9 m".
QString limitValue(solver::JointType type, double v)
{
    if (isLength(type)) return JointText::tr("%1 m").arg(number(v));
    return JointText::tr("%1°").arg(fixed(degrees(v), 1));
}

/// The rate unit of a joint's coordinate.
QString rateUnit(solver::JointType type) { return isLength(type) ? JointText::tr("m/s") : JointText::tr("rad/s"); }

}  // namespace

QLocale locale()
{
    QLocale l;
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    return l;
}

QString typeName(solver::JointType type)
{
    switch (type) {
    case solver::JointType::Revolute: return JointText::tr("revolute");
    case solver::JointType::Actuator: return JointText::tr("pivoted actuator");
    case solver::JointType::Prismatic: return JointText::tr("prismatic");
    case solver::JointType::Free: return JointText::tr("free body");
    }
    return {};
}

QString unit(solver::JointType type) { return isLength(type) ? JointText::tr("m") : JointText::tr("°"); }

QString coordinate(solver::JointType type, double q)
{
    if (isLength(type)) return JointText::tr("%1 m").arg(fixed(q, 4));
    return JointText::tr("%1°").arg(fixed(degrees(q), 2));
}

QString limits(const solver::JointSpec& joint)
{
    if (joint.ll && joint.ul) {
        return JointText::tr("%1 … %2").arg(limitValue(joint.type, *joint.ll), limitValue(joint.type, *joint.ul));
    }
    if (joint.ll) return JointText::tr("≥ %1").arg(limitValue(joint.type, *joint.ll));
    if (joint.ul) return JointText::tr("≤ %1").arg(limitValue(joint.type, *joint.ul));
    return JointText::tr("unlimited");
}

QString number(double v, int digits)
{
    const double a = std::abs(v);
    if (v == 0) return QStringLiteral("0");
    const QLocale l = locale();
    if (a >= 1e-3 && a < 1e6) {
        // fixed notation with `digits` significant digits, trailing zeros dropped
        const int before = a >= 1 ? static_cast<int>(std::floor(std::log10(a))) + 1 : 0;
        const int leadingZeros = a < 1 ? -static_cast<int>(std::floor(std::log10(a))) - 1 : 0;
        const int decimals = std::max(0, digits - before + leadingZeros);
        QString s = l.toString(v, 'f', decimals);
        const QString point = l.decimalPoint();
        if (s.contains(point)) {
            const QString zero = l.zeroDigit();
            while (s.endsWith(zero)) s.chop(zero.size());
            if (s.endsWith(point)) s.chop(point.size());
        }
        return s;
    }
    return l.toString(v, 'g', digits);
}

QString force(double v, solver::JointType type)
{
    const bool torque = type == solver::JointType::Revolute;
    const double a = std::abs(v);
    if (std::isinf(v)) return JointText::tr("unlimited");
    if (a >= 1e6)
        return torque ? JointText::tr("%1 MN·m").arg(number(v / 1e6, 3)) : JointText::tr("%1 MN").arg(number(v / 1e6, 3));
    if (a >= 1e4)
        return torque ? JointText::tr("%1 kN·m").arg(number(v / 1e3, 3)) : JointText::tr("%1 kN").arg(number(v / 1e3, 3));
    return torque ? JointText::tr("%1 N·m").arg(number(v, 4)) : JointText::tr("%1 N").arg(number(v, 4));
}

QString drive(const solver::DriveSpec& d, solver::JointType type)
{
    switch (d.kind) {
    case solver::DriveKind::Hydraulic: {
        const solver::DriveSpec::Hydraulic h = d.hydraulic();
        QString speed = h.vmin == h.vmax
                            ? JointText::tr("%1 %2").arg(number(h.vmax, 3), rateUnit(type))
                            : JointText::tr("+%1/-%2 %3").arg(number(h.vmax, 3), number(h.vmin, 3), rateUnit(type));
        QString relief;
        if (std::isfinite(h.fmax) || std::isfinite(h.fmin)) {
            relief = h.fmax == h.fmin ? force(h.fmax, type)
                                      : JointText::tr("+%1/-%2").arg(force(h.fmax, type), force(h.fmin, type));
            return JointText::tr("hydraulic %1, relief %2").arg(speed, relief);
        }
        return JointText::tr("hydraulic %1").arg(speed);
    }
    case solver::DriveKind::Motor:
        return JointText::tr("motor T0 %1, W0 %2 rad/s")
            .arg(force(d.param("T0").value_or(0), solver::JointType::Revolute), number(d.param("W0").value_or(0)));
    case solver::DriveKind::Pneumatic:
        return JointText::tr("pneumatic %1").arg(force(d.param("F").value_or(0), type));
    case solver::DriveKind::Servo: {
        QString s = JointText::tr("servo KP %1, KI %2, KD %3")
                        .arg(number(d.param("KP").value_or(0)), number(d.param("KI").value_or(0)),
                             number(d.param("KD").value_or(0)));
        if (auto f = d.param("FMAX")) s = JointText::tr("%1, FMAX %2").arg(s, force(*f, type));
        return s;
    }
    }
    return {};
}

QString mass(const solver::BodySpec& body)
{
    if (!body.hasMass) return JointText::tr("massless");
    return JointText::tr("%1 kg").arg(number(body.mass));
}

}  // namespace studio::jointtext
