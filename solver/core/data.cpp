#include "solver/core/data.h"

#include "solver/core/state.h"

namespace solver {

Data::Data(const Model& model)
{
    const auto nb = static_cast<std::size_t>(model.nb);
    const auto n = static_cast<Eigen::Index>(model.nb);
    const Vector6d zero6 = Vector6d::Zero();

    // kinematics
    X_wb.assign(nb, Eigen::Isometry3d::Identity());
    X_wj.assign(nb, Eigen::Isometry3d::Identity());
    omega.assign(nb, Eigen::Vector3d::Zero());
    vel.assign(nb, Eigen::Vector3d::Zero());
    alpha.assign(nb, Eigen::Vector3d::Zero());
    acc.assign(nb, Eigen::Vector3d::Zero());
    S.assign(nb, zero6);
    v.assign(nb, zero6);
    a.assign(nb, zero6);

    // applied loads
    fext.assign(nb, zero6);
    tauExt = Eigen::VectorXd::Zero(n);
    if (model.contact && model.contact->makeScratch) {
        contacts.reserve(kMaxContacts);
        contactScratch = model.contact->makeScratch(*model.contact->geometry);
    }

    // fluid power
    const auto nc = static_cast<Eigen::Index>(model.circuits.size());
    const auto np = static_cast<Eigen::Index>(model.pumps.size());
    fluidRate = Eigen::VectorXd::Zero(kFluidStates * nc);
    for (Eigen::VectorXd* v : {&supplyPressure, &pumpFlow, &pumpDemand}) v->setZero(np);
    pumpShare = Eigen::VectorXd::Ones(np);
    for (Eigen::VectorXd* v : {&pressureA, &pressureB, &flowA, &flowB, &reliefFlow, &oilStiffness, &fluidDecay})
        v->setZero(nc);
    cavitation.assign(model.circuits.size(), 0);

    // dynamics
    qdd = Eigen::VectorXd::Zero(n);
    tau = Eigen::VectorXd::Zero(n);
    driveForce = Eigen::VectorXd::Zero(n);
    limitForce = Eigen::VectorXd::Zero(n);
    reactionWorld.assign(nb, zero6);
    reactionJoint.assign(nb, zero6);

    // scratch
    c.assign(nb, zero6);
    Ib.assign(nb, RigidInertia{});
    com.assign(nb, Eigen::Vector3d::Zero());
    pb.assign(nb, zero6);
    IA.assign(nb, Matrix6d::Zero());
    pA.assign(nb, zero6);
    U.assign(nb, zero6);
    f.assign(nb, zero6);
    D = Eigen::VectorXd::Zero(n);
    uA = Eigen::VectorXd::Zero(n);
    tauKnown = Eigen::VectorXd::Zero(n);
    tauDrive = Eigen::VectorXd::Zero(n);
    dq = Eigen::VectorXd::Ones(n);
    prescribed.assign(nb, 0);
    coordinates.assign(nb, CoordinateCache{});
}

}  // namespace solver
