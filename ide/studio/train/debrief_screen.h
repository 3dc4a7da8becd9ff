#pragma once
// DebriefScreen: the attempt looked at again. The run replayed from its samples in a
// 3D view (Play/Pause, a scrub slider), the force of the most loaded drive and the
// relief-valve openings against time (QtCharts, a red vertical line at the replay's
// time: the series named "ReplayCursor"), the timeline of events (a click seeks
// the replay there) and "You and the expert": the attempt's measures beside those of
// the stage's demonstration run headless (TrainingController::computeExpert).

#include "ide/i18n/texts.h"

#include <QWidget>

#include <memory>

class QChartView;
class QLabel;
class QListWidget;
class QPushButton;
class QSlider;
class QTableWidget;

namespace studio {

class TrainingController;
class Viewport;

class DebriefScreen : public QWidget {
    Q_OBJECT
public:
    explicit DebriefScreen(TrainingController* training, QWidget* parent = nullptr);

    /// Shows the controller's last run from its start (nothing before one).
    void fill();
    /// The replay, `seconds` of play later; false when it is not playing.
    bool advance(double seconds);
    /// The replay stops (the screen is left).
    void leave() { m_playing = false; }
    /// The comparison with the expert (again, once the expert's run is known).
    void fillComparison();
    /// Every text in the UI's language.
    void retranslate();

    Viewport* view() const { return m_view; }
    QSlider* slider() const { return m_slider; }
    QListWidget* timeline() const { return m_timeline; }
    QChartView* forceChart() const { return m_forceChart; }
    QTableWidget* comparison() const { return m_comparison; }

signals:
    void backRequested();

private:
    void showSample(int index);
    void fillTimeline();
    void fillCharts();

    TrainingController* m_training;
    i18n::Texts m_texts;
    Viewport* m_view = nullptr;
    QSlider* m_slider = nullptr;
    QPushButton* m_play = nullptr;
    QLabel* m_time = nullptr;
    QListWidget* m_timeline = nullptr;
    QChartView* m_forceChart = nullptr;
    QChartView* m_reliefChart = nullptr;
    QTableWidget* m_comparison = nullptr;
    bool m_playing = false;
    double m_clock = 0.0;  ///< the replay's time [s]
};

}  // namespace studio
