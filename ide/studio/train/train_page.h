#pragma once
// TrainPage: the Train workspace, where an operator takes the training course. It is a
// stack of screens over one TrainingController (training_controller.h: the course, the
// operator and the trainee records, the open tutorial and its demonstration, the
// attempt's recording and record, the expert's run):
//  - CourseScreen (course_screen.h): the tutorials by level with the operator's best,
//    the languages and the operator;
//  - StartScreen (start_screen.h): a stage's intro and its demonstration;
//  - AttemptScreen (attempt_screen.h): the 3D view with the HUD, the hydraulics, the
//    expert's ghost;
//  - ResultScreen (result_screen.h): passed or not, the score and what to improve;
//  - DebriefScreen (debrief_screen.h): the replay, the charts, the events, the expert;
//  - RecordsView (records_view.h): the trainer's view of the trainee records; in kiosk
//    mode only after the PIN (QSettings "trainer/pin"), and not at all without one.
// The page moves between them, polls the runner's frames (every 16 ms) into the screen
// shown, and says the training centre's state on the course and attempt screens.
//
// Language (docs/glossary.md): the course screen's "Español" and "English" switch the
// whole application at once (i18n::switchTo). On QEvent::LanguageChange the page has
// the controller retitle the course and then every screen set its texts again, the
// HUD's at the next frame. Numbers follow the locale (1,5 in Spanish); files for
// machines keep '.'.
//
// The page owns no thread: the TutorialRunner (owned by MainWindow, whose station
// writes its commands during an attempt) runs the sessions.

#include "ide/studio/train/centre_link.h"
#include "ide/studio/train/training_controller.h"

#include <QWidget>

#include <memory>
#include <vector>

class QChartView;
class QCheckBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSlider;
class QStackedWidget;
class QTableWidget;
class QTimer;

namespace trainer {
class Station;
}

namespace studio {

class AttemptScreen;
class CourseScreen;
class DebriefScreen;
class HydraulicPanel;
class RecordsView;
class ResultScreen;
class StartScreen;
class TutorialRunner;
class Viewport;

class TrainPage : public QWidget {
    Q_OBJECT
public:
    enum class Screen { Course, Start, Attempt, Result, Debrief, Records };

    TrainPage(TutorialRunner* runner, trainer::Station* station, QWidget* parent = nullptr);
    ~TrainPage() override;

    /// The language of tutorial texts: the UI's (i18n::current(): "es" or "en").
    static QString language() { return TrainingController::language(); }
    /// Reads the course from `dir` again (at first the bundled tutorials, paths::tutorialsDir()).
    void setTutorialsDir(const QString& dir);

    /// The operator in training, by code (badge number…); a new code is added to the
    /// records. "" is the guest.
    void setOperator(const QString& id);
    QString operatorId() const { return m_training->operatorId(); }
    /// The operator's best results at a tutorial.
    CourseProgress progressOf(const QString& tutorialId) const { return m_training->progressOf(tutorialId); }
    /// The trainee records in use (nullptr: they could not be opened, QSettings instead).
    trainer::records::RecordsDb* records() const { return m_training->records(); }
    /// Why the records could not be opened or written ("" when all is well).
    QString recordsProblem() const { return m_training->recordsProblem(); }
    /// Opens the trainee records at the SQLite file `path` ("" = the default) instead of
    /// the ones in use, and imports the pending attempts; false when they cannot be
    /// opened (recordsProblem() says why; training goes on without them).
    bool openRecordsAt(const QString& path);
    /// How many pending attempts the last opening of the records imported.
    int importedPending() const { return m_training->importedPending(); }
    /// Kiosk mode: the records only after the trainer's PIN, hidden without one.
    void setKiosk(bool kiosk);
    /// Every stage can be opened, passed or not (a trainer previewing; screenshots).
    void setAllUnlocked(bool unlocked);
    /// The trainer's records view (in kiosk mode only after the PIN).
    void showRecords();
    RecordsView* recordsView() const { return m_recordsView; }

    Screen screen() const { return m_screen; }
    /// Opens a tutorial's start screen (by its TUTORIAL id); false when unknown, broken or locked.
    bool openTutorial(const QString& id);
    /// The tutorial open now (nullptr on the course screen).
    std::shared_ptr<const trainer::Tutorial> tutorial() const { return m_training->tutorial(); }
    /// Plays the open tutorial's demonstration on the start screen.
    void watchDemonstration();
    /// Starts an attempt at the open tutorial with the operator's commands (the station),
    /// or — a test hook — driven by `drive`, an input log (e.g. demoLog()).
    void startAttempt(std::shared_ptr<const trainer::InputLog> drive = nullptr);
    /// Ends the attempt now (Esc, Stop).
    void stopAttempt();
    void showCourse();
    void showDebrief();
    void retry();
    void nextStage();
    /// The open tutorial's demonstration log (nullptr when it has none): the one chosen
    /// for the stage (useAsDemonstration) or the shipped DEMO.
    std::shared_ptr<const trainer::InputLog> demoLog() const { return m_training->demoLog(); }
    /// The file of demoLog() ("" none).
    QString demoFile() const { return m_training->demoFile(); }
    /// The station profile the demonstration is replayed with.
    const trainer::StationProfile& demoProfile() const { return m_training->demoProfile(); }
    /// Why the stage's chosen demonstration is not used ("" when it is, or none is chosen).
    QString demoWarning() const { return m_training->demoWarning(); }
    /// The operator's input of the last live attempt ("" none), and the profile it went through.
    QString recordedInput() const { return m_training->recordedInput(); }
    /// Copies the last live attempt's input (and its profile) to `path`. False with `error`.
    bool saveDemonstration(const QString& path, QString* error = nullptr)
    {
        return m_training->saveDemonstration(path, error);
    }
    /// Makes `path` ("" = the last attempt's input, saved as the stage's user copy)
    /// the open stage's demonstration. False with `error` (nothing changes then).
    bool useAsDemonstration(const QString& path = {}, QString* error = nullptr);
    /// Back to the shipped demonstration for the open stage.
    void useShippedDemonstration();
    /// <AppDataLocation>/demonstrations/<id>.demo.log: the user copy of a stage's demonstration.
    static QString userDemonstrationPath(const QString& tutorialId)
    {
        return TrainingController::userDemonstrationPath(tutorialId);
    }
    /// The expert's ghost during attempts (the "Show the expert" box).
    void setShowExpert(bool show);
    bool showExpert() const;
    /// The result of the last attempt (nullptr before one ended).
    const trainer::RunOutput* lastRun() const { return m_training->lastRun(); }
    /// The expert's run of the open tutorial, once the debrief computed it (nullptr before).
    const trainer::RunOutput* expertRun() const { return m_training->expertRun(); }

    // parts, for tests and wiring
    TrainingController* training() const { return m_training.get(); }
    CourseScreen* courseScreen() const { return m_course; }
    StartScreen* startScreen() const { return m_start; }
    AttemptScreen* attemptScreen() const { return m_attempt; }
    ResultScreen* resultScreen() const { return m_result; }
    DebriefScreen* debriefScreen() const { return m_debrief; }
    QListWidget* courseList() const;
    Viewport* attemptViewport() const;
    Viewport* demoViewport() const;
    QLabel* hud() const;
    QLabel* resultHeading() const;
    QLabel* resultNote() const;
    QTableWidget* breakdownTable() const;
    QChartView* forceChart() const;
    QTableWidget* comparisonTable() const;
    QListWidget* timeline() const;
    QSlider* replaySlider() const;
    QSlider* demoSlider() const;
    QCheckBox* expertBox() const;
    /// The attempt's hydraulics beside the view, and the box that shows it (shown only
    /// for a model with pumps).
    HydraulicPanel* hydraulicPanel() const;
    QCheckBox* hydraulicsBox() const;
    QPushButton* recordsButton() const;
    /// The course screen's button that switches to language `code` ("es", "en"; nullptr: none).
    QPushButton* languageButton(const QString& code) const;
    QLabel* courseTitle() const;
    QLabel* startTitle() const;
    QLabel* resultScore() const;

    // the training centre (docs/training-centre.md): the workspace as a station of the
    // centre (centre/train_station.h drives it through these)
    /// The tutorials the course offers (those that loaded), in the course's order.
    std::vector<std::shared_ptr<const trainer::Tutorial>> tutorials() const { return m_training->tutorials(); }
    TutorialRunner* runner() const { return m_training->runner(); }
    /// A live attempt (the operator's commands) is on: running, paused, or ended but
    /// not yet taken by onFinished.
    bool attemptLive() const { return m_training->attemptLive(); }
    /// Starts an attempt at tutorial `id` for operator `operatorCode` ("" the guest) as
    /// if the trainee had chosen it, locked or not (the instructor decides). False
    /// when the tutorial is unknown or cannot start.
    bool startAttemptFor(const QString& id, const QString& operatorCode);
    /// What the network indicator says (the attempt's bar and the course screen).
    /// `name`: the station's name; `detail`: why it failed (translated), or the
    /// instructor who paused the attempt.
    void setCentreLink(CentreLink link, const QString& name, const QString& detail = {});
    /// The indicator's text now ("" when off).
    QString centreLinkText() const;

signals:
    /// An attempt with live commands began (the station's commands go to the runner) …
    void attemptStarted(std::shared_ptr<const trainer::Tutorial> tutorial);
    /// … and ended (or was left).
    void attemptEnded();
    void screenChanged(studio::TrainPage::Screen screen);

protected:
    /// QEvent::LanguageChange: every text again, in the new language (retranslate()).
    void changeEvent(QEvent* event) override;

private:
    void setScreen(Screen s);
    void retranslate();
    void refreshCourse();
    void poll();
    void onFinished();
    void showResult();
    /// Leaves what runs (the demonstration, the attempt, the replay).
    void leaveRun();
    void askRecordsPin();
    /// The records view's tutorial titles (in language()) and pass marks.
    void giveRecordsTheTutorials();
    void showCentreLink();

    std::unique_ptr<TrainingController> m_training;
    bool m_kiosk = false;
    Screen m_screen = Screen::Course;
    QStackedWidget* m_stack = nullptr;
    QTimer* m_timer = nullptr;
    CourseScreen* m_course = nullptr;
    StartScreen* m_start = nullptr;
    AttemptScreen* m_attempt = nullptr;
    ResultScreen* m_result = nullptr;
    DebriefScreen* m_debrief = nullptr;
    RecordsView* m_recordsView = nullptr;
    // the training centre's indicator (centre/train_station.h)
    CentreLink m_centreLink = CentreLink::Off;
    QString m_centreName, m_centreDetail;
};

}  // namespace studio
