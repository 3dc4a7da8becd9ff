// The Train workspace as a station of the training centre (ide/studio/centre/
// train_station.h; padrob-studio --station-name NAME --centre-key FILE --loopback): the
// main window (a real window under Xvfb) on a loopback DDS domain of its own, and an
// instructor (trainer::centre::InstructorNode) in the same process on its own Bus. The
// instructor sees the station announce its model, hash and tutorials; `start T0 OP-1`
// runs T0 in the Train workspace for OP-1 (the attempt's clock advances); `pause`
// stops the clock; `inject power-cut` shows in the state's faults and in the attempt's
// events; `resume` goes on; a command under another key is refused (bad-signature) and
// changes nothing; `stop` ends the attempt aborted with every instructor action in its
// events, in order; the station withdraws when it is destroyed. A screenshot of the
// attempt with the network indicator.

#include "tests/studio/gui_test.h"
#include "ide/i18n/language.h"
#include "ide/studio/app/main_window.h"
#include "ide/studio/centre/train_station.h"
#include "ide/studio/train/train_page.h"
#include "ide/studio/train/tutorial_runner.h"
#include "ide/studio/view/viewport.h"
#include "trainer/centre/instructor_node.h"
#include "trainer/centre/signing.h"
#include "trainer/centre/station_node.h"
#include "trainer/records/records_db.h"

#include <QApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QSettings>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <thread>
#include <optional>
#include <unistd.h>

using namespace studio;
using studio::test::screenshotPath;
using studio::test::settle;
namespace centre = trainer::centre;

class TrainStationTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_keyFile;
    const int m_domain = 1 + static_cast<int>(::getpid() % 230);
    const std::string m_name = "TS-studio-" + std::to_string(::getpid());
    const std::string m_desk = "desk-" + std::to_string(::getpid());
    std::unique_ptr<MainWindow> m_window;
    std::unique_ptr<TrainStation> m_station;
    std::unique_ptr<centre::Bus> m_bus;
    std::unique_ptr<centre::InstructorNode> m_instructor;
    centre::CentreKey m_key;
    QElapsedTimer m_clock;

    TrainPage* page() const { return m_window->trainPage(); }
    void poll() { m_instructor->poll(m_clock.nsecsElapsed() * 1e-9); }
    const centre::StationView* view(const std::string& name) const
    {
        const auto& all = m_instructor->stations();
        const auto it = all.find(name);
        return it == all.end() ? nullptr : &it->second;
    }
    const centre::StationView* view() const { return view(m_name); }
    const centre::State* stateOf(const std::string& name) const
    {
        const centre::StationView* v = view(name);
        return v && v->hasState ? &v->state : nullptr;
    }
    template <class F>
    bool waitFor(F done, int ms = 10000)
    {
        return QTest::qWaitFor([&] {
            poll();
            return done();
        }, ms);
    }
    /// Sends a command and waits for its reply.
    std::optional<centre::Reply> command(const std::string& kind, const std::string& arg = {},
                                         const std::string& arg2 = {})
    {
        const std::uint64_t n = m_instructor->send(m_name, kind, arg, arg2);
        if (n == 0) return std::nullopt;
        waitFor([&] { return m_instructor->reply(n).has_value(); });
        return m_instructor->reply(n);
    }
    std::string status() const { return view() && view()->hasState ? view()->state.status : std::string(); }
    double attemptTime() const { return view() && view()->hasState ? view()->state.attemptTime : -1.0; }
    bool hasEvent(const std::string& kind, const std::string& detail) const
    {
        if (!view()) return false;
        for (const centre::Event& e : view()->events)
            if (e.kind == kind && e.detail == detail) return true;
        return false;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName("PadrobTest");
        QCoreApplication::setApplicationName("padrob-studio-train-station-test");
        QSettings().clear();
        const QString db = trainer::records::RecordsDb::defaultSqlitePath();
        for (const char* suffix : {"", "-wal", "-shm"}) QFile::remove(db + suffix);
        QVERIFY(i18n::install("en"));
        QVERIFY(m_dir.isValid());
        m_keyFile = m_dir.filePath("centre.key");
        QString error;
        QVERIFY2(centre::CentreKey::create(m_keyFile, &error), qPrintable(error));
        centre::CentreKey key;
        QVERIFY2(key.load(m_keyFile, &error), qPrintable(error));
        m_key = key;
        m_clock.start();

        m_window = std::make_unique<MainWindow>();
        m_window->openInitial(QString());
        m_window->resize(1600, 1000);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        m_window->setWorkspace(MainWindow::Workspace::Train);
        settle();

        // the station: as padrob-studio --station-name NAME --centre-key FILE --loopback,
        // FILE its own node key (padrob centre key --node NAME: it signs only what this
        // station says, docs/training-centre.md); the instructor holds the centre's key
        const QString nodeKey = m_dir.filePath("station.key");
        QVERIFY2(key.createNodeKey(m_name, nodeKey, &error), qPrintable(error));
        TrainStationOptions o;
        o.name = QString::fromStdString(m_name);
        o.keyFile = nodeKey;
        o.network = centre::BusOptions::loopback(m_domain);
        m_station = TrainStation::forPage(page(), o);
        QVERIFY2(m_station->online(), qPrintable(m_station->problem()));
        QVERIFY(m_station->hasKey());

        centre::BusOptions net = centre::BusOptions::loopback(m_domain);
        net.key = key;
        m_bus = centre::Bus::open(net, &error);
        QVERIFY2(m_bus, qPrintable(error));
        m_instructor = std::make_unique<centre::InstructorNode>(*m_bus, m_desk, key);
        m_instructor->announce();
    }

    void cleanupTestCase()
    {
        m_station.reset();
        m_instructor.reset();
        m_bus.reset();
        m_window.reset();
    }

    void announcesItself()
    {
        QVERIFY2(waitFor([&] { return view() && view()->hasState; }), "the station is not heard");
        const centre::Announce& a = view()->announce;
        QCOMPARE(a.role, std::string("station"));
        QCOMPARE(a.model, std::string("liner_manipulator_fluid"));  // T0 runs on the fluid-power machine
        QFile model(QStringLiteral(PADROB_SOURCE_DIR "/models/liner_manipulator_fluid.pad"));
        QVERIFY(model.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromStdString(a.modelHash),
                 QString::fromLatin1(QCryptographicHash::hash(model.readAll(), QCryptographicHash::Sha256).toHex()));
        QVERIFY(std::find(a.tutorials.begin(), a.tutorials.end(), "T0") != a.tutorials.end());
        QCOMPARE(status(), std::string("idle"));
        QVERIFY(page()->centreLinkText().contains("On the centre's network as " + QString::fromStdString(m_name)));
    }

    void startRunsTheTutorialForTheOperator()
    {
        const auto r = command("start", "T0", "OP-1");
        QVERIFY(r && r->accepted);
        QCOMPARE(page()->screen(), TrainPage::Screen::Attempt);
        QCOMPARE(QString::fromStdString(page()->tutorial()->spec.id), QString("T0"));
        QCOMPARE(page()->operatorId(), QString("OP-1"));
        QVERIFY(page()->attemptLive());
        QVERIFY(waitFor([&] { return status() == "running" && attemptTime() > 0.5; }));
        QCOMPARE(view()->state.tutorial, std::string("T0"));
        QCOMPARE(view()->state.operatorCode, std::string("OP-1"));
        QVERIFY(!view()->state.q.empty());
        QVERIFY(waitFor([&] { return hasEvent("instructor", "start:" + m_desk); }));
        // the states come at about 60 Hz
        const std::uint64_t seq0 = view()->state.seq;
        QTest::qWait(1000);
        poll();
        const double rate = double(view()->state.seq - seq0);
        QVERIFY2(rate > 45 && rate < 75, qPrintable(QString::number(rate)));
    }

    void pauseStopsTheClock()
    {
        const auto r = command("pause");
        QVERIFY(r && r->accepted);
        QVERIFY(waitFor([&] { return status() == "paused"; }));
        QTest::qWait(100);
        poll();
        const double t = attemptTime();
        QTest::qWait(600);
        poll();
        QCOMPARE(attemptTime(), t);
        QVERIFY(waitFor([&] { return hasEvent("instructor", "pause:" + m_desk); }));
        // pausing again is refused
        const auto again = command("pause");
        QVERIFY(again && !again->accepted);
        QCOMPARE(again->message, std::string("not-running"));
    }

    void powerCutIsInTheStateAndTheEvents()
    {
        const auto r = command("inject", "power-cut");
        QVERIFY(r && r->accepted);
        QCOMPARE(r->message, std::string("done"));
        QVERIFY(waitFor([&] { return view()->state.faults.find("power-cut") != std::string::npos; }));
        QVERIFY(view()->state.warnings & centre::WarnFault);
        QVERIFY(waitFor([&] { return hasEvent("fault", "power-cut"); }));
        const auto f = m_window->tutorialRunner()->latest();
        QVERIFY(f);
        bool inSession = false;
        for (const auto& e : f->events) inSession |= e.kind == trainer::TutorialEvent::Kind::Fault;
        QVERIFY(inSession);
        // an unknown drive: the session's own sentence
        const auto bad = command("inject", "hose-burst", "NO SUCH DRIVE");
        QVERIFY(bad && !bad->accepted);
        QVERIFY(bad->message != "done" && !bad->message.empty());
        const auto unknown = command("inject", "meteor");
        QVERIFY(unknown && !unknown->accepted);
        QCOMPARE(unknown->message, std::string("unknown-fault"));

        const auto resumed = command("resume");
        QVERIFY(resumed && resumed->accepted);
        const double t = attemptTime();
        QVERIFY(waitFor([&] { return status() == "running" && attemptTime() > t + 0.3; }));
    }

    void anotherKeyIsRefused()
    {
        centre::InstructorNode intruder(*m_bus, "intruder", centre::CentreKey::fromBytes(QByteArray(32, 'x')));
        const std::uint64_t n = intruder.send(m_name, "stop");
        QVERIFY(n != 0);
        QVERIFY(QTest::qWaitFor([&] {
            intruder.poll(m_clock.nsecsElapsed() * 1e-9);
            return intruder.reply(n).has_value();
        }, 10000));
        QVERIFY(!intruder.reply(n)->accepted);
        QCOMPARE(intruder.reply(n)->message, std::string("bad-signature"));
        QTest::qWait(300);
        poll();
        QCOMPARE(status(), std::string("running"));
        QCOMPARE(page()->screen(), TrainPage::Screen::Attempt);
        const auto unknown = command("fly");
        QVERIFY(unknown && !unknown->accepted);
        QCOMPARE(unknown->message, std::string("unknown-command"));
    }

    void screenshotWithTheIndicator()
    {
        settle(500);
        auto* label = page()->findChild<QLabel*>("CentreLink");
        QVERIFY(label && label->isVisible());
        QVERIFY(label->text().contains(QString::fromStdString(m_name)));
        QVERIFY(m_window->grab().save(screenshotPath("train_station_en.png")));
    }

    void stopEndsTheAttemptAbortedWithTheInstructorsActions()
    {
        const auto r = command("stop");
        QVERIFY(r && r->accepted);
        QVERIFY(waitFor([&] { return status() == "ended"; }));
        QTRY_VERIFY_WITH_TIMEOUT(page()->screen() == TrainPage::Screen::Result, 10000);
        QVERIFY(page()->lastRun());
        const trainer::TutorialResult& res = page()->lastRun()->result;
        QCOMPARE(res.endReason, std::string("aborted"));
        std::vector<std::string> actions;
        for (const auto& e : res.events) {
            if (e.kind == trainer::TutorialEvent::Kind::Instructor) actions.push_back(e.detail);
            if (e.kind == trainer::TutorialEvent::Kind::Fault) actions.push_back("fault:" + e.detail);
        }
        const std::vector<std::string> expected{"start:" + m_desk, "pause:" + m_desk, "fault:power-cut",
                                                "resume:" + m_desk, "stop:" + m_desk};
        QCOMPARE(actions, expected);
        QVERIFY(waitFor([&] { return hasEvent("aborted", ""); }));
        // stopping again is refused
        const auto again = command("stop");
        QVERIFY(again && !again->accepted);
        QCOMPARE(again->message, std::string("not-running"));
        // start again, for another operator, then the instructor's reset ends it aborted
        const auto start = command("start", "T0", "OP-2");
        QVERIFY(start && start->accepted);
        QVERIFY(waitFor([&] { return status() == "running" && view()->state.operatorCode == "OP-2"; }));
        const long g = m_window->tutorialRunner()->generation();
        const auto reset = command("reset");
        QVERIFY(reset && reset->accepted);
        QVERIFY(waitFor([&] { return m_window->tutorialRunner()->generation() != g && status() == "running"; }));
        QVERIFY(waitFor([&] { return hasEvent("instructor", "reset:" + m_desk); }));
        QCOMPARE(page()->operatorId(), QString("OP-2"));
    }

    // The headless station (padrob station: trainer::centre::StationNode) and the studio's
    // answer the same commands with the same words and publish the same state: both run
    // T0 with the levers at rest, paused, faulted, stopped by one instructor; the running
    // score is published by both (0: the levers at rest do no work).
    void bothStationsPublishTheSameState()
    {
        const std::string headless = "TS-headless-" + std::to_string(::getpid());
        centre::BusOptions net = centre::BusOptions::loopback(m_domain);
        net.reads = centre::TopicCommand;
        net.node = QString::fromStdString(headless);
        net.key = m_key;
        QString error;
        std::unique_ptr<centre::Bus> bus = centre::Bus::open(net, &error);
        QVERIFY2(bus, qPrintable(error));
        centre::StationNodeOptions o;
        o.name = headless;
        o.key = m_key;
        const auto all = page()->tutorials();
        const auto t0 = std::find_if(all.begin(), all.end(), [](const auto& t) { return t->spec.id == "T0"; });
        QVERIFY(t0 != all.end());
        for (const auto& t : all)
            if (t->modelFile == (*t0)->modelFile) o.tutorials.push_back(t);
        centre::StationNode node(*bus, o);
        QVERIFY2(node.ok(), qPrintable(node.error()));
        std::atomic<bool> stop{false};
        std::thread thread([&] { node.run(stop); });
        struct Join {
            std::atomic<bool>& stop;
            std::thread& thread;
            ~Join()
            {
                stop = true;
                if (thread.joinable()) thread.join();
            }
        } join{stop, thread};
        QVERIFY2(waitFor([&] { return stateOf(headless) != nullptr; }), "the headless station is not heard");

        const std::vector<std::string> both{m_name, headless};
        // the same command to both; both answers
        auto commandBoth = [&](const std::string& kind, const std::string& arg = {}, const std::string& arg2 = {}) {
            std::vector<std::uint64_t> n;
            for (const auto& s : both) n.push_back(m_instructor->send(s, kind, arg, arg2));
            waitFor([&] { return m_instructor->reply(n[0]).has_value() && m_instructor->reply(n[1]).has_value(); });
            return std::make_pair(m_instructor->reply(n[0]), m_instructor->reply(n[1]));
        };
        auto statusBoth = [&](const std::string& st) {
            return waitFor([&] {
                const centre::State* a = stateOf(m_name);
                const centre::State* b = stateOf(headless);
                return a && b && a->status == st && b->status == st && a->attemptTime > 1.0 && b->attemptTime > 1.0;
            });
        };
        auto same = [&](const char* when) {
            poll();
            const centre::State& a = *stateOf(m_name);
            const centre::State& b = *stateOf(headless);
            const QString what = QString("%1: studio %2 %3 %4 score %5 faults %6 warnings %7; headless %8 %9 %10 score %11 faults %12 warnings %13")
                                     .arg(when)
                                     .arg(QString::fromStdString(a.status), QString::fromStdString(a.tutorial),
                                          QString::fromStdString(a.operatorCode))
                                     .arg(a.score)
                                     .arg(QString::fromStdString(a.faults))
                                     .arg(a.warnings)
                                     .arg(QString::fromStdString(b.status), QString::fromStdString(b.tutorial),
                                          QString::fromStdString(b.operatorCode))
                                     .arg(b.score)
                                     .arg(QString::fromStdString(b.faults))
                                     .arg(b.warnings);
            QVERIFY2(a.status == b.status && a.tutorial == b.tutorial && a.operatorCode == b.operatorCode, qPrintable(what));
            QVERIFY2(a.goal == b.goal && a.goals == b.goals && a.goals > 0, qPrintable(what));
            QVERIFY2(a.faults == b.faults && a.warnings == b.warnings && a.endReason == b.endReason, qPrintable(what));
            // (the levers at rest do no work: both score 0, docs/training.md "The score")
            QVERIFY2(a.score >= 0 && std::abs(a.score - b.score) < 0.5, qPrintable(what));
            QVERIFY2(a.q.size() == b.q.size() && a.commands.size() == b.commands.size(), qPrintable(what));
            for (std::size_t i = 0; i < a.commands.size(); ++i) QVERIFY2(a.commands[i] == b.commands[i], qPrintable(what));
        };

        auto [sa, sb] = commandBoth("start", "T0", "OP-7");
        QVERIFY(sa && sa->accepted && sb && sb->accepted);
        QVERIFY(statusBoth("running"));
        QVERIFY(waitFor([&] { return stateOf(m_name)->operatorCode == "OP-7"; }));
        auto [pa, pb] = commandBoth("pause");
        QVERIFY(pa && pa->accepted && pb && pb->accepted);
        QVERIFY(statusBoth("paused"));
        same("paused");
        if (QTest::currentTestFailed()) return;
        auto [ra, rb] = commandBoth("resume");  // the same refusal from both
        QVERIFY(ra && rb && ra->accepted && rb->accepted);
        auto [aa, ab] = commandBoth("resume");
        QVERIFY(aa && ab && !aa->accepted && !ab->accepted);
        QCOMPARE(aa->message, ab->message);
        QCOMPARE(aa->message, std::string("not-paused"));
        auto [ia, ib] = commandBoth("inject", "power-cut");
        QVERIFY(ia && ib && ia->accepted && ib->accepted);
        QCOMPARE(ia->message, ib->message);
        QVERIFY(waitFor([&] {
            return stateOf(m_name)->faults == "power-cut" && stateOf(headless)->faults == "power-cut";
        }));
        same("power cut");
        if (QTest::currentTestFailed()) return;
        auto [ua, ub] = commandBoth("inject", "meteor");
        QVERIFY(ua && ub && !ua->accepted && !ub->accepted);
        QCOMPARE(ua->message, ub->message);
        auto [xa, xb] = commandBoth("stop");
        QVERIFY(xa && xb && xa->accepted && xb->accepted);
        QVERIFY(statusBoth("ended"));
        QVERIFY(waitFor([&] { return !stateOf(m_name)->endReason.empty() && !stateOf(headless)->endReason.empty(); }));
        same("ended");
        if (QTest::currentTestFailed()) return;
        QCOMPARE(stateOf(m_name)->endReason, std::string("aborted"));
        auto [za, zb] = commandBoth("pause");
        QVERIFY(za && zb && !za->accepted && !zb->accepted);
        QCOMPARE(za->message, zb->message);
    }

    void withdrawsWhenClosed()
    {
        m_station.reset();
        QVERIFY(waitFor([&] { return view() && view()->presence == "left"; }));
    }

    // a station's node key under another name: no key, and the link says whose it is
    void anotherStationsKeyIsRefused()
    {
        TrainStationOptions o;
        o.name = QStringLiteral("someone-else");
        o.keyFile = m_dir.filePath("station.key");
        o.network = centre::BusOptions::loopback(m_domain);
        auto other = TrainStation::forPage(page(), o);
        QVERIFY(!other->hasKey());
        QVERIFY2(other->problem().contains(QString::fromStdString(m_name)) && other->problem().contains("someone-else"),
                 qPrintable(other->problem()));
    }
};

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat());
    QApplication app(argc, argv);
    TrainStationTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "train_station_test.moc"
