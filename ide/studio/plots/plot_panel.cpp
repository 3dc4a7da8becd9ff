#include "ide/studio/plots/plot_panel.h"

#include "ide/studio/sim/simulation_runner.h"

#include "solver/core/output_file.h"
#include "ide/i18n/diagnostic_text.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLineSeries>
#include <QLocale>
#include <QPixmap>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTimer>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>

namespace studio {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kKeyRole = Qt::UserRole + 1;
constexpr int kMinChartHeight = 190;  // [px] room for the legend, the plot and both axes' labels and titles

/// A CSV field, quoted when it must be (RFC 4180).
QByteArray csvField(const QString& text)
{
    QByteArray utf8 = text.toUtf8();
    if (!utf8.contains(',') && !utf8.contains('"') && !utf8.contains('\n') && !utf8.contains('\r')) return utf8;
    utf8.replace("\"", "\"\"");
    return '"' + utf8 + '"';
}

/// The shortest decimal that reads back to `v` ("" for NaN).
void appendNumber(QByteArray& out, double v)
{
    if (std::isnan(v)) return;
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, int(r.ptr - buf));
}

}  // namespace

PlotPanel::PlotPanel(QWidget* parent) : QWidget(parent)
{
    // (the texts: retranslate())
    auto* split = new QSplitter(Qt::Horizontal, this);

    auto* side = new QWidget(split);
    auto* sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    m_list = new QTreeWidget(side);
    m_list->setHeaderHidden(true);
    m_list->setColumnCount(2);  // the signal, and its chart box when ticked
    // a long signal name (in any language) scrolls instead of being cut
    m_list->header()->setStretchLastSection(false);
    m_list->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_list->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    sideLayout->addWidget(m_list, 1);
    auto* buttons = new QHBoxLayout;
    m_clearButton = new QPushButton(side);
    m_csvButton = new QPushButton(side);
    m_pngButton = new QPushButton(side);
    buttons->addWidget(m_clearButton);
    buttons->addWidget(m_csvButton);
    buttons->addWidget(m_pngButton);
    sideLayout->addLayout(buttons);

    // the charts scroll when the panel is too short for all of them (a chart squeezed
    // below kMinChartHeight elides its axes' labels)
    auto* scroll = new QScrollArea(split);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_chartArea = new QWidget(scroll);
    scroll->setWidget(m_chartArea);
    m_chartLayout = new QVBoxLayout(m_chartArea);
    m_chartLayout->setContentsMargins(0, 0, 0, 0);
    m_chartLayout->setSpacing(0);
    m_placeholder = new QLabel(m_chartArea);
    m_placeholder->setAlignment(Qt::AlignCenter);
    m_placeholder->setWordWrap(true);
    m_chartLayout->addWidget(m_placeholder, 1);

    split->addWidget(side);
    split->addWidget(scroll);
    split->setStretchFactor(0, 0);
    split->setStretchFactor(1, 1);
    split->setSizes({260, 740});
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(split);

    m_redrawTimer = new QTimer(this);
    m_redrawTimer->setInterval(100);
    connect(m_redrawTimer, &QTimer::timeout, this, [this] {
        if (m_dirty && isVisible()) refresh();
    });
    m_redrawTimer->start();
    m_pollTimer = new QTimer(this);
    m_pollTimer->setInterval(16);
    connect(m_pollTimer, &QTimer::timeout, this, &PlotPanel::poll);

    connect(m_list, &QTreeWidget::itemChanged, this, &PlotPanel::onItemChanged);
    connect(m_clearButton, &QPushButton::clicked, this, [this] {
        clear();
        refresh();
    });
    connect(m_csvButton, &QPushButton::clicked, this, &PlotPanel::exportCsvInteractive);
    connect(m_pngButton, &QPushButton::clicked, this, &PlotPanel::exportPngInteractive);
    retranslate();
}

void PlotPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        // the list, the legends, the axes' titles and numbers in the new language (the
        // history and the ticks stay)
        rebuildList();
        rebuildCharts();
    }
    QWidget::changeEvent(event);
}

void PlotPanel::retranslate()
{
    m_list->setToolTip(tr("Tick the signals to plot; each unit gets its own chart, or choose beside a ticked signal "
                          "a numbered chart to overlay signals of any units."));
    m_clearButton->setText(tr("Clear"));
    m_clearButton->setToolTip(tr("Forget the samples plotted so far"));
    m_csvButton->setText(tr("CSV…"));
    m_csvButton->setToolTip(tr("Export time and the ticked signals as CSV"));
    m_pngButton->setText(tr("PNG…"));
    m_pngButton->setToolTip(tr("Save the charts as a PNG image"));
    m_placeholder->setText(tr("Tick signals in the list to plot them against time."));
}

QString PlotPanel::labelOf(const Signal& s) const
{
    if (s.kind == Kind::Energy) return tr("mechanical energy [J]");
    if (s.kind == Kind::ContactForce) return tr("largest contact force [kN]");
    // the symbols are the same in every language, but the drive's force
    const QString symbol = s.kind == Kind::Force ? tr("F drive") : s.symbol;
    return tr("%1 %2 [%3]", "a signal: the joint, the quantity's symbol, its unit").arg(ownerOf(s), symbol, s.unit);
}

QString PlotPanel::ownerOf(const Signal& s) const
{
    if (s.isPump())
        return s.ownerName.isEmpty() ? tr("pump %1").arg(s.ownerId) : tr("pump %1 %2").arg(s.ownerId).arg(s.ownerName);
    return s.ownerName.isEmpty() ? tr("C %1").arg(s.ownerId) : tr("C %1 %2").arg(s.ownerId).arg(s.ownerName);
}

PlotPanel::~PlotPanel() = default;

void PlotPanel::setBundle(std::shared_ptr<const ModelBundle> bundle)
{
    m_bundle = std::move(bundle);
    m_samples.clear();
    m_signals.clear();
    if (m_bundle && m_bundle->model) {
        const solver::Model& m = *m_bundle->model;
        std::vector<int> joints(std::size_t(m.nb));
        for (int i = 0; i < m.nb; ++i) joints[std::size_t(i)] = i;
        std::sort(joints.begin(), joints.end(),
                  [&](int a, int b) { return m.jointId[std::size_t(a)] < m.jointId[std::size_t(b)]; });
        for (int i : joints) {
            const std::size_t k = std::size_t(i);
            const int id = m.jointId[k];
            const QString name = QString::fromStdString(m.jointName[k]);
            if (m.freeSlot[k] >= 0) {
                // a free joint: its translation along B1's joint axes, as padrob simulate's
                // q<j>x… columns (slots 0–2); it transmits no load
                if (m.freeSlot[k] > 2) continue;
                const int a = m.freeSlot[k];
                const QString axis = QString(QChar(u"xyz"[a]));
                Signal& q = addSignal(Kind::Q, QStringLiteral("q") + axis, QStringLiteral("q_") + axis, QStringLiteral("m"),
                                      id, name);
                q.tree = i;
                q.axis = a;
                Signal& qd = addSignal(Kind::Qd, QStringLiteral("qd") + axis, QStringLiteral("dq_") + axis + QStringLiteral("/dt"),
                                       QStringLiteral("m/s"), id, name);
                qd.tree = i;
                qd.axis = a;
                continue;
            }
            // angles in degrees, as the Joints sliders show them
            const bool turns = m.jointType[k] == solver::JointType::Revolute;
            const QString length = turns ? QStringLiteral("°") : QStringLiteral("m");
            const QString rate = turns ? QStringLiteral("°/s") : QStringLiteral("m/s");
            const QString force = turns ? QStringLiteral("N m") : QStringLiteral("N");
            auto add = [&](Kind kind, const QString& prefix, const QString& symbol, const QString& unit) {
                addSignal(kind, prefix, symbol, unit, id, name).tree = i;
            };
            add(Kind::Q, QStringLiteral("q"), QStringLiteral("q"), length);
            m_signals.back().scale = turns ? 180 / std::numbers::pi : 1.0;
            add(Kind::Qd, QStringLiteral("qd"), QStringLiteral("dq/dt"), rate);
            m_signals.back().scale = turns ? 180 / std::numbers::pi : 1.0;
            if (m.drive[k].type != solver::DriveType::None) add(Kind::Force, QStringLiteral("f"), QStringLiteral("F"), force);
            if (m.drive[k].type == solver::DriveType::FluidPower) {
                // the chambers' pressures, in MPa (the panel's numbers)
                add(Kind::PressureA, QStringLiteral("pA"), QStringLiteral("p_A"), QStringLiteral("MPa"));
                m_signals.back().index = m.drive[k].circuit;
                add(Kind::PressureB, QStringLiteral("pB"), QStringLiteral("p_B"), QStringLiteral("MPa"));
                m_signals.back().index = m.drive[k].circuit;
            }
            add(Kind::Ma, QStringLiteral("Ma"), QStringLiteral("M_A"), QStringLiteral("N m"));
            add(Kind::Mr, QStringLiteral("Mr"), QStringLiteral("M_R"), QStringLiteral("N m"));
            add(Kind::Mt, QStringLiteral("Mt"), QStringLiteral("M_T"), QStringLiteral("N m"));
            add(Kind::Fa, QStringLiteral("Fa"), QStringLiteral("F_A"), QStringLiteral("N"));
            add(Kind::Fr, QStringLiteral("Fr"), QStringLiteral("F_R"), QStringLiteral("N"));
            add(Kind::Ft, QStringLiteral("Ft"), QStringLiteral("F_T"), QStringLiteral("N"));
        }
        for (std::size_t p = 0; p < m.pumps.size(); ++p) {
            const int id = m.pumps[p].id;
            const QString name = QString::fromStdString(m.pumps[p].name);
            addSignal(Kind::Supply, QStringLiteral("pS"), QStringLiteral("p_S"), QStringLiteral("MPa"), id, name).index =
                int(p);
            addSignal(Kind::PumpFlow, QStringLiteral("Qp"), QStringLiteral("Q"), QStringLiteral("L/min"), id, name).index =
                int(p);
        }
        if (m.contact) {
            // CONTACT: the largest contact force, in kN
            Signal c;
            c.kind = Kind::ContactForce;
            c.key = QStringLiteral("contact");
            c.unit = QStringLiteral("kN");
            m_signals.push_back(c);
        }
        Signal e;
        e.kind = Kind::Energy;
        e.key = QStringLiteral("energy");
        e.unit = QStringLiteral("J");
        m_signals.push_back(e);
    }
    const QStringList before = m_selected;
    m_selected.clear();
    for (const QString& key : before) {
        if (indexOf(key) >= 0) m_selected << key;
    }
    rebuildList();
    rebuildCharts();
    if (before != m_selected) emit selectionChanged();
}

PlotPanel::Signal& PlotPanel::addSignal(Kind kind, const QString& prefix, const QString& symbol, const QString& unit,
                                        int ownerId, const QString& ownerName)
{
    Signal s;
    s.kind = kind;
    s.key = prefix + QLatin1Char(':') + QString::number(ownerId);
    s.unit = unit;
    s.symbol = symbol;
    s.ownerId = ownerId;
    s.ownerName = ownerName;
    m_signals.push_back(s);
    return m_signals.back();
}

void PlotPanel::setRunner(SimulationRunner* runner)
{
    if (m_runner) disconnect(m_runner, nullptr, this, nullptr);
    m_runner = runner;
    m_lastPolled.reset();
    m_leftOut.reset();
    if (!runner) {
        m_pollTimer->stop();
        return;
    }
    connect(runner, &SimulationRunner::bundleChanged, this, [this] {
        if (m_runner) setBundle(m_runner->bundle());
    });
    connect(runner, &SimulationRunner::restarted, this, [this] {
        clear();
        refresh();
    });
    setBundle(runner->bundle());
    m_pollTimer->start();
}

void PlotPanel::poll()
{
    if (!m_runner) return;
    std::shared_ptr<const Snapshot> s = m_runner->latest();
    if (!s) return;
    if (s == m_lastPolled) {
        // nothing newer since the last poll: the snapshot the interval left out is the
        // simulation's state now (paused, or between two publications)
        if (m_leftOut == s) addSample(*s, true);
        m_leftOut.reset();
        return;
    }
    m_lastPolled = s;
    m_leftOut = addSample(*s, false) ? nullptr : s;
}

void PlotPanel::addSnapshot(const Snapshot& snapshot)
{
    addSample(snapshot, false);
}

bool PlotPanel::addSample(const Snapshot& snapshot, bool always)
{
    if (!snapshot.bundle) return false;
    if (snapshot.bundle != m_bundle) setBundle(snapshot.bundle);
    if (!m_samples.empty()) {
        const double last = m_samples.back().t;
        if (snapshot.t < last) {
            clear();  // a reset
        } else if (snapshot.t == last || (!always && snapshot.t - last < m_minInterval)) {
            return false;
        }
    }
    auto at = [](const Eigen::VectorXd& v, int i) { return i >= 0 && i < v.size() ? v[i] : kNaN; };
    const auto& circuits = snapshot.circuits;
    const auto& pumps = snapshot.pumps;
    auto circuit = [&](int i) { return i >= 0 && std::size_t(i) < circuits.size() ? &circuits[std::size_t(i)] : nullptr; };
    auto pump = [&](int i) { return i >= 0 && std::size_t(i) < pumps.size() ? &pumps[std::size_t(i)] : nullptr; };
    Sample sample;
    sample.t = snapshot.t;
    sample.values.resize(m_signals.size());
    for (std::size_t k = 0; k < m_signals.size(); ++k) {
        const Signal& s = m_signals[k];
        double v = kNaN;
        switch (s.kind) {
        case Kind::Q: v = at(snapshot.q, s.tree) * s.scale; break;
        case Kind::Qd: v = at(snapshot.qd, s.tree) * s.scale; break;
        case Kind::Force: v = at(snapshot.driveForce, s.tree); break;
        case Kind::PressureA:
            if (const CircuitSnapshot* c = circuit(s.index)) v = c->pressureA * 1e-6;
            break;
        case Kind::PressureB:
            if (const CircuitSnapshot* c = circuit(s.index)) v = c->pressureB * 1e-6;
            break;
        case Kind::Supply:
            if (const PumpSnapshot* p = pump(s.index)) v = p->supplyPressure * 1e-6;
            break;
        case Kind::PumpFlow:
            if (const PumpSnapshot* p = pump(s.index)) v = p->flow * 60000.0;  // [L/min]
            break;
        case Kind::Ma:
        case Kind::Mr:
        case Kind::Mt:
        case Kind::Fa:
        case Kind::Fr:
        case Kind::Ft:
            if (s.tree >= 0 && std::size_t(s.tree) < snapshot.reactionJoint.size()) {
                v = snapshot.reactionJoint[std::size_t(s.tree)][int(s.kind) - int(Kind::Ma)];
            }
            break;
        case Kind::Energy: v = snapshot.energy; break;
        case Kind::ContactForce: v = snapshot.largestContactForce * 1e-3; break;
        }
        sample.values[k] = v;
    }
    m_samples.push_back(std::move(sample));
    const double from = snapshot.t - m_window;
    while (!m_samples.empty() && m_samples.front().t < from) m_samples.pop_front();
    m_dirty = true;
    return true;
}

void PlotPanel::clear()
{
    m_samples.clear();
    m_dirty = true;
}

QStringList PlotPanel::signalKeys() const
{
    QStringList keys;
    for (const Signal& s : m_signals) keys << s.key;
    return keys;
}

int PlotPanel::indexOf(const QString& key) const
{
    for (std::size_t k = 0; k < m_signals.size(); ++k) {
        if (m_signals[k].key == key) return int(k);
    }
    return -1;
}

QString PlotPanel::signalLabel(const QString& key) const
{
    const int k = indexOf(key);
    return k < 0 ? QString() : labelOf(m_signals[std::size_t(k)]);
}

QString PlotPanel::signalUnit(const QString& key) const
{
    const int k = indexOf(key);
    return k < 0 ? QString() : m_signals[std::size_t(k)].unit;
}

void PlotPanel::setSignalSelected(const QString& key, bool selected)
{
    if (indexOf(key) < 0 || m_selected.contains(key) == selected) return;
    if (selected) {
        m_selected << key;
    } else {
        m_selected.removeAll(key);
    }
    // tick the list to match
    m_updatingList = true;
    for (QTreeWidgetItemIterator it(m_list); *it; ++it) {
        if ((*it)->data(0, kKeyRole).toString() != key) continue;
        (*it)->setCheckState(0, selected ? Qt::Checked : Qt::Unchecked);
        // a ticked signal shows, with its chart box beside it
        if (!selected) {
            m_list->removeItemWidget(*it, 1);
            continue;
        }
        addChartBox(*it, key);
        if ((*it)->parent()) (*it)->parent()->setExpanded(true);
    }
    m_updatingList = false;
    rebuildCharts();
    emit selectionChanged();
}

void PlotPanel::onItemChanged(QTreeWidgetItem* item, int column)
{
    if (m_updatingList || column != 0) return;
    const QString key = item->data(0, kKeyRole).toString();
    if (!key.isEmpty()) setSignalSelected(key, item->checkState(0) == Qt::Checked);
}

void PlotPanel::addChartBox(QTreeWidgetItem* item, const QString& key)
{
    if (m_list->itemWidget(item, 1)) return;
    auto* box = new QComboBox;
    box->setObjectName(QStringLiteral("ChartBox:") + key);
    box->setToolTip(tr("The chart this signal is drawn in: its unit's, or a numbered one shared by signals of any "
                       "units"));
    box->addItem(tr("by unit"), 0);
    for (int n = 1; n <= kMaxCharts; ++n) box->addItem(tr("chart %1").arg(n), n);
    box->setCurrentIndex(signalChart(key));
    connect(box, &QComboBox::activated, this, [this, key](int i) { setSignalChart(key, i); });
    m_list->setItemWidget(item, 1, box);
}

void PlotPanel::setSignalChart(const QString& key, int chart)
{
    if (indexOf(key) < 0) return;
    chart = std::clamp(chart, 0, kMaxCharts);
    if (chart == signalChart(key)) return;
    if (chart == 0) m_chartOf.remove(key);
    else m_chartOf.insert(key, chart);
    if (auto* box = m_list->findChild<QComboBox*>(QStringLiteral("ChartBox:") + key)) box->setCurrentIndex(chart);
    if (m_selected.contains(key)) rebuildCharts();
}

int PlotPanel::chartIndexOf(const QString& key) const
{
    const int k = indexOf(key);
    for (std::size_t c = 0; c < m_charts.size(); ++c) {
        const auto& ids = m_charts[c].signalIndices;
        if (k >= 0 && std::find(ids.begin(), ids.end(), k) != ids.end()) return int(c);
    }
    return -1;
}

QStringList PlotPanel::chartUnits(int i) const
{
    QStringList units;
    if (i >= 0 && std::size_t(i) < m_charts.size())
        for (const QString& u : m_charts[std::size_t(i)].units) units << u;
    return units;
}

void PlotPanel::rebuildList()
{
    m_updatingList = true;
    m_list->clear();
    QTreeWidgetItem* group = nullptr;
    QString groupOwner;
    for (const Signal& s : m_signals) {
        QTreeWidgetItem* item = nullptr;
        if (s.kind == Kind::Energy) {
            item = new QTreeWidgetItem(m_list, {tr("Mechanical energy [J]")});
        } else if (s.kind == Kind::ContactForce) {
            item = new QTreeWidgetItem(m_list, {tr("Largest contact force [kN]")});
        } else {
            // a group per joint, and per pump
            const QString owner = ownerOf(s);
            if (!group || owner != groupOwner) {
                group = new QTreeWidgetItem(m_list, {owner});
                group->setFlags(Qt::ItemIsEnabled);
                groupOwner = owner;
            }
            QString text;
            switch (s.kind) {
            case Kind::Q:
                text = s.axis < 0 ? tr("coordinate q [%1]")
                                  : tr("translation along %1 q_%2 [%3]")
                                        .arg(QStringLiteral("ART").at(s.axis), QStringLiteral("xyz").at(s.axis), QStringLiteral("%1"));
                break;
            case Kind::Qd:
                text = s.axis < 0 ? tr("rate dq/dt [%1]")
                                  : tr("velocity along %1 dq_%2/dt [%3]")
                                        .arg(QStringLiteral("ART").at(s.axis), QStringLiteral("xyz").at(s.axis), QStringLiteral("%1"));
                break;
            case Kind::Force: text = tr("drive force [%1]"); break;
            case Kind::PressureA: text = tr("chamber A pressure p_A [%1]"); break;
            case Kind::PressureB: text = tr("chamber B pressure p_B [%1]"); break;
            case Kind::Supply: text = tr("supply pressure p_S [%1]"); break;
            case Kind::PumpFlow: text = tr("delivered flow Q [%1]"); break;
            case Kind::Ma: text = tr("reaction moment about A [%1]"); break;
            case Kind::Mr: text = tr("reaction moment about R [%1]"); break;
            case Kind::Mt: text = tr("reaction moment about T [%1]"); break;
            case Kind::Fa: text = tr("reaction force along A [%1]"); break;
            case Kind::Fr: text = tr("reaction force along R [%1]"); break;
            case Kind::Ft: text = tr("reaction force along T [%1]"); break;
            case Kind::Energy:
            case Kind::ContactForce: break;
            }
            item = new QTreeWidgetItem(group, {text.arg(s.unit)});
        }
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        item->setData(0, kKeyRole, s.key);
        item->setToolTip(0, labelOf(s));
        item->setCheckState(0, m_selected.contains(s.key) ? Qt::Checked : Qt::Unchecked);
        if (m_selected.contains(s.key)) addChartBox(item, s.key);
        if (group && m_selected.contains(s.key)) group->setExpanded(true);
    }
    m_updatingList = false;
}

PlotPanel::Chart PlotPanel::makeChart(const QString& group)
{
    Chart c;
    c.group = group;
    auto* qchart = new QChart;
    qchart->setAnimationOptions(QChart::NoAnimation);
    qchart->legend()->setAlignment(Qt::AlignTop);
    qchart->setMargins(QMargins(4, 4, 4, 4));
    // the axes' numbers in the current locale (1,5 in Spanish), without group
    // separators ("132.000 N" would read as 132 N next to model text)
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    qchart->setLocalizeNumbers(true);
    qchart->setLocale(locale);
    c.x = new QValueAxis;
    c.x->setTitleText(tr("t [s]"));
    c.x->setLabelFormat(QStringLiteral("%.1f"));
    qchart->addAxis(c.x, Qt::AlignBottom);
    c.view = new QChartView(qchart, m_chartArea);
    c.view->setMinimumHeight(kMinChartHeight);
    m_chartLayout->addWidget(c.view, 1);
    return c;
}

void PlotPanel::rebuildCharts()
{
    for (Chart& c : m_charts) delete c.view;  // (owns its chart, axes and series)
    m_charts.clear();
    for (const QString& key : m_selected) {
        const int k = indexOf(key);
        const Signal& s = m_signals[std::size_t(k)];
        // its unit's chart, or the numbered chart chosen for it
        const int numbered = signalChart(key);
        const QString group = numbered > 0 ? QStringLiteral("#%1").arg(numbered) : s.unit;
        auto chart = std::find_if(m_charts.begin(), m_charts.end(), [&](const Chart& c) { return c.group == group; });
        if (chart == m_charts.end()) {
            m_charts.push_back(makeChart(group));
            chart = m_charts.end() - 1;
        }
        // a vertical axis per unit: the first on the left, the others on the right
        auto unit = std::find(chart->units.begin(), chart->units.end(), s.unit);
        if (unit == chart->units.end()) {
            auto* y = new QValueAxis;
            y->setTitleText(s.unit);
            y->setLabelFormat(QStringLiteral("%.6g"));
            chart->view->chart()->addAxis(y, chart->ys.empty() ? Qt::AlignLeft : Qt::AlignRight);
            chart->units.push_back(s.unit);
            chart->ys.push_back(y);
            unit = chart->units.end() - 1;
        }
        const int axis = int(unit - chart->units.begin());
        auto* series = new QLineSeries;
        series->setName(labelOf(s));
        chart->view->chart()->addSeries(series);
        series->attachAxis(chart->x);
        series->attachAxis(chart->ys[std::size_t(axis)]);
        chart->signalIndices.push_back(k);
        chart->series.push_back(series);
        chart->seriesAxis.push_back(axis);
    }
    m_placeholder->setVisible(m_charts.empty());
    refresh();
}

QLineSeries* PlotPanel::series(const QString& key) const
{
    const int k = indexOf(key);
    for (const Chart& c : m_charts) {
        for (std::size_t i = 0; i < c.signalIndices.size(); ++i) {
            if (c.signalIndices[i] == k) return c.series[i];
        }
    }
    return nullptr;
}

void PlotPanel::refresh()
{
    m_dirty = false;
    const std::size_t n = m_samples.size();
    double x0 = 0, x1 = m_window;
    if (n > 0) {
        const double first = m_samples.front().t, last = m_samples.back().t;
        x0 = last - first < m_window ? first : last - m_window;
        x1 = x0 + m_window;
    }
    QList<QPointF> points;
    points.reserve(qsizetype(std::min<std::size_t>(n, std::size_t(m_maxPoints)) + 2));
    for (Chart& c : m_charts) {
        // each vertical axis spans its own signals
        std::vector<double> los(c.ys.size(), std::numeric_limits<double>::infinity());
        std::vector<double> his(c.ys.size(), -std::numeric_limits<double>::infinity());
        for (std::size_t i = 0; i < c.series.size(); ++i) {
            const std::size_t k = std::size_t(c.signalIndices[i]);
            double& lo = los[std::size_t(c.seriesAxis[i])];
            double& hi = his[std::size_t(c.seriesAxis[i])];
            points.clear();
            auto add = [&](std::size_t row) {
                const double v = m_samples[row].values[k];
                points.append(QPointF(m_samples[row].t, v));
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            };
            if (n <= std::size_t(m_maxPoints)) {
                for (std::size_t row = 0; row < n; ++row) {
                    if (std::isfinite(m_samples[row].values[k])) add(row);
                }
            } else {
                // each bucket's minimum and maximum, in time order
                const std::size_t buckets = std::size_t(m_maxPoints) / 2;
                for (std::size_t b = 0; b < buckets; ++b) {
                    const std::size_t from = b * n / buckets, to = (b + 1) * n / buckets;
                    std::size_t rmin = to, rmax = to;
                    for (std::size_t row = from; row < to; ++row) {
                        const double v = m_samples[row].values[k];
                        if (!std::isfinite(v)) continue;
                        if (rmin == to || v < m_samples[rmin].values[k]) rmin = row;
                        if (rmax == to || v > m_samples[rmax].values[k]) rmax = row;
                    }
                    if (rmin == to) continue;
                    add(std::min(rmin, rmax));
                    if (rmin != rmax) add(std::max(rmin, rmax));
                }
            }
            c.series[i]->replace(points);
        }
        c.x->setRange(x0, x1);
        for (std::size_t a = 0; a < c.ys.size(); ++a) {
            double lo = los[a], hi = his[a];
            if (!(lo <= hi)) {
                lo = -1;
                hi = 1;
            }
            const double span = hi - lo;
            const double pad = span > 0 ? 0.05 * span : (hi == 0 ? 1.0 : 0.05 * std::abs(hi));
            c.ys[a]->setRange(lo - pad, hi + pad);
            c.ys[a]->applyNiceNumbers();
        }
    }
}

bool PlotPanel::exportCsv(const QString& path)
{
    std::vector<std::size_t> columns;
    QByteArray out = csvField(tr("t [s]"));
    for (const QString& key : m_selected) {
        const std::size_t k = std::size_t(indexOf(key));
        columns.push_back(k);
        out += ',' + csvField(labelOf(m_signals[k]));
    }
    out += '\n';
    for (const Sample& s : m_samples) {
        appendNumber(out, s.t);
        for (std::size_t k : columns) {
            out += ',';
            appendNumber(out, s.values[k]);
        }
        out += '\n';
    }
    // durably (fsynced, then renamed over the old file), never over a device or a folder
    solver::Text error;
    if (!solver::writeWholeFile(QFile::encodeName(path).toStdString(), std::string_view(out.constData(), std::size_t(out.size())), {},
                                error)) {
        m_error = i18n::text(error);
        return false;
    }
    m_error.clear();
    return true;
}

bool PlotPanel::exportPng(const QString& path)
{
    refresh();
    const QPixmap image = m_chartArea->grab();
    if (image.isNull() || !image.save(path, "PNG")) {
        m_error = tr("Cannot save the image %1").arg(QDir::toNativeSeparators(path));
        return false;
    }
    m_error.clear();
    return true;
}

void PlotPanel::exportCsvInteractive()
{
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export plots as CSV"), QString(), tr("CSV files (*.csv)"));
    if (!path.isEmpty() && !exportCsv(path)) emit exportFailed(m_error);
}

void PlotPanel::exportPngInteractive()
{
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Save plots as PNG"), QString(), tr("PNG images (*.png)"));
    if (!path.isEmpty() && !exportPng(path)) emit exportFailed(m_error);
}

void PlotPanel::setWindow(double seconds)
{
    m_window = std::isfinite(seconds) ? std::max(0.1, seconds) : 20.0;
    if (!m_samples.empty()) {
        const double from = m_samples.back().t - m_window;
        while (m_samples.front().t < from) m_samples.pop_front();
    }
    m_dirty = true;
}

void PlotPanel::setMinSampleInterval(double seconds)
{
    m_minInterval = std::isfinite(seconds) ? std::max(0.0, seconds) : 0.0;
}

void PlotPanel::setMaxPoints(int points)
{
    m_maxPoints = std::max(10, points);
    m_dirty = true;
}

}  // namespace studio
