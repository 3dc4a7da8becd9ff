#include "ide/studio/sim/snapshot.h"

#include "solver/contact/contact_geometry.h"
#include "solver/kinematics/kinematics.h"

#include <algorithm>

namespace studio {

std::shared_ptr<Snapshot> captureSnapshot(const solver::Simulation& sim,
                                          std::shared_ptr<const ModelBundle> bundle)
{
    static const auto noEvents = std::make_shared<const std::vector<solver::SimulationEvent>>();
    const solver::Model& m = sim.model();
    const solver::State& s = sim.state();
    const solver::Data& d = sim.data();
    auto snap = std::make_shared<Snapshot>();
    snap->bundle = std::move(bundle);
    snap->t = s.t;
    snap->bodyPoses = d.X_wb;
    snap->theta = s.q;
    snap->q.resize(m.nb);
    snap->qd.resize(m.nb);
    for (int i = 0; i < m.nb; ++i) {
        snap->q[i] = m.coordinate(i, s.q[i]);
        snap->qd[i] = s.qd[i] * m.coordinateRate(i, s.q[i]);
    }
    // a free joint's slots 0–2: its body frame's translation from the start along B1's
    // joint axes, as `padrob simulate` writes it
    for (int first : m.freeJoints) {
        const solver::FreeJointMotion f = solver::freeJointMotion(m, d, s.q, s.qd, first);
        for (int a = 0; a < 3; ++a) {
            snap->q[first + a] = f.position[a];
            snap->qd[first + a] = f.velocity[a];
        }
    }
    snap->u = s.u;
    snap->push = s.push;
    snap->driveForce = d.driveForce;
    snap->reactionJoint = d.reactionJoint;
    snap->energy = solver::mechanicalEnergy(m, d);
    snap->contacts.reserve(d.contacts.size());
    for (const solver::ContactPoint& c : d.contacts) {
        // shown on the solid that moves: the force on B, or on A when B stands still
        const auto& shapes = m.contact->geometry->shapes;
        const bool bStill = c.shapeB >= 0 && static_cast<std::size_t>(c.shapeB) < shapes.size() &&
                            shapes[static_cast<std::size_t>(c.shapeB)].body < 0;
        snap->contacts.push_back({c.point, bStill ? Eigen::Vector3d(-c.normal) : c.normal,
                                  bStill ? Eigen::Vector3d(-c.force) : c.force});
        snap->largestContactForce = std::max(snap->largestContactForce, c.force.norm());
    }
    // fluid power (nothing to allocate without pumps)
    snap->pumps.resize(m.pumps.size());
    for (std::size_t p = 0; p < m.pumps.size(); ++p) {
        const auto i = static_cast<Eigen::Index>(p);
        PumpSnapshot& out = snap->pumps[p];
        out.supplyPressure = d.supplyPressure[i];
        out.flow = d.pumpFlow[i];
        out.demand = d.pumpDemand[i];
        out.qmax = m.pumps[p].qmax;
        out.pmax = m.pumps[p].pmax;
    }
    snap->circuits.resize(m.circuits.size());
    for (std::size_t c = 0; c < m.circuits.size(); ++c) {
        const auto i = static_cast<Eigen::Index>(c);
        const solver::CompiledCircuit& k = m.circuits[c];
        CircuitSnapshot& out = snap->circuits[c];
        out.joint = k.joint;
        out.spool = s.fluid[solver::kFluidStates * i];
        out.pressureA = d.pressureA[i];
        out.pressureB = d.pressureB[i];
        out.flowA = d.flowA[i];
        out.flowB = d.flowB[i];
        out.relief = m.pumps[static_cast<std::size_t>(k.pump)].pmax;
        out.cavitation = d.cavitation[c];
    }
    snap->eventLog = noEvents;
    return snap;
}

}  // namespace studio
