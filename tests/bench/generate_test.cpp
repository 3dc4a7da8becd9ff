// The scaling models (bench/generate.h) are valid model text: they load and
// compile without a diagnostic, have n bodies, the drives and limits they promise,
// and simulate.

#include "bench/generate.h"

#include "solver/integrate/simulation.h"
#include "solver/pipeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace solver {
namespace {

using bench::chainModelText;
using bench::treeModelText;
using bench::GeneratedModelOptions;

// compiled, without a single diagnostic
std::shared_ptr<const Model> compileClean(const std::string& text, const std::string& name)
{
    const CompiledModel compiled = solver::compileText(text, name);
    for (const Diagnostic& d : compiled.diagnostics) ADD_FAILURE() << d.format();
    return compiled.model;
}

int drives(const Model& m)
{
    int k = 0;
    for (const CompiledDrive& d : m.drive) k += d.type == DriveType::Hydraulic ? 1 : 0;
    return k;
}

TEST(GeneratedModel, ChainsLoadCompileAndHaveNBodies)
{
    for (int n : {1, 2, 10, 100, 1000}) {
        SCOPED_TRACE(n);
        auto m = compileClean(chainModelText(n), "chain.pad");
        ASSERT_TRUE(m);
        EXPECT_EQ(m->nb, n);
        EXPECT_TRUE(m->cuts.empty());
        EXPECT_EQ(drives(*m), (n + 2) / 3);  // joints 1, 4, 7, …
        for (int i = 0; i < m->nb; ++i) {
            EXPECT_EQ(m->parent[i], i - 1);
            const bool driven = m->drive[i].type == DriveType::Hydraulic;
            EXPECT_EQ(driven, i % 3 == 0);
            EXPECT_DOUBLE_EQ(m->lower[i], driven ? -0.2 : -0.5);
            EXPECT_DOUBLE_EQ(m->upper[i], driven ? 0.2 : 0.5);
        }
    }
}

TEST(GeneratedModel, TreesLoadCompileAndHaveNBodies)
{
    for (int n : {1, 3, 10, 100, 1000}) {
        SCOPED_TRACE(n);
        auto m = compileClean(treeModelText(n), "tree.pad");
        ASSERT_TRUE(m);
        EXPECT_EQ(m->nb, n);
        EXPECT_TRUE(m->cuts.empty());
        // link k hangs from link k/2
        for (int i = 0; i < m->nb; ++i) {
            const int id = m->bodyId[i];
            const int p = m->parent[i];
            EXPECT_EQ(p < 0 ? 0 : m->bodyId[p], id / 2) << "link " << id;
        }
    }
}

TEST(GeneratedModel, ChainIsThreeDimensional)
{
    auto m = compileClean(chainModelText(4), "chain.pad");
    ASSERT_TRUE(m);
    // joint axes alternate x, y (the joint frame's first column, in the parent)
    EXPECT_TRUE(m->X_pj[0].linear().col(0).isApprox(Eigen::Vector3d::UnitX()));
    EXPECT_TRUE(m->X_pj[1].linear().col(0).isApprox(Eigen::Vector3d::UnitY()));
    EXPECT_TRUE(m->X_pj[2].linear().col(0).isApprox(Eigen::Vector3d::UnitX()));
}

TEST(GeneratedModel, OptionsAreHonoured)
{
    GeneratedModelOptions o;
    o.driveEvery = 0;
    o.limit = 0;
    o.driveLimit = 0.1;  // no drive: not used
    o.linkMass = 2.5;
    auto m = compileClean(chainModelText(7, o), "chain.pad");
    ASSERT_TRUE(m);
    EXPECT_EQ(drives(*m), 0);
    EXPECT_FALSE(std::isfinite(m->lower[3]));
    EXPECT_DOUBLE_EQ(m->mass[6], 2.5);
    EXPECT_THROW(chainModelText(0), std::invalid_argument);
    EXPECT_THROW(treeModelText(-1), std::invalid_argument);
}

TEST(GeneratedModel, DrivenChainAndTreeSimulate)
{
    for (const std::string& text : {chainModelText(30), treeModelText(30)}) {
        auto m = compileClean(text, "generated.pad");
        ASSERT_TRUE(m);
        Simulation sim(m, SimulationOptions{});
        std::vector<SimulationEvent> events;
        std::string error;
        for (int k = 1; k <= 500; ++k) {
            const double t = 1e-3 * k;
            for (int j = 0; j < m->nb; ++j) {
                if (m->drive[j].type != DriveType::None) sim.setCommand(j, 0.8 * std::sin(2 * 3.14159 * 2 * t + j));
            }
            ASSERT_TRUE(sim.advanceTo(t, events, error)) << error;
        }
        for (int j = 0; j < m->nb; ++j) {
            EXPECT_GE(sim.state().q[j], m->lower[j] - 1e-9);
            EXPECT_LE(sim.state().q[j], m->upper[j] + 1e-9);
        }
    }
}

}  // namespace
}  // namespace solver
