// Kinematics, forward dynamics (with the joint reactions) and the thesis's reference
// Newton–Euler system on the liner manipulator (a tree) and the excavator (a closed
// loop: the dense constrained path).

#include "bench/bench_models.h"

#include "solver/core/data.h"
#include "solver/dynamics/applied_forces.h"
#include "solver/dynamics/forward_dynamics.h"
#include "solver/kinematics/kinematics.h"
#include "solver/reference/newton_euler.h"

#include <benchmark/benchmark.h>

namespace {

const char* const kLiner = "liner_manipulator.pad";
const char* const kExcavator = "excavator.pad";

// positions and velocities of every body
void BM_Kinematics(benchmark::State& st, const char* name)
{
    const auto model = bench::example(name);
    const solver::State s = bench::drivenState(model);
    solver::Data data(*model);
    for (auto _ : st) {
        solver::forwardKinematics(*model, s, data);
        benchmark::DoNotOptimize(data.X_wb.data());
    }
}
BENCHMARK_CAPTURE(BM_Kinematics, liner, kLiner);
BENCHMARK_CAPTURE(BM_Kinematics, excavator, kExcavator);

// kinematics + applied forces + hybrid dynamics (reactions included): one evaluation
// of the ODE's right-hand side
void BM_ForwardDynamics(benchmark::State& st, const char* name)
{
    const auto model = bench::example(name);
    const solver::State s = bench::drivenState(model);
    solver::Data data(*model);
    for (auto _ : st) {
        solver::forwardKinematics(*model, s, data);
        solver::applyForces(*model, s, data);
        solver::hybridDynamics(*model, s, data);
        benchmark::DoNotOptimize(data.qdd.data());
    }
}
BENCHMARK_CAPTURE(BM_ForwardDynamics, liner, kLiner);
BENCHMARK_CAPTURE(BM_ForwardDynamics, excavator, kExcavator);

// the dynamics and the reactions' backward pass alone, on kinematics computed once
// (the reactions are pass 4 of hybridDynamics and cannot be timed apart from it)
void BM_DynamicsAndReactions(benchmark::State& st, const char* name)
{
    const auto model = bench::example(name);
    const solver::State s = bench::drivenState(model);
    solver::Data data(*model);
    solver::forwardKinematics(*model, s, data);
    solver::applyForces(*model, s, data);
    for (auto _ : st) {
        solver::hybridDynamics(*model, s, data);
        benchmark::DoNotOptimize(data.reactionJoint.data());
    }
}
BENCHMARK_CAPTURE(BM_DynamicsAndReactions, liner, kLiner);
BENCHMARK_CAPTURE(BM_DynamicsAndReactions, excavator, kExcavator);

// the thesis's system A·X = B: its own kinematics, assembly and LU
void BM_ReferenceNewtonEuler(benchmark::State& st, const char* name)
{
    const auto model = bench::example(name);
    const solver::State s = bench::drivenState(model);
    solver::Data data(*model);
    solver::forwardKinematics(*model, s, data);
    solver::applyForces(*model, s, data);
    solver::reference::NewtonEulerSystem system(*model);
    for (auto _ : st) {
        const auto& r = system.solve(s, data.fext, data.tauExt, false);
        benchmark::DoNotOptimize(r.qdd.data());
    }
    st.counters["unknowns"] = system.size();
}
BENCHMARK_CAPTURE(BM_ReferenceNewtonEuler, liner, kLiner);
BENCHMARK_CAPTURE(BM_ReferenceNewtonEuler, excavator, kExcavator);

}  // namespace
