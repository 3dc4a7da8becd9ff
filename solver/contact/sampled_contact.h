#pragma once
// Contact points of a cylinder or a cone against a box, a cylinder or a cone by sampled
// surface points (docs/contact.md, "Round solids"). FCL's GJK pairs give one point per
// pair, measured by libccd's MPR along the line between the centres: a claw's cylinder
// against the mill's 11 m grate came out metres deep, and a drum lying on the floor
// rocked on one wandering point. Here each solid's surface is sampled (a box's corners
// and edges, a cylinder's rims, a cone's rim and apex), every sample inside the other
// solid is a contact whose depth and normal are the other solid's nearest face, and at
// most `maxPoints` of them are kept (the deepest, then the ones farthest apart): a drum
// lying on the floor rests on its two rims, a cylinder standing on its end on its rim.
// Analytic, allocation-free once `out` has its capacity.

#include <fcl/geometry/collision_geometry.h>
#include <fcl/narrowphase/contact_point.h>

#include <Eigen/Geometry>

#include <vector>

namespace solver {

/// The least depth [m] that is a contact: two faces that meet where a joint holds them
/// together (a slide block on its mast, a bearing's flange on its housing) overlap by
/// the rounding of their poses, 1e-16 m; their points carried no force and cost the
/// narrow phase and the force law every evaluation.
inline constexpr double kLeastDepth = 1e-9;

/// Samples per rim of a cylinder or a cone.
inline constexpr int kRimSamples = 16;

/// The signed depth of world point `p` inside the solid `g` at pose `X` (> 0 inside, to
/// its nearest face) and that face's outward normal (world). False for a shape it does
/// not know (only BOX, CYLINDER, CONE).
bool depthInside(const fcl::CollisionGeometryd& g, const Eigen::Isometry3d& X, const Eigen::Vector3d& p, double& depth,
                 Eigen::Vector3d& normal);

/// The contact points of solids a and b (normals from a to b, depth ≥ 0), at most
/// `maxPoints`, into `out` (cleared first). False, and `out` untouched, unless one of them
/// is a CYLINDER or a CONE and the other a BOX, a CYLINDER or a CONE.
bool sampledContactPoints(const fcl::CollisionGeometryd& a, const Eigen::Isometry3d& Xa,
                          const fcl::CollisionGeometryd& b, const Eigen::Isometry3d& Xb, int maxPoints,
                          std::vector<fcl::ContactPoint<double>>& out);

}  // namespace solver
