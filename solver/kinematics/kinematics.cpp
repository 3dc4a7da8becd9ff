#include "solver/kinematics/kinematics.h"

#include <cassert>
#include <cmath>

namespace solver {

using Eigen::Vector3d;

namespace {

/// Body i's velocity (eq. 2.2–2.4) and velocity-product acceleration, from its parent's
/// velocity, its motion subspace and its pose (data.S[i], X_wb[i] already set).
inline void bodyVelocity(const Model& model, const Eigen::VectorXd& qd, Data& data, int i)
{
    const int p = model.parent[i];
    const Vector6d vj = data.S[i] * qd[i];
    if (p < 0) {
        data.v[i] = vj;
    } else {
        data.v[i] = data.v[p] + vj;
    }
    data.c[i] = crossMotion(data.v[i], vj);
    data.omega[i] = data.v[i].head<3>();
    data.vel[i] = data.v[i].tail<3>() + data.omega[i].cross(data.X_wb[i].translation());
}

}  // namespace

void forwardKinematics(const Model& model, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                       Data& data)
{
    const int nb = model.nb;
    assert((q.size() == nb || q.size() == model.nq) && qd.size() == nb);
    const bool bases = q.size() == model.nq && model.nq > nb;
    assert(static_cast<int>(data.X_wb.size()) == nb && static_cast<int>(data.c.size()) == nb);

    for (int i = 0; i < nb; ++i) {
        const int p = model.parent[i];
        const double sigma = model.axisSign[i];
        const double th = sigma * q[i];

        // the child's joint frame: the parent's joint frame moved by J(σθ) (eq. 2.1)
        // (the 3×3 and 3×1 parts, which multiply faster than the 4×4 storage)
        const Eigen::Isometry3d& X_pj = model.X_pj[i];
        Eigen::Matrix3d R;
        Vector3d x;
        if (p >= 0) {
            const Eigen::Isometry3d& X_wp = data.X_wb[p];
            multiply3(X_wp.linear(), X_pj.linear(), R);
            x = multiply3(X_wp.linear(), X_pj.translation()) + X_wp.translation();
        } else {
            R = X_pj.linear();
            x = X_pj.translation();
        }
        if (bases && model.freeBase[i] >= 0) {
            // a free joint's turns start from its base orientation (Model::freeBase)
            const Eigen::Index k = model.freeBase[i];
            const Eigen::Quaterniond base(q[k], q[k + 1], q[k + 2], q[k + 3]);
            R = R * base.normalized().toRotationMatrix();
        }
        Vector6d& s = data.S[i];
        if (model.jointType[i] == JointType::Prismatic) {
            const Vector3d r = R.col(1);
            x += th * r;
            s.head<3>().setZero();
            s.tail<3>() = sigma * r;
        } else {
            // turn about the frame's x axis (A): R ← R · Rx(σθ). A T 1 joint's cos θ and
            // sin θ are its length law's too (found once: actuatorCoordinateAt); σ = ±1,
            // and cos(−θ) = cos θ, sin(−θ) = −sin θ exactly
            double cs, sn;
            if (model.jointType[i] == JointType::Actuator) {
                const Data::CoordinateCache& k = actuatorCoordinateAt(model, data, i, q[i]);
                cs = k.cos;
                sn = sigma * k.sin;
            } else {
                cs = std::cos(th);
                sn = std::sin(th);
            }
            const Vector3d r = R.col(1), t = R.col(2);
            R.col(1) = cs * r + sn * t;
            R.col(2) = cs * t - sn * r;
            const Vector3d axis = sigma * R.col(0);
            s.head<3>() = axis;
            s.tail<3>() = x.cross(axis);
        }
        Eigen::Isometry3d& X_wj = data.X_wj[i];
        X_wj.linear() = R;
        X_wj.translation() = x;
        Eigen::Isometry3d& X_wb = data.X_wb[i];
        Eigen::Matrix3d Rwb;
        multiply3(R, model.X_jc[i].linear(), Rwb);
        X_wb.linear() = Rwb;
        X_wb.translation() = multiply3(R, model.X_jc[i].translation()) + x;
    }
    // the velocities in a pass of their own: reading S and X_wb right after they were
    // written (in pieces) stalls the processor's store forwarding
    velocityKinematics(model, qd, data);
}

void velocityKinematics(const Model& model, const Eigen::VectorXd& qd, Data& data)
{
    assert(qd.size() == model.nb);
    for (int i = 0; i < model.nb; ++i) bodyVelocity(model, qd, data, i);
}

void forwardKinematics(const Model& model, const State& state, Data& data)
{
    forwardKinematics(model, state.q, state.qd, data);
}

void bodyAccelerations(const Model& model, const Eigen::VectorXd& qdd, Data& data)
{
    const int nb = model.nb;
    assert(qdd.size() == nb && static_cast<int>(data.a.size()) == nb);
    for (int i = 0; i < nb; ++i) {
        // eq. 2.5–2.7 in spatial form
        const int p = model.parent[i];
        data.a[i] = data.c[i] + data.S[i] * qdd[i];
        if (p >= 0) data.a[i] += data.a[p];
        data.alpha[i] = data.a[i].head<3>();
        data.acc[i] = data.a[i].tail<3>() + data.alpha[i].cross(data.X_wb[i].translation()) +
                      data.omega[i].cross(data.vel[i]);
    }
}

Vector3d bodyPointPosition(const Data& data, int body, const Vector3d& p)
{
    return body < 0 ? p : Vector3d(data.X_wb[body] * p);
}

Vector3d bodyPointVelocity(const Data& data, int body, const Vector3d& p)
{
    if (body < 0) return Vector3d::Zero();
    const Vector3d x = data.X_wb[body] * p;
    return data.v[body].tail<3>() + data.omega[body].cross(x);
}

Vector3d bodyPointAcceleration(const Data& data, int body, const Vector3d& p)
{
    if (body < 0) return Vector3d::Zero();
    // classical acceleration from the spatial one: a_O + α × x + ω × v_x
    const Vector3d x = data.X_wb[body] * p;
    const Vector3d vx = data.v[body].tail<3>() + data.omega[body].cross(x);
    return data.a[body].tail<3>() + data.alpha[body].cross(x) + data.omega[body].cross(vx);
}

Vector3d comPosition(const Model& model, const Data& data, int body)
{
    return bodyPointPosition(data, body, model.com[body]);
}

Vector3d comVelocity(const Model& model, const Data& data, int body)
{
    return bodyPointVelocity(data, body, model.com[body]);
}

Vector3d comAcceleration(const Model& model, const Data& data, int body)
{
    return bodyPointAcceleration(data, body, model.com[body]);
}

Eigen::Isometry3d jointFramePose(const Model& model, const Data& data, int joint, bool parentSide)
{
    if (!parentSide) return data.X_wj[joint];
    const int p = model.parent[joint];
    return p < 0 ? model.X_pj[joint] : Eigen::Isometry3d(data.X_wb[p] * model.X_pj[joint]);
}

FreeJointMotion freeJointMotion(const Model& model, const Data& data, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& qd, int first)
{
    // slots 0–2 shift B1's joint frame F1 (their bodies keep its axes); slots 3–5 turn
    // about the shifted origin, the pivot; the body frame sits at F2⁻¹ from it at the start
    const int pivot = first + 2, body = first + kFreeJointCoordinates - 1;
    const Eigen::Matrix3d& R = data.X_wb[pivot].linear();
    const Vector3d arm = data.X_wb[body].translation() - data.X_wb[pivot].translation();
    const Vector3d start = model.X_pj[body].linear() * model.X_jc[body].translation();
    FreeJointMotion out;
    out.position = q.segment<3>(first) + R.transpose() * arm - start;
    out.velocity = qd.segment<3>(first) + R.transpose() * (data.omega[body] - data.omega[pivot]).cross(arm);
    return out;
}

double kineticEnergy(const Model& model, const Data& data)
{
    double e = 0;
    for (int i = 0; i < model.nb; ++i) {
        // ½ m |v_c|² + ½ ωᵀ I ω, with ω in body axes
        const Vector3d vc = comVelocity(model, data, i);
        const Vector3d wb = data.X_wb[i].linear().transpose() * data.omega[i];
        e += 0.5 * model.mass[i] * vc.squaredNorm() + 0.5 * wb.dot(model.inertia[i] * wb);
    }
    return e;
}

double potentialEnergy(const Model& model, const Data& data)
{
    double e = 0;
    for (int i = 0; i < model.nb; ++i) {
        e -= model.mass[i] * model.gravity.dot(comPosition(model, data, i));
    }
    return e;
}

double mechanicalEnergy(const Model& model, const Data& data)
{
    return kineticEnergy(model, data) + potentialEnergy(model, data);
}

}  // namespace solver
