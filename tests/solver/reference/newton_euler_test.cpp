// The reference Newton–Euler system (solver/reference/newton_euler.h) beyond what the
// dynamics tests use it for (tests/solver/dynamics/thesis_oracle_test.cpp: trees): its
// loop-closing joints against the dense constrained dynamics, its RK4 step against the
// simulator's, and a reused system giving the same answers.

#include "solver/reference/newton_euler.h"

#include "solver/dynamics/applied_forces.h"
#include "solver/dynamics/forward_dynamics.h"
#include "solver/integrate/simulation.h"
#include "tests/solver/test_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace solver {
namespace {

double relative(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
    return (a - b).lpNorm<Eigen::Infinity>() / std::max(b.lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST(NewtonEuler, SizeIsThirteenPerBodyAndSevenPerLoopClosure)
{
    const auto liner = test::compileExample("liner_manipulator.pad");
    const auto excavator = test::compileExample("excavator.pad");
    ASSERT_TRUE(liner && excavator);
    EXPECT_EQ(reference::NewtonEulerSystem(*liner).size(), 13 * 9);
    ASSERT_EQ(excavator->cuts.size(), 1u);
    EXPECT_EQ(reference::NewtonEulerSystem(*excavator).size(), 13 * 6 + 7);
}

// along driven simulations of the loop models: the reference's θ̈ against the dense
// constrained dynamics at every state (the loops are closed there)
TEST(NewtonEuler, LoopClosuresAgreeWithTheConstrainedDynamics)
{
    for (const char* name : {"four_bar.pad", "slider_crank.pad", "excavator.pad"}) {
        SCOPED_TRACE(name);
        const auto model = test::compileExample(name);
        ASSERT_TRUE(model);
        ASSERT_FALSE(model->cuts.empty());
        Simulation sim(model, test::rk4(1e-3));
        reference::NewtonEulerSystem system(*model);
        std::vector<SimulationEvent> events;
        std::string error;
        for (int k = 0; k <= 10; ++k) {
            int d = 0;
            for (int j = 0; j < model->nb; ++j) {
                if (model->drive[j].type != DriveType::None) sim.setCommand(j, std::sin(0.7 * k + d++));
            }
            ASSERT_TRUE(sim.advanceTo(0.05 * k, events, error)) << error;
            const Data& data = sim.data();
            const reference::NewtonEulerResult& r = system.solve(sim.state(), data.fext, data.tauExt);
            EXPECT_LT(r.relativeResidual, 1e-10) << "t = " << sim.state().t;
            EXPECT_LT(relative(r.qdd, data.qdd), 1e-8) << "t = " << sim.state().t << "\n reference "
                                                      << r.qdd.transpose() << "\n padrob    "
                                                      << data.qdd.transpose();
            // the drives' forces are determinate (the loops' redundant reactions are not)
            EXPECT_LT(relative(r.driveForce, data.driveForce), 1e-7) << "t = " << sim.state().t;
        }
    }
}

// one classic RK4 step over the reference equals the simulator's RK4 step (no events
// on the way: passive, no limits)
TEST(NewtonEuler, Rk4StepMatchesTheSimulatorsStep)
{
    for (const char* name : {"double_pendulum.pad", "liner_manipulator.pad"}) {
        SCOPED_TRACE(name);
        const auto model = test::compileExample(name);
        ASSERT_TRUE(model);
        SimulationOptions o = test::rk4(1e-3);
        o.drives = false;
        o.limits = false;
        Simulation sim(model, o);
        for (int j = 0; j < model->nb; ++j) sim.setInitial(j, sim.state().q[j], 0.3 * std::cos(j));
        State s = sim.state();
        Data data(*model);
        clearAppliedForces(data);
        // the reference's state: the simulator's, passive (its model may have drives)
        Model passive = *model;
        for (int j = 0; j < passive.nb; ++j) passive.drive[j] = CompiledDrive{};
        for (auto& l : s.limit) l = LimitState::Free;
        reference::NewtonEulerSystem system(passive);
        reference::Rk4Work work;
        std::vector<SimulationEvent> events;
        std::string error;
        for (int k = 1; k <= 5; ++k) {
            ASSERT_TRUE(sim.advanceTo(1e-3 * k, events, error)) << error;
            reference::rk4Step(system, s, data.fext, data.tauExt, 1e-3, work);
            EXPECT_NEAR(s.t, sim.state().t, 1e-15);
            EXPECT_LT(relative(s.q, sim.state().q), 1e-12) << s.q.transpose() << "\n" << sim.state().q.transpose();
            EXPECT_LT(relative(s.qd, sim.state().qd), 1e-10) << s.qd.transpose() << "\n"
                                                            << sim.state().qd.transpose();
        }
    }
}

TEST(NewtonEuler, AReusedSystemGivesTheSameAnswer)
{
    const auto model = test::compileExample("liner_manipulator.pad");
    ASSERT_TRUE(model);
    State s = makeState(*model);
    s.qd.setConstant(0.1);
    Data data(*model);
    clearAppliedForces(data);
    reference::NewtonEulerSystem system(*model);
    const Eigen::VectorXd first = system.solve(s, data.fext, data.tauExt).qdd;
    State other = s;
    other.qd.setConstant(-0.4);
    system.solve(other, data.fext, data.tauExt);
    const reference::NewtonEulerResult again = system.solve(s, data.fext, data.tauExt);
    EXPECT_EQ(again.qdd, first);
    EXPECT_EQ(reference::solveNewtonEuler(*model, s, data.fext, data.tauExt).qdd, first);
}

}  // namespace
}  // namespace solver
