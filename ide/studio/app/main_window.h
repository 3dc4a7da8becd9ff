#pragma once
// MainWindow: padrob-studio's window (DESIGN.md "layout").
//
// A mode bar on the left switches the three workspaces: Model, Station (devices,
// calibration, valve mapping: StationPage) and Train (the course, attempts, results and
// debriefs: TrainPage over a TutorialRunner; during a live attempt the station's
// commands go to the TutorialRunner instead of the SimulationRunner). Kiosk mode
// (padrob-studio --trainer) shows only the Train workspace, full screen, without the
// mode bar and menus; Ctrl+Shift+F12 and the trainer's PIN (QSettings "trainer/pin";
// none set: the keys alone) leave it. The Model workspace is an inner main
// window whose central widget is the 3D viewport layout, with docks for the model
// tree, the joint sliders, the editor (with its problems list), the plots and the
// hydraulics (HydraulicPanel, beside the plots: shown when a model with pumps is
// applied, hidden when one without is); its dock layout and the window geometry
// persist in QSettings, as do the recent files.
//
// Language: Settings ▸ Language ▸ Español / English (i18n::switchTo, remembered for the
// next start) changes every text of the running window: each widget re-sets its texts
// on QEvent::LanguageChange, and this window gives its children the new locale (numbers
// read 1,5 in Spanish; model text keeps '.').
//
// Not applied: while the editor holds text other than the applied model's (an edit, a
// file opened or File ▸ New not applied yet), a bar over the 3D view says that the view,
// the tree and the plots show the model applied before, with Apply and Revert.
//
// Files: with no model given, the window reopens the file opened last (QSettings
// "recentFiles"), or the bundled liner manipulator when it is gone. File ▸ New starts
// without the scene (the scene used last comes back with the next start). When the
// model's file changes on disk (an external editor; ModelDocument watches it, also
// when the editor replaces it by a rename) the model is reloaded and applied, keeping
// the simulation's pose when the new model has the same joints (by name, or id when
// unnamed, and type) and resuming the run; with unsaved edits the editor offers to
// reload instead (EditorPanel::offerReload).
//
// Data flow: the editor checks the text as it is typed; "Apply" gives a ModelBundle
// (only a model without errors) to the viewport, the tree, the sliders, the plots and
// the solver thread (SimulationRunner), which restarts paused at the model's initial
// state; a model with errors is never applied, the last good one keeps running. A
// 60 Hz timer draws the newest snapshot of the solver thread (never blocking it).

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/overrun_meter.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QPointer>

#include <memory>
#include <optional>
#include <utility>

class QAction;
class QActionGroup;
class QComboBox;
class QDockWidget;
class QImage;
class QLabel;
class QMenu;
class QPushButton;
class QStackedWidget;
class QTimer;
class QToolBar;

namespace trainer {
class KeyboardDevice;
class Station;
struct StationProfile;
}  // namespace trainer

namespace studio {

class EditorPanel;
class GettingStarted;
class HydraulicPanel;
class InertiaDialog;
class JointSliders;
class KeyboardInput;
class ModelTree;
class PlotPanel;
class VideoRecorder;
class SimulationRunner;
struct Snapshot;
class StationPage;
class TrainPage;
class TutorialRunner;
class ViewportLayout;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Opens `path`, or the bundled liner manipulator when it is empty; offers the
    /// recovery copies a crash left behind first.
    void openInitial(const QString& path);
    /// Opens a model file into the editor and applies it when it has no errors.
    bool openFile(const QString& path);

    /// Draws the scene file `path` around the model (View ▸ Scene; view/scene_file.h)
    /// and remembers it as the scene used last. When it cannot be used, says why (a
    /// message box that does not block, and the status bar) and keeps the scene it had.
    bool loadScene(const QString& path);
    /// No scene, now and at the next start.
    void clearScene();
    /// Loads the scene used last again (QSettings "scene/last"); false when there was
    /// none or it cannot be used any more (then said in the status bar and forgotten).
    bool restoreScene();
    /// The scene's file ("" for none).
    QString scenePath() const { return m_scenePath; }

    // parts, for tests and wiring
    EditorPanel* editor() const { return m_editor; }
    ViewportLayout* viewports() const { return m_viewports; }
    ModelTree* modelTree() const { return m_tree; }
    JointSliders* sliders() const { return m_sliders; }
    PlotPanel* plots() const { return m_plots; }
    HydraulicPanel* hydraulics() const { return m_hydraulics; }
    SimulationRunner* runner() const { return m_runner.get(); }
    /// The operator's station (input thread): devices, calibration, mapping → commands.
    trainer::Station* station() const { return m_station.get(); }
    /// The keyboard as a station device (the 3D view's keys go there, channel k = pair k).
    trainer::KeyboardDevice* keyboardDevice() const { return m_keyboardDevice.get(); }
    /// The heads-up display over the viewports (profile, active bank, device warnings).
    QLabel* hud() const { return m_hud; }
    StationPage* stationPage() const { return m_stationPage; }
    TrainPage* trainPage() const { return m_trainPage; }
    TutorialRunner* tutorialRunner() const { return m_tutorialRunner.get(); }

    /// Kiosk mode: only the Train workspace, full screen, no mode bar, menus or status bar.
    void setKioskMode(bool on);
    bool isKioskMode() const { return m_kiosk; }
    /// Ctrl+Shift+F12 in kiosk mode: asks the trainer's PIN (a dialog named
    /// "KioskPinDialog") when one is set, else leaves kiosk mode at once.
    void requestLeaveKiosk();
    std::shared_ptr<const ModelBundle> bundle() const { return m_bundle; }

    enum class Workspace { Model, Station, Train };
    void setWorkspace(Workspace w);
    Workspace workspace() const;

    /// The first-run overlay (GettingStarted): shown unless it was dismissed once
    /// (padrob-studio's main() asks, not kiosk mode); Help ▸ Getting Started opens it again.
    void showGettingStartedOnce();
    void showGettingStarted();
    GettingStarted* gettingStarted() const { return m_gettingStarted; }

    /// The simulation menu's actions.
    void run();
    void pause();
    void step();
    void reset();
    void setSpeed(double speed);

    /// View ▸ Record Video… (main_window_tools.cpp): records the 3D view of the workspace
    /// shown (the Model workspace's screens side by side, or the Train attempt's view)
    /// into `path` through ffmpeg (VideoRecorder); never over the model or the scene file.
    /// False with `error` set when it cannot start. The status bar shows "● REC" meanwhile.
    bool startRecording(const QString& path, QString* error = nullptr);
    /// Stops the recording; the recorder's finished() says when the file is complete.
    void stopRecording();
    VideoRecorder* recorder() const { return m_recorder; }

protected:
    void closeEvent(QCloseEvent* event) override;
    /// A language change (Settings ▸ Language, i18n::switchTo): the new locale for the
    /// children, and every text of the window again (retranslate()).
    void changeEvent(QEvent* event) override;

private:
    struct MenuItems;
    void buildWorkspaces();
    void buildMenus();
    /// Sets every text of the window in the current language: menus, actions, docks,
    /// workspaces, status bar, title (the parts set their own on the same event).
    void retranslate();
    QString recordsNoteText() const;
    void updateModelLabel();
    void showKeyboardControls();
    /// The Simulation toolbar of the Model workspace: the Simulation menu's Run, Pause,
    /// Step and Reset (the same actions, with icons) and the speed (main_window_tools.cpp).
    void buildSimulationBar();
    /// The toolbar's and the recording's texts (from retranslate()).
    void retranslateTools();
    /// View ▸ Record Video…: asks for the file and starts, or stops.
    void toggleRecording();
    void updateRecordingLabel();
    /// A frame of the 3D view being recorded (startRecording).
    QImage recordedFrame() const;
    void applyBundle(std::shared_ptr<const ModelBundle> bundle);
    void poll();
    void updateHud();
    /// Gives the station the model's drives, and the Station workspace the model: it
    /// installs the profile used last with this model, else its Gamepad profile, else
    /// the first stored, else one made for it.
    void setStationModel(const std::shared_ptr<const ModelBundle>& bundle);
    void updateTitle();
    void updateRecentMenu();
    void addRecent(const QString& path);
    bool maybeSave();  ///< false when the user cancelled
    bool save();
    bool saveAs();
    void newModel();
    void openDialog();
    void showLanguageReference();
    void showAbout();
    void showInertiaDialog();
    void offerRecovery();
    void onSimulationFailed(const QString& message);
    void onFileChangedOnDisk(const QString& path, bool deleted);
    /// Reads the model's file again and applies it, keeping the pose (see the top).
    void reloadFromDisk();
    /// The bar "not applied" over the 3D view: shown or hidden, its texts.
    void updateUnappliedBar();
    /// Sends a pose to the simulation (SimulationRunner::setPositions), counted.
    bool sendPose(const Eigen::VectorXd& theta);
    /// After a reload's apply: the pose kept for the new model, the run resumed.
    void restoreKeptPose();
    void restoreLayout();
    void saveLayout();

    std::shared_ptr<const ModelBundle> m_bundle;  ///< what runs: m_applied, in the scene under CONTACT
    std::shared_ptr<const ModelBundle> m_applied;  ///< as the editor applied it
    std::shared_ptr<const ModelBundle> m_sceneBundle;  ///< the scene loaded (nullptr: none)
    /// Applies m_applied in m_sceneBundle (bundleInScene): with CONTACT the model touches the
    /// scene's solids, and loading or clearing a scene compiles it again.
    void applyInScene();
    std::unique_ptr<SimulationRunner> m_runner;
    std::unique_ptr<TutorialRunner> m_tutorialRunner;  ///< before m_station: destroyed after it
    KeyboardInput* m_keyboard = nullptr;
    std::unique_ptr<trainer::Station> m_station;  ///< after m_runner: destroyed first
    std::shared_ptr<trainer::KeyboardDevice> m_keyboardDevice;
    QLabel* m_hud = nullptr;
    StationPage* m_stationPage = nullptr;
    TrainPage* m_trainPage = nullptr;
    QToolBar* m_modeBar = nullptr;
    bool m_kiosk = false;
    QString m_hudText;
    QString m_scenePath;
    QWidget* m_unappliedBar = nullptr;
    QLabel* m_unappliedText = nullptr;
    QPushButton* m_unappliedApply = nullptr;
    QPushButton* m_unappliedRevert = nullptr;
    /// A reload from disk waiting for its apply: the pose and the run to carry over.
    struct KeptPose {
        std::shared_ptr<const ModelBundle> bundle;  ///< the model the pose is of
        Eigen::VectorXd theta;
        bool running = false;
        QString file;
    };
    std::optional<KeptPose> m_keptPose;

    QStackedWidget* m_workspaces = nullptr;
    QMainWindow* m_modelSpace = nullptr;
    ViewportLayout* m_viewports = nullptr;
    EditorPanel* m_editor = nullptr;
    ModelTree* m_tree = nullptr;
    JointSliders* m_sliders = nullptr;
    PlotPanel* m_plots = nullptr;
    HydraulicPanel* m_hydraulics = nullptr;
    int m_fluidPower = -1;  ///< the applied model has pumps (1) or not (0); −1 before the first
    QList<QDockWidget*> m_docks;
    QDockWidget* m_treeDock = nullptr;
    QDockWidget* m_sliderDock = nullptr;
    QDockWidget* m_editorDock = nullptr;
    QDockWidget* m_plotsDock = nullptr;
    QDockWidget* m_hydraulicsDock = nullptr;
    std::unique_ptr<MenuItems> m_items;
    QActionGroup* m_workspaceGroup = nullptr;
    QList<QAction*> m_workspaceActions;

    QMenu* m_recentMenu = nullptr;
    GettingStarted* m_gettingStarted = nullptr;
    QAction* m_runAction = nullptr;
    QAction* m_pauseAction = nullptr;
    QAction* m_stepAction = nullptr;
    QAction* m_resetAction = nullptr;
    QActionGroup* m_speedGroup = nullptr;
    QComboBox* m_speedBox = nullptr;  ///< the toolbar's speed (m_speedGroup's choices)
    QLabel* m_speedLabel = nullptr;
    VideoRecorder* m_recorder = nullptr;
    QLabel* m_recordingLabel = nullptr;  ///< "● REC" in the status bar while recording

    QLabel* m_timeLabel = nullptr;
    QLabel* m_rtLabel = nullptr;
    QLabel* m_frameLabel = nullptr;
    QLabel* m_modelLabel = nullptr;
    QLabel* m_recordsNote = nullptr;
    std::pair<int, int> m_problemCounts{-1, 0};  ///< errors and warnings of the last check (−1: none yet)
    QTimer* m_pollTimer = nullptr;
    quint64 m_shownSerial = 0;
    std::shared_ptr<const Snapshot> m_shown;  ///< the snapshot the view shows
    long m_posesSent = 0;  ///< poses the sliders sent to the runner since its last reset (Snapshot::poseEdits)
    QElapsedTimer m_labelClock;  ///< since the status bar's figures were last set
    long m_labelStep = -1;       ///< the step they show
    bool m_labelRunning = false;
    OverrunMeter m_overruns;    ///< the late steps of the last seconds, for the status bar
    QElapsedTimer m_wallClock;  ///< its clock
};

}  // namespace studio
