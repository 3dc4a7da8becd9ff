#include "solver/reference/newton_euler.h"

#include <algorithm>
#include <cmath>

namespace solver::reference {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// unknowns per tree index, and their offsets; then per cut joint
constexpr int kPer = 13;
constexpr int kAG = 0, kAlpha = 3, kF = 6, kM = 9, kQdd = 12;
constexpr int kPerCut = 7;
constexpr int kCutF = 0, kCutM = 3, kCutQdd = 6;

Matrix3d crossMatrix(const Vector3d& v)
{
    Matrix3d s;
    s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return s;
}

// the drive's force in the modeler's coordinate q (MODEL_LANGUAGE.md "Drives")
double driveLaw(const Model& model, const State& state, const CompiledDrive& d, double u, double q, double qdot,
                double integral, ReliefState relief)
{
    switch (d.type) {
    case DriveType::FluidPower: {
        // F = p_A·A_A − p_B·A_B − c·q̇, written out here (an independent check of actuator.h)
        const CompiledCircuit& c = model.circuits[static_cast<std::size_t>(d.circuit)];
        const Eigen::Index k = kFluidStates * static_cast<Eigen::Index>(d.circuit);
        const double pA = state.fluid[k + 1] > 0 ? state.fluid[k + 1] : 0.0;
        const double pB = state.fluid[k + 2] > 0 ? state.fluid[k + 2] : 0.0;
        return pA * c.areaA - pB * c.areaB - c.friction * qdot;
    }
    case DriveType::None: return 0;
    case DriveType::Motor:
        if (std::abs(qdot) >= d.w0) return 0;
        return u * d.t0 * (1 - std::abs(qdot) / d.w0);
    case DriveType::Pneumatic: return u * d.force;
    case DriveType::Servo: {
        const double setPoint = d.setLow + (u + 1) / 2 * (d.setHigh - d.setLow);
        const double force = d.kp * (setPoint - q) + d.ki * integral + d.kd * (-qdot);
        return std::max(-d.servoFmax, std::min(d.servoFmax, force));
    }
    case DriveType::Hydraulic:
        if (relief == ReliefState::OpenExtending) return d.fmax;
        if (relief == ReliefState::OpenRetracting) return -d.fmin;
        return 0;
    }
    return 0;
}

}  // namespace

NewtonEulerSystem::NewtonEulerSystem(const Model& model) : m_model(model)
{
    const auto sz = static_cast<std::size_t>(model.nb);
    const auto n = static_cast<Eigen::Index>(kPer * model.nb + kPerCut * static_cast<int>(model.cuts.size()));
    m_X.resize(sz);
    for (auto* v : {&m_G, &m_x, &m_axis, &m_slide, &m_w, &m_vG}) v->assign(sz, Vector3d::Zero());
    m_Iw.assign(sz, Matrix3d::Zero());
    m_q.setZero(model.nb);
    m_qdot.setZero(model.nb);
    m_dq.setZero(model.nb);
    m_A.setZero(n, n);
    m_B.setZero(n);
    m_Xu.setZero(n);
    if (model.cuts.empty()) {
        m_lu = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
    } else {
        m_fullLu = Eigen::FullPivLU<Eigen::MatrixXd>(n, n);
    }
    NewtonEulerResult& r = m_result;
    r.qdd.setZero(model.nb);
    r.tau.setZero(model.nb);
    r.driveForce.setZero(model.nb);
    r.limitForce.setZero(model.nb);
    r.aG.assign(sz, Vector3d::Zero());
    r.alpha.assign(sz, Vector3d::Zero());
    r.reaction.assign(sz, Vector6d::Zero());
    r.cutReaction.assign(model.cuts.size(), Vector6d::Zero());
}

void NewtonEulerSystem::assemble(const State& state, const std::vector<Vector6d>& fext,
                                 const Eigen::VectorXd& tauExt)
{
    const Model& model = m_model;
    const int nb = model.nb;
    auto col = [](int i, int offset) { return static_cast<Eigen::Index>(kPer * i + offset); };
    auto cutCol = [nb](int c, int offset) { return static_cast<Eigen::Index>(kPer * nb + kPerCut * c + offset); };
    auto& X = m_X;
    auto& G = m_G;
    auto& x = m_x;
    auto& axis = m_axis;
    auto& slide = m_slide;
    auto& Iw = m_Iw;
    auto& w = m_w;
    auto& vG = m_vG;

    // positions (eq. 2.1): body frames, centres of mass, joint points and directions
    for (int i = 0; i < nb; ++i) {
        const int p = model.parent[i];
        const Eigen::Isometry3d X_wp = p < 0 ? Eigen::Isometry3d::Identity() : X[p];
        const double th = model.axisSign[i] * state.q[i];
        Eigen::Isometry3d J = Eigen::Isometry3d::Identity();
        if (model.jointType[i] == JointType::Prismatic) {
            J.translation() = Vector3d(0, th, 0);
        } else {
            J.linear() = Eigen::AngleAxisd(th, Vector3d::UnitX()).toRotationMatrix();
        }
        Eigen::Isometry3d X_wj = X_wp * model.X_pj[i];
        if (model.freeBase[i] >= 0 && state.q.size() == model.nq) {
            // a free joint's turns start from its base orientation (core/model.h)
            const Eigen::Index k = model.freeBase[i];
            X_wj = X_wj * Eigen::Quaterniond(state.q[k], state.q[k + 1], state.q[k + 2], state.q[k + 3]).normalized();
        }
        X_wj = X_wj * J;
        X[i] = X_wj * model.X_cj[i].inverse(Eigen::Isometry);
        x[i] = X_wj.translation();
        axis[i] = model.axisSign[i] * X_wj.linear().col(0);
        slide[i] = model.axisSign[i] * X_wj.linear().col(1);
        G[i] = X[i] * model.com[i];
        Iw[i] = X[i].linear() * model.inertia[i] * X[i].linear().transpose();
    }

    // velocities (eq. 2.2–2.4)
    auto pointVelocity = [&](int b, const Vector3d& y) -> Vector3d {
        return b < 0 ? Vector3d::Zero() : Vector3d(vG[b] + w[b].cross(y - G[b]));
    };
    for (int i = 0; i < nb; ++i) {
        const int p = model.parent[i];
        const Vector3d wp = p < 0 ? Vector3d::Zero() : w[p];
        Vector3d vx = pointVelocity(p, x[i]);
        if (model.jointType[i] == JointType::Prismatic) {
            w[i] = wp;
            vx += state.qd[i] * slide[i];
        } else {
            w[i] = wp + state.qd[i] * axis[i];
        }
        vG[i] = vx + w[i].cross(G[i] - x[i]);
    }

    // a body point's acceleration a_G − [y − G]× α + ω × (ω × (y − G)): adds coeff·(the
    // unknown part) to row r of A and −coeff·(the known part) to B(r), for a row vector coeff
    Eigen::MatrixXd& A = m_A;
    Eigen::VectorXd& B = m_B;
    A.setZero();
    B.setZero();
    auto addPointAcceleration = [&](Eigen::Index r, int b, const Vector3d& y,
                                    const Eigen::RowVector3d& coeff) {
        if (b < 0) return;
        A.block<1, 3>(r, col(b, kAG)) += coeff;
        A.block<1, 3>(r, col(b, kAlpha)) -= coeff * crossMatrix(y - G[b]);
        B(r) -= coeff.dot(w[b].cross(w[b].cross(y - G[b])));
    };

    // modeler's coordinate, its rate and dq/dθ, from the geometry
    Eigen::VectorXd& q = m_q;
    Eigen::VectorXd& qdot = m_qdot;
    Eigen::VectorXd& dq = m_dq;
    const Matrix3d one = Matrix3d::Identity();
    for (int i = 0; i < nb; ++i) {
        const int p = model.parent[i];
        const Eigen::Index r = col(i, 0);
        const double m = model.mass[i];
        const bool prismatic = model.jointType[i] == JointType::Prismatic;

        // Newton (eq. 2.8), about the centre of mass
        A.block<3, 3>(r, col(i, kAG)) = m * one;
        A.block<3, 3>(r, col(i, kF)) = -one;
        B.segment<3>(r) = m * model.gravity + fext[i].tail<3>();

        // Euler (eq. 2.9), about the centre of mass
        A.block<3, 3>(r + 3, col(i, kAlpha)) = Iw[i];
        A.block<3, 3>(r + 3, col(i, kM)) = -one;
        A.block<3, 3>(r + 3, col(i, kF)) = -crossMatrix(x[i] - G[i]);
        const Vector3d o = X[i].translation();
        const Vector3d momentG = fext[i].head<3>() + (o - G[i]).cross(fext[i].tail<3>());
        B.segment<3>(r + 3) = momentG - w[i].cross(Iw[i] * w[i]);

        // children's reactions act back on this body
        for (int k = i + 1; k < nb; ++k) {
            if (model.parent[k] != i) continue;
            A.block<3, 3>(r, col(k, kF)) += one;
            A.block<3, 3>(r + 3, col(k, kM)) += one;
            A.block<3, 3>(r + 3, col(k, kF)) += crossMatrix(x[k] - G[i]);
        }

        // joint rotation (eq. 2.7)
        const Vector3d wp = p < 0 ? Vector3d::Zero() : w[p];
        A.block<3, 3>(r + 6, col(i, kAlpha)) = one;
        if (p >= 0) A.block<3, 3>(r + 6, col(p, kAlpha)) = -one;
        if (!prismatic) {
            A.block<3, 1>(r + 6, col(i, kQdd)) = -axis[i];
            B.segment<3>(r + 6) = state.qd[i] * wp.cross(axis[i]);
        }

        // joint translation (eq. 2.5–2.6): the child's joint point against the parent's point there
        A.block<3, 3>(r + 9, col(i, kAG)) = one;
        A.block<3, 3>(r + 9, col(i, kAlpha)) = -crossMatrix(x[i] - G[i]);
        Vector3d rhs = -w[i].cross(w[i].cross(x[i] - G[i]));
        if (p >= 0) {
            A.block<3, 3>(r + 9, col(p, kAG)) = -one;
            A.block<3, 3>(r + 9, col(p, kAlpha)) = crossMatrix(x[i] - G[p]);
            rhs += w[p].cross(w[p].cross(x[i] - G[p]));
        }
        if (prismatic) {
            A.block<3, 1>(r + 9, col(i, kQdd)) = -slide[i];
            rhs += 2 * state.qd[i] * wp.cross(slide[i]);
        }
        B.segment<3>(r + 9) = rhs;

        // the modeler's coordinate: for T 1 the distance between the actuator's ends
        q[i] = state.q[i];
        qdot[i] = state.qd[i];
        dq[i] = 1;
        int s1 = -1, s2 = -1;
        Vector3d y1 = Vector3d::Zero(), y2 = Vector3d::Zero(), e = Vector3d::Zero();
        if (model.jointType[i] == JointType::Actuator) {
            const bool reversed = model.axisSign[i] < 0;
            s1 = reversed ? i : p;
            s2 = reversed ? p : i;
            y1 = s1 < 0 ? model.cl1[i] : Vector3d(X[s1] * model.cl1[i]);
            y2 = s2 < 0 ? model.cl2[i] : Vector3d(X[s2] * model.cl2[i]);
            const Vector3d d = y2 - y1;
            e = d.normalized();
            q[i] = d.norm();
            qdot[i] = e.dot(pointVelocity(s2, y2) - pointVelocity(s1, y1));
            // the end on the child turns about the joint axis
            const Vector3d dd = reversed ? Vector3d(-axis[i].cross(y1 - x[i]))
                                         : Vector3d(axis[i].cross(y2 - x[i]));
            dq[i] = e.dot(dd);
        }

        // drive or passive condition
        const Eigen::Index rc = r + 12;
        const CompiledDrive& drive = model.drive[i];
        const bool held = drive.type == DriveType::Hydraulic && state.relief[i] == ReliefState::Closed;
        if (state.limit[i] != LimitState::Free || (held && model.jointType[i] != JointType::Actuator)) {
            A(rc, col(i, kQdd)) = 1;  // θ̈ = 0
        } else if (held) {
            // L̇ held: L̈ = e·(a2 − a1) + (|v21|² − L̇²)/L = 0
            const Vector3d v21 = pointVelocity(s2, y2) - pointVelocity(s1, y1);
            addPointAcceleration(rc, s2, y2, e.transpose());
            addPointAcceleration(rc, s1, y1, -e.transpose());
            B(rc) -= (v21.squaredNorm() - qdot[i] * qdot[i]) / q[i];
        } else {
            const double force = driveLaw(model, state, drive, state.u[i], q[i], qdot[i], state.servoIntegral[i],
                                          state.relief[i]);
            if (prismatic) {
                A.block<1, 3>(rc, col(i, kF)) = slide[i].transpose();
            } else {
                A.block<1, 3>(rc, col(i, kM)) = axis[i].transpose();
            }
            B(rc) = force * dq[i] + tauExt[i];
        }
    }

    // loop-closing (cut) joints: body 1 in the parent's place, body 2 in the child's
    for (std::size_t k = 0; k < model.cuts.size(); ++k) {
        const CutJoint& cut = model.cuts[k];
        const int c = static_cast<int>(k);
        const int b1 = cut.body1, b2 = cut.body2;
        const Eigen::Index r = cutCol(c, 0);
        const Eigen::Isometry3d X_w2 =
            (b2 < 0 ? Eigen::Isometry3d::Identity() : Eigen::Isometry3d(X[b2])) * cut.X_2;
        const Vector3d xc = X_w2.translation();
        const Vector3d a = X_w2.linear().col(0);
        const Vector3d s = X_w2.linear().col(1);
        const bool prismatic = cut.type == JointType::Prismatic;
        const Vector3d w1 = b1 < 0 ? Vector3d::Zero() : w[b1];
        const Vector3d w2 = b2 < 0 ? Vector3d::Zero() : w[b2];

        // its load on body 2 (as a child's) and back on body 1 (as a parent's)
        if (b2 >= 0) {
            A.block<3, 3>(col(b2, 0), cutCol(c, kCutF)) -= one;
            A.block<3, 3>(col(b2, 3), cutCol(c, kCutM)) -= one;
            A.block<3, 3>(col(b2, 3), cutCol(c, kCutF)) -= crossMatrix(xc - G[b2]);
        }
        if (b1 >= 0) {
            A.block<3, 3>(col(b1, 0), cutCol(c, kCutF)) += one;
            A.block<3, 3>(col(b1, 3), cutCol(c, kCutM)) += one;
            A.block<3, 3>(col(b1, 3), cutCol(c, kCutF)) += crossMatrix(xc - G[b1]);
        }

        // its rate: about A (T 0, T 1), along R (T 2)
        const double rate = prismatic ? s.dot(pointVelocity(b2, xc) - pointVelocity(b1, xc)) : a.dot(w2 - w1);

        // rotation (eq. 2.7)
        if (b2 >= 0) A.block<3, 3>(r, col(b2, kAlpha)) += one;
        if (b1 >= 0) A.block<3, 3>(r, col(b1, kAlpha)) -= one;
        if (!prismatic) {
            A.block<3, 1>(r, cutCol(c, kCutQdd)) = -a;
            B.segment<3>(r) = rate * w1.cross(a);
        }
        // translation (eq. 2.5–2.6): body 2's point at P2 against body 1's point there
        for (int row = 0; row < 3; ++row) {
            const Eigen::RowVector3d unit = Eigen::RowVector3d::Unit(row);
            addPointAcceleration(r + 3 + row, b2, xc, unit);
            addPointAcceleration(r + 3 + row, b1, xc, -unit);
        }
        if (prismatic) {
            A.block<3, 1>(r + 3, cutCol(c, kCutQdd)) = -s;
            B.segment<3>(r + 3) += 2 * rate * w1.cross(s);
        }
        // passive: no load along its free direction
        if (prismatic) {
            A.block<1, 3>(r + 6, cutCol(c, kCutF)) = s.transpose();
        } else {
            A.block<1, 3>(r + 6, cutCol(c, kCutM)) = a.transpose();
        }
    }
}

void NewtonEulerSystem::solveLinear()
{
    // Gaussian elimination (eq. 2.11)
    if (m_model.cuts.empty()) {
        m_lu.compute(m_A);
        m_Xu.noalias() = m_lu.solve(m_B);
    } else {
        m_fullLu.compute(m_A);
        m_Xu.noalias() = m_fullLu.solve(m_B);
    }
}

const NewtonEulerResult& NewtonEulerSystem::solve(const State& state, const std::vector<Vector6d>& fext,
                                                  const Eigen::VectorXd& tauExt, bool residual)
{
    const Model& model = m_model;
    const int nb = model.nb;
    auto col = [](int i, int offset) { return static_cast<Eigen::Index>(kPer * i + offset); };
    assemble(state, fext, tauExt);
    solveLinear();

    NewtonEulerResult& out = m_result;
    out.relativeResidual = residual ? (m_A * m_Xu - m_B).norm() / std::max(m_B.norm(), 1e-300) : 0.0;
    for (int i = 0; i < nb; ++i) {
        out.qdd[i] = m_Xu(col(i, kQdd));
        out.aG[i] = m_Xu.segment<3>(col(i, kAG));
        out.alpha[i] = m_Xu.segment<3>(col(i, kAlpha));
        out.reaction[i].head<3>() = m_Xu.segment<3>(col(i, kM));
        out.reaction[i].tail<3>() = m_Xu.segment<3>(col(i, kF));
        out.tau[i] = model.jointType[i] == JointType::Prismatic ? m_slide[i].dot(out.reaction[i].tail<3>())
                                                                : m_axis[i].dot(out.reaction[i].head<3>());

        const CompiledDrive& drive = model.drive[i];
        const double law = driveLaw(m_model, state, drive, state.u[i], m_q[i], m_qdot[i], state.servoIntegral[i], state.relief[i]);
        const bool hydraulicHeld = drive.type == DriveType::Hydraulic &&
                                   (state.limit[i] != LimitState::Free || state.relief[i] == ReliefState::Closed);
        out.driveForce[i] = hydraulicHeld ? (out.tau[i] - tauExt[i]) / m_dq[i] : law;
        out.limitForce[i] = state.limit[i] != LimitState::Free && !hydraulicHeld
                                ? out.tau[i] - law * m_dq[i] - tauExt[i]
                                : 0.0;
    }
    for (std::size_t k = 0; k < model.cuts.size(); ++k) {
        const auto c0 = static_cast<Eigen::Index>(kPer * nb + kPerCut * static_cast<int>(k));
        out.cutReaction[k].head<3>() = m_Xu.segment<3>(c0 + kCutM);
        out.cutReaction[k].tail<3>() = m_Xu.segment<3>(c0 + kCutF);
    }
    return out;
}

NewtonEulerResult solveNewtonEuler(const Model& model, const State& state, const std::vector<Vector6d>& fext,
                                   const Eigen::VectorXd& tauExt)
{
    NewtonEulerSystem system(model);
    return system.solve(state, fext, tauExt, true);
}

void rk4Step(NewtonEulerSystem& system, State& state, const std::vector<Vector6d>& fext,
             const Eigen::VectorXd& tauExt, double h, Rk4Work& work)
{
    State& s = work.stage;
    s = state;  // the same sizes after the first step: no allocation
    work.q0 = state.q;
    work.qd0 = state.qd;
    // k1 at the start
    work.kq = work.qd0;
    work.kv = system.solve(s, fext, tauExt, false).qdd;
    work.accQ = work.kq;
    work.accV = work.kv;
    // k2, k3 at the middle, k4 at the end, each from the previous stage's slopes;
    // weights 1, 2, 2, 1
    for (int k = 2; k <= 4; ++k) {
        const double c = k == 4 ? 1.0 : 0.5;
        const double weight = k == 4 ? 1.0 : 2.0;
        s.t = state.t + c * h;
        s.q.head(work.kq.size()) = work.q0.head(work.kq.size()) + (c * h) * work.kq;  // (free bases: held)
        s.qd = work.qd0 + (c * h) * work.kv;
        work.kq = s.qd;
        work.kv = system.solve(s, fext, tauExt, false).qdd;
        work.accQ += weight * work.kq;
        work.accV += weight * work.kv;
    }
    state.q.head(work.accQ.size()) = work.q0.head(work.accQ.size()) + (h / 6) * work.accQ;
    state.qd = work.qd0 + (h / 6) * work.accV;
    state.t += h;
}

}  // namespace solver::reference
