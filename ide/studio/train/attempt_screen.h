#pragma once
// AttemptScreen: the attempt. One 3D view (the operator's seat inside a scene, else
// from where the target shows) with a HUD big enough to read from the seat: the goal,
// goal n of m, the distance, the angle off an ALIGN, the hold with its bar and what it
// waits for, the time and its limit, penalties,
// the load in the claws and the station's bank; warnings (the station's, overload,
// a worker too close, clearance, paused by the instructor) at the top right and the
// stage's hints at the bottom. The HUD is drawn into the view's frames
// (Viewport::addOverlay). A model with pumps gets the hydraulics (HydraulicPanel)
// beside the view, never over the target, which "Hydraulics" folds away (remembered:
// "trainer/showHydraulics"). "Show the expert" (remembered: "trainer/showExpert") runs
// the demonstration beside the attempt and draws it translucent (Viewport::setGhost).
// Below the view, the controls of the stage's drives (drive_controls.h); below that the
// training centre's indicator, the camera and Stop; Esc also ends it.
// The camera box's last choice, "Three screens", is the thesis's immersion set-up
// (attempt_screens.cpp): the seat's view in the middle and two more screens beside it,
// turned −60° and +60°, with dark separators between them; remembered
// ("trainer/threeScreens").

#include "ide/i18n/texts.h"

#include <QList>
#include <QWidget>

#include <memory>

class QCheckBox;
class QComboBox;
class QFrame;
class QHBoxLayout;
class QLabel;
class QProgressBar;

namespace trainer {
struct Goal;
struct SessionProgress;
struct Tutorial;
}  // namespace trainer

namespace studio {

class HydraulicPanel;
class TrainingController;
class Viewport;
struct TrainFrame;

class AttemptScreen : public QWidget {
    Q_OBJECT
public:
    explicit AttemptScreen(TrainingController* training, QWidget* parent = nullptr);

    /// An attempt began (TrainingController::beginAttempt): the expert, the HUD and the
    /// hydraulics from its first frame, before the screen shows.
    void prepare();
    /// Once shown: the camera (the seat turned towards the first goal in a scene, else
    /// the model and targets framed) and the keyboard focus on the view.
    void aim();
    /// The runner's frame of the attempt: the view, the hydraulics, the ghost and the HUD.
    void showFrame(const TrainFrame& f);
    /// Trainer Mode (kiosk): the expert box shows the trainer's choice
    /// ("trainer/kioskShowExpert", set in the records) and the trainee cannot change it.
    /// Outside it, the box is the studio's own ("trainer/showExpert").
    void setKiosk(bool kiosk);
    /// The attempt is left: no ghost, the expert box inert.
    void leave();
    /// Every text in the UI's language; the HUD at the next frame.
    void retranslate();

    Viewport* view() const { return m_view; }
    QLabel* hud() const { return m_hud; }
    /// How to drive, below the view: the profile's keys and levers for the stage's drives.
    QLabel* controls() const { return m_controls; }
    QCheckBox* expertBox() const { return m_expertBox; }
    HydraulicPanel* hydraulicPanel() const { return m_hydraulics; }
    QCheckBox* hydraulicsBox() const { return m_hydraulicsBox; }
    /// Three screens side by side (the seat at −60°, 0°, +60°) or the one view.
    void setThreeScreens(bool on);
    bool threeScreens() const { return m_three; }
    /// Screen `i` of the three, left to right (1 is view()); nullptr out of range.
    Viewport* screen(int i) const;
    /// The training centre's indicator (TrainPage::setCentreLink fills it).
    QLabel* centreLabel() const { return m_centre; }

signals:
    /// Esc or Stop.
    void stopRequested();

protected:
    /// Esc in the 3D view (which has the keyboard focus) ends the attempt.
    bool eventFilter(QObject* watched, QEvent* event) override;

    /// The HUD's lines for goal `g` under way: the distance, the angle off an ALIGN (in
    /// degrees, with its tolerance), and the hold: how much longer, or what it waits for
    /// ("Hold 2 s once you come within 0.12 m and align the head: 14° off").
    static QStringList goalLines(const trainer::Goal& g, const trainer::SessionProgress& p);

private:
    void updateHud(const TrainFrame& f);
    /// The controls line for the open tutorial and its profile (drive_controls.h).
    void showControls();
    /// The HUD in the top left corner, or the bottom left one while the current goal's
    /// target would be behind it there (the hints then go to the top).
    void placeHud(const TrainFrame& f);
    /// The HUD's and the hints' type in proportion to the view's height (a 720-line
    /// screen reads them smaller than a 1080-line one).
    void scaleHud();
    /// A scene's attempt: turns the seat towards the first goal when it is out of view.
    void aimSeatAtFirstGoal(const trainer::Tutorial& t);
    /// The side screens and their separators around `viewBox` in `row` (hidden).
    void buildSideScreens(QHBoxLayout* row, QWidget* viewBox);
    /// The side screens show what the middle one does: its model, scene, poses, ghost
    /// and seat, turned ∓60°.
    void syncSideScreens();

    TrainingController* m_training;
    i18n::Texts m_texts;
    bool m_on = false;  ///< between prepare() and leave()
    bool m_kiosk = false;
    long m_shownStep = -1;
    Viewport* m_view = nullptr;
    Viewport* m_left = nullptr;   ///< the side screens (three screens)
    Viewport* m_right = nullptr;
    QList<QWidget*> m_sideParts;  ///< the side screens and their separators
    bool m_three = false;
    QComboBox* m_cameraBox = nullptr;
    QCheckBox* m_expertBox = nullptr;
    HydraulicPanel* m_hydraulics = nullptr;
    QCheckBox* m_hydraulicsBox = nullptr;
    QFrame* m_hudPanel = nullptr;
    QLabel* m_hud = nullptr;
    QProgressBar* m_dwellBar = nullptr;
    QLabel* m_hintLabel = nullptr;
    QLabel* m_warningLabel = nullptr;
    QLabel* m_centre = nullptr;
    QLabel* m_controls = nullptr;
    bool m_hudLow = false;  ///< the HUD in the bottom left corner (placeHud)
    int m_hudFontPx = 0;
    QString m_hudText, m_hintText, m_warningText;  ///< as shown (set again only when they change)
};

}  // namespace studio
