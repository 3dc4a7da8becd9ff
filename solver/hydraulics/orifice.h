#pragma once
// The orifice law of every metering edge and relief (docs/hydraulics.md):
//   Q = K·x·g(Δp),  g(Δp) = sign(Δp)·√|Δp| for |Δp| ≥ p_lam,  Δp/√p_lam below it
// (turbulent above the laminar threshold p_lam, linear below it, continuous at it).

#include <cmath>

namespace solver::hydraulics {

/// g(Δp) [√Pa] and dg/dΔp [1/√Pa] (1/(2√|Δp|) turbulent, 1/√p_lam laminar) at one
/// Δp, from one square root: the pump's Newton iteration and every section need both.
struct OrificeLaw {
    double g = 0, slope = 0;
};
inline OrificeLaw orificeLaw(double dp, double pLam)
{
    const double a = std::abs(dp);
    OrificeLaw o;
    if (a >= pLam) {
        const double root = std::sqrt(a);
        o.g = dp >= 0 ? root : -root;
        o.slope = 0.5 / root;
    } else {
        const double root = std::sqrt(pLam);
        o.g = dp / root;
        o.slope = 1.0 / root;
    }
    return o;
}

}  // namespace solver::hydraulics
