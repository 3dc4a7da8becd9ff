#pragma once
// A closed-centre 4/3 proportional valve section (docs/hydraulics.md). The spool x in
// [−1, 1] follows the command u: ẋ = (u − x)/τ. x > 0 feeds chamber A from the supply
// and drains B to tank; x < 0 the other way round:
//   meter-in   Q = K·|x|·g(p_S − p_fed), or |x|·Qn with a compensator (PRE, POST) while
//              p_S − p_fed ≥ Δpn; never back into the supply (the section's load-check
//              valve, in every load-sensing section: a starved load stops, it does not sink);
//   meter-out  Q = K·|x|·g(p_drained) to tank (the orifice law, compensated or not).
// An opening below kSpoolClosed is closed (the spool's overlap): no flow, and the pump
// does not count the section as open.

#include "solver/core/fluid_power.h"
#include "solver/hydraulics/orifice.h"

#include <algorithm>
#include <cmath>

namespace solver::hydraulics {

/// ẋ [1/s].
inline double spoolRate(const CompiledCircuit& c, double x, double u) { return (std::clamp(u, -1.0, 1.0) - x) / c.tau; }

/// The meter-in flow into the fed chamber [m^3/s] at spool opening |x| = `opening`,
/// supply p_S and fed-chamber pressure pFed (≥ 0: the load-check valve), and its
/// derivative in p_fed (≤ 0 [m^3/(s Pa)]; −∂/∂p_S), for the stiffness estimate and
/// the pump's Newton iteration.
struct MeterIn {
    double flow = 0, slope = 0;
};
/// (Inline: the pump's Newton iteration calls it for every open section at every iterate.)
inline MeterIn meterIn(const CompiledCircuit& c, double opening, double pS, double pFed, double pLam)
{
    MeterIn m;
    const double dp = pS - pFed;
    if (c.comp != Compensation::None && dp >= c.dpn) {
        m.flow = opening * c.qn;
        return m;
    }
    // the section's load-check valve: no flow back from the chamber into the supply
    if (dp <= 0) return m;
    const OrificeLaw o = orificeLaw(dp, pLam);
    m.flow = c.k * opening * o.g;
    m.slope = -c.k * opening * o.slope;
    return m;
}

/// The section's flows into A and into B [m^3/s] (negative: out of the chamber), with
/// the meter-in flow scaled by `share` (a POST pump's flow sharing; 1 otherwise).
struct SectionFlows {
    double intoA = 0, intoB = 0;
    double slopeA = 0, slopeB = 0;  ///< −∂Q/∂p of each chamber's own flow (≥ 0) [m^3/(s Pa)]
};
inline SectionFlows sectionFlows(const CompiledCircuit& c, double x, double pS, double pA, double pB, double pLam,
                                 double share)
{
    SectionFlows f;
    const double opening = std::min(1.0, std::abs(x));
    if (opening < kSpoolClosed) return f;  // closed centre: the spool's overlap
    // x > 0 feeds A and drains B to tank; x < 0 the other way round
    const bool feedsA = x > 0;
    const MeterIn in = meterIn(c, opening, pS, feedsA ? pA : pB, pLam);
    const OrificeLaw out = orificeLaw(feedsA ? pB : pA, pLam);
    (feedsA ? f.intoA : f.intoB) = share * in.flow;
    (feedsA ? f.slopeA : f.slopeB) = -share * in.slope;
    (feedsA ? f.intoB : f.intoA) = -c.k * opening * out.g;
    (feedsA ? f.slopeB : f.slopeA) = c.k * opening * out.slope;
    return f;
}

/// The port relief of a chamber at pressure p [m^3/s to tank]: gain·(p − p_max) above p_max.
inline double reliefFlow(const CompiledCircuit& c, double p, double pmax)
{
    return p > pmax ? c.reliefGain * (p - pmax) : 0.0;
}

}  // namespace solver::hydraulics
