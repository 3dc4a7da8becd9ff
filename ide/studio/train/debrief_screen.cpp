#include "ide/studio/train/debrief_screen.h"

#include "ide/studio/train/train_ui.h"
#include "ide/studio/train/training_controller.h"
#include "ide/studio/train/tutorial_runner.h"
#include "ide/studio/view/viewport.h"

#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLineSeries>
#include <QPen>
#include <QListWidget>
#include <QPushButton>
#include <QSlider>
#include <QSplitter>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace studio {

using trainui::num;

namespace {

/// Labels with as many decimals as the ticks need ("%.1f": QtCharts' localized labels
/// take only 'f' formats, not "%g").
void decimalsForTicks(QValueAxis* axis)
{
    const double step = axis->tickCount() > 1 ? (axis->max() - axis->min()) / (axis->tickCount() - 1) : 1.0;
    int decimals = 0;
    while (decimals < 3 &&
           std::abs(step * std::pow(10.0, decimals) - std::round(step * std::pow(10.0, decimals))) > 1e-6)
        ++decimals;
    axis->setLabelFormat(QStringLiteral("%.%1f").arg(decimals));
}

/// A chart of one series against the time, its numbers in the locale's format.
QChart* makeChart(const QString& title, QLineSeries* series, const QString& yTitle, double yMin, double yMax,
                  double tMax)
{
    auto* chart = new QChart;
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setLocalizeNumbers(true);
    chart->setLocale(QLocale());
    chart->setTitle(title);
    chart->legend()->hide();
    chart->addSeries(series);
    auto* x = new QValueAxis;
    x->setTitleText(DebriefScreen::tr("t [s]"));
    x->setRange(0, std::max(1.0, tMax));
    auto* y = new QValueAxis;
    y->setTitleText(yTitle);
    y->setRange(yMin, yMax);
    x->applyNiceNumbers();
    y->applyNiceNumbers();
    decimalsForTicks(x);
    decimalsForTicks(y);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    series->attachAxis(x);
    series->attachAxis(y);
    // the replay cursor: a vertical line at the replay's time (moveCursor)
    auto* cursor = new QLineSeries;
    cursor->setObjectName("ReplayCursor");
    cursor->setPen(QPen(QColor(0xe5, 0x39, 0x35), 2));
    cursor->append(0, y->min());
    cursor->append(0, y->max());
    chart->addSeries(cursor);
    cursor->attachAxis(x);
    cursor->attachAxis(y);
    chart->setMargins(QMargins(4, 4, 4, 4));
    return chart;
}

/// Puts a chart's replay cursor at time `t` [s], across the whole height.
void moveCursor(QChartView* view, double t)
{
    if (!view->chart()) return;
    for (QAbstractSeries* s : view->chart()->series()) {
        auto* cursor = qobject_cast<QLineSeries*>(s);
        if (!cursor || cursor->objectName() != QLatin1String("ReplayCursor") || cursor->count() != 2) continue;
        cursor->replace(QList<QPointF>{{t, cursor->at(0).y()}, {t, cursor->at(1).y()}});
    }
}

}  // namespace

DebriefScreen::DebriefScreen(TrainingController* training, QWidget* parent) : QWidget(parent), m_training(training)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(12, 12, 12, 12);
    auto* split = new QSplitter(Qt::Horizontal);
    // the replay and its controls
    auto* replayBox = new QWidget;
    auto* replay = new QVBoxLayout(replayBox);
    replay->setContentsMargins(0, 0, 0, 0);
    m_view = new Viewport;
    m_view->setMinimumSize(320, 180);  // (room for the controls and charts at 1280×720)
    replay->addWidget(m_view, 1);
    auto* controls = new QHBoxLayout;
    m_play = new QPushButton;
    m_play->setObjectName("ReplayPlay");
    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setObjectName("ReplaySlider");
    m_time = new QLabel;
    m_time->setMinimumWidth(90);
    controls->addWidget(m_play);
    controls->addWidget(m_slider, 1);
    controls->addWidget(m_time);
    replay->addLayout(controls);
    m_forceChart = new QChartView;
    m_forceChart->setObjectName("ForceChart");
    m_forceChart->setMinimumHeight(150);
    m_forceChart->setRenderHint(QPainter::Antialiasing);
    m_reliefChart = new QChartView;
    m_reliefChart->setObjectName("ReliefChart");
    m_reliefChart->setMinimumHeight(120);
    replay->addWidget(m_forceChart);
    replay->addWidget(m_reliefChart);
    split->addWidget(replayBox);
    // the events and the expert
    auto* side = new QWidget;
    auto* sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    auto* eventsTitle = new QLabel;
    sideLayout->addWidget(eventsTitle);
    m_timeline = new QListWidget;
    m_timeline->setObjectName("Timeline");
    m_timeline->setWordWrap(true);
    sideLayout->addWidget(m_timeline, 1);
    auto* expertTitle = new QLabel;
    sideLayout->addWidget(expertTitle);
    m_comparison = new QTableWidget(5, 3);
    m_comparison->setObjectName("Comparison");
    m_comparison->verticalHeader()->hide();
    m_comparison->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_comparison->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_comparison->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    m_comparison->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_comparison->setSelectionMode(QAbstractItemView::NoSelection);
    m_comparison->setMinimumHeight(160);
    sideLayout->addWidget(m_comparison);
    auto* back = new QPushButton;
    sideLayout->addWidget(back);
    m_texts.add([=, this] {
        m_play->setText(m_playing ? tr("Pause") : tr("Play"));
        eventsTitle->setText("<b>" + tr("Events") + "</b>");
        expertTitle->setText("<b>" + tr("You and the expert") + "</b>");
        m_comparison->setHorizontalHeaderLabels({tr("Measure"), tr("You"), tr("Expert")});
        back->setText(tr("Back to the result"));
    });
    split->addWidget(side);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    layout->addWidget(split);

    connect(back, &QPushButton::clicked, this, [this] {
        m_playing = false;
        emit backRequested();
    });
    connect(m_slider, &QSlider::valueChanged, this, &DebriefScreen::showSample);
    connect(m_play, &QPushButton::clicked, this, [this] {
        const trainer::RunOutput* run = m_training->lastRun();
        if (!run || run->samples.empty()) return;
        m_playing = !m_playing;
        if (m_playing) {
            if (m_slider->value() >= m_slider->maximum()) m_slider->setValue(0);
            m_clock = run->samples[std::size_t(m_slider->value())].t;
        }
        m_play->setText(m_playing ? tr("Pause") : tr("Play"));
    });
    connect(m_timeline, &QListWidget::itemClicked, this, [this](QListWidgetItem* it) {
        const trainer::RunOutput* run = m_training->lastRun();
        if (!run) return;
        const double t = it->data(Qt::UserRole).toDouble();
        const auto& s = run->samples;
        const auto at = std::lower_bound(s.begin(), s.end(), t,
                                         [](const trainer::SessionSample& a, double v) { return a.t < v; });
        m_slider->setValue(int(std::min<std::ptrdiff_t>(at - s.begin(), std::ptrdiff_t(s.size()) - 1)));
    });
    connect(m_training, &TrainingController::expertReady, this, &DebriefScreen::fillComparison);
}

bool DebriefScreen::advance(double seconds)
{
    const trainer::RunOutput* run = m_training->lastRun();
    if (!m_playing || !run || run->samples.empty()) return false;
    m_clock += seconds;
    const auto& samples = run->samples;
    int i = m_slider->value();
    while (i + 1 < int(samples.size()) && samples[std::size_t(i + 1)].t <= m_clock) ++i;
    if (i + 1 >= int(samples.size())) {
        m_playing = false;
        m_play->setText(tr("Play"));
    }
    m_slider->setValue(i);
    return true;
}

void DebriefScreen::showSample(int index)
{
    const trainer::RunOutput* run = m_training->lastRun();
    if (!run || index < 0 || index >= int(run->samples.size())) return;
    const trainer::SessionSample& s = run->samples[std::size_t(index)];
    m_view->setSnapshot(snapshotFromSample(s, m_training->bundle()));
    m_time->setText(tr("%1 s").arg(num(s.t, 2)));
    moveCursor(m_forceChart, s.t);
    moveCursor(m_reliefChart, s.t);
    if (!m_playing) m_clock = s.t;
}

void DebriefScreen::fill()
{
    const trainer::RunOutput* run = m_training->lastRun();
    if (!run) return;
    m_playing = false;
    m_play->setText(tr("Play"));
    m_slider->setRange(0, std::max(0, int(run->samples.size()) - 1));
    m_slider->setValue(0);
    QTimer::singleShot(0, m_view, [v = m_view] { trainui::frameModelAndTargets(v); });
    fillTimeline();
    fillCharts();
    fillComparison();
    showSample(0);  // (the charts' cursors at the start)
}

void DebriefScreen::retranslate()
{
    m_texts.apply();
    if (!m_training->lastRun()) return;
    fillTimeline();
    fillCharts();
    fillComparison();
    showSample(m_slider->value());
}

void DebriefScreen::fillTimeline()
{
    const trainer::RunOutput* run = m_training->lastRun();
    if (!run) return;
    const auto t = m_training->tutorial();
    const std::string lang = TrainingController::language().toStdString();
    const int row = m_timeline->currentRow();
    m_timeline->clear();
    for (const trainer::TutorialEvent& e : run->result.events) {
        auto* it = new QListWidgetItem(tr("%1 s — %2").arg(num(e.t, 1), e.text(t.get(), lang)));
        it->setData(Qt::UserRole, e.t);
        m_timeline->addItem(it);
    }
    if (run->result.events.empty()) m_timeline->addItem(tr("No events."));
    if (row >= 0 && row < m_timeline->count()) {
        const QSignalBlocker block(m_timeline);
        m_timeline->setCurrentRow(row);
    }
}

void DebriefScreen::fillCharts()
{
    // the most loaded drive's force, and the relief valves open, against time
    const trainer::RunOutput* run = m_training->lastRun();
    const auto bundle = m_training->bundle();
    if (!run || !bundle) return;
    const auto& samples = run->samples;
    const solver::Model& m = *bundle->model;
    int joint = -1;
    double most = 0.0;
    for (const trainer::SessionSample& s : samples)
        for (std::size_t j = 0; j < s.driveForce.size(); ++j)
            if (std::abs(s.driveForce[j]) > most) {
                most = std::abs(s.driveForce[j]);
                joint = int(j);
            }
    const double tMax = samples.empty() ? 1.0 : samples.back().t;
    auto* force = new QLineSeries;
    double lo = 0.0, hi = 0.0;
    const bool linear = joint >= 0 && m.jointType[std::size_t(joint)] != solver::JointType::Revolute;
    const double scale = 1e-3;  // kN or kN·m
    if (joint >= 0) {
        for (const trainer::SessionSample& s : samples) {
            const double v = s.driveForce[std::size_t(joint)] * scale;
            force->append(s.t, v);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    const double pad = std::max(0.1, 0.08 * (hi - lo));
    QString name;
    if (joint >= 0) {
        name = QStringLiteral("C %1").arg(m.jointId[std::size_t(joint)]);
        if (!m.jointName[std::size_t(joint)].empty())
            name += ' ' + QString::fromStdString(m.jointName[std::size_t(joint)]);
    }
    QChart* old = m_forceChart->chart();
    m_forceChart->setChart(makeChart(joint >= 0 ? tr("Force of %1").arg(name) : tr("No drive force"), force,
                                     linear ? tr("kN") : tr("kN·m"), lo - pad, hi + pad, tMax));
    delete old;
    auto* relief = new QLineSeries;
    int reliefMax = 1;
    for (const trainer::SessionSample& s : samples) {
        const int open = int(std::count(s.relief.begin(), s.relief.end(), std::uint8_t(1)));
        reliefMax = std::max(reliefMax, open);
        relief->append(s.t, open);
    }
    old = m_reliefChart->chart();
    m_reliefChart->setChart(makeChart(tr("Relief valves open"), relief, tr("valves"), 0, reliefMax + 0.2, tMax));
    delete old;
}

void DebriefScreen::fillComparison()
{
    const trainer::RunOutput* run = m_training->lastRun();
    if (!run) return;
    const trainer::TutorialResult& you = run->result;
    const trainer::TutorialResult* expert = m_training->expertRun() ? &m_training->expertRun()->result : nullptr;
    const struct {
        QString label;
        double a, b;
        int decimals;
    } rows[] = {
        {tr("Time [s]"), you.time, expert ? expert->time : 0.0, 1},
        {tr("Path length [m]"), you.pathLength, expert ? expert->pathLength : 0.0, 2},
        {tr("Overshoot [m]"), you.overshoot, expert ? expert->overshoot : 0.0, 3},
        {tr("RMS jerk [m/s³]"), you.rmsJerk, expert ? expert->rmsJerk : 0.0, 2},
        {tr("Score"), you.score, expert ? expert->score : 0.0, 0},
    };
    m_comparison->setRowCount(5);
    for (int i = 0; i < 5; ++i) {
        m_comparison->setItem(i, 0, new QTableWidgetItem(rows[i].label));
        m_comparison->setItem(i, 1, new QTableWidgetItem(num(rows[i].a, rows[i].decimals)));
        m_comparison->setItem(i, 2,
                              new QTableWidgetItem(expert ? num(rows[i].b, rows[i].decimals)
                                                          : (m_training->demoLog() ? tr("…") : tr("none"))));
    }
}

}  // namespace studio
