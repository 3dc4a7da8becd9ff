#include "solver/hydraulics/valve.h"

#include "solver/hydraulics/orifice.h"

#include <algorithm>
#include <cmath>

namespace solver::hydraulics {

double spoolRate(const CompiledCircuit& c, double x, double u) { return (std::clamp(u, -1.0, 1.0) - x) / c.tau; }

double meterIn(const CompiledCircuit& c, double opening, double pS, double pFed, double pLam)
{
    const double dp = pS - pFed;
    if (c.comp != Compensation::None && dp >= c.dpn) return opening * c.qn;
    // the section's load-check valve: no flow back from the chamber into the supply
    if (dp <= 0) return 0;
    return c.k * opening * orificeRoot(dp, pLam);
}

double meterInSlope(const CompiledCircuit& c, double opening, double pS, double pFed, double pLam)
{
    const double dp = pS - pFed;
    if ((c.comp != Compensation::None && dp >= c.dpn) || dp <= 0) return 0;
    return -c.k * opening * orificeSlope(dp, pLam);
}

SectionFlows sectionFlows(const CompiledCircuit& c, double x, double pS, double pA, double pB, double pLam,
                          double share)
{
    SectionFlows f;
    const double opening = std::min(1.0, std::abs(x));
    if (opening < kSpoolClosed) return f;  // closed centre: the spool's overlap
    if (x > 0) {
        f.intoA = share * meterIn(c, opening, pS, pA, pLam);
        f.slopeA = -share * meterInSlope(c, opening, pS, pA, pLam);
        f.intoB = -c.k * opening * orificeRoot(pB, pLam);
        f.slopeB = c.k * opening * orificeSlope(pB, pLam);
    } else {
        f.intoB = share * meterIn(c, opening, pS, pB, pLam);
        f.slopeB = -share * meterInSlope(c, opening, pS, pB, pLam);
        f.intoA = -c.k * opening * orificeRoot(pA, pLam);
        f.slopeA = c.k * opening * orificeSlope(pA, pLam);
    }
    return f;
}

double reliefFlow(const CompiledCircuit& c, double p, double pmax) { return p > pmax ? c.reliefGain * (p - pmax) : 0.0; }

}  // namespace solver::hydraulics
