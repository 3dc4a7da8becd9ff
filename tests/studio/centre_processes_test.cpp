// The training centre with every node kind in its own process, on loopback: two
// `padrob station --demo`, a display node (`padrob-studio --display-of S1 --view centre`,
// a real window on the test's X display), an instructor (`padrob instructor send …`), and
// this test as a watching instructor (an InstructorNode without a key). The state must
// reach the display node's process: the test grabs the X screen where the display window
// is and sees its pixels change while S1's demonstration runs, and stay exactly the same
// while S1 is paused, while S2 streams on. ctest runs it alone (RUN_SERIAL): nothing
// else draws on the screen meanwhile.
#include "gui_test.h"
#include "ide/studio/centre/display_view.h"
#include "ide/studio/view/viewport.h"
#include "trainer/centre/bus.h"
#include "trainer/centre/instructor_node.h"
#include "trainer/centre/signing.h"

#include <QGuiApplication>
#include <QImage>
#include <QProcess>
#include <QScreen>
#include <QSurfaceFormat>
#include <QTemporaryDir>

#include <memory>
#include <unistd.h>

using studio::test::screenshotPath;
namespace centre = trainer::centre;

namespace {

const QString kTut0 = QStringLiteral(PADROB_SOURCE_DIR "/resources/tutorials/t0_reach.tut");
// where the display window is put (Qt's -geometry; Xvfb has no window manager to move it)
const QRect kDisplayRect(60, 60, 640, 360);

}  // namespace

class CentreProcessesTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_keyFile;
    const int m_domain = 1 + static_cast<int>((::getpid() + 57) % 230);
    const QString m_s1 = QStringLiteral("S1-proc-%1").arg(::getpid());
    const QString m_s2 = QStringLiteral("S2-proc-%1").arg(::getpid());
    std::vector<std::unique_ptr<QProcess>> m_processes;
    std::unique_ptr<centre::Bus> m_bus;
    std::unique_ptr<centre::InstructorNode> m_observer;

    QProcess* spawn(const QString& program, const QStringList& args)
    {
        auto p = std::make_unique<QProcess>();
        p->setProcessChannelMode(QProcess::ForwardedChannels);
        p->start(program, args);
        m_processes.push_back(std::move(p));
        return m_processes.back().get();
    }
    QStringList net() const { return {"--domain", QString::number(m_domain), "--loopback"}; }

    /// The test's own instructor node takes what arrived, and Qt its events, for `ms`.
    void pump(int ms)
    {
        QElapsedTimer t;
        t.start();
        do {
            m_observer->poll(studio::centreClock());
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
            QTest::qSleep(5);
        } while (t.elapsed() < ms);
    }
    template <class F>
    bool waitFor(F done, int ms)
    {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < ms) {
            pump(10);
            if (done()) return true;
        }
        return done();
    }
    const centre::StationView* station(const QString& name) const
    {
        const auto it = m_observer->stations().find(name.toStdString());
        return it == m_observer->stations().end() ? nullptr : &it->second;
    }
    std::string status(const QString& name) const
    {
        const centre::StationView* v = station(name);
        return v && v->hasState ? v->state.status : std::string();
    }
    /// `padrob instructor send STATION COMMAND…` as its own process: its exit status.
    int instructorSends(const QString& target, const QStringList& command)
    {
        QProcess* p = spawn(QStringLiteral(PADROB_CLI), QStringList{"instructor", "send", target} + command + net() +
                                                            QStringList{"--key", m_keyFile, "--timeout", "10"});
        if (!p->waitForStarted(5000)) return -1;
        // the test's node keeps reading meanwhile
        if (!waitFor([&] { return p->state() == QProcess::NotRunning; }, 30000)) return -2;
        return p->exitStatus() == QProcess::NormalExit ? p->exitCode() : -3;
    }
    /// The display window's pixels, from the whole X screen.
    static QImage grabDisplay()
    {
        return QGuiApplication::primaryScreen()
            ->grabWindow(0, kDisplayRect.x(), kDisplayRect.y(), kDisplayRect.width(), kDisplayRect.height())
            .toImage()
            .convertToFormat(QImage::Format_RGB32);
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_keyFile = m_dir.filePath("centre.key");
        QString error;
        QVERIFY2(centre::CentreKey::create(m_keyFile, &error), qPrintable(error));
        // the observer checks what the stations say with the centre's key (it sends nothing)
        centre::BusOptions o = centre::BusOptions::loopback(m_domain);
        QVERIFY2(o.key.load(m_keyFile, &error), qPrintable(error));
        m_bus = centre::Bus::open(o, &error);
        QVERIFY2(m_bus, qPrintable(error));
        m_observer = std::make_unique<centre::InstructorNode>(*m_bus, "observer-" + std::to_string(::getpid()),
                                                              centre::CentreKey());
    }

    void cleanupTestCase()
    {
        for (auto& p : m_processes) {
            if (p->state() == QProcess::NotRunning) continue;
            p->terminate();
            if (!p->waitForFinished(10000)) {
                p->kill();
                p->waitForFinished(5000);
            }
        }
        m_observer.reset();
        m_bus.reset();
    }

    void everyNodeKindInItsOwnProcess()
    {
        // two stations, a display node of S1 at a known place on the screen
        for (const QString& s : {m_s1, m_s2})
            QVERIFY(spawn(QStringLiteral(PADROB_CLI),
                          QStringList{"station", kTut0, "--name", s, "--demo", "--for", "240", "--key", m_keyFile} + net())
                        ->waitForStarted(5000));
        QProcess* display = spawn(QStringLiteral(PADROB_STUDIO),
                                  QStringList{"--display-of", m_s1, "--view", "centre", "--lang", "en", "-geometry",
                                              QStringLiteral("%1x%2+%3+%4")
                                                  .arg(kDisplayRect.width())
                                                  .arg(kDisplayRect.height())
                                                  .arg(kDisplayRect.x())
                                                  .arg(kDisplayRect.y()),
                                              "--centre-key", m_keyFile} +
                                      net());
        QVERIFY(display->waitForStarted(5000));
        QVERIFY2(waitFor([&] { return status(m_s1) == "idle" && status(m_s2) == "idle"; }, 30000),
                 "both stations are heard");

        // the instructor's process starts both demonstrations
        QCOMPARE(instructorSends(m_s1, {"start", "T0", "OP-1"}), 0);
        QCOMPARE(instructorSends(m_s2, {"start", "T0", "OP-2"}), 0);
        QVERIFY(waitFor([&] { return status(m_s1) == "running" && station(m_s1)->state.simTime > 1.0; }, 10000));
        QVERIFY(waitFor([&] { return status(m_s2) == "running"; }, 5000));

        // running: the display window's pixels change (the machine moves); the display
        // process loads the model first, so give it time
        QImage before, after;
        bool moving = false;
        for (int i = 0; i < 100 && !moving && display->state() == QProcess::Running; ++i) {
            before = grabDisplay();
            pump(300);
            after = grabDisplay();
            moving = before != after;
        }
        QVERIFY2(display->state() == QProcess::Running, "the display node runs");
        QVERIFY2(moving, "the display node's window follows S1's demonstration");
        // and again, a while later (not just the first frame after the model loaded)
        pump(500);
        before = grabDisplay();
        pump(500);
        after = grabDisplay();
        QVERIFY2(before != after, "the display node's window keeps following S1");
        QVERIFY(after.save(screenshotPath("centre_processes_running.png")));

        // S1 paused by the instructor's process: the display holds still, S2 goes on
        QCOMPARE(instructorSends(m_s1, {"pause"}), 0);
        QVERIFY(waitFor([&] { return status(m_s1) == "paused"; }, 5000));
        pump(1000);  // the display draws a little behind the stream
        const double s1Sim = station(m_s1)->state.simTime, s2Sim = station(m_s2)->state.simTime;
        const std::uint64_t s2Seq = station(m_s2)->state.seq;
        before = grabDisplay();
        pump(1500);
        after = grabDisplay();
        QVERIFY(after.save(screenshotPath("centre_processes_paused.png")));
        QVERIFY2(before == after, "the paused station's display node holds still");
        QCOMPARE(status(m_s1), std::string("paused"));
        QCOMPARE(station(m_s1)->state.simTime, s1Sim);
        QCOMPARE(station(m_s1)->presence, std::string("up"));  // paused, yet it streams on
        QCOMPARE(status(m_s2), std::string("running"));
        QVERIFY2(station(m_s2)->state.simTime > s2Sim + 1.0, "S2 streams on meanwhile");
        QVERIFY(station(m_s2)->state.seq > s2Seq + 60);
        QCOMPARE(station(m_s2)->presence, std::string("up"));

        // resumed: the display moves again
        QCOMPARE(instructorSends(m_s1, {"resume"}), 0);
        QVERIFY(waitFor([&] { return status(m_s1) == "running"; }, 5000));
        moving = false;
        for (int i = 0; i < 20 && !moving; ++i) {
            before = grabDisplay();
            pump(300);
            moving = before != grabDisplay();
        }
        QVERIFY2(moving, "resumed, the display node moves again");
        QCOMPARE(display->state(), QProcess::Running);
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(studio::Viewport::surfaceFormat());
    QApplication app(argc, argv);
    CentreProcessesTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "centre_processes_test.moc"
