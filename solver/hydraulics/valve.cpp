#include "solver/hydraulics/valve.h"

#include "solver/hydraulics/orifice.h"

#include <algorithm>
#include <cmath>

namespace solver::hydraulics {

double spoolRate(const CompiledCircuit& c, double x, double u) { return (std::clamp(u, -1.0, 1.0) - x) / c.tau; }

MeterIn meterIn(const CompiledCircuit& c, double opening, double pS, double pFed, double pLam)
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

SectionFlows sectionFlows(const CompiledCircuit& c, double x, double pS, double pA, double pB, double pLam,
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

double reliefFlow(const CompiledCircuit& c, double p, double pmax) { return p > pmax ? c.reliefGain * (p - pmax) : 0.0; }

}  // namespace solver::hydraulics
