#pragma once
// The real-time pacing of every loop that runs a simulation for a person, in one place
// (docs/architecture.md): padrob-studio's solver thread (SimulationRunner), the Train
// workspace's (TutorialRunner) and the headless station (`padrob station`, StationNode).
//
// Simulated time follows the wall clock at a speed (below 1: slow motion). From an anchor
// (simulated time τ₀ at wall time w₀), the step that ends at τ is due at
//     w₀ + (τ − τ₀) / speed.
// runDue() takes every step due by now, each up to `lead` early, and says when the next
// batch is due (wake()). Its rules:
//  - a batch ends after `maxBatch` of wall time, so the caller publishes and reads its
//    controls between batches (the GUI is never blocked by a catch-up);
//  - further behind than `maxLag` (a slow machine, a debugger, a suspended process): the
//    loop carries on from where it is instead of racing to catch up; the time given up is
//    added to droppedSeconds();
//  - a step that ends after it was due is an overrun (overruns());
//  - the next batch is at least `tick` after the last one was planned, not after it began:
//    a late wake-up does not shift the grid.
// The stepper is a callback and the clock is the steady clock unless one is given (the
// tests give a clock of their own). The caller waits until wake() on whatever it waits on
// (its controls' condition variable, a sleep). No allocation, no lock.

#include <algorithm>
#include <chrono>
#include <functional>
#include <utility>

namespace trainer {

struct PacedLoopOptions {
    double step = 1e-3;      ///< simulated time per step [s]
    double lead = 2e-3;      ///< a step may be taken this long before it is due [s]
    double tick = 1e-3;      ///< shortest interval between two batches [s]
    double maxLag = 0.05;    ///< further behind than this [s]: carry on from here
    double maxBatch = 0.01;  ///< longest batch [s of wall time]
};

class PacedLoop {
public:
    using Clock = std::chrono::steady_clock;
    /// `clock`: the wall time [s] (default: the steady clock, from construction).
    explicit PacedLoop(PacedLoopOptions options = {}, std::function<double()> clock = {});

    const PacedLoopOptions& options() const { return m_o; }
    /// The wall time now [s].
    double now() const { return m_clock ? m_clock() : std::chrono::duration<double>(Clock::now() - m_epoch).count(); }

    /// From now, simulated time `simTime` follows the wall clock at `speed` (> 0).
    void anchor(double simTime, double speed);
    /// A new run: the overrun and dropped-time counts start again from 0.
    void resetCounts()
    {
        m_overruns = 0;
        m_dropped = 0;
    }
    double speed() const { return m_speed; }
    /// The simulated time of the steps taken since the anchor [s].
    double simTime() const { return m_anchorSim + static_cast<double>(m_steps) * m_o.step; }
    /// When the step ending at simulated time `tau` is due [s of wall time].
    double due(double tau) const { return m_anchorWall + (tau - m_anchorSim) / m_speed; }

    /// How a batch ended.
    enum class End {
        CaughtUp,  ///< the next step is not due yet
        Batch,     ///< maxBatch of wall time went by
        Stopped,   ///< step() returned false (failed, ended, or the caller's controls changed)
    };
    /// Takes the steps due by now: `step()` takes one step of options().step and returns
    /// true, or returns false (no step taken: a failure, the end, new controls) to stop.
    template <class Step>
    End runDue(Step&& step);

    /// When the next batch is due [s of wall time], and as a time point of the steady clock
    /// (with the default clock).
    double wakeAt() const { return m_plannedWake; }
    Clock::time_point wake() const
    {
        return m_epoch + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(m_plannedWake));
    }

    /// Steps that ended after they were due, since resetCounts().
    long overruns() const { return m_overruns; }
    /// Wall time given up after falling behind, since resetCounts() [s].
    double droppedSeconds() const { return m_dropped; }

private:
    PacedLoopOptions m_o;
    std::function<double()> m_clock;
    Clock::time_point m_epoch = Clock::now();
    double m_speed = 1;
    double m_anchorWall = 0, m_anchorSim = 0;
    long m_steps = 0;            ///< taken since the anchor
    double m_plannedWake = 0;    ///< when the next batch is due
    long m_overruns = 0;
    double m_dropped = 0;
};

template <class Step>
PacedLoop::End PacedLoop::runDue(Step&& step)
{
    const double start = now();
    // too far behind: carry on from here rather than race to catch up
    const double lag = start - due(simTime() + m_o.step);
    if (lag > m_o.maxLag) {
        m_dropped += lag;
        anchor(simTime(), m_speed);
        m_plannedWake = start;
    }
    End end = End::CaughtUp;
    for (;;) {
        const double t = now();
        const double next = simTime() + m_o.step;
        if (due(next) - m_o.lead > t) break;
        if (t - start > m_o.maxBatch) {
            end = End::Batch;
            break;
        }
        if (!step()) {
            end = End::Stopped;
            break;
        }
        ++m_steps;
        if (now() > due(next)) ++m_overruns;
    }
    // the next batch: when its first step is due, but at least a tick after this one was
    // planned (not after it began: a late wake-up must not shift the grid)
    m_plannedWake = std::max(due(simTime() + m_o.step) - m_o.lead, m_plannedWake + m_o.tick);
    return end;
}

}  // namespace trainer
