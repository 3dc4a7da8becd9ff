#pragma once
// TrainPage: the Train workspace, where an operator takes the training course: the
// course, a stage's start screen with its demonstration, the attempt with its HUD, the
// result and the debrief.
//
//  - Course: the tutorials of resources/tutorials/*.tut (trainer::loadTutorial) ordered
//    by LEVEL, each with its title in the UI language, the operator's best stars, and
//    locked until every stage of the level below is passed. A tutorial with errors is
//    listed disabled with its first diagnostic as tooltip. Operators and attempts go to
//    the trainee records (trainer::records::RecordsDb, the SQLite file by default;
//    trainer::AttemptLog writes each attempt as it runs, a pending file when the
//    database refuses); when the records cannot be opened, progress is kept in
//    QSettings ("trainer/progress/<operator>/<tutorial>/…", CourseProgress).
//  - Start: title, intro, "Watch the demonstration" (the tutorial's DEMO input log
//    replayed by the TutorialRunner: play/pause, speed 0.25×–4×, a scrub slider) and Start.
//  - Attempt: one 3D view with a HUD big enough to read from the seat (goal, time /
//    limit, distance, dwell, bank, hints, warnings, penalties); Esc or Stop ends it.
//    A model with pumps gets the hydraulics (HydraulicPanel) beside the view, which
//    the attempt's "Hydraulics" box folds away (remembered: "trainer/showHydraulics").
//  - Result: passed/failed, stars, score, the breakdown, what to improve; Retry,
//    Debrief, Next stage.
//  - Debrief: the run replayed from its samples (scrub slider), the timeline of events
//    (a click seeks), the force of the most loaded drive and the relief-valve openings
//    against time (QtCharts), and the comparison with the expert (the demonstration run
//    headless with trainer::runTutorialWithLog).
//  - Records: the trainer's view of the trainee records (RecordsView); in kiosk mode
//    only after the PIN (QSettings "trainer/pin"), and not at all without one.
//
// Language (docs/glossary.md): the course screen has "Español" and "English" (big
// enough for the kiosk's touch screen) that switch the whole application at once
// (i18n::switchTo). On QEvent::LanguageChange every text is set again: the static ones
// (m_texts, i18n::Texts), the course with the tutorials' titles in the new language, the start
// screen, the HUD's goal and hints, the result, the debrief and the records. Numbers
// follow the locale (1,5 in Spanish); files for machines keep '.'.
//
// The expert's ghost: "Show the expert" during an attempt (off by default, remembered
// in QSettings "trainer/showExpert") runs the demonstration in a second session beside
// the attempt (TutorialRunner::setGhost) and draws it translucent (Viewport::setGhost).
//
// Every live attempt records the operator's input (a trainer::InputRecorder on the
// station, in its input thread) to <AppDataLocation>/attempt-input/, with the station
// profile in use beside it (<log>.profile.json); the result screen saves it as a
// demonstration and can make it this stage's demonstration (QSettings
// "trainer/demo/<tutorial id>"; a log that no longer loads falls back to the shipped
// DEMO with a warning on the start screen).
//
// The page owns no thread: the TutorialRunner (owned by MainWindow, whose station
// writes its commands during an attempt) runs the sessions.

#include "ide/studio/train/centre_link.h"
#include "ide/studio/model/model_bundle.h"
#include "trainer/input/input_log.h"
#include "trainer/records/records_db.h"
#include "trainer/training/camera_path.h"
#include "trainer/training/runner.h"
#include "trainer/training/tutorial.h"
#include "ide/i18n/texts.h"

#include <QHash>
#include <QPointer>
#include <QWidget>

#include <functional>
#include <memory>
#include <vector>

class QChartView;
class QCheckBox;
class QComboBox;
class QFrame;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSlider;
class QStackedWidget;
class QTableWidget;
class QTimer;

namespace trainer {
class AttemptLog;
class Station;
}

namespace studio {

class HydraulicPanel;
class RecordsView;
class TutorialRunner;
class Viewport;
struct TrainFrame;

/// The operator's best results per tutorial. From the trainee records (trainer/records)
/// when they open; else kept in QSettings ("trainer/progress/…": load(), record()).
struct CourseProgress {
    int stars = 0;
    double score = 0.0;
    bool passed = false;
    int attempts = 0;
    static CourseProgress load(const QString& operatorId, const QString& tutorialId);
    /// Adds an attempt, keeping the best stars and score.
    static void record(const QString& operatorId, const QString& tutorialId, const trainer::TutorialResult& r);
};

class TrainPage : public QWidget {
    Q_OBJECT
public:
    enum class Screen { Course, Start, Attempt, Result, Debrief, Records };

    TrainPage(TutorialRunner* runner, trainer::Station* station, QWidget* parent = nullptr);
    ~TrainPage() override;

    /// The language of tutorial texts: the UI's (i18n::current(): "es" or "en").
    static QString language();
    /// Reads the course from `dir` again (at first the bundled tutorials, paths::tutorialsDir()).
    void setTutorialsDir(const QString& dir);

    /// The operator in training, by code (badge number…); a new code is added to the
    /// records. "" is the guest.
    void setOperator(const QString& id);
    QString operatorId() const { return m_operator; }
    /// The operator's best results at a tutorial.
    CourseProgress progressOf(const QString& tutorialId) const;
    /// The trainee records in use (nullptr: they could not be opened, QSettings instead).
    trainer::records::RecordsDb* records() const { return m_db.get(); }
    /// Why the records could not be opened or written ("" when all is well).
    QString recordsProblem() const { return m_recordsProblem; }
    /// Opens the trainee records at the SQLite file `path` ("" = the default) instead of
    /// the ones in use, and imports the pending attempts; false when they cannot be
    /// opened (recordsProblem() says why; training goes on without them).
    bool openRecordsAt(const QString& path);
    /// How many pending attempts the last opening of the records imported.
    int importedPending() const { return m_imported; }
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
    std::shared_ptr<const trainer::Tutorial> tutorial() const;
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
    std::shared_ptr<const trainer::InputLog> demoLog() const { return m_demoLog; }
    /// The file of demoLog() ("" none).
    QString demoFile() const { return m_demoFile; }
    /// The station profile the demonstration is replayed with.
    const trainer::StationProfile& demoProfile() const { return m_demoProfile; }
    /// Why the stage's chosen demonstration is not used ("" when it is, or none is chosen).
    QString demoWarning() const { return m_demoWarning; }
    /// The operator's input of the last live attempt ("" none), and the profile it went through.
    QString recordedInput() const { return m_recordedInput; }
    /// Copies the last live attempt's input (and its profile) to `path`. False with `error`.
    bool saveDemonstration(const QString& path, QString* error = nullptr);
    /// Makes `path` ("" = the last attempt's input, saved as the stage's user copy)
    /// the open stage's demonstration. False with `error` (nothing changes then).
    bool useAsDemonstration(const QString& path = {}, QString* error = nullptr);
    /// Back to the shipped demonstration for the open stage.
    void useShippedDemonstration();
    /// <AppDataLocation>/demonstrations/<id>.demo.log: the user copy of a stage's demonstration.
    static QString userDemonstrationPath(const QString& tutorialId);
    /// The expert's ghost during attempts (the "Show the expert" box).
    void setShowExpert(bool show);
    bool showExpert() const;
    /// The result of the last attempt (nullptr before one ended).
    const trainer::RunOutput* lastRun() const { return m_lastRun.get(); }
    /// The expert's run of the open tutorial, once the debrief computed it (nullptr before).
    const trainer::RunOutput* expertRun() const { return m_expert.get(); }

    // parts, for tests and wiring
    QListWidget* courseList() const { return m_courseList; }
    Viewport* attemptViewport() const { return m_attemptView; }
    Viewport* demoViewport() const { return m_demoView; }
    QLabel* hud() const { return m_hud; }
    QLabel* resultHeading() const { return m_resultHeading; }
    QLabel* resultNote() const { return m_resultNote; }
    QTableWidget* breakdownTable() const { return m_breakdown; }
    QChartView* forceChart() const { return m_forceChart; }
    QTableWidget* comparisonTable() const { return m_comparison; }
    QListWidget* timeline() const { return m_timeline; }
    QSlider* replaySlider() const { return m_replaySlider; }
    QSlider* demoSlider() const { return m_demoSlider; }
    QCheckBox* expertBox() const { return m_expertBox; }
    /// The attempt's hydraulics beside the view, and the box that shows it (shown only
    /// for a model with pumps).
    HydraulicPanel* hydraulicPanel() const { return m_hydraulics; }
    QCheckBox* hydraulicsBox() const { return m_hydraulicsBox; }
    QPushButton* recordsButton() const { return m_recordsButton; }
    /// The course screen's button that switches to language `code` ("es", "en"; nullptr: none).
    QPushButton* languageButton(const QString& code) const;
    QLabel* courseTitle() const { return m_courseTitle; }
    QLabel* startTitle() const { return m_startTitle; }
    QLabel* resultScore() const { return m_resultScore; }

    // the training centre (docs/training-centre.md): the workspace as a station of the
    // centre (centre/train_station.h drives it through these)
    /// The tutorials the course offers (those that loaded), in the course's order.
    std::vector<std::shared_ptr<const trainer::Tutorial>> tutorials() const;
    TutorialRunner* runner() const { return m_runner; }
    /// A live attempt (the operator's commands) is on: running, paused, or ended but
    /// not yet taken by onFinished.
    bool attemptLive() const { return m_attemptLive; }
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
    /// Esc in the attempt's 3D view ends the attempt (the view has the keyboard focus).
    bool eventFilter(QObject* watched, QEvent* event) override;
    /// QEvent::LanguageChange: every text again, in the new language (retranslate()).
    void changeEvent(QEvent* event) override;

private:
    struct Entry {
        QString path;
        QString id;
        int level = 0;
        trainer::LocalText titleText;  ///< TITLE, in every language
        QString title;                 ///< in language()
        QString problem;  ///< the first error ("" when it loaded)
        std::shared_ptr<const trainer::Tutorial> tutorial;
    };
    QWidget* buildCourse();
    QWidget* buildStart();
    QWidget* buildAttempt();
    QWidget* buildResult();
    QWidget* buildDebrief();
    void setScreen(Screen s);
    void retranslate();
    /// The entries' titles in language().
    void retitle();
    void refreshCourse();
    /// The open tutorial's title, intro and pass mark on the start screen.
    void fillStart();
    QString unreadableDemoText() const;
    /// The result screen of m_lastRun (showResult() without changing screens).
    void fillResult();
    void fillTimeline();
    void fillCharts();
    bool isLocked(int entry) const;
    int entryOf(const QString& id) const;
    void poll();
    void updateHud(const TrainFrame& f);
    void onFinished();
    void showResult();
    void fillDebrief();
    void showReplaySample(int index);
    void computeExpert();
    void fillComparison();
    void leaveRun();

    void openRecords(const QString& path = {});
    void loadProgress();
    void loadDemonstration(const trainer::Tutorial& t);
    bool startRecording(const trainer::Tutorial& t);
    void stopRecording();
    void askRecordsPin();
    /// The records view's tutorial titles (in language()) and pass marks.
    void giveRecordsTheTutorials();
    /// A scene's attempt: turns the seat towards the first goal when it is out of view.
    void aimSeatAtFirstGoal(const trainer::Tutorial& t);
    QStringList knownOperators() const;

    TutorialRunner* m_runner;
    trainer::Station* m_station;
    std::unique_ptr<trainer::records::RecordsDb> m_db;
    qint64 m_operatorDbId = 0;
    QHash<QString, CourseProgress> m_progress;  ///< by tutorial id, from the records
    std::shared_ptr<const trainer::Tutorial> m_attemptTutorial;  ///< the log's: outlives it
    std::unique_ptr<trainer::AttemptLog> m_attemptLog;
    int m_imported = 0;
    bool m_kiosk = false;
    bool m_allUnlocked = false;
    // the operator's input of a live attempt, recorded in the station's input thread
    std::unique_ptr<trainer::InputRecorder> m_recorder;
    QString m_recordingFile;
    trainer::StationProfile m_recordingProfile;
    QString m_recordedInput;  ///< the last live attempt's, once stopped
    QString m_demoFile, m_demoWarning;
    QStringList m_demoUnreadable;  ///< the chosen demonstration that cannot be read, and why
    trainer::StationProfile m_demoProfile;
    qint64 m_lastLogUpdate = 0;  ///< ms (steady)
    QString m_recordsProblem;
    QString m_dir;
    QString m_operator;
    std::vector<Entry> m_entries;
    int m_current = -1;  ///< entry open
    std::shared_ptr<const ModelBundle> m_bundle, m_scene;
    std::shared_ptr<const trainer::InputLog> m_demoLog;
    trainer::CameraPath m_demoCamera;        ///< the demonstration's camera (empty: none)
    QCheckBox* m_demoFollow = nullptr;       ///< follow the demonstration's camera
    trainer::StationProfile m_profile;
    bool m_demoRunning = false;
    bool m_attemptLive = false;
    long m_shownStep = -1;
    std::shared_ptr<const trainer::RunOutput> m_lastRun;
    std::shared_ptr<const trainer::RunOutput> m_expert;
    QString m_expertFor;  ///< tutorial id of m_expert
    bool m_expertBusy = false;
    Screen m_screen = Screen::Course;

    QStackedWidget* m_stack = nullptr;
    QTimer* m_timer = nullptr;
    i18n::Texts m_texts;  ///< the texts that follow the language
    // course
    QLabel* m_courseTitle = nullptr;
    QList<QPushButton*> m_languageButtons;  ///< objectName "LanguageButton_<code>"
    QListWidget* m_courseList = nullptr;
    QComboBox* m_operatorBox = nullptr;
    QPushButton* m_openButton = nullptr;
    QPushButton* m_recordsButton = nullptr;
    RecordsView* m_recordsView = nullptr;
    // start
    QLabel* m_startTitle = nullptr;
    QLabel* m_startIntro = nullptr;
    QPushButton* m_watchButton = nullptr;
    QPushButton* m_startButton = nullptr;
    Viewport* m_demoView = nullptr;
    QPushButton* m_demoPlay = nullptr;
    QComboBox* m_demoSpeed = nullptr;
    QSlider* m_demoSlider = nullptr;
    QLabel* m_demoTime = nullptr;
    QLabel* m_demoNote = nullptr;
    // attempt
    Viewport* m_attemptView = nullptr;
    QComboBox* m_cameraBox = nullptr;
    QCheckBox* m_expertBox = nullptr;
    HydraulicPanel* m_hydraulics = nullptr;
    QCheckBox* m_hydraulicsBox = nullptr;
    QFrame* m_hudPanel = nullptr;
    QLabel* m_hud = nullptr;
    QProgressBar* m_dwellBar = nullptr;
    QLabel* m_hintLabel = nullptr;
    QLabel* m_warningLabel = nullptr;
    QString m_hudText, m_hintText, m_warningText;
    // the training centre's indicator (centre/train_station.h)
    QList<QLabel*> m_centreLabels;
    CentreLink m_centreLink = CentreLink::Off;
    QString m_centreName, m_centreDetail;
    void showCentreLink();
    // result
    QLabel* m_resultHeading = nullptr;
    QLabel* m_resultStars = nullptr;
    QLabel* m_resultScore = nullptr;
    QLabel* m_resultNote = nullptr;
    QTableWidget* m_breakdown = nullptr;
    QListWidget* m_improvements = nullptr;
    QPushButton* m_nextButton = nullptr;
    QPushButton* m_saveDemoButton = nullptr;
    QPushButton* m_useDemoButton = nullptr;
    bool m_notRecorded = false;       ///< the last attempt could not be written to the records …
    QString m_unwritten;              ///< … why
    bool m_madeDemonstration = false;  ///< the last attempt became the stage's demonstration
    // debrief
    Viewport* m_replayView = nullptr;
    QSlider* m_replaySlider = nullptr;
    QPushButton* m_replayPlay = nullptr;
    QLabel* m_replayTime = nullptr;
    QListWidget* m_timeline = nullptr;
    QChartView* m_forceChart = nullptr;
    QChartView* m_reliefChart = nullptr;
    QTableWidget* m_comparison = nullptr;
    bool m_replayPlaying = false;
    double m_replayClock = 0.0;
};

}  // namespace studio
