#include "trainer/station/calibration.h"

#include <QCoreApplication>
#include <QJsonValue>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace trainer {

namespace {

/// The translation context of this file's messages (lupdate reads Tr::tr).
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(trainer::ChannelCalibration)
};

/// Step 2 on a normalised x ≥ 0 with dead band d.
double outsideDeadBand(double x, double d)
{
    if (x <= d) return 0.0;
    return (x - d) / (1.0 - d);
}

}  // namespace

bool ChannelCalibration::isValid() const
{
    return problem().isEmpty();
}

QString ChannelCalibration::problem() const
{
    for (double v : {rawMin, rawCentre, rawMax, deadBandLow, deadBandHigh, exponent, filterHz})
        if (!std::isfinite(v)) return Tr::tr("a value is not a number");
    if (!(rawMin < rawMax)) return Tr::tr("the raw minimum must be below the raw maximum");
    if (rawCentre < rawMin || rawCentre > rawMax) return Tr::tr("the centre must lie between the minimum and the maximum");
    if (deadBandLow < 0.0 || deadBandLow > kMaxDeadBand || deadBandHigh < 0.0 || deadBandHigh > kMaxDeadBand)
        return Tr::tr("dead bands must be between 0 and 0.9 of the travel");
    if (curve == ResponseCurve::Exponential && (exponent < kMinExponent || exponent > kMaxExponent))
        return Tr::tr("the exponential curve's parameter must be between 0.05 and 10");
    if (filterHz < 0.0) return Tr::tr("the filter's cutoff cannot be negative");
    return {};
}

double ChannelCalibration::apply(double raw) const
{
    if (!std::isfinite(raw) || !isValid()) return 0.0;
    double x = 0.0;
    if (raw > rawCentre) {
        const double span = rawMax - rawCentre;
        x = span > 0.0 ? std::min(1.0, (raw - rawCentre) / span) : 0.0;
        x = outsideDeadBand(x, deadBandHigh);
    } else if (raw < rawCentre) {
        const double span = rawCentre - rawMin;
        x = span > 0.0 ? -outsideDeadBand(std::min(1.0, (rawCentre - raw) / span), deadBandLow) : 0.0;
    }
    if (inverted) x = -x;
    if (curve == ResponseCurve::Exponential && x != 0.0) {
        const double k = exponent;
        x = std::copysign(std::expm1(k * std::abs(x)) / std::expm1(k), x);
    }
    return std::clamp(x, -1.0, 1.0);
}

bool ChannelCalibration::outOfRange(double raw) const
{
    if (!std::isfinite(raw)) return true;
    const double margin = kOutOfRangeMargin * (rawMax - rawMin);
    return raw < rawMin - margin || raw > rawMax + margin;
}

QJsonObject ChannelCalibration::toJson() const
{
    return QJsonObject{{"min", rawMin},
                  {"centre", rawCentre},
                  {"max", rawMax},
                  {"deadBandLow", deadBandLow},
                  {"deadBandHigh", deadBandHigh},
                  {"inverted", inverted},
                  {"curve", curve == ResponseCurve::Linear ? "linear" : "exponential"},
                  {"filterHz", filterHz},
                  {"exponent", exponent},
                  {"captured", captured}};
}

bool ChannelCalibration::fromJson(const QJsonObject& json, ChannelCalibration& out, QString* error)
{
    ChannelCalibration c;
    auto number = [&](const char* key, double& v) {
        const QJsonValue j = json.value(key);
        if (j.isUndefined()) return true;
        if (!j.isDouble()) {
            if (error) *error = Tr::tr("“%1” must be a number").arg(key);
            return false;
        }
        v = j.toDouble();
        return true;
    };
    auto boolean = [&](const char* key, bool& v) {
        const QJsonValue j = json.value(key);
        if (j.isUndefined()) return true;
        if (!j.isBool()) {
            if (error) *error = Tr::tr("“%1” must be true or false").arg(key);
            return false;
        }
        v = j.toBool();
        return true;
    };
    if (!number("min", c.rawMin) || !number("centre", c.rawCentre) || !number("max", c.rawMax) ||
        !number("deadBandLow", c.deadBandLow) || !number("deadBandHigh", c.deadBandHigh) ||
        !number("exponent", c.exponent) || !number("filterHz", c.filterHz) || !boolean("inverted", c.inverted) ||
        !boolean("captured", c.captured))
        return false;
    const QJsonValue curve = json.value("curve");
    if (!curve.isUndefined()) {
        if (curve.toString() == "linear") c.curve = ResponseCurve::Linear;
        else if (curve.toString() == "exponential") c.curve = ResponseCurve::Exponential;
        else {
            if (error) *error = Tr::tr("“curve” must be \"linear\" or \"exponential\"");
            return false;
        }
    }
    if (!c.isValid()) {
        if (error) *error = c.problem();
        return false;
    }
    out = c;
    return true;
}

double LowPass::update(double x, double cutoffHz, double dt)
{
    if (!m_primed || cutoffHz <= 0.0 || !std::isfinite(m_y)) {
        m_y = x;
        m_primed = true;
        return m_y;
    }
    if (dt > 0.0) {
        const double alpha = -std::expm1(-2.0 * std::numbers::pi * cutoffHz * dt);
        m_y += alpha * (x - m_y);
    }
    return m_y;
}

void CalibrationCapture::startRest()
{
    m_phase = Phase::Rest;
    m_restCount = 0;
    m_restSum = 0.0;
}

void CalibrationCapture::startTravel()
{
    m_phase = Phase::Travel;
    m_travelCount = 0;
    m_min = m_max = centre();
}

void CalibrationCapture::add(double raw)
{
    if (!std::isfinite(raw)) return;
    if (m_phase == Phase::Rest) {
        if (m_restCount == 0) m_restMin = m_restMax = raw;
        m_restMin = std::min(m_restMin, raw);
        m_restMax = std::max(m_restMax, raw);
        m_restSum += raw;
        ++m_restCount;
    } else if (m_phase == Phase::Travel) {
        if (m_travelCount == 0 && m_restCount == 0) m_min = m_max = raw;
        m_min = std::min(m_min, raw);
        m_max = std::max(m_max, raw);
        ++m_travelCount;
    }
}

bool CalibrationCapture::complete(double nominalSpan, QString* why) const
{
    auto say = [&](const QString& text) {
        if (why) *why = text;
        return false;
    };
    if (m_restCount == 0) return say(Tr::tr("Leave the lever at rest to capture its centre."));
    const double c = centre();
    const double travel = std::max(m_max - c, c - m_min);
    if (m_travelCount == 0 || !(travel >= kMinTravel * std::abs(nominalSpan)))
        return say(Tr::tr("Move the lever to its full travel, both ways."));
    if (why) why->clear();
    return true;
}

ChannelCalibration CalibrationCapture::result(const ChannelCalibration& base) const
{
    ChannelCalibration c = base;
    const double centreValue = centre();
    const double up = m_max - centreValue, down = centreValue - m_min;
    c.rawMin = m_min;
    c.rawMax = m_max;
    c.rawCentre = centreValue;
    if (down < kOneSidedFraction * up) c.rawCentre = c.rawMin;
    else if (up < kOneSidedFraction * down) c.rawCentre = c.rawMax;
    c.captured = true;
    return c;
}

}  // namespace trainer
