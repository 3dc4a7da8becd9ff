// The training centre in padrob-studio (ide/studio/centre): the display feed's pose
// interpolation and model check without any network, then a real `padrob station
// --demo` on loopback seen and commanded by the instructor window and drawn by a
// display window (--display-of), both as real windows.
#include "gui_test.h"
#include "ide/i18n/language.h"
#include "ide/studio/centre/display_feed.h"
#include "ide/studio/centre/display_view.h"
#include "ide/studio/centre/display_window.h"
#include "ide/studio/centre/instructor_window.h"
#include "ide/studio/view/viewport.h"
#include "trainer/centre/pki.h"
#include "trainer/centre/signing.h"
#include "trainer/training/faults.h"

#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPlainTextEdit>
#include <QProcess>
#include <QPushButton>
#include <QScopeGuard>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTableWidget>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>
#include <memory>
#include <unistd.h>

using namespace studio;
using studio::test::screenshotPath;
using studio::test::settle;
namespace centre = trainer::centre;

namespace {

const QString kTut0 = QStringLiteral(PADROB_SOURCE_DIR "/resources/tutorials/t0_reach.tut");
const QString kTut1 = QStringLiteral(PADROB_SOURCE_DIR "/resources/tutorials/t1_wrist.tut");
const QString kModel = QStringLiteral(PADROB_SOURCE_DIR "/models/liner_manipulator.pad");

std::vector<double> at(const StateBuffer& b, double simTime)
{
    std::vector<double> q;
    b.at(simTime, q);
    return q;
}

std::vector<double> sampled(const StateBuffer& b, double now)
{
    std::vector<double> q;
    b.sample(now, q);
    return q;
}

bool near(const std::vector<double>& a, const std::vector<double>& b, double tol = 1e-9)
{
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::abs(a[i] - b[i]) > tol) return false;
    return true;
}

centre::State state(const std::string& station, std::uint64_t seq, double simTime, std::vector<double> q)
{
    centre::State s;
    s.station = station;
    s.seq = seq;
    s.simTime = simTime;
    s.q = std::move(q);
    s.status = "running";
    return s;
}

}  // namespace

class CentreTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_keyFile;
    centre::CentreKey m_key;
    const int m_domain = 1 + static_cast<int>(::getpid() % 230);
    const QString m_station = QStringLiteral("S-studio-%1").arg(::getpid());
    std::unique_ptr<QProcess> m_process;
    std::unique_ptr<InstructorWindow> m_instructor;

    int rowOf(const QString& station) const
    {
        QTableWidget* t = m_instructor->table();
        for (int r = 0; r < t->rowCount(); ++r)
            if (t->item(r, 0) && t->item(r, 0)->text() == station) return r;
        return -1;
    }
    QString cell(int column) const
    {
        const int r = rowOf(m_station);
        const QTableWidgetItem* it = r < 0 ? nullptr : m_instructor->table()->item(r, column);
        return it ? it->text() : QString();
    }
    /// Clicks the OK button of the dialog named `name`, once it is open.
    static QDialog* dialog(QWidget* parent, const char* name)
    {
        QDialog* d = nullptr;
        const bool open = QTest::qWaitFor([&] { return (d = parent->findChild<QDialog*>(name)) && d->isVisible(); }, 5000);
        return open ? d : nullptr;
    }
    static void accept(QDialog* d) { QTest::mouseClick(d->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok), Qt::LeftButton); }
    bool waitReply(const QString& contains, int ms = 10000)
    {
        return QTest::qWaitFor([&] { return m_instructor->replyText().contains(contains); }, ms);
    }

private slots:
    void initTestCase()
    {
        QVERIFY(i18n::install("en"));
        QVERIFY(m_dir.isValid());
        m_keyFile = m_dir.filePath("centre.key");
        QString error;
        QVERIFY2(centre::CentreKey::create(m_keyFile, &error), qPrintable(error));
        QVERIFY2(m_key.load(m_keyFile, &error), qPrintable(error));
    }

    /// The centre's network on loopback, with the centre's key (as --centre-key FILE).
    centre::BusOptions keyed(int domain) const
    {
        centre::BusOptions o = centre::BusOptions::loopback(domain);
        o.key = m_key;
        return o;
    }

    void cleanupTestCase()
    {
        m_instructor.reset();
        if (m_process && m_process->state() != QProcess::NotRunning) {
            m_process->kill();
            m_process->waitForFinished(5000);
        }
    }

    // ---- the pose between states (no network)

    void interpolationIsExactAtStatesAndLinearBetween()
    {
        StateBuffer b;
        const double transit = 0.004;
        for (int i = 0; i <= 30; ++i) QVERIFY(b.push(std::uint64_t(i), i / 60.0, {double(i), -2.0 * i}, 10 + i / 60.0 + transit));
        // drawn kDelay behind: at a state's time exactly its θ
        for (int i : {0, 7, 29, 30}) {
            const double now = 10 + i / 60.0 + transit + StateBuffer::kDelay;
            QVERIFY2(near(sampled(b, now), {double(i), -2.0 * i}), qPrintable(QString::number(i)));
            QVERIFY(near(at(b, i / 60.0), {double(i), -2.0 * i}));
        }
        // linear between two states
        QVERIFY(near(at(b, 10.25 / 60.0), {10.25, -20.5}));
        QVERIFY(near(sampled(b, 10 + 20.5 / 60.0 + transit + StateBuffer::kDelay), {20.5, -41.0}));
        // the delay is about two state periods
        QVERIFY(StateBuffer::kDelay > 1.5 / 60.0 && StateBuffer::kDelay < 2.5 / 60.0);
        // the same state again is ignored
        QVERIFY(!b.push(30, 30 / 60.0, {99.0, 99.0}, 11));
        QVERIFY(near(at(b, 1.0), {30.0, -60.0}));
    }

    void holdsTheNewestWhenNoneIsNewer()
    {
        StateBuffer b;
        QVERIFY(!b.sample(0, *std::make_unique<std::vector<double>>()));
        for (int i = 0; i < 5; ++i) b.push(std::uint64_t(i), 1.0 + i / 60.0, {double(i)}, 3.0 + i / 60.0);
        QVERIFY(near(sampled(b, 100.0), {4.0}));  // long after: the newest, not extrapolated
        QVERIFY(near(sampled(b, 3.0), {0.0}));     // before the oldest: the oldest
        QCOMPARE(b.latestSeq(), std::uint64_t(4));
    }

    void startsAfreshWhenTheStationRestartsOrBeginsAnAttempt()
    {
        StateBuffer b;
        for (int i = 0; i < 10; ++i) b.push(std::uint64_t(100 + i), 5.0 + i / 60.0, {double(i)}, 20 + i / 60.0);
        QCOMPARE(b.restarts(), 0);
        // the station restarted: seq from 0 (and simulated time too)
        QVERIFY(b.push(0, 0.0, {-1.0}, 30.0));
        QCOMPARE(b.restarts(), 1);
        QCOMPARE(b.size(), std::size_t(1));
        QVERIFY(near(sampled(b, 30.0), {-1.0}));
        b.push(1, 1 / 60.0, {-2.0}, 30.0 + 1 / 60.0);
        QVERIFY(near(sampled(b, 30.0 + 1 / 60.0 + StateBuffer::kDelay), {-2.0}));
        QVERIFY(near(sampled(b, 30.0 + 0.5 / 60.0 + StateBuffer::kDelay), {-1.5}));
        // a new attempt: seq goes on, simulated time from 0 again
        b.push(2, 2 / 60.0, {-3.0}, 30.0 + 2 / 60.0);
        QVERIFY(b.push(3, 0.0, {7.0}, 31.0));
        QCOMPARE(b.restarts(), 2);
        QVERIFY(near(sampled(b, 31.0 + StateBuffer::kDelay), {7.0}));
    }

    void jitterAndPausesKeepTheMotionSmooth()
    {
        // a motion θ = simulated time, states at 60 Hz arriving 2 … 14 ms late, frames at
        // 144 Hz; a 2 s pause in the middle
        StateBuffer b;
        unsigned seed = 12345;
        const auto jitter = [&] {
            seed = seed * 1103515245u + 12345u;
            return 0.002 + 0.012 * double((seed >> 16) & 0x7fff) / 32767.0;
        };
        std::vector<std::pair<double, double>> arrivals;  // (arrival, simTime)
        double sim = 0;
        for (int i = 0; i < 600; ++i) {
            const double wall = i / 60.0;
            const bool paused = wall >= 4.0 && wall < 6.0;
            if (!paused && i > 0) sim += 1 / 60.0;
            arrivals.emplace_back(wall + jitter(), sim);
        }
        std::sort(arrivals.begin(), arrivals.end());
        std::size_t next = 0;
        double last = -1, maxStep = 0;
        int held = 0, frames = 0;
        std::uint64_t seq = 0;
        for (double now = 0.1; now < 9.9; now += 1 / 144.0) {
            while (next < arrivals.size() && arrivals[next].first <= now) {
                b.push(seq++, arrivals[next].second, {arrivals[next].second}, arrivals[next].first);
                ++next;
            }
            const double q = sampled(b, now).at(0);
            QVERIFY2(q >= last - 1e-12, qPrintable(QString("backwards at %1: %2 after %3").arg(now).arg(q).arg(last)));
            if (now > 0.5 && last >= 0) {
                maxStep = std::max(maxStep, q - last);
                const bool moving = now < 3.9 || (now > 6.3 && now < 9.8);
                if (moving) {
                    ++frames;
                    if (q == last) ++held;
                }
            }
            last = q;
        }
        // never a jump of more than a state period, and (almost) never a frame without motion
        QVERIFY2(maxStep < 1 / 60.0, qPrintable(QString::number(maxStep)));
        QVERIFY2(held <= frames / 50, qPrintable(QString("%1 of %2 frames held").arg(held).arg(frames)));
        // after the pause the motion goes on from where it stopped, kDelay behind again
        // (the last frame at 9.9 s: simulated time 7.9 s, less the delay and the least transit)
        QVERIFY2(std::abs(last - (9.9 - 2.0 - StateBuffer::kDelay - 0.002)) < 0.005, qPrintable(QString::number(last)));
    }

    // ---- the model and the presence (no network)

    void theModelIsFoundAndItsHashChecked()
    {
        const QString hash = DisplayFeed::fileHash(kModel);
        QCOMPARE(hash.size(), 64);
        QString error;
        QCOMPARE(QFileInfo(DisplayFeed::findModel("liner_manipulator", hash.toStdString(), &error)).fileName(),
                 QStringLiteral("liner_manipulator.pad"));
        QVERIFY(DisplayFeed::findModel("liner_manipulator", std::string(64, '0'), &error).isEmpty());
        QVERIFY2(error.contains("liner_manipulator") && error.contains("version"), qPrintable(error));
        QVERIFY(DisplayFeed::findModel("../models/liner_manipulator", "", &error).isEmpty());
        QVERIFY(DisplayFeed::findModel("no_such_model", "", &error).isEmpty());
        QVERIFY2(error.contains("no_such_model"), qPrintable(error));

        DisplayFeed feed("S");
        centre::Announce a;
        a.node = "S";
        a.role = "station";
        a.model = "liner_manipulator";
        a.modelHash = std::string(64, 'f');
        feed.announce(a);
        QVERIFY(!feed.bundle());
        QVERIFY(!feed.problem().isEmpty());
        a.modelHash = hash.toStdString();
        feed.announce(a);
        QVERIFY(feed.bundle());
        QVERIFY2(feed.problem().isEmpty(), qPrintable(feed.problem()));
        // another node's announcement changes nothing
        centre::Announce other = a;
        other.node = "S2";
        other.modelHash = std::string(64, 'f');
        feed.announce(other);
        QVERIFY(feed.bundle() && feed.problem().isEmpty());
    }

    void presenceAndSceneFollowTheStation()
    {
        DisplayFeed feed("S");
        QCOMPARE(feed.presence(0), DisplayFeed::Presence::Waiting);
        centre::State s = state("S", 0, 0.0, std::vector<double>(9, 0.0));
        s.tutorial = "T0";
        feed.push(s, 1.0);
        QCOMPARE(feed.presence(1.1), DisplayFeed::Presence::Up);
        QVERIFY2(feed.scene(), "T0's scene: its target");
        QCOMPARE(feed.presence(1.0 + DisplayFeed::kSilentAfter + 0.01), DisplayFeed::Presence::Silent);
        feed.push(state("OTHER", 1, 0.1, {1.0}), 5.0);  // another station's: ignored
        QCOMPARE(feed.presence(5.0), DisplayFeed::Presence::Silent);
        feed.withdraw("S");
        QCOMPARE(feed.presence(5.0), DisplayFeed::Presence::Left);
        s.seq = 1;  // a state that was late: it stays gone
        s.simTime = 0.1;
        feed.push(s, 5.1);
        QCOMPARE(feed.presence(5.1), DisplayFeed::Presence::Left);
        // started again: it announces itself, then states come
        centre::Announce a;
        a.node = "S";
        a.role = "station";
        a.model = "liner_manipulator";
        feed.announce(a);
        s.seq = 0;
        s.simTime = 0;
        s.tutorial = "NO-SUCH-TUTORIAL";
        feed.push(s, 6.0);
        QCOMPARE(feed.presence(6.0), DisplayFeed::Presence::Up);
        QVERIFY(!feed.scene());
    }

    // ---- a real station on loopback

    void theInstructorStartsAStationAndInjectsAFault()
    {
        m_process = std::make_unique<QProcess>();
        m_process->setProcessChannelMode(QProcess::ForwardedErrorChannel);
        m_process->start(QStringLiteral(PADROB_CLI),
                         {"station", kTut0, kTut1, "--name", m_station, "--demo", "--for", "240", "--domain",
                          QString::number(m_domain), "--loopback", "--key", m_keyFile});
        QVERIFY(m_process->waitForStarted(5000));

        m_instructor = std::make_unique<InstructorWindow>(centre::BusOptions::loopback(m_domain), m_keyFile);
        InstructorWindow& w = *m_instructor;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.canCommand());
        QVERIFY2(QTest::qWaitFor([&] { return cell(InstructorWindow::ColStatus) == "idle"; }, 30000),
                 "the station's row appears, idle");
        QCOMPARE(cell(InstructorWindow::ColPresence), QStringLiteral("up"));
        QVERIFY(w.selectStation(m_station));
        QCOMPARE(w.selectedStation(), m_station);
        QPushButton* start = w.button("StartButton");
        QVERIFY(QTest::qWaitFor([&] { return start->isEnabled(); }, 5000));
        QVERIFY(!w.button("PauseButton")->isEnabled());

        // Start: the station's tutorials, an operator
        QTest::mouseClick(start, Qt::LeftButton);
        QDialog* d = dialog(&w, "StartDialog");
        QVERIFY(d);
        auto* tutorials = d->findChild<QComboBox*>("TutorialBox");
        QCOMPARE(tutorials->count(), 2);
        QCOMPARE(tutorials->itemText(1), QStringLiteral("T1"));
        tutorials->setCurrentIndex(0);
        QTest::keyClicks(d->findChild<QLineEdit*>("OperatorEdit"), "OP-9");
        accept(d);
        QVERIFY2(waitReply("done"), qPrintable(w.replyText()));
        QVERIFY(QTest::qWaitFor([&] { return cell(InstructorWindow::ColStatus) == "running"; }, 5000));
        QCOMPARE(cell(InstructorWindow::ColTutorial), QStringLiteral("T0"));
        QCOMPARE(cell(InstructorWindow::ColOperator), QStringLiteral("OP-9"));
        QVERIFY(QTest::qWaitFor([&] { return !cell(InstructorWindow::ColLatency).isEmpty(); }, 2000));
        QVERIFY(QTest::qWaitFor([&] { return w.eventLog()->toPlainText().contains("start"); }, 5000));

        // the live view follows the stream
        QVERIFY(QTest::qWaitFor([&] { return !w.view()->theta().empty(); }, 5000));
        QVERIFY2(w.view()->overlayText().isEmpty(), qPrintable(w.view()->overlayText()));
        const std::vector<double> q0 = w.view()->theta();
        QVERIFY2(QTest::qWaitFor([&] { return w.view()->theta() != q0; }, 5000), "the demonstration moves the machine");

        // a refusal, as a sentence
        w.sendCommand("resume");
        QVERIFY2(waitReply(InstructorWindow::refusalText("not-paused")), qPrintable(w.replyText()));

        // a power cut, through the dialog; the model's drives are offered for the others
        QTest::mouseClick(w.button("InjectButton"), Qt::LeftButton);
        d = dialog(&w, "FaultDialog");
        QVERIFY(d);
        QVERIFY(d->findChild<QComboBox*>("DriveBox")->count() >= 6);
        QVERIFY(d->findChild<QComboBox*>("DriveBox")->findText("LEVANTE PLUMA", Qt::MatchContains) >= 0);
        auto* kind = d->findChild<QComboBox*>("FaultKind");
        kind->setCurrentIndex(kind->findData("power-cut"));
        QVERIFY(!d->findChild<QComboBox*>("DriveBox")->isVisible());
        accept(d);
        QVERIFY2(waitReply("done"), qPrintable(w.replyText()));
        const QString cut = trainer::Fault::label(trainer::Fault::Kind::PowerCut);
        QVERIFY2(QTest::qWaitFor([&] { return cell(InstructorWindow::ColWarnings).contains(cut); }, 5000),
                 qPrintable(cell(InstructorWindow::ColWarnings)));
        QVERIFY(w.button("ClearButton")->isEnabled());
        settle(500);
        QVERIFY(w.grab().save(screenshotPath("instructor_en.png")));

        // in Spanish
        QVERIFY(i18n::install("es"));
        settle(500);
        QCOMPARE(w.table()->horizontalHeaderItem(0)->text(), QStringLiteral("Puesto"));
        QVERIFY(QTest::qWaitFor([&] { return cell(InstructorWindow::ColStatus) == QStringLiteral("en curso"); }, 2000));
        QVERIFY2(w.replyText().endsWith(QStringLiteral(": hecho.")), qPrintable(w.replyText()));  // the reply too
        QVERIFY(w.grab().save(screenshotPath("instructor_es.png")));
        QVERIFY(i18n::install("en"));
        settle(300);

        // clear it from the menu of active faults
        QMenu* menu = w.button("ClearButton")->menu();
        emit menu->aboutToShow();
        QCOMPARE(menu->actions().size(), 1);
        menu->actions().front()->trigger();
        QVERIFY2(waitReply("done"), qPrintable(w.replyText()));
        QVERIFY(QTest::qWaitFor([&] { return !cell(InstructorWindow::ColWarnings).contains(cut); }, 5000));
    }

    void aDisplayWindowFollowsTheStream()
    {
        QVERIFY(m_instructor);
        DisplayView::Screen side;
        QVERIFY(DisplayWindow::parseScreen("centre", &side));
        QCOMPARE(side, DisplayView::Centre);
        QVERIFY(!DisplayWindow::parseScreen("middle", &side));
        DisplayWindow d(m_station, DisplayView::Centre, keyed(m_domain));
        QVERIFY(d.busError().isEmpty());
        d.resize(1280, 720);
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QVERIFY2(QTest::qWaitFor([&] { return d.feed().bundle() && !d.view()->theta().empty(); }, 20000),
                 qPrintable(d.view()->overlayText()));
        QVERIFY2(d.view()->overlayText().isEmpty(), qPrintable(d.view()->overlayText()));
        QCOMPARE(d.view()->viewport()->camera(), QStringLiteral("Operator seat"));
        QCOMPARE(d.view()->viewport()->yawOffset(), 0.0);

        // a new attempt: the machine moves from the start again, and the drawn poses with it
        m_instructor->sendCommand("start", "T0", "OP-9");
        QVERIFY2(waitReply("done"), qPrintable(m_instructor->replyText()));
        QVERIFY(QTest::qWaitFor([&] { return d.feed().latest().status == "running" && d.feed().latest().simTime > 1.0; }, 5000));
        const auto poses0 = d.view()->viewport()->poses();
        QVERIFY(QTest::qWaitFor([&] {
            const auto& p = d.view()->viewport()->poses();
            for (std::size_t i = 0; i < p.size(); ++i)
                if (!p[i].isApprox(poses0[i], 1e-6)) return true;
            return false;
        }, 5000));
        QCOMPARE(d.view()->theta().size(), std::size_t(9));
        const StateBuffer& b = d.feed().buffer();

        // paused: the view holds exactly the station's pose
        m_instructor->sendCommand("pause");
        QVERIFY2(waitReply("done"), qPrintable(m_instructor->replyText()));
        settle(400);
        std::vector<double> held;
        QVERIFY(b.at(1e9, held));
        QVERIFY(near(d.view()->theta(), held, 0.0));
        QVERIFY(d.view()->viewport()->grabFramebuffer().save(screenshotPath("display_centre.png")));
        m_instructor->sendCommand("resume");
        QVERIFY2(waitReply("done"), qPrintable(m_instructor->replyText()));

        // the station shuts down: it says so, and the display says it
        m_process->terminate();
        QVERIFY(m_process->waitForFinished(10000));
        QVERIFY2(QTest::qWaitFor([&] { return d.view()->overlayText().contains("left"); }, 5000),
                 qPrintable(d.view()->overlayText()));
        QVERIFY(QTest::qWaitFor([&] { return cell(InstructorWindow::ColPresence) == "left"; }, 5000));
        QVERIFY(!m_instructor->button("PauseButton")->isEnabled());
        QVERIFY(d.view()->grab().save(screenshotPath("display_left.png")));
    }

    void withoutAKeyTheInstructorOnlyWatches()
    {
        InstructorWindow none(centre::BusOptions::loopback(m_domain), QString());
        QVERIFY2(none.findChild<QLabel*>("KeyLabel")->text().contains("none of it is shown"),
                 qPrintable(none.findChild<QLabel*>("KeyLabel")->text()));
        // a display without the key cannot check what it would draw: it says so, draws nothing
        DisplayWindow keyless(m_station, DisplayView::Left, centre::BusOptions::loopback(m_domain));
        QVERIFY(keyless.busError().contains("--centre-key"));
        QCOMPARE(keyless.view()->overlayText(), keyless.busError());
        QVERIFY(!none.canCommand());
        QVERIFY(!none.button("StartButton")->isEnabled());
        QVERIFY(none.button("StartButton")->toolTip().contains("--centre-key"));
        // a key file that cannot be used: said in the window, watching only
        const QString bad = m_dir.filePath("bad.key");
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("not a key");
        f.close();
        f.setPermissions(QFile::ReadOwner | QFile::WriteOwner);
        InstructorWindow badKey(centre::BusOptions::loopback(m_domain), bad);
        QVERIFY(!badKey.canCommand());
        QVERIFY2(badKey.findChild<QLabel*>("KeyLabel")->text().contains("cannot be used"),
                 qPrintable(badKey.findChild<QLabel*>("KeyLabel")->text()));
        // a network DDS refuses: said on the screen, no crash
        centre::BusOptions wrong = keyed(m_domain);
        wrong.domain = 300;
        DisplayWindow display("X", DisplayView::Right, wrong);
        QVERIFY(!display.busError().isEmpty());
        QCOMPARE(display.view()->overlayText(), display.busError());
        InstructorWindow offline(wrong, m_keyFile);
        QVERIFY(!offline.canCommand());
        QVERIFY(offline.findChild<QLabel*>("KeyLabel")->text().contains("300"));
        QVERIFY(!InstructorWindow::refusalText("bad-signature").isEmpty());
        QVERIFY(InstructorWindow::refusalText("bad-signature") != "bad-signature");
    }

    // ---- DDS Security: padrob-studio's nodes with --security DIR

    void aSecuredStationIsSeenOnlyWithAnIdentity()
    {
        // the centre's PKI, and identities for the station and the instructor window
        const QString pki = m_dir.filePath("pki");
        const QString station = QStringLiteral("S-secure-%1").arg(::getpid());
        const QString instructorName = QStringLiteral("instructor-studio-%1").arg(::getpid());
        QString error;
        QVERIFY2(centre::pki::createCentre(pki, &error), qPrintable(error));
        QVERIFY2(centre::pki::issueNode(pki, station, &error), qPrintable(error));
        QVERIFY2(centre::pki::issueNode(pki, instructorName, &error), qPrintable(error));
        const int domain = 1 + static_cast<int>((::getpid() + 115) % 230);  // DDS Security: 0-230

        QProcess secured;
        secured.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        secured.start(QStringLiteral(PADROB_CLI),
                      {"station", kTut0, "--name", station, "--demo", "--for", "120", "--domain",
                       QString::number(domain), "--loopback", "--key", m_keyFile, "--security", pki});
        QVERIFY(secured.waitForStarted(5000));
        const auto stop = qScopeGuard([&] {
            secured.kill();
            secured.waitForFinished(5000);
        });

        // the instructor window as `padrob-studio --instructor --security PKI --name NAME`
        centre::BusOptions net = centre::BusOptions::loopback(domain);
        net.securityDir = pki;
        net.node = instructorName;
        InstructorWindow w(net, m_keyFile);
        QVERIFY2(w.canCommand(), qPrintable(w.findChild<QLabel*>("KeyLabel")->text()));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const auto row = [&] {
            QTableWidget* t = w.table();
            for (int r = 0; r < t->rowCount(); ++r)
                if (t->item(r, 0) && t->item(r, 0)->text() == station) return r;
            return -1;
        };
        const auto status = [&] {
            const int r = row();
            return r < 0 || !w.table()->item(r, InstructorWindow::ColStatus) ? QString()
                                                                            : w.table()->item(r, InstructorWindow::ColStatus)->text();
        };
        QVERIFY2(QTest::qWaitFor([&] { return status() == "idle"; }, 30000), "the secured station is seen");
        QVERIFY(w.selectStation(station));
        w.sendCommand("start", "T0", "OP-SEC");
        QVERIFY2(QTest::qWaitFor([&] { return w.replyText().contains("done"); }, 10000), qPrintable(w.replyText()));
        QVERIFY(QTest::qWaitFor([&] { return status() == "running"; }, 5000));
        QVERIFY(QTest::qWaitFor([&] { return !w.view()->theta().empty(); }, 5000));

        // a display without DDS Security on the same domain, in its own process (Cyclone
        // has one domain per process, secured or not): nothing of the secured station, ever
        QProcess plain;
        plain.setProcessChannelMode(QProcess::ForwardedChannels);
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("PADROB_PLAIN_DISPLAY", station + QLatin1Char(' ') + QString::number(domain));
        env.insert("PADROB_PLAIN_DISPLAY_KEY", m_keyFile);
        plain.setProcessEnvironment(env);
        plain.start(QCoreApplication::applicationFilePath(), {});
        QVERIFY(plain.waitForStarted(5000));
        QVERIFY(QTest::qWaitFor([&] { return plain.state() == QProcess::NotRunning; }, 30000));
        QCOMPARE(plain.exitStatus(), QProcess::NormalExit);
        QCOMPARE(plain.exitCode(), 0);  // 3: it saw the station; 4: it could not open its bus
        QCOMPARE(status(), QStringLiteral("running"));  // meanwhile the secured instructor saw it all along

        // a secured display without its identity: said in the window, no crash
        centre::BusOptions secureDisplay = keyed(domain);
        secureDisplay.securityDir = pki;
        DisplayWindow missing(station, DisplayView::Left, secureDisplay);
        QVERIFY(!missing.busError().isEmpty());
        QVERIFY2(missing.busError().contains(DisplayWindow::defaultNodeName(station, DisplayView::Left)),
                 qPrintable(missing.busError()));
        QCOMPARE(missing.view()->overlayText(), missing.busError());
        QCOMPARE(DisplayWindow::defaultNodeName("S 1/x", DisplayView::Right), QStringLiteral("display-S_1_x-right"));
        // with its identity (its own process, as a display PC) it sees the station
        QVERIFY2(centre::pki::issueNode(pki, DisplayWindow::defaultNodeName(station, DisplayView::Centre), &error),
                 qPrintable(error));
        QProcess securedDisplay;
        securedDisplay.setProcessChannelMode(QProcess::ForwardedChannels);
        env.insert("PADROB_PLAIN_DISPLAY", station + QLatin1Char(' ') + QString::number(domain) + QLatin1Char(' ') + pki);
        securedDisplay.setProcessEnvironment(env);
        securedDisplay.start(QCoreApplication::applicationFilePath(), {});
        QVERIFY(securedDisplay.waitForStarted(5000));
        QVERIFY(QTest::qWaitFor([&] { return securedDisplay.state() == QProcess::NotRunning; }, 30000));
        QCOMPARE(securedDisplay.exitStatus(), QProcess::NormalExit);
        QCOMPARE(securedDisplay.exitCode(), 3);
        // an instructor window with security but no identity: said, watching nothing
        centre::BusOptions noIdentity = net;
        noIdentity.node = QStringLiteral("nobody");
        InstructorWindow refused(noIdentity, m_keyFile);
        QVERIFY(!refused.canCommand());
        QVERIFY2(refused.findChild<QLabel*>("KeyLabel")->text().contains("nobody"),
                 qPrintable(refused.findChild<QLabel*>("KeyLabel")->text()));
    }
};

/// PADROB_PLAIN_DISPLAY="STATION DOMAIN [PKI]": a display window (with DDS Security when
/// PKI is given, with the centre's key of PADROB_PLAIN_DISPLAY_KEY) that watches STATION
/// for 5 s (aSecuredStationIsSeenOnlyWithAnIdentity).
/// Exit 0: it saw nothing of it; 3: it saw an announcement or a state; 4: its bus did not open.
int plainDisplay(const QString& spec)
{
    const QStringList parts = spec.split(QLatin1Char(' '));
    centre::BusOptions o = centre::BusOptions::loopback(parts.value(1).toInt());
    o.securityDir = parts.value(2);
    QString error;
    if (!o.key.load(qEnvironmentVariable("PADROB_PLAIN_DISPLAY_KEY"), &error)) {
        std::fprintf(stderr, "plain display: %s\n", qPrintable(error));
        return 4;
    }
    DisplayWindow d(parts.value(0), DisplayView::Centre, o);
    if (!d.busError().isEmpty()) {
        std::fprintf(stderr, "plain display: %s\n", qPrintable(d.busError()));
        return 4;
    }
    d.resize(640, 360);
    d.show();
    // seen: its states, not just its announcement
    // (waits its time either way: what it saw is judged below)
    [[maybe_unused]] const bool states =
        QTest::qWaitFor([&] { return d.feed().buffer().size() > 1; }, o.securityDir.isEmpty() ? 5000 : 20000);
    const bool saw = d.feed().bundle() || !d.feed().latest().station.empty() || d.feed().buffer().size() > 0 ||
                     !d.view()->theta().empty() || d.feed().presence(centreClock()) != DisplayFeed::Presence::Waiting;
    if (saw && o.securityDir.isEmpty()) std::fprintf(stderr, "plain display: it saw the secured station\n");
    return saw ? 3 : 0;
}

int main(int argc, char** argv)
{
    QSurfaceFormat::setDefaultFormat(Viewport::surfaceFormat());
    QApplication app(argc, argv);
    if (qEnvironmentVariableIsSet("PADROB_PLAIN_DISPLAY")) return plainDisplay(qEnvironmentVariable("PADROB_PLAIN_DISPLAY"));
    CentreTest test;
    return QTest::qExec(&test, argc, argv);
}

#include "centre_test.moc"
