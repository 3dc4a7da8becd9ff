#include "solver/core/actuator_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace solver {

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

double wrapAngle(double angle)
{
    double w = std::remainder(angle, 2 * kPi);
    if (w <= -kPi) w += 2 * kPi;
    return w;
}

double ActuatorLengthLaw::rho() const
{
    return std::hypot(c1, c2);
}

double ActuatorLengthLaw::phi() const
{
    return std::atan2(c2, c1);
}

double ActuatorLengthLaw::minLength() const
{
    return std::sqrt(std::max(0.0, c0 - rho()));
}

double ActuatorLengthLaw::maxLength() const
{
    return std::sqrt(std::max(0.0, c0 + rho()));
}

double ActuatorLengthLaw::angleOfMaxLength() const
{
    return wrapAngle(phi());
}

double ActuatorLengthLaw::angleOfMinLength() const
{
    return wrapAngle(phi() + kPi);
}

double ActuatorLengthLaw::lengthSquared(double angle) const
{
    return c0 + c1 * std::cos(angle) + c2 * std::sin(angle);
}

double ActuatorLengthLaw::length(double angle) const
{
    return std::sqrt(std::max(0.0, lengthSquared(angle)));
}

double ActuatorLengthLaw::lengthRate(double angle) const
{
    const double l = length(angle);
    if (l <= 0) return 0;
    return (c2 * std::cos(angle) - c1 * std::sin(angle)) / (2 * l);
}

double ActuatorLengthLaw::lengthSecondDerivative(double angle) const
{
    const double l2 = lengthSquared(angle);
    if (!(l2 > 0)) return 0;
    const double l = std::sqrt(l2);
    const double d = (c2 * std::cos(angle) - c1 * std::sin(angle)) / (2 * l);
    return (c0 - l2 - 2 * d * d) / (2 * l);
}

void ActuatorLengthLaw::lengthDerivatives(double angle, double& len, double& rate,
                                          double& secondRate) const
{
    lengthDerivativesAt(std::cos(angle), std::sin(angle), len, rate, secondRate);
}

void ActuatorLengthLaw::lengthDerivativesAt(double c, double s, double& len, double& rate,
                                            double& secondRate) const
{
    const double l2 = c0 + c1 * c + c2 * s;
    if (!(l2 > 0)) {
        len = rate = secondRate = 0;
        return;
    }
    len = std::sqrt(l2);
    rate = (c2 * c - c1 * s) / (2 * len);
    secondRate = (c0 - l2 - 2 * rate * rate) / (2 * len);
}

double ActuatorLengthLaw::angleRate(double angle) const
{
    const double d = lengthRate(angle);
    if (d == 0) return std::numeric_limits<double>::infinity();
    return 1 / d;
}

std::optional<double> ActuatorLengthLaw::angleNear(double len, double near, double tolerance) const
{
    const double r = rho();
    if (!(r > 0) || !std::isfinite(len)) return std::nullopt;
    if (len < minLength() - tolerance || len > maxLength() + tolerance) return std::nullopt;

    // L² = c0 + ρ cos(θ − φ): two branches φ ± acos(k)
    const double k = std::clamp((len * len - c0) / r, -1.0, 1.0);
    const double da = std::acos(k);
    const double t1 = wrapAngle(phi() + da);
    const double t2 = wrapAngle(phi() - da);
    const double e1 = std::abs(wrapAngle(t1 - near));
    const double e2 = std::abs(wrapAngle(t2 - near));
    return e2 < e1 ? t2 : t1;
}

std::optional<double> ActuatorLengthLaw::angle(double len, double tolerance) const
{
    return angleNear(len, 0.0, tolerance);
}

}  // namespace solver
