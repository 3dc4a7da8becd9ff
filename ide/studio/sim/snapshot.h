#pragma once
// Snapshot: what the solver thread publishes, and the only thing the GUI reads of a
// running simulation (it never touches solver memory). Immutable once published;
// shared as std::shared_ptr<const Snapshot> (SimulationRunner::latest()).
//
// The runner publishes one after every batch of steps (about every millisecond while
// running, after each stepOnce(), and at every pause, reset, new model or failure);
// the GUI polls the newest at its own rate (60 Hz) and may skip many: values are
// those of the last step, and what must not be missed (events) is also kept in
// eventLog.

#include "ide/studio/model/model_bundle.h"
#include "solver/core/spatial.h"
#include "solver/integrate/simulation.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace studio {

/// One pump's operating point (solver/hydraulics/pump.h), in Model::pumps order.
struct PumpSnapshot {
    double supplyPressure = 0;  ///< p_S [Pa] (Data::supplyPressure)
    double flow = 0;            ///< delivered [m^3/s] (Data::pumpFlow; ≤ qmax)
    double demand = 0;          ///< what the open sections would draw [m^3/s] (Data::pumpDemand)
    double qmax = 0;            ///< the pump's Qmax [m^3/s]
    double pmax = 0;            ///< its p_max [Pa] (also every fed chamber's relief setting)
    /// The sections want more than the pump gives (their flows are shared out, or the supply falls).
    bool saturated() const { return demand > qmax; }
};

/// One CYL/HMOTOR drive: its valve section and its actuator's chambers, in
/// Model::circuits order.
struct CircuitSnapshot {
    int joint = -1;          ///< tree index of the driven joint
    double spool = 0;        ///< x in [−1, 1] (State::fluid)
    double pressureA = 0;    ///< p_A [Pa] (Data::pressureA; gauge, ≥ 0)
    double pressureB = 0;    ///< p_B [Pa] (Data::pressureB)
    double flowA = 0;        ///< valve flow into A [m^3/s] (< 0: out; Data::flowA)
    double flowB = 0;        ///< valve flow into B [m^3/s] (Data::flowB)
    double relief = 0;       ///< the port reliefs' setting: its pump's p_max [Pa]
    int cavitation = 0;      ///< 1 chamber A, 2 chamber B, 3 both (Data::cavitation), else 0
};

/// One contact of the snapshot's evaluation (CONTACT, Data::contacts), world axes, seen
/// from the solid that moves (of a pair of moving solids, the second).
struct ContactSnapshot {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< [m]
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); ///< unit, from the other solid into that one
    Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< on that solid [N]
};

struct Snapshot {
    std::shared_ptr<const ModelBundle> bundle;  ///< the model these values belong to
    double t = 0;                               ///< simulated time [s]
    long step = 0;                              ///< steps taken since the last reset (t = step · timeStep)
    long poseEdits = 0;                         ///< poses set by hand since the last reset (SimulationRunner::setPositions)
    double timeStep = 0;                        ///< the fixed step [s]
    std::vector<Eigen::Isometry3d> bodyPoses;   ///< X_wb per body, by tree index
    Eigen::VectorXd theta;                      ///< θ per tree joint (the state)
    Eigen::VectorXd q, qd;                      ///< modeler's coordinate and rate per tree joint
    Eigen::VectorXd u;                          ///< commands per tree joint in [−1, 1]
    solver::Push push;                          ///< the mouse's push in force (body −1: none)
    Eigen::VectorXd driveForce;                 ///< per tree joint [N or N m] (Data::driveForce)
    std::vector<solver::Vector6d> reactionJoint;  ///< per tree joint, joint axes (Data::reactionJoint)
    double energy = 0;                          ///< mechanical energy [J]
    std::vector<ContactSnapshot> contacts;      ///< CONTACT: the contacts (empty without)
    double largestContactForce = 0;             ///< |force| of the largest contact [N]
    /// Fluid power (docs/hydraulics.md): empty for a model without pumps.
    std::vector<PumpSnapshot> pumps;            ///< Model::pumps order
    std::vector<CircuitSnapshot> circuits;      ///< Model::circuits order
    /// Events since the previous published snapshot (limits, reliefs, welds, lock-up).
    /// A GUI polling at 60 Hz skips snapshots: read eventLog instead.
    std::vector<solver::SimulationEvent> events;
    /// Every event since the last reset, oldest first (the newest kSnapshotEventLog when
    /// there were more); shared between snapshots until the next event. Never null.
    std::shared_ptr<const std::vector<solver::SimulationEvent>> eventLog;
    long eventCount = 0;  ///< events since the last reset (≥ eventLog->size())

    // pacing (solver thread)
    bool running = false;      ///< advancing (not paused)
    double speed = 1;          ///< simulated seconds per wall-clock second requested (0.1 … 4)
    double realTimeFactor = 0; ///< achieved: simulated / wall time over the last second (0 paused)
    double stepMicros = 0;     ///< median compute time of one step over the last second [µs]
    /// Median wall-clock interval between consecutive steps' ends over the last second
    /// [µs]: timeStep / speed when paced (steps are batched per millisecond, so at speed
    /// > 1 this is the time of a step inside a batch).
    double stepPeriodMicros = 0;
    double stepPeriodMaxMicros = 0;  ///< the longest of those intervals [µs]
    /// Share of one CPU core the solver thread used over the last second (0 … 1;
    /// −1 when the platform cannot tell).
    double cpuLoad = -1;
    /// Steps that finished after their wall-clock deadline, the wall time at which
    /// their end is due (the solver may run up to 2 ms ahead), since reset.
    long overruns = 0;
    /// Wall-clock time given up [s] since reset: when more than 50 ms behind, the
    /// solver stops catching up and carries on from the current time (the simulation
    /// then runs behind real time; simulated time never jumps).
    double droppedSeconds = 0;
    std::string error;         ///< the simulation failed or a loop locked: why (then running is false)
};

/// Most events a Snapshot's eventLog keeps.
inline constexpr std::size_t kSnapshotEventLog = 1000;

/// A snapshot of `sim`'s current state and data (model fields only: pacing fields keep
/// their defaults, eventLog is empty, step is 0).
std::shared_ptr<Snapshot> captureSnapshot(const solver::Simulation& sim,
                                          std::shared_ptr<const ModelBundle> bundle);

}  // namespace studio
