#pragma once
// Running a tutorial without a window (`padrob tutorial`, the tests, the debrief's
// expert comparison): an input log replayed through a station profile, or the
// autopilot, drive a TutorialSession to its end.
//
// The autopilot records expert demonstrations for tutorial authors: it reads a path
// of joint targets (docs/training.md "Recording a demonstration with the autopilot")
// and moves the levers of a virtual valve console as a careful operator would —
// proportionally to the remaining way, ramped, one waypoint after another — through
// the same station profile, calibration and mapping as a person, while a recorder
// writes the lever readings as an input log. Replaying that log is the demonstration.

#include "trainer/input/input_log.h"
#include "trainer/station/profile.h"
#include "trainer/training/camera_path.h"
#include "trainer/training/session.h"

#include <QString>

#include <memory>
#include <vector>

namespace trainer {

/// The station profile a tutorial runs with: `override` (a .json file or a name of the
/// model's profiles) when given, else Tutorial::profile (its PROFILE, else the one Padrob
/// makes for the model). False with `error`.
bool tutorialProfile(const Tutorial& tutorial, const QString& override, StationProfile& out, QString* error);

struct RunOutput {
    TutorialResult result;
    std::vector<SessionSample> samples;
};

/// Replays `log` through `profile` into a session of `tutorial` until it ends; a log
/// that runs out leaves `grace` seconds for the machine to settle, then ends the attempt
/// (InputEnded). False with `error` when the profile cannot drive the model.
bool runTutorialWithLog(std::shared_ptr<const Tutorial> tutorial, std::shared_ptr<const InputLog> log,
                        const StationProfile& profile, RunOutput& out, QString* error, double grace = 3.0);

/// One waypoint of an autopilot path: joint targets (modeler coordinates) reached
/// together, or a pause with the levers centred.
struct AutopilotWaypoint {
    std::vector<std::pair<int, double>> targets;  ///< joint id → value
    double tolerance = 0.0;  ///< 0: per joint (1 mm, 0.2°)
    double wait = 0.0;       ///< [s] levers centred
    double lever = 0.0;      ///< 0: full travel; else how far (0 … 1) the levers open at most (eased together)
    std::vector<std::pair<int, double>> jointLever;  ///< joint id → how far its lever opens at most (the others eased with it)
    double ramp = 0.0;       ///< [s] a lever's full travel (0: the autopilot's 0.5 s)
    double stall = 0.0;      ///< [s] also reached when its joints have stopped this long short of their targets (0: never)
    int line = 0;
};

/// Reads an autopilot path: one waypoint per line, `id=value` pairs (values may end
/// in `deg`), `tol=value`, `lever=fraction` or `lever=id:fraction` and `ramp=seconds`
/// (a gentle move: the levers, or that joint's, open at most that far, the others eased
/// with them so that the joints still arrive together, and take that long for their full
/// travel instead of 0.5 s), `stall=seconds` (a push against something, as a part into its
/// seat: the waypoint is also reached once its joints have all moved less than their
/// tolerance for that long, their levers still pushing), or `wait=seconds`; `#` starts a
/// comment. False with `error` ("line 3: …").
bool parseAutopilotPath(const QString& text, std::vector<AutopilotWaypoint>& out, QString* error);

/// Drives a session of `tutorial` along `path` with the levers of a virtual console that
/// `profile` maps (an axis per drive), recording them to `logPath`. False with `error`
/// when a target's drive has no lever in the profile, or the log cannot be written. The
/// run's result (as the autopilot flew it) is in `out`.
/// The lever closes proportionally to the way left at the drive's full-lever rate (HYD:
/// VMAX/VMIN; CYL/HMOTOR: the valve's flow over the area it fills), and in time for its
/// ramp (and a spool's lag) to stop the joint at its target, never below what
/// moves the joint (HYD: 12 %; fluid power: the opening whose run-on, the lever's
/// return and the spool's lag, stays within half the tolerance); a joint that has shown
/// more speed than its valve gives (a load running ahead of its oil) is slowed down
/// sooner. A fluid-power joint has arrived only when it is within tolerance and has
/// settled, and near its target it is not pushed back while it still swings on its oil
/// (that would feed the swing). A lever that also
/// moves a joint the waypoint does not aim (the claws' lever) is eased as that joint
/// nears its end stop, so that it arrives at under a third of its speed. Levers whose
/// fluid-power sections share a pump are eased back together so that they never ask it
/// for more than 95 % of its flow (a careful operator does not saturate the pump).
/// With `camera`, a chase camera is recorded too: every 0.5 s, looking at the tracked
/// point (smoothed) from behind the machine and 35° to the side, from above.
bool recordWithAutopilot(std::shared_ptr<const Tutorial> tutorial, const std::vector<AutopilotWaypoint>& path,
                         const StationProfile& profile, const QString& logPath, RunOutput& out, QString* error,
                         CameraPath* camera = nullptr);

}  // namespace trainer
