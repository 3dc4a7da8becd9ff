#pragma once
// Live displays of a device's channels (the Station workspace and the calibration
// wizard):
//  - LevelBar: a horizontal bar over a scale, filled from an origin to the value (the
//    raw reading from the bottom of its range, the calibrated value −1…1 from 0), with
//    optional marks (the extremes seen while calibrating) and a shaded band (the dead
//    band);
//  - ButtonLamp: a small round lamp that lights while a button is pressed;
//  - ChannelPanel: one row per axis of a device — name (a gamepad's by SDL's names,
//    "Left stick X"), raw bar, raw number, calibrated bar, value, a flag ("not
//    calibrated" amber, "out of range" red) and "Calibrate…" — then the device's
//    buttons as lamps (a gamepad's labelled "A", "LB", …). The keyboard is digital:
//    its rows have no "Calibrate…" but a note saying why and a ramp (seconds to full
//    command: the low-pass of its channel's calibration, rampFilterHz()).

#include "trainer/station/station_engine.h"

#include <QColor>
#include <QList>
#include <QWidget>

#include <limits>

class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QPushButton;

namespace studio {

class LevelBar : public QWidget {
    Q_OBJECT
public:
    explicit LevelBar(QWidget* parent = nullptr);

    /// The scale [min, max]; the fill runs from `origin` to the value.
    void setScale(double min, double origin, double max);
    void setValue(double value);
    /// Thin marks at `low` and `high` (NaN: none), e.g. the extremes seen.
    void setMarks(double low, double high);
    /// A shaded span (NaN: none), e.g. the dead band.
    void setBand(double from, double to);
    void setFillColor(const QColor& color);

    double value() const { return m_value; }
    double minimum() const { return m_min; }
    double origin() const { return m_origin; }
    double maximum() const { return m_max; }
    /// Where `v` falls along the bar, 0 (min) … 1 (max), clamped.
    double fractionOf(double v) const;
    /// fractionOf(value()).
    double fraction() const { return fractionOf(m_value); }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    double m_min = -1.0, m_origin = 0.0, m_max = 1.0, m_value = 0.0;
    double m_markLow = kNone, m_markHigh = kNone;
    double m_bandFrom = kNone, m_bandTo = kNone;
    QColor m_fill{0x1e, 0x88, 0xe5};
};

class ButtonLamp : public QWidget {
    Q_OBJECT
public:
    /// `label`: a short text inside the lamp (the button's number).
    explicit ButtonLamp(const QString& label, QWidget* parent = nullptr);
    void setOn(bool on);
    bool isOn() const { return m_on; }
    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QString m_label;
    bool m_on = false;
};

class ChannelPanel : public QWidget {
    Q_OBJECT
public:
    explicit ChannelPanel(QWidget* parent = nullptr);

    /// Shows `device` (nullptr: none) with the ranges `profile` gives its channels (its
    /// calibration, else the axis's nominal range). Rows are rebuilt only when the
    /// device or its number of axes or buttons changes; otherwise values are updated.
    void setDevice(const trainer::DeviceState* device, const trainer::StationProfile& profile);

    int channelCount() const { return int(m_rows.size()); }
    LevelBar* rawBar(int axis) const { return m_rows.value(axis).raw; }
    LevelBar* valueBar(int axis) const { return m_rows.value(axis).value; }
    QLabel* rawLabel(int axis) const { return m_rows.value(axis).rawText; }
    QLabel* valueLabel(int axis) const { return m_rows.value(axis).valueText; }
    QLabel* flagLabel(int axis) const { return m_rows.value(axis).flag; }
    /// nullptr for a keyboard's channel (keys are not calibrated).
    QPushButton* calibrateButton(int axis) const { return m_rows.value(axis).calibrate; }
    /// A keyboard channel's ramp [s] (nullptr for other devices).
    QDoubleSpinBox* rampSpin(int axis) const { return m_rows.value(axis).ramp; }
    /// Why a keyboard has no calibration (shown for the keyboard only).
    QLabel* keyboardNote() const { return m_keyboardNote; }

    /// A key's ramp: the time to 95 % of the command (three time constants of the
    /// first-order low-pass) ↔ the low-pass cutoff. 0 ↔ 0 (no filter: at once).
    static double rampSeconds(double filterHz);
    static double rampFilterHz(double seconds);
    static constexpr double kMaxRamp = 3.0;  ///< [s]
    int buttonCount() const { return int(m_lamps.size()); }
    ButtonLamp* lamp(int button) const { return m_lamps.value(button); }

signals:
    /// "Calibrate…" of channel `axis` was pressed.
    void calibrateRequested(int axis);
    /// The ramp of keyboard channel `axis` was set to `seconds`.
    void rampChanged(int axis, double seconds);

protected:
    /// QEvent::LanguageChange: the titles again; the rows at the next setDevice().
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    struct Row {
        QLabel* name = nullptr;
        LevelBar* raw = nullptr;
        QLabel* rawText = nullptr;
        LevelBar* value = nullptr;
        QLabel* valueText = nullptr;
        QLabel* flag = nullptr;
        QPushButton* calibrate = nullptr;
        QDoubleSpinBox* ramp = nullptr;
    };
    static constexpr double kRampTimeConstants = 3.0;  ///< 95 % of a step
    void rebuild(const trainer::DeviceState* device);

    QString m_key;  ///< id, axes and buttons of the device shown
    QLabel* m_title = nullptr;
    QLabel* m_keyboardNote = nullptr;
    bool m_filling = false;
    QWidget* m_body = nullptr;
    QGridLayout* m_grid = nullptr;
    QLabel* m_buttonsTitle = nullptr;
    QGridLayout* m_lampGrid = nullptr;
    QList<Row> m_rows;
    QList<ButtonLamp*> m_lamps;
};

/// "512", "0.25", "-3.1e+04": a raw reading, integers without decimals (the locale's
/// decimal separator: "0,25" in Spanish; never group separators).
QString formatRaw(double raw);
/// "+0.42", "−1.00", "0.00": a calibrated value (Spanish "+0,42").
QString formatValue(double value);
/// `value` with `significant` digits in the locale ("2.5", "2,5"), without group separators.
QString formatNumber(double value, int significant = 6);

}  // namespace studio
