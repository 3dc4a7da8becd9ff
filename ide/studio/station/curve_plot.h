#pragma once
// CurvePlot: a channel's calibration drawn as output (−1…1, vertical) against the raw
// reading over its captured range (horizontal), with the dead band shaded, the centre
// marked and the live reading as a dot on the curve. Steps 1–4 of the calibration
// (trainer/station/calibration.h); the low-pass filter acts in time and is not drawn.

#include "trainer/station/calibration.h"

#include <QWidget>

#include <limits>

namespace studio {

class CurvePlot : public QWidget {
    Q_OBJECT
public:
    explicit CurvePlot(QWidget* parent = nullptr);

    void setCalibration(const trainer::ChannelCalibration& calibration);
    const trainer::ChannelCalibration& calibration() const { return m_calibration; }
    /// The live raw reading (NaN: none).
    void setReading(double raw);

    /// The raw span where the output is 0 (the dead band around the centre).
    static std::pair<double, double> deadBand(const trainer::ChannelCalibration& c);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    trainer::ChannelCalibration m_calibration;
    double m_reading = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace studio
