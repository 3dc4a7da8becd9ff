// The step loop allocates nothing (issue 3, "Speed"): a binary of its own, because it
// replaces the global operator new to count allocations.

#include "solver/compile/compile.h"
#include "solver/dynamics/applied_forces.h"
#include "solver/dynamics/forward_dynamics.h"
#include "solver/integrate/simulation.h"
#include "solver/kinematics/kinematics.h"
#include "solver/model/load.h"

#include <gtest/gtest.h>

#include <atomic>
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
    solver::LoadedModel loaded = solver::loadModelFile(std::string(PADROB_SOURCE_DIR) + "/models/liner_manipulator.pad");
    EXPECT_TRUE(loaded.ok());
    solver::Diagnostics d;
    return solver::compileLoaded(loaded, d);
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
