#include "solver/hydraulics/circuit.h"

#include "solver/hydraulics/actuator.h"
#include "solver/hydraulics/pump.h"
#include "solver/hydraulics/valve.h"

#include <algorithm>
#include <cmath>

namespace solver::hydraulics {

void evaluateHydraulics(const Model& model, const State& state, Data& data)
{
    if (model.circuits.empty()) return;
    const double bulk = model.fluid.bulk, pLam = model.fluid.laminar;
    for (std::size_t p = 0; p < model.pumps.size(); ++p) {
        const PumpOperatingPoint op =
            operatePump(model, static_cast<int>(p), state.fluid, data.supplyPressure[static_cast<Eigen::Index>(p)]);
        data.supplyPressure[static_cast<Eigen::Index>(p)] = op.supply;
        data.pumpFlow[static_cast<Eigen::Index>(p)] = op.flow;
        data.pumpDemand[static_cast<Eigen::Index>(p)] = op.demand;
        data.pumpShare[static_cast<Eigen::Index>(p)] = op.share;
    }
    for (std::size_t c = 0; c < model.circuits.size(); ++c) {
        const CompiledCircuit& k = model.circuits[c];
        const auto ci = static_cast<Eigen::Index>(c);
        const Eigen::Index i = kFluidStates * ci;
        const int j = k.joint;
        const CompiledPump& pump = model.pumps[static_cast<std::size_t>(k.pump)];
        const double x = state.fluid[i];
        const double pA = std::max(0.0, state.fluid[i + 1]), pB = std::max(0.0, state.fluid[i + 2]);
        const double pS = data.supplyPressure[k.pump];
        const SectionFlows f = sectionFlows(k, x, pS, pA, pB, pLam, data.pumpShare[k.pump]);
        const double rA = reliefFlow(k, pA, pump.pmax), rB = reliefFlow(k, pB, pump.pmax);
        const CoordinateMap map = coordinateMapAt(model, data, j, state.q[j]);
        const double q = map.q;
        const double qd = map.dq * state.qd[j];
        const double vA = k.volumeA(q), vB = k.volumeB(q);
        const double stiffA = bulk / vA, stiffB = bulk / vB;
        const ChamberRates r = chamberRates(k, stiffA, stiffB, qd, state.fluid[i + 1], state.fluid[i + 2],
                                            f.intoA - rA, f.intoB - rB);
        data.fluidRate[i] = spoolRate(k, x, state.u[j]);
        data.fluidRate[i + 1] = r.dpA;
        data.fluidRate[i + 2] = r.dpB;
        data.pressureA[ci] = pA;
        data.pressureB[ci] = pB;
        data.flowA[ci] = f.intoA;
        data.flowB[ci] = f.intoB;
        data.reliefFlow[ci] = rA + rB;
        data.cavitation[c] = r.cavitation;
        data.oilStiffness[ci] = bulk * (k.areaA * k.areaA / vA + k.areaB * k.areaB / vB);
        if (data.oilSpringStep > 0 && model.drive[static_cast<std::size_t>(j)].type == DriveType::FluidPower) {
            const double r = data.oilSpringStep / kOilSpringStep;
            data.inertiaFloor[j] = data.oilStiffness[ci] * r * r;
        }
        const double gA = f.slopeA + (pA > pump.pmax ? k.reliefGain : 0.0);
        const double gB = f.slopeB + (pB > pump.pmax ? k.reliefGain : 0.0);
        data.fluidDecay[ci] = std::max({stiffA * gA, stiffB * gB, 1.0 / k.tau});
    }
}

int substeps(const Model& model, const State& state, const Data& data, double h)
{
    double need = 1;
    for (std::size_t c = 0; c < model.circuits.size(); ++c) {
        const auto ci = static_cast<Eigen::Index>(c);
        const int j = model.circuits[c].joint;
        if (model.drive[static_cast<std::size_t>(j)].type != DriveType::FluidPower) continue;  // passive, burst
        need = std::max(need, data.fluidDecay[ci] * h / 1.8);
        if (state.limit[j] != LimitState::Free) continue;  // held: no oil spring on it
        const double dq = model.coordinateRate(j, state.q[j]);
        // the effective mass along q: D/dq² (the articulated-body inertia, or the mass
        // matrix's diagonal where the constrained dynamics ran instead)
        double inertia = data.D.size() > j ? data.D[j] : 0.0;
        if (!(inertia > 0) && data.M.rows() > j) inertia = data.M(j, j);
        if (!(inertia > 0) || dq == 0) continue;
        const double omega = std::sqrt(data.oilStiffness[ci] * dq * dq / inertia);
        need = std::max(need, omega * h / kOilSpringStep);
        // viscous friction on a light part: the rate's relaxation c/m
        need = std::max(need, model.circuits[c].friction * dq * dq / inertia * h / 1.8);
    }
    if (!std::isfinite(need)) return kMaxSubsteps;
    return static_cast<int>(std::min<double>(kMaxSubsteps, std::ceil(need - 1e-9)));
}

}  // namespace solver::hydraulics
