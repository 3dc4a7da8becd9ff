#pragma once
// The actuator a valve section drives (docs/hydraulics.md): a double-acting cylinder
// (CYL: areas A_A = π·BORE²/4, A_B = A_A − π·ROD²/4; chamber volumes
// V_A = Va + A_A·(q − LL), V_B = Vb + A_B·(UL − q)) or a hydraulic motor (HMOTOR:
// displacement Dm for both, fixed line volumes). In the modeler's coordinate q:
//   ṗ_A = β/V_A·(Q_A − A_A·q̇),  ṗ_B = β/V_B·(Q_B + A_B·q̇)   (a pressure at 0 stays there
//                                                             while this is negative: cavitation)
//   F   = p_A·A_A − p_B·A_B − c·q̇                            (along +q)

#include "solver/core/fluid_power.h"

#include <algorithm>

namespace solver::hydraulics {

/// The force (or torque) along +q [N or N m] at pressures pA, pB (taken ≥ 0) and rate qd.
inline double actuatorForce(const CompiledCircuit& c, double pA, double pB, double qd)
{
    return std::max(0.0, pA) * c.areaA - std::max(0.0, pB) * c.areaB - c.friction * qd;
}

/// A chamber at 0 Pa is said to cavitate while the oil would leave it faster than this
/// fraction of its valve's nominal flow (and than kCavitationFlow): at 0 the chamber is
/// topped up from tank (a make-up valve) as long as the load only creeps ahead of the
/// oil; a load running away empties it.
inline constexpr double kCavitationFraction = 0.05;
inline constexpr double kCavitationFlow = 1e-7;  ///< [m^3/s]

struct ChamberRates {
    double dpA = 0, dpB = 0;  ///< [Pa/s]
    int cavitation = 0;       ///< 1: A held at 0, 2: B held at 0, 3: both
};
/// The chambers' pressure rates for the net flows into them (valve minus relief)
/// qA, qB [m^3/s] at the modeler's rate qd, with stiffA = β/V_A and stiffB = β/V_B
/// [Pa/m^3] the oil's stiffness in each chamber at the current volumes.
inline ChamberRates chamberRates(const CompiledCircuit& c, double stiffA, double stiffB, double qd, double pA,
                                 double pB, double qA, double qB)
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
