#pragma once
// TrainingController: what the Train workspace knows and does, without a widget. The
// five screens (course_screen.h, start_screen.h, attempt_screen.h, result_screen.h,
// debrief_screen.h) show it and ask it; TrainPage (train_page.h) puts them in a stack.
//
//  - The course: the tutorials of a folder (resources/tutorials/*.tut,
//    trainer::loadTutorial) ordered by LEVEL, each with its title in the UI language;
//    a tutorial with errors is kept with its first diagnostic. A stage is locked until
//    every stage of the level below is passed (unless everything is unlocked: a
//    trainer previewing, an instructor starting it).
//  - The operator and the trainee records (trainer::records::RecordsDb, the SQLite
//    file by default; pending attempts imported when they open). When the records
//    cannot be opened, progress is kept in QSettings ("trainer/progress/<operator>/
//    <tutorial>/…", CourseProgress) and the known operators in "trainer/operators".
//  - The open tutorial: its model and scene (makeTutorialBundle, makeTutorialScene),
//    its station profile, and its demonstration: the one a trainer chose for the stage
//    (QSettings "trainer/demo/<tutorial id>", with the profile recorded beside it) or
//    the shipped DEMO, with its camera path; a chosen log that no longer loads falls
//    back to the shipped one with a warning.
//  - The attempt: the runner's session, the operator's input recorded in the station's
//    input thread (trainer::InputRecorder) to <AppDataLocation>/attempt-input/ with the
//    profile beside it (<log>.profile.json), the attempt written to the records as it
//    runs (trainer::AttemptLog; a pending file when the database refuses), and its
//    result.
//  - The expert's run of the stage for the debrief (its demonstration run headless in a
//    worker thread, trainer::runTutorialWithLog).

#include "ide/studio/model/model_bundle.h"
#include "trainer/input/input_log.h"
#include "trainer/records/records_db.h"
#include "trainer/training/camera_path.h"
#include "trainer/training/runner.h"
#include "trainer/training/tutorial.h"

#include <QHash>
#include <QObject>
#include <QStringList>

#include <memory>
#include <vector>

namespace trainer {
class AttemptLog;
class Station;
}  // namespace trainer

namespace studio {

class TutorialRunner;
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

class TrainingController : public QObject {
    Q_OBJECT
public:
    /// A tutorial of the course.
    struct Entry {
        QString path;
        QString id;
        int level = 0;
        trainer::LocalText titleText;  ///< TITLE, in every language
        QString title;                 ///< in language()
        QString problem;               ///< the first error ("" when it loaded)
        std::shared_ptr<const trainer::Tutorial> tutorial;
    };

    TrainingController(TutorialRunner* runner, trainer::Station* station, QObject* parent = nullptr);
    ~TrainingController() override;

    /// The language of tutorial texts: the UI's (i18n::current(): "es" or "en").
    static QString language();
    /// The records' code of an operator ("" is the guest).
    static QString operatorCode(const QString& id);

    TutorialRunner* runner() const { return m_runner; }
    trainer::Station* station() const { return m_station; }

    // ---- the course
    /// Reads the course from `dir`; the open tutorial is closed.
    void setTutorialsDir(const QString& dir);
    const std::vector<Entry>& entries() const { return m_entries; }
    int entryOf(const QString& id) const;
    /// Stage `entry` cannot be opened yet (the level below is not passed).
    bool isLocked(int entry) const;
    void setAllUnlocked(bool unlocked) { m_allUnlocked = unlocked; }
    bool allUnlocked() const { return m_allUnlocked; }
    /// The entries' titles in language() (after a change of language).
    void retitle();
    /// The tutorials that loaded, in the course's order.
    std::vector<std::shared_ptr<const trainer::Tutorial>> tutorials() const;

    // ---- the operator and the records
    /// The operator in training, by code; a new code is added to the records. "" is the guest.
    void setOperator(const QString& id);
    QString operatorId() const { return m_operator; }
    /// The operators the records (or QSettings) know, the guest left out.
    QStringList knownOperators() const;
    /// The operator's best results at a tutorial.
    CourseProgress progressOf(const QString& tutorialId) const;
    /// Reads the operator's progress from the records again (after an attempt).
    void loadProgress();
    trainer::records::RecordsDb* records() const { return m_db.get(); }
    /// Why the records could not be opened or written ("" when all is well).
    QString recordsProblem() const { return m_recordsProblem; }
    /// Opens the records at `path` ("" = the default) and imports the pending attempts;
    /// refused (false) during an attempt. False also when they cannot be opened.
    bool openRecordsAt(const QString& path);
    int importedPending() const { return m_imported; }
    /// An attempt is being written to the records (beginAttempt until it ends or is left).
    bool attemptRecorded() const { return m_attemptLog != nullptr; }

    // ---- the open tutorial
    /// Opens stage `entry` (its model and scene, profile and demonstration). False, with
    /// the entry's problem set, when its model cannot be built. `newModel` says whether
    /// the model changed (the views need it).
    bool open(int entry, bool* newModel = nullptr);
    /// No tutorial open (the course, the records).
    void close() { m_current = -1; }
    int current() const { return m_current; }
    std::shared_ptr<const trainer::Tutorial> tutorial() const;
    std::shared_ptr<const ModelBundle> bundle() const { return m_bundle; }
    std::shared_ptr<const ModelBundle> scene() const { return m_scene; }
    const trainer::StationProfile& profile() const { return m_profile; }

    // ---- demonstrations
    std::shared_ptr<const trainer::InputLog> demoLog() const { return m_demoLog; }
    QString demoFile() const { return m_demoFile; }
    const trainer::StationProfile& demoProfile() const { return m_demoProfile; }
    const trainer::CameraPath& demoCamera() const { return m_demoCamera; }
    /// Why the stage's chosen demonstration is not used ("" when it is, or none is chosen).
    QString demoWarning() const;
    QString recordedInput() const { return m_recordedInput; }
    bool saveDemonstration(const QString& path, QString* error = nullptr);
    bool useAsDemonstration(const QString& path = {}, QString* error = nullptr);
    void useShippedDemonstration();
    static QString userDemonstrationPath(const QString& tutorialId);

    // ---- the attempt
    /// Starts the runner's session of the open tutorial, driven by the operator (the
    /// station, whose input is recorded) or by `drive`, and the attempt's record. False
    /// (nothing started) when the runner refuses.
    bool beginAttempt(std::shared_ptr<const trainer::InputLog> drive);
    /// The operator's commands drive the attempt that runs (not a log).
    bool attemptLive() const { return m_attemptLive; }
    /// Writes the attempt's events to the records every so often (kLogEveryMs).
    void logProgress(const TrainFrame& frame);
    /// The session ended with `output`: records it (the records or QSettings) and keeps
    /// it as lastRun(). Returns whether the attempt was live.
    bool finishAttempt(std::shared_ptr<const trainer::RunOutput> output);
    /// Drops the session (the runner closed, the recording stopped, the attempt left
    /// "running" until the records mark it interrupted). Returns whether it was live.
    bool leaveAttempt();
    const trainer::RunOutput* lastRun() const { return m_lastRun.get(); }
    std::shared_ptr<const trainer::RunOutput> lastRunShared() const { return m_lastRun; }
    /// The last attempt could not be written to the records (why: unwritten()).
    bool notRecorded() const { return m_notRecorded; }
    QString unwritten() const { return m_unwritten; }
    /// The last attempt became the stage's demonstration (useAsDemonstration from the result).
    bool madeDemonstration() const { return m_madeDemonstration; }
    void setMadeDemonstration(bool made) { m_madeDemonstration = made; }

    // ---- the expert
    /// Runs the stage's demonstration headless (once per tutorial and log); expertReady()
    /// when done.
    void computeExpert();
    const trainer::RunOutput* expertRun() const { return m_expert.get(); }

signals:
    void expertReady();

private:
    void openRecords(const QString& path = {});
    void loadDemonstration(const trainer::Tutorial& t);
    bool startRecording(const trainer::Tutorial& t);
    void stopRecording();
    void forgetExpert();

    TutorialRunner* m_runner;
    trainer::Station* m_station;
    std::unique_ptr<trainer::records::RecordsDb> m_db;
    qint64 m_operatorDbId = 0;
    QHash<QString, CourseProgress> m_progress;  ///< by tutorial id, from the records
    int m_imported = 0;
    QString m_recordsProblem;
    QString m_operator;
    QString m_dir;
    std::vector<Entry> m_entries;
    bool m_allUnlocked = false;
    int m_current = -1;  ///< entry open
    std::shared_ptr<const ModelBundle> m_bundle, m_scene;
    trainer::StationProfile m_profile;
    // demonstrations
    std::shared_ptr<const trainer::InputLog> m_demoLog;
    QString m_demoFile;
    QStringList m_demoUnreadable;  ///< the chosen demonstration that cannot be read, and why
    trainer::StationProfile m_demoProfile;
    trainer::CameraPath m_demoCamera;  ///< the demonstration's camera (empty: none)
    // the attempt
    std::shared_ptr<const trainer::Tutorial> m_attemptTutorial;  ///< the log's: outlives it
    std::unique_ptr<trainer::AttemptLog> m_attemptLog;
    qint64 m_lastLogUpdate = 0;  ///< ms (steady)
    bool m_attemptLive = false;
    // the operator's input of a live attempt, recorded in the station's input thread
    std::unique_ptr<trainer::InputRecorder> m_recorder;
    QString m_recordingFile;
    trainer::StationProfile m_recordingProfile;
    QString m_recordedInput;  ///< the last live attempt's, once stopped
    std::shared_ptr<const trainer::RunOutput> m_lastRun;
    bool m_notRecorded = false;
    QString m_unwritten;
    bool m_madeDemonstration = false;
    // the expert
    std::shared_ptr<const trainer::RunOutput> m_expert;
    QString m_expertFor;  ///< tutorial id of m_expert
    bool m_expertBusy = false;
};

}  // namespace studio
