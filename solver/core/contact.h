#pragma once
// Contact dynamics (`CONTACT [MU μ] [E e]`, docs/contact.md): what the compiled Model,
// the State and the Data hold about it. The geometry (FCL shapes) and the algorithm
// live in solver/contact/; here are only the plain parts that core's types carry:
//   - CompiledContact: the law's parameters and the immutable geometry, shared by
//     every thread (Model::contact; null without CONTACT: the model is as before);
//   - ContactAnchor: a sticking contact's tangential anchor, kept between steps in
//     State::contacts (no creep: the tangential spring holds a resting body);
//   - ContactPoint: one contact of the last evaluation (Data::contacts), for output.

#include <Eigen/Core>

#include <memory>
#include <utility>
#include <vector>

namespace solver {

struct ContactGeometry;  ///< solver/contact/contact_geometry.h

/// Per-thread scratch of the contact algorithm (FCL objects, broad phase), owned by
/// Data and made by CompiledContact::makeScratch.
class ContactScratch {
public:
    virtual ~ContactScratch() = default;
};

/// Default Coulomb friction coefficient of CONTACT without MU.
inline constexpr double kDefaultContactFriction = 0.5;
/// Most contacts one evaluation keeps (Data::contacts, State::contacts); the deepest
/// are not chosen: the first found are kept, the others are dropped.
inline constexpr int kMaxContacts = 512;

struct CompiledContact {
    double mu = kDefaultContactFriction;  ///< Coulomb friction coefficient
    double restitution = 0;               ///< e in [0, 1]
    /// Normal law: per pair of solids k = m_eff·ω², c = 2ζ·m_eff·ω (shared out over the
    /// pair's contact points); ζ from e (docs/contact.md).
    double omega = 300;         ///< [rad/s]
    double dampingRatio = 1;    ///< ζ
    double depthCap = 0.01;     ///< [m]: deeper overlaps push no harder than this depth
    std::shared_ptr<const ContactGeometry> geometry;
    /// Makes the per-thread scratch for `geometry` (Data's constructor calls it).
    std::unique_ptr<ContactScratch> (*makeScratch)(const ContactGeometry&) = nullptr;
};

/// The body pairs (tree indices, −1: the ground; first < second) that have two solids
/// overlapping at the initial pose, which never touch each other (ContactGeometry::
/// excluded by body: what MuJoCo's <exclude> can say). Sorted, no repeats.
std::vector<std::pair<int, int>> contactExcludedBodies(const CompiledContact& contact);

/// A contact's tangential anchor: the material points of the two solids that were
/// together when it began to stick (or where the slip left the spring at μN).
struct ContactAnchor {
    int shapeA = -1, shapeB = -1;  ///< indices into ContactGeometry::shapes
    Eigen::Vector3d onA = Eigen::Vector3d::Zero();  ///< in A's body frame (ground: world)
    Eigen::Vector3d onB = Eigen::Vector3d::Zero();  ///< in B's body frame (ground: world)
};

/// One contact point of an evaluation. Force `force` acts on B at `point` (world),
/// its opposite on A.
struct ContactPoint {
    int shapeA = -1, shapeB = -1;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< world [m]
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); ///< from A to B, unit
    double depth = 0;                                  ///< [m]
    Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< on B, world [N]
    double stiffness = 0;   ///< the point's normal and tangential stiffness k [N/m]
    double normalSpeed = 0; ///< v_n: B's speed away from A along the normal [m/s]
    bool sticking = false;  ///< the tangential spring held (below μN)
    int anchor = -1;        ///< index into the State's anchors it used, −1: none
};

}  // namespace solver
