// Whole steps: Simulation::advanceTo(t + 1 ms) with RK4 (events, reactions), the
// parse + compile of a model file, and steps of generated chains and trees of
// 10 … 1000 bodies (the O(n) claim).

#include "bench/bench_models.h"

#include "solver/integrate/simulation.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace {

constexpr double kDt = 1e-3;

// one step with the sine commands set before it (a new command restarts the
// integrator, as at the station every millisecond), or with the commands held
void runSteps(benchmark::State& st, const std::shared_ptr<const solver::Model>& model, bool changing)
{
    solver::Simulation sim(model, solver::SimulationOptions{});
    std::vector<solver::SimulationEvent> events;
    events.reserve(64);
    std::string error;
    if (!changing) bench::sineCommands(sim, 0.5);  // held from here on (as padrob bench holds them)
    long k = 0, eventCount = 0;
    for (auto _ : st) {
        const double t = static_cast<double>(k) * kDt;
        if (changing) bench::sineCommands(sim, t);
        if (!sim.advanceTo(t + kDt, events, error)) {
            st.SkipWithError(error.c_str());
            break;
        }
        eventCount += static_cast<long>(events.size());
        events.clear();
        ++k;
    }
    st.counters["events"] = benchmark::Counter(static_cast<double>(eventCount));
    st.counters["realtime_factor"] =
        benchmark::Counter(kDt * static_cast<double>(k), benchmark::Counter::kIsRate);
}

void BM_Rk4Step(benchmark::State& st, const char* name, bool changing)
{
    runSteps(st, bench::example(name), changing);
}
BENCHMARK_CAPTURE(BM_Rk4Step, liner_commanded, "liner_manipulator.pad", true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Rk4Step, liner_held, "liner_manipulator.pad", false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Rk4Step, excavator_commanded, "excavator.pad", true)->Unit(benchmark::kMicrosecond);

// text → ModelSpec → checks → topology → Model
void BM_ParseCompile(benchmark::State& st)
{
    const std::string text = bench::exampleText("liner_manipulator.pad");
    for (auto _ : st) {
        auto model = bench::compileText(text, "liner_manipulator.pad");
        benchmark::DoNotOptimize(model.get());
    }
}
BENCHMARK(BM_ParseCompile)->Unit(benchmark::kMicrosecond);

// generated models: drives on every third joint, limits on all, commands held. (A new
// command restarts the integrator and gives the free joints the impulse of the
// prescribed rates' jump through the dense mass matrix, an O(n³) solve: `padrob bench
// --scaling` times that too.)
void BM_ChainStep(benchmark::State& st)
{
    const int n = static_cast<int>(st.range(0));
    runSteps(st, bench::generated(false, n), false);
    st.SetComplexityN(n);
}
BENCHMARK(BM_ChainStep)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMicrosecond)->Complexity();

void BM_TreeStep(benchmark::State& st)
{
    const int n = static_cast<int>(st.range(0));
    runSteps(st, bench::generated(true, n), false);
    st.SetComplexityN(n);
}
BENCHMARK(BM_TreeStep)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMicrosecond)->Complexity();

}  // namespace
