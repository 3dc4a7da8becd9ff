// padrob-studio as a whole, as a user meets it (a real window under Xvfb): it opens
// the liner manipulator by default and every bundled model, shows a typed error and
// refuses to apply it, applies the fixed model, runs a second of simulation that
// matches the solver library step for step, draws each display mode, reports a loop
// that locks up without blocking, and takes the operator's keys.

#include "tests/studio/gui_test.h"
#include "ide/studio/app/main_window.h"
#include "ide/studio/dialogs/inertia_dialog.h"
#include "ide/studio/plots/plot_panel.h"
#include "ide/studio/tree/joint_sliders.h"
#include "ide/i18n/language.h"
#include "ide/studio/editor/code_editor.h"
#include "ide/studio/editor/editor_panel.h"
#include "ide/studio/sim/keyboard_input.h"
#include "ide/studio/station/station_page.h"
#include "tests/studio/virtual_pad.h"
#include "trainer/station/profile_store.h"
#include "trainer/station/station.h"
#include "ide/studio/sim/simulation_runner.h"
#include "ide/studio/tree/model_tree.h"
#include "ide/studio/view/viewport.h"
#include "ide/studio/view/viewport_layout.h"
#include "solver/integrate/simulation.h"

#include <cmath>

#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QMainWindow>
#include <QMenuBar>
#include <QPushButton>
#include <QStatusBar>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QSet>
#include <QLabel>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QLocale>
#include <QTableWidget>
#include <QTextBlock>
#include <QTextCursor>
#include <QTimer>
#include <QMenu>
#include <QSettings>
#include <QAbstractButton>
#include <QTreeWidgetItem>

using namespace studio;
using studio::test::screenshotPath;

namespace {

QString modelPath(const QString& name) { return QStringLiteral(PADROB_SOURCE_DIR) + "/models/" + name; }

/// Distinct colours in an image (a blank view has one or two).
int colourCount(const QImage& image)
{
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 2) {
        for (int x = 0; x < image.width(); x += 2) colours.insert(image.pixel(x, y));
    }
    return static_cast<int>(colours.size());
}

/// Fraction of pixels that differ between two images of one size.
double difference(const QImage& a, const QImage& b)
{
    if (a.size() != b.size()) return 1;
    long differ = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) differ += a.pixel(x, y) != b.pixel(x, y);
    }
    return static_cast<double>(differ) / (a.width() * a.height());
}

/// Opens a model and waits until it is applied (the editor checks it on a worker thread).
bool openAndWait(MainWindow& w, const QString& path)
{
    const quint64 before = w.bundle() ? w.bundle()->serial : 0;
    if (!w.openFile(path)) return false;
    return QTest::qWaitFor([&] { return w.bundle() && w.bundle()->serial != before; }, 10000);
}

QString readText(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

/// The titles of the window's menus, in order.
QStringList menuTitles(const MainWindow& w)
{
    QStringList titles;
    for (const QAction* a : w.menuBar()->actions()) titles << a->text();
    return titles;
}

/// Settings ▸ Language ▸ `code`, as the user picks it.
void chooseLanguage(MainWindow& w, const QString& code)
{
    auto* action = w.findChild<QAction*>("Language_" + code);
    QVERIFY(action);
    action->trigger();
    QCOMPARE(i18n::current(), code);
    studio::test::settle(100);  // the LanguageChange events are posted
}

}  // namespace

class AppTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);  // settings and recovery copies in a test location
        QCoreApplication::setOrganizationName("PadrobTest");
        QCoreApplication::setApplicationName("padrob-studio-test");
        // start clean: no settings, no recovery copies from an earlier run
        QSettings().clear();
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/recovery").removeRecursively();
        // the tests below read English texts and '.' numbers, whatever the system's locale
        QVERIFY(i18n::install("en"));
    }

    void opensTheLinerManipulatorWhenGivenNoModel()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.openInitial(QString());
        QTRY_VERIFY_WITH_TIMEOUT(w.bundle(), 10000);
        QCOMPARE(w.bundle()->model->nb, 9);
        QVERIFY(w.editor()->filePath().endsWith("liner_manipulator_fluid.pad"));
        QVERIFY(w.windowTitle().startsWith("liner_manipulator_fluid.pad"));
        QCOMPARE(w.modelTree()->topLevelItemCount() > 0, true);
        // the three workspaces are there; Model is the current one
        QCOMPARE(w.workspace(), MainWindow::Workspace::Model);
        w.setWorkspace(MainWindow::Workspace::Train);
        QCOMPARE(w.workspace(), MainWindow::Workspace::Train);
        w.setWorkspace(MainWindow::Workspace::Model);
        QVERIFY(w.grab().save(screenshotPath("app_liner_manipulator.png")));
    }

    // Settings ▸ Language switches the running window between English and Spanish: menu
    // titles, docks, workspaces, the tree and the status bar's numbers change at once
    // (1,5 in Spanish), the choice is remembered, and model text keeps '.' whatever the
    // language (a typed model parses, a decimal comma stays an error, the inertia
    // calculator writes B lines with '.').
    void theLanguageChangesWithoutARestart()
    {
        QVERIFY(i18n::install("en"));
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        auto* timeLabel = w.findChild<QLabel*>("TimeLabel");
        auto* plotsDock = w.findChild<QDockWidget*>("PlotsDock");
        auto* slidersDock = w.findChild<QDockWidget*>("JointSlidersDock");
        QVERIFY(timeLabel && plotsDock && slidersDock);
        QCOMPARE(menuTitles(w),
                 QStringList({"&File", "&Edit", "&View", "&Simulation", "Se&ttings", "&Help"}));
        QCOMPARE(plotsDock->windowTitle(), QStringLiteral("Plots"));
        w.step();
        QTRY_COMPARE(timeLabel->text(), QStringLiteral("t = 0.001 s"));
        QCOMPARE(w.modelTree()->jointItem(2)->text(ModelTree::DetailsColumn), QStringLiteral("1.4 m … 1.617 m"));
        QVERIFY(w.sliders()->sliderCount() > 0);
        QVERIFY(w.sliders()->spinBox(0)->text().contains('.'));
        // the languages are named in their own language, checkable, one checked
        auto* es = w.findChild<QAction*>("Language_es");
        auto* en = w.findChild<QAction*>("Language_en");
        QVERIFY(es && en);
        QCOMPARE(es->text(), QStringLiteral("Español"));
        QCOMPARE(en->text(), QStringLiteral("English"));
        QVERIFY(en->isChecked() && !es->isChecked());

        chooseLanguage(w, "es");
        QTRY_COMPARE(menuTitles(w),
                     QStringList({"&Archivo", "&Editar", "&Ver", "&Simulación", "&Configuración", "Ay&uda"}));
        QVERIFY(es->isChecked() && !en->isChecked());
        QCOMPARE(es->text(), QStringLiteral("Español"));  // native names, not translated
        QCOMPARE(en->text(), QStringLiteral("English"));
        QCOMPARE(QSettings().value("ui/language").toString(), QStringLiteral("es"));
        QCOMPARE(plotsDock->windowTitle(), QStringLiteral("Gráficos"));
        QCOMPARE(slidersDock->windowTitle(), QStringLiteral("Articulaciones"));
        QTRY_COMPARE(timeLabel->text(), QStringLiteral("t = 0,001 s"));  // a decimal comma
        QCOMPARE(w.modelTree()->headerItem()->text(ModelTree::ElementColumn), QStringLiteral("Elemento"));
        QCOMPARE(w.modelTree()->jointItem(2)->text(ModelTree::DetailsColumn), QStringLiteral("1,4 m … 1,617 m"));
        QVERIFY2(w.sliders()->spinBox(0)->text().contains(','), qPrintable(w.sliders()->spinBox(0)->text()));
        QCOMPARE(w.editor()->applyButton()->text(), QStringLiteral("Aplicar"));
        QVERIFY(w.grab().save(screenshotPath("app_language_switched_es.png")));

        // the model language keeps '.': a model applied now parses as before ...
        const quint64 before = w.bundle()->serial;
        QString text = readText(modelPath("pendulum.pad"));
        w.editor()->setText(text);
        w.editor()->apply();
        QTRY_VERIFY_WITH_TIMEOUT(w.bundle()->serial != before, 10000);
        QCOMPARE(w.editor()->errorCount(), 0);
        QCOMPARE(w.bundle()->model->nb, 1);
        // ... a decimal comma is still refused ...
        w.editor()->setText(text.replace(QRegularExpression("\\nB 1 1\\.0"), "\nB 1 1,0"));
        QTRY_VERIFY_WITH_TIMEOUT(!w.editor()->isChecking(), 10000);
        QVERIFY(w.editor()->errorCount() > 0);
        w.editor()->undo();
        QTRY_VERIFY_WITH_TIMEOUT(!w.editor()->isChecking() && w.editor()->errorCount() == 0, 10000);
        // ... and the inertia calculator writes its B line with '.'
        QVERIFY(openAndWait(w, modelPath("excavator.pad")));
        w.findChild<QAction*>("InertiaCalculatorAction")->trigger();
        InertiaDialog* dialog = nullptr;
        QTRY_VERIFY((dialog = w.findChild<InertiaDialog*>()) && dialog->isVisible());
        QCOMPARE(dialog->windowTitle(), QStringLiteral("Calculadora de inercia"));
        QVERIFY(dialog->result());
        const QString computedBefore = dialog->computedBLine();
        // twice the first solid's density or mass: a B line other than the file's
        QTableWidgetItem* value = dialog->solidsTable()->item(0, InertiaDialog::ValueColumn);
        value->setText(QLocale().toString(QLocale().toDouble(value->text()) * 2));
        QTRY_VERIFY(dialog->result() && dialog->computedBLine() != computedBefore);
        const QString bLine = dialog->computedBLine();
        QVERIFY2(bLine.contains('.') && !bLine.section(" NAME", 0, 0).contains(','), qPrintable(bLine));
        QVERIFY(dialog->grab().save(screenshotPath("app_inertia_dialog_es.png")));
        const int line = dialog->bStatementLine();
        QVERIFY2(dialog->fileBLine() != bLine.trimmed(), qPrintable(dialog->fileBLine()));
        dialog->replaceButton()->click();
        QCOMPARE(w.editor()->editor()->document()->findBlockByNumber(line - 1).text().trimmed(), bLine.trimmed());
        // "In the file" follows the editor: the line just written, then a later edit
        QTRY_COMPARE(dialog->fileBLine(), bLine.trimmed());
        QTextCursor edit(w.editor()->editor()->document()->findBlockByNumber(line - 1));
        edit.movePosition(QTextCursor::EndOfBlock);
        edit.insertText("  // checked");
        QTRY_COMPARE(dialog->fileBLine(), bLine.trimmed() + "  // checked");
        w.editor()->undo();
        dialog->close();
        QTRY_VERIFY_WITH_TIMEOUT(!w.editor()->isChecking(), 10000);
        QCOMPARE(w.editor()->errorCount(), 0);

        // and back to English, again without a restart
        chooseLanguage(w, "en");
        QTRY_COMPARE(menuTitles(w),
                     QStringList({"&File", "&Edit", "&View", "&Simulation", "Se&ttings", "&Help"}));
        QVERIFY(en->isChecked() && !es->isChecked());
        QCOMPARE(QSettings().value("ui/language").toString(), QStringLiteral("en"));
        QCOMPARE(plotsDock->windowTitle(), QStringLiteral("Plots"));
        QTRY_COMPARE(timeLabel->text(), QStringLiteral("t = 0.000 s"));
        QCOMPARE(w.modelTree()->headerItem()->text(ModelTree::ElementColumn), QStringLiteral("Element"));
        QVERIFY(w.sliders()->spinBox(0)->text().contains('.'));
    }

    // The Model workspace with everything in it — the editor with a typed error, the
    // problems, the tree, the sliders, the 3D view, two plots after a second of motion
    // — in English and in Spanish, and the Spanish menus.
    void theModelWorkspaceInBothLanguages()
    {
        QVERIFY(i18n::install("en"));
        MainWindow w;
        w.resize(1600, 1000);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        w.plots()->setSignalSelected("q:2", true);
        w.plots()->setSignalSelected("f:2", true);
        const int lift = w.bundle()->model->jointIndex(2);
        w.runner()->setCommand(lift, 1.0);
        w.run();
        QTRY_VERIFY_WITH_TIMEOUT(w.runner()->latest() && w.runner()->latest()->t >= 1.0, 15000);
        w.pause();
        QTRY_VERIFY(!w.runner()->isRunning());
        w.modelTree()->setCurrentItem(w.modelTree()->jointItem(2));
        // a typed error: the problems list and the squiggle (the model applied stays)
        CodeEditor* editor = w.editor()->editor();
        editor->moveCursor(QTextCursor::End);
        QTest::keyClick(editor, Qt::Key_Return);
        QTest::keyClicks(editor, "C 99 QI 1,5");
        QTRY_VERIFY_WITH_TIMEOUT(w.editor()->errorCount() > 0, 5000);
        // room for the tree and the editor (the layout the earlier tests left is narrow)
        auto* space = w.findChild<QMainWindow*>("ModelWorkspace");
        space->resizeDocks({w.findChild<QDockWidget*>("ModelTreeDock"), w.findChild<QDockWidget*>("EditorDock")},
                           {380, 560}, Qt::Horizontal);
        space->resizeDocks({w.findChild<QDockWidget*>("PlotsDock")}, {330}, Qt::Vertical);
        w.plots()->refresh();
        studio::test::settle();
        QVERIFY(w.grab().save(screenshotPath("app_model_workspace_en.png")));

        chooseLanguage(w, "es");
        w.plots()->refresh();
        studio::test::settle();
        QVERIFY(w.grab().save(screenshotPath("app_model_workspace_es.png")));
        // the menus as they open (their accelerators, nothing clipped)
        int k = 0;
        for (QAction* a : w.menuBar()->actions()) {
            QMenu* menu = a->menu();
            menu->popup(w.mapToGlobal(QPoint(10 + 150 * k, 30)));
            QTRY_VERIFY(menu->isVisible());
            QVERIFY(menu->grab().save(screenshotPath(QStringLiteral("app_menu_%1_es.png").arg(k++))));
            menu->close();
        }
        // Settings ▸ Language: the languages by their own names, the one in use checked
        QMenu* languages = w.findChild<QMenu*>("LanguageMenu");
        languages->popup(w.mapToGlobal(QPoint(600, 60)));
        QTRY_VERIFY(languages->isVisible());
        QVERIFY(languages->grab().save(screenshotPath("app_menu_language_es.png")));
        languages->close();
        w.setWorkspace(MainWindow::Workspace::Model);
        chooseLanguage(w, "en");
        w.editor()->undo();
    }

    void settingsLightingRedrawsEveryViewAndIsRemembered()
    {
        // (the recent files as they were: opening a model adds to them)
        struct Restore {
            QVariant recent = QSettings().value("recentFiles");
            ~Restore()
            {
                Viewport::setLighting(Viewport::Lighting::Automatic);
                QSettings().remove("view/lighting");
                if (recent.isValid()) QSettings().setValue("recentFiles", recent);
                else QSettings().remove("recentFiles");
            }
        } restore;
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QMenu* menu = w.findChild<QMenu*>("LightingMenu");
        QVERIFY(menu);
        QCOMPARE(menu->actions().size(), 3);
        auto* automatic = w.findChild<QAction*>("Lighting_auto");
        auto* pixel = w.findChild<QAction*>("Lighting_pixel");
        auto* vertex = w.findChild<QAction*>("Lighting_vertex");
        QVERIFY(automatic && pixel && vertex);
        QVERIFY(automatic->isChecked());
        QVERIFY(!pixel->text().isEmpty() && !vertex->text().isEmpty());
        QVERIFY(openAndWait(w, QStringLiteral(PADROB_SOURCE_DIR "/models/liner_manipulator.pad")));
        QApplication::processEvents();
        Viewport* view = w.viewports()->viewport(0);
        pixel->trigger();
        QCOMPARE(Viewport::lighting(), Viewport::Lighting::PerPixel);
        QCOMPARE(QSettings().value("view/lighting").toString(), QStringLiteral("pixel"));
        QVERIFY(!view->lightsPerVertex());
        const QImage atPixels = view->grabFramebuffer();
        vertex->trigger();
        QVERIFY(vertex->isChecked() && !pixel->isChecked());
        QCOMPARE(Viewport::lighting(), Viewport::Lighting::PerVertex);
        QCOMPARE(QSettings().value("view/lighting").toString(), QStringLiteral("vertex"));
        QVERIFY(view->lightsPerVertex());
        const QImage atVertices = view->grabFramebuffer();
        QVERIFY(atPixels != atVertices);  // the same model, shaded otherwise
        // translated with the rest of the menus
        const QString english = vertex->text();
        chooseLanguage(w, "es");
        QTRY_COMPARE(vertex->text(), QStringLiteral("En los &vértices (más rápida)"));
        QCOMPARE(menu->title(), QStringLiteral("I&luminación"));
        QVERIFY(vertex->isChecked());
        QVERIFY(menu->grab().save(screenshotPath("app_menu_lighting_es.png")));
        chooseLanguage(w, "en");
        QTRY_COMPARE(vertex->text(), english);
        QVERIFY(menu->grab().save(screenshotPath("app_menu_lighting_en.png")));
        automatic->trigger();
        QCOMPARE(Viewport::lighting(), Viewport::Lighting::Automatic);
    }

    void opensEveryBundledModel()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const QFileInfoList models =
            QDir(QStringLiteral(PADROB_SOURCE_DIR) + "/models").entryInfoList({"*.pad"}, QDir::Files, QDir::Name);
        QVERIFY(models.size() >= 9);
        for (const QFileInfo& f : models) {
            QVERIFY2(openAndWait(w, f.absoluteFilePath()), qPrintable(f.fileName()));
            QCOMPARE(w.editor()->errorCount(), 0);
            // the view draws it
            QApplication::processEvents();
            const QImage image = w.viewports()->viewport(0)->grabFramebuffer();
            // (lit at the vertices here, on llvmpipe: a flat face is one colour)
            QVERIFY2(colourCount(image) > 30, qPrintable(f.fileName()));
        }
    }

    void aTypedErrorIsShownAndNotApplied()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("pendulum.pad")));
        const quint64 good = w.bundle()->serial;
        // type "C 99" (a joint without its B1/B2 lines) at the end
        CodeEditor* editor = w.editor()->editor();
        editor->setFocus();
        editor->moveCursor(QTextCursor::End);
        QTest::keyClick(editor, Qt::Key_Return);
        QTest::keyClicks(editor, "C 99");
        QTRY_VERIFY_WITH_TIMEOUT(w.editor()->errorCount() > 0, 5000);
        QVERIFY(w.isWindowModified() || w.windowTitle().contains('*'));
        QVERIFY(w.editor()->diagnostics().size() > 0);
        w.editor()->apply();
        QCOMPARE(w.bundle()->serial, good);  // the last good model stays
        QVERIFY(w.grab().save(screenshotPath("app_typed_error.png")));
        // fixed: applied
        w.editor()->undo();
        QTRY_COMPARE_WITH_TIMEOUT(w.editor()->errorCount(), 0, 5000);
        w.editor()->apply();
        QTRY_VERIFY_WITH_TIMEOUT(w.bundle()->serial != good, 5000);
        // (the text is the file's again: nothing to save)
    }

    void oneSecondOfSimulationMatchesTheSolver()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        const auto bundle = w.bundle();
        const solver::Model& m = *bundle->model;
        const int lift = m.jointIndex(2), slew = m.jointIndex(1);
        w.runner()->setCommand(lift, 1.0);
        w.runner()->setCommand(slew, 0.5);
        w.run();
        QTRY_VERIFY_WITH_TIMEOUT(w.runner()->latest() && w.runner()->latest()->t >= 1.0, 15000);
        w.pause();
        QTRY_VERIFY(!w.runner()->isRunning());
        const auto snap = w.runner()->latest();
        QVERIFY(snap->step >= 1000);
        // the solver library, step for step: RK4 at 1 ms with the same commands
        solver::SimulationOptions o;
        o.integrator.method = solver::IntegrationMethod::Rk4Fixed;
        o.integrator.step = 1e-3;
        solver::Simulation sim(bundle->model, o);
        sim.setCommand(lift, 1.0);
        sim.setCommand(slew, 0.5);
        std::vector<solver::SimulationEvent> ev;
        std::string err;
        for (long k = 1; k <= snap->step; ++k) QVERIFY(sim.advanceTo(k * 1e-3, ev, err));
        QCOMPARE(snap->theta.size(), sim.state().q.size());
        for (int j = 0; j < m.nb; ++j) QCOMPARE(snap->theta[j], sim.state().q[j]);
        // and it moved: the boom rose, the turret turned
        QVERIFY(snap->q[lift] > m.coordinate(lift, m.theta0[lift]) + 0.01);
        QVERIFY(snap->q[slew] > 0.05);
        // the view shows the moved machine
        QTRY_VERIFY(w.viewports()->viewport(0)->poses().size() == static_cast<std::size_t>(m.nb) &&
                    w.viewports()->viewport(0)->poses()[slew].isApprox(snap->bodyPoses[slew]));
        QVERIFY(w.grab().save(screenshotPath("app_after_one_second.png")));
    }

    void eachDisplayModeDraws()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        QApplication::processEvents();
        Viewport* v = w.viewports()->viewport(0);
        QImage images[3];
        const DisplayMode modes[3] = {DisplayMode::Schematic, DisplayMode::Dressed, DisplayMode::Both};
        const char* names[3] = {"schematic", "dressed", "both"};
        for (int i = 0; i < 3; ++i) {
            w.viewports()->setDisplayMode(modes[i]);
            QApplication::processEvents();
            images[i] = v->grabFramebuffer();
            QVERIFY(colourCount(images[i]) > 100);
            QVERIFY(images[i].save(screenshotPath(QString("app_view_%1.png").arg(names[i]))));
        }
        QVERIFY(difference(images[0], images[1]) > 0.02);
        QVERIFY(difference(images[2], images[0]) > 0.01);
        QVERIFY(difference(images[2], images[1]) > 0.01);
    }

    void aModelWithContactTouchesTheSceneLoaded()
    {
        // a free box over nothing of its own: with the scene's slab under it, it rests on it
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString model = dir.filePath("box.pad"), slab = dir.filePath("slab.pad");
        {
            QFile m(model), sc(slab);
            QVERIFY(m.open(QIODevice::WriteOnly) && sc.open(QIODevice::WriteOnly));
            m.write("GRAVITY 0 0 -9.81\nCONTACT\nB 1 50 2 2 2\nC 1 T 3\nB1 0 P1 0 0 0.25 A1 1 0 0 R1 0 1 0\n"
                    "B2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\nG 1 B 1 BOX 0.5 0.5 0.5\n");
            sc.write("G 1 B 0 BOX 4 4 0.2 POS 0 0 -0.1\n");
        }
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, model));
        auto heightAfterASecond = [&] {
            const quint64 serial = w.bundle()->serial;
            w.run();
            // (a wait that times out leaves NaN: the comparison after it fails)
            const bool ran = QTest::qWaitFor([&] { auto s = w.runner()->latest(); return s && s->bundle == w.bundle() && s->t > 1.0; }, 10000);
            w.pause();
            if (!ran) return std::nan("");
            const auto s = w.runner()->latest();
            return s && s->bundle && s->bundle->serial == serial ? s->bodyPoses[std::size_t(w.bundle()->model->bodyIndex(1))].translation().z()
                                                               : std::nan("");
        };
        QVERIFY(w.loadScene(slab));
        QVERIFY(std::abs(heightAfterASecond() - 0.25) < 1e-3);  // resting on the slab
        w.clearScene();
        QVERIFY(heightAfterASecond() < -1.0);  // nothing under it: it falls
    }

    void aSceneIsDrawnAndABadOneKeepsTheAppUsable()
    {
        const QString mill = QStringLiteral(PADROB_SOURCE_DIR) + "/resources/scenes/sag_mill.pad";
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString broken = dir.filePath("broken_scene.pad");
        {
            QFile f(broken);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("G 1 B 0 BOX 1 1\n");  // a box needs three sizes
        }
        {
            MainWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
            QVERIFY(w.scenePath().isEmpty());
            QVERIFY(w.loadScene(mill));
            QCOMPARE(w.scenePath(), QFileInfo(mill).absoluteFilePath());
            QVERIFY(w.viewports()->viewport(0)->scene());
            QCOMPARE(QSettings().value("scene/last").toString(), w.scenePath());
            QApplication::processEvents();
            QVERIFY(w.grab().save(screenshotPath("app_scene_mill.png")));
            // a scene that cannot be used: said in a box that does not block, the scene
            // drawn before stays, the simulation runs
            QVERIFY(!w.loadScene(broken));
            QMessageBox* box = nullptr;
            QTRY_VERIFY((box = w.findChild<QMessageBox*>("SceneProblemBox")) && box->isVisible());
            QVERIFY2(box->text().contains("broken_scene.pad:1:"), qPrintable(box->text()));
            QCOMPARE(w.scenePath(), QFileInfo(mill).absoluteFilePath());
            w.run();
            QTRY_VERIFY_WITH_TIMEOUT(w.runner()->latest()->step > 50, 5000);
            w.pause();
            box->close();
            // View ▸ Scene ▸ None
            w.clearScene();
            QVERIFY(!w.viewports()->viewport(0)->scene());
            QVERIFY(!QSettings().contains("scene/last"));
            QVERIFY(w.loadScene(mill));
        }
        // the next start draws the scene used last; a scene gone since is forgotten
        {
            MainWindow w;
            QVERIFY(w.restoreScene());
            QCOMPARE(w.scenePath(), QFileInfo(mill).absoluteFilePath());
            QVERIFY(w.viewports()->viewport(0)->scene());
        }
        QSettings().setValue("scene/last", dir.filePath("gone.pad"));
        {
            MainWindow w;
            QVERIFY(!w.restoreScene());
            QVERIFY(w.scenePath().isEmpty());
            QVERIFY(!QSettings().contains("scene/last"));
        }
    }

    void aLoopThatLocksUpStopsTheSimulationAndKeepsTheEditor()
    {
        // the slider-crank pushed by its piston into dead centre (t ≈ 0.6 s)
        QString text = readText(modelPath("slider_crank.pad"));
        QVERIFY(!text.isEmpty());
        text.replace(QRegularExpression("\\nD 1 MOTOR[^\\n]*"), "\n");
        text.replace("\nC 4 ", "\nC 4 LL 0.2 UL 0.46 ");
        text += "\nD 4 HYD VMAX 0.1\n";
        QTemporaryDir dir;
        const QString path = dir.filePath("locking.pad");
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(text.toUtf8());
        }
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, path));
        QSignalSpy failed(w.runner(), &SimulationRunner::failed);
        w.runner()->setCommand(w.bundle()->model->jointIndex(4), 1.0);
        w.run();
        QTRY_VERIFY_WITH_TIMEOUT(failed.count() == 1, 15000);
        QVERIFY(failed.at(0).at(0).toString().contains("locked up"));
        QTRY_VERIFY(!w.runner()->isRunning());
        auto* box = w.findChild<QMessageBox*>("SimulationStoppedBox");
        QVERIFY(box);
        QVERIFY(!box->isModal());
        QVERIFY(w.grab().save(screenshotPath("app_loop_locked.png")));
        // the editor still takes text
        CodeEditor* editor = w.editor()->editor();
        editor->moveCursor(QTextCursor::End);
        QTest::keyClicks(editor, "// still here");
        QVERIFY(w.editor()->text().endsWith("// still here"));
        box->close();
        w.reset();
        QTRY_VERIFY(w.runner()->latest() && w.runner()->latest()->t == 0.0);
    }

    void selectingInTheTreeHighlightsTheViewAndTheText()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        QTreeWidgetItem* item = w.modelTree()->jointItem(2);
        QVERIFY(item);
        w.modelTree()->setCurrentItem(item);
        const int lift = w.bundle()->model->jointIndex(2);
        QTRY_COMPARE(w.viewports()->viewport(0)->highlightedJoint(), lift);
        // the editor is at the joint's C statement
        const int line = w.bundle()->spec().joints[1].src.pos.line;
        QCOMPARE(w.editor()->editor()->cursorLine(), line);
        QVERIFY(w.editor()->editor()->textCursor().block().text().startsWith("C 2"));
    }

    void recentFilesAndLayoutPersist()
    {
        {
            MainWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(openAndWait(w, modelPath("four_bar.pad")));
            w.resize(1440, 900);  // wider than the Station workspace needs (its mapping table)
            w.close();
        }
        const QStringList recent = QSettings().value("recentFiles").toStringList();
        QVERIFY(!recent.isEmpty());
        QVERIFY(recent.front().endsWith("four_bar.pad"));
        MainWindow again;
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QCOMPARE(again.size(), QSize(1440, 900));
        const QMenu* recentMenu = again.findChild<QMenu*>("RecentFilesMenu");
        QVERIFY(recentMenu);
        QVERIFY(!recentMenu->actions().isEmpty());
        QVERIFY(recentMenu->actions().front()->text().endsWith("four_bar.pad"));
    }

    void closingWithUnsavedChangesAsksAndCanBeCancelled()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("pendulum.pad")));
        CodeEditor* editor = w.editor()->editor();
        editor->moveCursor(QTextCursor::End);
        QTest::keyClicks(editor, "// edit");
        QVERIFY(w.editor()->isModified());
        bool asked = false;
        QTimer::singleShot(200, [&] {
            auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
            if (!box) return;
            asked = true;
            box->button(QMessageBox::Cancel)->click();
        });
        QVERIFY(!w.close());  // cancelled: still open, the text is still there
        QVERIFY(asked);
        QVERIFY(w.isVisible());
        QVERIFY(w.editor()->text().endsWith("// edit"));
        // discard: it closes
        QTimer::singleShot(200, [&] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                box->button(QMessageBox::Discard)->click();
            }
        });
        QVERIFY(w.close());
    }

    void theOperatorsKeysOpenTheValves()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        const int lift = w.bundle()->model->jointIndex(2);
        // the station has the model and its profile (a key held while a profile is
        // installed acts only after it has been released)
        QTRY_VERIFY(w.station()->latest() && w.station()->latest()->drives.size() == 9 &&
                    w.station()->latest()->profileName == "Gamepad");
        Viewport* v = w.viewports()->viewport(0);
        v->setFocus();
        QTest::keyPress(v, Qt::Key_W);
        QTRY_COMPARE(w.runner()->commands()[static_cast<std::size_t>(lift)], 1.0);
        QTest::keyRelease(v, Qt::Key_W);
        QTRY_COMPARE(w.runner()->commands()[static_cast<std::size_t>(lift)], 0.0);
        QTest::keyPress(v, Qt::Key_S);
        QTRY_COMPARE(w.runner()->commands()[static_cast<std::size_t>(lift)], -1.0);
        QTest::keyRelease(v, Qt::Key_S);
    }

    // No shortcut of the window is a valve key (View > Fit All was F, the wrist's R/F
    // pair: with the view focused F moved the wrist and never fitted); Fit All is Home,
    // and Keyboard Controls says the shortcuts beside the valve keys.
    void noShortcutIsAValveKeyAndHomeFitsTheView()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        constexpr Qt::KeyboardModifiers chords = Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier;
        for (QAction* a : w.findChildren<QAction*>()) {
            for (const QKeySequence& k : a->shortcuts()) {
                if (k.isEmpty() || (k[0].keyboardModifiers() & chords)) continue;
                QVERIFY2(!KeyboardInput::isValveKey(k[0].key()),
                         qPrintable(a->text() + " has the valve key " + k.toString()));
            }
        }
        QTRY_VERIFY(w.station()->latest() && w.station()->latest()->drives.size() == 9 &&
                    w.station()->latest()->profileName == "Gamepad");
        // (a window's shortcuts act in the active window only)
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        Viewport* v = w.viewports()->viewport(0);
        v->setFocus();
        v->fitAll();
        const double fitted = v->cameraState().distance;
        Camera far = v->cameraState();
        far.distance = 5 * fitted;
        v->setCameraState(far);
        // F: the wrist (C 4, the fourth pair's second key), the view stays
        const int wrist = w.bundle()->model->jointIndex(4);
        QTest::keyPress(v, Qt::Key_F);
        QTRY_COMPARE(w.runner()->commands()[static_cast<std::size_t>(wrist)], -1.0);
        QTest::keyRelease(v, Qt::Key_F);
        QTRY_COMPARE(w.runner()->commands()[static_cast<std::size_t>(wrist)], 0.0);
        QCOMPARE(v->cameraState().distance, 5 * fitted);
        // Home: Fit All (the wrist moved a little: about the distance fitted before)
        QTest::keyClick(v, Qt::Key_Home);
        QTRY_VERIFY(std::abs(v->cameraState().distance - fitted) < 0.2 * fitted);
        // Keyboard Controls: the valve keys and the shortcuts
        w.findChild<QAction*>("KeyboardControlsAction")->trigger();
        QMessageBox* box = nullptr;
        QTRY_VERIFY((box = w.findChild<QMessageBox*>("KeyboardControlsBox")) && box->isVisible());
        QVERIFY(box->text().contains(QKeySequence(Qt::Key_Home).toString(QKeySequence::NativeText) + "</b> Fit All"));
        QVERIFY(box->text().contains("F5</b>"));
        QVERIFY(box->text().contains("R / F"));
        QVERIFY(box->grab().save(screenshotPath("app_keyboard_controls_en.png")));
        box->close();
        // and in Spanish
        chooseLanguage(w, "es");
        w.findChild<QAction*>("KeyboardControlsAction")->trigger();
        QTRY_VERIFY((box = w.findChild<QMessageBox*>("KeyboardControlsBox")) && box->isVisible());
        QVERIFY(box->text().contains("Atajos (ninguno abre una válvula):"));
        QVERIFY(box->text().contains("</b> Encuadrar todo"));
        QVERIFY(box->grab().save(screenshotPath("app_keyboard_controls_es.png")));
        box->close();
        chooseLanguage(w, "en");
    }

    // Issue 25, item 5: the Console profile with no console. The banner says what
    // happens — the keyboard drives the console's valves instead (never "valves closed"
    // while a key moves them) — a valve key does move the machine, and the Model
    // workspace's HUD says that the profile's console is missing (a Train attempt's HUD
    // shows the same lines: TrainTest::liveAttemptTakesTheKeyboardAndShowsTheHud).
    void theConsoleProfileWithoutAConsoleSaysTheKeyboardDrives()
    {
        QSettings().remove("station");
        MainWindow w;
        w.resize(1600, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        StationPage* page = w.stationPage();
        for (const QString& lang : QStringList{"en", "es"}) {
            if (lang == "es") chooseLanguage(w, "es");
            const bool en = lang == "en";
            QVERIFY(page->loadProfile("Console (8 levers)"));
            w.setWorkspace(MainWindow::Workspace::Station);
            const QString drives = en ? "the keyboard drives C 1 GIRO PLUMA" : "el teclado mueve C 1 GIRO PLUMA";
            QTRY_VERIFY2(page->warningsLabel()->text().contains(drives), qPrintable(page->warningsLabel()->text()));
            QVERIFY2(page->warningsLabel()->text().contains("C 9 GARRA INFERIOR"), qPrintable(page->warningsLabel()->text()));
            QVERIFY2(!page->warningsLabel()->text().contains(en ? "valves closed" : "válvulas cerradas"),
                     qPrintable(page->warningsLabel()->text()));
            QTest::qWait(50);
            QVERIFY(w.grab().save(screenshotPath("app_console_missing_station_" + lang + ".png")));

            // the machine does what the banner says: W opens the lift's valve
            w.setWorkspace(MainWindow::Workspace::Model);
            w.activateWindow();
            QVERIFY(QTest::qWaitForWindowActive(&w));
            const auto lift = static_cast<std::size_t>(w.bundle()->model->jointIndex(2));
            Viewport* v = w.viewports()->viewport(0);
            v->setFocus();
            QTest::keyPress(v, Qt::Key_W);
            QTRY_COMPARE(w.runner()->commands()[lift], 1.0);
            QTest::keyRelease(v, Qt::Key_W);
            QTRY_COMPARE(w.runner()->commands()[lift], 0.0);
            const QString missing = en ? "DAQ console on /dev/ttyUSB0 missing — the keyboard drives instead"
                                       : "Falta Consola DAQ en /dev/ttyUSB0 — el teclado las mueve en su lugar";
            QTRY_VERIFY2(w.hud()->isVisible() && w.hud()->text().contains(missing), qPrintable(w.hud()->text()));
            QVERIFY(w.grab().save(screenshotPath("app_console_missing_hud_" + lang + ".png")));
        }
        chooseLanguage(w, "en");
        QSettings().remove("station");
    }

    // Issue 25, item 10: a model too heavy for real time. The status bar shows the
    // share of late steps over the last seconds (not an ever-growing count) and says
    // in its tooltip what an overrun is and what to do.
    void overrunsAreARateWithAnExplanation()
    {
        MainWindow w;
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("excavator.pad")));
        auto* label = w.findChild<QLabel*>("RealTimeLabel");
        QVERIFY(label);
        w.runner()->setTimeStep(1e-5);  // 400,000 steps a second at ×4: more than one core does
        w.setSpeed(4);
        w.run();
        for (const QString& lang : QStringList{"en", "es"}) {
            if (lang == "es") chooseLanguage(w, "es");
            const QRegularExpression late(lang == "en" ? "\\d+ % of steps late" : "\\d+ % de pasos atrasados");
            QTRY_VERIFY2_WITH_TIMEOUT(label->text().contains(late), qPrintable(label->text()), 5000);
            QVERIFY2(!label->text().contains(QRegularExpression(lang == "en" ? "\\d overruns?$" : "\\d pasos? atrasados?$")),
                     qPrintable(label->text()));  // not an ever-growing count
            QVERIFY2(label->toolTip().contains(lang == "en" ? "took longer to compute than the real time it simulates"
                                                            : "tardó más en calcularse que el tiempo real que simula"),
                     qPrintable(label->toolTip()));
            QVERIFY(w.grab().save(screenshotPath("app_overruns_" + lang + ".png")));
        }
        w.pause();
        chooseLanguage(w, "en");
    }

    // The Station workspace: the liner's Gamepad profile is chosen at the first start,
    // the HUD shows the active bank, a profile's unsaved edits survive re-applying the
    // model, and the profile chosen is remembered for the next start.
    void theStationWorkspaceAndTheHud()
    {
        QSettings().remove("station");
        QDir(trainer::ProfileStore::defaultRoot()).removeRecursively();  // the test location's
        {
            MainWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
            StationPage* page = w.stationPage();
            QVERIFY(page);
            QCOMPARE(page->profile().name, QStringLiteral("Gamepad"));
            QVERIFY(page->isShippedProfile());
            // no gamepad: the HUD says so and what drives instead, and shows no bank the
            // operator could not switch (issue 25, items 5 and 10)
            QTRY_VERIFY2(w.hud()->isVisible() && w.hud()->text().contains("Gamepad missing — the keyboard drives instead"),
                         qPrintable(w.hud()->text()));
            QVERIFY2(!w.hud()->text().contains("Bank"), qPrintable(w.hud()->text()));
            {
                // a gamepad plugged in: the bank, and how to switch by the pad's button names
                studio::test::VirtualPad pad;
                QVERIFY2(pad.pad, SDL_GetError());
                QTRY_VERIFY2(w.hud()->text().contains("Bank: <b>Boom</b> (1 of 2) · Y: next bank · Left shoulder: Boom · "
                                                       "Right shoulder: Wrist"),
                             qPrintable(w.hud()->text()));
                QVERIFY(!w.hud()->text().contains("missing"));
                w.station()->post([](trainer::StationEngine& e) { e.selectBank(1); });
                QTRY_VERIFY(w.hud()->text().contains("Wrist</b> (2 of 2)"));
                QVERIFY(w.grab().save(screenshotPath("app_hud_bank.png")));
                pad.unplug();
                QTRY_VERIFY2(!w.hud()->text().contains("Bank"), qPrintable(w.hud()->text()));
            }
            w.setWorkspace(MainWindow::Workspace::Station);
            QTest::qWait(100);
            QVERIFY(w.grab().save(screenshotPath("app_station_workspace.png")));

            // a new profile, not saved yet, survives the model being applied again
            QVERIFY(page->newProfile("Trainer's"));
            QVERIFY(page->isDirty());
            w.editor()->apply();
            QTest::qWait(50);
            QCOMPARE(page->profile().name, QStringLiteral("Trainer's"));
            QVERIFY(page->isDirty());
            QVERIFY(page->save());
            QTRY_VERIFY(w.station()->latest() && w.station()->latest()->profileName == "Trainer's");
            w.setWorkspace(MainWindow::Workspace::Model);
        }
        // the next start picks the profile used last
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        QCOMPARE(w.stationPage()->profile().name, QStringLiteral("Trainer's"));
        QVERIFY(trainer::ProfileStore().remove(modelPath("liner_manipulator.pad"), "Trainer's"));
        QSettings().remove("station");
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat());
    QApplication app(argc, argv);
    AppTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "app_test.moc"
