#pragma once
// PlotPanel: live plots of a simulation against time (QtCharts). The user ticks
// signals in a list — for every tree joint its coordinate q, its rate q̇, its drive's
// force (driven joints), the pressures of chambers A and B (CYL/HMOTOR drives, in MPa)
// and the six reaction components in the joint's axes (A, R, T); every pump's supply
// pressure (MPa) and delivered flow (L/min); and the mechanical energy — and sees them
// while the machine moves: one chart per unit (°, m, N, N m, MPa, …), several
// signals in a chart, stacked. A ticked signal's "chart" box (beside it in the list,
// setSignalChart) puts it instead in one of kMaxCharts numbered charts, where signals of
// any units are overlaid: one vertical axis per unit, the first on the left, the others
// on the right. Angles are in degrees and lengths in metres, as the Joints sliders
// show them (a revolute joint's q in °, its rate in °/s). (The rate is
// written dq/dt: the fonts of a bare X server do not draw a combining dot.)
//
// Data: fed by addSnapshot() (or by setRunner(), which polls the runner's latest()
// at 60 Hz). Every signal's history is kept, not only the ticked ones', so a signal
// ticked later shows its past at once; only the last window() seconds are kept
// (default 20 s), at most one sample per minSampleInterval(). A snapshot earlier than
// the last (a reset) or of another model clears the history. The charts are redrawn
// at 10 Hz with at most maxPoints() points per series: longer histories are reduced
// to each bucket's minimum and maximum, so peaks survive and llvmpipe keeps up.
//
// Signals are named by stable keys: "q:J", "qd:J", "f:J", "pA:J", "pB:J", "Ma:J",
// "Mr:J", "Mt:J", "Fa:J", "Fr:J", "Ft:J" for the joint with id J (C J), "pS:P" and
// "Qp:P" for the pump with id P (PUMP P), and "energy"; a new model keeps the ticks of
// the keys it still has.
//
// Export: exportCsv() writes t and the ticked signals (every kept sample, shortest
// round-trip decimals, "." as the decimal point); exportPng() the charts as shown.

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/snapshot.h"

#include <QHash>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <deque>
#include <memory>
#include <vector>

QT_BEGIN_NAMESPACE
class QChartView;
class QLabel;
class QLineSeries;
class QPushButton;
class QTimer;
class QTreeWidget;
class QTreeWidgetItem;
class QValueAxis;
class QVBoxLayout;
QT_END_NAMESPACE

namespace studio {

class SimulationRunner;

class PlotPanel : public QWidget {
    Q_OBJECT
public:
    explicit PlotPanel(QWidget* parent = nullptr);
    ~PlotPanel() override;

    /// The model whose signals are listed; clears the history. Ticks of keys the new
    /// model also has stay.
    void setBundle(std::shared_ptr<const ModelBundle> bundle);
    /// Follows `runner`: its model (bundleChanged), its resets (clear), and its newest
    /// snapshot, polled at 60 Hz. nullptr: stops following.
    void setRunner(SimulationRunner* runner);

    /// Adds one sample (ignored when less than minSampleInterval() after the last).
    void addSnapshot(const Snapshot& snapshot);
    /// Forgets the history (the list and the ticks stay).
    void clear();

    /// Every signal of the model, in list order.
    QStringList signalKeys() const;
    /// "C 2 LEVANTE PLUMA q [m]", "pump 1 main p_S [MPa]" (as in the legend and the
    /// CSV header); "" for an unknown key.
    QString signalLabel(const QString& key) const;
    /// "m", "rad/s", "N", "N m", "J"…
    QString signalUnit(const QString& key) const;
    void setSignalSelected(const QString& key, bool selected);
    /// The ticked signals, in the order they were ticked.
    QStringList selectedSignals() const { return m_selected; }
    /// The chart a signal is drawn in when ticked: 0, its unit's chart (the default), or
    /// numbered chart 1 … kMaxCharts, shared with the signals of any unit put there.
    static constexpr int kMaxCharts = 4;
    void setSignalChart(const QString& key, int chart);
    int signalChart(const QString& key) const { return m_chartOf.value(key, 0); }
    /// The chart (0 = the top one) that shows a ticked signal; −1 when none does.
    int chartIndexOf(const QString& key) const;
    /// Chart `i`'s vertical axes' units, left one first.
    QStringList chartUnits(int i) const;

    void setWindow(double seconds);  ///< history kept and shown [s] (≥ 0.1)
    double window() const { return m_window; }
    void setMinSampleInterval(double seconds);  ///< default 4 ms
    double minSampleInterval() const { return m_minInterval; }
    void setMaxPoints(int points);  ///< per series on screen (≥ 10; default 1000)
    int maxPoints() const { return m_maxPoints; }

    int sampleCount() const { return int(m_samples.size()); }
    /// Charts on screen (one per unit of the ticked signals).
    int chartCount() const { return int(m_charts.size()); }
    /// The series of a ticked signal (nullptr otherwise): its points after refresh().
    QLineSeries* series(const QString& key) const;
    /// Redraws now (it happens by itself at 10 Hz when new samples came).
    void refresh();

    /// Writes t and the ticked signals to `path`. False (errorString()) on I/O errors.
    bool exportCsv(const QString& path);
    /// Saves the charts as shown to `path` (PNG). False (errorString()) on errors.
    bool exportPng(const QString& path);
    QString errorString() const { return m_error; }

signals:
    void selectionChanged();
    /// An export from the panel's own buttons failed (for the window to show).
    void exportFailed(const QString& message);

protected:
    /// A language change: the buttons, the list, the legends and the axes again (numbers
    /// in the new locale); the history and the ticks stay.
    void changeEvent(QEvent* event) override;

private:
    enum class Kind { Q, Qd, Force, PressureA, PressureB, Ma, Mr, Mt, Fa, Fr, Ft, Supply, PumpFlow, Energy, ContactForce };
    struct Signal {
        QString key, unit;
        QString symbol;  // "q", "dq/dt", "M_A"… (the same in every language)
        Kind kind = Kind::Q;
        int tree = -1;   // tree joint (joint signals)
        int axis = -1;   // a free joint's translation: 0, 1, 2 along B1's joint axes A, R, T; −1 otherwise
        int index = -1;  // Model::circuits index (PressureA/B) or Model::pumps index (Supply, PumpFlow)
        int ownerId = 0;    // the joint's id (C J), or the pump's (PUMP P)
        double scale = 1;   // from SI to the unit shown (rad → °)
        QString ownerName;  // its NAME
        bool isPump() const { return kind == Kind::Supply || kind == Kind::PumpFlow; }
    };
    struct Sample {
        double t = 0;
        std::vector<double> values;  // per signal (m_signals order)
    };
    struct Chart {
        QString group;  // a unit, or "#N" for numbered chart N
        QChartView* view = nullptr;
        QValueAxis* x = nullptr;
        std::vector<QString> units;   // one vertical axis per unit
        std::vector<QValueAxis*> ys;
        std::vector<int> signalIndices;
        std::vector<QLineSeries*> series;
        std::vector<int> seriesAxis;  // index into ys
    };

    void retranslate();
    /// "C 2 LEVANTE PLUMA q [m]", "mechanical energy [J]" in the current language.
    QString labelOf(const Signal& s) const;
    /// What a signal belongs to: "C 2 LEVANTE PLUMA", "pump 1 main" (its list group).
    QString ownerOf(const Signal& s) const;
    /// Appends a signal keyed "prefix:ownerId".
    Signal& addSignal(Kind kind, const QString& prefix, const QString& symbol, const QString& unit, int ownerId,
                      const QString& ownerName);
    int indexOf(const QString& key) const;
    void rebuildList();
    void rebuildCharts();
    /// A new chart in the chart area, its time axis, no series.
    Chart makeChart(const QString& group);
    /// The chart box beside a ticked signal's item (column 1).
    void addChartBox(QTreeWidgetItem* item, const QString& key);
    void onItemChanged(QTreeWidgetItem* item, int column);
    void poll();
    /// addSnapshot's work; `always`: also when less than minSampleInterval() after the
    /// last sample. False when the snapshot was left out.
    bool addSample(const Snapshot& snapshot, bool always);
    void exportCsvInteractive();
    void exportPngInteractive();

    std::shared_ptr<const ModelBundle> m_bundle;
    std::vector<Signal> m_signals;
    QStringList m_selected;
    QHash<QString, int> m_chartOf;  // key → numbered chart (absent: its unit's)
    std::deque<Sample> m_samples;
    std::vector<Chart> m_charts;
    double m_window = 20;
    double m_minInterval = 0.004;
    int m_maxPoints = 1000;
    bool m_dirty = false;
    bool m_updatingList = false;
    QString m_error;

    QPointer<SimulationRunner> m_runner;
    std::shared_ptr<const Snapshot> m_lastPolled;
    /// The runner's newest snapshot when the sampling interval left it out: plotted at
    /// the next poll that finds nothing newer (paused, the plot ends where the
    /// simulation stands)
    std::shared_ptr<const Snapshot> m_leftOut;
    QTimer* m_pollTimer = nullptr;
    QTimer* m_redrawTimer = nullptr;
    QTreeWidget* m_list = nullptr;
    QWidget* m_chartArea = nullptr;
    QVBoxLayout* m_chartLayout = nullptr;
    QLabel* m_placeholder = nullptr;
    QPushButton* m_clearButton = nullptr;
    QPushButton* m_csvButton = nullptr;
    QPushButton* m_pngButton = nullptr;
};

}  // namespace studio
