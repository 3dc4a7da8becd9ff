#pragma once
// LeverBars: which levers the expert moves, over the demonstration's replay (issue 25,
// item 13). One row per drive of the stage: the control that moved it in the recorded
// input (drive_controls.h: the demonstration profile's mapping of the log's devices)
// and the drive, over a bar of its command u ∈ [−1, 1] from the centre (+ green to the
// right, − amber to the left), as the replayed input gives it (Snapshot::u).
// Drawn over the 3D view (Viewport::addOverlay); transparent to the mouse.

#include "ide/studio/train/drive_controls.h"

#include <QList>
#include <QWidget>

#include <Eigen/Core>

#include <vector>

namespace studio {

class LeverBars : public QWidget {
    Q_OBJECT
public:
    explicit LeverBars(QWidget* parent = nullptr);

    /// The rows: each drive with its controls (the first is shown).
    void setDrives(const QList<DriveControls>& drives);
    /// The commands per tree joint (Snapshot::u); repaints when they change.
    void setCommands(const Eigen::VectorXd& u);
    /// Row `i`'s command as last set (0 when out of range).
    double command(int row) const;
    int rows() const { return int(m_rows.size()); }
    /// Row `i`'s label, "lever 2 — C 2 LEVANTE PLUMA".
    QString label(int row) const;

    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    struct Row {
        int treeJoint = -1;
        QString label;
        double u = 0.0;
    };
    std::vector<Row> m_rows;
};

}  // namespace studio
