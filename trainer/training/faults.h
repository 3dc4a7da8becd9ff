#pragma once
// Faults an instructor injects into a running attempt (docs/training.md "Faults the
// instructor injects"): TutorialSession::inject() and clearFault(). The
// physics honours them (a burst hose: solver::Simulation::setDriveFault), the session
// applies the rest to the operator's commands and to the people in the scene, and the
// checker scores what follows as for any run. A fault costs no points by itself.

#include "solver/integrate/simulation.h"

#include <Eigen/Core>
#include <QString>

#include <limits>
#include <string>

namespace trainer {

struct Fault {
    enum class Kind {
        HoseBurst,   ///< a drive loses its pressure: its joint goes passive (the load sags)
        StuckValve,  ///< a drive's valve sticks at an opening: its lever does nothing
        WorkerIn,    ///< a person walks into the work area (one of the tutorial's WORKERs)
        PowerCut,    ///< every valve closes (commands 0: the machine holds) until power is back
    };
    Kind kind = Kind::HoseBurst;
    /// HoseBurst, StuckValve: the drive, by its joint's name in the model (as the
    /// events name it: "LEVANTE PLUMA"; "C 2" for a joint without a name; matched
    /// without regard to case).
    std::string drive;
    /// StuckValve: the opening it sticks at, a command in [−1, 1]; NaN: where the valve
    /// is now (the command the solver has). inject() stores the one it used.
    double opening = std::numeric_limits<double>::quiet_NaN();
    /// HoseBurst: what is left of the drive (solver::DriveFault; default: passive).
    solver::DriveFault hose;
    /// WorkerIn: the WORKER (index in the tutorial's order, from 0) and where the person
    /// now stands: the new place of its first graphic's POS (the person moves as a
    /// whole, translated, not turned) [m, world].
    int worker = 0;
    Eigen::Vector3d where = Eigen::Vector3d::Zero();

    /// Stable name: "hose-burst", "stuck-valve", "worker-in", "power-cut".
    static const char* key(Kind k);
    /// The kind of a key(); false (and `k` unchanged) for any other text.
    static bool fromKey(const std::string& key, Kind* k);
    /// Translated, e.g. "Hose burst".
    static QString label(Kind k);
    /// True for the kinds that name a drive.
    static bool onDrive(Kind k) { return k == Kind::HoseBurst || k == Kind::StuckValve; }
};

}  // namespace trainer
