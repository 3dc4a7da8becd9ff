#include "solver/kinematics/inverse.h"

#include "solver/kinematics/joint_geometry.h"
#include "solver/kinematics/kinematics.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace solver {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// a T 1 joint's angles stay this far inside the dead points of its branch [rad]
constexpr double kDeadPointMargin = 1e-6;

struct Problem {
    const Model& model;
    const IkFrame& frame;
    const IkTarget& target;
    std::vector<int> joints;           // moving joints (tree indices), parents first
    std::vector<double> lower, upper;  // their θ ranges
};

// residual e (dim 3 or 6) at the kinematics in data, and the unweighted errors
void residual(const Problem& pb, const Data& data, Eigen::VectorXd& e, double& posErr,
              double& angErr)
{
    const Eigen::Isometry3d X = framePose(data, pb.frame);
    const Eigen::Vector3d dp = pb.target.position - X.translation();
    posErr = dp.norm();
    angErr = 0;
    e.head<3>() = pb.target.positionWeight * dp;
    if (pb.target.orientation) {
        const Eigen::AngleAxisd aa(Eigen::Matrix3d(*pb.target.orientation * X.linear().transpose()));
        angErr = std::abs(aa.angle());
        e.tail<3>() = pb.target.orientationWeight * aa.angle() * aa.axis();
    }
}

// J = −∂e/∂θ: the weighted rates of p_F and of F's attitude per unit θ of each moving
// joint (rows as e, one column per moving joint)
void jacobian(const Problem& pb, const Data& data, Eigen::MatrixXd& J)
{
    const Eigen::Vector3d p = framePose(data, pb.frame).translation();
    for (std::size_t k = 0; k < pb.joints.size(); ++k) {
        const Vector6d& s = data.S[pb.joints[k]];
        const Eigen::Index c = static_cast<Eigen::Index>(k);
        J.col(c).head<3>() = pb.target.positionWeight * (s.tail<3>() + s.head<3>().cross(p));
        if (pb.target.orientation) J.col(c).tail<3>() = pb.target.orientationWeight * s.head<3>();
    }
}

double clampTo(double v, double lo, double hi)
{
    return std::min(std::max(v, lo), hi);
}

bool withinTolerance(const IkTarget& t, double posErr, double angErr)
{
    return (t.positionWeight <= 0 || posErr <= t.positionTolerance) &&
           (!t.orientation || t.orientationWeight <= 0 || angErr <= t.angleTolerance);
}

// one LM attempt from theta (in/out); returns the weighted cost ½|e|² at the end
double attempt(const Problem& pb, Eigen::VectorXd& theta, Data& data, const IkOptions& opt,
               IkResult& res, double& posErr, double& angErr)
{
    const Model& model = pb.model;
    const Eigen::Index n = static_cast<Eigen::Index>(pb.joints.size());
    const Eigen::Index m = pb.target.orientation ? 6 : 3;
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.nb);
    Eigen::VectorXd e(m), eTrial(m), g(n), step(n);
    Eigen::MatrixXd J(m, n), H(n, n);
    Eigen::VectorXd trial = theta;

    forwardKinematics(model, theta, zero, data);
    residual(pb, data, e, posErr, angErr);
    double cost = 0.5 * e.squaredNorm();
    double lambda = opt.initialDamping;
    int stalls = 0;

    for (int it = 0; it < opt.maxIterations; ++it) {
        if (withinTolerance(pb.target, posErr, angErr)) break;
        ++res.iterations;
        jacobian(pb, data, J);
        g.noalias() = J.transpose() * e;  // −∇cost: the descent direction

        // active set: a joint on a limit that the descent direction pushes further out
        std::vector<char> active(n, 1);
        for (Eigen::Index k = 0; k < n; ++k) {
            const int i = pb.joints[k];
            const double lo = pb.lower[k], hi = pb.upper[k];
            const double span = std::isfinite(hi - lo) ? hi - lo : 1.0;
            const double tol = 1e-12 * std::max(1.0, span);
            if ((theta[i] <= lo + tol && g[k] < 0) || (theta[i] >= hi - tol && g[k] > 0)) active[k] = 0;
        }

        bool improved = false;
        for (int tries = 0; tries < 30 && !improved; ++tries) {
            H.noalias() = J.transpose() * J;
            for (Eigen::Index k = 0; k < n; ++k) {
                if (!active[k]) {
                    H.row(k).setZero();
                    H.col(k).setZero();
                    H(k, k) = 1;
                    continue;
                }
                H(k, k) += lambda * (H(k, k) + 1e-9);
            }
            Eigen::VectorXd rhs = g;
            for (Eigen::Index k = 0; k < n; ++k)
                if (!active[k]) rhs[k] = 0;
            step = H.ldlt().solve(rhs);
            if (!step.allFinite()) {
                lambda *= 10;
                continue;
            }

            // the trial point, clamped to the ranges
            trial = theta;
            for (Eigen::Index k = 0; k < n; ++k) {
                const int i = pb.joints[k];
                trial[i] = clampTo(theta[i] + step[k], pb.lower[k], pb.upper[k]);
            }
            forwardKinematics(model, trial, zero, data);
            double pTrial = 0, aTrial = 0;
            residual(pb, data, eTrial, pTrial, aTrial);
            const double costTrial = 0.5 * eTrial.squaredNorm();
            if (costTrial < cost) {
                theta = trial;
                e = eTrial;
                posErr = pTrial;
                angErr = aTrial;
                const double gain = cost - costTrial;
                cost = costTrial;
                lambda = std::max(lambda / 3, 1e-12);
                improved = true;
                // stalled at a minimum that misses the target (unreachable): stop
                stalls = gain <= 1e-12 * cost ? stalls + 1 : 0;
                if (stalls >= 5) {
                    forwardKinematics(model, theta, zero, data);
                    return cost;
                }
            } else {
                lambda *= 4;
            }
        }
        if (!improved) {
            // no step lowers the cost any more: a (constrained) minimum
            forwardKinematics(model, theta, zero, data);
            break;
        }
    }
    forwardKinematics(model, theta, zero, data);
    return cost;
}

}  // namespace

Eigen::Isometry3d framePose(const Data& data, const IkFrame& frame)
{
    assert(frame.body >= 0 && frame.body < static_cast<int>(data.X_wb.size()));
    return data.X_wb[frame.body] * frame.X_bf;
}

void ikJointRange(const Model& model, int i, bool limits, double& lower, double& upper)
{
    lower = limits ? model.lower[i] : -kInf;
    upper = limits ? model.upper[i] : kInf;
    if (model.jointType[i] == JointType::Actuator) {
        // the branch (φ, φ + π) or (φ − π, φ) of L(θ) that holds θ0, unwrapped to its turn
        constexpr double pi = std::numbers::pi;
        const ActuatorLengthLaw& law = model.lengthLaw[i];
        const double theta0 = model.theta0[i];
        const double side = wrapAngle(theta0 - law.phi()) >= 0 ? 1.0 : -1.0;
        const double mid = law.phi() + side * 0.5 * pi;
        const double centre = theta0 - wrapAngle(theta0 - mid);
        lower = std::max(lower, centre - 0.5 * pi + kDeadPointMargin);
        upper = std::min(upper, centre + 0.5 * pi - kDeadPointMargin);
    }
}

IkResult inverseKinematics(const Model& model, const IkFrame& frame, const IkTarget& target,
                           const Eigen::VectorXd& start, Data& data, const IkOptions& options)
{
    assert(start.size() == model.nb || start.size() == model.nq);
    assert(frame.body >= 0 && frame.body < model.nb);

    // the moving joints: those asked for (or all) that lie on the body's path from ground
    std::vector<char> onPath(model.nb, 0);
    for (int b = frame.body; b >= 0; b = model.parent[b]) onPath[b] = 1;
    Problem pb{model, frame, target, {}, {}, {}};
    for (int i = 0; i < model.nb; ++i) {
        const bool asked = options.joints.empty() ||
                           std::find(options.joints.begin(), options.joints.end(), i) != options.joints.end();
        if (!asked || !onPath[i] || model.freeSlot[i] >= 0) continue;  // (a free body is not steered)
        double lo = 0, hi = 0;
        ikJointRange(model, i, options.limits, lo, hi);
        pb.joints.push_back(i);
        pb.lower.push_back(lo);
        pb.upper.push_back(hi);
    }

    IkResult best;
    best.theta = start;
    double bestCost = kInf;
    std::mt19937 rng(options.seed);
    constexpr double pi = std::numbers::pi;

    for (int a = 0; a <= options.restarts; ++a) {
        Eigen::VectorXd theta = start;
        for (std::size_t k = 0; k < pb.joints.size(); ++k) {
            const int i = pb.joints[k];
            const double lo = pb.lower[k], hi = pb.upper[k];
            if (a == 0) {
                theta[i] = clampTo(start[i], lo, hi);
                continue;
            }
            const bool prismatic = model.jointType[i] == JointType::Prismatic;
            const double reach = prismatic ? 1.0 : pi;
            const double l = std::isfinite(lo) ? lo : start[i] - reach;
            const double h = std::isfinite(hi) ? hi : start[i] + reach;
            theta[i] = std::uniform_real_distribution<double>(l, h)(rng);
        }
        IkResult res;
        double posErr = 0, angErr = 0;
        const double cost = attempt(pb, theta, data, options, res, posErr, angErr);
        best.iterations += res.iterations;
        best.attempts = a + 1;
        if (cost < bestCost) {
            bestCost = cost;
            best.theta = theta;
            best.positionError = posErr;
            best.angleError = angErr;
            best.converged = withinTolerance(target, posErr, angErr);
        }
        if (best.converged) break;
    }

    // unlimited revolute angles: within π of the start
    for (int i : pb.joints) {
        if (model.jointType[i] == JointType::Revolute && !std::isfinite(model.lower[i]) &&
            !std::isfinite(model.upper[i]))
            best.theta[i] = start[i] + wrapAngle(best.theta[i] - start[i]);
    }
    best.coordinates.resize(model.nb);
    for (int i = 0; i < model.nb; ++i) best.coordinates[i] = model.coordinate(i, best.theta[i]);
    forwardKinematics(model, best.theta, Eigen::VectorXd::Zero(model.nb), data);
    return best;
}

}  // namespace solver
