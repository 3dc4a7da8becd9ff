// Large models: the checks stay linear-ish and exact past the dense mass-matrix limit,
// and a model beyond the size limit gets one clear error.

#include "solver/pipeline.h"
#include "solver/spec/validate.h"

#include <gtest/gtest.h>

#include <string>

namespace {

/// A chain of n pendulum links hanging from ground, each 0.1 m long, 1 kg.
std::string chain(std::size_t n, bool masslessLeaf)
{
    std::string text;
    for (std::size_t i = 1; i <= n; ++i) {
        const std::string id = std::to_string(i);
        text += (masslessLeaf && i == n) ? "B " + id + "\n" : "B " + id + " 1 0.01 0.01 0.01\n";
        text += "C " + id + "\nB1 " + std::to_string(i - 1) + " P1 0 0 0 A1 1 0 0 R1 0 1 0\nB2 " + id +
                " P2 0 0 0.1 A2 1 0 0 R2 0 1 0\n";
    }
    return text;
}

}  // namespace

TEST(LargeModel, LongChainBeyondTheDenseLimitLoads)
{
    solver::CompiledModel m = solver::compileText(chain(3000, false), "chain.pad");
    ASSERT_TRUE(m.ok()) << (m.diagnostics.empty() ? "" : m.diagnostics.items()[0].format());
    ASSERT_TRUE(m.topology);
    EXPECT_EQ(m.topology->dof, 3000);
    EXPECT_DOUBLE_EQ(m.topology->totalMass, 3000.0);
}

TEST(LargeModel, MasslessLeafOfALongChainIsFound)
{
    // the leaf's tiny diagonal entry (0 kg m²) sits beside the root's ~1e6 kg m²:
    // the exact per-joint sums find it without a relative tolerance over the whole matrix
    solver::CompiledModel m = solver::compileText(chain(3000, true), "chain.pad");
    ASSERT_EQ(m.diagnostics.size(), 1u);
    EXPECT_EQ(m.diagnostics.items()[0].code, "joint-moves-no-mass");
    EXPECT_EQ(m.diagnostics.items()[0].pos, (solver::SourcePos{4 * 3000 - 2, 1}));
    EXPECT_EQ(m.diagnostics.items()[0].message.rfind("joint 3000 moves no mass", 0), 0u);
}

TEST(LargeModel, TooManyBodiesIsOneClearError)
{
    std::string text;
    for (std::size_t i = 1; i <= solver::kMaxBodies + 5; ++i) text += "B " + std::to_string(i) + " 1 1 1 1\n";
    solver::CompiledModel m = solver::compileText(text, "many.pad");
    ASSERT_FALSE(m.ok());
    EXPECT_EQ(m.diagnostics.items()[0].format(),
              "many.pad:10001:1: error: the model has 10005 bodies; Padrob takes at most 10000 "
              "[split the machine into smaller models, or merge bodies that move together]");
    EXPECT_EQ(m.diagnostics.errorCount(), 1u);
}
