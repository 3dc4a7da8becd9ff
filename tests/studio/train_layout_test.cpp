// Every screen at the sizes stations have (issue 25, item 2): the Model workspace, the
// Station page and each Train screen (course, start, attempt, result, debrief, records)
// at 1280×720 and 1920×1080 in Spanish (the longer language) and in English, and the
// kiosk's Train screens at 1024×768 in Spanish. Each screen is shot
// (layout_<screen>_<size>_<lang>.png) and its geometry checked, as a person would look:
// the window is not pushed past the screen by minimum sizes, no button's text is cut
// (its size hint fits its width) and every visible button lies inside the window, the
// start screen's demonstration slider and the debrief's Play/scrub row have room, the
// Station mapping table's Live column is inside its viewport, the HUD does not cover the
// target, and the Model workspace's dock tabs read whole.

#include "tests/studio/gui_test.h"
#include "ide/i18n/language.h"
#include "ide/studio/app/main_window.h"
#include "ide/studio/station/mapping_table.h"
#include "ide/studio/station/station_page.h"
#include "ide/studio/train/debrief_screen.h"
#include "ide/studio/train/records_view.h"
#include "ide/studio/train/train_page.h"
#include "ide/studio/train/tutorial_runner.h"
#include "ide/studio/view/camera.h"
#include "ide/studio/view/viewport.h"
#include "trainer/training/tutorial.h"

#include <QAbstractButton>
#include <QApplication>
#include <QFile>
#include <QHeaderView>
#include <QLabel>
#include <QMainWindow>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTabBar>
#include <QTableWidget>
#include <QTest>

#include <memory>

using namespace studio;
using studio::test::screenshotPath;
using studio::test::settle;

namespace {

/// Where `w` lies in `window`'s coordinates.
QRect rectIn(const QWidget* w, const QWidget* window)
{
    return QRect(w->mapTo(window, QPoint(0, 0)), w->size());
}

/// Every visible button under `root`: inside the window, and wide enough for its text.
QString badButtons(const QWidget* root, const QWidget* window)
{
    QStringList bad;
    for (const QAbstractButton* b : root->findChildren<QAbstractButton*>()) {
        if (!b->isVisible() || b->text().isEmpty() || b->visibleRegion().isEmpty()) continue;
        const QRect r = rectIn(b, window);
        if (!window->rect().contains(r))
            bad << QStringLiteral("“%1” outside the window (%2,%3 %4×%5)")
                       .arg(b->text())
                       .arg(r.x())
                       .arg(r.y())
                       .arg(r.width())
                       .arg(r.height());
        else if (b->width() < b->sizeHint().width())
            bad << QStringLiteral("“%1” cut: %2 px for %3").arg(b->text()).arg(b->width()).arg(b->sizeHint().width());
    }
    return bad.join("; ");
}

}  // namespace

class TrainLayoutTest : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> m_window;
    TrainPage* page() const { return m_window->trainPage(); }

    void shoot(const QString& screen, const QString& tag)
    {
        settle(250);
        QVERIFY(m_window->grab().save(screenshotPath("layout_" + screen + "_" + tag + ".png")));
    }

    void checkButtons(const QWidget* root, const QString& where)
    {
        const QString bad = badButtons(root, m_window.get());
        QVERIFY2(bad.isEmpty(), qPrintable(where + ": " + bad));
    }

    void setSize(const QSize& size)
    {
        m_window->setGeometry(QRect(QPoint(0, 0), size));
        settle(300);
        QVERIFY2(m_window->width() <= size.width() && m_window->height() <= size.height(),
                 qPrintable(QStringLiteral("the window needs %1×%2 for %3×%4")
                                .arg(m_window->width())
                                .arg(m_window->height())
                                .arg(size.width())
                                .arg(size.height())));
    }

    void modelWorkspace(const QString& tag)
    {
        m_window->setWorkspace(MainWindow::Workspace::Model);
        shoot("model", tag);
        checkButtons(m_window.get(), "Model");
        // the left dock's tabs (Model, Joints): each tab as wide as its text asks
        auto* space = m_window->findChild<QMainWindow*>("ModelWorkspace");
        QVERIFY(space);
        int tabs = 0;
        for (QTabBar* bar : space->findChildren<QTabBar*>()) {
            if (!bar->isVisible()) continue;
            for (int i = 0; i < bar->count(); ++i) {
                ++tabs;
                const int text = bar->fontMetrics().horizontalAdvance(bar->tabText(i));
                QVERIFY2(bar->tabRect(i).width() >= text + 8,
                         qPrintable(QStringLiteral("tab “%1”: %2 px for %3 px of text")
                                        .arg(bar->tabText(i))
                                        .arg(bar->tabRect(i).width())
                                        .arg(text)));
            }
            QVERIFY(bar->elideMode() == Qt::ElideNone || bar->width() >= bar->sizeHint().width());
        }
        QVERIFY(tabs >= 2);
    }

    void stationPage(const QString& tag)
    {
        m_window->setWorkspace(MainWindow::Workspace::Station);
        shoot("station", tag);
        checkButtons(m_window->stationPage(), "Station");
        // the Live column inside the table's viewport, and the table inside the window
        QTableWidget* table = m_window->stationPage()->mappingTable()->table();
        const int live = MappingTable::LiveColumn;
        const int right = table->columnViewportPosition(live) + table->columnWidth(live);
        QVERIFY2(table->columnWidth(live) >= 100 && right <= table->viewport()->width(),
                 qPrintable(QStringLiteral("Live column %1 px, ends at %2 of %3")
                                .arg(table->columnWidth(live))
                                .arg(right)
                                .arg(table->viewport()->width())));
        QVERIFY(m_window->rect().contains(rectIn(table->viewport(), m_window.get())));
    }

    /// The course, the start screen, an attempt (its HUD), the result, the debrief and
    /// the records of T0, each shot and checked.
    void trainScreens(const QString& tag, bool kiosk)
    {
        QWidget* w = m_window.get();
        m_window->setWorkspace(MainWindow::Workspace::Train);
        page()->showCourse();
        shoot("train_course", tag);
        checkButtons(page(), "course");
        // start: the demonstration's slider has room
        QVERIFY(page()->openTutorial("T0"));
        shoot("train_start", tag);
        checkButtons(page(), "start");
        QSlider* demo = page()->demoSlider();
        QVERIFY2(demo->isVisible() && demo->width() >= 200,
                 qPrintable(QStringLiteral("demonstration slider %1 px").arg(demo->width())));
        QVERIFY(w->rect().contains(rectIn(demo, w)));
        // the attempt, driven by the demonstration a second in: the HUD clear of the target
        TutorialRunner* runner = m_window->tutorialRunner();
        page()->startAttempt(page()->demoLog());
        runner->setPaused(true);
        runner->seek(1.2);  // (off-clock)
        QTRY_VERIFY_WITH_TIMEOUT(runner->latest() && runner->latest()->snapshot->t > 1.0, 10000);
        settle(300);
        shoot("train_hud", tag);
        checkButtons(page(), "attempt");
        Viewport* view = page()->attemptViewport();
        const QWidget* hud = page()->hud()->parentWidget();  // the HUD's panel
        QVERIFY(hud->isVisible());
        const QRect hudRect(hud->mapTo(view, QPoint(0, 0)), hud->size());
        const Camera& camera = view->cameraState();
        const Eigen::Vector3d goal = page()->tutorial()->spec.goals.front().target;
        Eigen::Vector2d pixel;
        QVERIFY(camera.pixelOf(goal, view->width(), view->height(), pixel));
        // (the ray through that pixel goes to the target)
        QVERIFY(camera.rayThrough(pixel.x(), pixel.y(), view->width(), view->height())
                    .dot((goal - camera.eye()).normalized()) > 0.9999);
        const QPointF target(pixel.x(), pixel.y());
        QVERIFY2(view->rect().contains(target.toPoint()), "the target is out of the view");
        QVERIFY2(!hudRect.adjusted(-30, -30, 30, 30).contains(target.toPoint()),
                 qPrintable(QStringLiteral("the HUD (%1,%2 %3×%4) covers the target at %5,%6")
                                .arg(hudRect.x())
                                .arg(hudRect.y())
                                .arg(hudRect.width())
                                .arg(hudRect.height())
                                .arg(target.x())
                                .arg(target.y())));
        // the rest off-clock: the result's buttons whole
        runner->setPaused(false);
        runner->seek(runner->latest()->duration + 1.0);
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 30000);
        shoot("train_result", tag);
        checkButtons(page(), "result");
        // the debrief: Play, the scrub slider and the time in view and wide enough
        page()->showDebrief();
        QTRY_VERIFY_WITH_TIMEOUT(page()->expertRun(), 30000);
        shoot("train_debrief", tag);
        checkButtons(page(), "debrief");
        QSlider* scrub = page()->replaySlider();
        QVERIFY2(scrub->isVisible() && scrub->width() >= 200,
                 qPrintable(QStringLiteral("replay slider %1 px").arg(scrub->width())));
        QVERIFY(w->rect().contains(rectIn(scrub, w)));
        auto* play = page()->debriefScreen()->findChild<QPushButton*>("ReplayPlay");
        QVERIFY(play && play->isVisible() && w->rect().contains(rectIn(play, w)));
        QVERIFY2(scrub->height() >= scrub->sizeHint().height(), "the replay row is squeezed");
        if (!kiosk) {
            page()->showRecords();
            QVERIFY(page()->recordsView()->selectOperator("guest"));
            shoot("train_records", tag);
            checkButtons(page(), "records");
        }
        page()->showCourse();
    }

    void walk(const char* lang, const QSize& size)
    {
        QVERIFY(i18n::switchTo(lang));
        setSize(size);
        const QString tag = QStringLiteral("%1x%2_%3").arg(size.width()).arg(size.height()).arg(lang);
        modelWorkspace(tag);
        stationPage(tag);
        trainScreens(tag, false);
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("PadrobTest");
        QCoreApplication::setApplicationName("padrob-studio-train-layout-test");
        QSettings().clear();
        const QString db = trainer::records::RecordsDb::defaultSqlitePath();
        for (const char* suffix : {"", "-wal", "-shm"}) QFile::remove(db + suffix);
        QVERIFY(i18n::install("en"));
        m_window = std::make_unique<MainWindow>();
        m_window->openInitial(QString());
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    }

    void cleanupTestCase()
    {
        m_window.reset();
        i18n::install("en");
    }

    void spanishAt1280x720() { walk("es", QSize(1280, 720)); }
    void englishAt1280x720() { walk("en", QSize(1280, 720)); }
    void spanishAt1920x1080() { walk("es", QSize(1920, 1080)); }
    void englishAt1920x1080() { walk("en", QSize(1920, 1080)); }

    // the kiosk (no menus, no mode bar) on a 1024×768 screen, in Spanish
    void kioskInSpanishAt1024x768()
    {
        QVERIFY(i18n::switchTo("es"));
        m_window->setKioskMode(true);
        settle(300);
        m_window->setWindowState(Qt::WindowNoState);  // (the screen under test is larger)
        setSize(QSize(1024, 768));
        trainScreens("kiosk_1024x768_es", true);
        m_window->setKioskMode(false);
        QVERIFY(i18n::switchTo("en"));
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat());
    QApplication app(argc, argv);
    TrainLayoutTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "train_layout_test.moc"
