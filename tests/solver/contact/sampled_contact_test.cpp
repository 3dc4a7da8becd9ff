// The sampled contact points of cylinders and cones (solver/contact/sampled_contact.h):
// depths and normals of points inside a box, a cylinder and a cone; a drum lying on a
// box touches it along its two rims, a drum standing on its end around its rim, a claw
// (a box) against the mill's wide thin grate (a cylinder) by the grate's face, millimetres
// deep, not the metres libccd's MPR measured along the line between the centres.

#include "solver/contact/sampled_contact.h"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace solver {
namespace {

Eigen::Isometry3d at(const Eigen::Vector3d& p, const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity())
{
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.linear() = R;
    X.translation() = p;
    return X;
}

/// Rotation taking z to the world's y (a cylinder's axis along y).
Eigen::Matrix3d zToY() { return Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix(); }

TEST(SampledContact, DepthInsideBoxCylinderAndCone)
{
    double d = 0;
    Eigen::Vector3d n;
    const fcl::Boxd box(2, 4, 6);
    ASSERT_TRUE(depthInside(box, at({1, 0, 0}), {1.5, 0.2, 0.1}, d, n));
    EXPECT_NEAR(d, 0.5, 1e-12);
    EXPECT_TRUE(n.isApprox(Eigen::Vector3d::UnitX()));
    ASSERT_TRUE(depthInside(box, at({0, 0, 0}), {0, 0, -2.9}, d, n));
    EXPECT_NEAR(d, 0.1, 1e-12);
    EXPECT_TRUE(n.isApprox(-Eigen::Vector3d::UnitZ()));
    ASSERT_TRUE(depthInside(box, at({0, 0, 0}), {0, 0, 4}, d, n));
    EXPECT_LT(d, 0);  // outside
    // a cylinder with its axis along y, radius 1, 0.2 thick
    const fcl::Cylinderd disc(1, 0.2);
    ASSERT_TRUE(depthInside(disc, at({0, 0, 0}, zToY()), {0.5, 0.09, 0}, d, n));
    EXPECT_NEAR(d, 0.01, 1e-12);
    EXPECT_TRUE(n.isApprox(Eigen::Vector3d::UnitY())) << n.transpose();
    ASSERT_TRUE(depthInside(disc, at({0, 0, 0}, zToY()), {0, 0, 0.98}, d, n));
    EXPECT_NEAR(d, 0.02, 1e-12);
    EXPECT_TRUE(n.isApprox(Eigen::Vector3d::UnitZ())) << n.transpose();
    // a cone: base radius 1 at z = −1, apex at z = +1 (lz 2)
    const fcl::Coned cone(1, 2);
    ASSERT_TRUE(depthInside(cone, at({0, 0, 0}), {0, 0, -0.9}, d, n));
    EXPECT_NEAR(d, 0.1, 1e-12);
    EXPECT_TRUE(n.isApprox(-Eigen::Vector3d::UnitZ()));
    // on the axis at z = 0.5: the side is at radius 0.25, 0.25/√1.25 away along its normal
    ASSERT_TRUE(depthInside(cone, at({0, 0, 0}), {0, 0, 0.5}, d, n));
    EXPECT_NEAR(d, 0.25 / std::sqrt(1.25), 1e-12);
    ASSERT_TRUE(depthInside(cone, at({0, 0, 0}), {0.3, 0, 0}, d, n));  // side at 0.5: 0.2 in
    EXPECT_NEAR(d, 0.2 / std::sqrt(1.25), 1e-12);
    EXPECT_TRUE(n.isApprox(Eigen::Vector3d(1, 0, 0.5).normalized()));
    EXPECT_FALSE(depthInside(fcl::Sphered(1), at({0, 0, 0}), {0, 0, 0}, d, n));
}

TEST(SampledContact, ADrumLyingOnABoxTouchesAlongBothRims)
{
    std::vector<fcl::ContactPoint<double>> points;
    points.reserve(64);
    const fcl::Boxd floor(10, 10, 1);  // top at z = 0
    const fcl::Cylinderd drum(0.25, 1);
    // 1 mm into the floor, its axis along y, turned about it by 7° (no sample at the bottom)
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.122, Eigen::Vector3d::UnitY()).toRotationMatrix() * zToY();
    ASSERT_TRUE(sampledContactPoints(floor, at({0, 0, -0.5}), drum, at({0.3, 0, 0.249}, R), 8, points));
    ASSERT_EQ(points.size(), 2u);
    for (const auto& p : points) {
        EXPECT_NEAR(p.penetration_depth, 1e-3, 1e-9);
        EXPECT_TRUE(p.normal.isApprox(Eigen::Vector3d::UnitZ())) << p.normal.transpose();  // from the floor to the drum
        EXPECT_NEAR(p.pos.x(), 0.3, 1e-9);
        EXPECT_NEAR(std::abs(p.pos.y()), 0.5, 1e-9);
    }
    // the same pair the other way round: normals from the drum to the floor
    ASSERT_TRUE(sampledContactPoints(drum, at({0.3, 0, 0.249}, R), floor, at({0, 0, -0.5}), 8, points));
    ASSERT_EQ(points.size(), 2u);
    EXPECT_TRUE(points[0].normal.isApprox(-Eigen::Vector3d::UnitZ()));
    // lifted 2 mm clear: no point
    ASSERT_TRUE(sampledContactPoints(floor, at({0, 0, -0.5}), drum, at({0.3, 0, 0.252}, R), 8, points));
    EXPECT_TRUE(points.empty());
}

TEST(SampledContact, ADrumStandingOnItsEndTouchesAroundItsRim)
{
    std::vector<fcl::ContactPoint<double>> points;
    const fcl::Boxd floor(10, 10, 1);
    const fcl::Cylinderd drum(0.25, 1);
    ASSERT_TRUE(sampledContactPoints(floor, at({0, 0, -0.5}), drum, at({0, 0, 0.499}), 8, points));
    ASSERT_EQ(points.size(), 8u);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const auto& p : points) {
        EXPECT_NEAR(p.penetration_depth, 1e-3, 1e-9);
        EXPECT_NEAR(p.pos.z(), -5e-4, 1e-9);
        centre += p.pos / 8;
    }
    // spread around the rim: their centre near the axis, not bunched at one side
    EXPECT_LT(std::hypot(centre.x(), centre.y()), 0.05);
}

TEST(SampledContact, AClawAgainstTheMillsWideThinGrateIsMillimetresDeepByItsFace)
{
    std::vector<fcl::ContactPoint<double>> points;
    // the grate: radius 5.56 m, 0.12 m thick, its axis along y, its face at y = −0.06
    const fcl::Cylinderd grate(5.5614, 0.12);
    const fcl::Boxd claw(0.1, 0.3, 0.2);
    // the claw 4 mm into the face, 3 m off the axis (the line between the centres runs
    // almost along the face: MPR measured metres along it)
    ASSERT_TRUE(sampledContactPoints(claw, at({3, -0.06 - 0.15 + 0.004, 1}), grate, at({0, 0, 0}, zToY()), 8, points));
    ASSERT_FALSE(points.empty());
    for (const auto& p : points) {
        EXPECT_NEAR(p.penetration_depth, 0.004, 1e-9);
        EXPECT_TRUE(p.normal.isApprox(Eigen::Vector3d::UnitY())) << p.normal.transpose();  // claw → grate
    }
    // a box against a box is not this routine's (FCL's box–box is exact)
    EXPECT_FALSE(sampledContactPoints(claw, at({0, 0, 0}), fcl::Boxd(1, 1, 1), at({0, 0, 0}), 8, points));
}

}  // namespace
}  // namespace solver
