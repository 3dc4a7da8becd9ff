#include "tests/solver/dynamics/thesis_oracle.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace solver::test {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// unknowns per tree index, and their offsets
constexpr int kPer = 13;
constexpr int kAG = 0, kAlpha = 3, kF = 6, kM = 9, kQdd = 12;

Matrix3d crossMatrix(const Vector3d& v)
{
    Matrix3d s;
    s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return s;
}

// the drive's force in the modeler's coordinate q (MODEL_LANGUAGE.md "Drives")
double driveLaw(const CompiledDrive& d, double u, double q, double qdot, double integral,
                ReliefState relief)
{
    switch (d.type) {
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

OracleResult solveThesisSystem(const Model& model, const State& state,
                               const std::vector<Vector6d>& fext, const Eigen::VectorXd& tauExt)
{
    const int nb = model.nb;
    const auto n = static_cast<Eigen::Index>(kPer * nb);
    const auto sz = static_cast<std::size_t>(nb);
    auto col = [](int i, int offset) { return static_cast<Eigen::Index>(kPer * i + offset); };

    // positions (eq. 2.1): body frames, centres of mass, joint points and directions
    std::vector<Eigen::Isometry3d> X(sz);
    std::vector<Vector3d> G(sz), x(sz), axis(sz), slide(sz);
    std::vector<Matrix3d> Iw(sz);
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
        const Eigen::Isometry3d X_wj = X_wp * model.X_pj[i] * J;
        X[i] = X_wj * model.X_cj[i].inverse(Eigen::Isometry);
        x[i] = X_wj.translation();
        axis[i] = model.axisSign[i] * X_wj.linear().col(0);
        slide[i] = model.axisSign[i] * X_wj.linear().col(1);
        G[i] = X[i] * model.com[i];
        Iw[i] = X[i].linear() * model.inertia[i] * X[i].linear().transpose();
    }

    // velocities (eq. 2.2–2.4)
    std::vector<Vector3d> w(sz), vG(sz);
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
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd B = Eigen::VectorXd::Zero(n);
    auto addPointAcceleration = [&](Eigen::Index r, int b, const Vector3d& y,
                                    const Eigen::RowVector3d& coeff) {
        if (b < 0) return;
        A.block<1, 3>(r, col(b, kAG)) += coeff;
        A.block<1, 3>(r, col(b, kAlpha)) -= coeff * crossMatrix(y - G[b]);
        B(r) -= coeff.dot(w[b].cross(w[b].cross(y - G[b])));
    };

    // modeler's coordinate, its rate and dq/dθ, from the geometry
    Eigen::VectorXd q(nb), qdot(nb), dq(nb);
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
        Vector3d y1, y2, e;
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
            const double force = driveLaw(drive, state.u[i], q[i], qdot[i], state.servoIntegral[i],
                                          state.relief[i]);
            if (prismatic) {
                A.block<1, 3>(rc, col(i, kF)) = slide[i].transpose();
            } else {
                A.block<1, 3>(rc, col(i, kM)) = axis[i].transpose();
            }
            B(rc) = force * dq[i] + tauExt[i];
        }
    }

    // Gaussian elimination (eq. 2.11)
    const Eigen::VectorXd X_u = A.partialPivLu().solve(B);

    OracleResult out;
    out.relativeResidual = (A * X_u - B).norm() / std::max(B.norm(), 1e-300);
    out.qdd.resize(nb);
    out.tau.resize(nb);
    out.driveForce.resize(nb);
    out.limitForce.resize(nb);
    out.aG.resize(sz);
    out.alpha.resize(sz);
    out.reaction.resize(sz);
    for (int i = 0; i < nb; ++i) {
        out.qdd[i] = X_u(col(i, kQdd));
        out.aG[i] = X_u.segment<3>(col(i, kAG));
        out.alpha[i] = X_u.segment<3>(col(i, kAlpha));
        out.reaction[i].head<3>() = X_u.segment<3>(col(i, kM));
        out.reaction[i].tail<3>() = X_u.segment<3>(col(i, kF));
        out.tau[i] = model.jointType[i] == JointType::Prismatic
                         ? slide[i].dot(out.reaction[i].tail<3>())
                         : axis[i].dot(out.reaction[i].head<3>());

        const CompiledDrive& drive = model.drive[i];
        const double law = driveLaw(drive, state.u[i], q[i], qdot[i], state.servoIntegral[i],
                                    state.relief[i]);
        const bool hydraulicHeld = drive.type == DriveType::Hydraulic &&
                                   (state.limit[i] != LimitState::Free ||
                                    state.relief[i] == ReliefState::Closed);
        out.driveForce[i] = hydraulicHeld ? (out.tau[i] - tauExt[i]) / dq[i] : law;
        out.limitForce[i] = state.limit[i] != LimitState::Free && !hydraulicHeld
                                ? out.tau[i] - law * dq[i] - tauExt[i]
                                : 0.0;
    }
    return out;
}

}  // namespace solver::test
