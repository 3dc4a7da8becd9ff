#pragma once
// Snapshot: what the solver thread publishes after each step, and the only thing the
// GUI reads of a running simulation (it never touches solver memory). Immutable once
// published; shared as std::shared_ptr<const Snapshot>.

#include "ide/studio/model/model_bundle.h"
#include "solver/core/spatial.h"
#include "solver/integrate/simulation.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace studio {

struct Snapshot {
    std::shared_ptr<const ModelBundle> bundle;  ///< the model these values belong to
    double t = 0;                               ///< simulated time [s]
    long step = 0;                              ///< steps taken since the last reset
    std::vector<Eigen::Isometry3d> bodyPoses;   ///< X_wb per body, by tree index
    Eigen::VectorXd theta;                      ///< θ per tree joint (the state)
    Eigen::VectorXd q, qd;                      ///< modeler's coordinate and rate per tree joint
    Eigen::VectorXd u;                          ///< commands per tree joint in [−1, 1]
    Eigen::VectorXd driveForce;                 ///< per tree joint [N or N m] (Data::driveForce)
    std::vector<solver::Vector6d> reactionJoint;  ///< per tree joint, joint axes (Data::reactionJoint)
    double energy = 0;                          ///< mechanical energy [J]
    std::vector<solver::SimulationEvent> events;  ///< events of this step (limits, reliefs, welds…)

    // pacing (solver thread)
    bool running = false;      ///< advancing (not paused)
    double speed = 1;          ///< simulated seconds per wall-clock second requested (0.1 … 4)
    double realTimeFactor = 0; ///< achieved: simulated / wall time over the last second
    double stepMicros = 0;     ///< median compute time of one step over the last second [µs]
    long overruns = 0;         ///< steps that finished after their wall-clock deadline (since reset)
    std::string error;         ///< the simulation failed or a loop locked: why (then running is false)
};

}  // namespace studio
