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

/// depthInside with p given in g's frame (q = X⁻¹·p).
bool depthInsideLocal(const fcl::CollisionGeometryd& g, const Eigen::Isometry3d& X, const Eigen::Vector3d& q,
                      double& depth, Eigen::Vector3d& normal)
{
    Eigen::Vector3d n;
    switch (g.getNodeType()) {
    case fcl::GEOM_BOX: {
        const Eigen::Vector3d h = static_cast<const fcl::Boxd&>(g).side / 2;
        const Eigen::Vector3d d = h - q.cwiseAbs();
        Eigen::Index k = 0;
        depth = d.minCoeff(&k);
        n = Eigen::Vector3d::Zero();
        n[k] = q[k] >= 0 ? 1 : -1;
        break;
    }
    case fcl::GEOM_CYLINDER: {
        const auto& c = static_cast<const fcl::Cylinderd&>(g);
        const double rho = std::sqrt(q.x() * q.x() + q.y() * q.y());
        const double dr = c.radius - rho, dz = c.lz / 2 - std::abs(q.z());
        if (dr < dz) {
            depth = dr;
            n = rho > 1e-12 ? Eigen::Vector3d(q.x() / rho, q.y() / rho, 0) : Eigen::Vector3d::UnitX();
        } else {
            depth = dz;
            n = Eigen::Vector3d(0, 0, q.z() >= 0 ? 1 : -1);
        }
        break;
    }
    case fcl::GEOM_CONE: {
        // base at z = −lz/2, apex at +lz/2; the side's outward normal ∝ (ρ̂, r/lz)
        const auto& c = static_cast<const fcl::Coned&>(g);
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
        break;
    }
    default: return false;
    }
    normal = X.linear() * n;
    return true;
}

/// Half the sides of the box round a box, a cylinder or a cone in its own frame (a
/// cone's base at z = −lz/2, apex at +lz/2: centred too).
Eigen::Vector3d halfBox(const fcl::CollisionGeometryd& g)
{
    switch (g.getNodeType()) {
    case fcl::GEOM_BOX: return static_cast<const fcl::Boxd&>(g).side / 2;
    case fcl::GEOM_CYLINDER: {
        const auto& c = static_cast<const fcl::Cylinderd&>(g);
        return {c.radius, c.radius, c.lz / 2};
    }
    default: {
        const auto& c = static_cast<const fcl::Coned&>(g);
        return {c.radius, c.radius, c.lz / 2};
    }
    }
}

bool isRound(const fcl::CollisionGeometryd& g)
{
    return g.getNodeType() == fcl::GEOM_CYLINDER || g.getNodeType() == fcl::GEOM_CONE;
}

bool isKnown(const fcl::CollisionGeometryd& g) { return isRound(g) || g.getNodeType() == fcl::GEOM_BOX; }

/// A unit vector normal to `a` (unit).
Eigen::Vector3d anyNormal(const Eigen::Vector3d& a)
{
    const Eigen::Vector3d t = std::abs(a.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return a.cross(t).normalized();
}

/// The directions in which the other solid's faces look (world, unit, up to 4): a box's
/// three axes, a cylinder's or a cone's axis and the direction from its axis toward
/// `towards`. Both senses of each are used.
int faceDirections(const fcl::CollisionGeometryd& g, const Eigen::Isometry3d& X, const Eigen::Vector3d& towards,
                   std::array<Eigen::Vector3d, 4>& dirs)
{
    if (g.getNodeType() == fcl::GEOM_BOX) {
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
/// the floor touches it at its lowest point, not at the nearest sample).
template <class F>
void forEachSample(const fcl::CollisionGeometryd& g, const Eigen::Isometry3d& X, const std::array<Eigen::Vector3d, 4>& dirs,
                   int nDirs, F&& f)
{
    if (g.getNodeType() == fcl::GEOM_BOX) {
        const Eigen::Vector3d h = static_cast<const fcl::Boxd&>(g).side / 2;
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
    const bool cone = g.getNodeType() == fcl::GEOM_CONE;
    const double r = cone ? static_cast<const fcl::Coned&>(g).radius : static_cast<const fcl::Cylinderd&>(g).radius;
    const double lz = cone ? static_cast<const fcl::Coned&>(g).lz : static_cast<const fcl::Cylinderd&>(g).lz;
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

/// Adds to `cand` the samples of `s` (pose Xs) that lie inside `o` (pose Xo); `flip`:
/// s is b (its normal from a to b is then o's outward normal, else its opposite).
void samplesInside(const fcl::CollisionGeometryd& s, const Eigen::Isometry3d& Xs, const fcl::CollisionGeometryd& o,
                   const Eigen::Isometry3d& Xo, bool sIsB, std::array<Candidate, kMaxCandidates>& cand, std::size_t& n)
{
    std::array<Eigen::Vector3d, 4> dirs;
    const int nDirs = faceDirections(o, Xo, Xs.translation(), dirs);
    const Eigen::Isometry3d inverse = Xo.inverse(Eigen::Isometry);
    forEachSample(s, Xs, dirs, nDirs, [&](const Eigen::Vector3d& p) {
        double depth = 0;
        Eigen::Vector3d outward;
        if (n >= kMaxCandidates || !depthInsideLocal(o, Xo, inverse * p, depth, outward) || depth <= 0) return;
        // p is on s's surface, o's nearest face is depth away along `outward`
        cand[n++] = {p + 0.5 * depth * outward, sIsB ? Eigen::Vector3d(outward) : Eigen::Vector3d(-outward), depth};
    });
}

}  // namespace

bool depthInside(const fcl::CollisionGeometryd& g, const Eigen::Isometry3d& X, const Eigen::Vector3d& p, double& depth,
                 Eigen::Vector3d& normal)
{
    return depthInsideLocal(g, X, X.inverse(Eigen::Isometry) * p, depth, normal);
}

bool sampledContactPoints(const fcl::CollisionGeometryd& a, const Eigen::Isometry3d& Xa,
                          const fcl::CollisionGeometryd& b, const Eigen::Isometry3d& Xb, int maxPoints,
                          std::vector<fcl::ContactPoint<double>>& out)
{
    if (!(isKnown(a) && isKnown(b) && (isRound(a) || isRound(b)))) return false;
    out.clear();
    // the boxes round the two solids (oriented with them) apart: no sample can be inside
    // (most pairs whose axis-aligned boxes meet: a long round bar has a fat one)
    if (fcl::obbDisjoint<double>(Eigen::Matrix3d(Xa.linear().transpose() * Xb.linear()),
                                 Eigen::Vector3d(Xa.linear().transpose() * (Xb.translation() - Xa.translation())),
                                 halfBox(a), halfBox(b)))
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
