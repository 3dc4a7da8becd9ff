// MainWindow's menus, their texts in the UI's language, and the dialogs the Help menu
// opens (Keyboard Controls, the model language's reference, About). The rest of the
// window is in main_window.cpp.

#include "ide/studio/app/main_window.h"

#include "ide/i18n/language.h"
#include "ide/paths/paths.h"
#include "ide/studio/app/menu_items.h"
#include "ide/studio/editor/editor_panel.h"
#include "ide/studio/plots/plot_panel.h"
#include "ide/studio/app/getting_started.h"
#include "ide/studio/sim/keyboard_input.h"
#include "ide/studio/sim/simulation_runner.h"
#include "ide/studio/station/station_page.h"
#include "ide/studio/train/train_page.h"
#include "ide/studio/tree/joint_sliders.h"
#include "ide/studio/tree/model_tree.h"
#include "ide/studio/view/viewport_layout.h"
#include "trainer/input/keyboard_device.h"
#include "trainer/station/station.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QEvent>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QTextBrowser>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace studio {

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
    // (Home, as in most 3D tools: F, the letter many use, is a valve key, KeyboardInput::isValveKey)
    m.fitAll = m.view->addAction(QString(), QKeySequence(Qt::Key_Home), this, [this] { m_viewports->fitAll(); });
    m.fitAll->setObjectName("FitAllAction");
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
    m.record = m.view->addAction(QString(), this, &MainWindow::toggleRecording);
    m.record->setObjectName("RecordVideoAction");
    m.view->addSeparator();
    for (QDockWidget* d : m_docks) m.view->addAction(d->toggleViewAction());  // (named after their docks)

    // Simulation
    m.simulation = menuBar()->addMenu(QString());
    m_runAction = m.simulation->addAction(QString(), QKeySequence(Qt::Key_F5), this, &MainWindow::run);
    m_pauseAction = m.simulation->addAction(QString(), QKeySequence(Qt::Key_F6), this, &MainWindow::pause);
    m_stepAction = m.simulation->addAction(QString(), QKeySequence(Qt::Key_F10), this, &MainWindow::step);
    m_resetAction = m.simulation->addAction(QString(), QKeySequence(Qt::CTRL | Qt::Key_R), this, &MainWindow::reset);
    m_runAction->setObjectName("RunAction");
    m_pauseAction->setObjectName("PauseAction");
    m_stepAction->setObjectName("StepAction");
    m_resetAction->setObjectName("ResetAction");
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
    m.keyboard->setObjectName("KeyboardControlsAction");

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
    m.gettingStarted = m.help->addAction(QString(), this, &MainWindow::showGettingStarted);
    m.gettingStarted->setObjectName("GettingStartedAction");
    m.about = m.help->addAction(QString(), this, &MainWindow::showAbout);

    buildSimulationBar();
}

void MainWindow::showGettingStarted()
{
    if (!m_gettingStarted) m_gettingStarted = new GettingStarted(this, m_runAction, m_pauseAction);
    m_gettingStarted->open();
}

void MainWindow::showGettingStartedOnce()
{
    if (!GettingStarted::wasShown()) showGettingStarted();
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
    // the left docks (tabbed) never narrower than their tabs' titles: on a 1280-pixel
    // screen they were squeezed until the tabs read "M…" and "Articulaci…"
    QTabBar tabs;
    tabs.addTab(m_treeDock->windowTitle());
    tabs.addTab(m_sliderDock->windowTitle());
    for (QDockWidget* d : {m_treeDock, m_sliderDock}) d->setMinimumWidth(std::max(240, tabs.sizeHint().width() + 8));

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
    m.gettingStarted->setText(tr("&Getting Started"));
    m.about->setText(tr("&About Padrob Studio"));
    retranslateTools();

    // the status bar and the title (a passing message in the old language goes)
    statusBar()->clearMessage();
    if (m_recordsNote) m_recordsNote->setText(recordsNoteText());
    updateModelLabel();
    updateUnappliedBar();
    // the time and the real-time factor again, in the new language
    m_shown.reset();
    m_labelStep = -1;
    m_labelClock.invalidate();
    if (m_timeLabel) poll();
    updateTitle();
}

void MainWindow::showKeyboardControls()
{
    // which way each key moves its drive: + is the way the joint's coordinate grows (as
    // the Joints sliders show it), named after the joint's kind
    const auto directions = [this](int treeJoint, int sign) {
        QString plus = tr("+"), minus = tr("−");
        if (m_bundle && treeJoint >= 0 && treeJoint < m_bundle->model->nb) {
            switch (m_bundle->model->jointType[std::size_t(treeJoint)]) {
            case solver::JointType::Revolute:
                plus = tr("turns +", "a revolute joint's angle grows");
                minus = tr("turns −", "a revolute joint's angle shrinks");
                break;
            case solver::JointType::Actuator:
                plus = tr("cylinder out", "a T 1 joint's actuator lengthens");
                minus = tr("cylinder in", "a T 1 joint's actuator shortens");
                break;
            default:
                plus = tr("slides +", "a prismatic joint's displacement grows");
                minus = tr("slides −", "a prismatic joint's displacement shrinks");
                break;
            }
        }
        return sign < 0 ? std::pair{minus, plus} : std::pair{plus, minus};
    };
    const auto row = [](const QString& keys, const QString& drive, const QString& ways) {
        return "<tr><td><b>" + keys.toHtmlEscaped() + "</b>&nbsp;&nbsp;</td><td>" + drive.toHtmlEscaped() +
               "&nbsp;&nbsp;</td><td>" + ways.toHtmlEscaped() + "</td></tr>";
    };
    const auto ways = [&directions](const QString& pair, int treeJoint, int sign) {
        const QStringList keys = pair.split(QStringLiteral(" / "));
        const auto [first, second] = directions(treeJoint, sign);
        return tr("%1: %2 · %3: %4", "each key of a pair and which way it moves the drive")
            .arg(keys.value(0), first, keys.value(1), second);
    };
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
            const QString pair = pairs[ms.mapping.axis];
            text += row(pair, drive, ways(pair, ms.treeJoint, ms.mapping.sign));
        }
    }
    if (!mapped) {
        for (const KeyBinding& b : m_keyboard->bindings()) {
            const QString joint = b.jointName.isEmpty() ? tr("C %1").arg(b.jointId)
                                                        : tr("C %1 %2").arg(QString::number(b.jointId), b.jointName);
            text += row(b.keysText(), joint, ways(b.keysText(), b.treeJoint, 1));
        }
    }
    text += "</table>";
    // the view's and the simulation's shortcuts, none of them a valve key
    QStringList shortcuts;
    for (QAction* a : {m_items->fitAll, m_runAction, m_pauseAction, m_stepAction, m_resetAction}) {
        shortcuts << QStringLiteral("<b>%1</b> %2").arg(a->shortcut().toString(QKeySequence::NativeText).toHtmlEscaped(),
                                                       QString(a->text()).remove(QLatin1Char('&')).toHtmlEscaped());
    }
    // the mouse in the 3D view (CameraController)
    const QString mouse = "<table>" + row(tr("Left drag"), tr("orbits around the model"), QString()) +
                          row(tr("Middle drag, or Shift + left drag"), tr("pans"), QString()) +
                          row(tr("Wheel"), tr("zooms towards the cursor"), QString()) +
                          row(tr("Double click"), tr("frames the whole model"), QString()) +
                          row(tr("Ctrl + left drag on a body"),
                              tr("picks the body and pushes it while the simulation runs (a spring pulls the point "
                                 "you grabbed toward the cursor); release to let go"),
                              QString()) +
                          "</table>";
    auto* box = new QMessageBox(QMessageBox::Information, tr("Keyboard Controls"),
                                QStringLiteral("<p>%1</p>%2<p>%3<br>%4</p><p>%5</p>%6")
                                    .arg(tr("With the 3D view focused, hold a key to open a valve:"), text,
                                         tr("Shortcuts (none of them opens a valve):"),
                                         shortcuts.join(QStringLiteral(" · ")), tr("Mouse in the 3D view:"), mouse),
                                QMessageBox::Ok, this);
    box->setObjectName("KeyboardControlsBox");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
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

}  // namespace studio
