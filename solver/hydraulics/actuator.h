#pragma once
// The actuator a valve section drives (docs/hydraulics.md): a double-acting cylinder
// (CYL: areas A_A = π·BORE²/4, A_B = A_A − π·ROD²/4; chamber volumes
// V_A = Va + A_A·(q − LL), V_B = Vb + A_B·(UL − q)) or a hydraulic motor (HMOTOR:
// displacement Dm for both, fixed line volumes). In the modeler's coordinate q:
//   ṗ_A = β/V_A·(Q_A − A_A·q̇),  ṗ_B = β/V_B·(Q_B + A_B·q̇)   (a pressure at 0 stays there
//                                                             while this is negative: cavitation)
//   F   = p_A·A_A − p_B·A_B − c·q̇                            (along +q)

#include "solver/core/fluid_power.h"

namespace solver::hydraulics {

/// The force (or torque) along +q [N or N m] at pressures pA, pB (taken ≥ 0) and rate qd.
double actuatorForce(const CompiledCircuit& c, double pA, double pB, double qd);

/// The net outflow [m^3/s] from a chamber at 0 Pa above which it is said to cavitate.
inline constexpr double kCavitationFlow = 1e-7;

struct ChamberRates {
    double dpA = 0, dpB = 0;  ///< [Pa/s]
    int cavitation = 0;       ///< 1: A held at 0, 2: B held at 0, 3: both
};
/// The chambers' pressure rates for the net flows into them (valve minus relief)
/// qA, qB [m^3/s] at the modeler's coordinate q and rate qd.
ChamberRates chamberRates(const CompiledCircuit& c, double bulk, double q, double qd, double pA, double pB, double qA,
                          double qB);

}  // namespace solver::hydraulics
