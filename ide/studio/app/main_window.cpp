#include "ide/studio/app/main_window.h"

#include "ide/studio/dialogs/inertia_dialog.h"
#include "ide/studio/editor/editor_panel.h"
#include "ide/studio/plots/plot_panel.h"
#include "ide/studio/sim/hydraulic_panel.h"
#include "ide/studio/sim/keyboard_input.h"
#include "ide/studio/station/station_page.h"
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
#include <QInputDialog>
#include <QLineEdit>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QShortcut>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

namespace studio {

namespace {

constexpr int kMaxRecent = 8;

}  // namespace

// The menus and actions whose texts retranslate() sets (built once by buildMenus()).
struct MainWindow::MenuItems {
    QMenu *file = nullptr, *examples = nullptr, *edit = nullptr, *view = nullptr, *camera = nullptr, *scene = nullptr,
          *screens = nullptr, *simulation = nullptr, *speed = nullptr, *settings = nullptr, *language = nullptr,
          *lighting = nullptr, *help = nullptr;
    QAction *newModel = nullptr, *open = nullptr, *save = nullptr, *saveAs = nullptr, *quit = nullptr;
    QAction *undo = nullptr, *redo = nullptr, *apply = nullptr, *inertia = nullptr;
    QAction *fitAll = nullptr, *loadScene = nullptr, *noScene = nullptr, *frames = nullptr, *contacts = nullptr, *separate = nullptr;
    QAction *keyboard = nullptr, *reference = nullptr, *about = nullptr;
    std::vector<std::pair<QAction*, DisplayMode>> displayModes;
    std::vector<std::pair<QAction*, QString>> cameras;  ///< with the camera's name (Viewport::cameraNames)
    std::vector<std::pair<QAction*, int>> screenCounts;
    std::vector<std::pair<QAction*, double>> speeds;
    std::vector<std::pair<QAction*, QString>> languages;  ///< with the language's code
    std::vector<std::pair<QAction*, Viewport::Lighting>> lightings;
};

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
    m_modelSpace->setCentralWidget(m_viewports);

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
        updateModelLabel();
    });
    connect(m_editor, &EditorPanel::fileChangedOnDisk, this, &MainWindow::onFileChangedOnDisk);
    connect(m_tree, &ModelTree::bodySelected, this, [this](int body) { m_viewports->setHighlight(body, -1); });
    connect(m_tree, &ModelTree::jointSelected, this, [this](int joint) { m_viewports->setHighlight(-1, joint); });
    connect(m_tree, &ModelTree::sourceSelected, this, [this](int line) { m_editor->goToLine(line, 1); });
    connect(m_viewports, &ViewportLayout::problem, this, [this](const QString& message) {
        // e.g. a mesh that failed to load: drawn as a placeholder, and said why
        statusBar()->showMessage(message, 15000);
        m_viewports->setToolTip(message);
    });
    connect(m_sliders, &JointSliders::posesChanged, this,
            [this](const std::vector<Eigen::Isometry3d>& poses) { m_viewports->setPoses(poses); });
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
    const QString pin = QSettings().value("trainer/pin").toString();
    if (pin.isEmpty()) return setKioskMode(false);
    if (findChild<QInputDialog*>("KioskPinDialog")) return;  // already asking
    auto* dialog = new QInputDialog(this);
    dialog->setObjectName("KioskPinDialog");
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Leave Trainer Mode"));
    dialog->setLabelText(tr("Trainer's PIN:"));
    dialog->setTextEchoMode(QLineEdit::Password);
    connect(dialog, &QInputDialog::textValueSelected, this, [this, pin](const QString& typed) {
        if (typed == pin) setKioskMode(false);
    });
    dialog->open();
}

void MainWindow::buildMenus()
{
    m_items = std::make_unique<MenuItems>();
    MenuItems& m = *m_items;
    // (the texts: retranslate())

    // File
    m.file = menuBar()->addMenu(QString());
    m.newModel = m.file->addAction(QString(), QKeySequence::New, this, &MainWindow::newModel);
    m.open = m.file->addAction(QString(), QKeySequence::Open, this, &MainWindow::openDialog);
    m.save = m.file->addAction(QString(), QKeySequence::Save, this, &MainWindow::save);
    m.saveAs = m.file->addAction(QString(), QKeySequence::SaveAs, this, &MainWindow::saveAs);
    m_recentMenu = m.file->addMenu(QString());
    m_recentMenu->setObjectName("RecentFilesMenu");
    m.examples = m.file->addMenu(QString());
    const QFileInfoList models = QDir(paths::modelsDir()).entryInfoList({"*.pad"}, QDir::Files, QDir::Name);
    for (const QFileInfo& f : models) {
        m.examples->addAction(f.completeBaseName(), this, [this, path = f.absoluteFilePath()] {
            if (maybeSave()) openFile(path);
        });
    }
    m.file->addSeparator();
    m.quit = m.file->addAction(QString(), QKeySequence::Quit, this, &QWidget::close);
    updateRecentMenu();

    // Edit
    m.edit = menuBar()->addMenu(QString());
    m.undo = m.edit->addAction(QString(), QKeySequence::Undo, this, [this] { m_editor->undo(); });
    m.redo = m.edit->addAction(QString(), QKeySequence::Redo, this, [this] { m_editor->redo(); });
    m.edit->addSeparator();
    m.apply = m.edit->addAction(QString(), QKeySequence(Qt::CTRL | Qt::Key_Return), this, [this] { m_editor->apply(); });
    m.inertia = m.edit->addAction(QString(), this, &MainWindow::showInertiaDialog);
    m.inertia->setObjectName("InertiaCalculatorAction");

    // View
    m.view = menuBar()->addMenu(QString());
    auto* modes = new QActionGroup(this);
    for (DisplayMode mode : {DisplayMode::Schematic, DisplayMode::Dressed, DisplayMode::Both}) {
        QAction* a = m.view->addAction(QString(), this, [this, mode] { m_viewports->setDisplayMode(mode); });
        a->setCheckable(true);
        a->setChecked(mode == DisplayMode::Dressed);
        modes->addAction(a);
        m.displayModes.emplace_back(a, mode);
    }
    m.view->addSeparator();
    m.camera = m.view->addMenu(QString());
    for (const QString& name : Viewport::cameraNames()) {
        m.cameras.emplace_back(m.camera->addAction(QString(), this, [this, name] { m_viewports->setCamera(name); }), name);
    }
    m.fitAll = m.view->addAction(QString(), QKeySequence(Qt::Key_F), this, [this] { m_viewports->fitAll(); });
    m.scene = m.view->addMenu(QString());
    m.scene->setObjectName("SceneMenu");
    m.loadScene = m.scene->addAction(QString(), this, [this] {
        const QString start = m_scenePath.isEmpty() ? paths::scenesDir() : QFileInfo(m_scenePath).absolutePath();
        const QString path = QFileDialog::getOpenFileName(this, tr("Load Scene"), start,
                                                          tr("Padrob models (*.pad);;All files (*)"));
        if (!path.isEmpty()) loadScene(path);
    });
    m.noScene = m.scene->addAction(QString(), this, &MainWindow::clearScene);
    m.frames = m.view->addAction(QString());
    m.frames->setCheckable(true);
    connect(m.frames, &QAction::toggled, this, [this](bool on) { m_viewports->setShowFrames(on); });
    m.contacts = m.view->addAction(QString());
    m.contacts->setCheckable(true);
    m.contacts->setObjectName(QStringLiteral("showContacts"));
    connect(m.contacts, &QAction::toggled, this, [this](bool on) { m_viewports->setShowContacts(on); });
    m.screens = m.view->addMenu(QString());
    auto* screenGroup = new QActionGroup(this);
    for (int n = 1; n <= 3; ++n) {
        QAction* a = m.screens->addAction(QString(), this, [this, n] {
            m_viewports->setSeparateWindows(false);
            m_viewports->setScreens(n);
        });
        a->setCheckable(true);
        a->setChecked(n == 1);
        screenGroup->addAction(a);
        m.screenCounts.emplace_back(a, n);
    }
    m.separate = m.screens->addAction(QString(), this, [this] {
        m_viewports->setScreens(3);
        m_viewports->setSeparateWindows(true);
    });
    m.separate->setCheckable(true);
    screenGroup->addAction(m.separate);
    m.view->addSeparator();
    for (QDockWidget* d : m_docks) m.view->addAction(d->toggleViewAction());  // (named after their docks)

    // Simulation
    m.simulation = menuBar()->addMenu(QString());
    m_runAction = m.simulation->addAction(QString(), QKeySequence(Qt::Key_F5), this, &MainWindow::run);
    m_pauseAction = m.simulation->addAction(QString(), QKeySequence(Qt::Key_F6), this, &MainWindow::pause);
    m_stepAction = m.simulation->addAction(QString(), QKeySequence(Qt::Key_F10), this, &MainWindow::step);
    m_resetAction = m.simulation->addAction(QString(), QKeySequence(Qt::CTRL | Qt::Key_R), this, &MainWindow::reset);
    m_pauseAction->setEnabled(false);
    m.speed = m.simulation->addMenu(QString());
    m_speedGroup = new QActionGroup(this);
    for (double s : {0.1, 0.25, 0.5, 1.0, 2.0, 4.0}) {
        QAction* a = m.speed->addAction(QString(), this, [this, s] { setSpeed(s); });
        a->setCheckable(true);
        a->setChecked(s == 1.0);
        m_speedGroup->addAction(a);
        m.speeds.emplace_back(a, s);
    }
    m.simulation->addSeparator();
    m.keyboard = m.simulation->addAction(QString(), this, &MainWindow::showKeyboardControls);

    // Settings ▸ Language: each language by its own name; the choice is remembered
    // (i18n::switchTo) and every window changes language at once (retranslate())
    m.settings = menuBar()->addMenu(QString());
    m.settings->setObjectName("SettingsMenu");
    m.language = m.settings->addMenu(QString());
    m.language->setObjectName("LanguageMenu");
    auto* languages = new QActionGroup(this);
    languages->setExclusive(true);
    for (const QString& code : i18n::languages()) {
        QAction* a = m.language->addAction(i18n::nativeName(code), this, [code] { i18n::switchTo(code); });
        a->setObjectName("Language_" + code);
        a->setCheckable(true);
        a->setChecked(code == i18n::current());
        languages->addAction(a);
        m.languages.emplace_back(a, code);
    }
    // Settings ▸ Lighting: where the 3D views compute their light (Viewport::setLighting);
    // remembered, and every view redrawn at once
    m.lighting = m.settings->addMenu(QString());
    m.lighting->setObjectName("LightingMenu");
    auto* lightings = new QActionGroup(this);
    lightings->setExclusive(true);
    for (Viewport::Lighting l : {Viewport::Lighting::Automatic, Viewport::Lighting::PerPixel,
                                 Viewport::Lighting::PerVertex}) {
        QAction* a = m.lighting->addAction(QString(), this, [l] {
            Viewport::setLighting(l);
            QSettings().setValue("view/lighting", Viewport::lightingName(l));
            for (QWidget* w : QApplication::allWidgets()) {
                if (auto* v = qobject_cast<Viewport*>(w)) v->renderNow();
            }
        });
        a->setObjectName("Lighting_" + Viewport::lightingName(l));
        a->setCheckable(true);
        a->setChecked(l == Viewport::lighting());
        lightings->addAction(a);
        m.lightings.emplace_back(a, l);
    }

    // Help
    m.help = menuBar()->addMenu(QString());
    m.reference = m.help->addAction(QString(), QKeySequence::HelpContents, this, &MainWindow::showLanguageReference);
    m.about = m.help->addAction(QString(), this, &MainWindow::showAbout);
}

void MainWindow::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        // the new language's locale (i18n::install made it the default) for every child
        // that has not set its own: spin boxes write 1,5 in Spanish
        setLocale(QLocale());
        retranslate();
    }
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslate()
{
    // the workspaces and the docks
    m_modeBar->setWindowTitle(tr("Workspaces"));
    const QString workspaceNames[] = {tr("Model"), tr("Station"), tr("Train")};
    for (int i = 0; i < m_workspaceActions.size(); ++i) m_workspaceActions[i]->setText(workspaceNames[i]);
    m_treeDock->setWindowTitle(tr("Model"));
    m_sliderDock->setWindowTitle(tr("Joints"));
    m_editorDock->setWindowTitle(tr("Editor"));
    m_plotsDock->setWindowTitle(tr("Plots"));
    m_hydraulicsDock->setWindowTitle(tr("Hydraulics"));

    // the menus
    MenuItems& m = *m_items;
    m.file->setTitle(tr("&File"));
    m.newModel->setText(tr("&New"));
    m.open->setText(tr("&Open…"));
    m.save->setText(tr("&Save"));
    m.saveAs->setText(tr("Save &As…"));
    m_recentMenu->setTitle(tr("&Recent Files"));
    m.examples->setTitle(tr("&Examples"));
    m.quit->setText(tr("&Quit"));
    m.edit->setTitle(tr("&Edit"));
    m.undo->setText(tr("&Undo"));
    m.redo->setText(tr("&Redo"));
    m.apply->setText(tr("&Apply Model"));
    m.inertia->setText(tr("&Inertia Calculator…"));
    m.view->setTitle(tr("&View"));
    for (const auto& [action, mode] : m.displayModes) {
        switch (mode) {
        case DisplayMode::Schematic: action->setText(tr("&Schematic")); break;
        case DisplayMode::Dressed: action->setText(tr("&Dressed")); break;
        case DisplayMode::Both: action->setText(tr("&Both")); break;
        }
    }
    m.camera->setTitle(tr("&Camera"));
    for (const auto& [action, name] : m.cameras) action->setText(Viewport::cameraLabel(name));
    m.fitAll->setText(tr("&Fit All"));
    m.scene->setTitle(tr("S&cene"));
    m.loadScene->setText(tr("&Load…"));
    m.noScene->setText(tr("&None"));
    m.frames->setText(tr("Body &Frames"));
    m.contacts->setText(tr("&Contacts"));
    m.contacts->setToolTip(tr("Show where solids touch (models with CONTACT): a red disc at each contact point, its "
                              "force as an orange arrow"));
    m.screens->setTitle(tr("&Screens"));
    for (const auto& [action, n] : m.screenCounts) action->setText(tr("%n Screen(s)", nullptr, n));
    m.separate->setText(tr("Three &Windows (three monitors)"));
    m.simulation->setTitle(tr("&Simulation"));
    m_runAction->setText(tr("&Run"));
    m_pauseAction->setText(tr("&Pause"));
    m_stepAction->setText(tr("&Step"));
    m_resetAction->setText(tr("R&eset"));
    m.speed->setTitle(tr("S&peed"));
    for (const auto& [action, s] : m.speeds) action->setText(QStringLiteral("×%1").arg(QLocale().toString(s)));
    m.keyboard->setText(tr("&Keyboard Controls…"));
    m.settings->setTitle(tr("Se&ttings"));
    m.language->setTitle(tr("&Language"));
    m.lighting->setTitle(tr("L&ighting"));
    for (const auto& [action, l] : m.lightings) {
        switch (l) {
        case Viewport::Lighting::Automatic:
            action->setText(tr("&Automatic: at the vertices on a software OpenGL, else at every pixel"));
            break;
        case Viewport::Lighting::PerPixel: action->setText(tr("At every &pixel (finer)")); break;
        case Viewport::Lighting::PerVertex: action->setText(tr("At the &vertices (faster)")); break;
        }
        action->setChecked(l == Viewport::lighting());
    }
    for (const auto& [action, code] : m.languages) action->setChecked(code == i18n::current());
    m.help->setTitle(tr("&Help"));
    m.reference->setText(tr("Model &Language Reference"));
    m.about->setText(tr("&About Padrob Studio"));

    // the status bar and the title (a passing message in the old language goes)
    statusBar()->clearMessage();
    if (m_recordsNote) m_recordsNote->setText(recordsNoteText());
    updateModelLabel();
    // the time and the real-time factor again, in the new language
    m_shownStep = m_labelStep = -1;
    m_labelClock.invalidate();
    if (m_timeLabel) poll();
    updateTitle();
}

void MainWindow::showKeyboardControls()
{
    // what the station does with the keys: the profile's own keyboard mappings, or
    // the pairs on the drives in order when the profile does not map the keyboard
    QString text = "<table>";
    const QStringList pairs = KeyboardInput::pairNames();
    bool mapped = false;
    if (const auto st = m_station->latest()) {
        for (const trainer::MappingState& ms : st->mappings) {
            if (ms.mapping.device != QLatin1String("keyboard") || ms.mapping.axis >= pairs.size()) continue;
            mapped = true;
            QString drive = tr("C %1").arg(ms.mapping.drive);
            for (const trainer::DriveInfo& d : st->drives)
                if (d.jointId == ms.mapping.drive) drive = d.label();
            if (ms.bank >= 0) drive = tr("%1 (%2)", "a drive and its bank").arg(drive, st->bankNames.value(ms.bank));
            if (ms.mapping.sign < 0) drive = tr("%1, reversed", "a drive the key moves the other way").arg(drive);
            text += "<tr><td><b>" + pairs[ms.mapping.axis].toHtmlEscaped() + "</b></td><td>" + drive.toHtmlEscaped() +
                    "</td></tr>";
        }
    }
    if (!mapped) {
        for (const KeyBinding& b : m_keyboard->bindings()) {
            const QString joint = b.jointName.isEmpty() ? tr("C %1").arg(b.jointId)
                                                        : tr("C %1 %2").arg(QString::number(b.jointId), b.jointName);
            text += "<tr><td><b>" + b.keysText().toHtmlEscaped() + "</b></td><td>" + joint.toHtmlEscaped() +
                    "</td></tr>";
        }
    }
    text += "</table>";
    QMessageBox::information(
        this, tr("Keyboard Controls"),
        QStringLiteral("<p>%1</p>%2<p>%3</p>")
            .arg(tr("With the 3D view focused, hold a key to open a valve:"), text,
                 tr("Mouse in the 3D view: left drag orbits, middle drag or Shift + left drag pans, the wheel "
                    "zooms, a double click frames the model. Ctrl + left drag on a body pushes it while the "
                    "simulation runs (a spring pulls the point you grabbed toward the cursor); release to let go.")));
}

// ---------------------------------------------------------------- files

void MainWindow::openInitial(const QString& path)
{
    offerRecovery();
    if (!m_editor->filePath().isEmpty() || m_editor->isModified()) return;  // a recovered model
    const QString initial = path.isEmpty() ? paths::defaultModel() : path;
    if (!openFile(initial)) m_editor->newModel();
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

void MainWindow::onFileChangedOnDisk(const QString& path, bool deleted)
{
    if (deleted) {
        statusBar()->showMessage(tr("%1 was deleted or moved on disk; the text in the editor is kept — save it to "
                                    "write it again.").arg(QDir::toNativeSeparators(path)));
        return;
    }
    const QString question = m_editor->isModified()
                                 ? tr("%1 changed on disk. Reload it and lose your unsaved changes?")
                                 : tr("%1 changed on disk. Reload it?");
    if (QMessageBox::question(this, tr("Model Changed on Disk"), question.arg(QDir::toNativeSeparators(path))) ==
        QMessageBox::Yes) {
        m_editor->reload();
        m_editor->apply();
    }
}

// ---------------------------------------------------------------- the model and the simulation

void MainWindow::applyBundle(std::shared_ptr<const ModelBundle> bundle)
{
    if (!bundle) return;
    m_applied = std::move(bundle);
    applyInScene();
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
    m_shownStep = m_labelStep = -1;
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
    m_runner->reset();
    m_sliders->reset();
    m_shownStep = m_labelStep = -1;
    m_labelClock.invalidate();
}

void MainWindow::setSpeed(double speed) { m_runner->setSpeed(speed); }

void MainWindow::poll()
{
    const std::shared_ptr<const Snapshot> s = m_runner->latest();
    // the status bar's figures ten times a second while running: at every frame, the
    // status bar was laid out and painted 60 times a second, on the thread that draws
    const bool labels = !m_labelClock.isValid() || m_labelClock.elapsed() >= 100 || (s && !s->running);
    if (s && s->bundle == m_bundle && s->step != m_shownStep) {
        m_shownStep = s->step;
        m_viewports->setSnapshot(s);
    }
    if (s && s->bundle == m_bundle && labels && (s->step != m_labelStep || s->running != m_labelRunning)) {
        m_labelStep = s->step;
        m_labelRunning = s->running;
        m_timeLabel->setText(tr("t = %1 s").arg(QLocale().toString(s->t, 'f', 3)));
        m_rtLabel->setText(s->running ? tr("real time ×%1, %2 µs/step, %n overrun(s)", nullptr,
                                           static_cast<int>(s->overruns))
                                            .arg(QLocale().toString(s->realTimeFactor, 'f', 2),
                                                 QLocale().toString(s->stepMicros, 'f', 0))
                                      : tr("paused"));
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
        if (st->bankNames.size() > 1)
            lines << tr("Bank: <b>%1</b> (%2 of %3)")
                         .arg(st->bankNames.value(st->activeBank).toHtmlEscaped())
                         .arg(st->activeBank + 1)
                         .arg(st->bankNames.size());
        for (const QString& w : st->warnings)
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
    dialog->show();
}

void MainWindow::showLanguageReference()
{
    auto* dialog = new QDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Model Language Reference"));
    auto* layout = new QVBoxLayout(dialog);
    auto* browser = new QTextBrowser;
    QFile f(paths::docsDir() + "/model-language.md");
    if (f.open(QIODevice::ReadOnly)) {
        browser->setMarkdown(QString::fromUtf8(f.readAll()));
    } else {
        browser->setPlainText(tr("The reference (docs/model-language.md) was not found at %1.").arg(paths::docsDir()));
    }
    layout->addWidget(browser);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    layout->addWidget(buttons);
    dialog->resize(900, 800);
    dialog->show();
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About Padrob Studio"),
                       tr("<h3>Padrob Studio %1</h3><p>Real-time training simulators of heavy machines, built from a "
                          "model file: bodies, joints, hydraulic drives, forces and graphics.</p>")
                           .arg(QStringLiteral(PADROB_VERSION)));
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
