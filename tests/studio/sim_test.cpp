// Tests of padrob-studio's solver thread (SimulationRunner) and keyboard input:
// a run is the same as a plain solver::Simulation stepped by hand (determinism),
// single steps, reset, slow motion, a loop that locks up, pacing (reported), and the
// keyboard mapping.

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/keyboard_input.h"
#include "ide/studio/sim/simulation_runner.h"
#include "ide/studio/sim/snapshot.h"

#include "solver/integrate/simulation.h"
#include "trainer/station/profile_store.h"
#include "trainer/station/station.h"

#include "tests/studio/virtual_pad.h"

#include <SDL.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QKeyEvent>
#include <QSignalSpy>
#include <QTest>
#include <QWidget>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

using studio::KeyboardInput;
using studio::SimulationRunner;
using studio::Snapshot;

namespace {

using studio::test::VirtualPad;

QString modelText(const QString& name)
{
    QFile f(QStringLiteral(PADROB_SOURCE_DIR "/models/") + name);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll());
}

std::shared_ptr<const studio::ModelBundle> bundleOf(const QString& text, const QString& name)
{
    solver::Diagnostics diags(name.toStdString());
    auto bundle = studio::makeBundle(text, name, diags);
    if (!bundle) {
        for (const solver::Diagnostic& d : diags) qWarning("%s", d.format().c_str());
    }
    return bundle;
}

std::shared_ptr<const studio::ModelBundle> example(const QString& name)
{
    return bundleOf(modelText(name), name);
}

/// The slider-crank driven by a hydraulic piston into its dead centre (x = 0.45 m at
/// 0.1 m/s from 0.389 m: the loop locks up at t ≈ 0.61 s).
std::shared_ptr<const studio::ModelBundle> lockingSliderCrank()
{
    QString text = modelText("slider_crank.pad");
    text.replace(QStringLiteral("C 4 T 2 QI 0.39"), QStringLiteral("C 4 T 2 LL 0.2 UL 0.46 QI 0.39"));
    text.replace(QStringLiteral("D 1 MOTOR T0 2.0 W0 31.416"), QString());
    text += QStringLiteral("\nD 4 HYD VMAX 0.1\n");
    return bundleOf(text, QStringLiteral("slider_crank_locking.pad"));
}

solver::SimulationOptions rk4(double h)
{
    solver::SimulationOptions o;
    o.integrator.method = solver::IntegrationMethod::Rk4Fixed;
    o.integrator.step = h;
    return o;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Waits (processing events) until the runner's snapshot says it is paused.
bool waitPaused(const SimulationRunner& r, int ms = 2000)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms) {
        auto s = r.latest();
        if (s && !s->running) return true;
        QTest::qWait(5);
    }
    return false;
}

double processCpuSeconds()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

}  // namespace

class SimTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void initialSnapshotIsPaused();
    void stepOnceAdvancesOneStep();
    void runMatchesPlainSimulation();
    void resetReturnsToInitialState();
    void setSpeedHalvesSimulatedTime();
    void lockUpReportsFailedAndPauses();
    void newBundleReplacesRunningSimulation();
    void destructionStopsTheThread();
    void commandsAreOneSnapshot();
    void stepPeriodHistogram();
    void pacingReport();
    void tooHeavyRunsBehindAndStaysResponsive();
    void keyboardMapsDrivesInJointIdOrder();
    void keyboardWritesCommands();
    void virtualGamepadDrivesTheMachineThroughTheStation();
    void stationLatencyReport();

private:
    std::shared_ptr<const studio::ModelBundle> m_pendulum, m_liner;
};

void SimTest::initTestCase()
{
    m_pendulum = example(QStringLiteral("pendulum.pad"));
    m_liner = example(QStringLiteral("liner_manipulator.pad"));
    QVERIFY(m_pendulum);
    QVERIFY(m_liner);
}

void SimTest::initialSnapshotIsPaused()
{
    SimulationRunner r;
    QVERIFY(!r.latest());
    QSignalSpy bundles(&r, &SimulationRunner::bundleChanged);
    r.setBundle(m_liner);
    QCOMPARE(bundles.count(), 1);
    auto s = r.latest();  // published at once, in the GUI thread
    QVERIFY(s);
    const solver::Model& m = *m_liner->model;
    QCOMPARE(s->bundle, m_liner);
    QCOMPARE(s->step, 0L);
    QCOMPARE(s->t, 0.0);
    QCOMPARE(s->timeStep, SimulationRunner::kDefaultTimeStep);
    QVERIFY(!s->running);
    QVERIFY(!r.isRunning());
    QCOMPARE(int(s->bodyPoses.size()), m.nb);
    QCOMPARE(int(s->theta.size()), m.nb);
    QCOMPARE(int(s->q.size()), m.nb);
    QCOMPARE(int(s->reactionJoint.size()), m.nb);
    QVERIFY(s->eventLog && s->eventLog->empty());
    const int lift = m.jointIndex(2);
    QCOMPARE(s->theta[lift], m.theta0[std::size_t(lift)]);
    QVERIFY(std::abs(s->q[lift] - 1.464) < 1e-9);  // the modeler's coordinate: the cylinder's length
    QVERIFY(s->driveForce[lift] > 1e5);             // holds the boom
    QVERIFY(std::isfinite(s->energy));
    QCOMPARE(int(r.commands().size()), m.nb);
    r.setBundle(nullptr);
    QVERIFY(!r.latest());
    r.start();  // no model: nothing
    QVERIFY(!r.isRunning());
}

void SimTest::stepOnceAdvancesOneStep()
{
    SimulationRunner r;
    r.setBundle(m_pendulum);
    const double h = r.timeStep();
    r.stepOnce();
    QTRY_COMPARE(r.latest()->step, 1L);
    auto s = r.latest();
    QCOMPARE(s->t, h);
    QVERIFY(!s->running);

    solver::Simulation ref(m_pendulum->model, rk4(h));
    std::vector<solver::SimulationEvent> events;
    std::string error;
    QVERIFY(ref.advanceTo(h, events, error));
    QVERIFY(sameBits(s->theta[0], ref.state().q[0]));
    QVERIFY(sameBits(s->qd[0], ref.state().qd[0]));

    for (int i = 0; i < 3; ++i) r.stepOnce();
    QTRY_COMPARE(r.latest()->step, 4L);
    QTest::qWait(50);  // and no more
    QCOMPARE(r.latest()->step, 4L);
    QCOMPARE(r.latest()->t, 4 * h);
}

void SimTest::runMatchesPlainSimulation()
{
    // the liner manipulator lifting its boom (joint 2, hydraulic) for about a second
    SimulationRunner r;
    r.setBundle(m_liner);
    const solver::Model& m = *m_liner->model;
    const int lift = m.jointIndex(2);
    QVERIFY(lift >= 0);
    r.setCommand(lift, 1.0);
    QSignalSpy states(&r, &SimulationRunner::stateChanged);
    r.start();
    QVERIFY(r.isRunning());
    QCOMPARE(states.count(), 1);
    QCOMPARE(states.at(0).at(0).toBool(), true);
    QTest::qWait(1000);
    r.pause();
    QCOMPARE(states.count(), 2);
    QCOMPARE(states.at(1).at(0).toBool(), false);
    QVERIFY(waitPaused(r));
    auto s = r.latest();
    QVERIFY2(s->step > 300, qPrintable(QString::number(s->step)));
    QVERIFY(s->error.empty());
    const double h = s->timeStep;
    QCOMPARE(s->t, double(s->step) * h);
    QCOMPARE(s->u[lift], 1.0);

    // the same steps by hand
    solver::Simulation ref(m_liner->model, rk4(h));
    ref.setCommand(lift, 1.0);
    std::vector<solver::SimulationEvent> events;
    std::string error;
    for (long k = 0; k < s->step; ++k) QVERIFY2(ref.advanceTo(double(k + 1) * h, events, error), error.c_str());
    QCOMPARE(s->t, ref.state().t);
    for (int i = 0; i < m.nb; ++i) {
        QVERIFY2(sameBits(s->theta[i], ref.state().q[i]),
                 qPrintable(QStringLiteral("joint %1: %2 vs %3").arg(i).arg(s->theta[i], 0, 'g', 17)
                                .arg(ref.state().q[i], 0, 'g', 17)));
        QVERIFY(sameBits(s->driveForce[i], ref.data().driveForce[i]));
    }
    // the boom's cylinder extends at its pump speed (0.0180 m/s)
    const double q0 = m.coordinate(lift, m.theta0[std::size_t(lift)]);
    QVERIFY(std::abs((s->q[lift] - q0) / s->t - 0.0180) < 0.0005);
    // the paused runner does not move on
    QTest::qWait(50);
    QCOMPARE(r.latest()->step, s->step);
}

void SimTest::resetReturnsToInitialState()
{
    SimulationRunner r;
    r.setBundle(m_pendulum);
    const solver::Model& m = *m_pendulum->model;
    auto initial = r.latest();
    r.setCommand(0, 0.5);  // (the pendulum has no drive: a command is just kept)
    r.setSpeed(2);
    r.start();
    QTest::qWait(200);
    QVERIFY(r.latest()->step > 0);
    QSignalSpy restarted(&r, &SimulationRunner::restarted);
    QSignalSpy states(&r, &SimulationRunner::stateChanged);
    r.reset();
    QCOMPARE(restarted.count(), 1);
    QCOMPARE(states.count(), 1);
    QCOMPARE(states.at(0).at(0).toBool(), false);
    QVERIFY(!r.isRunning());
    auto s = r.latest();  // at once
    QCOMPARE(s->step, 0L);
    QCOMPARE(s->t, 0.0);
    QVERIFY(!s->running);
    QCOMPARE(s->theta[0], m.theta0[0]);
    QCOMPARE(s->qd[0], m.thetaDot0[0]);
    QCOMPARE(s->energy, initial->energy);
    QCOMPARE(r.commands()[0], 0.5);  // kept
    QCOMPARE(r.speed(), 2.0);        // kept
    QTest::qWait(50);  // nothing of the old run comes back
    QCOMPARE(r.latest()->step, 0L);
    r.stepOnce();
    QTRY_COMPARE(r.latest()->step, 1L);
    QCOMPARE(r.latest()->u[0], 0.5);
    r.setSpeed(100);
    QCOMPARE(r.speed(), SimulationRunner::kMaxSpeed);
    r.setSpeed(0);
    QCOMPARE(r.speed(), SimulationRunner::kMinSpeed);
}

void SimTest::setSpeedHalvesSimulatedTime()
{
    SimulationRunner r;
    r.setBundle(m_pendulum);
    r.setSpeed(0.5);
    QElapsedTimer wall;
    r.start();
    wall.start();
    QTest::qWait(1500);
    auto running = r.latest();
    r.pause();
    const double seconds = double(wall.nsecsElapsed()) * 1e-9;
    QVERIFY(waitPaused(r));
    auto s = r.latest();
    const double ratio = s->t / seconds;
    qInfo("speed 0.5: %.3f s simulated in %.3f s wall (%.3f); snapshot realTimeFactor %.3f, speed %.2f", s->t,
          seconds, ratio, running->realTimeFactor, running->speed);
    QVERIFY2(ratio > 0.3 && ratio < 0.6, qPrintable(QString::number(ratio)));
    QVERIFY(running->realTimeFactor > 0.3 && running->realTimeFactor < 0.7);
    QCOMPARE(running->speed, 0.5);
    QCOMPARE(s->realTimeFactor, 0.0);  // paused
}

void SimTest::lockUpReportsFailedAndPauses()
{
    auto crank = lockingSliderCrank();
    QVERIFY(crank);
    const solver::Model& m = *crank->model;
    const int piston = m.jointIndex(4);
    QVERIFY(piston >= 0);
    QVERIFY(m.drive[std::size_t(piston)].type == solver::DriveType::Hydraulic);
    SimulationRunner r;
    r.setBundle(crank);
    r.setCommand(piston, 1.0);
    QSignalSpy failed(&r, &SimulationRunner::failed);
    QSignalSpy states(&r, &SimulationRunner::stateChanged);
    r.setSpeed(2);
    r.start();
    QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, 5000);
    const QString message = failed.at(0).at(0).toString();
    qInfo("failed: %s", qPrintable(message));
    QVERIFY(message.contains(QStringLiteral("locked up at t = 0.6")));
    QVERIFY(!r.isRunning());
    QCOMPARE(states.count(), 2);
    QCOMPARE(states.last().at(0).toBool(), false);
    auto s = r.latest();
    QVERIFY(!s->running);
    QVERIFY(!s->error.empty());
    QVERIFY2(s->t > 0.55 && s->t < 0.65, qPrintable(QString::number(s->t)));
    QVERIFY(s->q[piston] > 0.44 && s->q[piston] <= 0.45 + 1e-9);
    for (int i = 0; i < m.nb; ++i) QVERIFY(std::isfinite(s->theta[i]));
    QVERIFY(!s->eventLog->empty());
    QVERIFY(s->eventLog->back().kind == solver::SimulationEvent::Kind::LoopLocked);
    // stays stopped until reset
    r.start();
    r.stepOnce();
    QVERIFY(!r.isRunning());
    QTest::qWait(50);
    QCOMPARE(r.latest()->step, s->step);
    QCOMPARE(failed.count(), 1);
    r.reset();
    QVERIFY(r.latest()->error.empty());
    QCOMPARE(r.latest()->step, 0L);
    r.stepOnce();
    QTRY_COMPARE(r.latest()->step, 1L);
}

void SimTest::newBundleReplacesRunningSimulation()
{
    SimulationRunner r;
    r.setBundle(m_liner);
    r.start();
    QTest::qWait(100);
    QSignalSpy states(&r, &SimulationRunner::stateChanged);
    r.setBundle(m_pendulum);
    QCOMPARE(states.count(), 1);
    QCOMPARE(r.latest()->bundle, m_pendulum);
    for (int i = 0; i < 10; ++i) {
        QTest::qWait(10);
        QCOMPARE(r.latest()->bundle, m_pendulum);  // never the old model's steps again
        QCOMPARE(r.latest()->step, 0L);
    }
    QCOMPARE(int(r.commands().size()), 1);
}

void SimTest::destructionStopsTheThread()
{
    auto crank = lockingSliderCrank();
    for (int i = 0; i < 3; ++i) {
        auto r = std::make_unique<SimulationRunner>();
        r->setBundle(i == 2 ? crank : m_liner);
        r->setCommand(i == 2 ? crank->model->jointIndex(4) : 3, 1.0);
        r->setSpeed(4);
        r->start();
        // the third locks up meanwhile: its signals are still queued when it goes
        std::this_thread::sleep_for(std::chrono::milliseconds(i == 2 ? 400 : 50));
        QElapsedTimer clock;
        clock.start();
        r.reset();
        QVERIFY(clock.elapsed() < 200);
    }
    QTest::qWait(20);
}

void SimTest::commandsAreOneSnapshot()
{
    SimulationRunner r;
    r.setBundle(m_liner);
    const int nb = m_liner->model->nb;
    std::vector<double> u(std::size_t(nb), 0.0);
    u[0] = 2;    // clamped
    u[1] = -0.5;
    u[2] = std::nan("");
    r.setCommands(u);
    std::vector<double> c = r.commands();
    QCOMPARE(c[0], 1.0);
    QCOMPARE(c[1], -0.5);
    QCOMPARE(c[2], 0.0);
    r.setCommands(std::vector<double>{0.25});  // missing ones are 0
    c = r.commands();
    QCOMPARE(c[0], 0.25);
    QCOMPARE(c[1], 0.0);
    r.setCommand(nb, 1);  // out of range: ignored
    r.setCommand(-1, 1);
    r.stepOnce();
    QTRY_COMPARE(r.latest()->step, 1L);
    QCOMPARE(r.latest()->u[0], 0.25);
    QCOMPARE(r.latest()->u[1], 0.0);
}

void SimTest::stepPeriodHistogram()
{
    studio::StepPeriodHistogram h;
    QCOMPARE(h.median(), 0.0);
    QCOMPARE(h.maxJitter(1000), 0.0);
    for (int i = 0; i < 1000; ++i) h.add(1000.0 + (i % 10));  // 100 each of 1000 … 1009 µs
    h.add(2500.4);
    h.add(12345.0);   // a coarse bin: [12300, 12400)
    h.add(250000.0);  // beyond 100 ms
    QCOMPARE(h.count, 1003L);
    QCOMPARE(h.minMicros, 1000.0);
    QCOMPARE(h.maxMicros, 250000.0);
    QCOMPARE(h.median(), 1005.5);            // rank 502
    QCOMPARE(h.percentile(0.99), 1009.5);    // rank 993
    QCOMPARE(h.percentile(0.9985), 12350.0); // rank 1002
    QCOMPARE(h.percentile(1.0), 250000.0);
    QCOMPARE(h.percentile(0.0), 1000.5);
    QCOMPARE(h.maxJitter(1000), 249000.0);
    QCOMPARE(studio::StepPeriodHistogram::bin(-3), 0);
    QCOMPARE(studio::StepPeriodHistogram::bin(4999.9), 4999);
    QCOMPARE(studio::StepPeriodHistogram::bin(5000), studio::StepPeriodHistogram::kFineBins);
    QCOMPARE(studio::StepPeriodHistogram::bin(1e9), studio::StepPeriodHistogram::kBins - 1);
    studio::StepPeriodHistogram other;
    other.add(990);
    h.merge(other);
    QCOMPARE(h.count, 1004L);
    QCOMPARE(h.minMicros, 990.0);
    QCOMPARE(h.maxJitter(1000), 249000.0);
    studio::StepPeriodHistogram empty;
    empty.merge(other);
    QCOMPARE(empty.count, 1L);
    QCOMPARE(empty.maxMicros, 990.0);
}

void SimTest::pacingReport()
{
    // the liner slewing (joint 1) for 10 s at speed 1, polled like the GUI does (60 Hz)
    SimulationRunner r;
    r.setBundle(m_liner);
    const int slew = m_liner->model->jointIndex(1);
    r.setCommand(slew, 1.0);
    const double cpu0 = processCpuSeconds();
    QElapsedTimer wall;
    r.resetStepPeriods();
    r.start();
    wall.start();
    double worstLatestMicros = 0;
    std::shared_ptr<const Snapshot> last;
    int polls = 0;
    while (wall.elapsed() < 10000) {
        QTest::qWait(16);
        const auto t0 = std::chrono::steady_clock::now();
        last = r.latest();
        const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
        worstLatestMicros = std::max(worstLatestMicros, us);
        ++polls;
        if (polls % 60 == 0) {
            qInfo("t %6.3f s  rtf %.4f  step %.1f us  period %.1f us (max %.0f)  cpu %.1f%%  overruns %ld", last->t,
                  last->realTimeFactor, last->stepMicros, last->stepPeriodMicros, last->stepPeriodMaxMicros,
                  100 * last->cpuLoad, last->overruns);
        }
    }
    const double seconds = double(wall.nsecsElapsed()) * 1e-9;
    const double cpu = processCpuSeconds() - cpu0;
    r.pause();
    QVERIFY(waitPaused(r));
    auto s = r.latest();
    qInfo("pacing (liner, 1 ms RK4, speed 1, 10 s): simulated %.3f s in %.3f s wall (overall factor %.4f)", s->t,
          seconds, s->t / seconds);
    qInfo("  last second: real-time factor %.4f, median step period %.1f us (max %.0f us), median step compute "
          "%.1f us, solver thread CPU %.1f%% of a core",
          last->realTimeFactor, last->stepPeriodMicros, last->stepPeriodMaxMicros, last->stepMicros,
          100 * last->cpuLoad);
    qInfo("  overruns %ld, dropped %.3f s; process CPU %.1f%% of a core (GUI thread polling included); "
          "latest() worst %.1f us over %d polls",
          s->overruns, s->droppedSeconds, 100 * cpu / seconds, worstLatestMicros, polls);
    // every paced step's period, in the runner's histogram
    const studio::StepPeriodHistogram h = r.stepPeriods();
    qInfo("  step period over the run (%ld steps): median %.1f us, 99%% %.1f us, 99.9%% %.1f us, max %.0f us, "
          "max jitter %.0f us",
          h.count, h.median(), h.percentile(0.99), h.percentile(0.999), h.maxMicros, h.maxJitter(1000));
    QVERIFY(s->error.empty());
    QVERIFY2(last->realTimeFactor > 0.5 && last->realTimeFactor < 1.5, qPrintable(QString::number(last->realTimeFactor)));
    QVERIFY(s->t / seconds > 0.5 && s->t / seconds < 1.5);
    QVERIFY(last->stepPeriodMicros > 0);
    QVERIFY2(h.count > s->step / 2 && h.count <= s->step, qPrintable(QString::number(h.count)));
    QVERIFY(h.median() > 0);
    QVERIFY(h.percentile(0.99) >= h.median());
    QVERIFY(h.percentile(0.999) >= h.percentile(0.99));
    QVERIFY(h.maxMicros >= h.percentile(0.999));
    // a reset while paused: nothing counted until the next paced step
    r.resetStepPeriods();
    QCOMPARE(r.stepPeriods().count, 0L);
    r.start();
    QTRY_VERIFY(r.stepPeriods().count > 10);
    r.pause();
}

void SimTest::tooHeavyRunsBehindAndStaysResponsive()
{
    // 10 µs steps of the excavator (a closed loop: the dense constrained path, ~15 µs a
    // step here) at speed 4 (400,000 steps a second) need several cores: the runner
    // falls behind, gives up catching up, keeps publishing, and still pauses at once.
    // (The liner manipulator, at ~2.5 µs a step, now keeps up with this.)
    const auto excavator = example(QStringLiteral("excavator.pad"));
    QVERIFY(excavator);
    SimulationRunner r;
    r.setTimeStep(1e-5);
    r.setSpeed(4);
    r.setBundle(excavator);
    QCOMPARE(r.latest()->timeStep, 1e-5);
    r.start();
    long lastStep = -1;
    int updates = 0;
    for (int i = 0; i < 60; ++i) {
        QTest::qWait(16);
        const long step = r.latest()->step;
        if (step != lastStep) ++updates;
        lastStep = step;
    }
    auto s = r.latest();
    qInfo("too heavy: rtf %.3f, dropped %.3f s, overruns %ld, step %.1f us, %d of 60 polls saw a new snapshot",
          s->realTimeFactor, s->droppedSeconds, s->overruns, s->stepMicros, updates);
    QVERIFY(s->running);
    QVERIFY(s->realTimeFactor < 0.9 * 4);
    QVERIFY(s->droppedSeconds > 0.1);
    QVERIFY(s->overruns > 0);
    QVERIFY(updates > 30);
    QElapsedTimer clock;
    clock.start();
    r.pause();
    QVERIFY(waitPaused(r, 1000));
    qInfo("paused after %lld ms", clock.elapsed());
    QVERIFY(clock.elapsed() < 200);
}

void SimTest::keyboardMapsDrivesInJointIdOrder()
{
    SimulationRunner r;
    KeyboardInput keys(&r);
    QVERIFY(keys.bindings().isEmpty());
    QSignalSpy changed(&keys, &KeyboardInput::bindingsChanged);
    r.setBundle(m_liner);
    QCOMPARE(changed.count(), 1);
    const auto& b = keys.bindings();
    QCOMPARE(b.size(), 9);  // the liner's nine drives
    const int plus[] = {Qt::Key_Q, Qt::Key_W, Qt::Key_E, Qt::Key_R, Qt::Key_T, Qt::Key_Y, Qt::Key_U, Qt::Key_I, Qt::Key_O};
    const int minus[] = {Qt::Key_A, Qt::Key_S, Qt::Key_D, Qt::Key_F, Qt::Key_G, Qt::Key_H, Qt::Key_J, Qt::Key_K, Qt::Key_L};
    for (int k = 0; k < 9; ++k) {
        QCOMPARE(b[k].jointId, k + 1);
        QCOMPARE(b[k].plusKey, plus[k]);
        QCOMPARE(b[k].minusKey, minus[k]);
        QCOMPARE(b[k].treeJoint, m_liner->model->jointIndex(k + 1));
    }
    QCOMPARE(b[1].jointName, QStringLiteral("LEVANTE PLUMA"));
    QCOMPARE(b[1].keysText(), QStringLiteral("W / S"));
    const QStringList lines = keys.describe();
    QCOMPARE(lines.size(), 9);
    QVERIFY(lines[1].contains(QStringLiteral("W / S")));
    QVERIFY(lines[1].contains(QStringLiteral("LEVANTE PLUMA")));
    qInfo("%s", qPrintable(lines.join(QLatin1Char('\n'))));
    r.setBundle(m_pendulum);  // no drives
    QVERIFY(keys.bindings().isEmpty());
}

void SimTest::keyboardWritesCommands()
{
    SimulationRunner r;
    KeyboardInput keys(&r);
    r.setBundle(m_liner);
    const int slew = m_liner->model->jointIndex(1), lift = m_liner->model->jointIndex(2);
    QWidget w;
    w.resize(200, 100);
    keys.attachTo(&w);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QSignalSpy commandSpy(&keys, &KeyboardInput::commandChanged);

    QTest::keyPress(&w, Qt::Key_W);
    QCOMPARE(r.commands()[std::size_t(lift)], 1.0);
    QCOMPARE(keys.command(lift), 1.0);
    QCOMPARE(commandSpy.count(), 1);
    // auto-repeat is ignored: no extra command
    QKeyEvent repeat(QEvent::KeyPress, Qt::Key_W, Qt::NoModifier, QStringLiteral("w"), true);
    QCoreApplication::sendEvent(&w, &repeat);
    QCOMPARE(commandSpy.count(), 1);
    QTest::keyRelease(&w, Qt::Key_W);
    QCOMPARE(r.commands()[std::size_t(lift)], 0.0);
    QTest::keyPress(&w, Qt::Key_A);
    QCOMPARE(r.commands()[std::size_t(slew)], -1.0);
    QTest::keyPress(&w, Qt::Key_Q);  // both keys of a pair: 0
    QCOMPARE(r.commands()[std::size_t(slew)], 0.0);
    QTest::keyRelease(&w, Qt::Key_A);
    QCOMPARE(r.commands()[std::size_t(slew)], 1.0);
    // Ctrl+W is a shortcut, not the boom
    QTest::keyPress(&w, Qt::Key_W, Qt::ControlModifier);
    QCOMPARE(r.commands()[std::size_t(lift)], 0.0);
    QTest::keyRelease(&w, Qt::Key_W, Qt::ControlModifier);
    // an unmapped key passes through
    QTest::keyPress(&w, Qt::Key_Z);
    QCOMPARE(commandSpy.count(), 5);
    // losing the focus releases everything
    QFocusEvent out(QEvent::FocusOut, Qt::ActiveWindowFocusReason);
    QCoreApplication::sendEvent(&w, &out);
    QCOMPARE(r.commands()[std::size_t(slew)], 0.0);
    // the runner takes the command at its next step
    QTest::keyPress(&w, Qt::Key_S);
    r.stepOnce();
    QTRY_COMPARE(r.latest()->step, 1L);
    QCOMPARE(r.latest()->u[lift], -1.0);
    keys.setEnabled(false);
    QCOMPARE(r.commands()[std::size_t(lift)], 0.0);
    QTest::keyPress(&w, Qt::Key_S);
    QCOMPARE(r.commands()[std::size_t(lift)], 0.0);
}

// The whole path with SDL's virtual gamepad (no hardware): axis → calibration →
// mapping → bank switch by button → u in the solver → the joint moves; a lever held
// through a bank switch waits for the centre; unplugging closes the valves.
void SimTest::virtualGamepadDrivesTheMachineThroughTheStation()
{
    VirtualPad vp;
    QVERIFY2(vp.pad, SDL_GetError());
    SDL_Joystick* pad = vp.pad;

    SimulationRunner r;
    r.setBundle(m_liner);
    const solver::Model& m = *m_liner->model;
    const auto lift = std::size_t(m.jointIndex(2)), wristLift = std::size_t(m.jointIndex(5));
    {
        trainer::Station station([&r](std::span<const double> u) { r.setCommands(u); });
        station.start(true);
        trainer::ProfileStore store(QDir::temp().filePath("padrob-sim-test-profiles"));
        trainer::StationProfile profile;
        QList<trainer::ProfileIssue> issues;
        QVERIFY(store.load(PADROB_SOURCE_DIR "/models/liner_manipulator.pad", "Gamepad", profile, issues));
        const QList<trainer::DriveInfo> drives = trainer::drivesOf(m);
        station.call([&](trainer::StationEngine& e) {
            e.setDrives(m.nb, drives);
            issues = e.setProfile(profile);
        });
        QVERIFY(issues.isEmpty());
        auto connected = [&] {
            auto st = station.latest();
            if (!st) return false;
            for (const trainer::DeviceState& d : st->devices)
                if (d.info.kind == trainer::DeviceKind::Gamepad && d.status == trainer::DeviceStatus::Connected)
                    return true;
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(connected(), 3000);
        QTRY_COMPARE_WITH_TIMEOUT(station.latest()->bankNames.value(station.latest()->activeBank), QString("Boom"), 2000);

        // bank Boom: pull the left stick back → C 2 LEVANTE PLUMA lifts
        SDL_JoystickSetVirtualAxis(pad, SDL_CONTROLLER_AXIS_LEFTY, 32767);
        QTRY_COMPARE_WITH_TIMEOUT(r.commands()[lift], 1.0, 2000);
        QCOMPARE(r.commands()[wristLift], 0.0);
        const double lift0 = r.latest()->q[Eigen::Index(lift)];
        r.start();
        QTRY_VERIFY_WITH_TIMEOUT(r.latest()->t > 0.3, 3000);
        QVERIFY2(r.latest()->q[Eigen::Index(lift)] > lift0 + 0.003, "the boom's cylinder did not extend (18 mm/s at full flow)");

        // the right shoulder button selects bank Wrist; the stick still held back must
        // neither keep lifting the boom nor jump the wrist
        SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, 1);
        QTRY_COMPARE_WITH_TIMEOUT(station.latest()->activeBank, 1, 2000);
        SDL_JoystickSetVirtualButton(pad, SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, 0);
        QTRY_COMPARE_WITH_TIMEOUT(r.commands()[lift], 0.0, 2000);
        QTest::qWait(50);
        QCOMPARE(r.commands()[wristLift], 0.0);
        QVERIFY(station.latest()->warnings.join("\n").contains("LEVANTE MUÑECA"));
        const double wrist0 = r.latest()->q[Eigen::Index(wristLift)];
        SDL_JoystickSetVirtualAxis(pad, SDL_CONTROLLER_AXIS_LEFTY, 0);
        QTRY_VERIFY_WITH_TIMEOUT(station.latest()->warnings.isEmpty(), 2000);
        SDL_JoystickSetVirtualAxis(pad, SDL_CONTROLLER_AXIS_LEFTY, -32768);  // push: the wrist lowers
        QTRY_COMPARE_WITH_TIMEOUT(r.commands()[wristLift], -1.0, 2000);
        const double t1 = r.latest()->t;
        QTRY_VERIFY_WITH_TIMEOUT(r.latest()->t > t1 + 0.3, 3000);
        QVERIFY2(r.latest()->q[Eigen::Index(wristLift)] < wrist0 - 0.002, "the wrist's cylinder did not retract");
        QCOMPARE(r.commands()[lift], 0.0);

        // unplugged: valves closed, a warning that names the pad
        vp.unplug();
        QTRY_COMPARE_WITH_TIMEOUT(r.commands()[wristLift], 0.0, 2000);
        QTRY_VERIFY_WITH_TIMEOUT(station.latest()->warnings.join("\n").contains("Padrob test gamepad"), 2000);
        r.pause();
        station.stop();
    }
}

// Input-to-solver latency (a report, not a timed test): from the moment SDL's virtual
// pad's axis moves to the first solver step that uses the new command, through the
// station's input thread and the runner. Target: under one station period (1 ms) plus
// one solver step (1 ms) plus the runner's publishing (up to a batch, 1 ms).
void SimTest::stationLatencyReport()
{
    VirtualPad vp;
    QVERIFY2(vp.pad, SDL_GetError());
    SimulationRunner r;
    r.setBundle(m_liner);
    const solver::Model& m = *m_liner->model;
    const auto slew = Eigen::Index(m.jointIndex(1));
    trainer::Station station([&r](std::span<const double> u) { r.setCommands(u); });
    station.start(true);
    trainer::StationProfile profile;
    profile.name = "latency";
    profile.always.append({"gamepad", SDL_CONTROLLER_AXIS_LEFTX, 1, 1.0, 1});
    profile.banks.append({"-", {}, {}});
    station.call([&](trainer::StationEngine& e) {
        e.setDrives(m.nb, trainer::drivesOf(m));
        e.setProfile(profile);
    });
    QTRY_VERIFY_WITH_TIMEOUT(station.latest() && !station.latest()->devices.isEmpty() &&
                                 station.latest()->warnings.isEmpty() && station.latest()->setupWarnings.isEmpty(),
                             3000);
    r.start();
    std::vector<double> micros;
    for (int i = 0; i < 60; ++i) {
        const double target = (i % 2) ? 0.0 : 0.5;
        QTest::qWait(7);  // the machine runs a little between moves
        const auto t0 = std::chrono::steady_clock::now();
        SDL_JoystickSetVirtualAxis(vp.pad, SDL_CONTROLLER_AXIS_LEFTX, Sint16(target * 32767.0));
        for (;;) {
            const auto s = r.latest();
            if (std::abs(s->u[slew] - target) < 1e-3) break;
            QVERIFY2(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(2), "the command never arrived");
            std::this_thread::sleep_for(std::chrono::microseconds(50));
        }
        micros.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    }
    r.pause();
    station.stop();
    std::sort(micros.begin(), micros.end());
    qInfo("input-to-solver latency (virtual pad → station thread → runner → step using it), %zu moves: "
          "median %.0f us, 90%% %.0f us, max %.0f us",
          micros.size(), micros[micros.size() / 2], micros[micros.size() * 9 / 10], micros.back());
}

QTEST_MAIN(SimTest)
#include "sim_test.moc"
