// Tutorials (issue 7): the file format's diagnostics (where and how to fix), and the
// session's checks against the solver: reaching with a dwell, grasping the 4,500 kg
// liner (and missing it), carrying it, placing and dropping it, hits, hard hits, a
// worker's safety zone, limit bangs, the time limit, and the score.

#include "trainer/training/camera_path.h"
#include "trainer/training/runner.h"
#include "trainer/training/session.h"
#include "solver/kinematics/kinematics.h"
#include "trainer/training/tutorial.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace trainer;

namespace {

const std::string kSource = PADROB_SOURCE_DIR;
const std::string kManipulator = kSource + "/models/liner_manipulator.pad";
const std::string kStation = kSource + "/models/liner_station.pad";

std::string header(const std::string& model, const std::string& extra = {})
{
    return "TUTORIAL X LEVEL 1\n"
           "TITLE ES \"Prueba\" EN \"Test\"\n"
           "MODEL \"" + model + "\"\n" + extra;
}

const char* kReachGoal = "GOAL g REACH BODY 6 POINT 0 0.48 0 AT -2.10 3.08 1.32 TOL 0.15\n"
                         "  DWELL 1\n"
                         "  NAME ES \"Objetivo\" EN \"Target\"\n";

std::shared_ptr<const Tutorial> load(const std::string& text, solver::Diagnostics& d,
                                     const std::string& file = kSource + "/tests/trainer/x.tut")
{
    return loadTutorialText(text, file, d);
}

const solver::Diagnostic* find(const solver::Diagnostics& d, const std::string& code)
{
    for (const solver::Diagnostic& x : d) {
        if (x.code == code) return &x;
    }
    return nullptr;
}

std::string dump(const solver::Diagnostics& d)
{
    std::string s;
    for (const solver::Diagnostic& x : d) s += x.format() + "\n";
    return s;
}

/// Steps `s` with commands `u` (per joint id 1…) for `seconds`.
void drive(TutorialSession& s, std::vector<std::pair<int, double>> u, double seconds)
{
    std::vector<double> cmd(std::size_t(s.tutorial().model->nb), 0.0);
    for (auto [id, v] : u) cmd[std::size_t(s.tutorial().model->jointIndex(id))] = v;
    s.setCommands(cmd);
    s.advanceTo(s.time() + seconds);
}

}  // namespace

TEST(TutorialFile, TheShippedFirstStageLoads)
{
    solver::Diagnostics d;
    auto t = loadTutorial(kSource + "/resources/tutorials/t0_reach.tut", d);
    ASSERT_TRUE(t) << dump(d);
    EXPECT_EQ(t->spec.id, "T0");
    EXPECT_EQ(t->title("es"), "Alcanzar un objetivo");
    EXPECT_EQ(t->title("en"), "Reach a target");
    ASSERT_EQ(t->spec.goals.size(), 1u);
    EXPECT_EQ(t->spec.goals[0].kind, Goal::Kind::Reach);
    EXPECT_FALSE(t->demoFile.empty());
    // only slew, boom lift and extension are enabled
    const solver::Model& m = *t->model;
    for (int id = 1; id <= 9; ++id) EXPECT_EQ(t->enabled[std::size_t(m.jointIndex(id))] != 0, id <= 3) << id;
}

TEST(TutorialFile, ProblemsAreReportedWhereTheyAreWithAHint)
{
    struct Case {
        const char* name;
        std::string text;
        const char* code;
        int line;
    };
    const std::vector<Case> cases = {
        {"unknown statement", header(kManipulator, "GOLA g JOINT\n") + kReachGoal, "unknown-statement", 4},
        {"decimal comma", header(kManipulator, "PASS 60,5\n") + kReachGoal, "expected-number", 4},
        {"missing model", header(kSource + "/models/nope.pad") + kReachGoal, "model-errors", 3},
        {"no goal", header(kManipulator), "missing-statement", 1},
        {"unknown body", header(kManipulator) + "GOAL g REACH BODY 42 POINT 0 0 0 AT 0 3 0 TOL 0.1\n NAME ES \"a\" EN \"b\"\n",
         "unknown-body", 4},
        {"not a drive", header(kStation, "DRIVES 1 12\n") + kReachGoal, "not-a-drive", 4},
        {"unknown joint", header(kManipulator, "SET 77 0\n") + kReachGoal, "unknown-joint", 4},
        {"beyond limits", header(kManipulator, "SET 3 2.5\n") + kReachGoal, "out-of-range", 4},
        {"only Spanish", "TUTORIAL X\nTITLE ES \"Prueba\"\nMODEL \"" + kManipulator + "\"\n" + kReachGoal,
         "missing-language", 2},
        {"goal without name", header(kManipulator) + "GOAL g JOINT\n JOINT 3 AT 0.5 TOL 0.01\n", "missing-name", 4},
        {"ALIGN without goal", header(kManipulator, "ALIGN 0 1 0 WITH 0 0 1 ANGTOL 5 DEG\n") + kReachGoal,
         "misplaced-statement", 4},
        {"weights", header(kManipulator, "WEIGHTS TIME 30 PATH 30 SMOOTH 30 SAFETY 30\n") + kReachGoal, "weights-sum", 4},
        {"par over limit", header(kManipulator, "TIME LIMIT 60 PAR 90\n") + kReachGoal, "out-of-range", 4},
        {"place before grasp",
         header(kStation, "GRIP LOAD 15 AT 0 -0.285 -0.065767 TOOL 6 AT 0 0.48 0 TOL 0.03 ANGTOL 3 DEG\n"
                          "CLAW 9 CLOSE 0.12 OPEN 0.03\n") +
             "GOAL p PLACE AT 0 4 0.5 TOL 0.05\n NAME ES \"a\" EN \"b\"\n",
         "place-before-grasp", 6},
        {"joint goal beyond limits", header(kManipulator) + "GOAL g JOINT\n JOINT 3 AT 1.5 TOL 0.01\n NAME ES \"a\" EN \"b\"\n",
         "unreachable-goal", 5},
        {"unreachable target", header(kManipulator, "DRIVES 1 2 3\n") +
                                   "GOAL g REACH BODY 6 POINT 0 0.48 0 AT -2.1 3.1 4.5 TOL 0.15\n NAME ES \"a\" EN \"b\"\n",
         "unreachable-goal", 5},
        {"worker without scene", header(kManipulator, "WORKER G 1 2 ZONE 1\n") + kReachGoal, "missing-scene", 4},
        {"part without name", header(kManipulator, "PART MODEL G 1\n") + kReachGoal, "missing-name", 4},
        {"part of no graphic", header(kManipulator, "PART MODEL G 999\n NAME ES \"a\" EN \"b\"\n") + kReachGoal,
         "unknown-graphic", 4},
        {"hint for no goal", header(kManipulator, "HINT GOAL zz ES \"a\" EN \"b\"\n") + kReachGoal, "unknown-goal", 4},
    };
    for (const Case& c : cases) {
        solver::Diagnostics d;
        auto t = load(c.text, d);
        EXPECT_FALSE(t) << c.name;
        const solver::Diagnostic* x = find(d, c.code);
        ASSERT_TRUE(x) << c.name << ": expected " << c.code << ", got\n" << dump(d);
        EXPECT_EQ(x->pos.line, c.line) << c.name << ": " << x->format();
        EXPECT_FALSE(x->hint.empty()) << c.name << ": " << x->format();
    }
}

TEST(TutorialFile, NotANumberIsSaidAsSuchAndControlCharactersAreEscaped)
{
    for (const char* bad : {"NaN", "inf", "-Infinity"}) {
        solver::Diagnostics d;
        EXPECT_FALSE(load(header(kManipulator, std::string("PASS ") + bad + "\n") + kReachGoal, d)) << bad;
        const solver::Diagnostic* x = find(d, "expected-number");
        ASSERT_TRUE(x) << dump(d);
        EXPECT_NE(x->message.find("is not a finite number"), std::string::npos) << x->format();
        EXPECT_EQ(x->hint.find("comma"), std::string::npos) << "no decimal comma in " << bad << ": " << x->format();
    }
    {
        solver::Diagnostics d;
        EXPECT_FALSE(load(header(kManipulator, "PASS 60,5\n") + kReachGoal, d));
        const solver::Diagnostic* x = find(d, "expected-number");
        ASSERT_TRUE(x) << dump(d);
        EXPECT_NE(x->hint.find("60.5"), std::string::npos) << x->format();
    }
    {
        // an escape sequence in a quoted token (a pasted terminal control, a corrupt file)
        // is named by its code, never printed raw
        solver::Diagnostics d;
        EXPECT_FALSE(load(header("/nonexistent/\x1b[2Jm\x07.pad") + kReachGoal, d));
        const std::string all = dump(d);
        EXPECT_EQ(all.find('\x1b'), std::string::npos) << all;
        EXPECT_EQ(all.find('\x07'), std::string::npos) << all;
        EXPECT_NE(all.find("unexpected control character (code 27)"), std::string::npos) << all;
    }
}

TEST(TutorialFile, AModelWithErrorsIsReportedInItsOwnFile)
{
    QTemporaryDir dir;
    const QString model = dir.filePath("broken.pad");
    QFile f(model);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("B 1 4,5 1 1 1\nC 1\nB1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0\nB2 1 P2 0 0 0 A2 0 0 1 R2 1 0 0\n");
    f.close();
    solver::Diagnostics d;
    auto t = load(header(model.toStdString()) + kReachGoal, d);
    EXPECT_FALSE(t);
    bool inModel = false;
    for (const solver::Diagnostic& x : d) inModel = inModel || (x.file == model.toStdString() && x.pos.line == 1);
    EXPECT_TRUE(inModel) << dump(d);
    EXPECT_TRUE(find(d, "model-errors"));
}

TEST(TutorialFile, ACorruptDemonstrationIsAWarningAndTheTutorialStillLoads)
{
    QTemporaryDir dir;
    QFile f(dir.filePath("demo.log"));
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("# padrob input log 1\n#device 0 {\"id\":\nthis is not a log\n");
    f.close();
    solver::Diagnostics d;
    auto t = load(header(kManipulator, "DEMO \"demo.log\"\n") + kReachGoal, d, dir.filePath("t.tut").toStdString());
    ASSERT_TRUE(t) << dump(d);
    EXPECT_TRUE(t->demoFile.empty());
    const solver::Diagnostic* x = find(d, "bad-demonstration");
    ASSERT_TRUE(x) << dump(d);
    EXPECT_EQ(x->severity, solver::Severity::Warning);
    EXPECT_EQ(x->pos.line, 4);
}

TEST(TutorialSession, AReachGoalNeedsItsDwellAndTheScoreFollowsTheRun)
{
    solver::Diagnostics d;
    auto t = load(header(kManipulator, "DRIVES 1 2 3\nTIME LIMIT 60 PAR 30\n") + kReachGoal, d);
    ASSERT_TRUE(t) << dump(d);
    TutorialSession s(t);
    // slew left, lift, extend: the joint targets of the point (-2.11, 3.09, 1.32)
    drive(s, {{1, 1.0}}, 0.6 / 0.131);
    drive(s, {{2, 1.0}}, (1.52 - 1.464) / 0.0180);
    EXPECT_EQ(s.progress().goal, 0);
    double entered = -1;
    for (int k = 0; k < 800 && !s.ended(); ++k) {
        drive(s, {{3, 1.0}}, 0.01);
        if (entered < 0 && s.progress().withinTolerance) entered = s.time();
        // the running score (what the stations publish) is the result's, at every moment
        if (k % 50 == 0) {
            ASSERT_EQ(s.score(), s.result().score) << "at t = " << s.time();
        }
    }
    ASSERT_GT(entered, 0);
    ASSERT_TRUE(s.ended());
    // done after being held within tolerance for its DWELL (1 s), not before
    EXPECT_NEAR(s.result().events.back().t - entered, 1.0, 0.011);
    ASSERT_TRUE(s.ended());
    const TutorialResult r = s.result();
    EXPECT_TRUE(r.completed);
    EXPECT_TRUE(r.passed);
    EXPECT_EQ(r.endReason, "completed");
    ASSERT_EQ(r.breakdown.size(), 4u);
    EXPECT_DOUBLE_EQ(r.breakdown[0].points, r.breakdown[0].max);  // under par
    EXPECT_GT(r.breakdown[1].value, 60.0);                        // one joint at a time: not straight
    EXPECT_LT(r.breakdown[1].value, 100.0);
    EXPECT_DOUBLE_EQ(r.breakdown[3].points, r.breakdown[3].max);  // no penalty
    EXPECT_GE(r.stars, 1);
    double sum = 0;
    for (const ScoreItem& i : r.breakdown) sum += i.points;
    EXPECT_NEAR(r.score, sum, 1e-9);
    EXPECT_EQ(s.score(), r.score);
}

TEST(TutorialSession, DisabledDrivesStayClosed)
{
    solver::Diagnostics d;
    auto t = load(header(kManipulator, "DRIVES 1 2 3\n") + kReachGoal, d);
    ASSERT_TRUE(t) << dump(d);
    TutorialSession s(t);
    const solver::Model& m = *t->model;
    const double wrist0 = s.simulation().state().q[m.jointIndex(4)];
    drive(s, {{4, 1.0}, {6, 1.0}}, 1.0);
    EXPECT_NEAR(s.simulation().state().q[m.jointIndex(4)], wrist0, 1e-9);
}

TEST(TutorialSession, LimitBangsAndTheTimeLimit)
{
    solver::Diagnostics d;
    auto t = load(header(kManipulator, "TIME LIMIT 12 PAR 6\nLIMITS PENALTY 2 SPEED 0.5\n") + kReachGoal, d);
    ASSERT_TRUE(t) << dump(d);
    TutorialSession s(t);
    drive(s, {{3, 1.0}}, 11.0);  // the extension runs into its end stop at full speed
    TutorialResult r = s.result();
    ASSERT_EQ(r.count(TutorialEvent::Kind::LimitBang), 1);
    EXPECT_NEAR(r.events.front().t, 10.0 + 0.0, 0.1);  // 0.9 m at 0.090 m/s
    EXPECT_DOUBLE_EQ(r.penalties, 2.0);
    drive(s, {{3, -0.2}}, 0.5);  // backing off slowly: no bang
    drive(s, {{3, 0.3}}, 2.0);   // slowly back onto the stop: no bang either
    EXPECT_TRUE(s.ended());
    r = s.result();
    EXPECT_EQ(r.count(TutorialEvent::Kind::LimitBang), 1);
    EXPECT_EQ(r.endReason, "time-up");
    EXPECT_FALSE(r.passed);
    EXPECT_EQ(r.breakdown[0].points, 0.0);
}

namespace {

/// liner_station at the pose where the open claws surround the liner's near edge
/// (models/liner_station.pad "GRASPING IT ON THE CART").
std::string graspStation(const std::string& goals, const std::string& extra = {})
{
    return header(kStation,
                  "SET 1 -90 DEG\nSET 2 1.46095\nSET 3 0.45\nSET 5 0.413\n"
                  "GRIP LOAD 15 AT 0 -0.285 -0.065767 TOOL 6 AT 0 0.48 0 TOL 0.03 ANGTOL 3 DEG\n"
                  "CLAW 8 CLOSE -0.12 OPEN -0.03\n"
                  "CLAW 9 CLOSE 0.12 OPEN 0.03\n"
                  "FINGERS 7 8 9\n" + extra) +
           goals;
}

/// On liner_station: take the liner, then lift it.
std::shared_ptr<const Tutorial> takeAndLift(solver::Diagnostics& d)
{
    return load(graspStation("GOAL take GRASP\n NAME ES \"Tome la lainera\" EN \"Take the liner\"\n"
                             "GOAL up PLACE AT 4.1378 0 0.5 TOL 0.1\n NAME ES \"Súbala\" EN \"Lift it\"\n"),
                d);
}

}  // namespace

TEST(TutorialSession, ClosingTheClawsOnTheGripGraspsTheLinerWhichThenRisesWithTheArm)
{
    solver::Diagnostics d;
    auto t = takeAndLift(d);
    ASSERT_TRUE(t) << dump(d);
    TutorialSession s(t);
    const solver::Model& m = *t->model;
    const int z = m.jointIndex(12);
    const int lift = m.jointIndex(2);
    drive(s, {}, 0.2);
    const double forceBefore = s.simulation().data().driveForce[lift];
    drive(s, {{8, -1.0}, {9, 1.0}}, 5.0);  // claws close (0.15 m at their speed)
    ASSERT_EQ(s.result().count(TutorialEvent::Kind::Grasp), 1) << s.result().events.size();
    EXPECT_EQ(s.progress().goal, 1);
    EXPECT_TRUE(s.progress().grasped);
    const double z0 = s.simulation().state().q[z];
    drive(s, {{2, 1.0}}, 3.0);  // lift the boom
    const double z1 = s.simulation().state().q[z];
    EXPECT_GT(z1, z0 + 0.1);
    // the boom cylinder now carries the liner: its weight's moment (~820 kN, see
    // models/liner_station.pad "CHECKED") on top of the arm's
    EXPECT_GT(s.simulation().data().driveForce[lift] - forceBefore, 6e5);
    // held there until within tolerance of the target, then released: placed
    EXPECT_FALSE(s.ended());
}

namespace {

const ScoreItem& item(const TutorialResult& r, const std::string& key)
{
    for (const ScoreItem& i : r.breakdown)
        if (i.key == key) return i;
    static const ScoreItem none;
    ADD_FAILURE() << "no score item " << key;
    return none;
}

/// Path, smoothness and safety of `r` are their quality × weight × the work done (closed form).
void expectEarnedInProportion(const TutorialResult& r, const Scoring& sc, double work)
{
    EXPECT_NEAR(r.work, work, 1e-12);
    const double efficiency = item(r, "path").value / 100.0;
    EXPECT_NEAR(item(r, "path").points, sc.wPath * efficiency * work, 1e-9);
    EXPECT_NEAR(item(r, "smooth").points, sc.wSmooth * std::clamp(1.0 - r.rmsJerk / sc.jerkReference, 0.0, 1.0) * work,
                1e-9);
    EXPECT_NEAR(item(r, "safety").points, sc.wSafety * std::max(0.0, 1.0 - r.penalties / sc.wSafety) * work, 1e-9);
    for (const char* key : {"path", "smooth", "safety"}) EXPECT_NEAR(item(r, key).earnable, item(r, key).max * work, 1e-9);
    EXPECT_EQ(item(r, "time").points, 0.0);  // not complete
    EXPECT_EQ(item(r, "time").earnable, 0.0);
}

}  // namespace

TEST(TutorialSession, AnAttemptStoppedBeforeAnythingMovedScoresNothingAndIsNotToldToWorkFaster)
{
    solver::Diagnostics d;
    auto t = load(header(kManipulator, "DRIVES 1 2 3\nTIME LIMIT 60 PAR 30\n") + kReachGoal, d);
    ASSERT_TRUE(t) << dump(d);
    TutorialSession s(t);
    drive(s, {}, 2.0);  // no lever touched
    s.stop(TutorialEvent::Kind::Aborted);
    const TutorialResult r = s.result();
    EXPECT_EQ(r.endReason, "aborted");
    expectEarnedInProportion(r, t->scoring(), 0.0);
    EXPECT_EQ(r.score, 0.0);  // was 50: smoothness 15 and safety 35 of nothing
    EXPECT_EQ(s.score(), 0.0);
    EXPECT_EQ(item(r, "path").value, 0.0);  // no "Path 100 %" for a path never taken
    const QStringList advice = r.improvements();
    ASSERT_EQ(advice.size(), 1) << advice.join(" | ").toStdString();
    EXPECT_TRUE(advice[0].startsWith("Nothing was done towards the goals")) << advice[0].toStdString();
    for (const ScoreItem& i : r.breakdown) EXPECT_TRUE(i.advice().isEmpty()) << i.key;  // not "Work faster"
}

TEST(TutorialSession, HalfTheGoalsDoneEarnHalfThePathSmoothnessAndSafety)
{
    solver::Diagnostics d;
    auto t = takeAndLift(d);
    ASSERT_TRUE(t) << dump(d);
    TutorialSession s(t);
    std::vector<double> cmd(std::size_t(t->model->nb), 0.0);
    cmd[std::size_t(t->model->jointIndex(8))] = -1.0;
    cmd[std::size_t(t->model->jointIndex(9))] = 1.0;
    s.setCommands(cmd);
    // stopped in the very step the grasp is done: the second goal has not begun to be worked on
    while (s.progress().goal < 1 && s.time() < 6.0) s.step();
    ASSERT_EQ(s.progress().goal, 1);
    s.stop(TutorialEvent::Kind::Aborted);
    const TutorialResult r = s.result();
    expectEarnedInProportion(r, t->scoring(), 0.5);
    EXPECT_GT(r.score, 0.0);
    EXPECT_NEAR(s.score(), r.score, 1e-12);
    EXPECT_TRUE(r.improvements().value(0).startsWith("Complete every goal")) << r.improvements().join(" | ").toStdString();
}

TEST(TutorialSession, TheWayMadeTowardsTheGoalUnderWayCountsAsWorkAndTheHudKnowsTheAngleError)
{
    solver::Diagnostics d;
    // the reach goal of T1 with its ALIGN: the head must point like the arrow
    const char* aligned = "GOAL g REACH BODY 6 POINT 0 0.48 0 AT -2.10 3.08 1.32 TOL 0.15\n"
                          "  ALIGN 0 1 0 WITH -0.575 0.589 -0.567 ANGTOL 8 DEG\n"
                          "  DWELL 1\n"
                          "  NAME ES \"Objetivo\" EN \"Target\"\n";
    auto t = load(header(kManipulator, "DRIVES 1 2 3 4 5\nTIME LIMIT 60 PAR 30\n") + aligned, d);
    ASSERT_TRUE(t) << dump(d);
    TutorialSession s(t);
    s.step();
    const double d0 = s.progress().distance;
    ASSERT_GT(d0, 0.5);
    // the HUD's angle error: the head's axis against the arrow, with its tolerance
    const solver::Data& data = s.simulation().data();
    const Eigen::Vector3d head = data.X_wb[std::size_t(t->model->bodyIndex(6))].linear() * Eigen::Vector3d::UnitY();
    const double expected = std::acos(std::clamp(head.dot(Eigen::Vector3d(-0.575, 0.589, -0.567).normalized()), -1.0, 1.0));
    EXPECT_NEAR(s.progress().angleError, expected, 1e-6);
    EXPECT_NEAR(s.progress().angleTolerance, 8.0 * std::numbers::pi / 180.0, 1e-12);
    EXPECT_FALSE(s.progress().positioned);
    // slew towards the target: part of the way
    drive(s, {{1, 1.0}}, 0.6 / 0.131);
    const double dNow = s.progress().distance;
    ASSERT_LT(dNow, d0);
    s.stop(TutorialEvent::Kind::Aborted);
    const TutorialResult r = s.result();
    // the way made past the first centimetre, over the way to the tolerance
    expectEarnedInProportion(r, t->scoring(), (d0 - dNow - 0.01) / (d0 - 0.15 - 0.01));
}

TEST(TutorialSession, ClawsClosedAwayFromTheGripMissAndReleasingOutOfPlaceIsADrop)
{
    solver::Diagnostics d;
    auto t = load(graspStation("GOAL take GRASP\n NAME ES \"Tome la lainera\" EN \"Take the liner\"\n"
                               "GOAL put PLACE AT 4.1378 0 1.2 TOL 0.05\n NAME ES \"Póngala\" EN \"Put it\"\n",
                               "DROP PENALTY 20\n"),
                  d);
    ASSERT_TRUE(t) << dump(d);
    {
        TutorialSession s(t);
        drive(s, {{3, -1.0}}, 1.5);  // pull the claws back off the liner's edge
        drive(s, {{8, -1.0}, {9, 1.0}}, 5.0);
        const TutorialResult r = s.result();
        EXPECT_EQ(r.count(TutorialEvent::Kind::Grasp), 0);
        EXPECT_EQ(r.count(TutorialEvent::Kind::MissedGrasp), 1);
        EXPECT_FALSE(s.progress().grasped);
    }
    TutorialSession s(t);
    drive(s, {{8, -1.0}, {9, 1.0}}, 5.0);
    ASSERT_TRUE(s.progress().grasped);
    drive(s, {{2, 1.0}}, 2.0);
    const double high = s.simulation().state().q[t->model->jointIndex(12)];
    drive(s, {{8, 1.0}, {9, -1.0}}, 5.0);  // open the claws in the air
    const TutorialResult r = s.result();
    EXPECT_EQ(r.count(TutorialEvent::Kind::Release), 1);
    ASSERT_EQ(r.count(TutorialEvent::Kind::Drop), 1);
    EXPECT_DOUBLE_EQ(r.penalties, 20.0);
    EXPECT_FALSE(s.progress().grasped);
    drive(s, {}, 1.0);
    EXPECT_NEAR(s.simulation().state().q[t->model->jointIndex(12)], 0.228, 1e-6) << "fell from " << high;
}

TEST(TutorialSession, ReleasedWithinToleranceIsPlacedAndFixed)
{
    solver::Diagnostics d;
    // grasp, lift for 2 s: the liner then sits where the PLACE target says
    auto probe = load(graspStation("GOAL take GRASP\n NAME ES \"a\" EN \"b\"\n"), d);
    ASSERT_TRUE(probe) << dump(d);
    Eigen::Vector3d where;
    {
        TutorialSession s(probe);
        drive(s, {{8, -1.0}, {9, 1.0}}, 5.0);
        ASSERT_TRUE(s.ended());
    }
    {
        auto t2 = load(graspStation("GOAL take GRASP\n NAME ES \"a\" EN \"b\"\nGOAL hold JOINT\n JOINT 7 AT 0.2 TOL 0.001\n NAME ES \"c\" EN \"d\"\n"), d);
        ASSERT_TRUE(t2) << dump(d);
        TutorialSession s(t2);
        drive(s, {{8, -1.0}, {9, 1.0}}, 5.0);
        drive(s, {{2, 1.0}}, 2.0);
        where = solver::comPosition(*t2->model, s.simulation().data(), t2->model->bodyIndex(15));
    }
    char place[160];
    std::snprintf(place, sizeof place, "GOAL put PLACE AT %.6f %.6f %.6f TOL 0.05 FIX\n NAME ES \"Póngala\" EN \"Put it\"\n",
                  where.x(), where.y(), where.z());
    auto t = load(graspStation(std::string("GOAL take GRASP\n NAME ES \"a\" EN \"b\"\n") + place), d);
    ASSERT_TRUE(t) << dump(d);
    TutorialSession s(t);
    drive(s, {{8, -1.0}, {9, 1.0}}, 5.0);
    drive(s, {{2, 1.0}}, 2.0);
    EXPECT_TRUE(s.progress().withinTolerance) << s.progress().distance;
    drive(s, {{8, 1.0}, {9, -1.0}}, 5.0);
    ASSERT_TRUE(s.ended());
    const TutorialResult r = s.result();
    EXPECT_TRUE(r.completed);
    EXPECT_EQ(r.count(TutorialEvent::Kind::Drop), 0);
    // bolted: the liner stays where it was released
    const Eigen::Vector3d after = solver::comPosition(*t->model, s.simulation().data(), t->model->bodyIndex(15));
    EXPECT_LT((after - where).norm(), 0.05);
}

namespace {

/// A yard with a wall in front of the claws and a person to the right of the arm.
std::string yard(QTemporaryDir& dir)
{
    const QString scene = dir.filePath("yard.pad");
    QFile f(scene);
    f.open(QIODevice::WriteOnly);
    f.write("G 1 B 0 BOX 0.6 0.2 0.8 POS 0 4.3 0.21 COLOR 0.8 0.2 0.2\n"
            "G 2 B 0 CYL 0.2 1.75 POS 1.6 3.0 -0.2 COLOR 0.9 0.6 0.1\n"
            "G 3 B 0 SPHERE 0.12 POS 1.6 3.0 0.8 COLOR 0.9 0.9 0.1\n");
    return scene.toStdString();
}

}  // namespace

TEST(TutorialSession, TouchingTheSceneIsAHitAndTooFastItEndsTheAttempt)
{
    QTemporaryDir dir;
    const std::string scene = yard(dir);
    for (double hard : {0.5, 0.05}) {
        solver::Diagnostics d;
        auto t = load(header(kManipulator, "SCENE \"" + scene + "\"\nAVOID SCENE PENALTY 5 NEAR 0.1 HARD " + std::to_string(hard) + "\n") + kReachGoal, d);
        ASSERT_TRUE(t) << dump(d);
        TutorialSession s(t);
        drive(s, {{3, 1.0}}, 8.5);  // extend into the wall at 0.09 m/s (the end stop is at 10 s)
        const TutorialResult r = s.result();
        EXPECT_EQ(r.count(TutorialEvent::Kind::NearMiss), 1);
        if (hard > 0.09) {
            ASSERT_EQ(r.count(TutorialEvent::Kind::Hit), 1) << hard;
            EXPECT_DOUBLE_EQ(r.penalties, 5.0);
            EXPECT_FALSE(s.ended());
            EXPECT_LE(s.progress().clearance, 0.0);
        } else {
            ASSERT_EQ(r.count(TutorialEvent::Kind::HardHit), 1) << hard;
            EXPECT_TRUE(s.ended());
            EXPECT_EQ(r.endReason, "hard-hit");
            EXPECT_FALSE(r.passed);
        }
        const TutorialEvent& e = r.events.back();
        EXPECT_NEAR(e.value, 0.09, 0.02);  // the speed of the touching point
    }
}

// CONTACT: the tutorial's model touches its scene's solids too (a box resting on the
// scene's slab stays there; without the scene's solids it would fall through)
TEST(TutorialSession, AModelWithContactTouchesItsScene)
{
    QTemporaryDir dir;
    const QString model = dir.filePath("box.pad"), scene = dir.filePath("slab.pad");
    QFile m(model), sc(scene);
    ASSERT_TRUE(m.open(QIODevice::WriteOnly) && sc.open(QIODevice::WriteOnly));
    // a driven slider (the tutorial's goal) and a free box beside it
    m.write("GRAVITY 0 0 -9.81\nCONTACT\nB 1 50 2 2 2 NAME \"box\"\nB 2 10 1 1 1 NAME \"slider\"\nC 1 T 3\n"
            "B1 0 P1 0 0 0.25 A1 1 0 0 R1 0 1 0\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 1 0\n"
            "G 1 B 1 BOX 0.5 0.5 0.5\n"
            "C 2 T 2 LL 0 UL 1\nB1 0 P1 0 2 1 A1 0 0 1 R1 1 0 0\nB2 2 P2 0 0 0 A2 0 0 1 R2 1 0 0\n"
            "D 2 HYD VMAX 0.5 VMIN 0.5\n");
    sc.write("G 1 B 0 BOX 4 4 0.2 POS 0 0 -0.1 COLOR 0.5 0.5 0.5\n");
    m.close();
    sc.close();
    const std::string goal = "GOAL g REACH BODY 2 POINT 0 0 0 AT 0.5 2 1 TOL 0.1\n  DWELL 5\n"
                             "  NAME ES \"Objetivo\" EN \"Target\"\n";
    for (const bool withScene : {true, false}) {
        solver::Diagnostics d;
        auto t = load(header(model.toStdString(), withScene ? "SCENE \"" + scene.toStdString() + "\"\n" : "") + goal, d);
        ASSERT_TRUE(t) << dump(d);
        ASSERT_TRUE(t->model->contact);
        TutorialSession s(t);
        drive(s, {}, 1.0);
        const double z = s.simulation().data().X_wb[std::size_t(t->model->bodyIndex(1))].translation().z();
        if (withScene) {
            EXPECT_NEAR(z, 0.25, 1e-3);  // resting on the slab
        } else {
            EXPECT_LT(z, -4.0);  // nothing under it: free fall, ½ g t²
        }
    }
}

TEST(TutorialSession, ATakenLoadCountsAgainstTheSceneOnceItHasComeClearOfItsCart)
{
    // the fluid machine lifts the liner only once its boom's oil has built the holding
    // pressure: until then the liner still lies on the cart's timbers, and that is no hit
    solver::Diagnostics d;
    const std::string text = "TUTORIAL X LEVEL 1\nTITLE ES \"Prueba\" EN \"Test\"\n"
                             "MODEL \"" + kSource + "/models/liner_station_fluid.pad\"\n"
                             "SET 1 -90 DEG\nSET 2 1.46095\nSET 3 0.45\nSET 5 0.413\n"
                             "AVOID SCENE PENALTY 5 NEAR 0.05 HARD 0.3\n"
                             "GRIP LOAD 15 AT 0 -0.285 -0.065767 TOOL 6 AT 0 0.48 0 TOL 0.03 ANGTOL 3 DEG\n"
                             "CLAW 8 CLOSE -0.12 OPEN -0.03\nCLAW 9 CLOSE 0.12 OPEN 0.03\nFINGERS 7 8 9\n"
                             "GOAL take GRASP\n NAME ES \"Tome\" EN \"Take\"\n"
                             "GOAL up PLACE AT 4.1378 0 3.5 TOL 0.1\n NAME ES \"Suba\" EN \"Up\"\n";
    auto t = load(text, d);
    ASSERT_TRUE(t) << dump(d);
    TutorialSession s(t);
    // the liner is a free body there: its height is its centre of mass's
    auto z = [&] { return solver::comPosition(*t->model, s.simulation().data(), t->model->bodyIndex(15)).z(); };
    drive(s, {{8, -1.0}, {9, 1.0}}, 8.0);  // the claws shut on the liner's edge
    ASSERT_EQ(s.result().count(TutorialEvent::Kind::Grasp), 1) << s.result().events.size();
    const double z0 = z();
    drive(s, {{2, 0.06}}, 6.0);  // the boom, gently, until the liner is off the timbers
    EXPECT_GT(z(), z0 + 0.01);
    EXPECT_EQ(s.result().count(TutorialEvent::Kind::Hit), 0) << "taking the liner is not a hit";
    EXPECT_GT(s.progress().clearance, 0.0);
    // once clear, the liner counts: set back down on the cart, it touches it
    drive(s, {{2, -0.03}}, 12.0);
    EXPECT_LT(z(), z0 + 0.005);
    EXPECT_EQ(s.result().count(TutorialEvent::Kind::Hit), 1);
}

TEST(TutorialSession, UnderContactAReleasedLinerIsJudgedWhereItComesToRest)
{
    // liner_station_fluid: the liner is a free body under CONTACT. Taken, lifted off its
    // timbers and let go, it falls back onto them; the PLACE goal is decided once it rests
    auto text = [](const std::string& place) {
        return "TUTORIAL X LEVEL 1\nTITLE ES \"Prueba\" EN \"Test\"\n"
               "MODEL \"" + kSource + "/models/liner_station_fluid.pad\"\n"
               "SET 1 -90 DEG\nSET 2 1.46095\nSET 3 0.45\nSET 5 0.413\nDROP PENALTY 20\n"
               "GRIP LOAD 15 AT 0 -0.285 -0.065767 TOOL 6 AT 0 0.48 0 TOL 0.03 ANGTOL 3 DEG\n"
               "CLAW 8 CLOSE -0.12 OPEN -0.03\nCLAW 9 CLOSE 0.12 OPEN 0.03\nFINGERS 7 8 9\n"
               "GOAL take GRASP\n NAME ES \"Tome\" EN \"Take\"\n"
               "GOAL put PLACE AT " + place + "\n NAME ES \"Póngala\" EN \"Put it\"\n";
    };
    const Eigen::Vector3d onCart(4.137788, 0, 0.228);
    for (const bool onItsPlace : {true, false}) {
        solver::Diagnostics d;
        // its place: where it lay, on the cart (FIX: bolted there); elsewhere: 1 m up
        auto t = load(text(onItsPlace ? "4.137788 0 0.228 TOL 0.02 FIX" : "4.137788 0 1.228 TOL 0.02"), d);
        ASSERT_TRUE(t) << dump(d);
        ASSERT_TRUE(t->model->contact);
        TutorialSession s(t);
        const int liner = t->model->bodyIndex(15);
        auto com = [&] { return solver::comPosition(*t->model, s.simulation().data(), liner); };
        drive(s, {{8, -1.0}, {9, 1.0}}, 8.0);
        ASSERT_TRUE(s.progress().grasped);
        drive(s, {{2, 0.06}}, 6.0);  // off the timbers
        ASSERT_GT(com().z(), onCart.z() + 0.01);
        // the claws open: released in the air
        for (int k = 0; k < 600 && s.result().count(TutorialEvent::Kind::Release) == 0; ++k) {
            drive(s, {{8, 1.0}, {9, -1.0}}, 0.01);
        }
        TutorialResult r = s.result();
        ASSERT_EQ(r.count(TutorialEvent::Kind::Release), 1);
        EXPECT_GT(com().z(), onCart.z() + 0.005) << "let go above its timbers";
        EXPECT_EQ(r.count(TutorialEvent::Kind::Drop), 0) << "not judged while it falls";
        EXPECT_FALSE(r.completed);
        drive(s, {{8, 1.0}, {9, -1.0}}, 4.0);
        r = s.result();
        EXPECT_NEAR(com().z(), onCart.z(), 2e-3) << "fallen back onto its timbers";
        if (onItsPlace) {
            ASSERT_TRUE(s.ended());
            EXPECT_TRUE(r.completed);
            EXPECT_EQ(r.count(TutorialEvent::Kind::Drop), 0);
            EXPECT_EQ(s.simulation().state().welds.size(), 1u) << "bolted once at rest";
        } else {
            EXPECT_FALSE(s.ended());
            ASSERT_EQ(r.count(TutorialEvent::Kind::Drop), 1) << "at rest out of place";
            const auto drop = std::find_if(r.events.begin(), r.events.end(),
                                           [](const TutorialEvent& e) { return e.kind == TutorialEvent::Kind::Drop; });
            EXPECT_DOUBLE_EQ(drop->penalty, 20.0);
            const auto release = std::find_if(r.events.begin(), r.events.end(), [](const TutorialEvent& e) {
                return e.kind == TutorialEvent::Kind::Release;
            });
            EXPECT_GE(drop->t, release->t + 0.5) << "judged once it has rested 0.5 s, not at the release";
        }
    }
}

TEST(TutorialSession, EnteringAWorkersZoneIsAPenaltyAndTouchingThemEndsTheAttempt)
{
    QTemporaryDir dir;
    const std::string scene = yard(dir);
    solver::Diagnostics d;
    auto t = load(header(kManipulator, "SCENE \"" + scene + "\"\nWORKER G 2 3 ZONE 1.0 PENALTY 10\n NAME ES \"el mecánico\" EN \"the fitter\"\n") +
                      kReachGoal,
                  d);
    ASSERT_TRUE(t) << dump(d);
    TutorialSession s(t);
    drive(s, {}, 0.1);
    EXPECT_GT(s.progress().workerDistance, 1.0);
    EXPECT_FALSE(s.progress().nearWorker);
    drive(s, {{1, -1.0}}, 2.0);  // slew right, towards the person
    EXPECT_TRUE(s.progress().nearWorker) << s.progress().workerDistance;
    TutorialResult r = s.result();
    ASSERT_EQ(r.count(TutorialEvent::Kind::WorkerZone), 1);
    EXPECT_EQ(r.events.back().detail, "the fitter");
    drive(s, {{1, -1.0}}, 6.0);
    r = s.result();
    EXPECT_TRUE(s.ended());
    EXPECT_EQ(r.endReason, "worker-hit");
    EXPECT_FALSE(r.passed);
}

TEST(TutorialRun, TheDemonstrationPassesAndACarelessRunFailsWithItsPenalties)
{
    solver::Diagnostics d;
    auto t = loadTutorial(kSource + "/resources/tutorials/t0_reach.tut", d);
    ASSERT_TRUE(t) << dump(d);
    StationProfile profile;
    QString error;
    ASSERT_TRUE(tutorialProfile(*t, {}, profile, &error)) << error.toStdString();
    auto log = std::make_shared<InputLog>();
    ASSERT_TRUE(InputLog::load(QString::fromStdString(t->demoFile), *log, &error)) << error.toStdString();
    RunOutput out;
    ASSERT_TRUE(runTutorialWithLog(t, log, profile, out, &error)) << error.toStdString();
    EXPECT_TRUE(out.result.passed);
    EXPECT_GE(out.result.score, t->scoring().pass);
    EXPECT_FALSE(out.samples.empty());

    // careless: the extension slammed into its end stop, the boom never lifted
    QTemporaryDir dir;
    std::vector<AutopilotWaypoint> path;
    ASSERT_TRUE(parseAutopilotPath("3=1.2\n", path, &error));
    RunOutput careless;
    ASSERT_TRUE(recordWithAutopilot(t, path, profile, dir.filePath("careless.log"), careless, &error)) << error.toStdString();
    auto clog = std::make_shared<InputLog>();
    ASSERT_TRUE(InputLog::load(dir.filePath("careless.log"), *clog, &error));
    RunOutput replay;
    ASSERT_TRUE(runTutorialWithLog(t, clog, profile, replay, &error));
    EXPECT_FALSE(replay.result.passed);
    EXPECT_EQ(replay.result.count(TutorialEvent::Kind::LimitBang), 1);
    EXPECT_FALSE(replay.result.completed);

    // the same target pushed for with stall=: the extension stops on its end stop short
    // of 1.2 m, and once it has stood there 0.5 s the waypoint is reached and the path
    // ends, where the careless run waits for it until the time limit
    ASSERT_TRUE(parseAutopilotPath("3=1.2 stall=0.5\n", path, &error)) << error.toStdString();
    RunOutput pushed;
    ASSERT_TRUE(recordWithAutopilot(t, path, profile, dir.filePath("pushed.log"), pushed, &error)) << error.toStdString();
    EXPECT_GT(careless.result.time, 100.0);
    EXPECT_LT(pushed.result.time, 20.0);
}

TEST(Autopilot, PathsAreCheckedLineByLine)
{
    std::vector<AutopilotWaypoint> p;
    QString error;
    ASSERT_TRUE(parseAutopilotPath("# comment\n1=-90deg 2=1.5 tol=0.01\n\nwait=2\n", p, &error));
    ASSERT_EQ(p.size(), 2u);
    EXPECT_NEAR(p[0].targets[0].second, -std::numbers::pi / 2, 1e-12);
    EXPECT_DOUBLE_EQ(p[0].tolerance, 0.01);
    EXPECT_DOUBLE_EQ(p[1].wait, 2.0);
    EXPECT_EQ(p[1].line, 4);
    EXPECT_FALSE(parseAutopilotPath("1=0.5\n2=abc\n", p, &error));
    EXPECT_TRUE(error.startsWith("line 2")) << error.toStdString();
    EXPECT_FALSE(parseAutopilotPath("wait=-1\n", p, &error));
    EXPECT_FALSE(parseAutopilotPath("x=1\n", p, &error));
    // gentle moves: a lever cap for all, or for one joint, and a slower lever ramp
    ASSERT_TRUE(parseAutopilotPath("2=1.5 1=0.3 lever=0.5 lever=2:0.02 ramp=3\n", p, &error)) << error.toStdString();
    ASSERT_EQ(p.size(), 1u);
    EXPECT_DOUBLE_EQ(p[0].lever, 0.5);
    ASSERT_EQ(p[0].jointLever.size(), 1u);
    EXPECT_EQ(p[0].jointLever[0].first, 2);
    EXPECT_DOUBLE_EQ(p[0].jointLever[0].second, 0.02);
    EXPECT_DOUBLE_EQ(p[0].ramp, 3.0);
    EXPECT_FALSE(parseAutopilotPath("2=1.5 lever=0\n", p, &error));
    EXPECT_FALSE(parseAutopilotPath("2=1.5 lever=1.5\n", p, &error));
    EXPECT_FALSE(parseAutopilotPath("2=1.5 lever=x:0.1\n", p, &error));
    EXPECT_FALSE(parseAutopilotPath("2=1.5 ramp=0\n", p, &error));
    // a push: also reached once the joints have stood still that long
    ASSERT_TRUE(parseAutopilotPath("2=1.5 stall=1.5\n", p, &error)) << error.toStdString();
    EXPECT_DOUBLE_EQ(p[0].stall, 1.5);
    EXPECT_FALSE(parseAutopilotPath("2=1.5 stall=0\n", p, &error));
    EXPECT_FALSE(parseAutopilotPath("wait=1 stall=2\n", p, &error));
    EXPECT_FALSE(parseAutopilotPath("wait=1 ramp=2\n", p, &error));  // nothing to move gently
    EXPECT_TRUE(error.startsWith("line 1")) << error.toStdString();
}

TEST(Autopilot, OnTheFluidPowerMachineItSharesThePumpAndEasesTheClawsOntoTheirStop)
{
    // T0 and T4 run on models/liner_manipulator_fluid.pad: one 66.6 l/min pump for all
    solver::Diagnostics d;
    auto t0 = loadTutorial(kSource + "/resources/tutorials/t0_reach.tut", d);
    auto t4 = loadTutorial(kSource + "/resources/tutorials/t4_claws.tut", d);
    ASSERT_TRUE(t0 && t4) << dump(d);
    ASSERT_FALSE(t0->model->pumps.empty());
    StationProfile profile;
    QString error;
    ASSERT_TRUE(tutorialProfile(*t0, {}, profile, &error)) << error.toStdString();
    QTemporaryDir dir;
    std::vector<AutopilotWaypoint> path;
    // slew (20 l/min) and telescope (66.6 l/min) together: the levers are eased back to
    // what the pump gives, so it never saturates
    ASSERT_TRUE(parseAutopilotPath("1=0.6 3=0.5\n", path, &error));
    RunOutput run;
    ASSERT_TRUE(recordWithAutopilot(t0, path, profile, dir.filePath("share.log"), run, &error)) << error.toStdString();
    EXPECT_EQ(run.result.count(TutorialEvent::Kind::Saturation), 0);
    EXPECT_EQ(run.result.count(TutorialEvent::Kind::Cavitation), 0);
    // the claws' one lever: opened on the slower upper claw (C 8), the lower one (C 9)
    // meets its stop gently (no limit bang), then holds on it at its relief setting
    ASSERT_TRUE(tutorialProfile(*t4, {}, profile, &error)) << error.toStdString();
    ASSERT_TRUE(parseAutopilotPath("9=0.14\nwait=0.5\n8=-0.012 tol=0.006\n", path, &error));
    ASSERT_TRUE(recordWithAutopilot(t4, path, profile, dir.filePath("claws.log"), run, &error)) << error.toStdString();
    EXPECT_TRUE(run.result.completed);
    EXPECT_EQ(run.result.count(TutorialEvent::Kind::LimitBang), 0);
    EXPECT_EQ(run.result.count(TutorialEvent::Kind::Overload), 1);
}

TEST(CameraPath, KeysRoundTripAndInterpolateTheShortWayRound)
{
    CameraPath p;
    p.add({0.0, {0, 0, 0}, 10, 3.0, 0.2});
    p.add({2.0, {2, 0, 1}, 6, -3.0, 0.6});  // yaw across ±π: the short way is through π
    QTemporaryDir dir;
    QString error;
    ASSERT_TRUE(p.save(dir.filePath("x.cam"), &error)) << error.toStdString();
    CameraPath q;
    ASSERT_TRUE(CameraPath::load(dir.filePath("x.cam"), q, &error)) << error.toStdString();
    ASSERT_EQ(q.keys().size(), 2u);
    const CameraKey mid = q.at(1.0);
    EXPECT_NEAR(mid.target.x(), 1.0, 1e-9);
    EXPECT_NEAR(mid.distance, 8.0, 1e-9);
    EXPECT_NEAR(std::remainder(mid.yaw - std::numbers::pi, 2 * std::numbers::pi), 0.0, 1e-6);
    EXPECT_NEAR(q.at(-1).distance, 10.0, 1e-9);  // held before the first key
    EXPECT_NEAR(q.at(9).pitch, 0.6, 1e-9);       // and after the last
    EXPECT_FALSE(CameraPath::parse("0 1 2 3 4 5 6\n", q, &error));  // no header
    EXPECT_FALSE(CameraPath::parse("# padrob camera path 1\n0 1 2 3 4 5\n", q, &error));
    EXPECT_TRUE(error.startsWith("line 2")) << error.toStdString();
    EXPECT_FALSE(CameraPath::parse("# padrob camera path 1\n1 0 0 0 5 0 0\n0 0 0 0 5 0 0\n", q, &error));  // time back
    EXPECT_FALSE(CameraPath::parse("# padrob camera path 1\n0 0 0 0 -5 0 0\n", q, &error));
    // every shipped demonstration has its camera
    solver::Diagnostics d;
    auto t = loadTutorial(kSource + "/resources/tutorials/t7_mill.tut", d);
    ASSERT_TRUE(t) << dump(d);
    EXPECT_TRUE(d.empty()) << dump(d);
    ASSERT_FALSE(t->cameraFile.empty());
    ASSERT_TRUE(CameraPath::load(QString::fromStdString(t->cameraFile), q, &error));
    EXPECT_GT(q.duration(), 100.0);
}
