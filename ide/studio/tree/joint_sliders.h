#pragma once
// JointSliders: poses the model by hand, one slider (and a spin box with units) per
// independent coordinate — revolute joints in degrees, T 1 actuators by their length
// and T 2 joints by their displacement in metres — ranged by the joint's limits (or
// ±180°, the actuator's reachable lengths, ± the mechanism's size).
//
// Moving one recomputes the pose with a private solver::Simulation (drives and limits
// off, so that every dependent coordinate is free to follow): setInitial() for that
// joint, and the loops close again around it. A move is taken in steps of at most 2°
// (or 2 % of the mechanism's size) so the loops follow the assembly they are in. When
// they cannot close, the sliders stop at the last pose that closes, and the status
// line says so. Only meant while the simulation is paused (the main window disables
// the widget while it runs). Every pose is published with posesChanged (X_wb per body,
// tree index) and coordinatesChanged (the modeler's coordinate of every tree joint).
//
// The sliders are the simulation's state, as MuJoCo's simulate's are: the main window
// gives them every state the solver thread publishes (showState: paused, each one;
// running, ten a second), and a move by the modeler (a slider, a spin box, Reset pose)
// emits poseEdited with the whole closed pose, which the main window sends to the
// solver thread (SimulationRunner::setPositions); the 3D view then shows the
// simulation's snapshot of it, and Run continues from it.

#include "ide/studio/model/model_bundle.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QWidget>

#include <functional>
#include <memory>
#include <vector>

class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QPushButton;
class QSlider;

namespace solver {
class Simulation;
}

namespace studio {

class JointSliders : public QWidget {
    Q_OBJECT
public:
    explicit JointSliders(QWidget* parent = nullptr);
    ~JointSliders() override;

    /// One slider per independent coordinate of `bundle`, at the model's initial state
    /// (nullptr: none). Emits nothing: the model's initial pose is the solver thread's.
    void setBundle(std::shared_ptr<const ModelBundle> bundle);
    std::shared_ptr<const ModelBundle> bundle() const { return m_bundle; }

    /// Back to the model's initial state; emits posesChanged, coordinatesChanged and
    /// poseEdited.
    void reset();

    /// Shows the state θ of the simulation (per tree joint; dim nb or nq, a free joint's
    /// base orientation aside): the sliders and spin boxes move there, and the next move
    /// starts from it. Emits nothing (the pose is the simulation's already).
    void showState(const Eigen::VectorXd& theta);

    /// Moves slider `k`'s joint to coordinate `q` (SI: rad, or m for T 1 / T 2) as a
    /// drag would, emitting the signals. Returns false when the loops could not close
    /// all the way there (the pose then stops at the last one that closes).
    bool setCoordinate(int k, double q);

    // the sliders (index k = 0 … sliderCount()−1, in the order of the independent joints)
    int sliderCount() const { return static_cast<int>(m_rows.size()); }
    int sliderJoint(int k) const;  ///< tree index of slider k's joint
    QSlider* slider(int k) const;
    QDoubleSpinBox* spinBox(int k) const;  ///< degrees or metres
    /// Slider k's range in SI (rad or m).
    double lower(int k) const;
    double upper(int k) const;

    /// The current pose: X_wb per body (tree index).
    const std::vector<Eigen::Isometry3d>& poses() const;
    /// The current modeler's coordinate of every tree joint (rad or m; T 1: length).
    Eigen::VectorXd coordinates() const;
    /// The current kinematic coordinates θ of every tree joint (rad or m).
    Eigen::VectorXd theta() const;
    /// The status line ("" when the last move closed the loops).
    QString status() const;

signals:
    void posesChanged(const std::vector<Eigen::Isometry3d>& X_wb);
    /// The modeler's coordinate of every tree joint (rad or m; T 1: the length).
    void coordinatesChanged(const Eigen::VectorXd& q);
    /// The modeler moved the pose (a slider, a spin box, Reset pose): θ of every tree
    /// joint (dim nb), a pose whose loops close, for the simulation to take.
    void poseEdited(const Eigen::VectorXd& theta);

protected:
    /// A language change: every label, tooltip, unit and the status line again.
    void changeEvent(QEvent* event) override;

private:
    struct Row {
        int specIndex = -1;  // in the spec's joints
        int joint = -1;      // tree index
        int jointId = 0;
        solver::JointType type = solver::JointType::Revolute;
        double lo = 0, hi = 0;  // SI
        QLabel* label = nullptr;
        QSlider* slider = nullptr;
        QDoubleSpinBox* spin = nullptr;
    };

    void retranslate();
    /// The status line: `text` gives it in the current language ({}: none).
    void setStatus(std::function<QString()> text);

    void buildRows();
    void rebuildSimulation(const Eigen::VectorXd* goodTheta);
    bool stepTo(int joint, double theta);
    bool closed(int joint, double theta) const;
    bool moveRow(int k, double q);
    void showValues();
    /// Emits posesChanged and coordinatesChanged; with `edited` also poseEdited.
    void publish(bool edited);
    /// The private simulation at θ (every tree joint set; the loops close around it).
    void placeAt(const Eigen::VectorXd& theta);
    double displayValue(const Row& row, double q) const;

    std::shared_ptr<const ModelBundle> m_bundle;
    std::unique_ptr<solver::Simulation> m_sim;
    int m_setCalls = 0;  // setInitial() calls since the simulation was built
    std::vector<Row> m_rows;
    QWidget* m_rowsWidget = nullptr;
    QGridLayout* m_grid = nullptr;
    QLabel* m_empty = nullptr;
    QLabel* m_status = nullptr;
    std::function<QString()> m_statusText;
    QPushButton* m_reset = nullptr;
};

}  // namespace studio
