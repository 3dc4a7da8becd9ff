#pragma once
// Random states, drives and applied loads for the dynamics tests.

#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/core/state.h"
#include "solver/kinematics/joint_geometry.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace solver::test {

inline double uniform(std::mt19937& rng, double lo, double hi)
{
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}

inline bool chance(std::mt19937& rng, double p)
{
    return uniform(rng, 0, 1) < p;
}

/// The range random angles of joint i are drawn from: its limits where it has them;
/// else ±π (revolute), ±0.5 m (prismatic); for T 1 also inside θ0's monotonic branch
/// of L(θ), 0.3 rad away from its dead points.
inline void sampleRange(const Model& model, int i, double& lo, double& hi)
{
    constexpr double pi = std::numbers::pi;
    const bool prismatic = model.jointType[i] == JointType::Prismatic;
    lo = std::isfinite(model.lower[i]) ? model.lower[i] : (prismatic ? -0.5 : -pi);
    hi = std::isfinite(model.upper[i]) ? model.upper[i] : (prismatic ? 0.5 : pi);
    if (model.jointType[i] == JointType::Actuator) {
        const ActuatorLengthLaw& law = model.lengthLaw[i];
        const double theta0 = model.theta0[i];
        const double side = wrapAngle(theta0 - law.phi()) >= 0 ? 1.0 : -1.0;
        // the branch (φ, φ + π) or (φ − π, φ), unwrapped to the turn that holds θ0
        const double mid = law.phi() + side * 0.5 * pi;
        const double centre = theta0 - wrapAngle(theta0 - mid);
        const double b0 = centre - 0.5 * pi, b1 = centre + 0.5 * pi;
        lo = std::max(lo, b0 + 0.3);
        hi = std::min(hi, b1 - 0.3);
    }
}

/// A random state: θ within the sample range, θ̇ in ±1 (±0.5 m/s), u in [−1, 1] (0 one
/// time in five), servo integrals; with `statuses`, random limit states (the joint then
/// sits on that limit) and relief valves.
inline State randomState(const Model& model, std::mt19937& rng, bool statuses = true)
{
    State s = makeState(model);
    s.t = uniform(rng, 0, 10);
    for (int i = 0; i < model.nb; ++i) {
        const bool prismatic = model.jointType[i] == JointType::Prismatic;
        double lo = 0, hi = 0;
        sampleRange(model, i, lo, hi);
        s.q[i] = uniform(rng, lo, hi);
        s.qd[i] = uniform(rng, -1, 1) * (prismatic ? 0.5 : 1.0);
        s.u[i] = chance(rng, 0.2) ? 0.0 : uniform(rng, -1, 1);
        s.servoIntegral[i] = uniform(rng, -0.1, 0.1);
        s.limit[i] = LimitState::Free;
        s.relief[i] = ReliefState::Closed;
        if (!statuses) continue;
        const double r = uniform(rng, 0, 1);
        if (r < 0.2 && std::isfinite(model.lower[i])) {
            s.limit[i] = LimitState::AtLower;
            s.q[i] = model.lower[i];
        } else if (r > 0.8 && std::isfinite(model.upper[i])) {
            s.limit[i] = LimitState::AtUpper;
            s.q[i] = model.upper[i];
        }
        // a relief valve opens only at a finite force
        const CompiledDrive& d = model.drive[i];
        if (d.type == DriveType::Hydraulic && chance(rng, 0.5)) {
            const bool extending = chance(rng, 0.5);
            if (extending && std::isfinite(d.fmax)) s.relief[i] = ReliefState::OpenExtending;
            if (!extending && std::isfinite(d.fmin)) s.relief[i] = ReliefState::OpenRetracting;
        }
    }
    return s;
}

/// The model with a random drive on each joint (or none), random parameters.
inline Model withRandomDrives(const Model& model, std::mt19937& rng)
{
    Model m = model;
    const double inf = std::numeric_limits<double>::infinity();
    for (int i = 0; i < m.nb; ++i) {
        CompiledDrive d;
        switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
        case 0: d.type = DriveType::None; break;
        case 1:
            d.type = DriveType::Hydraulic;
            d.vmax = uniform(rng, 0.05, 0.5);
            d.vmin = uniform(rng, 0.05, 0.5);
            d.fmax = chance(rng, 0.2) ? inf : uniform(rng, 10, 1000);
            d.fmin = chance(rng, 0.2) ? inf : uniform(rng, 10, 1000);
            break;
        case 2:
            d.type = DriveType::Motor;
            d.t0 = uniform(rng, 1, 50);
            d.w0 = uniform(rng, 0.3, 3);
            break;
        case 3:
            d.type = DriveType::Pneumatic;
            d.force = uniform(rng, -100, 100);
            break;
        default:
            d.type = DriveType::Servo;
            d.kp = uniform(rng, 0, 500);
            d.ki = uniform(rng, 0, 50);
            d.kd = uniform(rng, 0, 50);
            d.servoFmax = chance(rng, 0.3) ? inf : uniform(rng, 5, 200);
            d.setLow = uniform(rng, -1, 0);
            d.setHigh = uniform(rng, 0.1, 1);
            break;
        }
        m.drive[i] = d;
    }
    return m;
}

/// Random applied loads: moments in ±5 N m, forces in ±50 N, generalized forces in ±10.
inline void randomAppliedForces(std::mt19937& rng, Data& data)
{
    for (Vector6d& f : data.fext) {
        for (int k = 0; k < 6; ++k) f[k] = k < 3 ? uniform(rng, -5, 5) : uniform(rng, -50, 50);
    }
    for (Eigen::Index i = 0; i < data.tauExt.size(); ++i) data.tauExt[i] = uniform(rng, -10, 10);
}

}  // namespace solver::test
