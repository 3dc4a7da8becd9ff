#pragma once
// MuJoCo side by side with Padrob (built when Debian's libmujoco-dev is found:
// PADROB_HAVE_MUJOCO). The model is exported to MJCF (solver/io/mjcf.h), loaded into
// MuJoCo in this process, checked to follow the same trajectory as Padrob (passive
// joints, no limits: the same ODE both integrate with RK4 at the same step), and
// timed.

#include "solver/core/model.h"

#include <string>
#include <vector>

namespace ide::cli {

struct MujocoRun {
    /// Largest distance between the two engines' body positions (centres of mass,
    /// world) over the agreement run [m].
    double maxPositionError = 0;
    double agreementSeconds = 0;      ///< simulated time compared [s]
    std::vector<double> stepMicros;   ///< per timing run: mean time of one mj_step (RK4, dt) [µs]
    std::vector<double> forwardMicros;///< per timing run: mean time of one mj_forward [µs]
    /// What had to be set after loading because MuJoCo's compiler refuses it (massless
    /// bodies, inertias breaking the triangle inequality), one line each.
    std::vector<std::string> adjustments;
    /// What the comparison leaves out of Padrob's model so that both integrate the same
    /// equations (drives, limits, applied forces), one line each.
    std::vector<std::string> notes;
};

/// Exports, loads, checks agreement over `agreementSeconds` (body positions within
/// `tolerance` [m]) and times `steps` steps and forward evaluations, `runs` times.
/// False with `error` when it cannot: a model with loops, MuJoCo refusing it, or the
/// engines disagreeing (then no timing: a fast wrong answer does not count).
///
/// Details (ide/cli/mujoco_bench.cpp): the MJCF of solver::toMjcf with timestep dt is
/// loaded from memory; bodies with placeholder mass properties get their true mass,
/// principal moments and principal axes (body_mass, body_inertia, body_iquat;
/// mj_setConst after), each listed in `adjustments`; MuJoCo's joint limits are
/// disabled (mjDSBL_LIMIT). Padrob runs a solver::Simulation of the model without its
/// applied forces, every drive passive and no limits, RK4 at dt. Both start from the
/// keyframe "initial" (θ0, θ̇0); after every step the world positions of every body's
/// centre of mass are compared (Padrob: comPosition; MuJoCo: xipos after
/// mj_kinematics). Timing: one warm-up run, then `runs` runs of `steps` mj_step calls,
/// each from the initial state, then the same for mj_forward (steps or runs 0: no
/// timing), std::chrono::steady_clock.
bool runMujoco(const solver::Model& model, double dt, int steps, int runs, double agreementSeconds, double tolerance,
               MujocoRun& out, std::string& error);

}  // namespace ide::cli
