// Tutorial T7's task checked as data: the liner manipulator of models/liner_station.pad
// takes the 4,500 kg liner from its cart and carries it to its mounting position in the
// SAG mill (resources/scenes/sag_mill.pad): row 20 (9 o'clock) of the feed-end ring.
//
//  (a) the grasp on the cart (liner_station.pad's header);
//  (b) the mounting target, derived from the scene's numbers (shell and bolt pads), and
//      what keeps the claws from setting the liner there: they hold it by its edge, so the
//      head stands in the plane of the liner beyond that edge, where the neighbouring
//      liners and the shell are; the target is also out of the arm's reach with that grip.
//      A grip on the lifter bar (not in the model yet) seats it from this placement;
//  (c) a path in joint space from the initial pose to the grasp, then, gripped, to the
//      liner presented in front of its slot (as near as the edge grip lets it come),
//      sampled every 3 cm of motion at most: the arm and the liner ≥ 0.05 m from the
//      scene (except where the liner lies on the cart and lifts off it), no worker within
//      1 m, the liner above its z stop (C 12's LL, a plane everywhere).
//
// The waypoints and the target are written into the header of
// resources/scenes/generate_sag_mill.py ("The liner's mounting position and a path to
// it"), where the tutorials take them from; keep both in step.
#include "solver/collision/collision_world.h"
#include "solver/kinematics/inverse.h"
#include "solver/kinematics/kinematics.h"
#include "solver/pipeline.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace solver {
namespace {

using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using Eigen::VectorXd;

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180;

// ---- numbers of liner_station.pad (its header) ----------------------------------------
constexpr double kBackDepth = 0.163301;  ///< the liner's back (its lowest line) under its centre of mass [m]
constexpr double kLinerZStop = 0.228;    ///< C 12's LL: the liner's centre of mass never below [m]

// ---- what the checks ask ----------------------------------------------------------------
constexpr double kClear = 0.05;       ///< machine and liner to the scene [m]
constexpr double kPeople = 1.0;       ///< machine and liner to a worker [m]
constexpr double kStep = 0.03;        ///< largest motion of any point between two samples [m]
constexpr double kPoseTol = 0.02;     ///< the liner where a waypoint says [m] …
constexpr double kAngleTol = 2 * deg;  ///< … and turned as it says [rad]

/// The mounting target (test MountingTargetFollowsFromTheScene derives it from the
/// scene): the liner's centre of mass [m] and its attitude C 13 yaw, C 14 pitch, C 15
/// roll (Z-Y-X) [deg]: length along −y, width downwards, face (z) towards the mill's
/// axis (+x). The liner is symmetric under a half turn about its z: yaw +90°, roll +90°
/// is the same mount.
const Vector3d kMountCom(-4.023099, -0.273650, 0.300000);
const Vector3d kMountAttitude(-90, 0, -90);

/// The grip (at the waypoint "closed"): the liner's centre of mass in the head's frame
/// (body 6) [m]; its axes are the head's turned by kGripPitch about the head's x.
const Vector3d kGripCom(0, 0.764486, 0.067960);
constexpr double kGripPitch = 0.4397 * deg;

/// A waypoint: joints 1–9 in the modeler's coordinates (C 1, C 4, C 6 [rad]; C 2 and
/// C 5 the cylinders' lengths [m]; C 3, C 7, C 8, C 9 [m]), whether the claws hold the
/// liner (welded to the head at the grip), and where the liner then is: its centre of
/// mass [m] and C 13–15 [deg]. Between waypoints the joints' kinematic coordinates θ
/// move linearly (T 1: the angle, not the length).
struct Waypoint {
    const char* name;
    std::array<double, 9> q;
    bool gripped;
    Vector3d com;
    Vector3d attitude;
};

// clang-format off
const std::vector<Waypoint> kPath = {
    // the manipulator's initial pose (QI); the liner lies on its cart
    {"start",   {0, 1.464, 0, 0, 0.412, 0, 0.075, 0, 0}, false, {4.1378, 0, 0.2280}, {-90, 0, 0}},
    // slewed to the cart, the open claws 0.30 m before the liner's near edge, at its height
    {"front",   {-1.570796, 1.460950, 0.150000, 0, 0.413000, 0, 0.075, 0, 0}, false, {4.1378, 0, 0.2280}, {-90, 0, 0}},
    // telescope out: the open claws around the edge (liner_station.pad's grasp)
    {"grasp",   {-1.570796, 1.460950, 0.450000, 0, 0.413000, 0, 0.075, 0, 0}, false, {4.1378, 0, 0.2280}, {-90, 0, 0}},
    // claws closed on the plate; from here the liner moves with the head
    {"closed",  {-1.570796, 1.460950, 0.450000, 0, 0.413000, 0, 0.075, -0.1397, 0.1415}, true, {4.1378, 0, 0.2280}, {-90, 0, 0}},
    // lifted 0.25 m, level
    {"lift",    {-1.570796, 1.478151, 0.431222, 0, 0.403152, 0, 0.075, -0.1397, 0.1415}, true, {4.1378, 0, 0.4780}, {-90, 0, 0}},
    // pulled 0.40 m back over the cart's near end, level
    {"pull",    {-1.570796, 1.480480, 0.028893, 0, 0.401747, 0, 0.075, -0.1397, 0.1415}, true, {3.7378, 0, 0.4780}, {-90, 0, 0}},
    // boom up, wrist down to keep it level: the liner 1.6 m up, clear of the cart
    {"raise",   {-1.570796, 1.567000, 0, 0, 0.333342, 0, 0.075, -0.1397, 0.1415}, true, {3.4708, 0, 1.6243}, {-90, 0, 0}},
    // head rolled a half turn: the liner upside down (its face will look back at the arm)
    {"roll",    {-1.570796, 1.567000, 0, 0, 0.333342, 3.141593, 0.075, -0.1397, 0.1415}, true, {3.4697, 0, 1.4884}, {90, 0, -179.12}},
    // boom at the top, wrist nose down: the liner hangs 51° from level, 2.75 m out
    {"tilt",    {-1.570796, 1.610000, 0, 0, 0.100000, 3.141593, 0.075, -0.1397, 0.1415}, true, {2.7484, 0, 1.0728}, {90, 0, -129.10}},
    // slewed 183° through the discharge end's side (+y) to the empty row at 9 o'clock
    {"swing",   {1.623156, 1.610000, 0, 0, 0.100000, 3.141593, 0.075, -0.1397, 0.1415}, true, {-2.7447, -0.1438, 1.0728}, {-87, 0, -129.10}},
    // lowered and turned as mounted, in front of its slot: as near as the head lets it come
    {"present", {1.640381, 1.564252, 0.638685, 0.001028, 0.044000, 3.212055, 0.075, -0.1397, 0.1415}, true, {-3.0001, -0.2137, 0.2999}, {-90, 0, -90.02}},
};

/// A grip on the lifter bar, for the station's redesign (not in liner_station.pad): the
/// claws close across the lifter (the head's z along the liner's width y), the head
/// looking at the liner's face (its y = the liner's −z), the teeth's centre line 0.2 m
/// above the centre of mass (liner z 0.17 … 0.23, where the lifter is 0.29 … 0.26 m
/// wide): the liner's centre of mass at (0, 0.68, 0) in the head's frame. Teeth on the
/// lifter at C 8 = −0.086, C 9 = +0.086; the piston's pad on its top at C 7 = 0.17.
const std::vector<Waypoint> kLifterGrip = {
    // the liner aligned with its slot, 0.30 m out towards the mill's axis
    {"pre-seat", {1.688839, 1.470693, 0.125355, -0.118115, 0.408428, 3.137440, 0.17, -0.086, 0.086}, true, {-3.723099, -0.273650, 0.3}, {-90, 0, -90}},
    // on its seat
    {"seat",     {1.675318, 1.469965, 0.424419, -0.104574, 0.408836, 3.138300, 0.17, -0.086, 0.086}, true, {-4.023099, -0.273650, 0.3}, {-90, 0, -90}},
};
// clang-format on

Matrix3d attitude(const Vector3d& yprDeg)
{
    return (Eigen::AngleAxisd(yprDeg[0] * deg, Vector3d::UnitZ()) *
            Eigen::AngleAxisd(yprDeg[1] * deg, Vector3d::UnitY()) *
            Eigen::AngleAxisd(yprDeg[2] * deg, Vector3d::UnitX()))
        .toRotationMatrix();
}

double angleBetween(const Matrix3d& a, const Matrix3d& b)
{
    return std::abs(Eigen::AngleAxisd(Matrix3d(a * b.transpose())).angle());
}

/// The angle to a mount attitude, either way round (the liner's half-turn symmetry).
double angleToMount(const Matrix3d& r, const Matrix3d& mount)
{
    const Matrix3d flipped = mount * Eigen::AngleAxisd(pi, Vector3d::UnitZ()).toRotationMatrix();
    return std::min(angleBetween(r, mount), angleBetween(r, flipped));
}

/// The liner's grip for a lifter-bar grasp (kLifterGrip): the liner in the head's frame.
Isometry3d lifterGrip()
{
    Matrix3d headInLiner;  // columns: the head's axes in the liner's frame
    headInLiner.col(0) = Vector3d::UnitX();
    headInLiner.col(1) = -Vector3d::UnitZ();
    headInLiner.col(2) = Vector3d::UnitY();
    Isometry3d X = Isometry3d::Identity();
    X.linear() = headInLiner.transpose();
    X.translation() = Vector3d(0, 0.68, 0);
    return X;
}

bool isWorker(const GraphicSpec& g)
{
    // the scene's people: legs, vest, head, hard hat (generate_sag_mill.py)
    for (const Vector3d& c : {Vector3d(0.15, 0.20, 0.45), Vector3d(0.95, 0.45, 0.05), Vector3d(0.80, 0.62, 0.50),
                              Vector3d(0.95, 0.90, 0.10)})
        if ((g.color - c).norm() < 1e-9) return true;
    return false;
}

/// Clearances of one pose [m] (≤ 0: touching or overlapping).
struct Clearances {
    double arm = 1e9;     ///< bodies 1–9 to the scene (and the machine's own ground graphics)
    double liner = 1e9;   ///< the liner to the scene, the cart included
    double people = 1e9;  ///< bodies 1–9 and (when held) the liner to the workers
    double self = 1e9;    ///< the held liner to the boom, telescope, wrist and rocker (bodies 2–5)
    std::string armWhat, linerWhat;
};

/// The station in the mill: the model, the scene, and clearance worlds against the
/// scene and against its workers alone.
struct Station {
    CompiledModel machine = compileFile(test::modelPath("liner_station.pad"));
    CompiledModel scene = compileFile(std::string(PADROB_SOURCE_DIR) + "/resources/scenes/sag_mill.pad");
    std::shared_ptr<const Model> model;
    std::unique_ptr<Data> data;
    std::unique_ptr<CollisionWorld> world, people;
    int head = -1, liner = -1;
    std::vector<int> arm;     // tree indices of bodies 1–9
    std::vector<int> joints;  // tree indices of joints 1–9
    VectorXd qi;
    Isometry3d grip = Isometry3d::Identity();  // the liner in the head's frame, at "closed"

    Station()
    {
        EXPECT_TRUE(scene.ok());
        model = test::modelOrFail(machine);
        if (!model || !scene.ok()) return;
        data = std::make_unique<Data>(*model);
        Diagnostics diags;
        world = std::make_unique<CollisionWorld>(machine.spec, *model, &scene.spec, diags);
        // the workers alone, against the moving bodies alone
        ModelSpec workers = scene.spec;
        std::erase_if(workers.graphics, [](const GraphicSpec& g) { return !isWorker(g); });
        EXPECT_EQ(workers.graphics.size(), 8u);
        ModelSpec moving = machine.spec;
        std::erase_if(moving.graphics, [](const GraphicSpec& g) { return g.body == 0; });
        people = std::make_unique<CollisionWorld>(moving, *model, &workers, diags);
        EXPECT_FALSE(diags.hasErrors());
        head = model->bodyIndex(6);
        liner = model->bodyIndex(15);
        for (int id = 1; id <= 9; ++id) {
            arm.push_back(model->bodyIndex(id));
            joints.push_back(model->jointIndex(id));
        }
        qi = makeState(*model).q;
        forwardKinematics(*model, theta(kPath[3].q), VectorXd::Zero(model->nb), *data);
        grip = data->X_wb[std::size_t(head)].inverse() * data->X_wb[std::size_t(liner)];
    }
    bool ok() const { return model && world && people; }

    /// θ for joints 1–9 at the modeler's coordinates q, the liner at its QI.
    VectorXd theta(const std::array<double, 9>& q) const
    {
        VectorXd th = qi;
        for (int k = 0; k < 9; ++k) {
            const int i = joints[std::size_t(k)];
            th[i] = model->jointType[std::size_t(i)] == JointType::Actuator
                        ? *model->lengthLaw[std::size_t(i)].angleNear(q[std::size_t(k)], model->theta0[std::size_t(i)])
                        : q[std::size_t(k)];
        }
        return th;
    }
    /// The liner's joints C 10–15 for its pose X_wl (attitude Rz·Ry·Rx).
    void placeLiner(VectorXd& th, const Isometry3d& X) const
    {
        const Matrix3d& R = X.linear();
        th[model->jointIndex(10)] = X.translation().x();
        th[model->jointIndex(11)] = X.translation().y();
        th[model->jointIndex(12)] = X.translation().z();
        th[model->jointIndex(13)] = std::atan2(R(1, 0), R(0, 0));
        th[model->jointIndex(14)] = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
        th[model->jointIndex(15)] = std::atan2(R(2, 1), R(2, 2));
    }
    /// Kinematics at th; with `held` the liner is put where the head holds it (X_hl).
    void pose(VectorXd& th, const Isometry3d* held)
    {
        forwardKinematics(*model, th, VectorXd::Zero(model->nb), *data);
        if (!held) return;
        placeLiner(th, data->X_wb[std::size_t(head)] * *held);
        forwardKinematics(*model, th, VectorXd::Zero(model->nb), *data);
    }
    Isometry3d linerPose() const { return data->X_wb[std::size_t(liner)]; }

    /// Clearances at the kinematics in data.
    Clearances clearances(bool held)
    {
        Clearances c;
        world->update(*data);
        people->update(*data);
        for (int b : arm) {
            const Clearance k = world->bodyToScene(b);
            if (k.valid() && k.distance < c.arm) {
                c.arm = k.distance;
                c.armWhat = world->shapes()[std::size_t(k.shapeA)].describe() + " – " +
                            world->shapes()[std::size_t(k.shapeB)].describe();
            }
            c.people = std::min(c.people, people->bodyToScene(b).distance);
        }
        const Clearance l = world->bodyToScene(liner);
        c.liner = l.distance;
        if (l.valid()) c.linerWhat = world->shapes()[std::size_t(l.shapeB)].describe();
        if (held) {
            c.people = std::min(c.people, people->bodyToScene(liner).distance);
            for (int id = 2; id <= 5; ++id) c.self = std::min(c.self, world->between(model->bodyIndex(id), liner).distance);
        }
        return c;
    }

    /// Samples of the straight line in θ from a to b (joints 1–9), no point of the
    /// machine or of the liner moving more than kStep between two: a point within 5 m of
    /// every rotation axis moves at most 5 m·|Δθ| per turn, 1:1 per slide.
    std::vector<VectorXd> samples(const std::array<double, 9>& a, const std::array<double, 9>& b) const
    {
        const VectorXd ta = theta(a), tb = theta(b);
        double bound = 0;
        for (int i : joints)
            bound += std::abs(tb[i] - ta[i]) * (model->jointType[std::size_t(i)] == JointType::Prismatic ? 1.0 : 5.0);
        const int n = std::max(1, int(std::ceil(bound / kStep)));
        std::vector<VectorXd> out;
        for (int s = 0; s <= n; ++s) out.push_back(ta + (tb - ta) * (double(s) / n));
        return out;
    }
};

/// The bolt pads of the empty position: the scene's CYL 0.045 × 0.02 discs.
std::vector<const GraphicSpec*> boltPads(const ModelSpec& scene)
{
    std::vector<const GraphicSpec*> pads;
    for (const GraphicSpec& g : scene.graphics)
        if (g.shape == ShapeKind::Cylinder && g.dims.size() == 2 && std::abs(g.dims[0] - 0.045) < 1e-9 &&
            std::abs(g.dims[1] - 0.02) < 1e-9)
            pads.push_back(&g);
    return pads;
}

// ------------------------------------------------------------------------- (b) the target

TEST(LinerMillReach, MountingTargetFollowsFromTheScene)
{
    Station st;
    ASSERT_TRUE(st.ok());
    // the shell (G 1): a tube along the mill's axis; its bore is the liners' seat
    const GraphicSpec* shell = nullptr;
    for (const GraphicSpec& g : st.scene.spec.graphics)
        if (g.id == 1) shell = &g;
    ASSERT_TRUE(shell && shell->shape == ShapeKind::Tube);
    const double radius = shell->dims[1];
    EXPECT_NEAR(radius, 36 * 0.3048 / 2, 1e-4);  // 36'-0" mill: true size
    const Vector3d axisDir = shell->axis.normalized();
    // the four bolt pads: their centre and their axis (the radial direction, outwards)
    const auto pads = boltPads(st.scene.spec);
    ASSERT_EQ(pads.size(), 4u);
    Vector3d centre = Vector3d::Zero();
    for (const GraphicSpec* p : pads) centre += p->position / 4;
    const Vector3d out = pads[0]->axis.normalized();
    Vector3d onAxis = shell->position + axisDir * axisDir.dot(centre - shell->position);
    EXPECT_NEAR((centre - onAxis).normalized().dot(out), 1.0, 1e-9);

    // the liner's back on the bore: its centre of mass kBackDepth inside it; its face
    // towards the axis, its length along the axis, its width round the shell (downwards)
    const Vector3d com = onAxis + (radius - kBackDepth) * out;
    Matrix3d mount;
    mount.col(2) = -out;
    mount.col(0) = -axisDir;
    mount.col(1) = mount.col(2).cross(mount.col(0));
    EXPECT_LT((com - kMountCom).norm(), 1e-6) << com.transpose();
    EXPECT_LT(angleBetween(mount, attitude(kMountAttitude)), 1e-9);
    // 9 o'clock, the feed-end ring's middle, at the axis' height
    EXPECT_NEAR(out.x(), -1.0, 1e-9);
    // above the liner's z stop, so that a mounted liner is not held up by it
    EXPECT_GT(com.z(), kLinerZStop + 0.05);

    // the pads are under the liner's bolt holes: ±0.85 m along it, ±0.2 m across, on its back
    Isometry3d X = Isometry3d::Identity();
    X.linear() = mount;
    X.translation() = com;
    for (const GraphicSpec* p : pads) {
        const Vector3d local = X.inverse() * p->position;
        EXPECT_NEAR(std::abs(local.x()), 0.85, 1e-4);  // the scene has 4 decimals
        EXPECT_NEAR(std::abs(local.y()), 0.2, 1e-4);
        EXPECT_NEAR(local.z(), -(kBackDepth - 0.01), 1e-3);  // the pads' middle, 10 mm proud of the bore
    }

    // the slot is empty: the liner set on its seat touches (the pads), and drawn back
    // along the radius towards the axis it is free of the neighbours all the way out,
    // so that it can go in straight (the drawn plates leave room for its wider back)
    VectorXd th = st.qi;
    st.placeLiner(th, X);
    st.pose(th, nullptr);
    EXPECT_LE(st.clearances(false).liner, 0.0);
    for (double d = 0.03; d <= 0.6; d += 0.01) {
        Isometry3d Y = X;
        Y.translation() -= d * out;
        st.placeLiner(th, Y);
        st.pose(th, nullptr);
        const Clearances c = st.clearances(false);
        EXPECT_GT(c.liner, 0.0) << "drawn back " << d << " m: " << c.linerWhat;
    }
}

// ------------------------------------------------------------------------- (a) the grasp

TEST(LinerMillReach, GraspOnTheCart)
{
    Station st;
    ASSERT_TRUE(st.ok());
    const Model& m = *st.model;
    // the liner at its QI, lying on the cart
    VectorXd th = st.theta(kPath[2].q);
    st.pose(th, nullptr);
    const Isometry3d X_wl = st.linerPose();
    EXPECT_LT((X_wl.translation() - Vector3d(4.137788, 0, 0.228)).norm(), 1e-9);
    // the head's grip point on the liner's (liner_station.pad: THE GRIP)
    const Vector3d headGrip = st.data->X_wb[std::size_t(st.head)] * Vector3d(0, 0.48, 0);
    const Vector3d linerGrip = X_wl * Vector3d(0, -0.285, -0.065767);
    EXPECT_LT((headGrip - linerGrip).norm(), 1e-4);
    // open, the teeth clear the plate; nothing of the arm within 5 cm of the cart (the
    // lower claw passes under the liner's overhanging edge, 6.9 cm over the deck)
    Clearances c = st.clearances(false);
    EXPECT_GE(c.arm, kClear) << c.armWhat;
    EXPECT_GT(st.world->between(m.bodyIndex(8), st.liner).distance, 0.03);
    EXPECT_GT(st.world->between(m.bodyIndex(9), st.liner).distance, 0.03);
    // closed, they hold the plate
    th = st.theta(kPath[3].q);
    st.pose(th, nullptr);
    c = st.clearances(false);
    EXPECT_GE(c.arm, kClear) << c.armWhat;
    EXPECT_LE(st.world->between(m.bodyIndex(8), st.liner).distance, 1e-3);
    EXPECT_LE(st.world->between(m.bodyIndex(9), st.liner).distance, 1e-3);
    // the grip: what the head holds from here on
    EXPECT_LT((st.grip.translation() - kGripCom).norm(), 1e-5) << st.grip.translation().transpose();
    EXPECT_LT(angleBetween(st.grip.linear(), Eigen::AngleAxisd(kGripPitch, Vector3d::UnitX()).toRotationMatrix()),
              1e-5);
    // the liner lies on its z stop, on the timbers (touching)
    EXPECT_NEAR(th[m.jointIndex(12)], kLinerZStop, 1e-12);
    EXPECT_LE(c.liner, 1e-3) << c.linerWhat;
}

// ------------------------------------------------------------------------- (c) the path

TEST(LinerMillReach, PathFromTheStartToTheSlotIsClear)
{
    Station st;
    ASSERT_TRUE(st.ok());
    const Model& m = *st.model;
    const double restZ = kPath.front().com.z();

    // every waypoint puts the liner where it says
    for (const Waypoint& w : kPath) {
        VectorXd th = st.theta(w.q);
        st.pose(th, w.gripped ? &st.grip : nullptr);
        const Isometry3d X = st.linerPose();
        EXPECT_LT((X.translation() - w.com).norm(), kPoseTol) << w.name << ": " << X.translation().transpose();
        EXPECT_LT(angleBetween(X.linear(), attitude(w.attitude)), kAngleTol) << w.name;
        // within the joints' limits, the cylinders' lengths included
        for (int k = 0; k < 9; ++k) {
            const int i = st.joints[std::size_t(k)];
            EXPECT_GE(th[i], m.lower[std::size_t(i)] - 1e-9) << w.name << " C " << k + 1;
            EXPECT_LE(th[i], m.upper[std::size_t(i)] + 1e-9) << w.name << " C " << k + 1;
        }
    }
    // the last one: turned as mounted, in front of the slot, 1.02 m short of the seat
    const Waypoint& last = kPath.back();
    EXPECT_LT(angleToMount(attitude(last.attitude), attitude(kMountAttitude)), 0.1 * deg);
    EXPECT_NEAR((last.com - kMountCom).x(), 1.023, 0.01);

    // between them, sampled
    int samples = 0;
    double worstArm = 1e9, worstLiner = 1e9, worstPeople = 1e9, worstSelf = 1e9, lowest = 1e9;
    for (std::size_t k = 1; k < kPath.size(); ++k) {
        const Waypoint& a = kPath[k - 1];
        const Waypoint& b = kPath[k];
        const bool held = a.gripped && b.gripped;
        const bool liftOff = a.q == kPath[3].q;  // from "closed": the liner leaves the cart
        const std::vector<VectorXd> line = st.samples(a.q, b.q);
        std::vector<Vector3d> last;  // tracked points of the previous sample
        for (VectorXd th : line) {
            ++samples;
            st.pose(th, held ? &st.grip : nullptr);
            const Clearances c = st.clearances(held);
            const std::string at = std::string(a.name) + " → " + b.name;
            // the sampling: no tracked point (liner corners, head, claws' tips, boom nose)
            // moves more than kStep between samples
            const Isometry3d L = st.linerPose();
            std::vector<Vector3d> points;
            for (double x : {-1.275, 1.275})
                for (double y : {-0.425, 0.425})
                    for (double z : {-0.163, 0.27}) points.push_back(L * Vector3d(x, y, z));
            points.push_back(st.data->X_wb[std::size_t(st.head)].translation());
            points.push_back(st.data->X_wb[std::size_t(m.bodyIndex(8))] * Vector3d(0, 0.36, 0));
            points.push_back(st.data->X_wb[std::size_t(m.bodyIndex(9))] * Vector3d(0, 0.36, 0));
            points.push_back(st.data->X_wb[std::size_t(m.bodyIndex(2))] * Vector3d(0, 0.85, 0));
            if (!last.empty()) {
                for (std::size_t p = 0; p < points.size(); ++p) EXPECT_LE((points[p] - last[p]).norm(), kStep + 1e-9) << at;
            }
            last = points;

            EXPECT_GE(c.arm, kClear) << at << ": " << c.armWhat;
            EXPECT_GE(c.people, kPeople) << at;
            worstArm = std::min(worstArm, c.arm);
            worstPeople = std::min(worstPeople, c.people);
            if (!held) {
                // the liner lies on the cart; the open claws come round its edge without touching it
                if (b.q[7] == 0) {
                    EXPECT_GT(st.world->between(m.bodyIndex(8), st.liner).distance, 0.0) << at;
                    EXPECT_GT(st.world->between(m.bodyIndex(9), st.liner).distance, 0.0) << at;
                }
                continue;
            }
            const double z = th[m.jointIndex(12)];
            EXPECT_GE(c.self, kClear) << at;
            worstSelf = std::min(worstSelf, c.self);
            if (liftOff && z < restZ + 2 * kClear) {
                // lifting off the timbers: clear of them by about its height
                EXPECT_GE(c.liner, 0.5 * (z - restZ) - 1e-9) << at << ": " << c.linerWhat;
                continue;
            }
            EXPECT_GE(c.liner, kClear) << at << ": " << c.linerWhat;
            EXPECT_GE(z, kLinerZStop + kClear) << at;
            worstLiner = std::min(worstLiner, c.liner);
            lowest = std::min(lowest, z);
        }
    }
    EXPECT_GT(samples, 1000);
    // the margins (for the header): arm 6.7 cm (the lower claw over the cart's deck),
    // liner 6.1 cm (the feed-end head, presented), people 1.08 m, liner to the arm 0.54 m,
    // the liner's centre of mass 0.30 m up (presented)
    RecordProperty("samples", samples);
    RecordProperty("arm", std::to_string(worstArm));
    RecordProperty("liner", std::to_string(worstLiner));
    RecordProperty("people", std::to_string(worstPeople));
    RecordProperty("self", std::to_string(worstSelf));
    RecordProperty("lowest", std::to_string(lowest));
}

// ------------------------------------------------------------- (b) why not to the seat

TEST(LinerMillReach, TheEdgeGripCannotSeatTheLiner)
{
    Station st;
    ASSERT_TRUE(st.ok());
    const Model& m = *st.model;
    Isometry3d seat = Isometry3d::Identity();
    seat.linear() = attitude(kMountAttitude);
    seat.translation() = kMountCom;

    // out of reach: the nearest the arm (joints 1–6) gets with the liner so held
    IkFrame frame{st.head, st.grip};
    IkTarget target;
    target.position = seat.translation();
    target.orientation = seat.linear();
    IkOptions opt;
    for (int id = 1; id <= 6; ++id) opt.joints.push_back(m.jointIndex(id));
    opt.restarts = 20;
    const IkResult r = inverseKinematics(m, frame, target, st.theta(kPath.back().q), *st.data, opt);
    EXPECT_FALSE(r.converged);
    EXPECT_GT(r.positionError, 0.2);
    RecordProperty("nearest", std::to_string(r.positionError) + " m, " + std::to_string(r.angleError / deg) + " deg");

    // and out of room: wherever the arm is, a head holding the liner by its edge stands
    // above it in its plane, its mast reaching 0.38 m beyond the liner's back: with the
    // liner on its seat the head is in the row above and in the shell. Moved out along
    // the radius with it, the head clears the scene only when the liner is ~0.9 m out.
    VectorXd th = st.theta(kPath.back().q);
    st.pose(th, &st.grip);
    const std::vector<Isometry3d> X = st.data->X_wb;
    const Isometry3d held = st.linerPose();
    double clearFrom = -1;
    for (double d = 0; d <= 1.2; d += 0.02) {
        Isometry3d Y = seat;
        Y.translation().x() += d;  // towards the axis
        const Isometry3d move = Y * held.inverse();
        st.data->X_wb = X;
        for (int id : {6, 7, 8, 9, 15}) st.data->X_wb[std::size_t(m.bodyIndex(id))] = move * X[std::size_t(m.bodyIndex(id))];
        st.world->update(*st.data);
        double headGroup = 1e9;
        for (int id : {6, 7, 8, 9}) headGroup = std::min(headGroup, st.world->bodyToScene(m.bodyIndex(id)).distance);
        if (d == 0) {
            EXPECT_LE(headGroup, 0.0);
        }
        if (headGroup > 0 && clearFrom < 0) clearFrom = d;
    }
    EXPECT_GT(clearFrom, 0.8);
    RecordProperty("head clear from", std::to_string(clearFrom));
}

TEST(LinerMillReach, ALifterGripWouldSeatItFromThisPlacement)
{
    Station st;
    ASSERT_TRUE(st.ok());
    const Model& m = *st.model;
    const Isometry3d grip = lifterGrip();
    // the waypoints put the liner where they say: aligned 0.30 m out, then on its seat
    for (const Waypoint& w : kLifterGrip) {
        VectorXd th = st.theta(w.q);
        st.pose(th, &grip);
        const Isometry3d X = st.linerPose();
        EXPECT_LT((X.translation() - w.com).norm(), kPoseTol) << w.name;
        EXPECT_LT(angleBetween(X.linear(), attitude(w.attitude)), kAngleTol) << w.name;
        for (int i : st.joints) {
            EXPECT_GE(th[i], m.lower[std::size_t(i)] - 1e-9) << w.name;
            EXPECT_LE(th[i], m.upper[std::size_t(i)] + 1e-9) << w.name;
        }
    }
    const Waypoint& seat = kLifterGrip.back();
    EXPECT_LT((seat.com - kMountCom).norm(), 1e-6);
    EXPECT_LT(angleToMount(attitude(seat.attitude), attitude(kMountAttitude)), 1e-9);
    // IK finds the seat from the pre-seat pose
    IkFrame frame{st.head, grip};
    IkTarget target;
    target.position = kMountCom;
    target.orientation = attitude(kMountAttitude);
    IkOptions opt;
    for (int id = 1; id <= 6; ++id) opt.joints.push_back(m.jointIndex(id));
    const IkResult r = inverseKinematics(m, frame, target, st.theta(kLifterGrip.front().q), *st.data, opt);
    ASSERT_TRUE(r.converged);
    for (int id = 1; id <= 6; ++id)
        EXPECT_NEAR(m.coordinate(m.jointIndex(id), r.theta[m.jointIndex(id)]), seat.q[std::size_t(id - 1)], 2e-6) << "C " << id;
    // pushed in straight: the arm ≥ 5 cm from everything, the liner free until its back
    // meets the bolt pads (proud of the bore by 20 mm), people far
    const std::vector<VectorXd> line = st.samples(kLifterGrip.front().q, seat.q);
    for (VectorXd th : line) {
        st.pose(th, &grip);
        const Clearances c = st.clearances(true);
        EXPECT_GE(c.arm, kClear) << c.armWhat;
        EXPECT_GE(c.self, kClear);
        EXPECT_GE(c.people, kPeople);
        const double out = st.linerPose().translation().x() - kMountCom.x();
        if (out > 0.02) {
            EXPECT_GT(c.liner, 0.0) << out << " m out: " << c.linerWhat;
        }
    }
    // on the seat it touches the pads
    VectorXd th = st.theta(seat.q);
    st.pose(th, &grip);
    EXPECT_LE(st.clearances(true).liner, 0.0);
    // but it cannot be taken so from where the cart stands: the head would have to
    // look down on the lifter 4.1 m out, beyond its reach
    VectorXd rest = st.qi;
    st.pose(rest, nullptr);
    target.position = st.linerPose().translation();
    target.orientation = st.linerPose().linear();
    opt.restarts = 20;
    const IkResult onCart = inverseKinematics(m, frame, target, st.theta(kPath[2].q), *st.data, opt);
    EXPECT_FALSE(onCart.converged);
    EXPECT_GT(onCart.positionError, 0.1);
}

}  // namespace
}  // namespace solver
