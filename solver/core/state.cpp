#include "solver/core/state.h"

#include <algorithm>
#include <cmath>

namespace solver {

namespace {

// a start within this distance of a limit is on it [rad or m, relative above 1]
bool onLimit(double theta, double limit)
{
    return std::isfinite(limit) && std::abs(theta - limit) <= 1e-9 * std::max(1.0, std::abs(limit));
}

}  // namespace

State makeState(const Model& model)
{
    const auto n = static_cast<Eigen::Index>(model.nb);
    State s;
    s.t = 0;
    s.q = Eigen::Map<const Eigen::VectorXd>(model.theta0.data(), static_cast<Eigen::Index>(model.theta0.size()));
    s.qd = Eigen::Map<const Eigen::VectorXd>(model.thetaDot0.data(), n);
    s.u = Eigen::VectorXd::Zero(n);
    s.servoIntegral = Eigen::VectorXd::Zero(n);
    s.limit.assign(model.nb, LimitState::Free);
    s.relief.assign(model.nb, ReliefState::Closed);
    s.fluid = Eigen::VectorXd::Zero(kFluidStates * static_cast<Eigen::Index>(model.circuits.size()));
    for (std::size_t c = 0; c < model.circuits.size(); ++c) {
        const CompiledCircuit& k = model.circuits[c];
        if (!k.hasP0) continue;
        s.fluid[kFluidStates * static_cast<Eigen::Index>(c) + 1] = k.p0A;
        s.fluid[kFluidStates * static_cast<Eigen::Index>(c) + 2] = k.p0B;
    }

    if (model.contact) s.contacts.reserve(kMaxContacts);

    // a joint that starts on a limit, and does not start moving away from it, rests on it
    for (int i = 0; i < model.nb; ++i) {
        if (onLimit(s.q[i], model.lower[i]) && s.qd[i] <= 0) {
            s.limit[i] = LimitState::AtLower;
        } else if (onLimit(s.q[i], model.upper[i]) && s.qd[i] >= 0) {
            s.limit[i] = LimitState::AtUpper;
        }
    }
    return s;
}

bool foldFreeRotations(const Model& model, State& state, double threshold)
{
    using Eigen::AngleAxisd;
    using Eigen::Vector3d;
    bool folded = false;
    for (int first : model.freeJoints) {
        const int r = first + 3;  // the turns: slots 3, 4, 5
        const Vector3d phi(state.q[r], state.q[r + 1], state.q[r + 2]);
        if (threshold > 0 && !(phi.cwiseAbs().maxCoeff() > threshold)) continue;
        const Vector3d rate(state.qd[r], state.qd[r + 1], state.qd[r + 2]);
        const Eigen::Matrix3d rx = AngleAxisd(phi[0], Vector3d::UnitX()).toRotationMatrix();
        const Eigen::Matrix3d rxy = rx * AngleAxisd(phi[1], Vector3d::UnitY()).toRotationMatrix();
        const Eigen::Matrix3d turn = rxy * AngleAxisd(phi[2], Vector3d::UnitZ()).toRotationMatrix();
        // the angular velocity in the base axes, then in the new base's
        const Vector3d omega = Vector3d::UnitX() * rate[0] + rx.col(1) * rate[1] + rxy.col(2) * rate[2];
        const Vector3d newRate = turn.transpose() * omega;
        const Eigen::Index k = model.freeBase[static_cast<std::size_t>(r)];
        const Eigen::Quaterniond base(state.q[k], state.q[k + 1], state.q[k + 2], state.q[k + 3]);
        const Eigen::Quaterniond next = (base.normalized() * Eigen::Quaterniond(turn)).normalized();
        state.q[k] = next.w();
        state.q[k + 1] = next.x();
        state.q[k + 2] = next.y();
        state.q[k + 3] = next.z();
        for (int a = 0; a < 3; ++a) {
            state.q[r + a] = 0.0;
            state.qd[r + a] = newRate[a];
        }
        folded = true;
    }
    return folded;
}

}  // namespace solver
