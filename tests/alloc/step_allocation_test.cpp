// The step loop allocates nothing (issue 3, "Speed"): a binary of its own, because it
// replaces the global operator new to count allocations.

#include "solver/dynamics/applied_forces.h"
#include "solver/dynamics/forward_dynamics.h"
#include "solver/integrate/simulation.h"
#include "solver/kinematics/kinematics.h"
#include "bench/generate.h"
#include "solver/pipeline.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_allocations{0};
}

// the replacements below pair malloc with free on purpose
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t n)
{
    ++g_allocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace {

std::shared_ptr<const solver::Model> liner()
{
    solver::CompiledModel loaded = solver::compileFile(std::string(PADROB_SOURCE_DIR) + "/models/liner_manipulator.pad");
    EXPECT_TRUE(loaded.ok());
    return loaded.model;
}

}  // namespace

TEST(StepAllocation, TheCounterCounts)
{
    const long before = g_allocations;
    auto* v = new std::vector<double>(10);
    delete v;
    EXPECT_EQ(g_allocations - before, 2);  // the vector and its buffer
}

TEST(StepAllocation, ForwardDynamicsAllocatesNothing)
{
    auto model = liner();
    ASSERT_TRUE(model);
    solver::State state = solver::makeState(*model);
    solver::Data data(*model);
    state.u.setConstant(0.5);
    const long before = g_allocations;
    for (int k = 0; k < 100; ++k) {
        solver::forwardKinematics(*model, state, data);
        solver::applyForces(*model, state, data);
        solver::hybridDynamics(*model, state, data);
    }
    EXPECT_EQ(g_allocations - before, 0);
}

TEST(StepAllocation, Rk4StepsWithEventFunctionsAllocateNothing)
{
    auto model = liner();
    ASSERT_TRUE(model);
    solver::SimulationOptions o;  // RK4 at 1 ms, limits and relief valves watched
    solver::Simulation sim(model, o);
    std::vector<solver::SimulationEvent> events;
    events.reserve(16);
    std::string error;
    sim.setCommand(model->jointIndex(3), 1.0);  // the telescope extends
    ASSERT_TRUE(sim.advanceTo(0.01, events, error)) << error;  // the restart after the command
    const long before = g_allocations;
    for (int k = 2; k <= 500; ++k) ASSERT_TRUE(sim.advanceTo(0.005 * k, events, error));
    EXPECT_EQ(g_allocations - before, 0) << "allocations in 499 output steps of 5 ms (2,495 RK4 steps)";
    EXPECT_GT(sim.state().q[model->jointIndex(3)], 0.2);
}

namespace {

std::shared_ptr<const solver::Model> fromText(const std::string& text)
{
    solver::CompiledModel loaded = solver::compileText(text, "generated.pad");
    EXPECT_TRUE(loaded.ok());
    return loaded.model;
}

/// Steps of 1 ms with every drive's command changed before every step (a sine per
/// drive, as an operator's sticks); returns the allocations counted over `steps` steps
/// after a warm-up second.
long commandedStepAllocations(const std::shared_ptr<const solver::Model>& model, int steps, int* events)
{
    solver::Simulation sim(model, solver::SimulationOptions{});
    std::vector<solver::SimulationEvent> ev;
    ev.reserve(100000);
    std::string error;
    auto command = [&](int k) {
        for (int j = 0; j < model->nb; ++j) {
            if (model->drive[j].type != solver::DriveType::None)
                sim.setCommand(j, 0.8 * std::sin(2 * M_PI * 0.5 * k * 1e-3 + j));
        }
    };
    for (int k = 1; k <= 1000; ++k) {
        command(k);
        EXPECT_TRUE(sim.advanceTo(k * 1e-3, ev, error)) << error;
    }
    const std::size_t eventsBefore = ev.size();
    const long before = g_allocations;
    for (int k = 1001; k <= 1000 + steps; ++k) {
        command(k);
        if (!sim.advanceTo(k * 1e-3, ev, error)) {
            ADD_FAILURE() << error;
            break;
        }
    }
    const long counted = g_allocations - before;
    *events = static_cast<int>(ev.size() - eventsBefore);
    return counted;
}

}  // namespace

TEST(StepAllocation, ANewCommandEveryStepAllocatesNothing)
{
    // the liner manipulator: every joint hydraulic, each step restarts after a new command
    int events = 0;
    EXPECT_EQ(commandedStepAllocations(liner(), 2000, &events), 0) << "2000 RK4 steps with new commands";
}

TEST(StepAllocation, TheFluidPowerLinerAllocatesNothing)
{
    // one load-sensing pump, nine valve sections, the chambers' pressures as states:
    // pump saturation (the supply solved for), reliefs, cavitation events and sub-steps
    solver::CompiledModel loaded =
        solver::compileFile(std::string(PADROB_SOURCE_DIR) + "/models/liner_manipulator_fluid.pad");
    ASSERT_TRUE(loaded.ok());
    ASSERT_FALSE(loaded.model->circuits.empty());
    int events = 0;
    EXPECT_EQ(commandedStepAllocations(loaded.model, 2000, &events), 0) << "2000 RK4 steps with new commands";
}

TEST(StepAllocation, ImpulsesOnFreeJointsAllocateNothing)
{
    // a chain with passive joints between the drives: every new command gives the free
    // joints an impulse (the articulated-body algorithm with impulses), and the passive
    // joints hit and leave their limits
    int events = 0;
    EXPECT_EQ(commandedStepAllocations(fromText(bench::chainModelText(30)), 2000, &events), 0)
        << "2000 RK4 steps of a 30-link chain";
    EXPECT_GT(events, 0) << "the limits were to be hit on the way";
}

TEST(StepAllocation, ABurstHoseAllocatesNothingInTheStepLoop)
{
    // the boom's hose bursts (issue 10): the boom falls with its cylinder passive, every
    // other valve commanded every step, until the boom lands on its stop (an event)
    auto model = liner();
    ASSERT_TRUE(model);
    solver::Simulation sim(model, solver::SimulationOptions{});
    std::vector<solver::SimulationEvent> events;
    events.reserve(10000);
    std::string error;
    const int boom = model->jointIndex(2);
    ASSERT_TRUE(sim.advanceTo(0.01, events, error)) << error;
    ASSERT_TRUE(sim.setDriveFault(boom, solver::DriveFault{2e4}));  // injected between steps
    ASSERT_TRUE(sim.advanceTo(0.02, events, error)) << error;
    const double before0 = sim.state().q[boom];
    const long before = g_allocations;
    for (int k = 3; k <= 2000; ++k) {
        for (int j = 0; j < model->nb; ++j) sim.setCommand(j, 0.5 * std::sin(0.003 * k + j));
        if (!sim.advanceTo(0.01 * k, events, error)) {
            ADD_FAILURE() << error;
            break;
        }
    }
    EXPECT_EQ(g_allocations - before, 0) << "allocations in 1998 steps of 10 ms with a burst hose";
    EXPECT_NE(sim.state().q[boom], before0);  // it moved
    bool landed = false;
    for (const solver::SimulationEvent& e : events)
        landed = landed || (e.kind == solver::SimulationEvent::Kind::LimitHit && e.joint == boom);
    EXPECT_TRUE(landed) << "the boom was to land on its stop";
}

TEST(StepAllocation, ContactsAllocateNothing)
{
    // CONTACT: a 4.5 t box dropped onto the floor (box-box contacts, anchors kept and
    // renewed) and a pendulum's ball rubbing along it (sphere-box, slipping)
    auto model = fromText("GRAVITY 0 0 -9.81\nCONTACT MU 0.4\nB 1 4500 750 750 750\nC 1 T 2 QI 0.52\n"
                          "B1 0 P1 0 0 0 A1 1 0 0 R1 0 0 1\nB2 1 P2 0 0 0 A2 1 0 0 R2 0 0 1\n"
                          "B 2 10 0.1 0.1 0.1\nC 2 QI 1.0\nB1 0 P1 3 0 1.12 A1 1 0 0 R1 0 0 -1\n"
                          "B2 2 P2 0 0 1 A2 1 0 0 R2 0 0 -1\n"
                          "G 1 B 1 BOX 1 1 1\nG 2 B 2 SPHERE 0.15\nG 3 B 0 BOX 8 4 1 POS 0 0 -0.5\n");
    ASSERT_TRUE(model);
    solver::Simulation sim(model, solver::SimulationOptions{});
    std::vector<solver::SimulationEvent> events;
    events.reserve(16);
    std::string error;
    ASSERT_TRUE(sim.advanceTo(0.05, events, error)) << error;
    const long before = g_allocations;
    std::size_t most = 0;
    for (int k = 51; k <= 2000; ++k) {
        ASSERT_TRUE(sim.advanceTo(k * 1e-3, events, error)) << error;
        most = std::max(most, sim.data().contacts.size());
    }
    EXPECT_EQ(g_allocations - before, 0) << "allocations in 1,950 steps with contacts";
    EXPECT_GE(most, 5u);  // the box's four corners and the ball
}

TEST(StepAllocation, AMousePushAllocatesNothing)
{
    // the studio's Ctrl + drag: a new target every step, the push cleared and taken again
    solver::CompiledModel loaded =
        solver::compileFile(std::string(PADROB_SOURCE_DIR) + "/models/tumbling_block.pad");
    ASSERT_TRUE(loaded.ok());
    solver::Simulation sim(loaded.model, solver::SimulationOptions{});
    std::vector<solver::SimulationEvent> events;
    events.reserve(100);
    std::string error;
    const int block = loaded.model->bodyIndex(1);
    ASSERT_TRUE(sim.setPush(block, Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0, 0, 1)));
    ASSERT_TRUE(sim.advanceTo(0.001, events, error)) << error;
    const long before = g_allocations;
    for (int k = 2; k <= 2000; ++k) {
        if (k % 500 == 0) sim.clearPush();
        else sim.setPush(block, Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(std::sin(0.01 * k), 0, 1));
        if (!sim.advanceTo(0.001 * k, events, error)) {
            ADD_FAILURE() << error;
            break;
        }
    }
    EXPECT_EQ(g_allocations - before, 0) << "allocations in 1999 steps with a new push each";
    EXPECT_GT(std::abs(sim.state().q[0]), 1e-3) << "the block was to move";
}
