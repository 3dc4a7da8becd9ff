#include "solver/hydraulics/pump.h"

#include "solver/core/state.h"
#include "solver/hydraulics/valve.h"

#include <algorithm>
#include <cmath>

namespace solver::hydraulics {

namespace {

struct Section {
    double opening, pFed;
};

/// Σ meter-in flows of pump p's sections at supply pS.
double demandAt(const Model& model, int p, const Eigen::VectorXd& fluid, double pS)
{
    double sum = 0;
    const double pLam = model.fluid.laminar;
    for (std::size_t c = 0; c < model.circuits.size(); ++c) {
        const CompiledCircuit& k = model.circuits[c];
        if (k.pump != p) continue;
        const Eigen::Index i = kFluidStates * static_cast<Eigen::Index>(c);
        const double x = fluid[i];
        if (std::abs(x) < kSpoolClosed) continue;
        const double pFed = std::max(0.0, x > 0 ? fluid[i + 1] : fluid[i + 2]);
        sum += meterIn(k, std::min(1.0, std::abs(x)), pS, pFed, pLam);
    }
    return sum;
}

}  // namespace

PumpOperatingPoint operatePump(const Model& model, int p, const Eigen::VectorXd& fluid)
{
    const CompiledPump& pump = model.pumps[static_cast<std::size_t>(p)];
    PumpOperatingPoint op;
    bool allPost = true, any = false;
    double highest = -1;
    for (std::size_t c = 0; c < model.circuits.size(); ++c) {
        const CompiledCircuit& k = model.circuits[c];
        if (k.pump != p) continue;
        any = true;
        if (k.comp != Compensation::Post) allPost = false;
        const Eigen::Index i = kFluidStates * static_cast<Eigen::Index>(c);
        const double x = fluid[i];
        if (std::abs(x) < kSpoolClosed) continue;
        highest = std::max(highest, std::max(0.0, x > 0 ? fluid[i + 1] : fluid[i + 2]));
    }
    if (!any) allPost = false;
    op.supply = pump.pmax;
    if (pump.loadSensing) op.supply = std::min(pump.pmax, std::max(0.0, highest) + pump.margin);
    op.demand = demandAt(model, p, fluid, op.supply);
    op.flow = op.demand;
    if (!(op.demand > pump.qmax)) return op;
    if (allPost) {
        op.share = pump.qmax / op.demand;
        op.flow = pump.qmax;
        return op;
    }
    // the supply at which the flows add up to Qmax: the Illinois method on [0, p_S]
    // (the demand rises with the supply; at 0 it is ≤ 0 < Qmax)
    double lo = 0, hi = op.supply;
    double flo = demandAt(model, p, fluid, lo) - pump.qmax, fhi = op.demand - pump.qmax;
    int side = 0;
    for (int iter = 0; iter < 60 && hi - lo > 1e-9 * pump.pmax; ++iter) {
        const double mid = std::clamp(hi - fhi * (hi - lo) / (fhi - flo), lo, hi);
        const double fmid = demandAt(model, p, fluid, mid) - pump.qmax;
        if (std::abs(fmid) <= 1e-12 * pump.qmax) {
            lo = hi = mid;
            break;
        }
        if ((fmid > 0) == (fhi > 0)) {
            hi = mid;
            fhi = fmid;
            if (side == -1) flo *= 0.5;
            side = -1;
        } else {
            lo = mid;
            flo = fmid;
            if (side == +1) fhi *= 0.5;
            side = +1;
        }
    }
    op.supply = 0.5 * (lo + hi);
    op.flow = demandAt(model, p, fluid, op.supply);
    return op;
}

}  // namespace solver::hydraulics
