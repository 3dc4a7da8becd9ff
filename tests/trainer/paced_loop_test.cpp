// The one real-time pacing (trainer/station/paced_loop.h), on a clock of the test's own:
// each step costs what the test says, and the loop "sleeps" by moving the clock to
// wakeAt(). Pacing at speed 1 and in slow motion, a stall dropped instead of raced
// through, overruns when the steps are slower than real time, batches bounded in wall
// time (the GUI is never kept waiting), a stop from the stepper, and a late wake-up that
// does not shift the grid.

#include "trainer/station/paced_loop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using trainer::PacedLoop;
using trainer::PacedLoopOptions;

namespace {

struct FakeClock {
    double t = 0;
};

/// A loop on a fake clock whose steps cost `cost` [s] each; run(until) wakes at every
/// wakeAt() up to wall time `until`.
struct Harness {
    FakeClock clock;
    PacedLoop loop;
    double cost;
    long steps = 0;
    double longestBatch = 0;
    explicit Harness(double stepCost, PacedLoopOptions o = {})
        : loop(o, [this] { return clock.t; }), cost(stepCost)
    {
    }
    void run(double until)
    {
        while (clock.t < until) {
            const double start = clock.t;
            loop.runDue([&] {
                clock.t += cost;
                ++steps;
                return true;
            });
            longestBatch = std::max(longestBatch, clock.t - start);
            clock.t = std::max(clock.t, loop.wakeAt());  // sleep until the next batch
        }
    }
};

}  // namespace

TEST(PacedLoop, SimulatedTimeFollowsTheWallClock)
{
    Harness h(50e-6);
    h.loop.anchor(0.0, 1.0);
    h.run(2.0);
    // at most `lead` ahead of the wall clock, and never behind by more than a step
    EXPECT_GE(h.loop.simTime(), h.clock.t - 1e-3);
    EXPECT_LE(h.loop.simTime(), h.clock.t + h.loop.options().lead + 1e-3);
    EXPECT_EQ(h.loop.overruns(), 0);
    EXPECT_EQ(h.loop.droppedSeconds(), 0.0);
    EXPECT_NEAR(double(h.steps), 2000.0, 3.0);
}

TEST(PacedLoop, SlowMotionRunsAtItsSpeed)
{
    Harness h(50e-6);
    h.loop.anchor(10.0, 0.25);  // from simulated 10 s, a quarter of real time
    h.run(4.0);
    EXPECT_NEAR(h.loop.simTime(), 10.0 + 0.25 * 4.0, 0.25 * 4e-3);
    // and faster again from here: the anchor moves, the simulated time does not jump
    const double at = h.loop.simTime();
    h.loop.anchor(at, 4.0);
    h.run(5.0);
    EXPECT_NEAR(h.loop.simTime(), at + 4.0 * 1.0, 4.0 * 4e-3);
}

TEST(PacedLoop, AStallIsDroppedNotRacedThrough)
{
    Harness h(50e-6);
    h.loop.anchor(0.0, 1.0);
    h.run(1.0);
    const double before = h.loop.simTime();
    h.clock.t += 3.0;  // the process was suspended for 3 s
    const long stepsBefore = h.steps;
    h.loop.runDue([&] {
        h.clock.t += h.cost;
        ++h.steps;
        return true;
    });
    EXPECT_LE(h.steps - stepsBefore, 3);  // carried on from here
    EXPECT_NEAR(h.loop.droppedSeconds(), 3.0, 0.01);
    h.run(h.clock.t + 1.0);
    EXPECT_NEAR(h.loop.simTime(), before + 1.0, 0.01);  // the stall's 3 s are not simulated
    h.loop.resetCounts();
    EXPECT_EQ(h.loop.droppedSeconds(), 0.0);
}

TEST(PacedLoop, StepsSlowerThanRealTimeOverrunInBoundedBatches)
{
    PacedLoopOptions o;
    Harness h(2e-3, o);  // each step takes 2 ms of wall time for 1 ms of simulated time
    h.loop.anchor(0.0, 1.0);
    h.run(1.0);
    EXPECT_GT(h.loop.overruns(), 100);
    // no batch holds the thread past maxBatch and the step in progress
    EXPECT_LE(h.longestBatch, o.maxBatch + 2 * h.cost + 1e-12);
    // it runs at half speed and gives up what it cannot do
    EXPECT_NEAR(h.loop.simTime(), 0.5, 0.06);
    EXPECT_GT(h.loop.droppedSeconds(), 0.3);
}

TEST(PacedLoop, TheStepperStopsABatch)
{
    FakeClock c;
    PacedLoop loop({}, [&] { return c.t; });
    loop.anchor(0.0, 1.0);
    c.t = 0.0205;  // 20 steps due (and two more within the lead)
    int n = 0;
    EXPECT_EQ(loop.runDue([&] { return ++n <= 5; }), PacedLoop::End::Stopped);
    EXPECT_EQ(n, 6);
    EXPECT_NEAR(loop.simTime(), 5e-3, 1e-12);  // the refused step is not counted
    EXPECT_EQ(loop.runDue([&] { return true; }), PacedLoop::End::CaughtUp);
    EXPECT_NEAR(loop.simTime(), 0.022, 1e-9);  // caught up, `lead` ahead
}

TEST(PacedLoop, ALateWakeUpDoesNotShiftTheGrid)
{
    FakeClock c;
    PacedLoop loop({}, [&] { return c.t; });
    loop.anchor(0.0, 1.0);
    loop.runDue([] { return true; });
    // the next batch is due when its step is, less the lead
    EXPECT_NEAR(loop.wakeAt(), loop.due(loop.simTime() + 1e-3) - 2e-3, 1e-12);
    c.t = loop.wakeAt() + 0.7e-3;  // woken late
    loop.runDue([] { return true; });
    EXPECT_NEAR(loop.simTime(), c.t + 2e-3, 1e-3);
    // the steps stay on the millisecond grid of the anchor
    const double k = loop.simTime() / 1e-3;
    EXPECT_NEAR(k, std::round(k), 1e-9);
}
