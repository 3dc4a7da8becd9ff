#pragma once
// MuJoCo side by side with Padrob (built when Debian's libmujoco-dev is found:
// PADROB_HAVE_MUJOCO). The model is exported to MJCF (solver/io/mjcf.h), loaded into
// MuJoCo in this process, checked to follow the same trajectory as Padrob (passive
// joints, no limits: the same ODE both integrate with RK4 at the same step), and
// timed.

#include "solver/core/model.h"
#include "solver/io/mjcf.h"

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

    // With a contact export (runMujoco's `contacts`): the same model with its geoms and
    // contacts on, loaded and timed after the agreement check (which runs without them).
    bool contactLoaded = false;
    int geoms = 0;                          ///< MuJoCo's ngeom
    std::vector<double> contactStepMicros;  ///< per timing run: mean mj_step with contacts [µs]
    double meanContacts = 0;                ///< MuJoCo's ncon, mean over the last timing run
    /// The run with contacts side by side (contactSeconds > 0): both engines from the
    /// initial state, contacts on, every joint passive, limits off; per exported body its
    /// centre of mass at the end in each, and the largest distance over the run [m].
    struct BodyEnd {
        std::string body;  ///< "1 \"box\""
        Eigen::Vector3d padrob = Eigen::Vector3d::Zero(), mujoco = Eigen::Vector3d::Zero();
    };
    double contactSeconds = 0;      ///< how long they ran side by side [s]
    double contactMaxDistance = 0;
    std::string contactFailure;     ///< why the side-by-side run stopped early ("" it did not)
    std::vector<BodyEnd> contactEnd;
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
///
/// `contacts` (may be null): the export options with the model's spec (and scene) for
/// its geoms (solver::MjcfOptions::spec; the model has CONTACT). Padrob's side of the
/// agreement run then leaves the contacts out (MuJoCo's export there has no geoms), and
/// afterwards the export with geoms is loaded (the same true masses put in) and
/// `steps` mj_step calls are timed `runs` times from the keyframe: contactStepMicros;
/// with `contactSeconds` > 0 both engines first run that long with contacts, side by
/// side (contactEnd, contactMaxDistance: the differences of the two contact laws,
/// reported, not judged: docs/contact.md gives what to expect).
bool runMujoco(const solver::Model& model, double dt, int steps, int runs, double agreementSeconds, double tolerance,
               MujocoRun& out, std::string& error, const solver::MjcfOptions* contacts = nullptr,
               double contactSeconds = 0);

}  // namespace ide::cli
