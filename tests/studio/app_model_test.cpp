// The Model workspace as a modeler uses it (a real window under Xvfb; issue 25, items
// 8, 9 and 16): the joint sliders are the simulation's state, paused (they follow it,
// and a slider sets it); a bar says when the editor holds a model that is not applied;
// File ▸ New leaves the last model's scene; the file opened last is opened again; and
// the model's file reloads when another program writes it, keeping the pose when the
// joints are the same.

#include "tests/studio/gui_test.h"
#include "ide/i18n/language.h"
#include "ide/studio/app/main_window.h"
#include "ide/studio/editor/code_editor.h"
#include "ide/studio/editor/editor_panel.h"
#include "ide/studio/sim/simulation_runner.h"
#include "ide/studio/tree/joint_sliders.h"
#include "ide/studio/view/viewport.h"
#include "ide/studio/view/viewport_layout.h"

#include <QAction>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QSaveFile>
#include <QSettings>
#include <QSlider>
#include <QStatusBar>
#include <QTimer>
#include <QMessageBox>
#include <QApplication>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTextCursor>

#include <cmath>

using namespace studio;
using studio::test::screenshotPath;
using studio::test::settle;

namespace {

QString modelPath(const QString& name) { return QStringLiteral(PADROB_SOURCE_DIR) + "/models/" + name; }

QString readText(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

/// Writes `text` to `path` as editors that save by a rename do (a new file over the old).
bool writeByRename(const QString& path, const QString& text)
{
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return false;
    f.write(text.toUtf8());
    return f.commit();
}

/// Shows the window, opens a model and waits until it is applied (the editor checks it
/// on a worker thread).
bool openAndWait(MainWindow& w, const QString& path)
{
    w.show();
    if (!QTest::qWaitForWindowExposed(&w)) return false;
    const quint64 before = w.bundle() ? w.bundle()->serial : 0;
    if (!w.openFile(path)) return false;
    return QTest::qWaitFor([&] { return w.bundle() && w.bundle()->serial != before; }, 10000);
}

/// Runs the simulation until `seconds` of simulated time more, then pauses; true when
/// the paused snapshot of the model applied is there.
bool runFor(MainWindow& w, double seconds)
{
    const double from = w.runner()->latest()->t;
    w.run();
    const bool ran = QTest::qWaitFor([&] { return w.runner()->latest()->t >= from + seconds; }, 10000);
    w.pause();
    return ran && QTest::qWaitFor([&] {
               const auto s = w.runner()->latest();
               return !s->running && s->bundle == w.bundle();
           }, 5000);
}

/// The sliders show the snapshot's coordinates (every slider's joint, and its spin box).
bool slidersShowTheSimulation(MainWindow& w)
{
    const auto s = w.runner()->latest();
    const Eigen::VectorXd q = w.sliders()->coordinates();
    if (q.size() != s->q.size()) return false;
    for (int k = 0; k < w.sliders()->sliderCount(); ++k) {
        const int j = w.sliders()->sliderJoint(k);
        if (std::abs(q[j] - s->q[j]) > 1e-9) return false;
        const double shown = w.sliders()->spinBox(k)->value();
        const double expected = w.bundle()->model->jointType[std::size_t(j)] == solver::JointType::Revolute
                                    ? s->q[j] * 180 / M_PI
                                    : s->q[j];
        if (std::abs(shown - expected) > 0.01) return false;
    }
    return true;
}

/// The four-bar's `text` written to `file`, opened in `w` (shown), its crank driven for
/// 0.2 s, paused.
bool openACopyAndTurnTheCrank(MainWindow& w, const QString& file, const QString& text)
{
    if (!writeByRename(file, text) || !openAndWait(w, file)) return false;
    w.runner()->setCommand(w.bundle()->model->jointIndex(1), 1.0);
    return runFor(w, 0.2);
}

/// Another program writes `text` (other than the editor's) to the model's `file`; true
/// once the window has applied it.
bool writeAndWaitForTheReload(MainWindow& w, const QString& file, const QString& text)
{
    const quint64 serial = w.bundle()->serial;
    if (text == w.editor()->text() || !writeByRename(file, text)) return false;
    return QTest::qWaitFor([&] { return w.bundle()->serial != serial; }, 10000);
}

/// Settings ▸ Language ▸ `code`, as the user picks it.
void chooseLanguage(MainWindow& w, const QString& code)
{
    auto* action = w.findChild<QAction*>("Language_" + code);
    QVERIFY(action);
    action->trigger();
    QCOMPARE(i18n::current(), code);
    settle(100);  // the LanguageChange events are posted
}

}  // namespace

class AppModelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("PadrobTest");
        QCoreApplication::setApplicationName("padrob-studio-model-test");
        QSettings().clear();
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/recovery").removeRecursively();
        QVERIFY(i18n::install("en"));
    }

    // Item 8: paused, the sliders are the simulated state; a slider sets it (through the
    // runner), the view shows it, and Run continues from it.
    void theSlidersShowAndSetTheSimulatedState()
    {
        MainWindow w;
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        const solver::Model& m = *w.bundle()->model;
        const int lift = m.jointIndex(2), extension = m.jointIndex(3);
        // the boom rises and the telescope extends for a while
        w.runner()->setCommand(lift, 1.0);
        w.runner()->setCommand(extension, 1.0);
        QVERIFY(runFor(w, 0.3));
        const double t0 = w.runner()->latest()->t;
        QVERIFY(w.runner()->latest()->q[extension] > 0.01);
        QVERIFY(w.sliders()->isEnabled());
        QTRY_VERIFY(slidersShowTheSimulation(w));

        // a slider moved by hand: the simulation's state takes it (the time stays)
        int k = 0;
        while (k < w.sliders()->sliderCount() && w.sliders()->sliderJoint(k) != extension) ++k;
        QVERIFY(k < w.sliders()->sliderCount());
        QSlider* slider = w.sliders()->slider(k);
        slider->setValue(slider->maximum() / 2);
        const double wanted = w.sliders()->lower(k) + 0.5 * (w.sliders()->upper(k) - w.sliders()->lower(k));
        QTRY_VERIFY(std::abs(w.runner()->latest()->q[extension] - wanted) < 1e-6);
        const auto set = w.runner()->latest();
        QCOMPARE(set->t, t0);
        QCOMPARE(set->poseEdits, 1L);
        QVERIFY(std::abs(set->q[lift] - w.sliders()->coordinates()[lift]) < 1e-9);  // the others stay
        // the view shows the simulation's state (not a pose of the sliders' own)
        QTRY_VERIFY(w.viewports()->viewport(0)->poses().size() == std::size_t(m.nb) &&
                    w.viewports()->viewport(0)->poses()[std::size_t(extension)].isApprox(set->bodyPoses[std::size_t(extension)]));
        QTRY_VERIFY(slidersShowTheSimulation(w));

        // Run continues from there: the valves closed, the telescope holds where it was set
        w.runner()->setCommand(lift, 0.0);
        w.runner()->setCommand(extension, 0.0);
        QVERIFY(runFor(w, 0.2));
        const auto after = w.runner()->latest();
        QVERIFY(after->t > t0 + 0.15);
        QVERIFY2(std::abs(after->q[extension] - wanted) < 1e-3, qPrintable(QString::number(after->q[extension])));
        QTRY_VERIFY(slidersShowTheSimulation(w));
        // Reset goes back to the initial state, and the sliders with it
        w.reset();
        QTRY_VERIFY(w.runner()->latest()->t == 0 && slidersShowTheSimulation(w));
        QVERIFY(std::abs(w.sliders()->coordinates()[extension] - m.coordinate(extension, m.theta0[std::size_t(extension)])) < 1e-9);
    }

    // Item 8 with a closed loop: the pose sent is the sliders' closed one, every joint
    // (the dependent ones too), and the simulation runs on from it.
    void aSliderPoseOfALoopIsTheSimulationsState()
    {
        MainWindow w;
        QVERIFY(openAndWait(w, modelPath("four_bar.pad")));
        const solver::Model& m = *w.bundle()->model;
        const int crank = m.jointIndex(1);
        w.runner()->setCommand(crank, 1.0);
        QVERIFY(runFor(w, 0.2));
        QTRY_VERIFY(slidersShowTheSimulation(w));
        QCOMPARE(w.sliders()->sliderCount(), 1);
        const double from = w.sliders()->coordinates()[crank];
        const Eigen::VectorXd before = w.runner()->latest()->theta;
        w.sliders()->spinBox(0)->setValue((from - 0.5) * 180 / M_PI);  // half a radian back
        QTRY_VERIFY(w.runner()->latest()->poseEdits == 1);
        const auto s = w.runner()->latest();
        const double set = w.sliders()->spinBox(0)->value() * M_PI / 180;  // as the spin box rounded it
        QVERIFY(std::abs(set - (from - 0.5)) < 1e-3);
        QVERIFY2(std::abs(s->q[crank] - set) < 1e-6, qPrintable(QString("%1 %2").arg(s->q[crank]).arg(set)));
        const Eigen::VectorXd sliders = w.sliders()->theta();
        for (int j = 0; j < m.nb; ++j) QVERIFY(std::abs(s->theta[j] - sliders[j]) < 1e-6);
        QVERIFY(std::abs(s->theta[m.jointIndex(3)] - before[m.jointIndex(3)]) > 1e-3);  // the rocker followed
        QVERIFY(runFor(w, 0.02));
        QVERIFY(w.runner()->latest()->error.empty());
        const double now = w.runner()->latest()->q[crank];
        QVERIFY2(now > from - 0.5 && now < from - 0.2, qPrintable(QString::number(now - from)));  // on from the pose set
    }

    // Item 9a: a bar over the 3D view says that the editor's text is not applied, with
    // Apply and Revert; it goes when applied or reverted.
    void aBarSaysTheEditorsTextIsNotApplied()
    {
        MainWindow w;
        w.resize(1280, 720);
        QVERIFY(openAndWait(w, modelPath("pendulum.pad")));
        auto* bar = w.findChild<QWidget*>("UnappliedBar");
        auto* text = w.findChild<QLabel*>("UnappliedText");
        QVERIFY(bar && text);
        QVERIFY(bar->isHidden());
        const QString applied = w.editor()->text();
        const QString onTheMoon = QString(applied).replace("GRAVITY 0 0 -9.81", "GRAVITY 0 0 -1.62");
        QVERIFY(onTheMoon != applied);
        CodeEditor* editor = w.editor()->editor();
        editor->moveCursor(QTextCursor::End);
        QTest::keyClicks(editor, "// on the moon");
        QTRY_VERIFY(bar->isVisible());
        QVERIFY(text->text().contains("not applied"));
        settle(600);  // (the check is done: the editor's status line is settled)
        QVERIFY(w.grab().save(screenshotPath("app_model_not_applied_en.png")));
        chooseLanguage(w, "es");
        QTRY_VERIFY(text->text().contains("no aplicados"));
        QCOMPARE(w.findChild<QPushButton*>("UnappliedRevert")->text(), QStringLiteral("Revertir"));
        QVERIFY(w.grab().save(screenshotPath("app_model_not_applied_es.png")));
        chooseLanguage(w, "en");

        // Revert: the applied text again, no bar
        w.findChild<QPushButton*>("UnappliedRevert")->click();
        QCOMPARE(w.editor()->text(), applied);
        QTRY_VERIFY(bar->isHidden());
        // typed and deleted back to the applied text: no bar (after the check)
        editor->moveCursor(QTextCursor::End);
        QTest::keyClicks(editor, "x");
        QTRY_VERIFY(bar->isVisible());
        QTest::keyClick(editor, Qt::Key_Backspace);
        QTRY_VERIFY(bar->isHidden());
        // Apply on the bar: the new model runs, no bar
        w.editor()->setText(onTheMoon);
        QTRY_VERIFY(bar->isVisible());
        const quint64 before = w.bundle()->serial;
        w.findChild<QPushButton*>("UnappliedApply")->click();
        QTRY_VERIFY(w.bundle()->serial != before);
        QVERIFY(bar->isHidden());
        QCOMPARE(w.bundle()->model->gravity.z(), -1.62);
        // File ▸ New: the editor holds another (empty) model, the old one still shows
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTimer::singleShot(200, [] {  // the text typed is not saved: discard it
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
                box->button(QMessageBox::Discard)->click();
        });
        QTest::keyClick(&w, Qt::Key_N, Qt::ControlModifier);
        QTRY_VERIFY(w.editor()->filePath().isEmpty());
        QTRY_VERIFY(bar->isVisible());
        QCOMPARE(w.bundle()->model->nb, 1);  // still the pendulum
    }

    // Item 9b: File ▸ New does not put the new model in the last model's scene (which
    // comes back at the next start).
    void aNewModelLeavesTheScene()
    {
        MainWindow w;
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        QVERIFY(w.loadScene(QStringLiteral(PADROB_SOURCE_DIR) + "/resources/scenes/sag_mill.pad"));
        QVERIFY(w.viewports()->scene());
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTest::keyClick(&w, Qt::Key_N, Qt::ControlModifier);
        QTRY_VERIFY(w.editor()->filePath().isEmpty());
        QVERIFY(w.scenePath().isEmpty());
        QVERIFY(!w.viewports()->scene());
        QVERIFY(!w.viewports()->viewport(0)->scene());
        QVERIFY(QSettings().value("scene/last").toString().endsWith("sag_mill.pad"));
        // a model typed into it and applied runs without the mill
        w.editor()->setText(readText(modelPath("pendulum.pad")));
        w.editor()->apply();
        QTRY_VERIFY(w.bundle() && w.bundle()->model->nb == 1);
        QVERIFY(!w.viewports()->scene());
    }

    // Item 9c: with no model given the window opens the file opened last; a model given
    // wins; a last file that is gone gives the bundled liner manipulator.
    void theFileOpenedLastIsOpenedAgain()
    {
        {
            MainWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(openAndWait(w, modelPath("four_bar.pad")));
            QVERIFY(w.close());
        }
        {
            MainWindow w;
            w.openInitial(QString());
            QVERIFY(w.editor()->filePath().endsWith("four_bar.pad"));
            QTRY_VERIFY_WITH_TIMEOUT(w.bundle() && w.bundle()->model->nb == 3, 10000);  // (C 4 closes the loop)
        }
        {
            MainWindow w;
            w.openInitial(modelPath("pendulum.pad"));  // the command line's model
            QVERIFY(w.editor()->filePath().endsWith("pendulum.pad"));
        }
        QSettings().setValue("recentFiles", QStringList{QDir::temp().filePath("padrob-gone-model.pad")});
        MainWindow w;
        w.openInitial(QString());
        QVERIFY(w.editor()->filePath().endsWith("liner_manipulator_fluid.pad"));
    }

    // Item 16: another program writes the model's file: it is reloaded and applied, the
    // pose kept (the same joints) and the run resumed.
    void anExternalEditReloadsKeepingThePose()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("four_bar.pad"), text = readText(modelPath("four_bar.pad"));
        MainWindow w;
        QVERIFY(dir.isValid() && openACopyAndTurnTheCrank(w, file, text));
        const int nb = w.bundle()->model->nb;
        const Eigen::VectorXd pose = w.runner()->latest()->theta;
        // a heavier coupler, written by a rename (the watch must survive it)
        const QString heavier = QString(text).replace("B 2 0.7 ", "B 2 1.4 ");
        QVERIFY(writeAndWaitForTheReload(w, file, heavier));
        QCOMPARE(w.bundle()->model->mass[std::size_t(w.bundle()->model->bodyIndex(2))], 1.4);
        QCOMPARE(w.editor()->text(), heavier);
        QVERIFY(!w.editor()->isModified());
        QTRY_VERIFY(w.runner()->latest()->bundle == w.bundle() && w.runner()->latest()->poseEdits == 1);
        const Eigen::VectorXd kept = w.runner()->latest()->theta;
        // (the loop is closed again around the pose kept: equal to the closure's tolerance)
        for (int j = 0; j < nb; ++j)
            QVERIFY2(std::abs(kept[j] - pose[j]) < 1e-6, qPrintable(QString("joint %1: %2 kept, %3 before").arg(j).arg(kept[j], 0, 'g', 17).arg(pose[j], 0, 'g', 17)));
        QTRY_VERIFY(slidersShowTheSimulation(w));

        // again, while it runs: reloaded, and it runs on from the pose
        w.runner()->setCommand(w.bundle()->model->jointIndex(1), 1.0);
        w.run();
        QTRY_VERIFY(w.runner()->latest()->t > 0.05);
        QVERIFY(writeAndWaitForTheReload(w, file, text));
        QTRY_VERIFY(w.runner()->isRunning());
        QTRY_VERIFY(w.runner()->latest()->bundle == w.bundle() && w.runner()->latest()->poseEdits == 1 &&
                    w.runner()->latest()->t > 0.02);
        w.pause();
        QVERIFY(w.runner()->latest()->error.empty());
    }

    // Item 16: a change of the joints starts from the initial pose; unsaved edits are not
    // replaced without asking (a bar offers Reload).
    void aStructuralChangeStartsAtTheInitialPoseAndEditsAreKept()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("four_bar.pad"), text = readText(modelPath("four_bar.pad"));
        MainWindow w;
        QVERIFY(dir.isValid() && openACopyAndTurnTheCrank(w, file, text));
        // a joint renamed: the structure is not the same, the initial pose
        QVERIFY(writeAndWaitForTheReload(w, file, QString(text).replace("NAME \"crank pivot O2\"", "NAME \"crank pivot\"")));
        settle(200);
        const auto s = w.runner()->latest();
        QCOMPARE(s->poseEdits, 0L);
        QCOMPARE(s->t, 0.0);
        const int crank = w.bundle()->model->jointIndex(1);
        QVERIFY(std::abs(s->theta[crank] - w.bundle()->model->theta0[std::size_t(crank)]) < 1e-9);  // 60°
        QVERIFY(w.statusBar()->currentMessage().contains("initial pose"));

        // unsaved edits: the file changes, the edits stay, a bar offers Reload
        CodeEditor* editor = w.editor()->editor();
        editor->moveCursor(QTextCursor::End);
        QTest::keyClicks(editor, "// mine");
        QVERIFY(w.editor()->isModified());
        const quint64 serial2 = w.bundle()->serial;
        QVERIFY(writeByRename(file, text));
        auto* reloadBar = w.findChild<QWidget*>("ReloadBar");
        QVERIFY(reloadBar);
        QTRY_VERIFY_WITH_TIMEOUT(reloadBar->isVisible(), 5000);
        QVERIFY(w.editor()->text().endsWith("// mine"));
        QCOMPARE(w.bundle()->serial, serial2);
        QVERIFY(w.grab().save(screenshotPath("app_model_changed_on_disk_en.png")));
        chooseLanguage(w, "es");
        QTRY_COMPARE(w.findChild<QPushButton*>("ReloadButton")->text(), QStringLiteral("Recargar"));
        QVERIFY(w.grab().save(screenshotPath("app_model_changed_on_disk_es.png")));
        chooseLanguage(w, "en");
        w.findChild<QPushButton*>("ReloadButton")->click();
        QTRY_VERIFY_WITH_TIMEOUT(w.bundle()->serial != serial2, 10000);
        QCOMPARE(w.editor()->text(), text);
        QVERIFY(reloadBar->isHidden());
    }
};

QTEST_MAIN(AppModelTest)
#include "app_model_test.moc"
