#include "solver/kinematics/loop_closure.h"

#include "solver/kinematics/positions.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace solver {

namespace {

// world vectors of one cut joint
struct CutFrames {
    Eigen::Vector3d p1, a1, r1, t1;
    Eigen::Vector3d p2, a2, r2, t2;
};

CutFrames cutFrames(const JointGeometry& g, const Eigen::Isometry3d& X_w1,
                    const Eigen::Isometry3d& X_w2)
{
    CutFrames f;
    f.p1 = X_w1 * g.side1.origin;
    f.a1 = X_w1.linear() * g.side1.a();
    f.r1 = X_w1.linear() * g.side1.r();
    f.t1 = X_w1.linear() * g.side1.t();
    f.p2 = X_w2 * g.side2.origin;
    f.a2 = X_w2.linear() * g.side2.a();
    f.r2 = X_w2.linear() * g.side2.r();
    f.t2 = X_w2.linear() * g.side2.t();
    return f;
}

}  // namespace

bool closureRowIsLength(JointType type, int row)
{
    if (type == JointType::Prismatic) return row >= 3;
    return row < 3;
}

void closureResidual(const Topology& topo, const std::vector<JointGeometry>& geometry,
                     const std::vector<Eigen::Isometry3d>& X_wb, Eigen::VectorXd& phi)
{
    phi.resize(kClosureEquations * static_cast<Eigen::Index>(topo.loopJoints.size()));
    for (std::size_t k = 0; k < topo.loopJoints.size(); ++k) {
        const int c = topo.loopJoints[k];
        const JointGeometry& g = geometry[c];
        const CutFrames f = cutFrames(g, X_wb[topo.side1Body[c]], X_wb[topo.side2Body[c]]);
        auto rows =
            phi.segment<kClosureEquations>(kClosureEquations * static_cast<Eigen::Index>(k));
        if (g.type == JointType::Prismatic) {
            const Eigen::Vector3d d = f.p2 - f.p1;
            rows << f.a1.dot(f.r2), f.a1.dot(f.t2), f.r1.dot(f.t2), d.dot(f.a1), d.dot(f.t1);
        } else {
            rows << f.p2 - f.p1, f.a1.dot(f.r2), f.a1.dot(f.t2);
        }
    }
}

void closureJacobian(const Topology& topo, const std::vector<JointGeometry>& geometry,
                     const std::vector<Eigen::Isometry3d>& X_wb, Eigen::MatrixXd& jac)
{
    const auto nc = static_cast<Eigen::Index>(topo.loopJoints.size());
    const auto nt = static_cast<Eigen::Index>(topo.treeJoints.size());
    jac.setZero(kClosureEquations * nc, nt);

    for (Eigen::Index col = 0; col < nt; ++col) {
        const int j = topo.treeJoints[col];
        const Vector6d s = jointMotionWorld(topo, geometry, X_wb, j);
        const Eigen::Vector3d w = s.head<3>();
        const Eigen::Vector3d v = s.tail<3>();

        for (Eigen::Index k = 0; k < nc; ++k) {
            const int c = topo.loopJoints[k];
            const bool moves1 = jointMovesBody(topo, j, topo.side1Body[c]);
            const bool moves2 = jointMovesBody(topo, j, topo.side2Body[c]);
            if (!moves1 && !moves2) continue;
            const JointGeometry& g = geometry[c];
            const CutFrames f = cutFrames(g, X_wb[topo.side1Body[c]], X_wb[topo.side2Body[c]]);

            // rates of the cut joint's points and directions per unit θ̇_j
            const Eigen::Vector3d z = Eigen::Vector3d::Zero();
            const Eigen::Vector3d dp1 = moves1 ? Eigen::Vector3d(w.cross(f.p1) + v) : z;
            const Eigen::Vector3d dp2 = moves2 ? Eigen::Vector3d(w.cross(f.p2) + v) : z;
            const Eigen::Vector3d da1 = moves1 ? Eigen::Vector3d(w.cross(f.a1)) : z;
            const Eigen::Vector3d dr1 = moves1 ? Eigen::Vector3d(w.cross(f.r1)) : z;
            const Eigen::Vector3d dt1 = moves1 ? Eigen::Vector3d(w.cross(f.t1)) : z;
            const Eigen::Vector3d dr2 = moves2 ? Eigen::Vector3d(w.cross(f.r2)) : z;
            const Eigen::Vector3d dt2 = moves2 ? Eigen::Vector3d(w.cross(f.t2)) : z;

            auto rows = jac.block<kClosureEquations, 1>(kClosureEquations * k, col);
            if (g.type == JointType::Prismatic) {
                const Eigen::Vector3d d = f.p2 - f.p1;
                const Eigen::Vector3d dd = dp2 - dp1;
                rows << da1.dot(f.r2) + f.a1.dot(dr2), da1.dot(f.t2) + f.a1.dot(dt2),
                    dr1.dot(f.t2) + f.r1.dot(dt2), dd.dot(f.a1) + d.dot(da1),
                    dd.dot(f.t1) + d.dot(dt1);
            } else {
                rows << dp2 - dp1, da1.dot(f.r2) + f.a1.dot(dr2), da1.dot(f.t2) + f.a1.dot(dt2);
            }
        }
    }
}

ClosureSolveResult solveClosure(const Topology& topo, const std::vector<JointGeometry>& geometry,
                                const std::vector<int>& unknowns, Eigen::VectorXd& theta,
                                const ClosureSolveOptions& options)
{
    ClosureSolveResult result;
    const auto nc = static_cast<Eigen::Index>(topo.loopJoints.size());
    const auto m = kClosureEquations * nc;
    const auto n = static_cast<Eigen::Index>(unknowns.size());
    const double scale = options.lengthScale > 0 ? options.lengthScale : 1.0;

    // scaling: length rows divided by the length scale, prismatic columns multiplied
    Eigen::VectorXd rowScale = Eigen::VectorXd::Ones(m);
    for (Eigen::Index k = 0; k < nc; ++k) {
        const JointType type = geometry[topo.loopJoints[k]].type;
        for (int r = 0; r < kClosureEquations; ++r) {
            if (closureRowIsLength(type, r)) rowScale[kClosureEquations * k + r] = 1 / scale;
        }
    }
    Eigen::VectorXd colScale = Eigen::VectorXd::Ones(n);
    std::vector<Eigen::Index> column(unknowns.size());
    for (Eigen::Index i = 0; i < n; ++i) {
        const int j = unknowns[i];
        if (geometry[j].type == JointType::Prismatic) colScale[i] = scale;
        const auto it = std::find(topo.treeJoints.begin(), topo.treeJoints.end(), j);
        assert(it != topo.treeJoints.end());
        column[i] = it - topo.treeJoints.begin();
    }

    std::vector<Eigen::Isometry3d> X_wb;
    Eigen::VectorXd phi;
    auto evaluate = [&](const Eigen::VectorXd& th) {
        bodyPoses(topo, geometry, th, X_wb);
        closureResidual(topo, geometry, X_wb, phi);
        return rowScale.cwiseProduct(phi).squaredNorm();
    };

    double cost = evaluate(theta);
    result.residual = phi;
    result.residualNorm = phi.norm();
    if (result.residualNorm <= options.tolerance || n == 0) {
        result.converged = result.residualNorm <= options.tolerance;
        return result;
    }

    Eigen::MatrixXd full;
    Eigen::MatrixXd js(m, n);
    double mu = -1;
    for (int it = 0; it < options.maxIterations; ++it) {
        result.iterations = it + 1;

        // scaled Jacobian of the unknowns at the current point
        cost = evaluate(theta);
        closureJacobian(topo, geometry, X_wb, full);
        for (Eigen::Index i = 0; i < n; ++i) {
            js.col(i) = rowScale.cwiseProduct(full.col(column[i])) * colScale[i];
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
                result.residual = phi;
                result.residualNorm = phi.norm();
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

    result.converged = result.residualNorm <= options.tolerance;
    return result;
}

}  // namespace solver
