#include "ide/studio/app/main_window.h"

#include "ide/studio/app/menu_items.h"

#include "ide/studio/dialogs/inertia_dialog.h"
#include "ide/studio/editor/editor_panel.h"
#include "ide/studio/plots/plot_panel.h"
#include "ide/studio/sim/hydraulic_panel.h"
#include "ide/studio/sim/keyboard_input.h"
#include "ide/studio/station/live_state.h"
#include "ide/studio/station/station_page.h"
#include "ide/studio/train/pin_dialog.h"
#include "ide/studio/train/train_page.h"
#include "ide/studio/train/tutorial_runner.h"
#include "trainer/input/keyboard_device.h"
#include "trainer/station/profile_store.h"
#include "trainer/station/station.h"
#include "ide/studio/sim/simulation_runner.h"
#include "ide/studio/tree/joint_sliders.h"
#include "ide/studio/tree/model_tree.h"
#include "ide/studio/view/scene_file.h"
#include "ide/studio/view/viewport.h"
#include "ide/studio/view/viewport_layout.h"
#include "ide/i18n/language.h"
#include "ide/paths/paths.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QShortcut>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

namespace studio {

namespace {

constexpr int kMaxRecent = 8;

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_runner(std::make_unique<SimulationRunner>()),
      m_tutorialRunner(std::make_unique<TutorialRunner>())
{
    setObjectName("MainWindow");
    // the operator's station: its input thread reads every device (the keyboard, SDL
    // joysticks, serial consoles) and writes the mapped commands to the solver thread
    // (during a live attempt in the Train workspace, to the tutorial's)
    m_station = std::make_unique<trainer::Station>(
        [runner = m_runner.get(), tutorial = m_tutorialRunner.get()](std::span<const double> u) {
            if (tutorial->wantsCommands()) tutorial->setCommands(u);
            else runner->setCommands(u);
        });
    m_station->start(qEnvironmentVariableIntValue("PADROB_NO_JOYSTICKS") == 0);
    m_stationPage = new StationPage(m_station.get());
    connect(m_stationPage, &StationPage::profileChanged, this, [this](const trainer::StationProfile& p) {
        if (!p.name.isEmpty() && (m_stationPage->isUserProfile() || m_stationPage->isShippedProfile()))
            QSettings().setValue("station/profile/" + trainer::ProfileStore::modelKey(m_stationPage->modelPath()), p.name);
    });
    buildWorkspaces();
    buildMenus();

    // status bar: simulated time, real-time factor and overruns, frame time, model
    m_timeLabel = new QLabel;
    m_timeLabel->setObjectName("TimeLabel");
    m_rtLabel = new QLabel;
    m_rtLabel->setObjectName("RealTimeLabel");
    m_wallClock.start();
    m_frameLabel = new QLabel;
    m_frameLabel->setObjectName("FrameLabel");
    m_modelLabel = new QLabel;
    m_modelLabel->setObjectName("ModelLabel");
    statusBar()->addPermanentWidget(m_modelLabel);
    statusBar()->addPermanentWidget(m_timeLabel);
    statusBar()->addPermanentWidget(m_rtLabel);
    statusBar()->addPermanentWidget(m_frameLabel);
    // the trainee records at start-up: attempts kept in pending files were imported, or
    // the records cannot be opened (training goes on without them)
    // (a normal status bar widget: the passing messages, e.g. the model applied, hide it
    // only while they last; it goes after two minutes)
    if (!recordsNoteText().isEmpty()) {
        m_recordsNote = new QLabel(recordsNoteText());
        m_recordsNote->setObjectName("RecordsNote");
        statusBar()->addWidget(m_recordsNote, 1);
        QTimer::singleShot(120000, m_recordsNote, &QLabel::hide);
    }

    // the keyboard is a station device like any other
    m_keyboardDevice = std::make_shared<trainer::KeyboardDevice>(KeyboardInput::pairNames());
    m_station->post([device = m_keyboardDevice](trainer::StationEngine& e) { e.addDevice(device); });
    m_keyboard = new KeyboardInput(m_runner.get(), this);
    m_keyboard->setDevice(m_keyboardDevice);
    m_keyboard->attachTo(m_viewports);
    m_keyboard->attachTo(m_trainPage->attemptViewport());
    // an attempt: the Model workspace's simulation pauses, the station drives the tutorial's model
    connect(m_trainPage, &TrainPage::attemptStarted, this, [this](std::shared_ptr<const trainer::Tutorial> t) {
        m_runner->pause();
        const QList<trainer::DriveInfo> drives = trainer::drivesOf(*t->model);
        const int nb = t->model->nb;
        m_station->post([nb, drives](trainer::StationEngine& e) { e.setDrives(nb, drives); });
    });
    connect(m_trainPage, &TrainPage::attemptEnded, this, [this] {
        if (!m_bundle) return;
        const QList<trainer::DriveInfo> drives = trainer::drivesOf(*m_bundle->model);
        const int nb = m_bundle->model->nb;
        m_station->post([nb, drives](trainer::StationEngine& e) { e.setDrives(nb, drives); });
    });
    auto* leaveKiosk = new QShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F12), this);
    leaveKiosk->setContext(Qt::ApplicationShortcut);
    connect(leaveKiosk, &QShortcut::activated, this, &MainWindow::requestLeaveKiosk);
    m_hud = new QLabel(m_viewports);
    m_hud->setObjectName("Hud");
    m_hud->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_hud->setStyleSheet("QLabel#Hud { background: rgba(20, 24, 28, 190); color: white; border-radius: 6px; "
                         "padding: 8px 12px; font-size: 15pt; }");
    m_hud->move(12, 12);
    m_hud->hide();
    m_viewports->addOverlay(m_hud);  // the 3D views' native windows would hide it: drawn in their frames
    m_plots->setRunner(m_runner.get());
    m_hydraulics->setRunner(m_runner.get());
    // Ctrl + drag in the 3D view pushes a body: the target goes to the solver thread
    connect(m_viewports, &ViewportLayout::pushMoved, m_runner.get(), &SimulationRunner::setPush);
    connect(m_viewports, &ViewportLayout::pushReleased, m_runner.get(), &SimulationRunner::clearPush);
    // the hydraulics dock comes with a model that has pumps and goes with one that has none
    connect(m_hydraulics, &HydraulicPanel::modelChanged, this, [this](bool fluid) {
        if (int(fluid) == m_fluidPower || !m_runner->bundle()) return;
        m_fluidPower = int(fluid);
        m_hydraulicsDock->setVisible(fluid);
    });
    connect(m_plots, &PlotPanel::exportFailed, this,
            [this](const QString& message) { QMessageBox::warning(this, tr("Export"), message); });

    connect(m_runner.get(), &SimulationRunner::failed, this, &MainWindow::onSimulationFailed);
    connect(m_runner.get(), &SimulationRunner::stateChanged, this, [this](bool running) {
        m_runAction->setEnabled(!running);
        m_pauseAction->setEnabled(running);
        m_stepAction->setEnabled(!running);
        m_sliders->setEnabled(!running);
    });

    m_pollTimer = new QTimer(this);
    m_pollTimer->setInterval(16);
    connect(m_pollTimer, &QTimer::timeout, this, &MainWindow::poll);
    m_pollTimer->start();

    resize(1600, 1000);
    restoreLayout();
    retranslate();
}

QString MainWindow::recordsNoteText() const
{
    if (m_trainPage->importedPending() > 0)
        return tr("%n attempt(s) kept while the trainee records could not be written were added to them.", nullptr,
                  m_trainPage->importedPending());
    if (!m_trainPage->records()) return tr("The trainee records cannot be opened: %1").arg(m_trainPage->recordsProblem());
    return {};
}

void MainWindow::updateModelLabel()
{
    if (!m_modelLabel) return;
    const auto [errors, warnings] = m_problemCounts;
    m_modelLabel->setText(errors < 0 ? QString() : EditorPanel::problemCounts(errors, warnings));
}

MainWindow::~MainWindow()
{
    m_pollTimer->stop();
    delete m_stationPage;  // it talks to the station: before the station goes
    m_stationPage = nullptr;
    delete m_trainPage;  // it talks to the tutorial runner
    m_trainPage = nullptr;
    m_station->stop();  // no more commands to the runner
    m_runner->pause();
}

// ---------------------------------------------------------------- layout

void MainWindow::buildWorkspaces()
{
    m_workspaces = new QStackedWidget;

    // Model: an inner main window, so the docks belong to this workspace
    m_modelSpace = new QMainWindow;
    m_modelSpace->setObjectName("ModelWorkspace");
    m_modelSpace->setDockNestingEnabled(true);
    m_viewports = new ViewportLayout;
    // over the 3D view, the bar that says the editor's text is not applied (updateUnappliedBar)
    auto* centre = new QWidget;
    auto* centreLayout = new QVBoxLayout(centre);
    centreLayout->setContentsMargins(0, 0, 0, 0);
    centreLayout->setSpacing(0);
    m_unappliedBar = new QWidget;
    m_unappliedBar->setObjectName("UnappliedBar");
    m_unappliedBar->setAttribute(Qt::WA_StyledBackground);
    m_unappliedBar->setStyleSheet(
        QStringLiteral("QWidget#UnappliedBar { background: #fff3cd; border-bottom: 1px solid #e0c068; } "
                       "QWidget#UnappliedBar QLabel { color: #3d2e00; }"));
    m_unappliedText = new QLabel;
    m_unappliedText->setObjectName("UnappliedText");
    m_unappliedText->setWordWrap(true);
    m_unappliedApply = new QPushButton;
    m_unappliedApply->setObjectName("UnappliedApply");
    m_unappliedRevert = new QPushButton;
    m_unappliedRevert->setObjectName("UnappliedRevert");
    auto* barLayout = new QHBoxLayout(m_unappliedBar);
    barLayout->setContentsMargins(8, 4, 8, 4);
    barLayout->addWidget(m_unappliedText, 1);
    barLayout->addWidget(m_unappliedApply);
    barLayout->addWidget(m_unappliedRevert);
    m_unappliedBar->hide();
    centreLayout->addWidget(m_unappliedBar);
    centreLayout->addWidget(m_viewports, 1);
    m_modelSpace->setCentralWidget(centre);

    // (the texts: retranslate())
    auto dock = [this](const QString& name, QWidget* widget, Qt::DockWidgetArea area) {
        auto* d = new QDockWidget(m_modelSpace);
        d->setObjectName(name);
        d->setWidget(widget);
        m_modelSpace->addDockWidget(area, d);
        m_docks.append(d);
        return d;
    };
    m_tree = new ModelTree;
    m_sliders = new JointSliders;
    m_editor = new EditorPanel;
    m_plots = new PlotPanel;
    m_treeDock = dock("ModelTreeDock", m_tree, Qt::LeftDockWidgetArea);
    m_sliderDock = dock("JointSlidersDock", m_sliders, Qt::LeftDockWidgetArea);
    m_modelSpace->tabifyDockWidget(m_treeDock, m_sliderDock);
    m_treeDock->raise();
    m_editorDock = dock("EditorDock", m_editor, Qt::RightDockWidgetArea);
    m_plotsDock = dock("PlotsDock", m_plots, Qt::BottomDockWidgetArea);
    m_hydraulics = new HydraulicPanel;
    m_hydraulicsDock = dock("HydraulicsDock", m_hydraulics, Qt::BottomDockWidgetArea);
    m_modelSpace->splitDockWidget(m_plotsDock, m_hydraulicsDock, Qt::Horizontal);
    m_hydraulicsDock->hide();  // (until a model with pumps)
    m_modelSpace->resizeDocks({m_treeDock, m_editorDock}, {320, 560}, Qt::Horizontal);
    m_modelSpace->resizeDocks({m_plotsDock, m_hydraulicsDock}, {900, 560}, Qt::Horizontal);
    m_modelSpace->resizeDocks({m_plotsDock}, {240}, Qt::Vertical);

    m_workspaces->addWidget(m_modelSpace);
    m_workspaces->addWidget(m_stationPage);
    m_trainPage = new TrainPage(m_tutorialRunner.get(), m_station.get());
    m_workspaces->addWidget(m_trainPage);
    setCentralWidget(m_workspaces);

    // the mode bar
    auto* modes = new QToolBar;
    m_modeBar = modes;
    modes->setObjectName("WorkspaceBar");
    modes->setMovable(false);
    modes->setToolButtonStyle(Qt::ToolButtonTextOnly);
    addToolBar(Qt::LeftToolBarArea, modes);
    m_workspaceGroup = new QActionGroup(this);
    for (int i = 0; i < 3; ++i) {
        QAction* a = modes->addAction(QString());
        a->setCheckable(true);
        a->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(Qt::Key_1 + i)));
        m_workspaceGroup->addAction(a);
        m_workspaceActions.append(a);
        connect(a, &QAction::triggered, this, [this, i] { setWorkspace(static_cast<Workspace>(i)); });
    }
    m_workspaceActions.front()->setChecked(true);

    // wiring between the parts
    connect(m_editor, &EditorPanel::applied, this, [this](std::shared_ptr<const ModelBundle> b) { applyBundle(b); });
    connect(m_editor, &EditorPanel::modificationChanged, this, [this](bool) { updateTitle(); });
    connect(m_editor, &EditorPanel::diagnosticsChanged, this, [this](int errors, int warnings) {
        m_problemCounts = {errors, warnings};
        if (errors > 0) m_keptPose.reset();  // a reload with errors is not applied: no pose to carry
        updateModelLabel();
    });
    connect(m_editor, &EditorPanel::fileChangedOnDisk, this, &MainWindow::onFileChangedOnDisk);
    connect(m_editor, &EditorPanel::reloadRequested, this, &MainWindow::reloadFromDisk);
    connect(m_editor, &EditorPanel::unappliedChanged, this, &MainWindow::updateUnappliedBar);
    connect(m_unappliedApply, &QPushButton::clicked, m_editor, &EditorPanel::apply);
    connect(m_unappliedRevert, &QPushButton::clicked, m_editor, &EditorPanel::revertToApplied);
    connect(m_tree, &ModelTree::bodySelected, this, [this](int body) { m_viewports->setHighlight(body, -1); });
    connect(m_tree, &ModelTree::jointSelected, this, [this](int joint) { m_viewports->setHighlight(-1, joint); });
    connect(m_tree, &ModelTree::sourceSelected, this, [this](int line) { m_editor->goToLine(line, 1); });
    connect(m_viewports, &ViewportLayout::problem, this, [this](const QString& message) {
        // e.g. a mesh that failed to load: drawn as a placeholder, and said why
        statusBar()->showMessage(message, 15000);
        m_viewports->setToolTip(message);
    });
    // the sliders are the simulation's state: a pose set by hand goes to the solver thread,
    // and the view shows the snapshot of it (poll())
    connect(m_sliders, &JointSliders::poseEdited, this, &MainWindow::sendPose);
}

void MainWindow::setWorkspace(Workspace w)
{
    if (m_kiosk && w != Workspace::Train) return;
    if (w != Workspace::Train) m_trainPage->stopAttempt();  // an attempt is not left running unseen
    const int i = static_cast<int>(w);
    m_workspaces->setCurrentIndex(i);
    m_workspaceActions[i]->setChecked(true);
}

MainWindow::Workspace MainWindow::workspace() const
{
    return static_cast<Workspace>(m_workspaces->currentIndex());
}

void MainWindow::setKioskMode(bool on)
{
    if (on == m_kiosk) return;
    if (on) {
        setWorkspace(Workspace::Train);
        m_kiosk = true;
    } else {
        m_kiosk = false;
    }
    m_trainPage->setKiosk(on);
    menuBar()->setVisible(!on);
    m_modeBar->setVisible(!on);
    statusBar()->setVisible(!on);
    for (QAction* a : m_workspaceActions) a->setEnabled(!on);
    for (QAction* a : menuBar()->actions()) a->setEnabled(!on);
    if (on) showFullScreen();
    else showNormal();
}

void MainWindow::requestLeaveKiosk()
{
    if (!m_kiosk) return;
    if (PinDialog::trainerPin().isEmpty()) return setKioskMode(false);
    if (findChild<PinDialog*>("KioskPinDialog")) return;  // already asking
    auto* dialog = new PinDialog(tr("Leave Trainer Mode"), tr("Trainer's PIN:"), this);
    dialog->setObjectName("KioskPinDialog");
    connect(dialog, &PinDialog::unlocked, this, [this] { setKioskMode(false); });
    dialog->open();
}

// ---------------------------------------------------------------- files

void MainWindow::openInitial(const QString& path)
{
    offerRecovery();
    if (!m_editor->filePath().isEmpty() || m_editor->isModified()) return;  // a recovered model
    // the model given, else the file opened last, else the bundled liner manipulator
    QString initial = path;
    if (initial.isEmpty()) {
        const QString last = QSettings().value("recentFiles").toStringList().value(0);
        initial = !last.isEmpty() && QFileInfo(last).isFile() ? last : paths::defaultModel();
    }
    if (openFile(initial)) return;
    if (path.isEmpty() && initial != paths::defaultModel() && openFile(paths::defaultModel())) return;
    m_editor->newModel();
}

bool MainWindow::openFile(const QString& path)
{
    QString error;
    if (!m_editor->open(path, &error)) {
        QMessageBox::warning(this, tr("Open Model"), tr("Cannot open %1:\n%2").arg(QDir::toNativeSeparators(path), error));
        return false;
    }
    addRecent(QFileInfo(path).absoluteFilePath());
    m_editor->apply();  // a model with errors is not applied (the problems list shows them)
    updateTitle();
    QTimer::singleShot(0, this, [this] { m_viewports->fitAll(); });
    return true;
}

bool MainWindow::loadScene(const QString& path)
{
    const SceneFile scene = loadSceneFile(path);
    if (!scene.bundle) {
        statusBar()->showMessage(scene.error.section(QLatin1Char('\n'), 0, 0), 15000);
        // not modal: the app carries on without the scene (and a test is not blocked)
        auto* box = new QMessageBox(QMessageBox::Warning, tr("Load Scene"),
                                    tr("%1\n\nThe 3D view goes on without this scene.").arg(scene.error),
                                    QMessageBox::Ok, this);
        box->setObjectName("SceneProblemBox");
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->setWindowModality(Qt::NonModal);
        box->show();
        return false;
    }
    m_scenePath = QFileInfo(path).absoluteFilePath();
    m_viewports->setScene(scene.bundle);
    m_sceneBundle = scene.bundle;
    if (m_applied && m_applied->model->contact) applyInScene();  // its solids touch the scene's
    QSettings().setValue("scene/last", m_scenePath);
    statusBar()->showMessage(scene.note.isEmpty() ? tr("Scene: %1").arg(QFileInfo(path).fileName())
                                                  : tr("Scene: %1. %2").arg(QFileInfo(path).fileName(), scene.note),
                             6000);
    return true;
}

void MainWindow::clearScene()
{
    m_scenePath.clear();
    m_viewports->setScene(nullptr);
    m_sceneBundle.reset();
    if (m_applied && m_applied->model->contact) applyInScene();
    QSettings().remove("scene/last");
}

bool MainWindow::restoreScene()
{
    const QString path = QSettings().value("scene/last").toString();
    if (path.isEmpty()) return false;
    const SceneFile scene = loadSceneFile(path);
    if (!scene.bundle) {
        QSettings().remove("scene/last");
        const QString why = scene.error.section(QLatin1Char('\n'), 0, 0);
        statusBar()->showMessage(tr("The scene used last is not drawn: %1").arg(why), 15000);
        return false;
    }
    m_scenePath = QFileInfo(path).absoluteFilePath();
    m_viewports->setScene(scene.bundle);
    m_sceneBundle = scene.bundle;
    if (m_applied && m_applied->model->contact) applyInScene();
    return true;
}

void MainWindow::newModel()
{
    if (!maybeSave()) return;
    m_editor->newModel();
    // a new model is not put in the last model's scene (it comes back at the next start)
    m_scenePath.clear();
    m_viewports->setScene(nullptr);
    m_sceneBundle.reset();
    if (m_applied && m_applied->model->contact) applyInScene();
    updateTitle();
}

void MainWindow::openDialog()
{
    if (!maybeSave()) return;
    const QString start = m_editor->filePath().isEmpty() ? paths::modelsDir() : QFileInfo(m_editor->filePath()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Model"), start, tr("Padrob models (*.pad);;All files (*)"));
    if (!path.isEmpty()) openFile(path);
}

bool MainWindow::save()
{
    if (m_editor->filePath().isEmpty()) return saveAs();
    QString error;
    if (!m_editor->save(&error)) {
        QMessageBox::warning(this, tr("Save Model"), tr("The model was not saved:\n%1\n\nUse Save As to choose another place.").arg(error));
        return false;
    }
    updateTitle();
    return true;
}

bool MainWindow::saveAs()
{
    const QString start = m_editor->filePath().isEmpty() ? QDir::homePath() + "/model.pad" : m_editor->filePath();
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Model As"), start, tr("Padrob models (*.pad)"));
    if (path.isEmpty()) return false;
    QString error;
    if (!m_editor->saveAs(path, &error)) {
        QMessageBox::warning(this, tr("Save Model"), tr("The model was not saved:\n%1").arg(error));
        return false;
    }
    addRecent(path);
    updateTitle();
    return true;
}

bool MainWindow::maybeSave()
{
    if (!m_editor->isModified()) return true;
    const auto answer = QMessageBox::question(
        this, tr("Unsaved Changes"), tr("The model has unsaved changes. Save them?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Save) return save();
    return true;
}

void MainWindow::updateRecentMenu()
{
    m_recentMenu->clear();
    const QStringList recent = QSettings().value("recentFiles").toStringList();
    for (const QString& path : recent) {
        m_recentMenu->addAction(QDir::toNativeSeparators(path), this, [this, path] {
            if (maybeSave()) openFile(path);
        });
    }
    m_recentMenu->setEnabled(!recent.isEmpty());
}

void MainWindow::addRecent(const QString& path)
{
    QSettings settings;
    QStringList recent = settings.value("recentFiles").toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue("recentFiles", recent);
    updateRecentMenu();
}

void MainWindow::updateTitle()
{
    const QString path = m_editor->filePath();
    const QString name = path.isEmpty() ? tr("Untitled") : QFileInfo(path).fileName();
    setWindowTitle(name + (m_editor->isModified() ? "*" : "") + " — Padrob Studio");
}

void MainWindow::offerRecovery()
{
    const QList<EditorPanel::Recovery> copies = EditorPanel::recoveryFiles();
    for (const EditorPanel::Recovery& r : copies) {
        const QString what = r.originalPath.isEmpty() ? tr("an untitled model") : QDir::toNativeSeparators(r.originalPath);
        const auto answer = QMessageBox::question(
            this, tr("Recover Unsaved Changes"),
            tr("Padrob Studio was closed with unsaved changes to %1 (recovery copy of %2). Restore them?")
                .arg(what, QLocale().toString(r.saved, QLocale::ShortFormat)),
            QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
        if (answer == QMessageBox::Yes) {
            m_editor->restoreRecovery(r);
            m_editor->apply();
            updateTitle();
            return;
        }
        EditorPanel::discardRecovery(r);
    }
}


// ---------------------------------------------------------------- the model and the simulation

void MainWindow::applyBundle(std::shared_ptr<const ModelBundle> bundle)
{
    if (!bundle) return;
    m_applied = std::move(bundle);
    applyInScene();
    restoreKeptPose();
}

void MainWindow::applyInScene()
{
    if (!m_applied) return;
    solver::Diagnostics diagnostics;
    std::shared_ptr<const ModelBundle> bundle = bundleInScene(m_applied, m_sceneBundle.get(), diagnostics);
    if (!bundle) {
        // the scene's solids cannot be taken in (a mesh that cannot serve): the model runs
        // without them
        bundle = m_applied;
        statusBar()->showMessage(tr("The scene's solids cannot be taken into the model's contacts (a shape that cannot "
                                    "serve): the model runs without touching them"),
                                 15000);
    }
    m_bundle = bundle;
    m_runner->setBundle(bundle);
    m_viewports->setBundle(bundle);
    m_tree->setBundle(bundle);
    m_sliders->setBundle(bundle);
    setStationModel(bundle);
    m_shownSerial = bundle->serial;
    m_shown.reset();
    m_posesSent = 0;
    m_labelStep = -1;
    m_labelClock.invalidate();
    statusBar()->showMessage(tr("Model applied: %n bodies", nullptr, bundle->model->nb), 4000);
}

void MainWindow::run()
{
    if (!m_bundle) return;
    m_runner->start();
}

void MainWindow::pause() { m_runner->pause(); }

void MainWindow::step() { m_runner->stepOnce(); }

void MainWindow::reset()
{
    m_runner->reset();  // the sliders follow its snapshot (poll())
    m_shown.reset();
    m_posesSent = 0;
    m_labelStep = -1;
    m_labelClock.invalidate();
}

void MainWindow::setSpeed(double speed) { m_runner->setSpeed(speed); }

void MainWindow::poll()
{
    const std::shared_ptr<const Snapshot> s = m_runner->latest();
    // the status bar's figures ten times a second while running: at every frame, the
    // status bar was laid out and painted 60 times a second, on the thread that draws
    const bool labels = !m_labelClock.isValid() || m_labelClock.elapsed() >= 100 || (s && !s->running);
    if (s && s->bundle == m_bundle && s != m_shown) {
        m_shown = s;
        m_viewports->setSnapshot(s);
        // the sliders show the simulated state (paused: each one; running: ten a second),
        // once it holds every pose they sent (not an older one while a drag goes on)
        if (s->poseEdits >= m_posesSent && (!s->running || labels)) m_sliders->showState(s->theta);
    }
    if (s && s->bundle == m_bundle && labels && (s->step != m_labelStep || s->running != m_labelRunning)) {
        m_labelStep = s->step;
        m_labelRunning = s->running;
        m_timeLabel->setText(tr("t = %1 s").arg(QLocale().toString(s->t, 'f', 3)));
        if (s->running) m_overruns.add(m_wallClock.elapsed() * 1e-3, s->step, s->overruns);
        const QString late = m_overruns.text();
        m_rtLabel->setText(s->running ? tr("real time ×%1, %2 µs/step").arg(QLocale().toString(s->realTimeFactor, 'f', 2),
                                                                           QLocale().toString(s->stepMicros, 'f', 0)) +
                                            (late.isEmpty() ? QString() : QStringLiteral(", ") + late)
                                      : tr("paused"));
        m_rtLabel->setToolTip(m_overruns.toolTip());
    }
    if (labels) {
        m_labelClock.start();
        m_frameLabel->setText(tr("frame %1 ms").arg(QLocale().toString(m_viewports->frameMillis(), 'f', 1)));
    }
    updateHud();
}

void MainWindow::updateHud()
{
    const std::shared_ptr<const trainer::StationState> st = m_station->latest();
    QStringList lines;
    if (st) {
        if (const QString bank = hudBankLine(*st); !bank.isEmpty()) lines << bank;
        for (const QString& w : hudWarnings(*st))
            lines << QStringLiteral("<span style='color:#ffc04d'>⚠ %1</span>").arg(w.toHtmlEscaped());
    }
    const QString text = lines.join("<br>");
    if (text == m_hudText) return;
    m_hudText = text;
    m_hud->setText(text);
    m_hud->setVisible(!text.isEmpty());
    // one line each when they fit, wrapped to the viewport's width when they do not
    const int room = std::max(200, m_viewports->width() - 24);
    m_hud->setWordWrap(false);
    m_hud->setMinimumWidth(0);
    m_hud->setMaximumWidth(QWIDGETSIZE_MAX);
    m_hud->adjustSize();
    if (m_hud->width() > room) {
        m_hud->setWordWrap(true);
        m_hud->setFixedWidth(room);
        m_hud->adjustSize();
    }
    m_hud->raise();
}

void MainWindow::setStationModel(const std::shared_ptr<const ModelBundle>& bundle)
{
    const QList<trainer::DriveInfo> drives = trainer::drivesOf(*bundle->model);
    const int nb = bundle->model->nb;
    m_station->post([nb, drives](trainer::StationEngine& e) { e.setDrives(nb, drives); });
    if (!bundle->filePath.isEmpty() && bundle->filePath == m_stationPage->modelPath()) {
        m_stationPage->setDrives(drives);  // an edit re-applied: the profile and its edits stay
        return;
    }
    const QString key = trainer::ProfileStore::modelKey(bundle->filePath);
    QString preferred = QSettings().value("station/profile/" + key).toString();
    if (preferred.isEmpty()) preferred = QStringLiteral("Gamepad");  // the common case on first start
    m_stationPage->setModel(bundle->filePath, drives, preferred);
}

void MainWindow::onSimulationFailed(const QString& message)
{
    statusBar()->showMessage(message);
    // not modal: the editor stays usable (and a test is not blocked)
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Simulation Stopped"),
                                tr("%1\n\nThe simulation is paused at the last good state; the editor stays usable. "
                                   "Reset to start again.").arg(message),
                                QMessageBox::Ok, this);
    box->setObjectName("SimulationStoppedBox");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::NonModal);
    box->show();
}

// ---------------------------------------------------------------- dialogs

void MainWindow::showInertiaDialog()
{
    if (!m_bundle) return;
    auto* dialog = new InertiaDialog(m_bundle, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setSourceText(m_editor->text());
    connect(dialog, &InertiaDialog::bLineReady, this, [this](int, const QString& line, int existingLine) {
        InertiaDialog::applyBLine(m_editor->editor(), existingLine, line);
    });
    // "In the file" follows the editor (a Replace, an edit), a moment after the typing
    auto* follow = new QTimer(dialog);
    follow->setSingleShot(true);
    follow->setInterval(250);
    connect(follow, &QTimer::timeout, dialog, [this, dialog] { dialog->setSourceText(m_editor->text()); });
    connect(m_editor->editor()->document(), &QTextDocument::contentsChanged, follow, qOverload<>(&QTimer::start));
    dialog->show();
}

// ---------------------------------------------------------------- settings and close

void MainWindow::restoreLayout()
{
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
    m_modelSpace->restoreState(settings.value("window/modelWorkspace").toByteArray());
}

void MainWindow::saveLayout()
{
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    settings.setValue("window/modelWorkspace", m_modelSpace->saveState());
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!maybeSave() || !m_stationPage->maybeDiscard()) {
        event->ignore();
        return;
    }
    m_runner->pause();
    if (!m_kiosk) saveLayout();
    m_editor->discardOwnRecovery();
    event->accept();
}

}  // namespace studio
