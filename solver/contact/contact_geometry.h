#pragma once
// The solids that touch under CONTACT (docs/contact.md), compiled once into the
// Model (Model::contact, shared by every thread; immutable):
//   - every graphic of the machine (on its body; body 0: the ground) and of the scene
//     (ground graphics of a `--scene` file or a tutorial's scene), except those marked
//     NOCONTACT;
//   - pairs that never touch: two shapes of one body, two shapes on the ground, and two
//     shapes that already overlap by more than kInitialOverlap at the initial pose (a
//     pin in its bore, a turret on its base plate).
// A mesh that cannot serve as a collision shape is an error "contact-shape".

#include "solver/core/diagnostic.h"
#include "solver/core/model.h"
#include "solver/spec/model_spec.h"

#include <fcl/geometry/collision_geometry.h>

#include <Eigen/Geometry>

#include <memory>
#include <utility>
#include <vector>

namespace solver {

/// Overlap at the initial pose above which two shapes never touch each other [m].
inline constexpr double kInitialOverlap = 1e-3;

struct ContactShape {
    std::shared_ptr<fcl::CollisionGeometryd> geometry;  ///< FCL's queries do not change it
    Eigen::Isometry3d local = Eigen::Isometry3d::Identity();  ///< in the body frame (ground: world)
    int body = -1;       ///< tree index, −1: ground
    int graphicId = 0;   ///< the G statement's id
    bool scene = false;  ///< from the scene
    /// A TUBE on the ground or in the scene (the mill's shell): its frame's inverse (the
    /// axis is z) and the radii and half-length a moving solid must stay clear of to
    /// miss it (the inner wall's polygon's apothem, the outer radius), so that the
    /// narrow phase skips the tube for a solid inside its bore (clearOfTube).
    bool tube = false;
    Eigen::Isometry3d tubeInverse = Eigen::Isometry3d::Identity();
    double tubeInner = 0, tubeOuter = 0, tubeHalfLength = 0;
};

/// Whether a solid within the sphere (centre c, world; radius r) cannot touch the still
/// tube `t`: inside its bore, outside its outer wall, or beyond its ends.
bool clearOfTube(const ContactShape& t, const Eigen::Vector3d& c, double r);

struct ContactGeometry {
    std::vector<ContactShape> shapes;
    std::vector<int> moving;  ///< indices of the shapes on moving bodies
    std::vector<int> still;   ///< indices of the ground's and the scene's
    /// Pairs (a < b) overlapping at the initial pose: they never touch. Sorted.
    std::vector<std::pair<int, int>> excluded;
    /// Per body (tree index): the mass its contacts move, m (the body's and its
    /// descendants') [kg], for the stiffness law (≥ 1e-3).
    std::vector<double> mass;

    bool isExcluded(int a, int b) const;
};

/// The contact model of a compiled model without it (`model`: everything but
/// Model::contact), from its spec's CONTACT statement and graphics and the scene's
/// ground graphics (`scene` may be null). Null without CONTACT, or with errors
/// (added to `diags`).
std::shared_ptr<const CompiledContact> compileContact(const ModelSpec& spec, const ModelSpec* scene,
                                                      const Model& model, Diagnostics& diags);

/// The normal damper's force is held within kDamperCap times the spring's (k·d): the
/// force rises from 0 as the solids meet (no jump that RK4 would step across badly)
/// and e does not depend on the impact speed (contact_forces.h).
inline constexpr double kDamperCap = 4;
/// The most damping: ζ = 2 keeps the fastest decay ω·(ζ + √(ζ² − 1)) = 3.7·ω within
/// RK4's stability at the 1 ms step (ω·h = 0.3: 1.1 < 2.8, with room for a stack's
/// contacts adding their dampers).
inline constexpr double kMostDamping = 2;
/// The least restitution the normal law gives (at ζ = kMostDamping); E below it
/// bounces that much.
inline constexpr double kLeastRestitution = 0.1;

/// The damping ratio ζ of the normal spring–damper (its force held ≥ 0) whose bounce
/// has coefficient of restitution e (e below kLeastRestitution: that one's, ζ ≈ 2).
double dampingRatioFor(double e);

}  // namespace solver
