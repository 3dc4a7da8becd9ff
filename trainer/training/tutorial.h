#pragma once
// Tutorials: a stage of the training course as a data file. The format looks
// like the model language (one statement per line, keywords, `//` comments; the same
// lexer) and is documented in docs/training.md. A file is parsed into a TutorialSpec
// as written (with source positions), then resolved once against its model and scene
// into an immutable Tutorial that any number of sessions (the Train workspace, the
// headless `padrob tutorial`, the tests) share read-only.
//
// A tutorial with errors is never half-loaded: loadTutorial() returns nullptr and
// every problem as a Diagnostic with its file, line and column and a hint.

#include "solver/core/diagnostic.h"
#include "solver/core/model.h"
#include "solver/pipeline.h"
#include "solver/spec/model_spec.h"
#include "trainer/station/profile.h"

#include <Eigen/Core>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace trainer {

/// A text a person reads, in every language of the product (ISO 639-1: "es", "en").
struct LocalText {
    std::map<std::string, std::string> byLanguage;
    solver::SourcePos pos;
    /// The text in `language`, else English, else any.
    std::string in(const std::string& language) const;
    bool empty() const { return byLanguage.empty(); }
};

/// The languages every text of a tutorial must have.
inline const std::vector<std::string> kTutorialLanguages{"es", "en"};

/// A body-fixed direction that must point along a world direction.
struct Alignment {
    Eigen::Vector3d local = Eigen::Vector3d::UnitX();  ///< in the body's frame (unit)
    Eigen::Vector3d world = Eigen::Vector3d::UnitX();  ///< unit
    double tolerance = 0.0;                            ///< [rad]
    solver::SourcePos pos;
};

struct JointTarget {
    int jointId = 0;
    double value = 0.0;      ///< modeler coordinate (T 1: length; revolute: rad)
    double tolerance = 0.0;
    solver::SourcePos pos;
};

struct Goal {
    enum class Kind {
        Reach,  ///< a point on a body at a world position (and attitude), held DWELL s
        Joint,  ///< joints at values, held DWELL s
        Grasp,  ///< the GRIP's load is grasped
        Place,  ///< the GRIP's load released at a world pose
    };
    Kind kind = Kind::Reach;
    std::string id;
    LocalText name;               ///< what the HUD shows ("Bring the claws over the liner")
    int bodyId = 0;               ///< Reach
    Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< Reach: on the body, body frame
    Eigen::Vector3d target = Eigen::Vector3d::Zero();  ///< Reach: of the point; Place: of the load's centre of mass
    double tolerance = 0.0;       ///< [m]
    std::vector<Alignment> align; ///< Reach, Place
    std::vector<JointTarget> joints;  ///< Joint
    double dwell = 0.0;           ///< [s]
    bool fix = false;             ///< Place: the placed load is bolted (welded to the ground)
    double seat = 0.0;            ///< Place: within this of the target the load's touches are free, hard hits not (0: 3 × tolerance) [m]
    solver::SourcePos pos;
};

/// How the load is grasped: when the tool's grip point is within `tolerance` of the
/// load's and the closing joints are past their CLOSE values, the load is welded to
/// the tool; it is released when they are back past their OPEN values.
struct Grip {
    int loadBodyId = 0;
    int toolBodyId = 0;
    Eigen::Vector3d loadPoint = Eigen::Vector3d::Zero();  ///< on the load, its frame
    Eigen::Vector3d toolPoint = Eigen::Vector3d::Zero();  ///< on the tool, its frame
    double tolerance = 0.0;       ///< [m]
    double angleTolerance = 0.0;  ///< [rad] between the load's axes and the tool's (as at the grip)
    Eigen::Matrix3d relative = Eigen::Matrix3d::Identity();  ///< load axes in the tool frame at a proper grip
    std::vector<JointTarget> close;  ///< value: a closing joint counts as closed beyond it (towards its TOL sign)
    std::vector<JointTarget> open;
    std::vector<int> fingerBodyIds;  ///< bodies that may touch the load (tool, claws)
    solver::SourcePos pos;
    bool present = false;
};

struct Hint {
    LocalText text;
    std::string goal;       ///< "" any goal
    double after = 0.0;     ///< shown after this long on the goal [s]
};

struct Worker {
    std::vector<int> graphicIds;  ///< the scene's G ids of the person
    double zone = 1.0;            ///< safety distance [m]
    double penalty = 10.0;
    LocalText name;
    solver::SourcePos pos;
};

/// A named part of the scene or of the model's ground graphics (the blast wall, the
/// liner cart), so that hits name what was touched.
struct Part {
    bool scene = true;             ///< the scene's graphics; false: the model's ground graphics
    std::vector<int> graphicIds;
    LocalText name;
    solver::SourcePos pos;
};

struct Scoring {
    double timeLimit = 300.0;  ///< the attempt ends there, failed [s]
    double parTime = 120.0;    ///< full time points at or under it [s]
    double pass = 60.0;        ///< pass mark, 0–100
    double wTime = 25, wPath = 20, wSmooth = 15, wSafety = 40;  ///< sum 100
    double jerkReference = 20.0;  ///< RMS jerk of the tracked point at which smoothness gives 0 [m/s³]
    double hitPenalty = 5.0;
    double nearDistance = 0.10;   ///< closer than this to the scene: a near miss (no penalty) [m]
    double hardSpeed = 0.5;       ///< touching at more than this: a hard hit, the attempt ends [m/s]
    bool avoidScene = false;
    double overloadPenalty = 3.0;
    double limitPenalty = 1.0;
    double limitSpeedFraction = 0.5;  ///< a limit hit faster than this × the drive's speed is a bang
    double dropPenalty = 20.0;
};

struct TutorialSpec {
    std::string file;
    std::string id;
    int level = 0;
    LocalText title;
    std::vector<LocalText> intro;  ///< paragraphs
    std::string modelPath, scenePath, profile, demoPath, cameraPath;  ///< as written
    solver::SourcePos modelPos, scenePos, profilePos, demoPos;
    std::vector<int> drives;       ///< enabled drives (joint ids); empty: all
    solver::SourcePos drivesPos;
    struct Set {
        int jointId = 0;
        double value = 0.0;
        solver::SourcePos pos;
    };
    std::vector<Set> initial;
    std::vector<Goal> goals;
    std::vector<Hint> hints;
    std::vector<Worker> workers;
    std::vector<Part> parts;
    Grip grip;
    bool track = false;
    int trackBodyId = 0;
    Eigen::Vector3d trackPoint = Eigen::Vector3d::Zero();
    Scoring scoring;
};

/// Parses tutorial text (no files are read). Problems go to `diags`.
TutorialSpec parseTutorial(const std::string& text, const std::string& file, solver::Diagnostics& diags);

/// A tutorial resolved against its model and scene: ids are tree indices, paths are
/// absolute, the model is compiled. Immutable once made.
struct Tutorial {
    TutorialSpec spec;
    std::string directory;  ///< of the tutorial file
    std::string modelFile, sceneFile, demoFile, cameraFile;  ///< absolute ("" none)
    /// The station profile it runs with: PROFILE's (read when the tutorial was loaded),
    /// else the one Padrob makes for the model.
    StationProfile profile;
    /// The model as compiled once (solver/pipeline.h), and the scene (nullptr: no scene,
    /// or one with errors): the studio draws and runs these, it does not compile again.
    std::shared_ptr<const solver::CompiledModel> compiled;
    std::shared_ptr<const solver::CompiledModel> scene;
    /// Parts of `compiled` and `scene` (sharing their ownership).
    std::shared_ptr<const solver::Model> model;
    std::shared_ptr<const solver::ModelSpec> modelSpec;
    std::shared_ptr<const solver::ModelSpec> sceneSpec;  ///< nullptr: no scene
    std::vector<char> enabled;       ///< per tree joint: its drive is enabled
    std::vector<std::pair<int, double>> initialTheta;  ///< tree joint → θ
    // resolved indices
    int loadBody = -1, toolBody = -1;
    std::vector<int> fingerBodies;
    int trackBody = -1;
    Eigen::Vector3d trackPoint = Eigen::Vector3d::Zero();
    std::vector<int> goalBody;       ///< per goal: tree index (Reach) or −1
    struct Target {
        int joint = -1;  ///< tree index
        double value = 0.0, tolerance = 0.0;  ///< modeler coordinate
    };
    std::vector<std::vector<Target>> goalJoints;  ///< per goal (Joint goals)
    std::vector<Target> gripClose, gripOpen;
    std::vector<std::vector<int>> workerShapes;  ///< per worker: scene G ids that exist

    const Scoring& scoring() const { return spec.scoring; }
    std::string title(const std::string& language) const { return spec.title.in(language); }
};

/// Reads, parses and resolves a tutorial file: its model (and scene) are loaded and
/// compiled; every id, tolerance and text is checked. nullptr when there are errors
/// (all in `diags`, with the model's own when it has errors). Warnings (a demonstration
/// that cannot be read…) leave the tutorial usable.
std::shared_ptr<const Tutorial> loadTutorial(const std::string& path, solver::Diagnostics& diags);
/// The same from text; `file` names it and is the base of its relative paths.
std::shared_ptr<const Tutorial> loadTutorialText(const std::string& text, const std::string& file,
                                                 solver::Diagnostics& diags);

}  // namespace trainer
