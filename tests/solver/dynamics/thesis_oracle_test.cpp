// The O(n) hybrid articulated-body algorithm with reactions against the thesis's
// assembled Newton–Euler system A·X = B (eq. 2.10–2.11, tests/solver/dynamics/
// thesis_oracle.h), on random states of every test model.

#include "solver/dynamics/forward_dynamics.h"
#include "solver/kinematics/kinematics.h"
#include "tests/solver/dynamics/random_states.h"
#include "tests/solver/dynamics/thesis_oracle.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace solver {
namespace {

constexpr double kRelative = 1e-9;

// |a − b|∞ ≤ 1e-9 · |b|∞ (plus a floor far below anything physical)
template <typename A, typename B>
::testing::AssertionResult agree(const A& a, const B& b, const char* what)
{
    const double scale = b.cwiseAbs().maxCoeff();
    const double err = (a - b).cwiseAbs().maxCoeff();
    if (err <= kRelative * scale + 1e-12) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << what << ": difference " << err << " against a scale of "
                                         << scale << "\n algorithm: " << a.transpose()
                                         << "\n oracle:    " << b.transpose();
}

// a std::vector of fixed-size vectors as one long vector
template <typename V>
Eigen::VectorXd flatten(const std::vector<V>& vs)
{
    Eigen::VectorXd out(static_cast<Eigen::Index>(vs.size() * V::RowsAtCompileTime));
    for (std::size_t k = 0; k < vs.size(); ++k) {
        out.segment<V::RowsAtCompileTime>(static_cast<Eigen::Index>(k * V::RowsAtCompileTime)) = vs[k];
    }
    return out;
}

std::string describe(const Model& model, const State& s)
{
    std::string out;
    for (int i = 0; i < model.nb; ++i) {
        out += "joint " + std::to_string(model.jointId[i]) + ": θ " + std::to_string(s.q[i]) +
               " θ̇ " + std::to_string(s.qd[i]) + " u " + std::to_string(s.u[i]) + " limit " +
               std::to_string(static_cast<int>(s.limit[i])) + " relief " +
               std::to_string(static_cast<int>(s.relief[i])) + " drive " +
               std::to_string(static_cast<int>(model.drive[i].type)) + "\n";
    }
    return out;
}

// one comparison: the algorithm against the oracle at a state, with random applied loads
void compareAt(const Model& model, const State& state, std::mt19937& rng, bool loads)
{
    Data data(model);
    if (loads) {
        test::randomAppliedForces(rng, data);
    } else {
        clearAppliedForces(data);
    }
    forwardDynamics(model, state, data);
    const test::OracleResult ref = test::solveThesisSystem(model, state, data.fext, data.tauExt);
    SCOPED_TRACE(describe(model, state));
    ASSERT_LT(ref.relativeResidual, 1e-12);

    EXPECT_TRUE(agree(data.qdd, ref.qdd, "θ̈"));
    EXPECT_TRUE(agree(data.tau, ref.tau, "τ"));
    EXPECT_TRUE(agree(data.driveForce, ref.driveForce, "drive force"));
    EXPECT_TRUE(agree(data.limitForce, ref.limitForce, "limit force"));
    EXPECT_TRUE(agree(flatten(data.reactionWorld), flatten(ref.reaction), "reactions"));
    EXPECT_TRUE(agree(flatten(data.alpha), flatten(ref.alpha), "angular accelerations"));
    std::vector<Eigen::Vector3d> aG(static_cast<std::size_t>(model.nb));
    for (int i = 0; i < model.nb; ++i) aG[i] = comAcceleration(model, data, i);
    EXPECT_TRUE(agree(flatten(aG), flatten(ref.aG), "centre-of-mass accelerations"));
}

// random states of a model with its own drives, then with random drives on every joint
void compareRandomStates(const std::shared_ptr<const Model>& model, unsigned seed, int trials = 40)
{
    ASSERT_TRUE(model);
    std::mt19937 rng(seed);
    for (int k = 0; k < trials; ++k) {
        SCOPED_TRACE("trial " + std::to_string(k));
        const Model& m = *model;
        compareAt(m, test::randomState(m, rng, k % 4 != 0), rng, k % 3 != 0);
        const Model driven = test::withRandomDrives(m, rng);
        compareAt(driven, test::randomState(driven, rng, k % 4 != 1), rng, k % 3 != 1);
        if (::testing::Test::HasFatalFailure()) return;
    }
}

TEST(ThesisOracle, Pendulum)
{
    compareRandomStates(test::compileExample("pendulum.pad"), 1);
}

TEST(ThesisOracle, DoublePendulum)
{
    compareRandomStates(test::compileExample("double_pendulum.pad"), 2);
}

TEST(ThesisOracle, InclineSlider)
{
    compareRandomStates(test::compileExample("incline_slider.pad"), 3);
}

TEST(ThesisOracle, LinerManipulator)
{
    compareRandomStates(test::compileExample("liner_manipulator.pad"), 4, 60);
}

TEST(ThesisOracle, BranchedTreeWithReversedT1AndPrismaticJoints)
{
    compareRandomStates(test::compileText(test::kZooModel), 5, 60);
}

TEST(ThesisOracle, CylinderArmWithMasslessBody)
{
    compareRandomStates(test::compileText(test::kCylinderArmModel), 6, 60);
}

TEST(ThesisOracle, InitialStatesOfEveryModel)
{
    // the states the simulations start from: valves closed, joints on their limits
    for (const char* name : {"pendulum.pad", "double_pendulum.pad", "incline_slider.pad",
                             "liner_manipulator.pad"}) {
        SCOPED_TRACE(name);
        const auto model = test::compileExample(name);
        ASSERT_TRUE(model);
        std::mt19937 rng(7);
        compareAt(*model, makeState(*model), rng, false);
    }
}

}  // namespace
}  // namespace solver
