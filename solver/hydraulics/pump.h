#pragma once
// A pump feeding any number of valve sections (docs/hydraulics.md):
//  - pressure-compensated (no MARGIN): the supply is p_max;
//  - load-sensing (MARGIN Δp_ls): the supply is min(p_max, the highest fed-chamber
//    pressure of its open sections + Δp_ls), Δp_ls (standby) with every section closed.
// When the sections would draw more than Qmax at that supply, the pump saturates: with
// every section COMP POST their meter-in flows are scaled by one factor Qmax/Σ (flow
// sharing); otherwise the supply falls to the pressure at which the flows add up to
// Qmax (each section's flow rises with the supply pressure; the highest load starves).

#include "solver/core/model.h"

#include <Eigen/Core>

namespace solver::hydraulics {

struct PumpOperatingPoint {
    double supply = 0;  ///< p_S [Pa]
    double share = 1;   ///< the factor on every meter-in flow (POST saturation), else 1
    double demand = 0;  ///< Σ meter-in flows at the unsaturated supply [m^3/s]
    double flow = 0;    ///< what the pump delivers [m^3/s] (≤ Qmax)
};

/// The operating point of pump `p` (index in model.pumps) at the fluid states `fluid`
/// (State::fluid). Pressures below 0 count as 0. A saturated supply is solved for by
/// Newton's method, safeguarded by bisection, from `guess` (the last evaluation's
/// supply pressure; any value outside the bracket starts from its middle). No allocation.
PumpOperatingPoint operatePump(const Model& model, int p, const Eigen::VectorXd& fluid, double guess = -1);

}  // namespace solver::hydraulics
