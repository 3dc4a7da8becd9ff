#include "solver/dynamics/constraints.h"

#include "solver/dynamics/mass_matrix.h"
#include "solver/kinematics/kinematics.h"

#include <Eigen/Cholesky>
#include <Eigen/SVD>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace solver {

using Eigen::Vector3d;

namespace {

ConstraintKind kindOf(JointType type)
{
    return type == JointType::Prismatic ? ConstraintKind::Prismatic : ConstraintKind::Revolute;
}

/// A body's motion at one instant: velocity and bias acceleration (θ̈ = 0), spatial.
struct BodyMotion {
    Vector3d w = Vector3d::Zero(), vo = Vector3d::Zero();   // ω, v_O
    Vector3d al = Vector3d::Zero(), ao = Vector3d::Zero();  // α, a_O at θ̈ = 0

    Vector3d pointVel(const Vector3d& x) const { return vo + w.cross(x); }
    Vector3d pointAcc(const Vector3d& x) const { return ao + al.cross(x) + w.cross(pointVel(x)); }
    Vector3d dirVel(const Vector3d& d) const { return w.cross(d); }
    Vector3d dirAcc(const Vector3d& d) const { return al.cross(d) + w.cross(w.cross(d)); }
};

BodyMotion motionOf(const Data& data, const std::vector<Vector6d>* a0, int body)
{
    BodyMotion m;
    if (body < 0) return m;
    m.w = data.v[body].head<3>();
    m.vo = data.v[body].tail<3>();
    if (a0) {
        m.al = (*a0)[body].head<3>();
        m.ao = (*a0)[body].tail<3>();
    }
    return m;
}

Eigen::Isometry3d worldFrame(const Data& data, int body, const Eigen::Isometry3d& X)
{
    return body < 0 ? X : data.X_wb[body] * X;
}

/// One constraint's frames in the world.
struct Frames {
    Vector3d p1, a1, r1, t1, p2, a2, r2, t2;
};

Frames framesOf(const Data& data, const Constraint& c)
{
    const Eigen::Isometry3d F1 = worldFrame(data, c.body1, c.X_1);
    const Eigen::Isometry3d F2 = worldFrame(data, c.body2, c.X_2);
    Frames f;
    f.p1 = F1.translation();
    f.a1 = F1.linear().col(0);
    f.r1 = F1.linear().col(1);
    f.t1 = F1.linear().col(2);
    f.p2 = F2.translation();
    f.a2 = F2.linear().col(0);
    f.r2 = F2.linear().col(1);
    f.t2 = F2.linear().col(2);
    return f;
}

Vector6d wrench(const Vector3d& moment, const Vector3d& force)
{
    Vector6d w;
    w << moment, force;
    return w;
}

/// One equation: value, loads on the two bodies per unit λ, and −Φ̈ at θ̈ = 0.
struct Row {
    double phi = 0;
    Vector6d w1 = Vector6d::Zero(), w2 = Vector6d::Zero();
    double gamma = 0;
};

// (p2 − p1)·e, e a fixed world axis
Row pointRow(const Frames& f, const BodyMotion& m1, const BodyMotion& m2, const Vector3d& e, bool accel)
{
    Row r;
    r.phi = (f.p2 - f.p1).dot(e);
    r.w1 = -wrench(f.p1.cross(e), e);
    r.w2 = wrench(f.p2.cross(e), e);
    if (accel) r.gamma = -(m2.pointAcc(f.p2) - m1.pointAcc(f.p1)).dot(e);
    return r;
}

// x·y, x a direction on body 1, y on body 2
Row dotRow(const Vector3d& x, const Vector3d& y, const BodyMotion& m1, const BodyMotion& m2, bool accel)
{
    Row r;
    r.phi = x.dot(y);
    const Vector3d xy = x.cross(y);
    r.w1 = wrench(xy, Vector3d::Zero());
    r.w2 = wrench(-xy, Vector3d::Zero());
    if (accel) {
        r.gamma = -(m1.dirAcc(x).dot(y) + 2 * m1.dirVel(x).dot(m2.dirVel(y)) + x.dot(m2.dirAcc(y)));
    }
    return r;
}

// (p2 − p1)·d, d a direction on body 1
Row offsetRow(const Frames& f, const Vector3d& d, const BodyMotion& m1, const BodyMotion& m2, bool accel)
{
    Row r;
    const Vector3d delta = f.p2 - f.p1;
    r.phi = delta.dot(d);
    r.w1 = wrench(-f.p1.cross(d) + d.cross(delta), -d);
    r.w2 = wrench(f.p2.cross(d), d);
    if (accel) {
        const Vector3d dv = m2.pointVel(f.p2) - m1.pointVel(f.p1);
        const Vector3d da = m2.pointAcc(f.p2) - m1.pointAcc(f.p1);
        r.gamma = -(da.dot(d) + 2 * dv.dot(m1.dirVel(d)) + delta.dot(m1.dirAcc(d)));
    }
    return r;
}

void scaleRow(Row& r, double s)
{
    r.phi *= s;
    r.w1 *= s;
    r.w2 *= s;
    r.gamma *= s;
}

/// The rows of one constraint, in the order of the header, length rows scaled.
template <typename Sink>
void constraintRows(const Model& model, const Data& data, const Constraint& c, const std::vector<Vector6d>* a0,
                    Sink&& sink)
{
    const Frames f = framesOf(data, c);
    const BodyMotion m1 = motionOf(data, a0, c.body1);
    const BodyMotion m2 = motionOf(data, a0, c.body2);
    const bool accel = a0 != nullptr;
    const double s = 1.0 / model.lengthScale;
    auto point = [&](int axis) {
        Row r = pointRow(f, m1, m2, Vector3d::Unit(axis), accel);
        scaleRow(r, s);
        sink(r);
    };
    switch (c.kind) {
    case ConstraintKind::Revolute:
        for (int k = 0; k < 3; ++k) point(k);
        sink(dotRow(f.a1, f.r2, m1, m2, accel));
        sink(dotRow(f.a1, f.t2, m1, m2, accel));
        break;
    case ConstraintKind::Prismatic: {
        sink(dotRow(f.a1, f.r2, m1, m2, accel));
        sink(dotRow(f.a1, f.t2, m1, m2, accel));
        sink(dotRow(f.r1, f.t2, m1, m2, accel));
        Row ra = offsetRow(f, f.a1, m1, m2, accel);
        scaleRow(ra, s);
        sink(ra);
        Row rt = offsetRow(f, f.t1, m1, m2, accel);
        scaleRow(rt, s);
        sink(rt);
        break;
    }
    case ConstraintKind::Weld:
        for (int k = 0; k < 3; ++k) point(k);
        sink(dotRow(f.a1, f.r2, m1, m2, accel));
        sink(dotRow(f.a1, f.t2, m1, m2, accel));
        sink(dotRow(f.r1, f.t2, m1, m2, accel));
        break;
    }
}

}  // namespace

void collectConstraints(const Model& model, const State& state, std::vector<Constraint>& out)
{
    out.clear();
    for (std::size_t k = 0; k < model.cuts.size(); ++k) {
        const CutJoint& cut = model.cuts[k];
        Constraint c;
        c.kind = kindOf(cut.type);
        c.body1 = cut.body1;
        c.body2 = cut.body2;
        c.X_1 = cut.X_1;
        c.X_2 = cut.X_2;
        c.cut = static_cast<int>(k);
        out.push_back(c);
    }
    for (std::size_t k = 0; k < state.welds.size(); ++k) {
        const Weld& w = state.welds[k];
        Constraint c;
        c.kind = ConstraintKind::Weld;
        c.body1 = w.bodyA;
        c.body2 = w.bodyB;
        c.X_1 = Eigen::Isometry3d::Identity();  // body a's own frame
        c.X_2 = w.X_ab.inverse(Eigen::Isometry);  // the same frame seen from body b
        c.weld = static_cast<int>(k);
        out.push_back(c);
    }
}

int constraintRowTotal(const std::vector<Constraint>& constraints)
{
    int n = 0;
    for (const Constraint& c : constraints) n += constraintRowCount(c.kind);
    return n;
}

bool hasConstraints(const Model& model, const State& state) { return !model.cuts.empty() || !state.welds.empty(); }

void constraintResidual(const Model& model, const Data& data, const std::vector<Constraint>& constraints,
                        Eigen::VectorXd& phi)
{
    phi.resize(constraintRowTotal(constraints));
    Eigen::Index row = 0;
    for (const Constraint& c : constraints) {
        constraintRows(model, data, c, nullptr, [&](const Row& r) { phi[row++] = r.phi; });
    }
}

void constraintJacobian(const Model& model, Data& data, const std::vector<Vector6d>* a0)
{
    const int rows = constraintRowTotal(data.constraints);
    const auto nrows = static_cast<std::size_t>(rows);
    if (data.G.rows() != rows || data.G.cols() != model.nb) data.G.resize(rows, model.nb);
    data.G.setZero();
    data.gamma.resize(rows);
    data.phi.resize(rows);
    data.W1.resize(nrows);
    data.W2.resize(nrows);
    data.rowConstraint.resize(nrows);

    int row = 0;
    for (std::size_t k = 0; k < data.constraints.size(); ++k) {
        const Constraint& c = data.constraints[k];
        constraintRows(model, data, c, a0, [&](const Row& r) {
            data.phi[row] = r.phi;
            data.gamma[row] = r.gamma;
            data.W1[static_cast<std::size_t>(row)] = r.w1;
            data.W2[static_cast<std::size_t>(row)] = r.w2;
            data.rowConstraint[static_cast<std::size_t>(row)] = static_cast<int>(k);
            for (int j = c.body1; j >= 0; j = model.parent[j]) data.G(row, j) += r.w1.dot(data.S[j]);
            for (int j = c.body2; j >= 0; j = model.parent[j]) data.G(row, j) += r.w2.dot(data.S[j]);
            ++row;
        });
    }
    assert(row == rows);
}

CutReading readCut(const Model& model, const Data& data, int k)
{
    const CutJoint& c = model.cuts[static_cast<std::size_t>(k)];
    const Eigen::Isometry3d F1 = worldFrame(data, c.body1, c.X_1);
    const Eigen::Isometry3d F2 = worldFrame(data, c.body2, c.X_2);
    const BodyMotion m1 = motionOf(data, nullptr, c.body1);
    const BodyMotion m2 = motionOf(data, nullptr, c.body2);
    const Vector3d a1 = F1.linear().col(0), r1 = F1.linear().col(1), r2 = F2.linear().col(1);
    CutReading out;
    out.angle = std::atan2(r1.cross(r2).dot(a1), r1.dot(r2));
    const double angleRate = (m2.w - m1.w).dot(a1);
    switch (c.type) {
    case JointType::Prismatic: {
        const Vector3d delta = F2.translation() - F1.translation();
        out.q = delta.dot(r1);
        out.qd = (m2.pointVel(F2.translation()) - m1.pointVel(F1.translation())).dot(r1) + delta.dot(m1.dirVel(r1));
        out.angle = 0;
        break;
    }
    case JointType::Actuator: {
        const Vector3d e1 = c.body1 < 0 ? c.cl1 : Vector3d(data.X_wb[c.body1] * c.cl1);
        const Vector3d e2 = c.body2 < 0 ? c.cl2 : Vector3d(data.X_wb[c.body2] * c.cl2);
        const Vector3d d = e2 - e1;
        out.q = d.norm();
        out.qd = out.q > 0 ? (m2.pointVel(e2) - m1.pointVel(e1)).dot(d) / out.q : 0.0;
        break;
    }
    case JointType::Revolute:
    case JointType::Free:  // (never a cut joint: topology.cpp)
        out.q = out.angle;
        out.qd = angleRate;
        break;
    }
    return out;
}

bool constraintRowIsLength(ConstraintKind kind, int row)
{
    switch (kind) {
    case ConstraintKind::Revolute:
    case ConstraintKind::Weld:
        return row < 3;
    case ConstraintKind::Prismatic:
        return row >= 3;
    }
    return false;
}

Eigen::MatrixXd constraintJacobianAt(const Model& model, const State& state, Data& data)
{
    forwardKinematics(model, state, data);
    collectConstraints(model, state, data.constraints);
    if (data.constraints.empty()) return Eigen::MatrixXd(0, model.nb);
    constraintJacobian(model, data, nullptr);
    return data.G;
}

// ---------------------------------------------------------------- corrections

namespace {

/// M's rows and columns of the joints `free` (M_FF).
Eigen::MatrixXd freeBlock(const Eigen::MatrixXd& M, const std::vector<int>& free)
{
    const auto nf = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd mff(nf, nf);
    for (Eigen::Index a = 0; a < nf; ++a) {
        for (Eigen::Index b = 0; b < nf; ++b) mff(a, b) = M(free[a], free[b]);
    }
    return mff;
}

}  // namespace

Eigen::VectorXd constraintCorrection(const Eigen::MatrixXd& M, const std::vector<int>& free,
                                     const Eigen::MatrixXd& G, const Eigen::VectorXd& target)
{
    const auto nf = static_cast<Eigen::Index>(free.size());
    Eigen::VectorXd out = Eigen::VectorXd::Zero(M.rows());
    if (nf == 0 || G.rows() == 0) return out;
    Eigen::MatrixXd gf(G.rows(), nf);
    for (Eigen::Index a = 0; a < nf; ++a) gf.col(a) = G.col(free[a]);
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(freeBlock(M, free));
    const Eigen::MatrixXd minvGt = ldlt.solve(gf.transpose());  // M_FF⁻¹ G_Fᵀ
    const Eigen::MatrixXd S = gf * minvGt;
    // a factorisation of non-finite numbers is undefined (Eigen's SVD crashes on them):
    // no correction, and the caller reports the constraints unmet
    if (!S.allFinite() || !target.allFinite()) return out;
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(S, Eigen::ComputeThinU | Eigen::ComputeThinV);
    svd.setThreshold(1e-10);
    const Eigen::VectorXd mu = svd.solve(target);
    const Eigen::VectorXd d = minvGt * mu;
    for (Eigen::Index a = 0; a < nf; ++a) {
        if (std::isfinite(d[a])) out[free[a]] = d[a];
    }
    return out;
}

Eigen::VectorXd freeResponse(const Eigen::MatrixXd& M, const std::vector<int>& free,
                             const Eigen::VectorXd& impulse, const Eigen::MatrixXd& G,
                             const Eigen::VectorXd& rates)
{
    const auto nf = static_cast<Eigen::Index>(free.size());
    Eigen::VectorXd rhs(nf);
    for (Eigen::Index a = 0; a < nf; ++a) rhs[a] = impulse[free[a]];
    const Eigen::VectorXd dq = freeBlock(M, free).ldlt().solve(rhs);
    Eigen::VectorXd out = Eigen::VectorXd::Zero(impulse.size());
    for (Eigen::Index a = 0; a < nf; ++a) {
        if (std::isfinite(dq[a])) out[free[a]] = dq[a];
    }
    if (G.rows() > 0) out -= constraintCorrection(M, free, G, G * (rates + out));
    return out;
}

bool projectOntoConstraints(const Model& model, State& state, Data& data, const std::vector<int>& free)
{
    if (!hasConstraints(model, state)) return true;
    // positions: Gauss–Newton, each step the mass-weighted least change
    constexpr double tol = 1e-12;
    bool closed = false;
    Eigen::VectorXd phi;
    for (int it = 0; it < 20; ++it) {
        forwardKinematics(model, state, data);
        collectConstraints(model, state, data.constraints);
        constraintResidual(model, data, data.constraints, phi);
        if (phi.lpNorm<Eigen::Infinity>() <= tol) {
            closed = true;
            break;
        }
        const Eigen::MatrixXd G = constraintJacobianAt(model, state, data);
        const Eigen::MatrixXd M = massMatrixAt(model, state, data);
        state.q.head(model.nb) -= constraintCorrection(M, free, G, phi);
    }
    if (!closed) {
        forwardKinematics(model, state, data);
        constraintResidual(model, data, data.constraints, phi);
        closed = phi.lpNorm<Eigen::Infinity>() <= 1e-9;  // close enough to go on
    }
    // velocities: the plastic-impact projection
    const Eigen::MatrixXd G = constraintJacobianAt(model, state, data);
    const Eigen::MatrixXd M = massMatrixAt(model, state, data);
    state.qd -= constraintCorrection(M, free, G, G * state.qd);
    return closed;
}

// ---------------------------------------------------------------- initial assembly

AssemblyResult assembleLoops(const Model& model, Data& data, const std::vector<int>& unknowns,
                             Eigen::VectorXd& theta, const AssemblyOptions& options)
{
    AssemblyResult result;
    const auto n = static_cast<Eigen::Index>(unknowns.size());
    const double scale = options.lengthScale > 0 ? options.lengthScale : 1.0;

    // the cut joints' rows, at rest (welds are not assembled)
    State at;
    at.q = theta;
    at.qd = Eigen::VectorXd::Zero(model.nb);
    collectConstraints(model, at, data.constraints);
    const auto m = static_cast<Eigen::Index>(constraintRowTotal(data.constraints));

    // Φ and G come with their length rows divided by Model::lengthScale: `unscale`
    // gives them back in m, `rowScale` divides them by the assembly's scale instead;
    // prismatic columns are multiplied by the scale
    Eigen::VectorXd unscale = Eigen::VectorXd::Ones(m), rowScale = Eigen::VectorXd::Ones(m);
    {
        Eigen::Index row = 0;
        for (const Constraint& c : data.constraints) {
            for (int r = 0; r < constraintRowCount(c.kind); ++r, ++row) {
                if (!constraintRowIsLength(c.kind, r)) continue;
                unscale[row] = model.lengthScale;
                rowScale[row] = model.lengthScale / scale;
            }
        }
    }
    Eigen::VectorXd colScale = Eigen::VectorXd::Ones(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        if (model.jointType[static_cast<std::size_t>(unknowns[i])] == JointType::Prismatic) colScale[i] = scale;
    }

    Eigen::VectorXd phi;  // as constraintResidual gives it
    auto evaluate = [&](const Eigen::VectorXd& th) {
        at.q = th;
        forwardKinematics(model, at, data);
        constraintResidual(model, data, data.constraints, phi);
        return rowScale.cwiseProduct(phi).squaredNorm();
    };
    auto keep = [&] {
        result.residual = unscale.cwiseProduct(phi);
        result.residualNorm = result.residual.norm();
    };

    double cost = evaluate(theta);
    keep();
    if (result.residualNorm <= options.tolerance || n == 0) {
        result.converged = result.residualNorm <= options.tolerance;
        return result;
    }

    Eigen::MatrixXd js(m, n);
    double mu = -1;
    for (int it = 0; it < options.maxIterations; ++it) {
        result.iterations = it + 1;

        // scaled Jacobian of the unknowns at the current point
        cost = evaluate(theta);
        constraintJacobian(model, data, nullptr);
        for (Eigen::Index i = 0; i < n; ++i) {
            js.col(i) = rowScale.cwiseProduct(data.G.col(unknowns[i])) * colScale[i];
        }
        const Eigen::VectorXd phiS = rowScale.cwiseProduct(phi);
        const Eigen::MatrixXd jtj = js.transpose() * js;
        const Eigen::VectorXd g = js.transpose() * phiS;
        const double maxDiag = std::max(jtj.diagonal().maxCoeff(), 1e-300);
        if (mu < 0) mu = 1e-9 * maxDiag;
        if (g.norm() <= 1e-15 * std::max(1.0, std::sqrt(cost))) break;  // stationary

        // damped step, more damping until the cost decreases
        bool accepted = false;
        for (int tries = 0; tries < 40 && !accepted; ++tries) {
            Eigen::MatrixXd a = jtj;
            a.diagonal().array() += mu;
            const Eigen::VectorXd stepS = -a.ldlt().solve(g);
            Eigen::VectorXd trial = theta;
            for (Eigen::Index i = 0; i < n; ++i) trial[unknowns[i]] += colScale[i] * stepS[i];
            const double trialCost = evaluate(trial);
            if (std::isfinite(trialCost) && trialCost < cost) {
                const double stepNorm = stepS.norm();
                theta = trial;
                cost = trialCost;
                keep();
                mu = std::max(mu / 10, 1e-15 * maxDiag);
                accepted = true;
                if (stepNorm <= 1e-15) it = options.maxIterations;  // no progress left
            } else {
                mu *= 10;
            }
        }
        if (!accepted) break;  // no descent: a (local) least-squares minimum
        if (result.residualNorm <= options.tolerance) break;
    }

    // the kinematics at the returned point
    at.q = theta;
    forwardKinematics(model, at, data);
    result.converged = result.residualNorm <= options.tolerance;
    return result;
}

}  // namespace solver
