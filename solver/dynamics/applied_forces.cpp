#include "solver/dynamics/applied_forces.h"

#include "solver/contact/contact_forces.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace solver {

namespace {

using Eigen::Vector3d;

/// Linear interpolation of the table (x increasing) at s, held at the ends.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double s)
{
    const std::size_t n = std::min(x.size(), y.size());
    if (n == 0) return 0.0;
    // first abscissa above s: s lies in [x[k-1], x[k])
    const auto it = std::upper_bound(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n), s);
    const auto k = static_cast<std::size_t>(it - x.begin());
    if (k == 0) return y.front();
    if (k == n) return y[n - 1];
    const double w = (s - x[k - 1]) / (x[k] - x[k - 1]);
    return y[k - 1] + w * (y[k] - y[k - 1]);
}

bool isBody(const Model& model, int b) { return b >= 0 && b < model.nb; }

/// World position of a body-local point (the ground's points are world points).
Vector3d worldPoint(const Data& data, int body, const Vector3d& local)
{
    return body < 0 ? local : Vector3d(data.X_wb[body] * local);
}

/// World velocity of the body point at world position p (zero on the ground).
Vector3d pointVelocity(const Data& data, int body, const Vector3d& p)
{
    if (body < 0) return Vector3d::Zero();
    return data.vel[body] + data.omega[body].cross(p - data.X_wb[body].translation());
}

/// Adds force F at world point p to body `body`'s load (moment about its origin).
void addForceAt(Data& data, int body, const Vector3d& p, const Vector3d& f)
{
    if (body < 0) return;
    Vector6d& w = data.fext[body];
    w.head<3>() += (p - data.X_wb[body].translation()).cross(f);
    w.tail<3>() += f;
}

/// The force's direction in world axes.
Vector3d worldDirection(const Data& data, const CompiledForce& f)
{
    if (f.local && f.body >= 0) return data.X_wb[f.body].linear() * f.dir;
    return f.dir;
}

/// Unit "up" of the model: against gravity, world +z without gravity.
Vector3d upDirection(const Model& model)
{
    const double g = model.gravity.norm();
    return g > 0 ? Vector3d(-model.gravity / g) : Vector3d::UnitZ();
}

/// Adds the push (header: "The push") to data.fext.
void applyPush(const Model& model, const Push& push, Data& data)
{
    const int b = push.body;
    if (!isBody(model, b)) return;
    const double m = subtreeMass(model, b);
    if (!(m > 0.0)) return;
    const Vector3d p = worldPoint(data, b, push.point);
    const double k = kPushFrequency * kPushFrequency * m;
    const double c = 2.0 * kPushFrequency * m;
    Vector3d force = k * (push.target - p) - c * pointVelocity(data, b, p);
    const double cap = kPushMaxAcceleration * m;
    const double size = force.norm();
    if (size > cap) force *= cap / size;
    if (!force.allFinite()) return;
    addForceAt(data, b, p, force);
    const Eigen::Matrix3d& R = data.X_wb[b].linear();
    data.fext[b].head<3>() -= 2.0 * kPushFrequency * (R * (model.inertia[b] * (R.transpose() * data.omega[b])));
}

}  // namespace

double subtreeMass(const Model& model, int body)
{
    if (!isBody(model, body)) return 0.0;
    double m = 0.0;
    // parent[k] < k: the bodies outboard of `body` have larger indices
    for (int k = body; k < model.nb; ++k) {
        int j = k;
        while (j > body) j = model.parent[j];
        if (j == body) m += model.mass[k];
    }
    return m;
}

double evaluateMagnitude(const CompiledMagnitude& mag, double t, const Model& model,
                         const State& state)
{
    using Kind = MagnitudeKind;
    switch (mag.kind) {
    case Kind::Constant:
        return mag.value;
    case Kind::Sine:
        return mag.offset +
               mag.amplitude * std::sin(2.0 * std::numbers::pi * mag.frequency * t + mag.phase);
    case Kind::TableTime:
        return interpolate(mag.x, mag.y, t);
    case Kind::TableJoint:
        if (mag.joint < 0 || mag.joint >= model.nb || mag.joint >= state.q.size()) return 0.0;
        return interpolate(mag.x, mag.y, model.coordinate(mag.joint, state.q[mag.joint]));
    }
    return 0.0;
}

void applyForces(const Model& model, const State& state, Data& data)
{
    assert(static_cast<int>(data.fext.size()) == model.nb);
    assert(data.tauExt.size() == model.nb);
    assert(state.q.size() == model.nb || state.q.size() == model.nq);
    for (Vector6d& w : data.fext) w.setZero();
    data.tauExt.setZero();

    for (const CompiledForce& f : model.forces) {
        switch (f.kind) {
        case ForceKind::Point: {
            if (!isBody(model, f.body)) break;
            const double m = evaluateMagnitude(f.mag, state.t, model, state);
            addForceAt(data, f.body, worldPoint(data, f.body, f.point),
                       m * worldDirection(data, f));
            break;
        }
        case ForceKind::Torque: {
            if (!isBody(model, f.body)) break;
            const double m = evaluateMagnitude(f.mag, state.t, model, state);
            data.fext[f.body].head<3>() += m * worldDirection(data, f);
            break;
        }
        case ForceKind::Joint: {
            if (f.joint < 0 || f.joint >= model.nb) break;
            const double m = evaluateMagnitude(f.mag, state.t, model, state);
            data.tauExt[f.joint] += m * model.coordinateRate(f.joint, state.q[f.joint]);
            break;
        }
        case ForceKind::Spring: {
            const int b1 = f.body, b2 = f.body2;
            if (!(b1 == -1 || isBody(model, b1)) || !(b2 == -1 || isBody(model, b2))) break;
            if (b1 < 0 && b2 < 0) break;
            const Vector3d p1 = worldPoint(data, b1, f.point);
            const Vector3d p2 = worldPoint(data, b2, f.point2);
            const Vector3d d = p2 - p1;
            const double length = d.norm();
            if (!(length > 0.0)) break;  // zero length: no direction, no force
            const Vector3d e = d / length;
            double tension = f.stiffness * (length - f.restLength);
            if (f.damping != 0.0) {
                const double rate =
                    e.dot(pointVelocity(data, b2, p2) - pointVelocity(data, b1, p1));
                tension += f.damping * rate;
            }
            addForceAt(data, b1, p1, tension * e);
            addForceAt(data, b2, p2, -tension * e);
            break;
        }
        case ForceKind::Aero: {
            if (!isBody(model, f.body)) break;
            const Vector3d p = worldPoint(data, f.body, f.point);
            const Vector3d v = pointVelocity(data, f.body, p);
            const double speed = v.norm();
            if (!(speed > 0.0)) break;
            const double q = 0.5 * f.rho * f.area;  // ½·ρ·AREA
            Vector3d force = -q * f.cd * speed * v;  // drag
            if (f.cl != 0.0) {
                const Vector3d vhat = v / speed;
                const Vector3d up = upDirection(model);
                const Vector3d across = up - up.dot(vhat) * vhat;
                const double n = across.norm();
                if (n >= 1e-9) force += (q * f.cl * speed * speed / n) * across;
            }
            addForceAt(data, f.body, p, force);
            break;
        }
        }
    }
    // CONTACT: the solids' contact forces (contact/contact_forces.h)
    if (model.contact) applyContacts(model, state, data);
    applyPush(model, state.push, data);
}

}  // namespace solver
