#include "solver/hydraulics/pump.h"

#include "solver/core/state.h"
#include "solver/hydraulics/valve.h"

#include <algorithm>
#include <cmath>

namespace solver::hydraulics {

namespace {

/// Σ meter-in flows of pump p's sections at supply pS, and its derivative in pS.
double demandAt(const Model& model, int p, const Eigen::VectorXd& fluid, double pS, double* slope = nullptr)
{
    double sum = 0, ds = 0;
    const double pLam = model.fluid.laminar;
    for (std::size_t c = 0; c < model.circuits.size(); ++c) {
        const CompiledCircuit& k = model.circuits[c];
        if (k.pump != p) continue;
        const Eigen::Index i = kFluidStates * static_cast<Eigen::Index>(c);
        const double x = fluid[i];
        if (std::abs(x) < kSpoolClosed) continue;
        const double opening = std::min(1.0, std::abs(x));
        const double pFed = std::max(0.0, x > 0 ? fluid[i + 1] : fluid[i + 2]);
        const MeterIn in = meterIn(k, opening, pS, pFed, pLam);
        sum += in.flow;
        ds -= in.slope;  // (the slope is ∂/∂p_fed = −∂/∂p_S)
    }
    if (slope) *slope = ds;
    return sum;
}

}  // namespace

PumpOperatingPoint operatePump(const Model& model, int p, const Eigen::VectorXd& fluid, double guess)
{
    const CompiledPump& pump = model.pumps[static_cast<std::size_t>(p)];
    PumpOperatingPoint op;
    double highest = -1;
    for (std::size_t c = 0; c < model.circuits.size(); ++c) {
        const CompiledCircuit& k = model.circuits[c];
        if (k.pump != p) continue;
        const Eigen::Index i = kFluidStates * static_cast<Eigen::Index>(c);
        const double x = fluid[i];
        if (std::abs(x) < kSpoolClosed) continue;
        highest = std::max(highest, std::max(0.0, x > 0 ? fluid[i + 1] : fluid[i + 2]));
    }
    op.supply = pump.pmax;
    if (pump.loadSensing) op.supply = std::min(pump.pmax, std::max(0.0, highest) + pump.margin);
    op.demand = demandAt(model, p, fluid, op.supply);
    op.flow = op.demand;
    if (!(op.demand > pump.qmax)) return op;
    if (pump.allPost) {
        op.share = pump.qmax / op.demand;
        op.flow = pump.qmax;
        return op;
    }
    // the supply at which the flows add up to Qmax, in [0, p_S] (the demand rises with
    // the supply; at 0 it is 0 < Qmax): Newton from `guess` (the last evaluation's
    // supply: a step's stages lie close together), kept inside the bracket, bisecting
    // where Newton would leave it or the demand is flat
    double lo = 0, hi = op.supply;
    double x = guess > lo && guess < hi ? guess : 0.5 * (lo + hi);
    const double tolFlow = 1e-10 * pump.qmax;
    double demandX = NAN;  // the demand at x, once evaluated there
    for (int iter = 0; iter < 100; ++iter) {
        double slope = 0;
        demandX = demandAt(model, p, fluid, x, &slope);
        const double f = demandX - pump.qmax;
        if (std::abs(f) <= tolFlow) break;
        if (f > 0) hi = x;
        else lo = x;
        if (hi - lo <= 1e-12 * pump.pmax) break;
        double next = slope > 0 ? x - f / slope : -1;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        x = next;
        demandX = NAN;
    }
    op.supply = x;
    op.flow = std::isnan(demandX) ? demandAt(model, p, fluid, x) : demandX;
    return op;
}

}  // namespace solver::hydraulics
