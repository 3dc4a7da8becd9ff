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

namespace solver::hydraulics {

/// ẋ [1/s].
double spoolRate(const CompiledCircuit& c, double x, double u);

/// The meter-in flow into the fed chamber [m^3/s] at spool opening |x| = `opening`,
/// supply p_S and fed-chamber pressure pFed (≥ 0: the load-check valve), and its
/// derivative in p_fed (≤ 0 [m^3/(s Pa)]; −∂/∂p_S), for the stiffness estimate and
/// the pump's Newton iteration.
struct MeterIn {
    double flow = 0, slope = 0;
};
MeterIn meterIn(const CompiledCircuit& c, double opening, double pS, double pFed, double pLam);

/// The section's flows into A and into B [m^3/s] (negative: out of the chamber), with
/// the meter-in flow scaled by `share` (a POST pump's flow sharing; 1 otherwise).
struct SectionFlows {
    double intoA = 0, intoB = 0;
    double slopeA = 0, slopeB = 0;  ///< −∂Q/∂p of each chamber's own flow (≥ 0) [m^3/(s Pa)]
};
SectionFlows sectionFlows(const CompiledCircuit& c, double x, double pS, double pA, double pB, double pLam,
                          double share);

/// The port relief of a chamber at pressure p [m^3/s to tank]: gain·(p − p_max) above p_max.
double reliefFlow(const CompiledCircuit& c, double p, double pmax);

}  // namespace solver::hydraulics
