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
    s.q = Eigen::Map<const Eigen::VectorXd>(model.theta0.data(), n);
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

}  // namespace solver
