#pragma once
// Calibration of one channel (an axis of a device): raw reading → command in [−1, 1].
//
//   1. Normalise against the captured raw minimum, centre (rest) and maximum, each side
//      on its own: centre → 0, maximum → +1, minimum → −1 (a pot rarely rests at
//      mid-travel). A one-sided channel (a trigger: centre = minimum) gives 0 … 1.
//   2. Dead band around the centre, settable separately below and above it (a
//      fraction of that side's travel, 0 … 0.9): inside it the result is 0, outside it
//      the rest of the travel is stretched back to 0 … 1, so the output is continuous.
//   3. Inversion.
//   4. Response curve: linear, or exponential with a parameter k > 0:
//      y = sign(x)·(e^{k|x|} − 1)/(e^k − 1) (fine control near the centre; k → 0 is
//      linear).
//   5. Low-pass filter, first order, cutoff fc [Hz] (0: none), on the result:
//      y ← y + α (x − y), α = 1 − e^{−2π fc Δt}.
//
// Every step keeps the result in [−1, 1], monotone in the raw reading (non-increasing
// when inverted), and 0 at the centre. A reading beyond the captured range by more
// than kOutOfRangeMargin of the span is flagged (the pot slipped, a wire is loose, the
// calibration is stale); it is clamped to ±1 meanwhile.

#include <QJsonObject>
#include <QString>

namespace trainer {

enum class ResponseCurve { Linear, Exponential };

struct ChannelCalibration {
    double rawMin = 0.0;
    double rawCentre = 0.5;
    double rawMax = 1.0;
    double deadBandLow = 0.0;   ///< fraction of the lower side's travel (0 … kMaxDeadBand)
    double deadBandHigh = 0.0;  ///< fraction of the upper side's travel
    bool inverted = false;
    ResponseCurve curve = ResponseCurve::Linear;
    double exponent = 2.0;      ///< k of the exponential curve (kMinExponent … kMaxExponent)
    double filterHz = 0.0;      ///< low-pass cutoff; 0 = none
    bool captured = false;      ///< false: the device's nominal range, never calibrated

    static constexpr double kMaxDeadBand = 0.9;
    static constexpr double kMinExponent = 0.05;
    static constexpr double kMaxExponent = 10.0;
    static constexpr double kOutOfRangeMargin = 0.03;

    /// min ≤ centre ≤ max, min < max, finite, dead bands and exponent in range, filter ≥ 0.
    bool isValid() const;
    /// Why not valid (translated), "" when valid.
    QString problem() const;

    /// Steps 1–4 (no filter): the command for `raw`.
    double apply(double raw) const;
    /// True when `raw` is beyond the captured range by more than the margin.
    bool outOfRange(double raw) const;

    QJsonObject toJson() const;
    /// Reads what toJson() wrote; missing keys keep their defaults. False (and `error`
    /// says which key) when a value has the wrong type; the result is then not valid.
    static bool fromJson(const QJsonObject& json, ChannelCalibration& out, QString* error = nullptr);

    bool operator==(const ChannelCalibration&) const = default;
};

/// The first-order low-pass of step 5, one per channel (its state).
class LowPass {
public:
    /// The filtered value after `dt` seconds with input `x` (the first call, or
    /// fc = 0, returns x).
    double update(double x, double cutoffHz, double dt);
    void reset() { m_primed = false; }
    double value() const { return m_y; }

private:
    double m_y = 0.0;
    bool m_primed = false;
};

/// Captures a calibration from live readings, as the wizard asks the trainer: first
/// the lever left at rest (the centre is the mean of the readings), then moved to its
/// full travel both ways (the extremes seen).
class CalibrationCapture {
public:
    void startRest();
    void startTravel();
    void add(double raw);
    /// Readings taken at rest; their spread (max − min) shows a noisy pot.
    int restCount() const { return m_restCount; }
    double restSpread() const { return m_restCount ? m_restMax - m_restMin : 0.0; }
    double centre() const { return m_restCount ? m_restSum / m_restCount : 0.0; }
    double seenMin() const { return m_min; }
    double seenMax() const { return m_max; }
    int travelCount() const { return m_travelCount; }
    /// Enough for a calibration: readings at rest, and travel that covers at least
    /// kMinTravel of `nominalSpan` on one side of the centre. `why` says what is missing.
    bool complete(double nominalSpan, QString* why = nullptr) const;
    /// `base` (dead bands, curve, filter kept) with the captured min, centre and max.
    /// A side moved less than kOneSidedFraction of the other is taken as one-sided
    /// (centre = that extreme: a trigger, a lever that only goes one way).
    ChannelCalibration result(const ChannelCalibration& base) const;

    static constexpr double kMinTravel = 0.2;
    static constexpr double kOneSidedFraction = 0.05;

private:
    enum class Phase { Idle, Rest, Travel } m_phase = Phase::Idle;
    int m_restCount = 0, m_travelCount = 0;
    double m_restSum = 0.0, m_restMin = 0.0, m_restMax = 0.0;
    double m_min = 0.0, m_max = 0.0;
};

}  // namespace trainer
