#include "trainer/training/reach.h"

#include "solver/core/data.h"
#include "solver/core/state.h"
#include "solver/kinematics/inverse.h"
#include "solver/kinematics/kinematics.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace trainer {

namespace {

/// The attitudes that satisfy the alignments: none (position only), the family of
/// rotations about the world direction of a single alignment (sampled), or the one
/// that two alignments fix.
std::vector<Eigen::Matrix3d> candidateAttitudes(const std::vector<Alignment>& align)
{
    std::vector<Eigen::Matrix3d> out;
    if (align.empty()) return out;
    const Alignment& a = align.front();
    const Eigen::Matrix3d r0 = Eigen::Quaterniond::FromTwoVectors(a.local, a.world).toRotationMatrix();
    constexpr int kSamples = 16;
    for (int k = 0; k < kSamples; ++k) {
        const double phi = 2 * std::numbers::pi * k / kSamples;
        const Eigen::Matrix3d r = Eigen::AngleAxisd(phi, a.world).toRotationMatrix() * r0;
        bool ok = true;
        for (std::size_t i = 1; i < align.size(); ++i) {
            const Eigen::Vector3d w = r * align[i].local;
            ok = ok && std::atan2(w.cross(align[i].world).norm(), w.dot(align[i].world)) <= align[i].tolerance;
        }
        if (ok || align.size() == 1) out.push_back(r);
    }
    if (out.empty()) {
        // two alignments that no sample meets within tolerance: the exact fit of both
        Eigen::Matrix3d local, world;
        local << align[0].local, align[1].local, align[0].local.cross(align[1].local);
        world << align[0].world, align[1].world, align[0].world.cross(align[1].world);
        Eigen::JacobiSVD<Eigen::Matrix3d> svd(world * local.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
        Eigen::Matrix3d r = svd.matrixU() * svd.matrixV().transpose();
        if (r.determinant() < 0) {
            Eigen::Matrix3d u = svd.matrixU();
            u.col(2) *= -1;
            r = u * svd.matrixV().transpose();
        }
        out.push_back(r);
    }
    return out;
}

}  // namespace

ReachCheck checkReach(const solver::Model& model, const std::vector<char>& enabled,
                      const std::vector<std::pair<int, double>>& initial, int body, const Eigen::Vector3d& point,
                      const Eigen::Vector3d& target, double tolerance, const std::vector<Alignment>& align)
{
    ReachCheck best;
    best.positionError = std::numeric_limits<double>::infinity();
    best.angleError = std::numeric_limits<double>::infinity();
    if (body < 0) return best;
    solver::State state = solver::makeState(model);
    for (const auto& [j, theta] : initial) state.q[j] = theta;
    solver::Data data(model);
    solver::IkFrame frame;
    frame.body = body;
    frame.X_bf.translation() = point;
    solver::IkOptions options;
    for (int j = 0; j < model.nb; ++j) {
        if (enabled[std::size_t(j)] && model.drive[std::size_t(j)].type != solver::DriveType::None) options.joints.push_back(j);
    }
    if (options.joints.empty()) return best;
    solver::IkTarget t;
    t.position = target;
    t.positionTolerance = 0.5 * tolerance;
    double angleTolerance = std::numbers::pi;
    for (const Alignment& a : align) angleTolerance = std::min(angleTolerance, a.tolerance);
    t.angleTolerance = 0.5 * angleTolerance;
    // first the position alone (its pose may already meet the alignments), then each
    // attitude that meets them
    const std::vector<Eigen::Matrix3d> attitudes = candidateAttitudes(align);
    for (std::size_t k = 0; k <= attitudes.size(); ++k) {
        if (k == 0) t.orientation.reset();
        else t.orientation = attitudes[k - 1];
        // the frame's attitude is the body's: the alignments are in the body's frame
        const solver::IkResult r = solver::inverseKinematics(model, frame, t, state.q, data, options);
        // alignments measured on the result (a one-alignment goal leaves a free turn)
        double excess = 0.0;
        solver::forwardKinematics(model, r.theta, Eigen::VectorXd::Zero(model.nb), data);
        for (const Alignment& a : align) {
            const Eigen::Vector3d w = data.X_wb[std::size_t(body)].linear() * a.local;
            excess = std::max(excess, std::atan2(w.cross(a.world).norm(), w.dot(a.world)) - a.tolerance);
        }
        const bool reachable = r.positionError <= tolerance && excess <= 0.0;
        if (reachable || r.positionError + excess < best.positionError + std::max(best.angleError, 0.0)) {
            best.reachable = reachable;
            best.positionError = r.positionError;
            best.angleError = std::max(excess, 0.0);
        }
        if (reachable) break;
    }
    return best;
}

}  // namespace trainer
