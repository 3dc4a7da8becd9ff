#include "ide/studio/sim/snapshot.h"

#include "solver/kinematics/kinematics.h"

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
    snap->u = s.u;
    snap->driveForce = d.driveForce;
    snap->reactionJoint = d.reactionJoint;
    snap->energy = solver::mechanicalEnergy(m, d);
    snap->eventLog = noEvents;
    return snap;
}

}  // namespace studio
