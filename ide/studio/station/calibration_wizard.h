#pragma once
// CalibrationWizard: calibrates one channel (an axis of a device) from live readings,
// as trainer::CalibrationCapture asks the trainer (DESIGN "The station"):
//  1. "Leave the lever at rest": restReadings() readings (≈1.5 s) give the centre; the
//     page shows the reading and its spread (a noisy pot shows here).
//  2. "Move the lever to its full travel, both ways": a live bar with the extremes
//     seen; Next only once the capture is complete (enough travel).
//  3. Settings: dead band below and above the centre, inversion, response curve,
//     low-pass cutoff, and under which name the profile keeps it (this device's id, or
//     its kind so that any gamepad uses it), with a plot of the curve and live bars of
//     the raw and calibrated value as these settings give it.
// Finish emits calibrationReady(); the Station page installs it (post → setCalibration)
// and keeps it in its profile.
//
// Language: on QEvent::LanguageChange the pages' texts are set again and the numbers
// follow the new locale (1,5 in Spanish; the spin boxes too).
//
// Readings: while liveInput() (the default) a timer reads the channel's raw value from
// the station's newest state kRefreshHz times a second. Tests turn that off and feed
// readings with addReading(); setRestReadings() shortens the rest capture.

#include "trainer/station/calibration.h"
#include "trainer/station/station.h"
#include "ide/i18n/texts.h"

#include <QPointer>
#include <QWizard>

#include <functional>
#include <limits>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QRadioButton;
class QTimer;

namespace studio {

class CurvePlot;
class LevelBar;

class CalibrationWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { RestPage = 0, TravelPage = 1, SettingsPage = 2 };
    static constexpr double kRefreshHz = 30.0;
    static constexpr int kDefaultRestReadings = 45;  ///< 1.5 s at kRefreshHz
    /// A rest spread above this fraction of the nominal span is pointed out.
    static constexpr double kNoisySpread = 0.02;

    /// Calibrates `axis` of `device` (a replay when `replay`). `current`: the channel's
    /// calibration now — its dead bands, curve and filter are the starting settings; the
    /// range is captured anew. `match`: the name to keep it under at first ("" = the
    /// kind for a gamepad, the id otherwise). `station` (not owned; nullptr: readings
    /// only through addReading()).
    CalibrationWizard(trainer::Station* station, const trainer::DeviceInfo& device, bool replay, int axis,
                      const trainer::ChannelCalibration& current, const QString& match = {},
                      QWidget* parent = nullptr);
    ~CalibrationWizard() override;

    /// Reads the station at kRefreshHz (true by default).
    void setLiveInput(bool live);
    bool liveInput() const;
    /// One reading of the channel, as the live timer gives it: captured on the rest and
    /// travel pages, previewed on the settings page.
    void addReading(double raw);
    double lastReading() const { return m_last; }

    void setRestReadings(int count);
    int restReadings() const { return m_restReadings; }
    /// Starts the rest capture again (the "Capture again" button).
    void restartRest();

    const trainer::CalibrationCapture& capture() const { return m_capture; }
    /// The travel that counts as complete is measured against this span (the axis's
    /// nominal range).
    double nominalSpan() const;
    /// The captured range with the settings of page 3.
    trainer::ChannelCalibration calibration() const;
    /// The device id, or its kind key (page 3's choice).
    QString deviceMatch() const;
    const trainer::DeviceInfo& device() const { return m_device; }
    int axis() const { return m_axis; }

    // page widgets, for tests
    QProgressBar* restProgress() const { return m_restProgress; }
    QLabel* restText() const { return m_restText; }
    LevelBar* restBar() const { return m_restBar; }
    LevelBar* travelBar() const { return m_travelBar; }
    QLabel* travelText() const { return m_travelText; }
    QDoubleSpinBox* deadBandLowSpin() const { return m_deadLow; }
    QDoubleSpinBox* deadBandHighSpin() const { return m_deadHigh; }
    QCheckBox* invertedCheck() const { return m_inverted; }
    QComboBox* curveCombo() const { return m_curve; }
    QDoubleSpinBox* exponentSpin() const { return m_exponent; }
    QDoubleSpinBox* filterSpin() const { return m_filter; }
    QRadioButton* thisDeviceRadio() const { return m_thisDevice; }
    QRadioButton* anyKindRadio() const { return m_anyKind; }
    CurvePlot* curvePlot() const { return m_plot; }
    LevelBar* previewRawBar() const { return m_previewRaw; }
    LevelBar* previewValueBar() const { return m_previewValue; }
    /// The calibrated value the settings page shows now (filter included).
    double previewValue() const { return m_previewOutput; }

    void accept() override;

signals:
    /// Finish: keep `calibration` for (`deviceMatch`, `axis`).
    void calibrationReady(const QString& deviceMatch, int axis, const trainer::ChannelCalibration& calibration);

protected:
    /// QEvent::LanguageChange: every text again.
    void changeEvent(QEvent* event) override;

private:
    QWizardPage* buildRestPage();
    QWizardPage* buildTravelPage();
    QWizardPage* buildSettingsPage();
    void readStation();
    void showRest();
    void showTravel();
    void showSettings();
    void settingsChanged();

    enum class Phase { None, Rest, Travel };

    QPointer<trainer::Station> m_station;
    trainer::DeviceInfo m_device;
    bool m_replay = false;
    int m_axis = 0;
    trainer::ChannelCalibration m_base;
    trainer::CalibrationCapture m_capture;
    trainer::LowPass m_previewFilter;
    Phase m_phase = Phase::None;
    int m_restReadings = kDefaultRestReadings;
    double m_last = std::numeric_limits<double>::quiet_NaN();
    double m_previewOutput = 0.0;
    QTimer* m_timer = nullptr;
    i18n::Texts m_texts;  ///< the texts that follow the language

    QLabel* m_connection[3] = {};
    QProgressBar* m_restProgress = nullptr;
    QLabel* m_restText = nullptr;
    QLabel* m_restNoise = nullptr;
    LevelBar* m_restBar = nullptr;
    LevelBar* m_travelBar = nullptr;
    QLabel* m_travelText = nullptr;
    QLabel* m_travelWhy = nullptr;
    QLabel* m_captured = nullptr;
    QDoubleSpinBox* m_deadLow = nullptr;
    QDoubleSpinBox* m_deadHigh = nullptr;
    QCheckBox* m_inverted = nullptr;
    QComboBox* m_curve = nullptr;
    QDoubleSpinBox* m_exponent = nullptr;
    QDoubleSpinBox* m_filter = nullptr;
    QRadioButton* m_thisDevice = nullptr;
    QRadioButton* m_anyKind = nullptr;
    CurvePlot* m_plot = nullptr;
    LevelBar* m_previewRaw = nullptr;
    LevelBar* m_previewValue = nullptr;
    QLabel* m_previewText = nullptr;
};

}  // namespace studio
