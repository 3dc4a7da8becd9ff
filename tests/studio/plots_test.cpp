// Tests of padrob-studio's live plots (PlotPanel): the signal list, series fed by
// synthetic snapshots, the window and downsampling, reset, CSV and PNG export, and a
// panel following a running SimulationRunner (screenshots in PADROB_SCREENSHOT_DIR).

#include "ide/i18n/language.h"
#include "ide/studio/model/model_bundle.h"
#include "ide/studio/plots/plot_panel.h"
#include "ide/studio/sim/simulation_runner.h"
#include "ide/studio/sim/snapshot.h"
#include "tests/studio/gui_test.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QLineSeries>
#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QValueAxis>

#include <cmath>
#include <memory>
#include <numbers>

using studio::PlotPanel;
using studio::Snapshot;

namespace {

/// Degrees per radian: the plots show a revolute joint's angle in degrees, as the sliders.
constexpr double kDeg = 180 / std::numbers::pi;

std::shared_ptr<const studio::ModelBundle> example(const QString& name)
{
    QFile f(QStringLiteral(PADROB_SOURCE_DIR "/models/") + name);
    if (!f.open(QIODevice::ReadOnly)) return nullptr;
    solver::Diagnostics diags(name.toStdString());
    return studio::makeBundle(QString::fromUtf8(f.readAll()), name, diags);
}

/// A pendulum snapshot at t: q = sin t, q̇ = cos t, reaction [t, 2t, 3t, 10t, 20t, 30t], energy 5.
Snapshot pendulumAt(const std::shared_ptr<const studio::ModelBundle>& bundle, double t)
{
    Snapshot s;
    s.bundle = bundle;
    s.t = t;
    s.theta = Eigen::VectorXd::Constant(1, std::sin(t));
    s.q = s.theta;
    s.qd = Eigen::VectorXd::Constant(1, std::cos(t));
    s.u = Eigen::VectorXd::Zero(1);
    s.driveForce = Eigen::VectorXd::Zero(1);
    solver::Vector6d r;
    r << t, 2 * t, 3 * t, 10 * t, 20 * t, 30 * t;
    s.reactionJoint = {r};
    s.energy = 5;
    return s;
}

QString screenshotDir()
{
    const QString dir = QStringLiteral(PADROB_SCREENSHOT_DIR);
    QDir().mkpath(dir);
    return dir;
}

/// Pixels that are not the background's colour, and distinct colours.
void imageStats(const QImage& image, double& inked, int& colours)
{
    const QRgb background = image.pixel(2, 2);
    QSet<QRgb> seen;
    long count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            if (p != background) ++count;
            if (seen.size() < 1000) seen.insert(p);
        }
    }
    inked = double(count) / double(image.width() * image.height());
    colours = int(seen.size());
}

}  // namespace

class PlotsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void listsSignalsOfEveryJoint();
    void plotsSelectedSignals();
    void windowAndDownsampling();
    void resetAndNewModelClear();
    void exportCsvReadsBack();
    void exportPngIsNotBlank();
    void followsRunner();
    void pausedThePlotEndsWhereTheSimulationStands();
    void spanishAtRunTimeKeepsTheCsvDecimalPoint();
    void overlaysSignalsOfAnyUnitsInAChosenChart();

private:
    std::shared_ptr<const studio::ModelBundle> m_pendulum, m_liner;
};

void PlotsTest::initTestCase()
{
    // the tests read English texts, whatever the system's locale
    QVERIFY(i18n::install("en"));
    m_pendulum = example(QStringLiteral("pendulum.pad"));
    m_liner = example(QStringLiteral("liner_manipulator.pad"));
    QVERIFY(m_pendulum);
    QVERIFY(m_liner);
}

void PlotsTest::listsSignalsOfEveryJoint()
{
    PlotPanel panel;
    QVERIFY(panel.signalKeys().isEmpty());
    panel.setBundle(m_liner);
    const QStringList keys = panel.signalKeys();
    QCOMPARE(keys.size(), 9 * 8 + 9 + 1);  // q, q̇, six reactions per joint; nine drives; energy
    QCOMPARE(keys.first(), QStringLiteral("q:1"));
    QVERIFY(keys.contains(QStringLiteral("f:2")));
    QVERIFY(keys.contains(QStringLiteral("Ft:9")));
    QCOMPARE(keys.last(), QStringLiteral("energy"));
    QCOMPARE(panel.signalLabel(QStringLiteral("q:2")), QStringLiteral("C 2 LEVANTE PLUMA q [m]"));
    QCOMPARE(panel.signalLabel(QStringLiteral("q:1")), QStringLiteral("C 1 GIRO PLUMA q [°]"));  // as the sliders
    QCOMPARE(panel.signalUnit(QStringLiteral("qd:1")), QStringLiteral("°/s"));
    QCOMPARE(panel.signalUnit(QStringLiteral("f:1")), QStringLiteral("N m"));  // the slew motor's torque
    QCOMPARE(panel.signalUnit(QStringLiteral("f:2")), QStringLiteral("N"));    // the boom cylinder's force
    QCOMPARE(panel.signalUnit(QStringLiteral("qd:3")), QStringLiteral("m/s"));
    QCOMPARE(panel.signalUnit(QStringLiteral("Ma:3")), QStringLiteral("N m"));
    panel.setBundle(m_pendulum);
    QCOMPARE(panel.signalKeys().size(), 8 + 1);  // no drive
    QVERIFY(!panel.signalKeys().contains(QStringLiteral("f:1")));

    // a free body: its translation along B1's joint axes and its rate, as padrob
    // simulate's q1x… columns; no reactions (a free joint transmits nothing)
    const auto block = example(QStringLiteral("tumbling_block.pad"));
    QVERIFY(block);
    panel.setBundle(block);
    QCOMPARE(panel.signalKeys(), (QStringList{QStringLiteral("qx:1"), QStringLiteral("qdx:1"), QStringLiteral("qy:1"),
                                              QStringLiteral("qdy:1"), QStringLiteral("qz:1"), QStringLiteral("qdz:1"),
                                              QStringLiteral("energy")}));
    QCOMPARE(panel.signalLabel(QStringLiteral("qy:1")), QStringLiteral("C 1 free q_y [m]"));
    QCOMPARE(panel.signalUnit(QStringLiteral("qdz:1")), QStringLiteral("m/s"));
}

void PlotsTest::plotsSelectedSignals()
{
    PlotPanel panel;
    panel.setBundle(m_pendulum);
    panel.setMinSampleInterval(0);
    for (int k = 0; k < 200; ++k) panel.addSnapshot(pendulumAt(m_pendulum, 0.01 * k));
    QCOMPARE(panel.sampleCount(), 200);
    QCOMPARE(panel.chartCount(), 0);
    QSignalSpy selection(&panel, &PlotPanel::selectionChanged);
    panel.setSignalSelected(QStringLiteral("q:1"), true);
    panel.setSignalSelected(QStringLiteral("Fr:1"), true);
    panel.setSignalSelected(QStringLiteral("nope"), true);  // unknown: ignored
    QCOMPARE(selection.count(), 2);
    QCOMPARE(panel.selectedSignals(), (QStringList{QStringLiteral("q:1"), QStringLiteral("Fr:1")}));
    QCOMPARE(panel.chartCount(), 2);  // ° and N
    panel.refresh();
    QLineSeries* q = panel.series(QStringLiteral("q:1"));
    QLineSeries* fr = panel.series(QStringLiteral("Fr:1"));
    QVERIFY(q && fr);
    QCOMPARE(q->count(), 200);
    QCOMPARE(fr->count(), 200);
    for (int k : {0, 1, 57, 199}) {
        const double t = 0.01 * k;
        QCOMPARE(q->at(k).x(), t);
        QCOMPARE(q->at(k).y(), std::sin(t) * kDeg);
        QCOMPARE(fr->at(k).y(), 20 * t);  // F_R is the fifth reaction component
    }
    QCOMPARE(q->name(), QStringLiteral("C 1 pivot q [°]"));
    // another force joins the N chart; a moment gets its own
    panel.setSignalSelected(QStringLiteral("Fa:1"), true);
    QCOMPARE(panel.chartCount(), 2);
    panel.setSignalSelected(QStringLiteral("Mt:1"), true);
    QCOMPARE(panel.chartCount(), 3);
    panel.refresh();
    QCOMPARE(panel.series(QStringLiteral("Mt:1"))->at(10).y(), 3 * 0.1);
    panel.setSignalSelected(QStringLiteral("Mt:1"), false);
    panel.setSignalSelected(QStringLiteral("q:1"), false);
    QCOMPARE(panel.chartCount(), 1);
    QVERIFY(!panel.series(QStringLiteral("q:1")));
    // the history of a signal ticked later is there at once
    panel.setSignalSelected(QStringLiteral("qd:1"), true);
    panel.refresh();
    QCOMPARE(panel.series(QStringLiteral("qd:1"))->count(), 200);
    QCOMPARE(panel.series(QStringLiteral("qd:1"))->at(100).y(), std::cos(1.0) * kDeg);
}

void PlotsTest::windowAndDownsampling()
{
    PlotPanel panel;
    panel.setBundle(m_pendulum);
    panel.setWindow(2);
    panel.setMinSampleInterval(0);
    panel.setMaxPoints(200);
    panel.setSignalSelected(QStringLiteral("q:1"), true);
    // 5 s at 1 ms, q = sin(2π·3t)
    double top = -2 * kDeg, bottom = 2 * kDeg;
    for (int k = 0; k <= 5000; ++k) {
        const double t = 0.001 * k;
        Snapshot s = pendulumAt(m_pendulum, t);
        s.q[0] = std::sin(2 * std::numbers::pi * 3 * t);
        if (t >= 3.0) {
            top = std::max(top, s.q[0] * kDeg);
            bottom = std::min(bottom, s.q[0] * kDeg);
        }
        panel.addSnapshot(s);
    }
    QVERIFY2(panel.sampleCount() >= 2000 && panel.sampleCount() <= 2001, qPrintable(QString::number(panel.sampleCount())));
    panel.refresh();
    QLineSeries* q = panel.series(QStringLiteral("q:1"));
    QVERIFY(q->count() <= 200);
    QVERIFY(q->count() >= 150);
    double seriesTop = -2 * kDeg, seriesBottom = 2 * kDeg;
    for (int i = 0; i < q->count(); ++i) {
        seriesTop = std::max(seriesTop, q->at(i).y());
        seriesBottom = std::min(seriesBottom, q->at(i).y());
        if (i > 0) QVERIFY(q->at(i).x() > q->at(i - 1).x());  // in time order
    }
    QCOMPARE(seriesTop, top);  // the peaks survive
    QCOMPARE(seriesBottom, bottom);
    QVERIFY(q->at(0).x() >= 3.0 - 1e-12);

    // at most one sample per minSampleInterval (4 ms by default)
    PlotPanel thin;
    QCOMPARE(thin.minSampleInterval(), 0.004);
    for (int k = 0; k <= 1000; ++k) thin.addSnapshot(pendulumAt(m_pendulum, 0.001 * k));
    QVERIFY2(thin.sampleCount() >= 200 && thin.sampleCount() <= 251, qPrintable(QString::number(thin.sampleCount())));
    QCOMPARE(thin.window(), 20.0);
}

void PlotsTest::resetAndNewModelClear()
{
    PlotPanel panel;
    panel.setMinSampleInterval(0);
    panel.setSignalSelected(QStringLiteral("q:1"), true);  // (no model yet: ignored)
    for (int k = 0; k < 50; ++k) panel.addSnapshot(pendulumAt(m_pendulum, 0.01 * k));
    QCOMPARE(panel.signalKeys().size(), 9);  // the snapshot brought its model
    panel.setSignalSelected(QStringLiteral("q:1"), true);
    QCOMPARE(panel.sampleCount(), 50);
    panel.addSnapshot(pendulumAt(m_pendulum, 0.49));  // the same time again: ignored
    QCOMPARE(panel.sampleCount(), 50);
    panel.addSnapshot(pendulumAt(m_pendulum, 0.0));  // back in time: a reset
    QCOMPARE(panel.sampleCount(), 1);
    panel.clear();
    QCOMPARE(panel.sampleCount(), 0);
    panel.refresh();
    QCOMPARE(panel.series(QStringLiteral("q:1"))->count(), 0);
    // a new model: new list, empty history; ticks of keys it also has stay
    panel.addSnapshot(pendulumAt(m_pendulum, 0.1));
    panel.setBundle(m_liner);
    QCOMPARE(panel.sampleCount(), 0);
    QCOMPARE(panel.selectedSignals(), QStringList{QStringLiteral("q:1")});
    QCOMPARE(panel.signalKeys().size(), 82);
}

void PlotsTest::exportCsvReadsBack()
{
    PlotPanel panel;
    panel.setBundle(m_pendulum);
    panel.setMinSampleInterval(0);
    for (int k = 0; k < 120; ++k) panel.addSnapshot(pendulumAt(m_pendulum, 0.01 * k + 0.1 / 3));
    panel.setSignalSelected(QStringLiteral("q:1"), true);
    panel.setSignalSelected(QStringLiteral("Fr:1"), true);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("plots.csv"));
    QVERIFY2(panel.exportCsv(path), qPrintable(panel.errorString()));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().split('\n');
    QCOMPARE(lines.size(), 1 + 120 + 1);  // header, rows, "" after the last newline
    QCOMPARE(QString::fromUtf8(lines[0]), QStringLiteral("t [s],C 1 pivot q [°],C 1 pivot F_R [N]"));
    QVERIFY(lines.last().isEmpty());
    for (int k = 0; k < 120; ++k) {
        const QList<QByteArray> cells = lines[k + 1].split(',');
        QCOMPARE(cells.size(), 3);
        const double t = 0.01 * k + 0.1 / 3;
        bool ok = false;
        QCOMPARE(cells[0].toDouble(&ok), t);  // exact: shortest round-trip decimals
        QVERIFY(ok);
        QCOMPARE(cells[1].toDouble(), std::sin(t) * kDeg);
        QCOMPARE(cells[2].toDouble(), 20 * t);
    }
    QVERIFY(!panel.exportCsv(dir.filePath(QStringLiteral("no/such/folder/x.csv"))));
    QVERIFY(!panel.errorString().isEmpty());
}

void PlotsTest::exportPngIsNotBlank()
{
    PlotPanel panel;
    panel.resize(900, 600);
    panel.setBundle(m_pendulum);
    panel.setMinSampleInterval(0);
    for (int k = 0; k < 600; ++k) panel.addSnapshot(pendulumAt(m_pendulum, 0.01 * k));
    panel.setSignalSelected(QStringLiteral("q:1"), true);
    panel.setSignalSelected(QStringLiteral("qd:1"), true);
    panel.setSignalSelected(QStringLiteral("Fa:1"), true);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const QString path = screenshotDir() + QStringLiteral("/plots_synthetic.png");
    QVERIFY2(panel.exportPng(path), qPrintable(panel.errorString()));
    QImage image(path);
    QVERIFY(!image.isNull());
    QVERIFY(image.width() > 300 && image.height() > 300);
    double inked = 0;
    int colours = 0;
    imageStats(image, inked, colours);
    qInfo("%s: %dx%d, %.1f%% inked, %d colours", qPrintable(path), image.width(), image.height(), 100 * inked, colours);
    QVERIFY(inked > 0.02);
    QVERIFY(colours > 10);
}

void PlotsTest::followsRunner()
{
    studio::SimulationRunner runner;
    PlotPanel panel;
    panel.resize(1000, 700);
    panel.setRunner(&runner);
    runner.setBundle(m_liner);
    QCOMPARE(panel.signalKeys().size(), 82);
    panel.setSignalSelected(QStringLiteral("q:2"), true);
    panel.setSignalSelected(QStringLiteral("f:2"), true);
    panel.setSignalSelected(QStringLiteral("Fr:2"), true);
    panel.setSignalSelected(QStringLiteral("q:3"), true);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const solver::Model& m = *m_liner->model;
    runner.setCommand(m.jointIndex(2), 1.0);   // boom up
    runner.setCommand(m.jointIndex(3), 1.0);   // telescope out
    runner.setSpeed(2);
    runner.start();
    QTest::qWait(1500);
    runner.setCommand(m.jointIndex(3), -1.0);  // and back in
    QTest::qWait(1000);
    runner.pause();
    // the last snapshot reaches the panel through the event loop: on a loaded machine
    // that can take longer than a fixed wait, so wait until the plot holds it
    const auto lastLift = [&] {
        panel.refresh();
        const QLineSeries* s = panel.series(QStringLiteral("q:2"));
        return s && s->count() > 0 ? s->at(s->count() - 1).y() : -1.0;
    };
    QTRY_VERIFY_WITH_TIMEOUT(qFuzzyCompare(lastLift(), runner.latest()->q[m.jointIndex(2)]), 15000);
    const int samples = panel.sampleCount();
    qInfo("%d samples over %.2f s simulated", samples, runner.latest()->t);
    QVERIFY(samples > 30);
    panel.refresh();
    QLineSeries* lift = panel.series(QStringLiteral("q:2"));
    QVERIFY(lift->count() > 30);
    for (int i = 1; i < lift->count(); ++i) QVERIFY(lift->at(i).y() > lift->at(i - 1).y());  // rising
    QCOMPARE(lift->at(lift->count() - 1).y(), runner.latest()->q[m.jointIndex(2)]);
    QCOMPARE(panel.chartCount(), 2);  // m and N
    const QString path = screenshotDir() + QStringLiteral("/plots_liner.png");
    QVERIFY(panel.exportPng(path));
    qInfo("%s", qPrintable(path));
    runner.reset();
    QVERIFY(panel.sampleCount() <= 1);
    QTest::qWait(50);
    QCOMPARE(panel.sampleCount(), 1);  // the initial state, polled again
}

// Paused, the plot's last sample is the simulation's state, even when it came less than
// the sampling interval after the sample before (CI, loaded: the snapshot published at
// the pause fell within 4 ms of the last one, was left out, and the plot ended short of
// the state). An interval longer than the run leaves out every snapshot but the first
// while it runs; paused, the newest is plotted.
void PlotsTest::pausedThePlotEndsWhereTheSimulationStands()
{
    studio::SimulationRunner runner;
    PlotPanel panel;
    panel.setRunner(&runner);
    runner.setBundle(m_pendulum);
    panel.setMinSampleInterval(1000);
    panel.setSignalSelected(QStringLiteral("q:1"), true);
    runner.start();
    QTRY_VERIFY_WITH_TIMEOUT(runner.latest() && runner.latest()->t > 0.3, 15000);
    runner.pause();
    QTRY_VERIFY_WITH_TIMEOUT(!runner.isRunning(), 15000);
    const double t = runner.latest()->t;
    QTRY_COMPARE_WITH_TIMEOUT(panel.sampleCount(), 2, 15000);  // the first, and the state paused
    panel.refresh();
    const QLineSeries* q = panel.series(QStringLiteral("q:1"));
    QVERIFY(q);
    QCOMPARE(q->at(q->count() - 1).x(), t);
    QCOMPARE(q->at(q->count() - 1).y(), runner.latest()->q[0] * kDeg);
    QTest::qWait(100);
    QCOMPARE(panel.sampleCount(), 2);  // once
}

// The panel changes language while it plots: the list, the legends and the axes'
// numbers (1,5) in Spanish, the history and the ticks kept; the CSV keeps '.'.
void PlotsTest::spanishAtRunTimeKeepsTheCsvDecimalPoint()
{
    PlotPanel panel;
    panel.resize(900, 600);
    panel.setBundle(m_pendulum);
    panel.setMinSampleInterval(0);
    for (int k = 0; k < 300; ++k) panel.addSnapshot(pendulumAt(m_pendulum, 0.01 * k + 0.1 / 3));
    panel.setSignalSelected(QStringLiteral("q:1"), true);
    panel.setSignalSelected(QStringLiteral("energy"), true);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.refresh();
    QVERIFY(panel.grab().save(screenshotDir() + QStringLiteral("/plots_en.png")));

    QVERIFY(i18n::install("es"));
    QTRY_COMPARE(panel.series(QStringLiteral("energy"))->name(), QStringLiteral("energía mecánica [J]"));
    QCOMPARE(panel.signalLabel(QStringLiteral("energy")), QStringLiteral("energía mecánica [J]"));
    QCOMPARE(panel.selectedSignals(), (QStringList{QStringLiteral("q:1"), QStringLiteral("energy")}));
    QCOMPARE(panel.sampleCount(), 300);
    QCOMPARE(panel.chartCount(), 2);
    for (QChartView* view : panel.findChildren<QChartView*>()) {
        QVERIFY(view->chart()->localizeNumbers());
        QCOMPARE(view->chart()->locale().decimalPoint(), QStringLiteral(","));
    }
    panel.refresh();
    studio::test::settle(200);
    QVERIFY(panel.grab().save(screenshotDir() + QStringLiteral("/plots_es.png")));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("plots.csv"));
    QVERIFY2(panel.exportCsv(path), qPrintable(panel.errorString()));
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().split('\n');
    QCOMPARE(QString::fromUtf8(lines[0]), QStringLiteral("t [s],C 1 pivot q [°],energía mecánica [J]"));
    const QList<QByteArray> cells = lines[1].split(',');
    QCOMPARE(cells.size(), 3);
    QCOMPARE(cells[0].toDouble(), 0.1 / 3);  // '.' and round-trip decimals, in every language
    QCOMPARE(cells[1].toDouble(), std::sin(0.1 / 3) * kDeg);

    QVERIFY(i18n::install("en"));
    QTRY_COMPARE(panel.series(QStringLiteral("energy"))->name(), QStringLiteral("mechanical energy [J]"));
    QCOMPARE(panel.findChildren<QChartView*>().front()->chart()->locale().decimalPoint(), QStringLiteral("."));
}

// Issue 25 item 15: signals of different units overlaid in one chart chosen per signal
// (the chart box beside a ticked signal), one vertical axis per unit, each spanning its
// own signals; back to its unit's chart; in English and Spanish.
void PlotsTest::overlaysSignalsOfAnyUnitsInAChosenChart()
{
    PlotPanel panel;
    panel.resize(1100, 700);
    panel.setBundle(m_pendulum);
    panel.setMinSampleInterval(0);
    for (int k = 0; k < 300; ++k) panel.addSnapshot(pendulumAt(m_pendulum, 0.01 * k));
    for (const char* key : {"q:1", "Fr:1", "Mt:1"}) panel.setSignalSelected(QString::fromLatin1(key), true);
    QCOMPARE(panel.chartCount(), 3);  // by unit: °, N, N m
    QCOMPARE(panel.signalChart(QStringLiteral("q:1")), 0);
    // q (°) and F_R (N) in chart 1, overlaid
    panel.setSignalChart(QStringLiteral("q:1"), 1);
    panel.setSignalChart(QStringLiteral("Fr:1"), 1);
    QCOMPARE(panel.chartCount(), 2);
    const int shared = panel.chartIndexOf(QStringLiteral("q:1"));
    QCOMPARE(panel.chartIndexOf(QStringLiteral("Fr:1")), shared);
    QVERIFY(panel.chartIndexOf(QStringLiteral("Mt:1")) != shared);
    QCOMPARE(panel.chartUnits(shared), (QStringList{QStringLiteral("°"), QStringLiteral("N")}));
    // M_T joins them through its chart box, as a user picks it
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto* box = panel.findChild<QComboBox*>(QStringLiteral("ChartBox:Mt:1"));
    QVERIFY(box && box->isVisible());
    QCOMPARE(box->count(), 1 + PlotPanel::kMaxCharts);
    QCOMPARE(box->itemText(0), QStringLiteral("by unit"));
    box->setCurrentIndex(1);
    emit box->activated(1);
    QCOMPARE(panel.signalChart(QStringLiteral("Mt:1")), 1);
    QCOMPARE(panel.chartCount(), 1);
    QCOMPARE(panel.chartUnits(0), (QStringList{QStringLiteral("°"), QStringLiteral("N"), QStringLiteral("N m")}));
    QVERIFY(!panel.findChild<QComboBox*>(QStringLiteral("ChartBox:qd:1")));  // unticked: no box
    // one vertical axis per unit, the first on the left, the others on the right, each
    // spanning its own signal (q ≤ 57.3°, F_R up to 59.8 N, M_T up to 8.97 N m)
    panel.refresh();
    QChart* chart = panel.findChildren<QChartView*>().front()->chart();
    QCOMPARE(chart->series().size(), 3);
    const auto yOf = [&](const char* key) {
        return qobject_cast<QValueAxis*>(chart->axes(Qt::Vertical, panel.series(QString::fromLatin1(key))).front());
    };
    QCOMPARE(yOf("q:1")->alignment(), Qt::AlignLeft);
    QCOMPARE(yOf("Fr:1")->alignment(), Qt::AlignRight);
    QVERIFY(yOf("Fr:1") != yOf("Mt:1"));
    QVERIFY(yOf("q:1")->max() >= std::sin(2.99) * kDeg && yOf("q:1")->max() < 100);
    QVERIFY(yOf("Fr:1")->max() >= 59.8 && yOf("Fr:1")->max() < 100);
    QVERIFY(yOf("Mt:1")->max() >= 8.97 && yOf("Mt:1")->max() < 20);
    QCOMPARE(panel.series(QStringLiteral("Fr:1"))->at(100).y(), 20 * 1.0);
    studio::test::settle(200);
    QVERIFY(panel.grab().save(screenshotDir() + QStringLiteral("/plots_overlay_en.png")));
    QVERIFY(i18n::install("es"));
    QTRY_VERIFY(panel.findChild<QComboBox*>(QStringLiteral("ChartBox:Mt:1")) &&
                panel.findChild<QComboBox*>(QStringLiteral("ChartBox:Mt:1"))->currentText() == "gráfico 1");
    QCOMPARE(panel.chartCount(), 1);
    panel.refresh();
    studio::test::settle(200);
    QVERIFY(panel.grab().save(screenshotDir() + QStringLiteral("/plots_overlay_es.png")));
    QVERIFY(i18n::install("en"));
    // back to its unit's chart
    panel.setSignalChart(QStringLiteral("Mt:1"), 0);
    QCOMPARE(panel.chartCount(), 2);
    QCOMPARE(panel.chartUnits(panel.chartIndexOf(QStringLiteral("Mt:1"))), QStringList{QStringLiteral("N m")});
}

QTEST_MAIN(PlotsTest)
#include "plots_test.moc"
