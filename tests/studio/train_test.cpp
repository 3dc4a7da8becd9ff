// The Train workspace as a trainee meets it (a real window under Xvfb): the course
// lists T0; its start screen plays the demonstration (pause, speed, seek); a live
// attempt takes the keyboard through the station and shows the goal and the time on
// the HUD, and Stop ends it; an attempt driven by the demonstration's input log
// passes, and the debrief shows the force plot, the timeline and the comparison with
// the expert; kiosk mode opens full screen without the mode bar and menus, and
// Ctrl+Shift+F12 (with the PIN when one is set) leaves it. The trainer's records view
// (operators, attempts, chart, CSV, adding an operator; records that cannot be opened:
// the attempt goes to a pending file, imported at the next opening); the expert's
// ghost beside a live attempt; a live attempt's recorded input saved as the stage's
// demonstration replays headless to the same result. The language at run time: the
// course screen's "Español" / "English" (in kiosk mode too) re-word the course, the
// start screen, the HUD and the result at once, numbers with the decimal comma in
// Spanish. Screenshots of the course, the kiosk's course screen, the start screen, the
// HUD, the result, the debrief and the records, in English and in Spanish (every
// tutorial's start, HUD and result: train_shots_test).

#include "tests/studio/gui_test.h"
#include "ide/paths/paths.h"
#include "ide/i18n/language.h"
#include "ide/studio/app/main_window.h"
#include "ide/studio/train/pin_dialog.h"
#include "ide/studio/train/records_view.h"
#include "ide/studio/train/train_page.h"
#include "ide/studio/train/tutorial_runner.h"
#include "ide/studio/view/viewport.h"
#include "trainer/station/station.h"
#include "trainer/training/camera_path.h"
#include "trainer/training/runner.h"
#include "trainer/training/tutorial.h"

#include <algorithm>
#include <cmath>

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QLegend>
#include <QLegendMarker>
#include <QValueAxis>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QListWidget>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QSlider>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTest>
#include <QToolBar>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <memory>

using namespace studio;
using studio::test::screenshotPath;
using studio::test::settle;

class TrainTest : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> m_window;
    TrainPage* page() const { return m_window->trainPage(); }

    /// A fresh window on the Train workspace.
    void openWindow()
    {
        m_window = std::make_unique<MainWindow>();
        m_window->openInitial(QString());
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        m_window->setWorkspace(MainWindow::Workspace::Train);
        settle();
    }

    /// An attempt driven by the demonstration's log, at 4× to spare time; waits for the result.
    void passWithTheDemonstration()
    {
        QVERIFY(page()->openTutorial("T0"));
        QVERIFY(page()->demoLog());
        page()->startAttempt(page()->demoLog());
        m_window->tutorialRunner()->setSpeed(4.0);
        QCOMPARE(page()->screen(), TrainPage::Screen::Attempt);
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 120000);
        QVERIFY(page()->lastRun());
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("PadrobTest");
        QCoreApplication::setApplicationName("padrob-studio-train-test");
        QSettings().clear();
        // fresh trainee records (the test location's SQLite file) and no pending attempts
        const QString db = trainer::records::RecordsDb::defaultSqlitePath();
        for (const char* suffix : {"", "-wal", "-shm"}) QFile::remove(db + suffix);
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/pending-attempts").removeRecursively();
        QVERIFY(i18n::install("en"));
        openWindow();
    }

    void cleanupTestCase()
    {
        m_window.reset();
        i18n::install("en");
    }

    // the tutorial compiles its model and scene once; the workspace draws and runs those
    // (no second compile), and the targets join the scene as graphics of the ground
    void tutorialBundlesReuseTheTutorialsCompiledModel()
    {
        solver::Diagnostics diags;
        const auto t = trainer::loadTutorial(PADROB_SOURCE_DIR "/resources/tutorials/t7_mill.tut", diags);
        QVERIFY(t);
        QVERIFY(t->compiled && t->scene);
        const auto bundle = makeTutorialBundle(*t);
        QVERIFY(bundle);
        QCOMPARE(bundle->compiled.get(), t->compiled.get());
        QCOMPARE(bundle->model.get(), t->model.get());
        QCOMPARE(&bundle->spec(), t->modelSpec.get());

        const auto scene = makeTutorialScene(*t);
        QVERIFY(scene);
        int targets = 0;
        for (const trainer::Goal& g : t->spec.goals)
            targets += g.kind == trainer::Goal::Kind::Reach || g.kind == trainer::Goal::Kind::Place ? 1 : 0;
        QVERIFY(targets > 0);
        QCOMPARE(scene->spec().graphics.size(), t->sceneSpec->graphics.size() + std::size_t(3 * targets));
        const solver::GraphicSpec& sphere = scene->spec().graphics[t->sceneSpec->graphics.size()];
        QCOMPARE(sphere.id, 900000);
        QCOMPARE(sphere.shape, solver::ShapeKind::Sphere);
        QCOMPARE(sphere.body, 0);
        QVERIFY(sphere.color.isApprox(Eigen::Vector3d(0.15, 0.75, 0.25)));
        const solver::GraphicSpec& cone = scene->spec().graphics[t->sceneSpec->graphics.size() + 2];
        QCOMPARE(cone.shape, solver::ShapeKind::Cone);
        QVERIFY(cone.axis.isApprox(Eigen::Vector3d(0, 0, -1)));
        QVERIFY(cone.position.z() > sphere.position.z());
    }

    void courseListsTheTutorials()
    {
        QListWidget* list = page()->courseList();
        QVERIFY(list->count() >= 1);
        QListWidgetItem* t0 = list->item(0);
        QVERIFY(t0->text().contains("Reach a target"));
        QVERIFY(t0->flags() & Qt::ItemIsEnabled);
        QCOMPARE(t0->data(Qt::UserRole).toString(), QString("T0"));
        // the next level is locked until T0 is passed
        if (list->count() > 1) {
            QVERIFY(!(list->item(1)->flags() & Qt::ItemIsEnabled));
            QVERIFY(!page()->openTutorial(list->item(1)->data(Qt::UserRole).toString()));
        }
        QVERIFY(m_window->grab().save(screenshotPath("train_course_en.png")));
    }

    void brokenTutorialIsListedDisabled()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile good(QStringLiteral(PADROB_SOURCE_DIR) + "/resources/tutorials/t0_reach.tut");
        QVERIFY(good.open(QIODevice::ReadOnly));
        QString text = QString::fromUtf8(good.readAll());
        text.replace("../../models", QStringLiteral(PADROB_SOURCE_DIR) + "/models");
        text.replace("\"t0_reach.demo.log\"", "\"" PADROB_SOURCE_DIR "/resources/tutorials/t0_reach.demo.log\"");
        QFile copy(dir.filePath("t0.tut"));
        QVERIFY(copy.open(QIODevice::WriteOnly));
        copy.write(text.toUtf8());
        copy.close();
        QFile broken(dir.filePath("t1_broken.tut"));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("TUTORIAL T1 LEVEL 1\nTITLE ES \"Roto\" EN \"Broken\"\nMODEL \"nowhere.pad\"\n");
        broken.close();
        page()->setTutorialsDir(dir.path());
        QListWidget* list = page()->courseList();
        QCOMPARE(list->count(), 2);
        QVERIFY(list->item(0)->flags() & Qt::ItemIsEnabled);
        QVERIFY(!(list->item(1)->flags() & Qt::ItemIsEnabled));
        QVERIFY(!list->item(1)->toolTip().isEmpty());
        page()->setTutorialsDir(paths::tutorialsDir());
    }

    void startScreenPlaysTheDemonstration()
    {
        QVERIFY(page()->openTutorial("T0"));
        QCOMPARE(page()->screen(), TrainPage::Screen::Start);
        settle(500);
        QVERIFY(m_window->grab().save(screenshotPath("train_start_en.png")));
        page()->watchDemonstration();
        TutorialRunner* runner = m_window->tutorialRunner();
        QTRY_VERIFY_WITH_TIMEOUT(runner->latest() && runner->latest()->snapshot->t > 0.5, 10000);
        QVERIFY(runner->latest()->duration > 5.0);
        // seek forward, then back: the same input gives the same state
        runner->setPaused(true);
        runner->seek(6.0);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(runner->latest()->snapshot->t - 6.0) < 0.01, 30000);
        const Eigen::VectorXd at6 = runner->latest()->snapshot->theta;
        runner->seek(2.0);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(runner->latest()->snapshot->t - 2.0) < 0.01, 30000);
        runner->seek(6.0);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(runner->latest()->snapshot->t - 6.0) < 0.01, 30000);
        QVERIFY((runner->latest()->snapshot->theta - at6).norm() < 1e-12);
        // speed 2: simulated time runs faster than the wall clock
        runner->setSpeed(2.0);
        runner->setPaused(false);
        const double t0 = runner->latest()->snapshot->t;
        QTest::qWait(1000);
        const double advanced = runner->latest()->snapshot->t - t0;
        QVERIFY2(advanced > 1.2, qPrintable(QString::number(advanced)));
        settle();
        QVERIFY(page()->demoSlider()->value() > 60);
        // the view follows the expert's recorded camera (DEMO … CAMERA)
        trainer::CameraPath path;
        QString error;
        QVERIFY2(trainer::CameraPath::load(QString::fromStdString(std::string(PADROB_SOURCE_DIR) +
                                                                  "/resources/tutorials/t0_reach.demo.cam"),
                                           path, &error),
                 qPrintable(error));
        runner->setPaused(true);
        settle();
        const trainer::CameraKey key = path.at(runner->latest()->snapshot->t);
        const Camera& cam = page()->demoViewport()->cameraState();
        QVERIFY2((cam.target - key.target).norm() < 1e-6, qPrintable(QString::number((cam.target - key.target).norm())));
        QCOMPARE(cam.distance, key.distance);
        QVERIFY(m_window->grab().save(screenshotPath("train_demo_en.png")));
    }

    void liveAttemptTakesTheKeyboardAndShowsTheHud()
    {
        QVERIFY(page()->openTutorial("T0"));
        page()->startAttempt();
        QCOMPARE(page()->screen(), TrainPage::Screen::Attempt);
        TutorialRunner* runner = m_window->tutorialRunner();
        QVERIFY(runner->wantsCommands());
        QTRY_VERIFY_WITH_TIMEOUT(runner->latest() && runner->latest()->snapshot->t > 0.3, 10000);
        // the station's keyboard: Q opens the first drive (C 1, the slew) while held
        Viewport* view = page()->attemptViewport();
        view->setFocus();
        const double before = runner->latest()->snapshot->theta[0];
        QTest::keyPress(view, Qt::Key_Q);
        QTest::qWait(800);
        QTest::keyRelease(view, Qt::Key_Q);
        settle();
        const double after = runner->latest()->snapshot->theta[0];
        QVERIFY2(std::abs(after - before) > 1e-3, qPrintable(QString("%1 → %2").arg(before).arg(after)));
        // the HUD: the goal's name, the time against the limit, the distance
        const QString hud = page()->hud()->text();
        QVERIFY2(hud.contains("Bring the claws to the green sphere"), qPrintable(hud));
        QVERIFY2(hud.contains("Time:") && hud.contains("/ 120 s"), qPrintable(hud));
        QVERIFY2(hud.contains("Distance:"), qPrintable(hud));
        QVERIFY(page()->hud()->font().pixelSize() >= 20 || page()->hud()->fontInfo().pixelSize() >= 20);
        // the station's profile (Gamepad) has no gamepad here: the attempt's HUD says so
        // and what drives instead (issue 25, item 5)
        auto* warnings = page()->findChild<QLabel*>("TrainWarnings");
        QVERIFY(warnings);
        QTRY_VERIFY2(warnings->isVisible() && warnings->text().contains("Gamepad missing — the keyboard drives instead"),
                     qPrintable(warnings->text()));
        QVERIFY(m_window->grab().save(screenshotPath("train_hud_en.png")));
        // Esc ends it: a result, not passed
        QTest::keyClick(view, Qt::Key_Escape);
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 5000);
        QVERIFY(!runner->wantsCommands());
        QCOMPARE(page()->lastRun()->result.endReason, std::string("aborted"));
        QVERIFY(!page()->lastRun()->result.passed);
        QVERIFY(page()->resultHeading()->text().contains("NOT PASSED"));
    }

    void demonstrationDrivenAttemptPasses()
    {
        passWithTheDemonstration();
        const trainer::TutorialResult& r = page()->lastRun()->result;
        QVERIFY2(r.passed, r.endReason.c_str());
        QCOMPARE(page()->resultHeading()->text(), QString("PASSED"));
        QCOMPARE(page()->breakdownTable()->rowCount(), int(r.breakdown.size()));
        QVERIFY(r.breakdown.size() >= 4);
        // the next stage is unlocked now
        QPushButton* next = m_window->findChild<QPushButton*>("NextButton");
        QCOMPARE(next->isEnabled(), page()->courseList()->count() > 1);
        QVERIFY(m_window->grab().save(screenshotPath("train_result_en.png")));
        // the course remembers the stars
        page()->showCourse();
        QVERIFY(page()->courseList()->item(0)->text().contains(QChar(0x2605)));
        QCOMPARE(page()->progressOf("T0").passed, true);
        // in the trainee records: the guest's attempts at T0, the aborted one and the passed one
        trainer::records::RecordsDb* records = page()->records();
        QVERIFY2(records, qPrintable(page()->recordsProblem()));
        trainer::records::Operator guest;
        QVERIFY(records->findOperator("guest", guest));
        QList<trainer::records::Attempt> attempts;
        QVERIFY(records->attemptsOf(guest.id, attempts));
        QCOMPARE(attempts.size(), 2);
        QCOMPARE(attempts[0].tutorialId, QString("T0"));  // newest first
        QVERIFY(attempts[0].passed);
        QCOMPARE(attempts[0].status, trainer::records::AttemptStatus::Finished);
        QVERIFY(!attempts[0].events.isEmpty());
        QCOMPARE(attempts[1].status, trainer::records::AttemptStatus::Aborted);
        QCOMPARE(page()->progressOf("T0").attempts, 2);
        if (page()->courseList()->count() > 1) {
            QVERIFY(page()->courseList()->item(1)->flags() & Qt::ItemIsEnabled);
            QVERIFY(page()->openTutorial("T0"));
            passWithTheDemonstration();
            next->click();
            QCOMPARE(page()->screen(), TrainPage::Screen::Start);
            QVERIFY(page()->tutorial()->spec.level >= 1);
        }
    }

    void debriefShowsThePlotTheTimelineAndTheExpert()
    {
        QVERIFY(page()->openTutorial("T0"));
        passWithTheDemonstration();
        page()->showDebrief();
        QCOMPARE(page()->screen(), TrainPage::Screen::Debrief);
        QChart* chart = page()->forceChart()->chart();
        QVERIFY(chart);
        QCOMPARE(chart->series().size(), 2);  // the force, and the replay cursor
        auto* series = qobject_cast<QLineSeries*>(chart->series().first());
        QVERIFY(series && series->count() > 100);
        QVERIFY(chart->title().contains("C 2"));  // the lift cylinder carries the most
        QVERIFY(page()->timeline()->count() >= 1);
        QTRY_VERIFY_WITH_TIMEOUT(page()->expertRun(), 60000);
        QTableWidget* cmp = page()->comparisonTable();
        QCOMPARE(cmp->rowCount(), 5);
        bool ok = false;
        QLocale().toDouble(cmp->item(4, 2)->text(), &ok);
        QVERIFY2(ok, qPrintable(cmp->item(4, 2)->text()));
        // the same input, the same run: the expert's score is the attempt's
        QCOMPARE(cmp->item(4, 1)->text(), cmp->item(4, 2)->text());
        // a click on the goal's event seeks the replay there
        QListWidgetItem* last = page()->timeline()->item(page()->timeline()->count() - 1);
        const QRect rect = page()->timeline()->visualItemRect(last);
        QTest::mouseClick(page()->timeline()->viewport(), Qt::LeftButton, {}, rect.center());
        QTRY_VERIFY(page()->replaySlider()->value() > 0);
        // the replay cursor: a vertical line at the replay's time, across the chart
        auto* cursor = qobject_cast<QLineSeries*>(chart->series().at(1));
        QVERIFY(cursor && cursor->objectName() == "ReplayCursor" && cursor->count() == 2);
        const auto cursorAtTheReplay = [&] {
            const double t = page()->lastRun()->samples[std::size_t(page()->replaySlider()->value())].t;
            return t > 0 && cursor->at(0).x() == t && cursor->at(1).x() == t;
        };
        QTRY_VERIFY(cursorAtTheReplay());
        auto* y = qobject_cast<QValueAxis*>(chart->axes(Qt::Vertical).front());
        QCOMPARE(cursor->at(0).y(), y->min());
        QCOMPARE(cursor->at(1).y(), y->max());
        page()->replaySlider()->setValue(page()->replaySlider()->value() / 2);  // scrubbing moves it
        QTRY_VERIFY(cursorAtTheReplay());
        settle(500);
        QVERIFY(m_window->grab().save(screenshotPath("train_debrief_en.png")));
    }

    void recordsViewShowsOperatorsAttemptsAndChart()
    {
        page()->showCourse();
        QPushButton* button = page()->recordsButton();
        QVERIFY(button->isVisible());
        button->click();
        QCOMPARE(page()->screen(), TrainPage::Screen::Records);
        RecordsView* view = page()->recordsView();
        QVERIFY(!view->message()->isVisible());
        QTableWidget* ops = view->operatorsTable();
        QVERIFY(ops->rowCount() >= 1);
        QVERIFY(view->selectOperator("guest"));
        const int row = ops->currentRow();
        QCOMPARE(ops->item(row, 0)->text(), QString("guest"));
        QVERIFY(ops->item(row, 2)->text().toInt() >= 3);  // attempts
        QCOMPARE(ops->item(row, 3)->text().toInt(), 1);   // tutorials passed: T0
        // the attempts, newest first, with the newest one's breakdown and events
        QTableWidget* attempts = view->attemptsTable();
        QCOMPARE(attempts->rowCount(), ops->item(row, 2)->text().toInt());
        const int guestAttempts = attempts->rowCount();
        QVERIFY(attempts->item(0, 2)->text().contains("passed"));
        QVERIFY(view->breakdownTable()->rowCount() >= 4);
        QVERIFY(view->eventsList()->count() >= 1);
        // the chart: T0's scores and its pass mark
        QChart* chart = view->chartView()->chart();
        QCOMPARE(chart->series().size(), 2);
        auto* scores = qobject_cast<QLineSeries*>(chart->series().at(0));
        QVERIFY(scores && scores->count() == attempts->rowCount());
        QVERIFY(chart->series().at(1)->name().contains("pass mark"));
        // the pass mark's colour is never an attempt's: the legend tells them apart
        auto* mark = qobject_cast<QLineSeries*>(chart->series().at(1));
        QCOMPARE(mark->objectName(), QString("PassMark"));
        QCOMPARE(mark->pen().style(), Qt::DashLine);
        QVERIFY(mark->color() != scores->color());
        QVERIFY(chart->legend()->isVisible());
        QCOMPARE(chart->legend()->markers().size(), 2);
        QVERIFY(chart->legend()->markers().at(0)->brush().color() != chart->legend()->markers().at(1)->brush().color());
        // an older attempt: its own breakdown (the aborted one has one too)
        attempts->setCurrentCell(attempts->rowCount() - 1, 0);
        QVERIFY(view->eventsList()->count() >= 1);
        // adding an operator; a code taken is refused
        const int before = ops->rowCount();
        QString error;
        QVERIFY2(view->addOperator("B-17", "Ana Pérez", &error), qPrintable(error));
        QCOMPARE(ops->rowCount(), before + 1);
        QCOMPARE(ops->item(ops->currentRow(), 1)->text(), QString("Ana Pérez"));
        QCOMPARE(view->attemptsTable()->rowCount(), 0);
        QVERIFY(!view->addOperator("B-17", "again", &error));
        QVERIFY(!error.isEmpty());
        // Export CSV: a header and a row per attempt
        QTemporaryDir dir;
        const QString csv = dir.filePath("attempts.csv");
        QVERIFY2(view->exportCsv(csv, &error), qPrintable(error));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(file.readAll()).split("\r\n", Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 1 + guestAttempts);  // only the guest has attempts
        // said where it went; the status as the studio names it; one title per tutorial,
        // in the studio's language
        QVERIFY(view->exportStatus()->isVisible());
        QVERIFY2(view->exportStatus()->text().contains(QString("Wrote %1 attempts to").arg(guestAttempts)),
                 qPrintable(view->exportStatus()->text()));
        QVERIFY(view->exportStatus()->text().contains(QDir::toNativeSeparators(csv)));
        const QString all = lines.join('\n');
        QVERIFY2(all.contains(",stopped,") && !all.contains(",aborted,"), qPrintable(all));
        for (const QString& line : lines.mid(1)) QVERIFY2(line.contains(",T0,Reach a target,"), qPrintable(line));
        QVERIFY(view->selectOperator("guest"));
        settle();
        // dates with the year's four digits
        const QString year = QString::number(QDate::currentDate().year());
        QVERIFY(attempts->rowCount() > 0 && attempts->item(0, 0));
        QVERIFY2(attempts->item(0, 0)->text().contains(year), qPrintable(attempts->item(0, 0)->text()));
        QVERIFY(m_window->grab().save(screenshotPath("train_records_en.png")));
        page()->showCourse();
        // in kiosk mode: hidden without a PIN
        m_window->setKioskMode(true);
        settle();
        QVERIFY(!page()->recordsButton()->isVisible());
        m_window->setKioskMode(false);
        settle();
        QVERIFY(page()->recordsButton()->isVisible());
    }

    // Issue 25 item 17: the attempt on three screens side by side (the seat at −60°, 0°,
    // +60°, dark separators between them), chosen in the View box and remembered; the
    // keys stay with the middle screen
    void threeScreensInTheAttempt()
    {
        QVERIFY(page()->openTutorial("T0"));
        page()->startAttempt();
        QCOMPARE(page()->screen(), TrainPage::Screen::Attempt);
        TutorialRunner* runner = m_window->tutorialRunner();
        QTRY_VERIFY_WITH_TIMEOUT(runner->latest() && runner->latest()->snapshot->t > 0.3, 10000);
        auto* camera = m_window->findChild<QComboBox*>("AttemptCamera");
        QVERIFY(camera);
        const int three = camera->findData("ThreeScreens");
        QVERIFY(three >= 0);
        QCOMPARE(camera->itemText(three), QString("Three screens (−60°, 0°, +60°)"));
        camera->setCurrentIndex(three);
        emit camera->activated(three);  // as a user's choice
        Viewport* middle = page()->attemptViewport();
        auto* left = m_window->findChild<Viewport*>("AttemptLeftScreen");
        auto* right = m_window->findChild<Viewport*>("AttemptRightScreen");
        QVERIFY(left && right);
        QTRY_VERIFY(left->isVisible() && right->isVisible());
        QVERIFY(QSettings().value("trainer/threeScreens").toBool());
        for (Viewport* v : {left, middle, right}) QCOMPARE(v->camera(), QString("Operator seat"));
        QVERIFY(std::abs(left->yawOffset() + M_PI / 3) < 1e-12);
        QCOMPARE(middle->yawOffset(), 0.0);
        QVERIFY(std::abs(right->yawOffset() - M_PI / 3) < 1e-12);
        // side by side, about as wide, a visible separator between neighbours
        const auto x = [&](QWidget* w) { return w->mapTo(m_window.get(), QPoint()).x(); };
        QVERIFY(x(left) < x(middle) && x(middle) < x(right));
        // (the middle one, with the HUD, is never the narrower)
        const QString widths = QString("%1 %2 %3").arg(left->width()).arg(middle->width()).arg(right->width());
        QVERIFY2(std::abs(left->width() - right->width()) <= 2, qPrintable(widths));
        QVERIFY2(middle->width() >= left->width() - 2 && left->width() > m_window->width() / 6, qPrintable(widths));
        QList<QWidget*> separators;
        for (QWidget* w : m_window->findChildren<QWidget*>("ScreenSeparator"))
            if (w->isVisible()) separators << w;
        QCOMPARE(separators.size(), 2);
        for (QWidget* s : separators) {
            QVERIFY(s->width() >= 4);
            QVERIFY((x(s) >= x(left) + left->width() && x(s) < x(middle)) ||
                    (x(s) >= x(middle) + middle->width() && x(s) < x(right)));
        }
        // the same machine at the same moment, seen three ways; the keys with the middle
        QTRY_VERIFY(!left->poses().empty() && left->poses().front().isApprox(middle->poses().front()));
        QVERIFY(right->bundle() == middle->bundle() && right->scene() == middle->scene());
        const QImage images[] = {left->grabFramebuffer(), middle->grabFramebuffer(), right->grabFramebuffer()};
        for (const QImage& a : images)
            for (const QImage& b : images)
                if (&a != &b) QVERIFY(a != b);
        QVERIFY(middle->hasFocus() || QApplication::focusWidget() == nullptr);
        QVERIFY(!left->hasFocus() && !right->hasFocus());
        settle();
        QVERIFY(m_window->grab().save(screenshotPath("train_three_screens_en.png")));
        m_window->findChild<QAction*>("Language_es")->trigger();
        QTRY_COMPARE(camera->itemText(three), QString("Tres pantallas (−60°, 0°, +60°)"));
        settle();
        QVERIFY(m_window->grab().save(screenshotPath("train_three_screens_es.png")));
        m_window->findChild<QAction*>("Language_en")->trigger();
        QTRY_COMPARE(camera->itemText(three), QString("Three screens (−60°, 0°, +60°)"));
        // the next attempt opens on three screens again; back to one with another view
        page()->stopAttempt();
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 5000);
        QVERIFY(page()->openTutorial("T0"));
        page()->startAttempt();
        QTRY_VERIFY(left->isVisible() && right->isVisible());
        QCOMPARE(camera->currentIndex(), three);
        const int iso = camera->findData("Iso");
        camera->setCurrentIndex(iso);
        emit camera->activated(iso);
        QVERIFY(!left->isVisible() && !right->isVisible());
        QVERIFY(!QSettings().value("trainer/threeScreens").toBool());
        page()->stopAttempt();
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 5000);
    }

    void recordsThatCannotOpenLeaveTrainingGoing()
    {
        QTemporaryDir dir;
        const QString junk = dir.filePath("records.sqlite");
        QFile f(junk);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(8192, 'x'));
        f.close();
        QVERIFY(!page()->openRecordsAt(junk));
        QVERIFY(!page()->records());
        QVERIFY(!page()->recordsProblem().isEmpty());
        page()->showRecords();
        QVERIFY(page()->recordsView()->message()->isVisible());
        QVERIFY(page()->recordsView()->message()->text().contains(page()->recordsProblem()));
        settle();
        QVERIFY(m_window->grab().save(screenshotPath("train_records_problem_en.png")));
        // training goes on: an attempt (stopped at once) goes to a pending file …
        QVERIFY(page()->openTutorial("T0"));
        page()->startAttempt();
        QTRY_VERIFY_WITH_TIMEOUT(m_window->tutorialRunner()->latest()->snapshot->t > 0.2, 5000);
        page()->stopAttempt();
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 5000);
        QVERIFY(page()->resultNote()->text().contains("could not be written"));
        // … imported when the records open again: at the next start, said in the status bar
        m_window.reset();
        openWindow();
        QVERIFY2(page()->records(), qPrintable(page()->recordsProblem()));
        QCOMPARE(page()->importedPending(), 1);
        auto* note = m_window->statusBar()->findChild<QLabel*>("RecordsNote");
        QVERIFY(note);
        QVERIFY2(note->text().contains("1 attempt"), qPrintable(note->text()));
        page()->showCourse();
    }

    void expertGhostRunsBesideTheAttempt()
    {
        QVERIFY(page()->openTutorial("T0"));
        page()->setShowExpert(true);
        page()->startAttempt();
        TutorialRunner* runner = m_window->tutorialRunner();
        QVERIFY(runner->hasGhost());
        QTRY_VERIFY_WITH_TIMEOUT(runner->latest()->snapshot->t > 2.5 && runner->latest()->ghost, 10000);
        const auto f = runner->latest();
        // in step with the attempt's clock, and moving where the operator does not
        QVERIFY2(std::abs(f->ghost->t - f->snapshot->t) < 2e-3, qPrintable(QString("%1 %2").arg(f->ghost->t).arg(f->snapshot->t)));
        QVERIFY((f->ghost->theta - f->snapshot->theta).norm() > 1e-3);
        QTRY_VERIFY(page()->attemptViewport()->ghost() != nullptr);
        settle();
        QVERIFY(m_window->grab().save(screenshotPath("train_ghost_en.png")));
        // off: no more ghost drawn, and the runner drops it
        page()->expertBox()->click();
        QVERIFY(!page()->showExpert());
        QVERIFY(!page()->attemptViewport()->ghost());
        QVERIFY(!runner->hasGhost());
        QTRY_VERIFY(!runner->latest()->ghost);
        page()->stopAttempt();
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 5000);
        QVERIFY(!page()->attemptViewport()->ghost());
    }

    void recordedInputReplaysToTheSameResult()
    {
        // a live attempt whose station replays the demonstration (as an operator's
        // devices would give it), recorded as every live attempt is
        QVERIFY(page()->openTutorial("T0"));
        const auto demo = page()->demoLog();
        QVERIFY(demo);
        trainer::Station* station = m_window->station();
        trainer::StationProfile before;
        trainer::StationProfile profile = page()->demoProfile();
        profile.devices.clear();
        station->call([&](trainer::StationEngine& e) {
            before = e.profile();
            e.setProfile(profile);
        });
        page()->startAttempt();
        QVERIFY(m_window->tutorialRunner()->wantsCommands());
        const auto devices = trainer::replayDevices(demo);
        station->call([&](trainer::StationEngine& e) {
            e.setReplayOnly(true);
            for (const auto& d : devices) e.addDevice(d);
        });
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 60000);
        station->call([&](trainer::StationEngine& e) {
            for (const auto& d : devices) e.removeDevice(d.get());
            e.setReplayOnly(false);
            e.setProfile(before);
        });
        const trainer::TutorialResult live = page()->lastRun()->result;
        QVERIFY2(live.passed, live.endReason.c_str());
        QVERIFY(!page()->recordedInput().isEmpty());
        QVERIFY(m_window->findChild<QPushButton*>("UseDemoButton")->isVisible());
        // saved, it replays headless to the same result
        QTemporaryDir dir;
        const QString saved = dir.filePath("mine.demo.log");
        QString error;
        QVERIFY2(page()->saveDemonstration(saved, &error), qPrintable(error));
        QVERIFY(QFile::exists(saved + ".profile.json"));
        QVERIFY2(page()->useAsDemonstration(saved, &error), qPrintable(error));
        QCOMPARE(page()->demoFile(), QFileInfo(saved).absoluteFilePath());
        trainer::RunOutput replay;
        QVERIFY2(trainer::runTutorialWithLog(page()->tutorial(), page()->demoLog(), page()->demoProfile(), replay, &error,
                                             TutorialRunner::kGrace),
                 qPrintable(error));
        QCOMPARE(replay.result.passed, live.passed);
        QCOMPARE(replay.result.goalsDone, live.goalsDone);
        QVERIFY2(std::abs(replay.result.time - live.time) < 0.5,
                 qPrintable(QString("%1 / %2").arg(replay.result.time).arg(live.time)));
        // the stage keeps it; a log that no longer loads falls back to the shipped one
        QVERIFY(page()->openTutorial("T0"));
        QCOMPARE(page()->demoFile(), QFileInfo(saved).absoluteFilePath());
        QVERIFY(page()->demoWarning().isEmpty());
        QFile broken(saved);
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("not a log\n");
        broken.close();
        QVERIFY(page()->openTutorial("T0"));
        QVERIFY(!page()->demoWarning().isEmpty());
        QVERIFY(page()->demoFile().endsWith("t0_reach.demo.log"));
        QVERIFY(page()->demoLog());
        QVERIFY(m_window->findChild<QLabel*>("DemoNote")->isVisible());
        page()->useShippedDemonstration();
        QVERIFY(page()->demoWarning().isEmpty());
        page()->showCourse();
    }

    void kioskModeIsFullScreenAndTheKeysLeaveIt()
    {
        QSettings().remove("trainer/pin");
        m_window->setWorkspace(MainWindow::Workspace::Model);
        m_window->setKioskMode(true);
        settle(500);
        QVERIFY(m_window->isKioskMode());
        QVERIFY(m_window->isFullScreen());
        QCOMPARE(m_window->workspace(), MainWindow::Workspace::Train);
        QVERIFY(!m_window->findChild<QToolBar*>("WorkspaceBar")->isVisible());
        QVERIFY(!m_window->menuBar()->isVisible());
        m_window->setWorkspace(MainWindow::Workspace::Model);  // refused in kiosk mode
        QCOMPARE(m_window->workspace(), MainWindow::Workspace::Train);
        // the languages, big enough for a finger
        for (const char* code : {"es", "en"}) {
            QPushButton* b = page()->languageButton(code);
            QVERIFY(b);
            QVERIFY(b->isVisible());
            QVERIFY2(b->height() >= 56 && b->width() >= 150, qPrintable(QString("%1×%2").arg(b->width()).arg(b->height())));
            QCOMPARE(b->text(), i18n::nativeName(code));
            QCOMPARE(b->isChecked(), QLatin1String(code) == QLatin1String("en"));
        }
        QVERIFY(m_window->grab().save(screenshotPath("train_kiosk_en.png")));
        // no PIN: the keys alone
        QTest::keyClick(page(), Qt::Key_F12, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY(!m_window->isKioskMode());
        QVERIFY(m_window->findChild<QToolBar*>("WorkspaceBar")->isVisible());
        QVERIFY(m_window->menuBar()->isVisible());
        // a PIN: asked; a wrong one keeps the kiosk and says so, the dialog stays for
        // another try, and the right one leaves
        QSettings().setValue("trainer/pin", "4711");
        m_window->setKioskMode(true);
        settle();
        QTest::keyClick(page(), Qt::Key_F12, Qt::ControlModifier | Qt::ShiftModifier);
        PinDialog* dialog = nullptr;
        QTRY_VERIFY((dialog = m_window->findChild<PinDialog*>("KioskPinDialog")) != nullptr);
        QVERIFY(!dialog->message()->isVisible());
        QTest::keyClicks(dialog->field(), "1234");
        QTest::keyClick(dialog->field(), Qt::Key_Return);
        settle();
        QVERIFY(m_window->isKioskMode());
        QVERIFY(dialog->isVisible());
        QVERIFY(dialog->message()->isVisible());
        QVERIFY2(dialog->message()->text().contains("not the trainer's PIN"), qPrintable(dialog->message()->text()));
        QVERIFY(dialog->field()->text().isEmpty());
        QTRY_VERIFY2(dialog->message()->height() >= dialog->message()->heightForWidth(dialog->message()->width()),
                     "the message is clipped");
        QVERIFY(dialog->grab().save(screenshotPath("train_kiosk_wrong_pin_en.png")));
        QTest::keyClicks(dialog->field(), "4711");
        QTest::keyClick(dialog->field(), Qt::Key_Return);
        QTRY_VERIFY(!m_window->isKioskMode());
        // five wrong PINs in a row lock the dialog for a while, the right one too
        m_window->setKioskMode(true);
        settle();
        QTest::keyClick(page(), Qt::Key_F12, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY((dialog = m_window->findChild<PinDialog*>("KioskPinDialog")) != nullptr);
        for (int i = 0; i < PinDialog::kMaxWrong; ++i) {
            dialog->field()->setText("0000");
            dialog->submit();
        }
        QVERIFY(dialog->isLocked());
        QVERIFY(!dialog->field()->isEnabled());
        QVERIFY2(dialog->message()->text().contains("wait 30 s"), qPrintable(dialog->message()->text()));
        dialog->field()->setText("4711");
        dialog->submit();
        settle();
        QVERIFY(m_window->isKioskMode());
        dialog->reject();
        QTRY_VERIFY(!m_window->findChild<PinDialog*>("KioskPinDialog"));
        // the records ask the same way
        QVERIFY(page()->recordsButton()->isVisible());
        page()->recordsButton()->click();
        QTRY_VERIFY((dialog = page()->findChild<PinDialog*>("RecordsPinDialog")) != nullptr);
        dialog->field()->setText("1");
        dialog->submit();
        QVERIFY(dialog->message()->isVisible());
        QVERIFY(page()->screen() != TrainPage::Screen::Records);
        dialog->field()->setText("4711");
        dialog->submit();
        QTRY_COMPARE(page()->screen(), TrainPage::Screen::Records);
        page()->showCourse();
        m_window->setKioskMode(false);
        QSettings().remove("trainer/pin");
    }

    // In Trainer Mode the expert's ghost is the trainer's choice (the records' box), not
    // what the studio's last session left, and the trainee cannot toggle it
    void kioskExpertIsTheTrainersChoice()
    {
        QSettings().setValue("trainer/showExpert", true);  // the trainer's own session
        QSettings().setValue("trainer/kioskShowExpert", false);
        m_window->setKioskMode(true);
        settle();
        TutorialRunner* runner = m_window->tutorialRunner();
        const auto attempt = [&](bool ghost) {
            QVERIFY(page()->openTutorial("T0"));
            page()->startAttempt();
            QCOMPARE(page()->screen(), TrainPage::Screen::Attempt);
            QCOMPARE(page()->expertBox()->isChecked(), ghost);
            QVERIFY(!page()->expertBox()->isEnabled());
            QCOMPARE(runner->hasGhost(), ghost);
            QTest::mouseClick(page()->expertBox(), Qt::LeftButton);  // a trainee's click does nothing
            QCOMPARE(page()->expertBox()->isChecked(), ghost);
            QCOMPARE(runner->hasGhost(), ghost);
            page()->stopAttempt();
            QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 5000);
        };
        attempt(false);
        // the trainer turns it on in the records (outside the kiosk here: no PIN needed)
        m_window->setKioskMode(false);
        page()->showCourse();
        page()->recordsButton()->click();
        auto* choice = page()->recordsView()->findChild<QCheckBox*>("KioskShowExpert");
        QVERIFY(choice && choice->isVisible() && !choice->isChecked());
        choice->click();
        QVERIFY(QSettings().value("trainer/kioskShowExpert").toBool());
        page()->showCourse();
        m_window->setKioskMode(true);
        settle();
        attempt(true);
        QVERIFY(QSettings().value("trainer/showExpert").toBool());  // the studio's own, untouched
        m_window->setKioskMode(false);
        page()->showCourse();
        QSettings().remove("trainer/kioskShowExpert");
        QSettings().remove("trainer/showExpert");
        QVERIFY(page()->expertBox()->isEnabled() || !page()->expertBox()->isChecked());
    }

    void operatorsAreKeptApart()
    {
        page()->showCourse();
        page()->setOperator("4711");
        QCOMPARE(page()->progressOf("T0").attempts, 0);
        QVERIFY(!page()->courseList()->item(0)->text().contains(QChar(0x2605)));
        if (page()->courseList()->count() > 1) QVERIFY(!(page()->courseList()->item(1)->flags() & Qt::ItemIsEnabled));
        page()->setOperator(QString());
        QVERIFY(page()->progressOf("T0").passed);
    }

    // A page whose first attempt ends after a change of language shows the result's and
    // the debrief's own texts in the new language (they are set at the change, not only
    // when a result is there to fill them)
    void aLanguageChangeBeforeAnyAttemptReachesTheResultAndDebrief()
    {
        TutorialRunner runner;
        TrainPage fresh(&runner, nullptr);
        auto* retry = fresh.findChild<QPushButton*>("RetryButton");
        QVERIFY(retry && !fresh.lastRun());
        QCOMPARE(retry->text(), QString("Retry"));
        i18n::switchTo("es");
        QTRY_COMPARE(retry->text(), QString("Reintentar"));
        const QList<QPushButton*> buttons = fresh.findChildren<QPushButton*>();
        QVERIFY(std::any_of(buttons.begin(), buttons.end(),
                            [](const QPushButton* b) { return b->text() == QString("Volver al resultado"); }));
        i18n::switchTo("en");
        QTRY_COMPARE(retry->text(), QString("Retry"));
    }

    void languageSwitchesAtRunTime()
    {
        // the course screen in English, T0 open in the background of an attempt later
        page()->showCourse();
        QPushButton* es = page()->languageButton("es");
        QPushButton* en = page()->languageButton("en");
        QVERIFY(es && en);
        QVERIFY(es->isVisible() && en->isVisible());  // outside kiosk mode too
        QVERIFY(en->isChecked() && !es->isChecked());
        QCOMPARE(page()->courseTitle()->text(), QString("Training course"));
        QVERIFY(page()->courseList()->item(0)->text().contains("Reach a target"));
        // a click on "Español": everything at once, no restart
        QTest::mouseClick(es, Qt::LeftButton);
        QTRY_COMPARE(page()->courseTitle()->text(), QString("Curso de entrenamiento"));
        QCOMPARE(i18n::current(), QString("es"));
        QCOMPARE(TrainPage::language(), QString("es"));
        QCOMPARE(QSettings().value("ui/language").toString(), QString("es"));  // remembered
        QVERIFY(es->isChecked() && !en->isChecked());
        QVERIFY2(page()->courseList()->item(0)->text().contains("Alcanzar un objetivo"),
                 qPrintable(page()->courseList()->item(0)->text()));
        QVERIFY(page()->courseList()->item(0)->text().contains("Nivel"));
        // the start screen follows a switch while it is shown
        QVERIFY(page()->openTutorial("T0"));
        const QString titleEs = page()->startTitle()->text();
        QVERIFY(titleEs.contains("Alcanzar un objetivo"));
        i18n::switchTo("en");
        QTRY_VERIFY(page()->startTitle()->text().contains("Reach a target"));
        // the HUD: the goal's name and the numbers, in Spanish during the attempt
        page()->startAttempt();
        TutorialRunner* runner = m_window->tutorialRunner();
        QTRY_VERIFY_WITH_TIMEOUT(runner->latest() && runner->latest()->snapshot->t > 0.5, 10000);
        QTRY_VERIFY(page()->hud()->text().contains("Bring the claws to the green sphere"));
        QVERIFY(page()->hud()->text().contains(QRegularExpression("Distance: \\d+\\.\\d\\d m")));
        i18n::switchTo("es");
        QTRY_VERIFY2(page()->hud()->text().contains("Lleve las garras a la esfera verde"), qPrintable(page()->hud()->text()));
        const QString hud = page()->hud()->text();
        QVERIFY2(hud.contains(QRegularExpression("Distancia: \\d+,\\d\\d m")), qPrintable(hud));
        QVERIFY2(hud.contains(QRegularExpression("Tiempo: \\d+,\\d / 120 s")), qPrintable(hud));
        // the result: the score's time with a decimal comma
        page()->stopAttempt();
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 5000);
        QVERIFY2(page()->resultHeading()->text() == QString("NO APROBADO"), qPrintable(page()->resultHeading()->text()));
        QVERIFY2(page()->resultScore()->text().contains(QRegularExpression("\\d,\\d s")),
                 qPrintable(page()->resultScore()->text()));
        // and back to English, on the result screen
        i18n::switchTo("en");
        QTRY_COMPARE(page()->resultHeading()->text(), QString("NOT PASSED"));
        QVERIFY2(page()->resultScore()->text().contains(QRegularExpression("\\d\\.\\d s")),
                 qPrintable(page()->resultScore()->text()));
        // the kiosk: its course screen has the buttons too, and they work there
        page()->showCourse();
        m_window->setKioskMode(true);
        settle();
        QVERIFY(es->isVisible());
        QTest::mouseClick(es, Qt::LeftButton);
        QTRY_COMPARE(page()->courseTitle()->text(), QString("Curso de entrenamiento"));
        QTest::mouseClick(en, Qt::LeftButton);
        QTRY_COMPARE(page()->courseTitle()->text(), QString("Training course"));
        m_window->setKioskMode(false);
        settle();
    }

    void spanishScreens()
    {
        m_window.reset();
        QVERIFY(i18n::install("es"));
        openWindow();
        page()->showCourse();
        settle();
        QVERIFY(page()->courseList()->item(0)->text().contains("Alcanzar un objetivo"));
        QVERIFY(m_window->grab().save(screenshotPath("train_course_es.png")));
        m_window->setKioskMode(true);
        settle(500);
        QVERIFY(page()->languageButton("es")->isChecked());
        QVERIFY(m_window->grab().save(screenshotPath("train_kiosk_es.png")));
        m_window->setKioskMode(false);
        settle(500);
        QVERIFY(page()->openTutorial("T0"));
        settle(500);
        QVERIFY(m_window->grab().save(screenshotPath("train_start_es.png")));
        page()->startAttempt();
        QTRY_VERIFY_WITH_TIMEOUT(m_window->tutorialRunner()->latest()->snapshot->t > 0.5, 10000);
        settle();
        QVERIFY2(page()->hud()->text().contains("Lleve las garras a la esfera verde"), qPrintable(page()->hud()->text()));
        QVERIFY(m_window->grab().save(screenshotPath("train_hud_es.png")));
        page()->stopAttempt();
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 5000);
        passWithTheDemonstration();
        QVERIFY(m_window->grab().save(screenshotPath("train_result_es.png")));
        page()->showDebrief();
        QTRY_VERIFY_WITH_TIMEOUT(page()->expertRun(), 60000);
        settle(500);
        QVERIFY(m_window->grab().save(screenshotPath("train_debrief_es.png")));
        // the records: the guest's attempts (most made in English, worded in Spanish now)
        page()->showRecords();
        QVERIFY(page()->recordsView()->selectOperator("guest"));
        QTableWidget* attempts = page()->recordsView()->attemptsTable();
        QVERIFY(attempts->rowCount() >= 2);
        attempts->setCurrentCell(attempts->rowCount() - 1, 0);  // the first attempt: in English
        settle(500);
        QVERIFY(m_window->grab().save(screenshotPath("train_records_es.png")));
        page()->showCourse();
        m_window.reset();
        QVERIFY(i18n::install("en"));
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat());
    QApplication app(argc, argv);
    TrainTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "train_test.moc"
