#pragma once
// StartScreen: a stage before its attempt. On the left its title, intro, time limit and
// pass mark, "Watch the demonstration", Start and Back to the course; on the right the
// demonstration: the stage's input log replayed by the TutorialRunner in a 3D view,
// with play/pause, speed 0.25×–4×, a scrub slider (a release seeks exactly) and, for a
// shipped demonstration with a camera path, the expert's camera; over the replay, the
// levers the expert moves (LeverBars). Under the intro, how to drive: the keys and
// levers of the stage's profile for its drives (drive_controls.h).

#include "ide/i18n/texts.h"

#include <QWidget>

#include <memory>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSlider;

namespace studio {

class LeverBars;
class TrainingController;
class Viewport;
struct TrainFrame;

class StartScreen : public QWidget {
    Q_OBJECT
public:
    explicit StartScreen(TrainingController* training, QWidget* parent = nullptr);

    /// Shows the open tutorial: its texts, its demonstration's controls, and the machine
    /// at the start (the runner's first frame of a session it then closes).
    void open();
    /// Plays the open tutorial's demonstration.
    void watchDemonstration();
    /// The demonstration is playing (or paused, or ended but not left).
    bool demoRunning() const { return m_demoRunning; }
    /// The runner's frame of the demonstration: the view, the expert's camera, the clock.
    void showFrame(const TrainFrame& f);
    /// The demonstration ended.
    void demoFinished();
    /// The demonstration is left (another screen, another run).
    void leave();
    /// Every text in the UI's language; the clock at the next frame.
    void retranslate();

    QLabel* title() const { return m_title; }
    Viewport* view() const { return m_view; }
    QSlider* slider() const { return m_slider; }
    /// How to drive: the keys and levers of the profile for the stage's drives.
    QLabel* controls() const { return m_controls; }
    /// The expert's levers over the replay (shown while the demonstration runs).
    LeverBars* leverBars() const { return m_bars; }

signals:
    void startRequested();
    void backRequested();

private:
    /// The open tutorial's title, intro and pass mark, and the demonstration's note.
    void fill();
    void seekSlider();
    /// The lever bars for the demonstration's log and profile, shown.
    void showLevers();

    TrainingController* m_training;
    i18n::Texts m_texts;
    QLabel* m_title = nullptr;
    QLabel* m_intro = nullptr;
    QLabel* m_controls = nullptr;  ///< how to drive (drive_controls.h)
    QPushButton* m_watchButton = nullptr;
    QPushButton* m_startButton = nullptr;
    Viewport* m_view = nullptr;
    QPushButton* m_play = nullptr;
    QComboBox* m_speed = nullptr;
    QSlider* m_slider = nullptr;
    QLabel* m_time = nullptr;
    QLabel* m_note = nullptr;
    QCheckBox* m_follow = nullptr;  ///< follow the demonstration's camera
    LeverBars* m_bars = nullptr;
    bool m_demoRunning = false;
    long m_shownStep = -1;
};

}  // namespace studio
