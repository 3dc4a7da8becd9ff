// Resolving a tutorial against its model and scene (docs/training.md "Checks").

#include "trainer/training/tutorial.h"

#include "solver/core/text_file.h"
#include "solver/pipeline.h"
#include "solver/parse/lexer.h"
#include "trainer/input/input_log.h"
#include "trainer/training/camera_path.h"
#include "trainer/station/profile.h"
#include "trainer/station/profile_store.h"
#include "trainer/training/reach.h"

#include <QFileInfo>

#include <cmath>
#include <filesystem>
#include <numbers>

namespace trainer {

namespace {

namespace fs = std::filesystem;
using solver::Diagnostics;
using solver::SourcePos;
using solver::Text;
using solver::plainText;
using solver::trText;

constexpr std::uintmax_t kMaxTutorialBytes = 1u << 20;

std::string num(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string resolvePath(const std::string& dir, const std::string& p)
{
    if (p.empty()) return {};
    fs::path path(p);
    if (path.is_relative()) path = fs::path(dir) / path;
    return path.lexically_normal().string();
}

void checkText(const LocalText& t, const Text& what, Diagnostics& d)
{
    for (const std::string& lang : kTutorialLanguages) {
        if (!t.byLanguage.count(lang)) {
            const std::string language = solver::parse::upper(lang);
            d.error("missing-language", t.pos, trText("Tutorials", "%1 has no %2 text").with(what).with(language),
                    trText("Tutorials", "add %1 \"…\": every text is in Spanish and English").with(language));
        }
    }
}

/// The errors of a model (or scene) file, each in its own file, into the tutorial's list.
void copyErrors(const solver::CompiledModel& loaded, const std::string& file, Diagnostics& diags)
{
    for (const solver::Diagnostic& d : loaded.diagnostics) {
        if (d.severity != solver::Severity::Error) continue;
        // keep the translatable form (an English-only diagnostic stays as it is)
        solver::Diagnostic& c = diags.error(d.code, d.pos, d.messageText.empty() ? plainText(d.message) : d.messageText,
                                            d.hintText.empty() ? plainText(d.hint) : d.hintText);
        c.file = d.file.empty() ? file : d.file;
    }
}

/// θ of a modeler coordinate value (T 1: a length), or nullopt when unreachable.
std::optional<double> thetaOf(const solver::Model& m, int j, double value)
{
    if (m.jointType[j] == solver::JointType::Actuator) return m.lengthLaw[j].angle(value);
    return value;
}

}  // namespace

std::shared_ptr<const Tutorial> loadTutorial(const std::string& path, Diagnostics& diags)
{
    diags.setFile(path);
    std::optional<std::string> text =
        solver::readTextFile(path, kMaxTutorialBytes, trText("Tutorials", "a tutorial file"), ".tut",
                             trText("Tutorials", "a tutorial is a short text file; check that this is one"), diags);
    if (!text) return nullptr;
    return loadTutorialText(*text, path, diags);
}

std::shared_ptr<const Tutorial> loadTutorialText(const std::string& text, const std::string& file, Diagnostics& diags)
{
    if (diags.file().empty()) diags.setFile(file);
    auto tut = std::make_shared<Tutorial>();
    tut->spec = parseTutorial(text, file, diags);
    const TutorialSpec& s = tut->spec;
    if (diags.hasErrors()) return nullptr;
    tut->directory = fs::absolute(fs::path(file)).parent_path().string();

    // texts: every one in every language
    checkText(s.title, trText("Tutorials", "the TITLE"), diags);
    if (s.title.empty()) {
        diags.error("missing-statement", {1, 1}, trText("Tutorials", "the tutorial has no TITLE"),
                    trText("Tutorials", "add TITLE ES \"…\" EN \"…\""));
    }
    for (const LocalText& p : s.intro) checkText(p, trText("Tutorials", "this INTRO"), diags);
    for (const Goal& g : s.goals) {
        if (g.name.empty()) {
            diags.error("missing-name", g.pos, trText("Tutorials", "goal '%1' has no NAME").with(g.id),
                        trText("Tutorials", "add a NAME ES \"…\" EN \"…\" line after it: the HUD shows it"));
        } else {
            checkText(g.name, trText("Tutorials", "goal '%1''s NAME").with(g.id), diags);
        }
    }
    for (const Hint& h : s.hints) checkText(h.text, trText("Tutorials", "this HINT"), diags);
    for (const Part& p : s.parts) {
        if (p.name.empty()) {
            diags.error("missing-name", p.pos, trText("Tutorials", "this PART has no NAME"),
                        trText("Tutorials", "add a NAME ES \"…\" EN \"…\" line after it"));
        } else {
            checkText(p.name, trText("Tutorials", "this PART's NAME"), diags);
        }
    }
    for (const Worker& w : s.workers) {
        if (!w.name.empty()) checkText(w.name, trText("Tutorials", "this WORKER's NAME"), diags);
    }

    // the model
    tut->modelFile = resolvePath(tut->directory, s.modelPath);
    auto compiled = std::make_shared<const solver::CompiledModel>(solver::compileFile(tut->modelFile));
    if (!compiled->ok()) {
        copyErrors(*compiled, tut->modelFile, diags);
        diags.error("model-errors", s.modelPos,
                    trText("Tutorials", "the model '%1' cannot be used (errors above)").with(s.modelPath),
                    trText("Tutorials", "fix the model, or check the path: it is relative to the tutorial's folder"));
        return nullptr;
    }
    tut->compiled = compiled;
    tut->model = compiled->model;
    tut->modelSpec = std::shared_ptr<const solver::ModelSpec>(compiled, &compiled->spec);

    // the scene
    if (!s.scenePath.empty()) {
        tut->sceneFile = resolvePath(tut->directory, s.scenePath);
        auto scene = std::make_shared<const solver::CompiledModel>(solver::compileFile(tut->sceneFile));
        if (!scene->ok()) {
            copyErrors(*scene, tut->sceneFile, diags);
            diags.error("scene-errors", s.scenePos,
                        trText("Tutorials", "the scene '%1' cannot be used (errors above)").with(s.scenePath),
                        trText("Tutorials", "fix the scene, or check the path: it is relative to the tutorial's folder"));
        } else {
            tut->scene = scene;
            tut->sceneSpec = std::shared_ptr<const solver::ModelSpec>(scene, &scene->spec);
            if (tut->model->contact) {
                // CONTACT: the machine touches the scene's solids too (docs/contact.md): the
                // model compiled again with them (the same bodies and joints)
                auto touching = std::make_shared<const solver::CompiledModel>(solver::compileSpec(compiled->spec, &scene->spec));
                if (!touching->ok()) {
                    copyErrors(*touching, tut->modelFile, diags);
                    diags.error("scene-errors", s.scenePos,
                                trText("Tutorials", "the scene '%1' cannot be used with the model's CONTACT (errors above)")
                                    .with(s.scenePath),
                                trText("Tutorials", "mark the scene's graphics that the model must not touch NOCONTACT"));
                    return nullptr;
                }
                tut->compiled = touching;
                tut->model = touching->model;
                tut->modelSpec = std::shared_ptr<const solver::ModelSpec>(touching, &touching->spec);
            }
        }
    }
    const solver::Model& m = *tut->model;

    // `keyword`: the statement that names the id (not translated)
    auto body = [&](int id, SourcePos pos, const std::string& keyword) {
        const int b = id == 0 ? -1 : m.bodyIndex(id);
        if (b < 0) {
            diags.error("unknown-body", pos,
                        trText("Tutorials", "%1: the model has no moving body %2")
                            .with(keyword)
                            .with(std::to_string(id)),
                        trText("Tutorials", "use a body id of '%1' (not the ground, 0)").with(s.modelPath));
        }
        return b;
    };
    auto joint = [&](int id, SourcePos pos, const std::string& keyword) {
        const int j = m.jointIndex(id);
        if (j < 0) {
            diags.error("unknown-joint", pos,
                        trText("Tutorials", "%1: the model has no joint %2 in its tree")
                            .with(keyword)
                            .with(std::to_string(id)),
                        trText("Tutorials", "use a joint id (C) of '%1'").with(s.modelPath));
        }
        return j;
    };

    // drives
    tut->enabled.assign(static_cast<std::size_t>(m.nb), s.drives.empty() ? 1 : 0);
    for (int id : s.drives) {
        const int j = joint(id, s.drivesPos, "DRIVES");
        if (j < 0) continue;
        if (m.drive[j].type == solver::DriveType::None) {
            diags.error("not-a-drive", s.drivesPos, trText("Tutorials", "joint %1 has no drive").with(std::to_string(id)),
                        trText("Tutorials", "DRIVES lists joints with a D statement in the model"));
            continue;
        }
        tut->enabled[static_cast<std::size_t>(j)] = 1;
    }
    // the initial state
    for (const TutorialSpec::Set& set : s.initial) {
        const int j = joint(set.jointId, set.pos, "SET");
        if (j < 0) continue;
        const std::optional<double> th = thetaOf(m, j, set.value);
        if (!th) {
            diags.error("out-of-range", set.pos,
                        trText("Tutorials", "joint %1's actuator cannot reach %2")
                            .with(std::to_string(set.jointId))
                            .with(num(set.value)),
                        trText("Tutorials", "give a length the joint's geometry allows"));
            continue;
        }
        if (*th < m.lower[j] - 1e-9 || *th > m.upper[j] + 1e-9) {
            diags.error("out-of-range", set.pos,
                        trText("Tutorials", "joint %1's initial value %2 is beyond its limits")
                            .with(std::to_string(set.jointId))
                            .with(num(set.value)),
                        trText("Tutorials", "give a value between its LL and UL"));
            continue;
        }
        tut->initialTheta.emplace_back(j, *th);
    }
    // the grip
    const Grip& g = s.grip;
    if (g.present) {
        tut->loadBody = body(g.loadBodyId, g.pos, "GRIP LOAD");
        tut->toolBody = body(g.toolBodyId, g.pos, "GRIP TOOL");
        if (tut->loadBody >= 0 && tut->loadBody == tut->toolBody) {
            diags.error("grip-self", g.pos, trText("Tutorials", "the load and the tool are the same body"),
                        trText("Tutorials", "the tool grips another body"));
        }
        if (g.close.empty()) {
            diags.error("missing-statement", g.pos, trText("Tutorials", "GRIP has no CLAW"),
                        trText("Tutorials", "add CLAW joint CLOSE value OPEN value lines after it"));
        }
        auto claws = [&](const std::vector<JointTarget>& list, std::vector<Tutorial::Target>& out) {
            for (const JointTarget& c : list) {
                const int j = joint(c.jointId, c.pos, "CLAW");
                if (j >= 0) out.push_back({j, c.value, 0.0});
            }
        };
        claws(g.close, tut->gripClose);
        claws(g.open, tut->gripOpen);
        for (int id : g.fingerBodyIds) {
            const int b = body(id, g.pos, "FINGERS");
            if (b >= 0) tut->fingerBodies.push_back(b);
        }
        if (tut->toolBody >= 0) tut->fingerBodies.push_back(tut->toolBody);
    }
    // goals
    bool grasped = false;
    for (const Goal& goal : s.goals) {
        tut->goalBody.push_back(-1);
        tut->goalJoints.emplace_back();
        switch (goal.kind) {
        case Goal::Kind::Reach:
            tut->goalBody.back() = body(goal.bodyId, goal.pos, "REACH");
            break;
        case Goal::Kind::Joint:
            if (goal.joints.empty()) {
                diags.error("missing-statement", goal.pos, trText("Tutorials", "goal '%1' has no JOINT line").with(goal.id),
                            trText("Tutorials", "add JOINT id AT value TOL d lines after it"));
            }
            for (const JointTarget& jt : goal.joints) {
                const int j = joint(jt.jointId, jt.pos, "JOINT");
                if (j < 0) continue;
                const std::optional<double> th = thetaOf(m, j, jt.value);
                if (!th || *th < m.lower[j] - 1e-9 || *th > m.upper[j] + 1e-9) {
                    diags.error("unreachable-goal", jt.pos,
                                trText("Tutorials", "joint %1 cannot reach %2: beyond its limits")
                                    .with(std::to_string(jt.jointId))
                                    .with(num(jt.value)),
                                trText("Tutorials", "give a target between the joint's LL and UL"));
                    continue;
                }
                tut->goalJoints.back().push_back({j, jt.value, jt.tolerance});
            }
            break;
        case Goal::Kind::Grasp:
            if (!g.present) {
                diags.error("missing-grip", goal.pos, trText("Tutorials", "a GRASP goal needs a GRIP statement"),
                            trText("Tutorials", "add GRIP LOAD … TOOL … (docs/training.md)"));
            }
            grasped = true;
            break;
        case Goal::Kind::Place:
            if (!g.present) {
                diags.error("missing-grip", goal.pos, trText("Tutorials", "a PLACE goal needs a GRIP statement"),
                            trText("Tutorials", "add GRIP LOAD … TOOL … (docs/training.md)"));
            }
            if (!grasped) {
                diags.error("place-before-grasp", goal.pos,
                            trText("Tutorials", "goal '%1' places the load before any GRASP goal").with(goal.id),
                            trText("Tutorials", "put a GRASP goal before it"));
            }
            grasped = false;
            break;
        }
    }
    // hints name goals that exist
    for (const Hint& h : s.hints) {
        if (h.goal.empty()) continue;
        bool found = false;
        for (const Goal& goal : s.goals) found = found || goal.id == h.goal;
        if (!found) {
            diags.error("unknown-goal", h.text.pos,
                        trText("Tutorials", "HINT names goal '%1', which the tutorial does not have").with(h.goal),
                        trText("Tutorials", "use a GOAL's id"));
        }
    }
    // tracked point
    if (s.track) {
        tut->trackBody = body(s.trackBodyId, {1, 1}, "TRACK");
        tut->trackPoint = s.trackPoint;
    } else if (tut->toolBody >= 0) {
        tut->trackBody = tut->toolBody;
        tut->trackPoint = g.toolPoint;
    } else {
        for (std::size_t k = 0; k < s.goals.size(); ++k) {
            if (tut->goalBody[k] >= 0) {
                tut->trackBody = tut->goalBody[k];
                tut->trackPoint = s.goals[k].point;
                break;
            }
        }
    }
    // workers: their graphics exist in the scene
    for (const Worker& w : s.workers) {
        tut->workerShapes.emplace_back();
        if (!tut->sceneSpec) {
            diags.error("missing-scene", w.pos, trText("Tutorials", "WORKER needs a SCENE with the person's graphics"),
                        trText("Tutorials", "add SCENE \"…\""));
            continue;
        }
        for (int id : w.graphicIds) {
            bool found = false;
            for (const solver::GraphicSpec& gr : tut->sceneSpec->graphics) found = found || gr.id == id;
            if (!found) {
                diags.error("unknown-graphic", w.pos,
                            trText("Tutorials", "the scene has no graphic G %1").with(std::to_string(id)),
                            trText("Tutorials", "use the G ids of the person in the scene file"));
            } else {
                tut->workerShapes.back().push_back(id);
            }
        }
    }
    // parts: their graphics exist (the scene's, or the model's on the ground)
    for (const Part& p : s.parts) {
        const solver::ModelSpec* spec = p.scene ? tut->sceneSpec.get() : tut->modelSpec.get();
        if (!spec) {
            diags.error("missing-scene", p.pos, trText("Tutorials", "PART SCENE needs a SCENE"),
                        trText("Tutorials", "add SCENE \"…\", or write PART MODEL for the model's graphics"));
            continue;
        }
        for (int id : p.graphicIds) {
            bool found = false;
            for (const solver::GraphicSpec& gr : spec->graphics) found = found || (gr.id == id && gr.body == 0);
            if (!found) {
                diags.error("unknown-graphic", p.pos,
                            (p.scene ? trText("Tutorials", "the scene has no ground graphic G %1")
                                     : trText("Tutorials", "the model has no ground graphic G %1"))
                                .with(std::to_string(id)),
                            trText("Tutorials", "use the G ids (on body 0) of the part"));
            }
        }
    }
    // the station profile: a file (relative to the tutorial) or a name of the model's profiles
    {
        const std::string asFile = resolvePath(tut->directory, s.profile);
        const QString which = QString::fromStdString(
            !s.profile.empty() && QFileInfo(QString::fromStdString(asFile)).isFile() ? asFile : s.profile);
        QList<ProfileIssue> issues;
        if (!ProfileStore().resolve(QString::fromStdString(tut->modelFile), which, drivesOf(m), tut->profile, issues)) {
            diags.error("bad-profile", s.profilePos,
                        trText("Tutorials", "the station profile '%1' cannot be used: %2")
                            .with(s.profile)
                            .with(issues.isEmpty() ? std::string() : issues.first().text().toStdString()),
                        trText("Tutorials", "name one of the model's profiles or give a .json file relative to the "
                                            "tutorial"));
        }
    }
    if (diags.hasErrors()) return nullptr;

    // reachability of the REACH goals (after the ids are known to be good)
    for (std::size_t k = 0; k < s.goals.size(); ++k) {
        const Goal& goal = s.goals[k];
        if (goal.kind != Goal::Kind::Reach) continue;
        const ReachCheck r = checkReach(m, tut->enabled, tut->initialTheta, tut->goalBody[k], goal.point, goal.target,
                                        goal.tolerance, goal.align);
        if (!r.reachable) {
            diags.error("unreachable-goal", goal.pos,
                        trText("Tutorials", "goal '%1' cannot be reached with the enabled drives: the nearest pose "
                                            "misses it by %2 m and %3°")
                            .with(goal.id)
                            .with(num(r.positionError))
                            .with(num(r.angleError * 180.0 / std::numbers::pi)),
                        trText("Tutorials", "move the target within reach, enable more DRIVES or widen TOL/ANGTOL"));
        }
    }
    if (diags.hasErrors()) return nullptr;

    // the demonstration: a problem there is a warning (training goes on without it)
    if (!s.demoPath.empty()) {
        tut->demoFile = resolvePath(tut->directory, s.demoPath);
        InputLog log;
        QString error;
        if (!InputLog::load(QString::fromStdString(tut->demoFile), log, &error)) {
            diags.warning("bad-demonstration", s.demoPos,
                          trText("Tutorials", "the demonstration cannot be used: %1").with(error.toStdString()),
                          trText("Tutorials", "record it again (Train ▸ Record demonstration) or fix the path"));
            tut->demoFile.clear();
        }
        if (!s.cameraPath.empty()) {
            tut->cameraFile = resolvePath(tut->directory, s.cameraPath);
            CameraPath camera;
            QString cameraError;
            if (!CameraPath::load(QString::fromStdString(tut->cameraFile), camera, &cameraError)) {
                diags.warning("bad-camera-path", s.demoPos,
                              trText("Tutorials", "the demonstration's camera path cannot be used: %1")
                                  .with(cameraError.toStdString()),
                              trText("Tutorials", "record the demonstration again, or remove CAMERA: the viewer's own "
                                                  "camera is used"));
                tut->cameraFile.clear();
            }
        }
    }
    return tut;
}

}  // namespace trainer
