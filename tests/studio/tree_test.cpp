// The model tree and the joint sliders (ide/studio/tree/) as real widgets: the tree of
// the four-bar and of the liner manipulator, selection signals, posing the four-bar by
// its crank against the closed-form solution, the liner's slew, a loop that cannot
// close, and screenshots.

#include "ide/i18n/language.h"
#include "ide/studio/model/model_bundle.h"
#include "ide/studio/tree/model_tree.h"
#include "ide/studio/tree/joint_sliders.h"
#include "solver/core/data.h"
#include "solver/core/state.h"
#include "solver/dynamics/constraints.h"

#include <QDir>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QFile>
#include <QSignalSpy>
#include <QSlider>
#include <QTreeWidget>
#include <QtTest>

#include <cmath>
#include <numbers>

using studio::ModelBundle;
using studio::ModelTree;
using studio::JointSliders;

namespace {

constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180; }

QString modelPath(const char* name) { return QStringLiteral(PADROB_SOURCE_DIR "/models/") + QLatin1String(name); }

QString readText(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(f.readAll());
}

std::shared_ptr<const ModelBundle> bundleOf(const QString& text, const QString& path = {})
{
    solver::Diagnostics diags;
    auto b = studio::makeBundle(text, path, diags);
    if (!b) {
        for (const solver::Diagnostic& d : diags) qWarning("%s", d.format().c_str());
    }
    return b;
}

std::shared_ptr<const ModelBundle> loadModel(const char* name)
{
    return bundleOf(readText(modelPath(name)), modelPath(name));
}

/// 1-based line of the first line of `text` that starts with `prefix`.
int lineStarting(const QString& text, const QString& prefix)
{
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (int k = 0; k < lines.size(); ++k) {
        if (lines[k].startsWith(prefix)) return k + 1;
    }
    return -1;
}

/// Index of the slider of joint `id` (−1 if none).
int sliderOf(const JointSliders& s, const ModelBundle& b, int id)
{
    for (int k = 0; k < s.sliderCount(); ++k) {
        if (s.sliderJoint(k) == b.model->jointIndex(id)) return k;
    }
    return -1;
}

/// World position of a point given in body `id`'s frame.
Eigen::Vector3d world(const std::vector<Eigen::Isometry3d>& X_wb, const ModelBundle& b, int id, const Eigen::Vector3d& p)
{
    return X_wb[static_cast<std::size_t>(b.model->bodyIndex(id))] * p;
}

void saveScreenshot(QWidget* w, const QString& name)
{
    const QString dir = QStringLiteral(PADROB_SCREENSHOT_DIR);
    QVERIFY(QDir().mkpath(dir));
    QVERIFY(w->grab().save(dir + QLatin1Char('/') + name));
}

// a double-rocker four-bar: ground 0.40, crank 0.30, coupler 0.10, rocker 0.25 (Grashof
// with the coupler shortest: the crank only swings between 18.6° and 57.9°)
const char* kDoubleRocker = R"(
B 1 0.6 1e-5 0.005 0.005 NAME "crank"
B 2 0.2 1e-5 0.0002 0.0002 NAME "coupler"
B 3 0.5 1e-5 0.003 0.003 NAME "rocker"
C 1 QI 40 DEG NAME "crank pivot"
B1 0 P1 0 0 0 A1 0 0 1 R1 1 0 0
B2 1 P2 -0.15 0 0 A2 0 0 1 R2 1 0 0
C 2 QI -14 DEG
B1 1 P1 0.15 0 0 A1 0 0 1 R1 1 0 0
B2 2 P2 -0.05 0 0 A2 0 0 1 R2 1 0 0
C 3 QI 108.75 DEG
B1 0 P1 0.4 0 0 A1 0 0 1 R1 1 0 0
B2 3 P2 -0.125 0 0 A2 0 0 1 R2 1 0 0
C 4 QI 82.6 DEG
B1 2 P1 0.05 0 0 A1 0 0 1 R1 1 0 0
B2 3 P2 0.125 0 0 A2 0 0 1 R2 1 0 0
)";

}  // namespace

class TreeTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void fourBarTreeShowsLoopAndCoordinates();
    void linerTreeShowsJointsAndDrives();
    void selectingAJointEmitsTreeIndexAndLine();
    void clickingABodyEmitsItsTreeIndex();
    void selectFromElsewhereDoesNotEmit();
    void fourBarCrankSliderFollowsTheClosedFormSolution();
    void fourBarDraggingTheSliderKeepsTheLoopClosed();
    void loopThatCannotCloseKeepsTheLastPose();
    void linerSlidersSlewRotatesTheBoom();
    void linerActuatorSliderIsInMetres();
    void resetReturnsToTheInitialPose();
    void everyModelPosesAtItsSliderEnds();
    void screenshots();
    void spanishAtRunTime();
};

// the tests read English texts and '.' numbers, whatever the system's locale
void TreeTest::initTestCase() { QVERIFY(i18n::install("en")); }

void TreeTest::fourBarTreeShowsLoopAndCoordinates()
{
    auto b = loadModel("four_bar.pad");
    QVERIFY(b);
    ModelTree tree;
    tree.setBundle(b);
    QTreeWidgetItem* bodies = tree.groupItem(ModelTree::Group::Bodies);
    QTreeWidgetItem* joints = tree.groupItem(ModelTree::Group::Joints);
    QVERIFY(bodies && joints);
    QCOMPARE(bodies->childCount(), 4);  // the ground and 3 bodies
    QCOMPARE(joints->childCount(), 4);
    QVERIFY(bodies->text(0).contains(QLatin1String("3")));
    QCOMPARE(tree.bodyItem(1)->text(ModelTree::DetailsColumn), QStringLiteral("0.2 kg"));
    QVERIFY(tree.bodyItem(2)->text(0).contains(QLatin1String("coupler")));

    QCOMPARE(tree.jointItem(4)->text(ModelTree::RoleColumn), QStringLiteral("loop closure"));
    QCOMPARE(tree.jointItem(4)->data(0, ModelTree::TreeIndexRole).toInt(), -1);
    QCOMPARE(tree.jointItem(2)->text(ModelTree::RoleColumn), QStringLiteral("dependent"));
    QCOMPARE(tree.jointItem(3)->text(ModelTree::RoleColumn), QStringLiteral("dependent"));
    QCOMPARE(tree.jointItem(1)->text(ModelTree::RoleColumn), QStringLiteral("independent"));
    QCOMPARE(tree.jointItem(1)->text(ModelTree::TypeColumn), QStringLiteral("revolute"));
    QCOMPARE(tree.jointItem(1)->text(ModelTree::DetailsColumn), QStringLiteral("unlimited"));
    QVERIFY(tree.jointItem(1)->text(ModelTree::DriveColumn).startsWith(QLatin1String("motor")));
    QCOMPARE(tree.jointItem(2)->text(ModelTree::DriveColumn), QStringLiteral("passive"));

    QTreeWidgetItem* loops = tree.groupItem(ModelTree::Group::LoopClosures);
    QCOMPARE(loops->childCount(), 1);
    QCOMPARE(loops->child(0)->data(0, ModelTree::IdRole).toInt(), 4);

    QTreeWidgetItem* coords = tree.groupItem(ModelTree::Group::Coordinates);
    QCOMPARE(coords->childCount(), 2);
    QTreeWidgetItem* independent = coords->child(0);
    QTreeWidgetItem* dependent = coords->child(1);
    QCOMPARE(independent->childCount(), 1);
    QCOMPARE(independent->child(0)->data(0, ModelTree::IdRole).toInt(), 1);
    QCOMPARE(independent->child(0)->text(ModelTree::DetailsColumn), QStringLiteral("initially 60.00°"));
    QCOMPARE(dependent->childCount(), 2);
    QList<int> dependentIds{dependent->child(0)->data(0, ModelTree::IdRole).toInt(), dependent->child(1)->data(0, ModelTree::IdRole).toInt()};
    std::sort(dependentIds.begin(), dependentIds.end());
    QCOMPARE(dependentIds, (QList<int>{2, 3}));

    // the chains hold the three tree joints, each once
    QTreeWidgetItem* chains = tree.groupItem(ModelTree::Group::Chains);
    QList<int> chained;
    for (int c = 0; c < chains->childCount(); ++c) {
        for (int k = 0; k < chains->child(c)->childCount(); ++k) chained << chains->child(c)->child(k)->data(0, ModelTree::IdRole).toInt();
    }
    std::sort(chained.begin(), chained.end());
    QCOMPARE(chained, (QList<int>{1, 2, 3}));
}

void TreeTest::linerTreeShowsJointsAndDrives()
{
    auto b = loadModel("liner_manipulator.pad");
    QVERIFY(b);
    ModelTree tree;
    tree.setBundle(b);
    QCOMPARE(tree.groupItem(ModelTree::Group::Joints)->childCount(), 9);
    QCOMPARE(tree.groupItem(ModelTree::Group::Bodies)->childCount(), 10);  // B 0 written, and 9 bodies
    QCOMPARE(tree.bodyItem(0)->text(0), QStringLiteral("B 0  base"));
    QCOMPARE(tree.bodyItem(1)->text(ModelTree::DetailsColumn), QStringLiteral("massless"));
    QCOMPARE(tree.bodyItem(2)->text(ModelTree::DetailsColumn), QStringLiteral("306 kg"));
    for (int id = 1; id <= 9; ++id) {
        QTreeWidgetItem* j = tree.jointItem(id);
        QVERIFY(j);
        QCOMPARE(j->text(ModelTree::RoleColumn), QStringLiteral("independent"));
        QVERIFY2(j->text(ModelTree::DriveColumn).startsWith(QLatin1String("hydraulic")), qPrintable(j->text(ModelTree::DriveColumn)));
    }
    // types and limits with units
    QCOMPARE(tree.jointItem(2)->text(ModelTree::TypeColumn), QStringLiteral("pivoted actuator"));
    QCOMPARE(tree.jointItem(2)->text(ModelTree::DetailsColumn), QStringLiteral("1.4 m … 1.617 m"));
    QCOMPARE(tree.jointItem(3)->text(ModelTree::TypeColumn), QStringLiteral("prismatic"));
    QCOMPARE(tree.jointItem(4)->text(ModelTree::DetailsColumn), QStringLiteral("-65.0° … 65.0°"));
    QCOMPARE(tree.jointItem(1)->text(ModelTree::DriveColumn), QStringLiteral("hydraulic 0.131 rad/s, relief 54 kN·m"));
    QVERIFY(tree.jointItem(2)->text(ModelTree::DriveColumn).contains(QLatin1String("m/s")));
    QVERIFY(tree.jointItem(2)->text(ModelTree::DriveColumn).contains(QLatin1String("MN")));
    QCOMPARE(tree.groupItem(ModelTree::Group::LoopClosures)->childCount(), 1);  // "none"
    QCOMPARE(tree.groupItem(ModelTree::Group::LoopClosures)->child(0)->data(0, ModelTree::ItemKindRole).toInt(),
             static_cast<int>(ModelTree::ItemKind::Info));
    QCOMPARE(tree.groupItem(ModelTree::Group::Coordinates)->child(0)->childCount(), 9);
    QCOMPARE(tree.groupItem(ModelTree::Group::Coordinates)->child(1)->childCount(), 0);
}

void TreeTest::selectingAJointEmitsTreeIndexAndLine()
{
    const QString text = readText(modelPath("liner_manipulator.pad"));
    auto b = bundleOf(text, modelPath("liner_manipulator.pad"));
    QVERIFY(b);
    ModelTree tree;
    tree.setBundle(b);
    QSignalSpy joints(&tree, &ModelTree::jointSelected);
    QSignalSpy bodies(&tree, &ModelTree::bodySelected);
    QSignalSpy lines(&tree, &ModelTree::sourceSelected);
    tree.setCurrentItem(tree.jointItem(5));
    QCOMPARE(joints.count(), 1);
    QCOMPARE(joints.at(0).at(0).toInt(), b->model->jointIndex(5));
    QCOMPARE(lines.count(), 1);
    QCOMPARE(lines.at(0).at(0).toInt(), lineStarting(text, QStringLiteral("C 5 ")));
    QCOMPARE(bodies.count(), 0);

    // the four-bar's loop-closing joint has no tree index
    const QString fourBar = readText(modelPath("four_bar.pad"));
    tree.setBundle(bundleOf(fourBar, modelPath("four_bar.pad")));
    tree.setCurrentItem(tree.jointItem(4));
    QCOMPARE(joints.count(), 2);
    QCOMPARE(joints.at(1).at(0).toInt(), -1);
    QCOMPARE(lines.at(1).at(0).toInt(), lineStarting(fourBar, QStringLiteral("C 4 ")));
    // a joint under "Chains" is the same joint
    QTreeWidgetItem* chainJoint = tree.groupItem(ModelTree::Group::Chains)->child(0)->child(0);
    tree.setCurrentItem(chainJoint);
    QCOMPARE(joints.last().at(0).toInt(), chainJoint->data(0, ModelTree::TreeIndexRole).toInt());
    QVERIFY(joints.last().at(0).toInt() >= 0);
    // groups emit nothing
    const int before = joints.count() + bodies.count() + lines.count();
    tree.setCurrentItem(tree.groupItem(ModelTree::Group::Chains));
    QCOMPARE(joints.count() + bodies.count() + lines.count(), before);
}

void TreeTest::clickingABodyEmitsItsTreeIndex()
{
    const QString text = readText(modelPath("four_bar.pad"));
    auto b = bundleOf(text, modelPath("four_bar.pad"));
    QVERIFY(b);
    ModelTree tree;
    tree.resize(700, 600);
    tree.setBundle(b);
    tree.show();
    QVERIFY(QTest::qWaitForWindowExposed(&tree));
    QSignalSpy bodies(&tree, &ModelTree::bodySelected);
    QSignalSpy lines(&tree, &ModelTree::sourceSelected);
    QTreeWidgetItem* rocker = tree.bodyItem(3);
    const QRect r = tree.visualItemRect(rocker);
    QVERIFY(r.isValid());
    QTest::mouseClick(tree.viewport(), Qt::LeftButton, {}, r.center());
    QCOMPARE(bodies.count(), 1);
    QCOMPARE(bodies.at(0).at(0).toInt(), b->model->bodyIndex(3));
    QCOMPARE(lines.at(0).at(0).toInt(), lineStarting(text, QStringLiteral("B 3 ")));
    // the ground: tree index −1, and no statement to jump to (B 0 is not written)
    QTest::mouseClick(tree.viewport(), Qt::LeftButton, {}, tree.visualItemRect(tree.bodyItem(0)).center());
    QCOMPARE(bodies.count(), 2);
    QCOMPARE(bodies.at(1).at(0).toInt(), -1);
    QCOMPARE(lines.count(), 1);
}

void TreeTest::selectFromElsewhereDoesNotEmit()
{
    auto b = loadModel("liner_manipulator.pad");
    QVERIFY(b);
    ModelTree tree;
    tree.setBundle(b);
    QSignalSpy joints(&tree, &ModelTree::jointSelected);
    QSignalSpy bodies(&tree, &ModelTree::bodySelected);
    QSignalSpy lines(&tree, &ModelTree::sourceSelected);
    tree.selectJoint(b->model->jointIndex(3));
    QCOMPARE(tree.currentItem(), tree.jointItem(3));
    tree.selectBody(b->model->bodyIndex(6));
    QCOMPARE(tree.currentItem(), tree.bodyItem(6));
    tree.selectBody(-1);
    QCOMPARE(tree.currentItem(), tree.bodyItem(0));
    QCOMPARE(joints.count() + bodies.count() + lines.count(), 0);
    // a new model keeps the selection when it has the same body
    tree.selectBody(b->model->bodyIndex(6));
    tree.setBundle(loadModel("liner_manipulator.pad"));
    QCOMPARE(tree.currentItem(), tree.bodyItem(6));
    QCOMPARE(joints.count() + bodies.count() + lines.count(), 0);
}

void TreeTest::fourBarCrankSliderFollowsTheClosedFormSolution()
{
    auto b = loadModel("four_bar.pad");
    QVERIFY(b);
    JointSliders sliders;
    sliders.setBundle(b);
    QCOMPARE(sliders.sliderCount(), 1);
    QCOMPARE(sliders.sliderJoint(0), b->model->jointIndex(1));
    QCOMPARE(sliders.spinBox(0)->suffix(), QStringLiteral(" °"));
    QVERIFY(std::abs(sliders.spinBox(0)->value() - 60.0) < 1e-9);  // the initial state
    QVERIFY(std::abs(sliders.lower(0) + kPi) < 1e-12 && std::abs(sliders.upper(0) - kPi) < 1e-12);

    QSignalSpy poses(&sliders, &JointSliders::posesChanged);
    QSignalSpy coords(&sliders, &JointSliders::coordinatesChanged);
    // the slider's position for 90° (range −180° … 180°)
    const int pos90 = static_cast<int>(std::lround((90.0 + 180.0) / 360.0 * sliders.slider(0)->maximum()));
    sliders.slider(0)->setValue(pos90);
    QCOMPARE(poses.count(), 1);
    QCOMPARE(coords.count(), 1);
    QVERIFY(sliders.status().isEmpty());
    QVERIFY(std::abs(sliders.spinBox(0)->value() - 90.0) < 1e-9);

    const auto X_wb = poses.at(0).at(0).value<std::vector<Eigen::Isometry3d>>();
    QCOMPARE(static_cast<int>(X_wb.size()), b->model->nb);
    // crank pin A at (0, 0.1); coupler and rocker meet at B
    const Eigen::Vector3d a = world(X_wb, *b, 1, {0.05, 0, 0});
    QVERIFY((a - Eigen::Vector3d(0, 0.1, 0)).norm() < 1e-12);
    QVERIFY((world(X_wb, *b, 2, {-0.175, 0, 0}) - a).norm() < 1e-9);
    const Eigen::Vector3d pinCoupler = world(X_wb, *b, 2, {0.175, 0, 0});
    const Eigen::Vector3d pinRocker = world(X_wb, *b, 3, {0.15, 0, 0});
    QVERIFY2((pinRocker - pinCoupler).norm() < 1e-9, qPrintable(QString::number((pinRocker - pinCoupler).norm())));
    QVERIFY((world(X_wb, *b, 3, {-0.15, 0, 0}) - Eigen::Vector3d(0.4, 0, 0)).norm() < 1e-9);

    // closed form: B on the circles |B − A| = 0.35 and |B − O4| = 0.30, open assembly
    // (B above the line A–O4, as at the initial pose)
    const Eigen::Vector2d A(0, 0.1), O4(0.4, 0);
    const double d = (O4 - A).norm(), b3 = 0.35, c = 0.30;
    const double along = (b3 * b3 - c * c + d * d) / (2 * d), h = std::sqrt(b3 * b3 - along * along);
    const Eigen::Vector2d u = (O4 - A) / d, n(-u.y(), u.x());
    const Eigen::Vector2d B = A + along * u + h * n;
    const double theta4 = std::atan2(B.y() - O4.y(), B.x() - O4.x());
    const double theta3 = std::atan2(B.y() - A.y(), B.x() - A.x());
    const Eigen::VectorXd q = coords.at(0).at(0).value<Eigen::VectorXd>();
    QCOMPARE(static_cast<int>(q.size()), b->model->nb);
    QVERIFY2(std::abs(q[b->model->jointIndex(1)] - rad(90)) < 1e-12, "crank");
    QVERIFY2(std::abs(q[b->model->jointIndex(3)] - theta4) < 1e-9,
             qPrintable(QStringLiteral("rocker %1 vs %2").arg(q[b->model->jointIndex(3)]).arg(theta4)));
    QVERIFY2(std::abs(q[b->model->jointIndex(2)] - (theta3 - rad(90))) < 1e-9, "coupler");
    QVERIFY((Eigen::Vector2d(pinRocker.x(), pinRocker.y()) - B).norm() < 1e-9);
}

void TreeTest::fourBarDraggingTheSliderKeepsTheLoopClosed()
{
    auto b = loadModel("four_bar.pad");
    QVERIFY(b);
    JointSliders sliders;
    sliders.resize(500, 200);
    sliders.setBundle(b);
    sliders.show();
    QVERIFY(QTest::qWaitForWindowExposed(&sliders));
    QSignalSpy poses(&sliders, &JointSliders::posesChanged);
    // a whole turn of the crank with the keyboard (page steps), the rocker swings between
    // its extremes 101.415° and 141.375° (four_bar.pad's header)
    QSlider* s = sliders.slider(0);
    s->setFocus();
    s->setPageStep(s->maximum() / 72);  // 5°
    double lowest = 1e9, highest = -1e9;
    for (int k = 0; k < 80; ++k) {
        QTest::keyClick(s, Qt::Key_PageUp);
        if (s->value() == s->maximum()) s->setValue(0);
        const auto& X_wb = sliders.poses();
        QVERIFY((world(X_wb, *b, 3, {0.15, 0, 0}) - world(X_wb, *b, 2, {0.175, 0, 0})).norm() < 1e-9);
        const double rocker = sliders.coordinates()[b->model->jointIndex(3)] * 180 / kPi;
        lowest = std::min(lowest, rocker);
        highest = std::max(highest, rocker);
    }
    QVERIFY(poses.count() >= 80);
    QVERIFY(sliders.status().isEmpty());
    QVERIFY2(lowest > 101.415158 - 1e-6 && lowest < 101.415158 + 0.2, qPrintable(QString::number(lowest)));
    QVERIFY2(highest < 141.375167 + 1e-6 && highest > 141.375167 - 0.2, qPrintable(QString::number(highest)));
}

void TreeTest::loopThatCannotCloseKeepsTheLastPose()
{
    auto b = bundleOf(QString::fromLatin1(kDoubleRocker));
    QVERIFY(b);
    JointSliders sliders;
    sliders.setBundle(b);
    QCOMPARE(sliders.sliderCount(), 1);
    const int crankJoint = b->model->jointIndex(1);
    QCOMPARE(sliders.sliderJoint(0), crankJoint);
    QVERIFY(std::abs(sliders.spinBox(0)->value() - 40.0) < 1e-9);
    const auto pinGap = [&] {
        const auto& X_wb = sliders.poses();
        return (world(X_wb, *b, 3, {0.125, 0, 0}) - world(X_wb, *b, 2, {0.05, 0, 0})).norm();
    };

    QSignalSpy poses(&sliders, &JointSliders::posesChanged);
    sliders.spinBox(0)->setValue(80.0);  // past the toggle position at 57.9°
    QCOMPARE(poses.count(), 1);
    QVERIFY(!sliders.status().isEmpty());
    const double reached = sliders.coordinates()[crankJoint] * 180 / kPi;
    QVERIFY2(reached > 54 && reached < 57.9, qPrintable(QString::number(reached)));
    QVERIFY(std::abs(sliders.spinBox(0)->value() - reached) < 1e-6);  // the controls show where it stopped
    QVERIFY2(pinGap() < 1e-9, qPrintable(QString::number(pinGap())));

    // and it goes on from there
    QVERIFY(sliders.setCoordinate(0, rad(30)));
    QVERIFY(sliders.status().isEmpty());
    QVERIFY(std::abs(sliders.coordinates()[crankJoint] - rad(30)) < 1e-12);
    QVERIFY(pinGap() < 1e-9);
}

void TreeTest::linerSlidersSlewRotatesTheBoom()
{
    auto b = loadModel("liner_manipulator.pad");
    QVERIFY(b);
    JointSliders sliders;
    sliders.setBundle(b);
    QCOMPARE(sliders.sliderCount(), 9);
    const int slew = sliderOf(sliders, *b, 1);
    QVERIFY(slew >= 0);
    const std::vector<Eigen::Isometry3d> before = sliders.poses();
    QSignalSpy poses(&sliders, &JointSliders::posesChanged);
    sliders.spinBox(slew)->setValue(90.0);
    QCOMPARE(poses.count(), 1);
    const auto after = poses.at(0).at(0).value<std::vector<Eigen::Isometry3d>>();
    const std::size_t boom = static_cast<std::size_t>(b->model->bodyIndex(2));
    // a quarter turn about the slew axis (world z through the origin)
    const Eigen::Matrix3d Rz = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    QVERIFY((after[boom].linear() - Rz * before[boom].linear()).norm() < 1e-12);
    QVERIFY((after[boom].translation() - Rz * before[boom].translation()).norm() < 1e-12);
    // the boom pointed along +y (0.08° above the horizontal): now along −x
    QVERIFY((after[boom].linear().col(1) - Eigen::Vector3d(-1, 0, 0)).norm() < 1e-2);
    QVERIFY((before[boom].linear().col(1) - Eigen::Vector3d(0, 1, 0)).norm() < 1e-2);
    // the others did not move relative to the turret
    for (int id = 3; id <= 9; ++id) {
        const std::size_t i = static_cast<std::size_t>(b->model->bodyIndex(id));
        QVERIFY(((before[boom].inverse() * before[i]).matrix() - (after[boom].inverse() * after[i]).matrix()).norm() < 1e-12);
    }
}

void TreeTest::linerActuatorSliderIsInMetres()
{
    auto b = loadModel("liner_manipulator.pad");
    QVERIFY(b);
    JointSliders sliders;
    sliders.setBundle(b);
    const int lift = sliderOf(sliders, *b, 2);
    QVERIFY(lift >= 0);
    QCOMPARE(sliders.spinBox(lift)->suffix(), QStringLiteral(" m"));
    QVERIFY(std::abs(sliders.lower(lift) - 1.4) < 1e-12);
    QVERIFY(std::abs(sliders.upper(lift) - 1.617) < 1e-12);
    QVERIFY(std::abs(sliders.spinBox(lift)->value() - 1.464) < 1e-4);
    const double boomBefore = sliders.theta()[b->model->jointIndex(2)];
    sliders.spinBox(lift)->setValue(1.6);
    QVERIFY(sliders.status().isEmpty());
    QVERIFY(std::abs(sliders.coordinates()[b->model->jointIndex(2)] - 1.6) < 1e-9);
    // a longer cylinder lifts the boom (its angle grows, about +50°)
    QVERIFY(sliders.theta()[b->model->jointIndex(2)] > boomBefore + rad(30));
    const int telescope = sliderOf(sliders, *b, 3);
    QCOMPARE(sliders.spinBox(telescope)->suffix(), QStringLiteral(" m"));
    QVERIFY(std::abs(sliders.upper(telescope) - 0.9) < 1e-12);
    const int yaw = sliderOf(sliders, *b, 4);
    QVERIFY(std::abs(sliders.spinBox(yaw)->maximum() - 1.1344 * 180 / kPi) < 0.01);
}

void TreeTest::resetReturnsToTheInitialPose()
{
    auto b = loadModel("four_bar.pad");
    QVERIFY(b);
    JointSliders sliders;
    sliders.setBundle(b);
    const Eigen::VectorXd initial = sliders.coordinates();
    QVERIFY(sliders.setCoordinate(0, rad(-120)));
    QVERIFY((sliders.coordinates() - initial).norm() > 0.1);
    QSignalSpy poses(&sliders, &JointSliders::posesChanged);
    sliders.reset();
    QCOMPARE(poses.count(), 1);
    QVERIFY((sliders.coordinates() - initial).norm() < 1e-12);
    QVERIFY(std::abs(sliders.spinBox(0)->value() - 60.0) < 1e-9);
    // no model: no sliders
    sliders.setBundle(nullptr);
    QCOMPARE(sliders.sliderCount(), 0);
    QVERIFY(sliders.poses().empty());
}

void TreeTest::everyModelPosesAtItsSliderEnds()
{
    // every model of models/: each slider to its ends and back to the middle; the loops
    // stay closed, and a move either gets there or says why not
    const QStringList files = QDir(QStringLiteral(PADROB_SOURCE_DIR "/models")).entryList({QStringLiteral("*.pad")});
    QVERIFY(files.size() >= 5);
    for (const QString& file : files) {
        auto b = loadModel(file.toUtf8().constData());
        QVERIFY2(b, qPrintable(file));
        ModelTree tree;
        tree.setBundle(b);
        QCOMPARE(tree.groupItem(ModelTree::Group::Joints)->childCount(), static_cast<int>(b->spec().joints.size()));
        JointSliders sliders;
        sliders.setBundle(b);
        // (a free body's six degrees of freedom have no slider: forces and contacts move it)
        QCOMPARE(sliders.sliderCount(), b->topology().dof - solver::kFreeJointCoordinates *
                                                                static_cast<int>(b->model->freeJoints.size()));
        const solver::Model& m = *b->model;
        solver::Data data(m);
        const solver::State state = solver::makeState(m);
        std::vector<solver::Constraint> constraints;
        solver::collectConstraints(m, state, constraints);
        for (int k = 0; k < sliders.sliderCount(); ++k) {
            for (double f : {0.0, 1.0, 0.5}) {
                const double target = sliders.lower(k) + f * (sliders.upper(k) - sliders.lower(k));
                const bool ok = sliders.setCoordinate(k, target);
                const double reached = sliders.coordinates()[sliders.sliderJoint(k)];
                QVERIFY2(ok == sliders.status().isEmpty(), qPrintable(file));
                if (ok) QVERIFY2(std::abs(reached - target) < 1e-9, qPrintable(QStringLiteral("%1 slider %2").arg(file).arg(k)));
                data.X_wb = sliders.poses();
                Eigen::VectorXd phi;
                solver::constraintResidual(m, data, constraints, phi);
                QVERIFY2(phi.size() == 0 || phi.lpNorm<Eigen::Infinity>() < 1e-9,
                         qPrintable(QStringLiteral("%1 slider %2 at %3").arg(file).arg(k).arg(target)));
            }
        }
    }
}

void TreeTest::screenshots()
{
    ModelTree tree;
    tree.resize(1000, 760);
    tree.setBundle(loadModel("liner_manipulator.pad"));
    tree.show();
    QVERIFY(QTest::qWaitForWindowExposed(&tree));
    tree.selectJoint(1);
    saveScreenshot(&tree, QStringLiteral("tree_liner_manipulator.png"));

    ModelTree fourBar;
    fourBar.resize(900, 560);
    fourBar.setBundle(loadModel("four_bar.pad"));
    fourBar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&fourBar));
    saveScreenshot(&fourBar, QStringLiteral("tree_four_bar.png"));

    JointSliders sliders;
    sliders.resize(560, 420);
    sliders.setBundle(loadModel("liner_manipulator.pad"));
    sliders.show();
    QVERIFY(QTest::qWaitForWindowExposed(&sliders));
    sliders.spinBox(0)->setValue(30.0);
    saveScreenshot(&sliders, QStringLiteral("sliders_liner_manipulator.png"));

    JointSliders rocker;
    rocker.resize(560, 160);
    rocker.setBundle(bundleOf(QString::fromLatin1(kDoubleRocker)));
    rocker.show();
    QVERIFY(QTest::qWaitForWindowExposed(&rocker));
    rocker.spinBox(0)->setValue(80.0);
    saveScreenshot(&rocker, QStringLiteral("sliders_loop_cannot_close.png"));
}

// The tree and the sliders change language while they are shown: texts, units and
// numbers (1,4 m) in Spanish, the selection and the pose kept; and back to English.
void TreeTest::spanishAtRunTime()
{
    const auto liner = loadModel("liner_manipulator.pad");
    ModelTree tree;
    tree.resize(1000, 760);
    tree.setBundle(liner);
    tree.show();
    QVERIFY(QTest::qWaitForWindowExposed(&tree));
    tree.selectJoint(liner->model->jointIndex(2));
    JointSliders sliders;
    sliders.resize(560, 420);
    sliders.setBundle(liner);
    sliders.show();
    QVERIFY(QTest::qWaitForWindowExposed(&sliders));
    sliders.spinBox(0)->setValue(30.0);
    JointSliders rocker;
    rocker.resize(560, 160);
    rocker.setBundle(bundleOf(QString::fromLatin1(kDoubleRocker)));
    rocker.show();
    QVERIFY(QTest::qWaitForWindowExposed(&rocker));
    rocker.spinBox(0)->setValue(80.0);
    QVERIFY2(rocker.status().startsWith(QStringLiteral("The loops cannot close with C 1 at 80.00°")), qPrintable(rocker.status()));

    QVERIFY(i18n::install("es"));
    QTRY_COMPARE(tree.headerItem()->text(ModelTree::ElementColumn), QStringLiteral("Elemento"));
    QCOMPARE(tree.jointItem(2)->text(ModelTree::TypeColumn), QStringLiteral("actuador pivotado"));
    QCOMPARE(tree.jointItem(2)->text(ModelTree::DetailsColumn), QStringLiteral("1,4 m … 1,617 m"));
    QCOMPARE(tree.jointItem(4)->text(ModelTree::DetailsColumn), QStringLiteral("-65,0° … 65,0°"));
    QCOMPARE(tree.jointItem(1)->text(ModelTree::DriveColumn), QStringLiteral("hidráulico 0,131 rad/s; alivio 54 kN·m"));
    QCOMPARE(tree.bodyItem(1)->text(ModelTree::DetailsColumn), QStringLiteral("sin masa"));
    QCOMPARE(tree.bodyItem(2)->text(ModelTree::DetailsColumn), QStringLiteral("306 kg"));
    QVERIFY(tree.currentItem() && tree.currentItem()->data(0, ModelTree::IdRole).toInt() == 2);  // kept
    QTRY_VERIFY2(sliders.spinBox(0)->text().startsWith(QLatin1String("30,00")), qPrintable(sliders.spinBox(0)->text()));
    QCOMPARE(sliders.spinBox(0)->value(), 30.0);  // the pose stays
    QCOMPARE(sliders.findChild<QPushButton*>()->text(), QStringLiteral("Restablecer postura"));
    QVERIFY2(rocker.status().startsWith(QStringLiteral("Los lazos no pueden cerrarse con C 1 en 80,00°")),
             qPrintable(rocker.status()));
    QTest::qWait(100);  // (the layouts, for the longer texts)
    saveScreenshot(&tree, QStringLiteral("tree_liner_manipulator_es.png"));
    saveScreenshot(&sliders, QStringLiteral("sliders_liner_manipulator_es.png"));
    saveScreenshot(&rocker, QStringLiteral("sliders_loop_cannot_close_es.png"));

    QVERIFY(i18n::install("en"));
    QTRY_COMPARE(tree.headerItem()->text(ModelTree::ElementColumn), QStringLiteral("Element"));
    QCOMPARE(tree.jointItem(2)->text(ModelTree::DetailsColumn), QStringLiteral("1.4 m … 1.617 m"));
    QTRY_VERIFY(sliders.spinBox(0)->text().startsWith(QLatin1String("30.00")));
    QVERIFY(rocker.status().startsWith(QStringLiteral("The loops cannot close with C 1 at 80.00°")));
}

QTEST_MAIN(TreeTest)
#include "tree_test.moc"
