#include "solver/contact/sampled_contact.h"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/math/bv/OBB.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace solver {

namespace {

/// What the sampling reads of a box, a cylinder or a cone, read once per pair (FCL's
/// getNodeType is a virtual call: once per sample it cost as much as the test; the
/// switch on the kind read here costs nothing beside it).
struct Solid {
    fcl::NODE_TYPE type = fcl::BV_UNKNOWN;
    Eigen::Vector3d half = Eigen::Vector3d::Zero();  ///< half the sides of its box (centred in its frame)
    double radius = 0, lz = 0;                       ///< a cylinder's or a cone's
};

Solid solidOf(const fcl::CollisionGeometryd& g)
{
    Solid s;
    s.type = g.getNodeType();
    switch (s.type) {
    case fcl::GEOM_BOX: s.half = static_cast<const fcl::Boxd&>(g).side / 2; break;
    case fcl::GEOM_CYLINDER: {
        const auto& c = static_cast<const fcl::Cylinderd&>(g);
        s.radius = c.radius;
        s.lz = c.lz;
        s.half = {c.radius, c.radius, c.lz / 2};
        break;
    }
    case fcl::GEOM_CONE: {
        // base at z = −lz/2, apex at +lz/2: centred too
        const auto& c = static_cast<const fcl::Coned&>(g);
        s.radius = c.radius;
        s.lz = c.lz;
        s.half = {c.radius, c.radius, c.lz / 2};
        break;
    }
    default: break;
    }
    return s;
}

/// The depth of q (in the solid's frame) inside a box of half sides h, and the face's
/// outward normal (the solid's frame).
inline void depthInBox(const Eigen::Vector3d& h, const Eigen::Vector3d& q, double& depth, Eigen::Vector3d& n)
{
    const Eigen::Vector3d d = h - q.cwiseAbs();
    Eigen::Index k = 0;
    depth = d.minCoeff(&k);
    n = Eigen::Vector3d::Zero();
    n[k] = q[k] >= 0 ? 1 : -1;
}

inline void depthInCylinder(const Solid& c, const Eigen::Vector3d& q, double& depth, Eigen::Vector3d& n)
{
    const double rho = std::sqrt(q.x() * q.x() + q.y() * q.y());
    const double dr = c.radius - rho, dz = c.lz / 2 - std::abs(q.z());
    if (dr < dz) {
        depth = dr;
        n = rho > 1e-12 ? Eigen::Vector3d(q.x() / rho, q.y() / rho, 0) : Eigen::Vector3d::UnitX();
    } else {
        depth = dz;
        n = Eigen::Vector3d(0, 0, q.z() >= 0 ? 1 : -1);
    }
}

/// base at z = −lz/2, apex at +lz/2; the side's outward normal ∝ (ρ̂, r/lz)
inline void depthInCone(const Solid& c, const Eigen::Vector3d& q, double& depth, Eigen::Vector3d& n)
{
    const double rho = std::sqrt(q.x() * q.x() + q.y() * q.y());
    const double slope = c.radius / c.lz;
    const double scale = std::sqrt(1 + slope * slope);
    const double side = (c.radius * (c.lz / 2 - q.z()) / c.lz - rho) / scale;
    const double base = q.z() + c.lz / 2;
    if (side < base) {
        depth = side;
        const Eigen::Vector3d radial = rho > 1e-12 ? Eigen::Vector3d(q.x() / rho, q.y() / rho, 0) : Eigen::Vector3d::UnitX();
        n = (radial + slope * Eigen::Vector3d::UnitZ()) / scale;
    } else {
        depth = base;
        n = -Eigen::Vector3d::UnitZ();
    }
}

/// depthInside with p given in g's frame (q = X⁻¹·p); `n` in g's frame.
bool depthInsideLocal(const Solid& g, const Eigen::Vector3d& q, double& depth, Eigen::Vector3d& n)
{
    switch (g.type) {
    case fcl::GEOM_BOX: depthInBox(g.half, q, depth, n); return true;
    case fcl::GEOM_CYLINDER: depthInCylinder(g, q, depth, n); return true;
    case fcl::GEOM_CONE: depthInCone(g, q, depth, n); return true;
    default: return false;
    }
}

/// Whether the ball (centre c, radius r; world) misses the box of half sides `half` at
/// pose X: every point of it is farther from the box than r.
bool ballMissesBox(const Eigen::Vector3d& c, double r, const Eigen::Isometry3d& X, const Eigen::Vector3d& half)
{
    const Eigen::Vector3d q = X.linear().transpose() * (c - X.translation());
    return (q.cwiseAbs() - half).cwiseMax(0.0).squaredNorm() > r * r;
}

bool isRound(const Solid& g) { return g.type == fcl::GEOM_CYLINDER || g.type == fcl::GEOM_CONE; }

bool isKnown(const Solid& g) { return isRound(g) || g.type == fcl::GEOM_BOX; }

/// A unit vector normal to `a` (unit).
Eigen::Vector3d anyNormal(const Eigen::Vector3d& a)
{
    const Eigen::Vector3d t = std::abs(a.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return a.cross(t).normalized();
}

/// The directions in which the other solid's faces look (world, unit, up to 4): a box's
/// three axes, a cylinder's or a cone's axis and the direction from its axis toward
/// `towards`. Both senses of each are used.
int faceDirections(const Solid& g, const Eigen::Isometry3d& X, const Eigen::Vector3d& towards,
                   std::array<Eigen::Vector3d, 4>& dirs)
{
    if (g.type == fcl::GEOM_BOX) {
        for (int i = 0; i < 3; ++i) dirs[static_cast<std::size_t>(i)] = X.linear().col(i);
        return 3;
    }
    const Eigen::Vector3d axis = X.linear().col(2);
    dirs[0] = axis;
    Eigen::Vector3d radial = towards - X.translation();
    radial -= radial.dot(axis) * axis;
    dirs[1] = radial.norm() > 1e-12 ? Eigen::Vector3d(radial.normalized()) : anyNormal(axis);
    return 2;
}

/// Calls f(p) for each surface sample of `g` at pose X (world points): a box's corners
/// and three points on each edge; a cylinder's two rims (kRimSamples each) and cap
/// centres, a cone's base rim, base centre and apex; and each rim's farthest point in
/// both senses of every direction in `dirs` (the other solid's faces: a drum rolling on
/// the floor touches it at its lowest point, not at the nearest sample). A rim for which
/// `skipRim(centre, radius)` holds is left out whole (none of its points can count).
template <class F, class SkipRim>
void forEachSample(const Solid& g, const Eigen::Isometry3d& X, const std::array<Eigen::Vector3d, 4>& dirs, int nDirs,
                   F&& f, SkipRim&& skipRim)
{
    if (g.type == fcl::GEOM_BOX) {
        const Eigen::Vector3d& h = g.half;
        for (int c = 0; c < 8; ++c) {
            const Eigen::Vector3d corner((c & 1) ? h.x() : -h.x(), (c & 2) ? h.y() : -h.y(), (c & 4) ? h.z() : -h.z());
            f(Eigen::Vector3d(X * corner));
            // the three edges leaving this corner toward + (each edge once)
            for (int axis = 0; axis < 3; ++axis) {
                if (corner[axis] > 0) continue;
                for (int k = 1; k <= 3; ++k) {
                    Eigen::Vector3d q = corner;
                    q[axis] = -h[axis] + 2 * h[axis] * k / 4.0;
                    f(Eigen::Vector3d(X * q));
                }
            }
        }
        return;
    }
    const bool cone = g.type == fcl::GEOM_CONE;
    const double r = g.radius;
    const double lz = g.lz;
    const Eigen::Vector3d axis = X.linear().col(2);
    const Eigen::Vector3d u = X.linear().col(0), v = X.linear().col(1);
    // the rim's directions, computed once
    static const std::array<std::array<double, 2>, kRimSamples> around = [] {
        std::array<std::array<double, 2>, kRimSamples> cs{};
        for (int k = 0; k < kRimSamples; ++k) {
            const double phi = 2 * std::numbers::pi * k / kRimSamples;
            cs[static_cast<std::size_t>(k)] = {std::cos(phi), std::sin(phi)};
        }
        return cs;
    }();
    auto rim = [&](double z) {
        const Eigen::Vector3d c = X * Eigen::Vector3d(0, 0, z);
        if (skipRim(c, r)) return;
        f(c);
        for (const auto& [cs, sn] : around) f(Eigen::Vector3d(c + r * (cs * u + sn * v)));
        for (int i = 0; i < nDirs; ++i) {
            Eigen::Vector3d d = dirs[static_cast<std::size_t>(i)];
            d -= d.dot(axis) * axis;
            const double n = d.norm();
            if (n < 1e-9) continue;  // looking along the axis: the rim's samples are all alike
            f(Eigen::Vector3d(c + r * d / n));
            f(Eigen::Vector3d(c - r * d / n));
        }
    };
    rim(-lz / 2);
    if (cone) {
        f(Eigen::Vector3d(X * Eigen::Vector3d(0, 0, lz / 2)));
    } else {
        rim(lz / 2);
    }
}

struct Candidate {
    Eigen::Vector3d point, normal;  // the contact point (midway), the normal from a to b
    double depth = 0;
};

constexpr std::size_t kMaxCandidates = 160;

/// Adds to `cand` the samples of `s` (pose Xs) that lie inside `o` (pose Xo); `sIsB`:
/// s is b (its normal from a to b is then o's outward normal, else its opposite).
void samplesInside(const Solid& s, const Eigen::Isometry3d& Xs, const Solid& o, const Eigen::Isometry3d& Xo, bool sIsB,
                   std::array<Candidate, kMaxCandidates>& cand, std::size_t& n)
{
    std::array<Eigen::Vector3d, 4> dirs;
    const int nDirs = faceDirections(o, Xo, Xs.translation(), dirs);
    const Eigen::Isometry3d inverse = Xo.inverse(Eigen::Isometry);
    forEachSample(
        s, Xs, dirs, nDirs,
        [&](const Eigen::Vector3d& p) {
            if (n >= kMaxCandidates) return;
            double depth = 0;
            Eigen::Vector3d local;
            if (!depthInsideLocal(o, Eigen::Vector3d(inverse * p), depth, local) || depth <= kLeastDepth) return;
            const Eigen::Vector3d outward = Xo.linear() * local;
            // p is on s's surface, o's nearest face is depth away along `outward`
            cand[n++] = {p + 0.5 * depth * outward, sIsB ? Eigen::Vector3d(outward) : Eigen::Vector3d(-outward), depth};
        },
        [&](const Eigen::Vector3d& c, double r) { return ballMissesBox(c, r, Xo, o.half); });
}

}  // namespace

bool depthInside(const fcl::CollisionGeometryd& g, const Eigen::Isometry3d& X, const Eigen::Vector3d& p, double& depth,
                 Eigen::Vector3d& normal)
{
    Eigen::Vector3d n;
    if (!depthInsideLocal(solidOf(g), X.inverse(Eigen::Isometry) * p, depth, n)) return false;
    normal = X.linear() * n;
    return true;
}

bool sampledContactPoints(const fcl::CollisionGeometryd& ga, const Eigen::Isometry3d& Xa,
                          const fcl::CollisionGeometryd& gb, const Eigen::Isometry3d& Xb, int maxPoints,
                          std::vector<fcl::ContactPoint<double>>& out)
{
    const Solid a = solidOf(ga), b = solidOf(gb);
    if (!(isKnown(a) && isKnown(b) && (isRound(a) || isRound(b)))) return false;
    out.clear();
    // the boxes round the two solids (oriented with them) apart: no sample can be inside
    // (most pairs whose axis-aligned boxes meet: a long round bar has a fat one). First
    // each one's ball against the other's box (a claw's ball is small beside a bar), then
    // the two boxes
    if (ballMissesBox(Xa.translation(), a.half.norm(), Xb, b.half) ||
        ballMissesBox(Xb.translation(), b.half.norm(), Xa, a.half) ||
        fcl::obbDisjoint<double>(Eigen::Matrix3d(Xa.linear().transpose() * Xb.linear()),
                                 Eigen::Vector3d(Xa.linear().transpose() * (Xb.translation() - Xa.translation())),
                                 a.half, b.half))
        return true;
    std::array<Candidate, kMaxCandidates> cand;
    std::size_t n = 0;
    samplesInside(a, Xa, b, Xb, false, cand, n);
    samplesInside(b, Xb, a, Xa, true, cand, n);
    if (n == 0) return true;
    // the first in the samples' fixed order, then each time the one farthest from those
    // kept (a support spread over the contact, not bunched at one end of it). Not the
    // deepest first: on a flat face every sample is as deep as the next, and a choice
    // that followed the smallest tilt would change the points, and the force, each step
    std::array<bool, kMaxCandidates> taken{};
    const std::size_t first = 0;
    std::array<std::size_t, kMaxCandidates> kept{};
    std::size_t nk = 0;
    kept[nk++] = first;
    taken[first] = true;
    while (nk < static_cast<std::size_t>(maxPoints)) {
        std::size_t best = n;
        double bestGap = 1e-6;  // a sample at a point already kept adds nothing
        for (std::size_t i = 0; i < n; ++i) {
            if (taken[i]) continue;
            double gap = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < nk; ++k) gap = std::min(gap, (cand[i].point - cand[kept[k]].point).norm());
            if (gap > bestGap) {
                bestGap = gap;
                best = i;
            }
        }
        if (best == n) break;
        kept[nk++] = best;
        taken[best] = true;
    }
    for (std::size_t k = 0; k < nk; ++k) {
        const Candidate& c = cand[kept[k]];
        out.emplace_back(c.normal, c.point, c.depth);
    }
    return true;
}

}  // namespace solver
