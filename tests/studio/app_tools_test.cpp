// The Model workspace's tools, as a user meets them in padrob-studio (a real window
// under Xvfb), issue 25 items 14 and 17:
//  - the Simulation toolbar: Run, Pause, Step and Reset are the Simulation menu's own
//    actions (one step per Step, back to t = 0 on Reset), with icons and tips naming
//    their shortcuts, and the speed box sets the runner's rate and follows the menu;
//  - Keyboard Controls says which way each valve key moves its drive, and the mouse;
//  - View ▸ Record Video: about a second of the 3D view to an MP4 through ffmpeg,
//    checked with ffprobe (frames, size); refused over a folder, a pipe or the model
//    file (also through a link), and a clear message without ffmpeg. Under CI=true a
//    missing ffmpeg or ffprobe fails the test (scripts/install-deps.sh installs them).
// Screenshots in English and Spanish.

#include "tests/studio/main_window_test.h"
#include "ide/i18n/language.h"
#include "ide/studio/app/main_window.h"
#include "ide/studio/sim/simulation_runner.h"
#include "ide/studio/view/video_recorder.h"
#include "ide/studio/view/viewport.h"
#include "ide/studio/view/viewport_layout.h"
#include "trainer/station/station.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QMessageBox>
#include <QProcess>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QToolButton>

#include <cmath>

#include <sys/stat.h>

using namespace studio;
using studio::test::chooseLanguage;
using studio::test::openAndWait;
using studio::test::screenshotPath;

namespace {

QString modelPath(const QString& name) { return QStringLiteral(PADROB_SOURCE_DIR) + "/models/" + name; }

/// The toolbar's button of an action.
QToolButton* button(QToolBar* bar, const char* action)
{
    return qobject_cast<QToolButton*>(bar->widgetForAction(bar->parentWidget()->window()->findChild<QAction*>(action)));
}

long stepOf(const MainWindow& w)
{
    const auto s = w.runner()->latest();
    return s ? s->step : -1;
}

}  // namespace

class AppToolsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("PadrobTest");
        QCoreApplication::setApplicationName("padrob-studio-tools-test");
        QSettings().clear();
        QVERIFY(i18n::install("en"));
    }

    void theToolbarRunsPausesStepsResetsAndSetsTheSpeed()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        auto* bar = w.findChild<QToolBar*>("SimulationBar");
        QVERIFY(bar && bar->isVisible());
        // the menu's own actions, not copies
        auto* run = w.findChild<QAction*>("RunAction");
        QVERIFY(run && bar->actions().contains(run));
        for (const char* name : {"PauseAction", "StepAction", "ResetAction"})
            QVERIFY(bar->actions().contains(w.findChild<QAction*>(name)));
        QVERIFY(!run->icon().isNull());
        QCOMPARE(run->toolTip(), QStringLiteral("Run (F5)"));
        QCOMPARE(w.findChild<QAction*>("StepAction")->toolTip(), QStringLiteral("Step (F10)"));
        QToolButton* runButton = button(bar, "RunAction");
        QToolButton* pauseButton = button(bar, "PauseAction");
        QToolButton* stepButton = button(bar, "StepAction");
        QToolButton* resetButton = button(bar, "ResetAction");
        QVERIFY(runButton && pauseButton && stepButton && resetButton);
        QVERIFY(!pauseButton->isEnabled());

        // Step: exactly one step at a time
        QTRY_VERIFY(stepOf(w) == 0);
        QTest::mouseClick(stepButton, Qt::LeftButton);
        QTRY_COMPARE(stepOf(w), 1L);
        QTest::mouseClick(stepButton, Qt::LeftButton);
        QTRY_COMPARE(stepOf(w), 2L);
        QTest::qWait(100);
        QCOMPARE(stepOf(w), 2L);
        // Run, then Pause
        QTest::mouseClick(runButton, Qt::LeftButton);
        QTRY_VERIFY(w.runner()->isRunning());
        QTRY_VERIFY(pauseButton->isEnabled() && !runButton->isEnabled() && !stepButton->isEnabled());
        QTRY_VERIFY(stepOf(w) > 50);
        QTest::mouseClick(pauseButton, Qt::LeftButton);
        QTRY_VERIFY(!w.runner()->isRunning());
        QTRY_VERIFY(runButton->isEnabled() && stepButton->isEnabled());
        // Reset: back to the start
        QTest::mouseClick(resetButton, Qt::LeftButton);
        QTRY_COMPARE(stepOf(w), 0L);

        // the speed box sets the runner's rate, and follows Simulation ▸ Speed
        auto* speed = w.findChild<QComboBox*>("SpeedBox");
        QVERIFY(speed && speed->isVisible());
        QCOMPARE(speed->count(), 6);
        QCOMPARE(speed->currentData().toDouble(), 1.0);
        const int twice = speed->findData(2.0);
        QVERIFY(twice >= 0);
        speed->setCurrentIndex(twice);
        emit speed->activated(twice);  // as a user's choice
        QCOMPARE(w.runner()->speed(), 2.0);
        QAction* half = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->text() == QStringLiteral("×0.5")) half = a;
        QVERIFY(half);
        half->trigger();
        QCOMPARE(w.runner()->speed(), 0.5);
        QCOMPARE(speed->currentText(), QStringLiteral("×0.5"));
        // run at ×0.5: the simulated time goes at about half the wall clock's pace
        run->trigger();
        QTRY_VERIFY(w.runner()->isRunning());
        QTRY_VERIFY(w.runner()->latest()->realTimeFactor > 0.3 && w.runner()->latest()->realTimeFactor < 0.7);
        w.findChild<QAction*>("PauseAction")->trigger();
        QTRY_VERIFY(!w.runner()->isRunning());
        QVERIFY(w.grab().save(screenshotPath("app_toolbar_en.png")));
        chooseLanguage(w, "es");
        QCOMPARE(run->toolTip(), QStringLiteral("Iniciar (F5)"));
        QCOMPARE(speed->currentText(), QStringLiteral("×0,5"));
        QVERIFY(w.grab().save(screenshotPath("app_toolbar_es.png")));
        chooseLanguage(w, "en");
    }

    // Keyboard Controls: each valve key's drive and which way it moves it, and the mouse
    void keyboardControlsSayTheDirectionsAndTheMouse()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, modelPath("liner_manipulator.pad")));
        QTRY_VERIFY(w.station()->latest() && w.station()->latest()->drives.size() == 9);
        w.findChild<QAction*>("KeyboardControlsAction")->trigger();
        QMessageBox* box = nullptr;
        QTRY_VERIFY((box = w.findChild<QMessageBox*>("KeyboardControlsBox")) && box->isVisible());
        const QString text = box->text();
        // C 1 GIRO PLUMA turns, C 2 LEVANTE PLUMA is a cylinder (T 1), C 3 EXTENSIÓN slides (T 2)
        QVERIFY2(text.contains("GIRO PLUMA&nbsp;&nbsp;</td><td>Q: turns + · A: turns −"), qPrintable(text));
        QVERIFY2(text.contains("LEVANTE PLUMA&nbsp;&nbsp;</td><td>W: cylinder out · S: cylinder in"), qPrintable(text));
        QVERIFY2(text.contains("EXTENSIÓN&nbsp;&nbsp;</td><td>E: slides + · D: slides −"), qPrintable(text));
        // the mouse, as CameraController does it
        for (const char* part : {"Left drag", "orbits", "Shift + left drag", "pans", "Wheel", "zooms towards the cursor",
                                 "Double click", "Ctrl + left drag on a body", "picks the body"})
            QVERIFY2(text.contains(QString::fromUtf8(part)), part);
        QVERIFY(box->grab().save(screenshotPath("app_keyboard_directions_en.png")));
        box->close();
        chooseLanguage(w, "es");
        w.findChild<QAction*>("KeyboardControlsAction")->trigger();
        QTRY_VERIFY((box = w.findChild<QMessageBox*>("KeyboardControlsBox")) && box->isVisible());
        QVERIFY2(box->text().contains("W: sale el cilindro · S: entra el cilindro"), qPrintable(box->text()));
        QVERIFY(box->text().contains("Rueda"));
        QVERIFY(box->grab().save(screenshotPath("app_keyboard_directions_es.png")));
        box->close();
        chooseLanguage(w, "en");
    }

    void recordsAVideoOfTheView()
    {
        const QString ffprobe = QStandardPaths::findExecutable("ffprobe");
        if (QStandardPaths::findExecutable("ffmpeg").isEmpty() || ffprobe.isEmpty()) {
            if (qEnvironmentVariable("CI") == QLatin1String("true"))
                QFAIL("ffmpeg and ffprobe are needed (package ffmpeg, scripts/install-deps.sh)");
            QSKIP("ffmpeg or ffprobe is not installed (package ffmpeg)");
        }
        QTemporaryDir dir;
        // the model under a video's name, so that only the check keeps it from being overwritten
        const QString model = dir.filePath("liner.mkv");
        QVERIFY(QFile::copy(modelPath("liner_manipulator.pad"), model));
        MainWindow w;
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(openAndWait(w, model));
        QAction* record = w.findChild<QAction*>("RecordVideoAction");
        QVERIFY(record);
        QCOMPARE(record->text(), QStringLiteral("&Record Video…"));

        // refusals, each saying why
        QString error;
        QVERIFY(!w.startRecording(model, &error));
        QVERIFY2(error.contains("not overwritten"), qPrintable(error));
        QVERIFY(QFile::link(model, dir.filePath("link.mp4")));
        QVERIFY(!w.startRecording(dir.filePath("link.mp4"), &error));
        QVERIFY2(error.contains("model"), qPrintable(error));
        QVERIFY(QDir(dir.path()).mkdir("folder.mp4"));
        QVERIFY(!w.startRecording(dir.filePath("folder.mp4"), &error));
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
        QCOMPARE(::mkfifo(QFile::encodeName(dir.filePath("pipe.mp4")).constData(), 0600), 0);
        QVERIFY(!w.startRecording(dir.filePath("pipe.mp4"), &error));
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
        w.recorder()->setProgram(dir.filePath("no-ffmpeg-here"));
        QVERIFY(!w.startRecording(dir.filePath("clip.mp4"), &error));
        QVERIFY2(error.contains("ffmpeg") && error.contains("apt install ffmpeg"), qPrintable(error));
        QVERIFY(!QFile::exists(dir.filePath("clip.mp4")));
        w.recorder()->setProgram(QString());
        QVERIFY(!w.findChild<QLabel*>("RecordingLabel")->isVisible());

        // about a second of the running machine
        const QString clip = dir.filePath("clip");  // (".mp4" is added)
        QElapsedTimer clock;
        clock.start();
        const Viewport* v = w.viewports()->viewport(0);
        const QSize viewSize = v->size() * v->devicePixelRatio();  // (the first frame's: the video's)
        QVERIFY2(w.startRecording(clip, &error), qPrintable(error));
        QVERIFY(w.recorder()->isRecording());
        QCOMPARE(w.recorder()->path(), clip + ".mp4");
        auto* label = w.findChild<QLabel*>("RecordingLabel");
        QTRY_VERIFY(label->isVisible());
        QVERIFY(label->text().startsWith("● REC 0:0"));
        QCOMPARE(record->text(), QStringLiteral("Stop &Recording"));
        w.run();
        QTest::qWait(700);
        QVERIFY(w.grab().save(screenshotPath("app_recording_en.png")));
        chooseLanguage(w, "es");
        QVERIFY(label->text().startsWith("● GRAB 0:0"));
        QVERIFY(w.grab().save(screenshotPath("app_recording_es.png")));
        chooseLanguage(w, "en");
        QTRY_VERIFY(w.recorder()->seconds() >= 1.0);
        QSignalSpy finished(w.recorder(), &VideoRecorder::finished);
        record->trigger();  // Stop Recording
        const double elapsed = clock.nsecsElapsed() * 1e-9;
        QVERIFY(!label->isVisible());
        QVERIFY(finished.wait(15000));
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(finished.at(0).at(1).toString()));
        w.pause();
        const long frames = w.recorder()->frames();
        const QSize size = w.recorder()->frameSize();
        // 25 frames a second of the wall clock, whatever the drawing took
        QVERIFY2(frames >= 25 && std::abs(frames - 25 * elapsed) <= 0.1 * 25 * elapsed + 2,
                 qPrintable(QString("%1 frames in %2 s").arg(frames).arg(elapsed)));

        // what ffprobe reads in the file: every frame written, at the view's size
        QProcess probe;
        probe.start(ffprobe, {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                              "stream=width,height,nb_read_frames,codec_name", "-of", "csv=p=0", clip + ".mp4"});
        QVERIFY(probe.waitForFinished(20000));
        const QStringList fields = QString::fromUtf8(probe.readAllStandardOutput()).trimmed().split(',');
        QCOMPARE(fields.size(), 4);
        QCOMPARE(fields[0], QStringLiteral("h264"));
        QCOMPARE(fields[1].toInt(), size.width());
        QCOMPARE(fields[2].toInt(), size.height());
        QVERIFY(viewSize.width() - size.width() <= 1 && viewSize.height() - size.height() <= 1);
        QVERIFY(size.width() % 2 == 0 && size.height() % 2 == 0);
        QVERIFY(std::abs(fields[3].toLong() - frames) <= 1);
        QCOMPARE(record->text(), QStringLiteral("&Record Video…"));
    }
};

QTEST_MAIN(AppToolsTest)
#include "app_tools_test.moc"
