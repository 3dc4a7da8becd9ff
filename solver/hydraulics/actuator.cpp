#include "solver/hydraulics/actuator.h"

#include <algorithm>

namespace solver::hydraulics {

double actuatorForce(const CompiledCircuit& c, double pA, double pB, double qd)
{
    return std::max(0.0, pA) * c.areaA - std::max(0.0, pB) * c.areaB - c.friction * qd;
}

ChamberRates chamberRates(const CompiledCircuit& c, double stiffA, double stiffB, double qd, double pA, double pB,
                          double qA, double qB)
{
    ChamberRates r;
    r.dpA = stiffA * (qA - c.areaA * qd);
    r.dpB = stiffB * (qB + c.areaB * qd);
    // (reported as cavitation only when the oil would leave faster than 5 % of the
    // valve's nominal flow: a chamber at tank pressure at rest, or crept on by a
    // neighbour's motion, is not cavitating)
    const double outflow = std::max(kCavitationFlow, kCavitationFraction * c.qn);
    if (pA <= 0 && r.dpA < 0) {
        if (qA - c.areaA * qd < -outflow) r.cavitation |= 1;
        r.dpA = 0;
    }
    if (pB <= 0 && r.dpB < 0) {
        if (qB + c.areaB * qd < -outflow) r.cavitation |= 2;
        r.dpB = 0;
    }
    return r;
}

}  // namespace solver::hydraulics
