// Faults an instructor injects into a running attempt (issue 10): a burst hose (the
// boom sags under its weight, its lever does nothing; repaired, it holds), a stuck
// valve (the drive runs at the stuck opening), a power cut (every drive holds), a
// worker walking into the work area (the checker's safety zone there); each recorded
// as an event that the attempt's record keeps; bad requests refused with a message.

#include "trainer/training/attempt_log.h"
#include "trainer/training/faults.h"
#include "trainer/training/session.h"
#include "trainer/training/tutorial.h"

#include "solver/kinematics/kinematics.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using namespace trainer;

namespace {

const std::string kSource = PADROB_SOURCE_DIR;
const std::string kManipulator = kSource + "/models/liner_manipulator.pad";

std::string header(const std::string& extra = {})
{
    return "TUTORIAL X LEVEL 1\n"
           "TITLE ES \"Prueba\" EN \"Test\"\n"
           "MODEL \"" + kManipulator + "\"\n" + extra +
           "GOAL g REACH BODY 6 POINT 0 0.48 0 AT -2.10 3.08 1.32 TOL 0.15\n"
           "  DWELL 1\n"
           "  NAME ES \"Objetivo\" EN \"Target\"\n";
}

std::shared_ptr<const Tutorial> load(const std::string& text)
{
    solver::Diagnostics d;
    auto t = loadTutorialText(text, kSource + "/tests/trainer/x.tut", d);
    std::string all;
    for (const solver::Diagnostic& x : d) all += x.format() + "\n";
    EXPECT_TRUE(t) << all;
    return t;
}

/// Steps `s` with commands `u` (per joint id 1…) for `seconds`.
void drive(TutorialSession& s, std::vector<std::pair<int, double>> u, double seconds)
{
    std::vector<double> cmd(std::size_t(s.tutorial().model->nb), 0.0);
    for (auto [id, v] : u) cmd[std::size_t(s.tutorial().model->jointIndex(id))] = v;
    s.setCommands(cmd);
    s.advanceTo(s.time() + seconds);
}

Fault onDrive(Fault::Kind kind, const std::string& drive, double opening = std::nan(""))
{
    Fault f;
    f.kind = kind;
    f.drive = drive;
    f.opening = opening;
    return f;
}

int count(const TutorialSession& s, TutorialEvent::Kind kind, const std::string& detail)
{
    int n = 0;
    for (const TutorialEvent& e : s.events()) n += e.kind == kind && e.detail == detail;
    return n;
}

}  // namespace

TEST(Faults, KeysRoundTrip)
{
    for (Fault::Kind k : {Fault::Kind::HoseBurst, Fault::Kind::StuckValve, Fault::Kind::WorkerIn, Fault::Kind::PowerCut}) {
        Fault::Kind back = Fault::Kind::PowerCut == k ? Fault::Kind::HoseBurst : Fault::Kind::PowerCut;
        ASSERT_TRUE(Fault::fromKey(Fault::key(k), &back)) << Fault::key(k);
        EXPECT_EQ(back, k);
        EXPECT_FALSE(Fault::label(k).isEmpty());
    }
    Fault::Kind k = Fault::Kind::StuckValve;
    EXPECT_FALSE(Fault::fromKey("hose", &k));
    EXPECT_EQ(k, Fault::Kind::StuckValve);
    EXPECT_STREQ(TutorialEvent::key(TutorialEvent::Kind::Fault), "fault");
    EXPECT_STREQ(TutorialEvent::key(TutorialEvent::Kind::FaultCleared), "fault-cleared");
}

TEST(Faults, ABurstHoseLetsTheBoomSagWhateverTheLeverSaysAndRepairedItHolds)
{
    auto t = load(header());
    ASSERT_TRUE(t);
    const solver::Model& m = *t->model;
    const int boom = m.jointIndex(2);
    TutorialSession s(t);
    drive(s, {}, 0.2);
    const double L0 = m.coordinate(boom, s.simulation().state().q[boom]);
    ASSERT_GT(s.simulation().data().driveForce[boom], 0.0);  // the cylinder holds the boom up

    QString error;
    ASSERT_TRUE(s.inject(onDrive(Fault::Kind::HoseBurst, "levante pluma"), &error)) << error.toStdString();
    ASSERT_EQ(s.events().size(), 1u);
    const TutorialEvent& e = s.events().back();
    EXPECT_EQ(e.kind, TutorialEvent::Kind::Fault);
    EXPECT_EQ(e.detail, "hose-burst LEVANTE PLUMA");
    EXPECT_NEAR(e.t, 0.2, 1e-9);
    EXPECT_EQ(e.penalty, 0.0);
    EXPECT_TRUE(e.text(t.get()).contains("LEVANTE PLUMA"));
    ASSERT_EQ(s.activeFaults().size(), 1u);
    EXPECT_EQ(s.activeFaults()[0].drive, "LEVANTE PLUMA");

    // the operator lifts with all they have: the boom sinks, the cylinder pushed in
    drive(s, {{2, 1.0}}, 0.1);
    const double L1 = m.coordinate(boom, s.simulation().state().q[boom]);
    const double rate1 = s.simulation().state().qd[boom] * m.coordinateRate(boom, s.simulation().state().q[boom]);
    EXPECT_LT(L1, L0 - 1e-4);
    EXPECT_LT(rate1, 0.0);
    drive(s, {{2, 1.0}}, 0.05);
    const double rate2 = s.simulation().state().qd[boom] * m.coordinateRate(boom, s.simulation().state().q[boom]);
    EXPECT_LT(rate2, rate1);  // faster and faster: falling
    EXPECT_NEAR(s.simulation().data().driveForce[boom], 0.0, 1e-9);
    // the same lever without the fault would have lifted it at vmax
    EXPECT_GT(m.drive[boom].vmax, 0.0);

    // repaired: it holds where it is (lever at rest), then lifts again
    ASSERT_TRUE(s.clearFault(Fault::Kind::HoseBurst, "LEVANTE PLUMA", &error)) << error.toStdString();
    EXPECT_TRUE(s.activeFaults().empty());
    EXPECT_EQ(count(s, TutorialEvent::Kind::FaultCleared, "hose-burst LEVANTE PLUMA"), 1);
    drive(s, {}, 0.01);
    const double held = s.simulation().state().q[boom];
    drive(s, {}, 0.5);
    EXPECT_NEAR(s.simulation().state().q[boom], held, 1e-12);
    EXPECT_GT(s.simulation().data().driveForce[boom], 0.0);
    drive(s, {{2, 1.0}}, 0.5);
    const double rate = s.simulation().state().qd[boom] * m.coordinateRate(boom, s.simulation().state().q[boom]);
    EXPECT_NEAR(rate, m.drive[boom].vmax, 1e-9);
    // nothing to clear any more
    EXPECT_FALSE(s.clearFault(Fault::Kind::HoseBurst, "LEVANTE PLUMA", &error));
    EXPECT_TRUE(error.contains("LEVANTE PLUMA")) << error.toStdString();
    // the faults cost nothing by themselves
    EXPECT_DOUBLE_EQ(s.result().penalties, 0.0);
}

TEST(Faults, AStuckValveRunsTheDriveAtItsOpeningWhateverTheLeverSays)
{
    auto t = load(header());
    ASSERT_TRUE(t);
    const solver::Model& m = *t->model;
    const int ext = m.jointIndex(3);  // EXTENSIÓN, T 2: θ is the extension [m]
    const double vmax = m.drive[ext].vmax, vmin = m.drive[ext].vmin;
    ASSERT_GT(vmax, 0.0);
    TutorialSession s(t);
    QString error;
    ASSERT_TRUE(s.inject(onDrive(Fault::Kind::StuckValve, "EXTENSIÓN", 0.5), &error)) << error.toStdString();
    drive(s, {{3, -1.0}}, 0.5);  // the operator retracts: it extends at half speed
    EXPECT_NEAR(s.simulation().state().qd[ext], 0.5 * vmax, 1e-12);
    EXPECT_NEAR(s.simulation().state().q[ext], 0.5 * vmax * 0.5, 1e-9);
    EXPECT_EQ(count(s, TutorialEvent::Kind::Fault, "stuck-valve EXTENSIÓN"), 1);
    EXPECT_DOUBLE_EQ(s.events().front().value, 0.5);

    // freed: the lever acts (retracting at u·vmin)
    ASSERT_TRUE(s.clearFault(Fault::Kind::StuckValve, "extensión", &error)) << error.toStdString();
    drive(s, {{3, -0.5}}, 0.2);
    EXPECT_NEAR(s.simulation().state().qd[ext], -0.5 * vmin, 1e-12);

    // stuck where it is now (no opening given): the lever's 0.8 of a moment ago
    drive(s, {{3, 0.8}}, 0.1);
    ASSERT_TRUE(s.inject(onDrive(Fault::Kind::StuckValve, "EXTENSIÓN"), &error)) << error.toStdString();
    ASSERT_EQ(s.activeFaults().size(), 1u);
    EXPECT_DOUBLE_EQ(s.activeFaults()[0].opening, 0.8);
    drive(s, {{3, 0.0}}, 0.2);
    EXPECT_NEAR(s.simulation().state().qd[ext], 0.8 * vmax, 1e-12);
    // an opening outside the valve's travel is refused
    EXPECT_FALSE(s.inject(onDrive(Fault::Kind::StuckValve, "EXTENSIÓN", 1.5), &error));
    EXPECT_TRUE(error.contains("1.50")) << error.toStdString();
    ASSERT_EQ(s.activeFaults().size(), 1u);
    EXPECT_DOUBLE_EQ(s.activeFaults()[0].opening, 0.8);
}

TEST(Faults, APowerCutHoldsEveryDriveUntilPowerIsBack)
{
    auto t = load(header());
    ASSERT_TRUE(t);
    const solver::Model& m = *t->model;
    TutorialSession s(t);
    QString error;
    const std::vector<std::pair<int, double>> levers{{1, 1.0}, {2, 1.0}, {3, 1.0}, {4, -1.0}, {6, 1.0}};
    drive(s, levers, 0.5);
    ASSERT_GT(std::abs(s.simulation().state().qd[m.jointIndex(1)]), 0.1);
    // a stuck valve does not outlast the power either
    ASSERT_TRUE(s.inject(onDrive(Fault::Kind::StuckValve, "GIRO PLUMA", 1.0), &error)) << error.toStdString();
    Fault cut;
    cut.kind = Fault::Kind::PowerCut;
    ASSERT_TRUE(s.inject(cut, &error)) << error.toStdString();
    EXPECT_EQ(count(s, TutorialEvent::Kind::Fault, "power-cut"), 1);
    drive(s, levers, 0.001);  // one step
    const Eigen::VectorXd q0 = s.simulation().state().q;
    for (int j = 0; j < m.nb; ++j) {
        if (m.drive[std::size_t(j)].type != solver::DriveType::None) {
            EXPECT_NEAR(s.simulation().state().qd[j], 0.0, 1e-12) << j;
        }
    }
    drive(s, levers, 1.0);
    EXPECT_LT((s.simulation().state().q - q0).cwiseAbs().maxCoeff(), 1e-12);
    // power back: the levers act again (the slew's valve is still stuck open)
    ASSERT_TRUE(s.clearFault(Fault::Kind::PowerCut, {}, &error)) << error.toStdString();
    EXPECT_EQ(count(s, TutorialEvent::Kind::FaultCleared, "power-cut"), 1);
    drive(s, {{3, 1.0}}, 0.1);
    EXPECT_NEAR(s.simulation().state().qd[m.jointIndex(3)], m.drive[std::size_t(m.jointIndex(3))].vmax, 1e-12);
    EXPECT_NEAR(s.simulation().state().qd[m.jointIndex(1)], m.drive[std::size_t(m.jointIndex(1))].vmax, 1e-12);
    EXPECT_FALSE(s.clearFault(Fault::Kind::PowerCut, {}, &error));
    EXPECT_FALSE(error.isEmpty());
}

namespace {

// where the person walks to: beside the arm's extension, within the 1 m zone, not touching
constexpr double kWorkerX = 1.1, kWorkerY = 3.0;

/// A yard with a person far to the right of the arm (as in tutorial_test.cpp).
std::string yard(QTemporaryDir& dir)
{
    const QString scene = dir.filePath("yard.pad");
    QFile f(scene);
    f.open(QIODevice::WriteOnly);
    f.write("G 1 B 0 BOX 0.6 0.2 0.8 POS 0 6.3 0.21 COLOR 0.8 0.2 0.2\n"
            "G 2 B 0 CYL 0.2 1.75 POS 4.6 0.0 -0.2 COLOR 0.9 0.6 0.1\n"
            "G 3 B 0 SPHERE 0.12 POS 4.6 0.0 0.8 COLOR 0.9 0.9 0.1\n");
    return scene.toStdString();
}

}  // namespace

TEST(Faults, AWorkerWhoWalksInIsCheckedWhereTheyStandNow)
{
    QTemporaryDir dir;
    const std::string scene = yard(dir);
    auto t = load(header("SCENE \"" + scene + "\"\nWORKER G 2 3 ZONE 1.0 PENALTY 10\n NAME ES \"el mecánico\" EN \"the fitter\"\n"));
    ASSERT_TRUE(t);
    TutorialSession s(t);
    drive(s, {}, 0.1);
    EXPECT_EQ(s.progress().workerDistance, -1.0);  // farther than the zone and 1 m more: not measured
    EXPECT_FALSE(s.progress().nearWorker);
    EXPECT_NEAR((s.workerPosition(0) - Eigen::Vector3d(4.6, 0.0, -0.2)).norm(), 0.0, 1e-12);

    Fault in;
    in.kind = Fault::Kind::WorkerIn;
    in.worker = 0;
    in.where = Eigen::Vector3d(kWorkerX, kWorkerY, -0.2);
    QString error;
    ASSERT_TRUE(s.inject(in, &error)) << error.toStdString();
    EXPECT_EQ(count(s, TutorialEvent::Kind::Fault, "worker-in the fitter"), 1);
    EXPECT_EQ(s.events().back().subject, 0);
    EXPECT_TRUE(s.events().back().text(t.get(), "es").contains("el mecánico")) << s.events().back().text(t.get(), "es").toStdString();
    EXPECT_NEAR((s.workerPosition(0) - in.where).norm(), 0.0, 1e-12);
    EXPECT_NEAR((s.workerOffset(0).translation() - (in.where - Eigen::Vector3d(4.6, 0.0, -0.2))).norm(), 0.0, 1e-12);
    drive(s, {}, 0.001);  // the checker looks at once
    EXPECT_TRUE(s.progress().nearWorker) << s.progress().workerDistance;
    EXPECT_GT(s.progress().workerDistance, 0.0);
    EXPECT_LT(s.progress().workerDistance, 1.0);
    ASSERT_EQ(s.result().count(TutorialEvent::Kind::WorkerZone), 1);
    EXPECT_EQ(s.events().back().kind, TutorialEvent::Kind::WorkerZone);
    EXPECT_EQ(s.events().back().detail, "the fitter");
    EXPECT_DOUBLE_EQ(s.result().penalties, 10.0);  // the zone's penalty; the fault none

    // the worker leaves: back where the scene has them
    ASSERT_TRUE(s.clearFault(Fault::Kind::WorkerIn, {}, &error, 0)) << error.toStdString();
    EXPECT_EQ(count(s, TutorialEvent::Kind::FaultCleared, "worker-in the fitter"), 1);
    EXPECT_TRUE(s.workerOffset(0).isApprox(Eigen::Isometry3d::Identity()));
    drive(s, {}, 0.001);
    EXPECT_EQ(s.progress().workerDistance, -1.0);
    EXPECT_FALSE(s.progress().nearWorker);
    EXPECT_FALSE(s.clearFault(Fault::Kind::WorkerIn, {}, &error));

    // there is no worker 1
    in.worker = 1;
    EXPECT_FALSE(s.inject(in, &error));
    EXPECT_TRUE(error.contains("0 to 0")) << error.toStdString();
}

TEST(Faults, BadRequestsAreRefusedWithWhatWasWrong)
{
    auto t = load(header());
    ASSERT_TRUE(t);
    TutorialSession s(t);
    QString error;
    EXPECT_FALSE(s.inject(onDrive(Fault::Kind::HoseBurst, "BOOM"), &error));
    EXPECT_TRUE(error.contains("BOOM")) << error.toStdString();
    // the valid ones are listed
    for (const char* d : {"GIRO PLUMA", "LEVANTE PLUMA", "EXTENSIÓN", "GARRA INFERIOR"})
        EXPECT_TRUE(error.contains(QString::fromUtf8(d))) << d << ": " << error.toStdString();
    EXPECT_FALSE(s.clearFault(Fault::Kind::StuckValve, "BOOM", &error));
    EXPECT_TRUE(error.contains("LEVANTE PLUMA")) << error.toStdString();
    // no worker in this tutorial
    Fault in;
    in.kind = Fault::Kind::WorkerIn;
    EXPECT_FALSE(s.inject(in, &error));
    EXPECT_TRUE(error.contains("no worker")) << error.toStdString();
    // a burst hose with a negative damping
    Fault bad = onDrive(Fault::Kind::HoseBurst, "EXTENSIÓN");
    bad.hose.damping = -1;
    EXPECT_FALSE(s.inject(bad, &error));
    EXPECT_TRUE(s.events().empty());
    EXPECT_TRUE(s.activeFaults().empty());
    EXPECT_EQ(s.simulation().driveFault(t->model->jointIndex(3)), nullptr);
    // after the end nothing more
    s.stop(TutorialEvent::Kind::Aborted);
    EXPECT_FALSE(s.inject(onDrive(Fault::Kind::HoseBurst, "EXTENSIÓN"), &error));
    EXPECT_FALSE(error.isEmpty());
}

TEST(Faults, TheAttemptsRecordSaysWhatTheInstructorDidAndWhen)
{
    auto t = load(header());
    ASSERT_TRUE(t);
    TutorialSession s(t);
    QString error;
    drive(s, {}, 0.3);
    ASSERT_TRUE(s.inject(onDrive(Fault::Kind::StuckValve, "GIRO PLUMA", -0.25), &error)) << error.toStdString();
    drive(s, {}, 0.2);
    ASSERT_TRUE(s.clearFault(Fault::Kind::StuckValve, "GIRO PLUMA", &error)) << error.toStdString();
    s.stop(TutorialEvent::Kind::Aborted);

    QTemporaryDir dir;
    records::RecordsDb db;
    ASSERT_TRUE(db.openSqlite(dir.filePath("records.sqlite"), false, &error)) << error.toStdString();
    const qint64 op = db.addOperator("OP-9", "Juan Soto", &error);
    ASSERT_GT(op, 0) << error.toStdString();
    AttemptLog log(&db, dir.filePath("pending"), "OP-9", "Juan Soto", *t, "es");
    ASSERT_TRUE(log.finish(s.events(), s.result(), true)) << log.problem().toStdString();
    records::Attempt stored;
    ASSERT_TRUE(db.attempt(log.attemptId(), stored, &error)) << error.toStdString();
    ASSERT_EQ(stored.events.size(), 3);
    EXPECT_EQ(stored.events[0].kind, "fault");
    EXPECT_EQ(stored.events[0].detail.toStdString(), "stuck-valve GIRO PLUMA");
    EXPECT_NEAR(stored.events[0].t, 0.3, 1e-9);
    EXPECT_DOUBLE_EQ(stored.events[0].value, -0.25);
    EXPECT_DOUBLE_EQ(stored.events[0].penalty, 0.0);
    EXPECT_TRUE(stored.events[0].text.contains("GIRO PLUMA")) << stored.events[0].text.toStdString();
    EXPECT_EQ(stored.events[1].kind, "fault-cleared");
    EXPECT_EQ(stored.events[1].detail.toStdString(), "stuck-valve GIRO PLUMA");
    EXPECT_NEAR(stored.events[1].t, 0.5, 1e-9);
    EXPECT_EQ(stored.events[2].kind, "aborted");
}
