#pragma once
// HydraulicPanel: the fluid-power circuit of a running model, live (docs/studio.md,
// "The hydraulic panel"). It reads Snapshots only (the GUI never touches solver
// memory) and paints with QPainter:
//  - per pump (Model::pumps order), labelled "PUMP 1 name": its supply pressure as a
//    bar against p_max, and the flow it delivers as a bar against Qmax, orange and
//    marked "saturated" while the open sections want more than Qmax;
//  - per valve section (Model::circuits order), labelled with its joint ("C 2
//    LEVANTE PLUMA"): the spool as a bar from the centre (−100 … +100 %), and the
//    pressures of chambers A and B as bars against the relief setting (the pump's
//    p_max), red from kReliefShare of it (where the solver reports the relief open),
//    hatched purple and marked while the chamber cavitates.
// Numbers are MPa, L/min and % in the current locale (QLocale: 12,5 MPa in Spanish).
// Hovering a pump or a section shows all its values, flows included (pumpSummary(),
// sectionSummary()). A model without pumps shows a one-line note instead.
//
// The layout follows the width: wide (a dock under the 3D view) one row per section
// with its joint at the left; narrow (the Train workspace's side panel) the joint
// above its bars. Rows shrink with the height down to the font's, then the panel
// scrolls.
//
// Data: setRunner() polls the runner's latest() at 60 Hz (the GUI's poll rate);
// setSnapshot() takes one from elsewhere (the Train workspace's TutorialRunner).

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/sim/snapshot.h"

#include <QPointer>
#include <QRect>
#include <QStringList>
#include <QWidget>

#include <memory>
#include <utility>
#include <vector>

class QFontMetrics;
class QLabel;
class QPainter;
class QScrollArea;
class QTimer;

namespace studio {

class SimulationRunner;

class HydraulicPanel : public QWidget {
    Q_OBJECT
public:
    /// A chamber at or above this share of its relief setting is drawn red (the
    /// solver's ReliefOpen event fires there too).
    static constexpr double kReliefShare = 0.98;

    explicit HydraulicPanel(QWidget* parent = nullptr);
    ~HydraulicPanel() override;

    /// Follows `runner`'s newest snapshot, polled at 60 Hz. nullptr: stops following.
    void setRunner(SimulationRunner* runner);
    /// Shows `snapshot` (nullptr: no model). A snapshot of another model emits modelChanged().
    void setSnapshot(std::shared_ptr<const Snapshot> snapshot);
    std::shared_ptr<const Snapshot> snapshot() const { return m_snapshot; }

    /// The model shown has pumps (false without a model).
    bool hasFluidPower() const { return m_snapshot && !m_snapshot->pumps.empty(); }
    /// A heading ("Hydraulics") above the bars, for where no dock title names the panel.
    void setHeadingVisible(bool visible);

    /// "PUMP 1 bomba LS 45 cm³/rev" (the pump of Model::pumps index p).
    QString pumpLabel(int p) const;
    /// "C 2 LEVANTE PLUMA" (the joint of Model::circuits index c).
    QString sectionLabel(int c) const;
    /// Every value of pump p, one per line (its tooltip); "" when there is none.
    QString pumpSummary(int p) const;
    /// Every value of section c, flows included, one per line (its tooltip); "".
    QString sectionSummary(int c) const;

    QSize sizeHint() const override;

signals:
    /// A snapshot of another model (or none) came; `hasFluidPower`: it has pumps.
    void modelChanged(bool hasFluidPower);

protected:
    /// A language change: the labels and numbers again.
    void changeEvent(QEvent* event) override;

private:
    class Canvas;
    friend class Canvas;
    /// What the canvas draws, and where: the layout for a width.
    struct Layout {
        bool wide = true;
        int row = 0;     ///< a row's height [px]
        int rows2 = 0;   ///< rows needed, counted in half rows
    };
    Layout layoutFor(int width, int height) const;
    /// The width of the wide layout's column of joints [px].
    int labelColumn(const QFontMetrics& fm) const;
    /// Sets the canvas's minimum height for its width (then it scrolls).
    void relayout();
    void paintCanvas(QPainter& p, int width, int height);
    /// The tooltip at a point of the canvas ("" none).
    QString toolTipAt(const QPoint& pos) const;
    void relabel();
    void poll();

    std::shared_ptr<const Snapshot> m_snapshot;
    std::shared_ptr<const ModelBundle> m_bundle;  ///< the model of the labels
    bool m_announced = false;  ///< modelChanged() was emitted for m_bundle
    QStringList m_pumpLabels, m_sectionLabels;
    /// Where each pump (−1 − p) and section (c) was last drawn, for tooltips.
    std::vector<std::pair<QRect, int>> m_hits;

    QPointer<SimulationRunner> m_runner;
    QTimer* m_pollTimer = nullptr;
    QLabel* m_heading = nullptr;
    QScrollArea* m_scroll = nullptr;
    Canvas* m_canvas = nullptr;
};

}  // namespace studio
