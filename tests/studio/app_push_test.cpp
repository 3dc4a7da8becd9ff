// Pushing a body with the mouse (issue 22 item 4), as a user does it in padrob-studio
// (a real window under Xvfb): the tumbling block (a free body) is picked under the
// cursor with Ctrl + left press, dragged to the right while the simulation runs, and
// follows the drag; the push reaches the solver thread (the snapshot carries it) and
// a red line is drawn from the grabbed point to the target; the release ends it.
// Ctrl + drag off the bodies neither pushes nor orbits.
// Screenshots with the window at 1280 × 720 asked for (the docks keep it at least
// 1336 × 755), in English and in Spanish, while dragging.

#include "tests/studio/main_window_test.h"
#include "ide/i18n/language.h"
#include "ide/studio/app/main_window.h"
#include "ide/studio/sim/simulation_runner.h"
#include "ide/studio/view/viewport.h"
#include "ide/studio/view/viewport_layout.h"

#include <QAction>
#include <QMouseEvent>
#include <QSettings>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTest>

#include <cmath>

using namespace studio;
using studio::test::chooseLanguage;
using studio::test::screenshotPath;

namespace {

QString modelPath(const QString& name) { return QStringLiteral(PADROB_SOURCE_DIR) + "/models/" + name; }

/// Where world point `p` shows in the view [pixels] (its camera's view and projection).
QPointF project(const Viewport& view, const Eigen::Vector3d& p)
{
    const Camera& c = view.cameraState();
    const double aspect = double(view.width()) / double(view.height());
    const Eigen::Vector4d e = c.viewMatrix() * p.homogeneous();
    const double f = 1.0 / std::tan(0.5 * c.verticalFieldOfView(aspect));
    const double x = f / aspect * e.x() / -e.z(), y = f * e.y() / -e.z();
    return {0.5 * (x + 1) * view.width(), 0.5 * (1 - y) * view.height()};
}

void sendMouse(Viewport& v, QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons,
               Qt::KeyboardModifiers mods)
{
    QMouseEvent e(type, at, v.mapToGlobal(at), button, buttons, mods);
    QCoreApplication::sendEvent(&v, &e);
}

/// The block's centre of mass in the newest snapshot [m, world].
Eigen::Vector3d blockCentre(const MainWindow& w, int block)
{
    const auto snap = w.runner()->latest();
    const auto b = static_cast<std::size_t>(block);
    return snap->bodyPoses[b] * snap->bundle->model->com[b];
}

}  // namespace

class AppPushTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("PadrobTest");
        QCoreApplication::setApplicationName("padrob-studio-push-test");
        QSettings().clear();
        QVERIFY(i18n::install("en"));
    }

    void ctrlDragPushesTheBlockAndTheReleaseLetsItGo()
    {
        MainWindow w;
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const quint64 before = w.bundle() ? w.bundle()->serial : 0;
        QVERIFY(w.openFile(modelPath("tumbling_block.pad")));
        QTRY_VERIFY_WITH_TIMEOUT(w.bundle() && w.bundle()->serial != before, 10000);
        const solver::Model& m = *w.bundle()->model;
        const int block = m.bodyIndex(1);
        Viewport& view = *w.viewports()->viewport(0);
        QVERIFY(view.setCamera("Front"));  // from −y: right on the screen is +x
        Camera camera = view.cameraState();
        camera.distance *= 2.5;  // room to drag it in
        view.setCameraState(camera);
        studio::test::settle(200);

        // Ctrl + drag off the block does nothing
        const QPointF corner(20, 20);
        sendMouse(view, QEvent::MouseButtonPress, corner, Qt::LeftButton, Qt::LeftButton, Qt::ControlModifier);
        sendMouse(view, QEvent::MouseMove, corner + QPointF(80, 0), Qt::NoButton, Qt::LeftButton, Qt::ControlModifier);
        QCOMPARE(view.pushedBody(), -1);
        QCOMPARE(view.cameraState().yaw, camera.yaw);  // nor orbits
        sendMouse(view, QEvent::MouseButtonRelease, corner + QPointF(80, 0), Qt::LeftButton, Qt::NoButton,
                  Qt::ControlModifier);
        QCOMPARE(w.runner()->push().body, -1);

        // the block's centre is under this pixel, the block is picked there
        const Eigen::Vector3d start = blockCentre(w, block);
        QVERIFY2((start - Eigen::Vector3d(0, 0, 1)).norm() < 1e-9, "the block starts centred at (0, 0, 1)");
        const QPointF at = project(view, start);
        int picked = -1;
        Eigen::Vector3d hit;
        QVERIFY(view.pick(at, picked, hit));
        QCOMPARE(picked, block);
        QVERIFY2(std::abs(hit.y() + 0.25) < 1e-6, "the hit is on the block's face toward the camera (y = −0.25)");

        w.runner()->start();
        QTRY_VERIFY(w.runner()->isRunning());
        sendMouse(view, QEvent::MouseButtonPress, at, Qt::LeftButton, Qt::LeftButton, Qt::ControlModifier);
        QCOMPARE(view.pushedBody(), block);
        const double pixels = 0.4 * view.width();
        for (int k = 1; k <= 10; ++k) {
            sendMouse(view, QEvent::MouseMove, at + QPointF(pixels * k / 10, 0), Qt::NoButton, Qt::LeftButton,
                      Qt::ControlModifier);
            QTest::qWait(20);
        }
        QCOMPARE(view.cameraState().yaw, camera.yaw);  // a push does not orbit
        QCOMPARE(view.cameraState().pitch, camera.pitch);
        // the target moved right (+x) in the plane y = −0.25 through the grabbed point,
        // under the cursor
        const Eigen::Vector3d target = view.pushTarget();
        QVERIFY2(target.x() > 0.3, qPrintable(QString::number(target.x())));
        QVERIFY((project(view, target) - (at + QPointF(pixels, 0))).manhattanLength() < 0.5);
        QVERIFY(std::abs(target.y() - hit.y()) < 1e-9);
        QCOMPARE(w.runner()->push().body, block);
        QTRY_VERIFY_WITH_TIMEOUT(w.runner()->latest()->push.body == block, 5000);  // in the solver
        studio::test::settle(150);  // the block on its way: the line long
        QImage shot = w.grab().toImage();
        // (the window cannot be made smaller than its docks' minimum: 1336 × 755 on Xvfb)
        QVERIFY2(shot.width() <= 1400 && shot.height() <= 800,
                 qPrintable(QStringLiteral("%1 x %2").arg(shot.width()).arg(shot.height())));
        // the red line is drawn: pixels of the push's red where the target is
        const QImage frame = view.grabFramebuffer();
        int red = 0;
        for (int y = 0; y < frame.height(); ++y)
            for (int x = 0; x < frame.width(); ++x) {
                const QColor c = frame.pixelColor(x, y);
                red += c.red() > 180 && c.green() < 90 && c.blue() < 90;
            }
        QVERIFY2(red > 50, qPrintable(QStringLiteral("%1 red pixels").arg(red)));
        QVERIFY(shot.save(screenshotPath("app_push_drag_en.png")));
        chooseLanguage(w, "es");
        QCOMPARE(view.pushedBody(), block);  // the language changes under the drag
        QVERIFY(w.grab().save(screenshotPath("app_push_drag_es.png")));
        chooseLanguage(w, "en");

        // the block follows (critically damped at 10 rad/s: most of the way within a second)
        QTRY_VERIFY_WITH_TIMEOUT(blockCentre(w, block).x() > 0.7 * target.x(), 10000);
        const Eigen::Vector3d moved = blockCentre(w, block);
        QVERIFY2(std::abs(moved.z() - 1) < 0.2, "pushed sideways, it stays at about its height");
        // the release ends the push, in the view, the runner and the solver
        sendMouse(view, QEvent::MouseButtonRelease, at + QPointF(pixels, 0), Qt::LeftButton, Qt::NoButton,
                  Qt::ControlModifier);
        QCOMPARE(view.pushedBody(), -1);
        QCOMPARE(w.runner()->push().body, -1);
        QTRY_VERIFY_WITH_TIMEOUT(w.runner()->latest()->push.body == -1, 5000);
        w.runner()->pause();
        QTRY_VERIFY(!w.runner()->isRunning());
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat());
    QApplication app(argc, argv);
    AppPushTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "app_push_test.moc"
