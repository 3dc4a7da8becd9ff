#include "solver/dynamics/forward_dynamics.h"

#include "solver/dynamics/constraints.h"
#include "solver/dynamics/drives.h"
#include "solver/dynamics/mass_matrix.h"
#include "solver/kinematics/kinematics.h"

#include <Eigen/Cholesky>
#include <Eigen/SVD>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <vector>

namespace solver {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

/// The joint's own inertia D (generalized, along θ) raised to its floor
/// (Data::inertiaFloor, along q: times (dq/dθ)²), when there is one.
double flooredInertia(const Data& data, int i, double D)
{
    if (data.inertiaFloor.size() == 0) return D;
    const double floor = data.inertiaFloor[i] * data.dq[i] * data.dq[i];
    return D < floor ? floor : D;
}

/// parent += IA − U Uᵀ/D: the articulated inertia a free joint passes to its parent
/// (RBDA table 7.1), column by column (Eigen's outer product is a call at -O2; and
/// always inlined: GCC left this as a call at -O3 too).
PADROB_SPATIAL_INLINE void passArticulatedInertia(Matrix6d& parent, const Matrix6d& IA, const Vector6d& U, double D)
{
    const Vector6d Ud = U / D;
    for (int k = 0; k < 6; ++k) {
        parent.col(k) += IA.col(k);
        parent.col(k) -= Ud * U(k);
    }
}

[[maybe_unused]] bool sized(const Model& model, const State& state, const Data& data)
{
    const auto n = static_cast<Eigen::Index>(model.nb);
    const auto nb = static_cast<std::size_t>(model.nb);
    return (state.q.size() == n || state.q.size() == model.nq) && state.qd.size() == n && state.u.size() == n &&
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

namespace {

/// Body i's spatial inertia about the world origin at the pose data.X_wb[i] (into
/// data.Ib[i]) and its centre of mass in the world (into data.com[i], which the bias
/// forces read: found once per pose, not again there).
void bodyInertia(const Model& model, Data& data, int i)
{
    const Eigen::Isometry3d& X = data.X_wb[i];
    Vector3d& com = data.com[i];
    com = multiply3(X.linear(), model.com[i]) + X.translation();
    Matrix3d ri;
    multiply3(X.linear(), model.inertia[i], ri);
    RigidInertia& I = data.Ib[i];
    multiply3(ri, X.linear().transpose(), I.Ibar);  // about the centre of mass, world axes
    rigidInertiaAt(model.mass[i], com, I.Ibar, I);
}

/// Pass 1: body inertias and bias forces about the world origin; per joint its drive
/// force and whether its acceleration (prescribed) or its force (tauKnown) is known.
/// Returns the number of free joints (θ̈ unknown).
int bodyTerms(const Model& model, const State& state, Data& data, bool keepInertias = false)
{
    const int nb = model.nb;
    int nFree = 0;

    // 1. body inertias, all of them before they are read: an inertia read right after
    // it was written (3×3 blocks stored in pieces) stalls the processor's store forwarding
    for (int i = 0; i < nb && !keepInertias; ++i) bodyInertia(model, data, i);
    // bias forces about the world origin; known θ̈ or τ per joint
    for (int i = 0; i < nb; ++i) {
        const Vector3d o = data.X_wb[i].translation();
        const Vector3d& com = data.com[i];  // (bodyInertia's, at these positions)

        // p = v ×* I v − fext − gravity (fext is about the body origin o)
        Vector6d& p = data.pb[i];
        p = crossForce(data.v[i], data.Ib[i] * data.v[i]);
        const Vector6d& fe = data.fext[i];
        const Vector3d fg = model.mass[i] * model.gravity;
        const Vector3d fo = fe.tail<3>();
        p.head<3>() -= fe.head<3>() + o.cross(fo) + com.cross(fg);
        p.tail<3>() -= fo + fg;

        // the drive's force along θ; known acceleration or known force
        const CoordinateMap map = coordinateMapAt(model, data, i, state.q[i]);
        data.dq[i] = map.dq;
        data.driveForce[i] = driveForceLaw(model, state, i, map);
        data.tauDrive[i] = data.driveForce[i] * map.dq;
        data.prescribed[i] = isPrescribed(model, state, i) ? 1 : 0;
        if (data.prescribed[i]) {
            data.qdd[i] = prescribedAcceleration(model, state, i, map);
            data.tauKnown[i] = 0;
        } else {
            data.tauKnown[i] = data.tauDrive[i] + data.tauExt[i];
            ++nFree;
        }
    }
    return nFree;
}

/// Pass 4: with data.f holding each body's I a + p less the constraint loads on it,
/// the joint forces leaves to root, the reactions, the drive and limit-stop forces.
void jointForces(const Model& model, const State& state, Data& data, bool reactions = true)
{
    const int nb = model.nb;
    // 4. joint forces, leaves to root (eq. 2.8–2.9 summed over each subtree)
    for (int i = nb - 1; i >= 0; --i) {
        const int lam = model.parent[i];
        const Vector6d& f = data.f[i];
        data.tau[i] = data.S[i].dot(f);

        // reaction at the child's joint point, in world and joint axes
        if (reactions) {
            const Eigen::Isometry3d& X_wj = data.X_wj[i];
            Vector6d& rw = data.reactionWorld[i];
            rw = forceAboutPoint(f, X_wj.translation());
            const Matrix3d Rt = X_wj.linear().transpose();
            data.reactionJoint[i].head<3>().noalias() = Rt * rw.head<3>();
            data.reactionJoint[i].tail<3>().noalias() = Rt * rw.tail<3>();
        }

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

/// Dense dynamics of a tree with constraints (loop closures, welds); see the header.
void constrainedDynamics(const Model& model, const State& state, Data& data);

}  // namespace

namespace {

void hybridDynamicsFrom(const Model& model, const State& state, Data& data, DynamicsOutputs outputs, int nFree);

}  // namespace

void hybridDynamics(const Model& model, const State& state, Data& data, DynamicsOutputs outputs)
{
    assert(sized(model, state, data));
    hybridDynamicsFrom(model, state, data, outputs, bodyTerms(model, state, data));
}

void hybridDynamicsSamePositions(const Model& model, const State& state, Data& data, DynamicsOutputs outputs)
{
    assert(sized(model, state, data) && !hasConstraints(model, state));
    hybridDynamicsFrom(model, state, data, outputs, bodyTerms(model, state, data, true));
}

namespace {

void hybridDynamicsFrom(const Model& model, const State& state, Data& data, DynamicsOutputs outputs, int nFree)
{
    const int nb = model.nb;
    if (hasConstraints(model, state)) {
        constrainedDynamics(model, state, data);
        return;
    }
    data.constraints.clear();
    data.constraintReactionWorld.clear();
    data.constraintReactionJoint.clear();
    const bool all = outputs != DynamicsOutputs::Accelerations;  // the forces too
    // every θ̈ known: no articulated inertias; with the forces asked for, the
    // Newton–Euler passes alone (RNEA)
    if (nFree == 0 && !all) return;

    // 2. articulated-body inertias and bias forces, leaves to root (RBDA table 7.1, §9.2)
    for (int i = 0; i < nb && nFree > 0; ++i) {
        data.Ib[i].toMatrix(data.IA[i]);
        data.pA[i] = data.pb[i];
    }
    for (int i = nb - 1; i >= 0 && nFree > 0; --i) {
        const int lam = model.parent[i];
        const Vector6d& s = data.S[i];
        if (!data.prescribed[i]) {
            Vector6d& U = data.U[i];
            U = multiply6(data.IA[i], s);
            const double D = flooredInertia(data, i, s.dot(U));
            const double u = data.tauKnown[i] - s.dot(data.pA[i]);
            data.D[i] = D;
            data.uA[i] = u;
            if (lam >= 0) {
                // I^a = I^A − U Uᵀ/D;  p^a = p^A + I^a c + U u/D
                const double k = (u - U.dot(data.c[i])) / D;
                data.pA[lam] += data.pA[i] + k * U;
                data.pA[lam] += multiply6(data.IA[i], data.c[i]);
                passArticulatedInertia(data.IA[lam], data.IA[i], U, D);
            }
        } else if (lam >= 0) {
            // a known θ̈ passes the whole inertia to the parent
            const Vector6d ac = data.c[i] + s * data.qdd[i];
            data.pA[lam] += data.pA[i];
            data.pA[lam] += multiply6(data.IA[i], ac);
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
        if (!all) continue;
        data.alpha[i] = a.head<3>();
        data.acc[i] = a.tail<3>() + data.alpha[i].cross(data.X_wb[i].translation()) +
                      data.omega[i].cross(data.vel[i]);
        data.f[i] = data.Ib[i] * a + data.pb[i];
    }

    if (all) jointForces(model, state, data, outputs == DynamicsOutputs::All);
}

}  // namespace

bool kinematicAccelerations(const Model& model, const State& state, Data& data)
{
    if (hasConstraints(model, state)) return false;
    for (int i = 0; i < model.nb; ++i) {
        if (!isPrescribed(model, state, i)) return false;
    }
    for (int i = 0; i < model.nb; ++i) data.qdd[i] = prescribedAcceleration(model, state, i);
    return true;
}

void impulseResponse(const Model& model, const State& state, Data& data, const Eigen::VectorXd& prescribedJump,
                     const Eigen::VectorXd& freeImpulse, Eigen::VectorXd& dqd, int alsoFree)
{
    const int nb = model.nb;
    assert(prescribedJump.size() == nb && freeImpulse.size() == nb && dqd.size() == nb);
    for (int i = 0; i < nb; ++i) {
        bodyInertia(model, data, i);
        data.Ib[i].toMatrix(data.IA[i]);
        data.pA[i].setZero();
        data.prescribed[i] = i != alsoFree && isPrescribed(model, state, i) ? 1 : 0;
    }
    // leaves to root: the articulated inertias, and the impulses the prescribed jumps
    // and the free joints' impulses pass to the parents (no velocity terms, no gravity)
    for (int i = nb - 1; i >= 0; --i) {
        const int lam = model.parent[i];
        const Vector6d& s = data.S[i];
        if (!data.prescribed[i]) {
            Vector6d& U = data.U[i];
            U = multiply6(data.IA[i], s);
            const double D = flooredInertia(data, i, s.dot(U));
            const double u = freeImpulse[i] - s.dot(data.pA[i]);
            data.D[i] = D;
            data.uA[i] = u;
            if (lam >= 0) {
                data.pA[lam] += data.pA[i] + (u / D) * U;
                passArticulatedInertia(data.IA[lam], data.IA[i], U, D);
            }
        } else if (lam >= 0) {
            data.pA[lam] += data.pA[i];
            data.pA[lam] += multiply6(data.IA[i], s * prescribedJump[i]);
            data.IA[lam] += data.IA[i];
        }
    }
    // root to leaves: the velocity changes
    for (int i = 0; i < nb; ++i) {
        const int lam = model.parent[i];
        Vector6d& dv = data.a[i];
        if (lam >= 0) {
            dv = data.a[lam];
        } else {
            dv.setZero();
        }
        double d = prescribedJump[i];
        if (!data.prescribed[i]) {
            d = (data.uA[i] - data.U[i].dot(dv)) / data.D[i];
            if (!std::isfinite(d)) d = 0;  // a massless subtree: no response
        }
        dqd[i] = d;
        dv += data.S[i] * d;
    }
}

namespace {

constexpr double kRankTolerance = 1e-9;  // singular values below this fraction of the largest are zero

void constrainedDynamics(const Model& model, const State& state, Data& data)
{
    const int nb = model.nb;
    const auto n = static_cast<Eigen::Index>(nb);

    // mass matrix by composite rigid bodies (RBDA §6.2), the articulated inertias as scratch
    for (int i = 0; i < nb; ++i) data.Ib[i].toMatrix(data.IA[i]);
    massMatrixFromInertias(model, data, data.IA, data.M);
    for (Eigen::Index i = 0; i < data.inertiaFloor.size(); ++i) data.M(i, i) = flooredInertia(data, static_cast<int>(i), data.M(i, i));

    // bias: accelerations and generalized forces at θ̈ = 0 (RNEA)
    data.a0.resize(static_cast<std::size_t>(nb));
    data.bias.resize(n);
    for (int i = 0; i < nb; ++i) {
        const int lam = model.parent[i];
        data.a0[i] = data.c[i];
        if (lam >= 0) data.a0[i] += data.a0[lam];
        data.f[i] = data.Ib[i] * data.a0[i] + data.pb[i];
    }
    for (int i = nb - 1; i >= 0; --i) {
        data.bias[i] = data.S[i].dot(data.f[i]);
        if (model.parent[i] >= 0) data.f[model.parent[i]] += data.f[i];
    }

    // constraint rows
    collectConstraints(model, state, data.constraints);
    constraintJacobian(model, data, &data.a0);
    const Eigen::Index m = data.G.rows();

    // free (unknown θ̈) and prescribed (known θ̈) coordinates
    std::vector<int> F;
    F.reserve(static_cast<std::size_t>(nb));
    for (int i = 0; i < nb; ++i) {
        if (!data.prescribed[i]) F.push_back(i);
    }
    const auto nF = static_cast<Eigen::Index>(F.size());
    Eigen::MatrixXd MFF(nF, nF), GF(m, nF);
    Eigen::VectorXd rhs(nF);
    Eigen::VectorXd gp = data.gamma;
    for (int p = 0; p < nb; ++p) {
        if (data.prescribed[p]) gp -= data.G.col(p) * data.qdd[p];
    }
    for (Eigen::Index a = 0; a < nF; ++a) {
        const int i = F[static_cast<std::size_t>(a)];
        double r = data.tauKnown[i] - data.bias[i];
        for (int p = 0; p < nb; ++p) {
            if (data.prescribed[p]) r -= data.M(i, p) * data.qdd[p];
        }
        rhs[a] = r;
        for (Eigen::Index b = 0; b < nF; ++b) MFF(a, b) = data.M(i, F[static_cast<std::size_t>(b)]);
        GF.col(a) = data.G.col(i);
    }

    // θ̈_F = particular + null-space part: G_F θ̈_F = γ' (least squares, redundant rows
    // allowed), Nᵀ(M_FF θ̈_F − rhs) = 0; then λ from G_Fᵀ λ = M_FF θ̈_F − rhs (min-norm)
    data.lambda.setZero(m);
    if (!GF.allFinite() || !MFF.allFinite() || !rhs.allFinite() || !gp.allFinite()) {
        // a factorisation of non-finite numbers is undefined (Eigen's SVD crashes on
        // them): non-finite accelerations, which the integrator reports with the time
        for (int i : F) data.qdd[i] = std::numeric_limits<double>::quiet_NaN();
        data.constraintSingular.resize(0);
        data.constraintRank = 0;
    } else if (nF > 0 && m > 0) {
        Eigen::JacobiSVD<Eigen::MatrixXd> svd(GF, Eigen::ComputeThinU | Eigen::ComputeFullV);
        data.constraintSingular = svd.singularValues();
        const Eigen::VectorXd& sv = data.constraintSingular;
        Eigen::Index numerical = 0;
        while (numerical < sv.size() && sv[numerical] > kRankTolerance * sv[0]) ++numerical;
        data.constraintRank = static_cast<int>(numerical);
        // the rank the simulation fixed at its last mode change, on the constraints: off
        // them (an integrator's intermediate stage) a redundant row of a planar loop is
        // no longer exactly redundant, and taking its tiny singular value for a
        // constraint would give nonsense accelerations
        Eigen::Index r = state.constraintRank >= 0 ? std::min<Eigen::Index>(state.constraintRank, sv.size()) : numerical;
        while (r > 0 && !(sv[r - 1] > 0)) --r;
        const auto& U = svd.matrixU();
        const auto& V = svd.matrixV();
        const Eigen::VectorXd sinv = sv.head(r).cwiseInverse();
        Eigen::VectorXd qF = V.leftCols(r) * sinv.cwiseProduct(U.leftCols(r).transpose() * gp);
        if (nF > r) {
            const Eigen::MatrixXd N = V.rightCols(nF - r);
            const Eigen::MatrixXd A = N.transpose() * MFF * N;
            const Eigen::VectorXd z = A.ldlt().solve(N.transpose() * (rhs - MFF * qF));
            qF += N * z;
        }
        const Eigen::VectorXd excess = MFF * qF - rhs;
            data.lambda = U.leftCols(r) * sinv.cwiseProduct(V.leftCols(r).transpose() * excess);
        for (Eigen::Index a = 0; a < nF; ++a) data.qdd[F[static_cast<std::size_t>(a)]] = qF[a];
    } else {
        data.constraintSingular.resize(0);
        data.constraintRank = 0;
        if (nF > 0) {
            const Eigen::VectorXd qF = MFF.ldlt().solve(rhs);
            for (Eigen::Index a = 0; a < nF; ++a) data.qdd[F[static_cast<std::size_t>(a)]] = qF[a];
        }
    }

    // accelerations, and each body's I a + p less the constraint loads on it
    for (int i = 0; i < nb; ++i) {
        const int lam = model.parent[i];
        Vector6d& a = data.a[i];
        a = data.c[i] + data.S[i] * data.qdd[i];
        if (lam >= 0) a += data.a[lam];
        data.alpha[i] = a.head<3>();
        data.acc[i] = a.tail<3>() + data.alpha[i].cross(data.X_wb[i].translation()) +
                      data.omega[i].cross(data.vel[i]);
        data.f[i] = data.Ib[i] * a + data.pb[i];
    }
    const auto nc = data.constraints.size();
    data.constraintReactionWorld.assign(nc, Vector6d::Zero());
    data.constraintReactionJoint.assign(nc, Vector6d::Zero());
    for (Eigen::Index row = 0; row < m; ++row) {
        const auto k = static_cast<std::size_t>(data.rowConstraint[static_cast<std::size_t>(row)]);
        const Constraint& c = data.constraints[k];
        const double l = data.lambda[row];
        const Vector6d& w1 = data.W1[static_cast<std::size_t>(row)];
        const Vector6d& w2 = data.W2[static_cast<std::size_t>(row)];
        if (c.body1 >= 0) data.f[c.body1] -= l * w1;
        if (c.body2 >= 0) data.f[c.body2] -= l * w2;
        data.constraintReactionWorld[k] += l * w2;  // about the origin for now
    }
    for (std::size_t k = 0; k < nc; ++k) {
        const Constraint& c = data.constraints[k];
        const Eigen::Isometry3d F2 = c.body2 >= 0 ? data.X_wb[c.body2] * c.X_2 : c.X_2;
        Vector6d& rw = data.constraintReactionWorld[k];
        rw = forceAboutPoint(rw, F2.translation());
        const Matrix3d Rt = F2.linear().transpose();
        data.constraintReactionJoint[k].head<3>() = Rt * rw.head<3>();
        data.constraintReactionJoint[k].tail<3>() = Rt * rw.tail<3>();
    }

    jointForces(model, state, data);
}

}  // namespace

}  // namespace solver
