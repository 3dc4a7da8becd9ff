#include "solver/dynamics/forward_dynamics.h"

#include "solver/dynamics/drives.h"
#include "solver/kinematics/kinematics.h"

#include <cassert>

namespace solver {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

[[maybe_unused]] bool sized(const Model& model, const State& state, const Data& data)
{
    const auto n = static_cast<Eigen::Index>(model.nb);
    const auto nb = static_cast<std::size_t>(model.nb);
    return state.q.size() == n && state.qd.size() == n && state.u.size() == n &&
           state.servoIntegral.size() == n && state.limit.size() == nb &&
           state.relief.size() == nb && data.X_wb.size() == nb && data.fext.size() == nb &&
           data.tauExt.size() == n && data.qdd.size() == n && data.IA.size() == nb &&
           data.prescribed.size() == nb && data.dq.size() == n && data.reactionJoint.size() == nb;
}

}  // namespace

void clearAppliedForces(Data& data)
{
    for (Vector6d& f : data.fext) f.setZero();
    data.tauExt.setZero();
}

void forwardDynamics(const Model& model, const State& state, Data& data)
{
    forwardKinematics(model, state, data);
    hybridDynamics(model, state, data);
}

void hybridDynamics(const Model& model, const State& state, Data& data)
{
    assert(sized(model, state, data));
    const int nb = model.nb;

    // 1. body inertias and bias forces about the world origin; known θ̈ or τ per joint
    for (int i = 0; i < nb; ++i) {
        const Eigen::Isometry3d& X = data.X_wb[i];
        const Matrix3d R = X.linear();
        const Vector3d o = X.translation();
        const Vector3d com = R * model.com[i] + o;
        Matrix3d ri;
        ri.noalias() = R * model.inertia[i];
        Matrix3d ic;
        ic.noalias() = ri * R.transpose();
        data.Ib[i] = rigidInertiaAt(model.mass[i], com, ic);

        // p = v ×* I v − fext − gravity (fext is about the body origin o)
        Vector6d& p = data.pb[i];
        p = crossForce(data.v[i], data.Ib[i] * data.v[i]);
        const Vector6d& fe = data.fext[i];
        const Vector3d fg = model.mass[i] * model.gravity;
        const Vector3d fo = fe.tail<3>();
        p.head<3>() -= fe.head<3>() + o.cross(fo) + com.cross(fg);
        p.tail<3>() -= fo + fg;
        data.Ib[i].toMatrix(data.IA[i]);
        data.pA[i] = p;

        // the drive's force along θ; known acceleration or known force
        const CoordinateMap map = coordinateMap(model, i, state.q[i]);
        data.dq[i] = map.dq;
        data.driveForce[i] = driveForceLaw(model, state, i, map);
        data.tauDrive[i] = data.driveForce[i] * map.dq;
        data.prescribed[i] = isPrescribed(model, state, i) ? 1 : 0;
        if (data.prescribed[i]) {
            data.qdd[i] = prescribedAcceleration(model, state, i, map);
            data.tauKnown[i] = 0;
        } else {
            data.tauKnown[i] = data.tauDrive[i] + data.tauExt[i];
        }
    }

    // 2. articulated-body inertias and bias forces, leaves to root (RBDA table 7.1, §9.2)
    for (int i = nb - 1; i >= 0; --i) {
        const int lam = model.parent[i];
        const Vector6d& s = data.S[i];
        if (!data.prescribed[i]) {
            Vector6d& U = data.U[i];
            U.noalias() = data.IA[i] * s;
            const double D = s.dot(U);
            const double u = data.tauKnown[i] - s.dot(data.pA[i]);
            data.D[i] = D;
            data.uA[i] = u;
            if (lam >= 0) {
                // I^a = I^A − U Uᵀ/D;  p^a = p^A + I^a c + U u/D
                const double k = (u - U.dot(data.c[i])) / D;
                data.pA[lam] += data.pA[i] + k * U;
                data.pA[lam].noalias() += data.IA[i] * data.c[i];
                data.IA[lam] += data.IA[i];
                data.IA[lam].noalias() -= (U / D) * U.transpose();
            }
        } else if (lam >= 0) {
            // a known θ̈ passes the whole inertia to the parent
            const Vector6d ac = data.c[i] + s * data.qdd[i];
            data.pA[lam] += data.pA[i];
            data.pA[lam].noalias() += data.IA[i] * ac;
            data.IA[lam] += data.IA[i];
        }
    }

    // 3. accelerations, root to leaves; the body's own share of the joint force
    for (int i = 0; i < nb; ++i) {
        const int lam = model.parent[i];
        Vector6d& a = data.a[i];
        a = data.c[i];
        if (lam >= 0) a += data.a[lam];
        if (!data.prescribed[i]) data.qdd[i] = (data.uA[i] - data.U[i].dot(a)) / data.D[i];
        a += data.S[i] * data.qdd[i];
        data.alpha[i] = a.head<3>();
        data.acc[i] = a.tail<3>() + data.alpha[i].cross(data.X_wb[i].translation()) +
                      data.omega[i].cross(data.vel[i]);
        data.f[i] = data.Ib[i] * a + data.pb[i];
    }

    // 4. joint forces, leaves to root (eq. 2.8–2.9 summed over each subtree)
    for (int i = nb - 1; i >= 0; --i) {
        const int lam = model.parent[i];
        const Vector6d& f = data.f[i];
        data.tau[i] = data.S[i].dot(f);

        // reaction at the child's joint point, in world and joint axes
        const Eigen::Isometry3d& X_wj = data.X_wj[i];
        Vector6d& rw = data.reactionWorld[i];
        rw = forceAboutPoint(f, X_wj.translation());
        const Matrix3d Rt = X_wj.linear().transpose();
        data.reactionJoint[i].head<3>().noalias() = Rt * rw.head<3>();
        data.reactionJoint[i].tail<3>().noalias() = Rt * rw.tail<3>();

        // drive and limit-stop forces
        // (a held hydraulic joint's cylinder carries what the joint transmits, less tauExt)
        const bool hydraulicHeld =
            model.drive[i].type == DriveType::Hydraulic && data.prescribed[i];
        if (hydraulicHeld) {
            data.driveForce[i] = (data.tau[i] - data.tauExt[i]) / data.dq[i];
        }
        data.limitForce[i] = state.limit[i] != LimitState::Free && !hydraulicHeld
                                 ? data.tau[i] - data.tauDrive[i] - data.tauExt[i]
                                 : 0.0;

        if (lam >= 0) data.f[lam] += f;
    }
}

}  // namespace solver
