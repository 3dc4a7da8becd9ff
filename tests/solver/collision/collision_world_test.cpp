// Clearances against hand calculations: primitives, the hollow tube, the cone's base,
// prisms, meshes, which pairs count, and the liner manipulator inside the SAG mill.
#include "solver/collision/collision_world.h"

#include "solver/kinematics/kinematics.h"
#include "solver/pipeline.h"
#include "tests/solver/test_models.h"
#include "tests/solver/temp_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace solver;

namespace {

/// A pendulum: body 1 hangs from a pivot at the origin (axis x), its frame 1 m below
/// it at θ = 0; a sphere of radius 0.1 on it.
const char* kPendulum =
    "GRAVITY 0 0 -9.81\n"
    "B 1 1 0.01 0.01 0.01\n"
    "C 1 QI 0\n"
    "B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 -1\n"
    "B2 1 P2 0 0 1 A2 1 0 0 R2 0 0 -1\n"
    "G 1 B 1 SPHERE 0.1\n"
    "G 2 B 0 BOX 0.2 0.2 0.2 POS 0 0 0.3\n";  // the machine's own support, joined through C 1

struct World {
    CompiledModel machine;
    CompiledModel scene;
    std::shared_ptr<const Model> model;
    std::unique_ptr<Data> data;
    std::unique_ptr<CollisionWorld> world;

    World(const std::string& machineText, const std::string& sceneText, const std::string& file = "<text>")
        : machine(compileText(machineText, file)), scene(compileText(sceneText, file))
    {
        model = test::modelOrFail(machine);
        if (!model) return;
        data = std::make_unique<Data>(*model);
        Diagnostics diags;
        world = std::make_unique<CollisionWorld>(machine.spec, *model, &scene.spec, diags);
        EXPECT_FALSE(diags.hasErrors());
    }
    Clearance at(double theta)
    {
        Eigen::VectorXd q = Eigen::VectorXd::Constant(model->nb, theta), qd = Eigen::VectorXd::Zero(model->nb);
        forwardKinematics(*model, q, qd, *data);
        world->update(*data);
        return world->machineToScene();
    }
};

}  // namespace

TEST(CollisionWorld, OverlappingShapesGiveTheirDepthAndTheDeepestPoints)
{
    // floor top at z = −1.05: the hanging sphere (centre −1, radius 0.1) is 5 cm into it
    World w(kPendulum, "G 1 B 0 BOX 4 4 0.2 POS 0 0 -1.15\n");
    ASSERT_TRUE(w.world);
    const Clearance c = w.at(0);
    ASSERT_TRUE(c.valid());
    EXPECT_NEAR(c.distance, -0.05, 1e-4);
    EXPECT_NEAR(c.pointA.z(), -1.1, 1e-4);  // the sphere's lowest point
    EXPECT_NEAR(c.pointB.z(), -1.05, 1e-4); // on the floor's top
    EXPECT_NEAR(c.pointA.x(), 0.0, 1e-4);
    // the pair query the tutorials use says the same
    const Clearance b = w.world->bodyToShapes(0, w.world->sceneShapes({1}));
    EXPECT_NEAR(b.distance, -0.05, 1e-4);
}

TEST(CollisionWorld, SphereAboveAFloorAsThePendulumSwings)
{
    // floor top at z = −1.9: hanging, the sphere's bottom is at −1.1 → 0.8 m
    World w(kPendulum, "G 1 B 0 BOX 4 4 0.2 POS 0 0 -2\n");
    ASSERT_TRUE(w.world);
    ASSERT_EQ(w.world->shapes().size(), 3u);
    Clearance c = w.at(0);
    EXPECT_NEAR(c.distance, 0.8, 1e-9);
    EXPECT_NEAR(c.pointA.z(), -1.1, 1e-6);
    EXPECT_NEAR(c.pointB.z(), -1.9, 1e-6);
    EXPECT_TRUE(w.world->shapes()[std::size_t(c.shapeB)].scene);
    // swung 60°: the centre at z = −cos 60° = −0.5
    c = w.at(std::numbers::pi / 3);
    EXPECT_NEAR(c.distance, 1.9 - 0.5 - 0.1, 1e-9);
    // the support (the machine's ground graphic) would be nearer, but the body hangs from
    // the ground through C 1: that pair does not count
    EXPECT_GT(c.distance, 1.0);
}

TEST(CollisionWorld, TouchingAndOverlappingGiveZeroOrLess)
{
    World w(kPendulum, "G 1 B 0 BOX 4 4 0.2 POS 0 0 -1.15\n");  // top at −1.05: into the sphere
    ASSERT_TRUE(w.world);
    EXPECT_LE(w.at(0).distance, 0.0);
}

TEST(CollisionWorld, InsideAHollowTubeTheClearanceIsToItsBore)
{
    // a tube around the sphere's centre (0, 0, −1), axis y: bore radius 0.5
    World w(kPendulum, "G 1 B 0 TUBE 0.6 0.5 2 POS 0 0 -1 AXIS 0 1 0\n");
    ASSERT_TRUE(w.world);
    // the 64-gon's bore is within 0.5 (1 − cos(π/64)) of the circle
    EXPECT_NEAR(w.at(0).distance, 0.4, 0.5 * (1 - std::cos(std::numbers::pi / 64)) + 1e-9);
}

TEST(CollisionWorld, ConesStandOnTheirBaseAndPrismsAreExtrudedOutlines)
{
    // a cone with its base at z = −1.6 and apex 0.3 above it: 0.2 below the sphere
    World cone(kPendulum, "G 1 B 0 CONE 0.2 0.3 POS 0 0 -1.6\n");
    ASSERT_TRUE(cone.world);
    EXPECT_NEAR(cone.at(0).distance, 0.2, 1e-6);
    // an L-shaped prism (concave outline), its top at z = −1.35: the sphere's centre is
    // over the L's notch, so the nearest is the inner edge x = −0.5, not the top below
    World prism(kPendulum, "G 1 B 0 PRISM 0.1 -1 -1 1 -1 1 -0.5 -0.5 -0.5 -0.5 1 -1 1 POS 0 0 -1.45\n");
    ASSERT_TRUE(prism.world);
    EXPECT_NEAR(prism.at(0).distance, std::hypot(0.5, 0.35) - 0.1, 1e-6);
    // moved so that the L's arm lies under the sphere: straight down, 0.25
    World under(kPendulum, "G 1 B 0 PRISM 0.1 -1 -1 1 -1 1 -0.5 -0.5 -0.5 -0.5 1 -1 1 POS 0.75 0 -1.45\n");
    ASSERT_TRUE(under.world);
    EXPECT_NEAR(under.at(0).distance, 0.25, 1e-6);
}

TEST(CollisionWorld, MeshesComeFromTheirFiles)
{
    test::TempDir dir("collision_mesh");
    dir.write("cube.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                          "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n");
    // the unit cube, moved so that its top is at z = −1.5
    const std::string scene = "G 1 B 0 MESH \"cube.obj\" POS -0.5 -0.5 -2.5\nG 2 B 0 MESH \"missing.obj\"\n";
    const std::string file = dir.path("scene.pad");
    CompiledModel machine = compileText(kPendulum, file);
    CompiledModel sceneModel = compileText(scene, file);
    auto model = test::modelOrFail(machine);
    ASSERT_TRUE(model);
    Diagnostics diags;
    CollisionWorld world(machine.spec, *model, &sceneModel.spec, diags);
    ASSERT_EQ(diags.size(), 1u);  // the missing mesh: left out, said so
    EXPECT_EQ(diags.begin()->code, "collision-shape");
    Data data(*model);
    forwardKinematics(*model, Eigen::VectorXd::Zero(1), Eigen::VectorXd::Zero(1), data);
    world.update(data);
    EXPECT_NEAR(world.machineToScene().distance, 0.4, 1e-6);
}

TEST(CollisionWorld, BetweenBodiesWhateverJoinsThem)
{
    const std::string text = std::string(kPendulum) +
                             "B 2 1 0.01 0.01 0.01\nC 2 T 2 QI 0\nB1 1 P1 0 0 0 A1 1 0 0 R1 0 1 0\n"
                             "B2 2 P2 0 0 0 A2 1 0 0 R2 0 1 0\nG 3 B 2 BOX 0.1 0.1 0.1 POS 0.5 0 0\n";
    World w(text, "");
    ASSERT_TRUE(w.world);
    w.at(0);
    // the box's near face at x = 0.45, the sphere's surface at 0.1
    EXPECT_NEAR(w.world->between(0, 1).distance, 0.35, 1e-6);
}

TEST(CollisionWorld, TheLinerManipulatorStandsClearInsideTheSagMill)
{
    const std::string machinePath = test::modelPath("liner_manipulator.pad");
    const std::string scenePath = std::string(PADROB_SOURCE_DIR) + "/resources/scenes/sag_mill.pad";
    CompiledModel machine = compileFile(machinePath);
    CompiledModel scene = compileFile(scenePath);
    ASSERT_TRUE(scene.ok());
    auto model = test::modelOrFail(machine);
    ASSERT_TRUE(model);
    Diagnostics diags;
    CollisionWorld world(machine.spec, *model, &scene.spec, diags);
    EXPECT_EQ(diags.size(), 0u);
    EXPECT_GT(world.shapes().size(), 200u);
    Data data(*model);
    const State s = makeState(*model);
    forwardKinematics(*model, s, data);
    world.update(data);
    const Clearance c = world.machineToScene();
    ASSERT_TRUE(c.valid());
    // at rest the arm is inside, clear of everything (the nearest: the piston, 0.12 m
    // from the discharge-end grate; the scene's header says why)
    EXPECT_GT(c.distance, 0.1) << world.shapes()[std::size_t(c.shapeA)].describe() << " – "
                               << world.shapes()[std::size_t(c.shapeB)].describe();
    EXPECT_LT(c.distance, 0.2);
    // extended along the mill's axis (telescope out, C 3 = 0.9 m) the arm hits that grate
    State out = s;
    out.q[model->jointIndex(3)] = 0.9;
    forwardKinematics(*model, out, data);
    world.update(data);
    EXPECT_LE(world.machineToScene().distance, 0.0);
    // slewed to the left (+90°), towards the empty liner position at 9 o'clock, the arm
    // half out is clear of the shell; fully out it reaches through that gap to the shell
    // (the liner it carries, 0.43 m thick, would be against the shell well before)
    out.q[model->jointIndex(1)] = std::numbers::pi / 2;
    out.q[model->jointIndex(3)] = 0.3;
    forwardKinematics(*model, out, data);
    world.update(data);
    const Clearance side = world.machineToScene();
    EXPECT_GT(side.distance, 0.0) << world.shapes()[std::size_t(side.shapeA)].describe() << " – "
                                  << world.shapes()[std::size_t(side.shapeB)].describe();
    out.q[model->jointIndex(3)] = 0.9;
    forwardKinematics(*model, out, data);
    world.update(data);
    const Clearance through = world.machineToScene();
    EXPECT_LE(through.distance, 0.0);
    EXPECT_EQ(world.shapes()[std::size_t(through.shapeB)].graphicId, 1);  // the shell itself
}
