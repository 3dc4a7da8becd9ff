// Clearance queries (FCL) of the liner manipulator in the SAG-mill scene
// (resources/scenes/sag_mill.pad: ~180 shapes, the shell a 512-triangle tube): one
// update of the machine's shapes to a new pose plus the smallest distance to the scene,
// at rest (the nearest shape 0.12 m away) and slewed towards the shell.

#include "bench/bench_models.h"

#include "solver/collision/collision_world.h"
#include "solver/core/data.h"
#include "solver/kinematics/kinematics.h"

#include <benchmark/benchmark.h>

namespace {

struct MillScene {
    solver::CompiledModel machine =
        solver::compileFile(std::string(PADROB_SOURCE_DIR) + "/models/liner_manipulator.pad");
    solver::CompiledModel scene =
        solver::compileFile(std::string(PADROB_SOURCE_DIR) + "/resources/scenes/sag_mill.pad");
    std::shared_ptr<const solver::Model> model = bench::example("liner_manipulator.pad");
    solver::Diagnostics diags;
    solver::CollisionWorld world{machine.spec, *model, &scene.spec, diags};
};

void BM_ClearanceInTheMill(benchmark::State& st, double slew)
{
    static MillScene mill;
    solver::State s = solver::makeState(*mill.model);
    s.q[mill.model->jointIndex(1)] = slew;
    solver::Data data(*mill.model);
    double swing = 0;
    for (auto _ : st) {
        // a slightly different pose each time, as in a run
        swing = swing > 0.01 ? 0.0 : swing + 1e-4;
        s.q[mill.model->jointIndex(3)] = 0.3 + swing;
        solver::forwardKinematics(*mill.model, s, data);
        mill.world.update(data);
        benchmark::DoNotOptimize(mill.world.machineToScene().distance);
    }
    st.counters["shapes"] = double(mill.world.shapes().size());
}
BENCHMARK_CAPTURE(BM_ClearanceInTheMill, at_rest, 0.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ClearanceInTheMill, towards_the_shell, 1.5707963267948966)->Unit(benchmark::kMicrosecond);

}  // namespace
