#pragma once
// OverrunMeter: the status bar's overruns as a share of the recent steps, not a count
// that climbs into the thousands under load, and what an overrun is. An overrun is a
// solver step that ended after its deadline: computing it took longer than the real
// time it simulates, so the simulation fell behind the wall clock (SimulationRunner,
// "Pacing"). The meter keeps the snapshots' step and overrun counts of the last
// kWindow seconds of wall time; percent() is the share of those steps that were late.

#include <QCoreApplication>
#include <QString>

#include <deque>

namespace studio {

class OverrunMeter {
    Q_DECLARE_TR_FUNCTIONS(studio::OverrunMeter)

public:
    static constexpr double kWindow = 2.0;  ///< [s] of wall time

    /// The counts of a snapshot (Snapshot::step, Snapshot::overruns) at wall time `now`
    /// [s]. Counts that went back (a reset, a new run) start the window again.
    void add(double now, long step, long overruns);
    void clear() { m_samples.clear(); }

    /// The share of the window's steps that were late [%] (0 without steps).
    double percent() const;
    /// Overruns since the counts last started (a run).
    long total() const { return m_samples.empty() ? 0 : m_samples.back().overruns; }

    /// "3 % of steps late", "" when none was late in the window.
    QString text() const;
    /// What an overrun is and what to do about it, with the total.
    QString toolTip() const;

private:
    struct Sample {
        double now;
        long step, overruns;
    };
    std::deque<Sample> m_samples;
};

}  // namespace studio
