#pragma once
// The orifice law of every metering edge and relief (docs/hydraulics.md):
//   Q = K·x·g(Δp),  g(Δp) = sign(Δp)·√|Δp| for |Δp| ≥ p_lam,  Δp/√p_lam below it
// (turbulent above the laminar threshold p_lam, linear below it, continuous at it).

namespace solver::hydraulics {

/// g(Δp) [√Pa].
double orificeRoot(double dp, double pLam);
/// dg/dΔp [1/√Pa]: 1/(2√|Δp|) turbulent, 1/√p_lam laminar.
double orificeSlope(double dp, double pLam);

}  // namespace solver::hydraulics
