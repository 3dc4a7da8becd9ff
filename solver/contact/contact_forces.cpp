#include "solver/contact/contact_forces.h"

#include "solver/contact/contact_geometry.h"
#include "solver/contact/sampled_contact.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/math/bv/OBB.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>
#include <fcl/narrowphase/detail/primitive_shape_algorithm/box_box.h>
#include <fcl/narrowphase/detail/traversal/collision/mesh_shape_collision_traversal_node.h>
#include <fcl/narrowphase/detail/traversal/collision_node.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace solver {

namespace {

/// Points of one pair within this distance of an anchor's point are the same contact [m].
constexpr double kAnchorMatch = 0.02;
/// Contact points asked of FCL per pair.
constexpr int kPointsPerPair = 8;
/// How far [m] any point of a moving solid may move before the pairs that may touch
/// are searched again (findContacts: a Verlet list, as molecular dynamics keeps its
/// neighbours): the broad phase runs once every few dozen steps, not four times a step.
constexpr double kPairMargin = 0.05;
/// What a pair's gap must exceed the two solids' motions by before it is skipped [m].
constexpr double kGapSlack = 1e-4;

class Scratch final : public ContactScratch {
public:
    explicit Scratch(const ContactGeometry& g) : geometry(&g), request(kPointsPerPair, true)
    {
        for (std::size_t i = 0; i < g.shapes.size(); ++i) {
            objects.push_back(std::make_unique<fcl::CollisionObjectd>(g.shapes[i].geometry, g.shapes[i].local));
            objects.back()->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(i)));
            objects.back()->computeAABB();
        }
        for (int i : g.still) still.registerObject(objects[i].get());
        still.setup();
        // the moving shapes by body, and a box per body for the broad phase's query
        for (int i : g.moving) {
            const int body = g.shapes[static_cast<std::size_t>(i)].body;
            auto it = std::find_if(groups.begin(), groups.end(), [body](const Group& gr) { return gr.body == body; });
            if (it == groups.end()) {
                groups.push_back({body, {}, std::make_shared<fcl::Boxd>(1, 1, 1), nullptr});
                groups.back().query = std::make_unique<fcl::CollisionObjectd>(groups.back().box);
                groups.back().query->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(-1)));
                it = groups.end() - 1;
            }
            it->shapes.push_back(i);
        }
        candidates.reserve(g.still.size());
        fat.resize(g.shapes.size());
        made.resize(g.shapes.size());
        reach.resize(g.shapes.size());
        moved.assign(g.shapes.size(), 0.0);
        for (std::size_t i = 0; i < g.shapes.size(); ++i) {
            // the farthest point of the shape's local box from its frame's origin
            const fcl::AABBd& local = g.shapes[i].geometry->aabb_local;
            reach[i] = local.min_.cwiseAbs().cwiseMax(local.max_.cwiseAbs()).norm();
        }
        pairs.reserve(g.moving.size() * (g.still.size() + g.moving.size()));
        result.clear();
        anchors.reserve(kMaxContacts);
        points.reserve(64);
    }

    /// A moving body's shapes and the box round them all, which queries the still
    /// shapes' tree once for the body (not once per shape).
    struct Group {
        int body = -1;
        std::vector<int> shapes;
        std::shared_ptr<fcl::Boxd> box;
        std::unique_ptr<fcl::CollisionObjectd> query;
    };

    const ContactGeometry* geometry;
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
    std::vector<Group> groups;
    std::vector<int> candidates;  // the still shapes whose boxes meet a group's
    /// A pair that may touch until a moving shape has moved by kPairMargin: b still (the
    /// ground's, the scene's) or moving; never excluded. In the order they are touched
    /// (moving bodies' groups, their shapes, the still shapes by index; then the moving
    /// pairs), which does not depend on when the list was made: the forces add up in
    /// the same order, and a step's result does not depend on the list's history.
    struct Pair {
        int a, b;
        bool still;
        /// At most the distance between the two solids when the list was made [m]
        /// (0: their boxes may meet): the pair cannot touch while the two have moved
        /// less than that between them (findContacts skips it).
        double gap;
    };
    std::vector<Pair> pairs;
    std::vector<fcl::AABBd> fat;  // per shape (the moving ones'): its box when the pairs were made, grown by kPairMargin
    std::vector<Eigen::Isometry3d> made;  // per shape (the moving ones'): its pose then
    std::vector<double> reach;  // per shape: how far its farthest point is from its frame's origin [m]
    std::vector<double> moved;  // per shape: how far any of its points may have moved since the list was made [m]
    bool pairsMade = false;
    long searches = 0;  // makePairs calls: a counter, not state
    fcl::DynamicAABBTreeCollisionManagerd still;
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    fcl::detail::GJKSolver_libccd<double> solver;
    std::vector<fcl::ContactPoint<double>> points;  // one pair's, the normal from a to b
    std::vector<ContactAnchor> anchors;  // updateContactAnchors' new list
    // the evaluation under way (the broad phase's callback)
    const Model* model = nullptr;
    const State* state = nullptr;
    Data* data = nullptr;
    // setContactTiming: a profiling counter, not state (changed through a const Data)
    bool timing = false;
    double seconds = 0;
};

Eigen::Vector3d pointVelocity(const Data& d, int body, const Eigen::Vector3d& p)
{
    if (body < 0) return Eigen::Vector3d::Zero();
    return d.vel[body] + d.omega[body].cross(p - d.X_wb[body].translation());
}

Eigen::Vector3d toWorld(const Data& d, int body, const Eigen::Vector3d& local)
{
    return body < 0 ? local : Eigen::Vector3d(d.X_wb[body] * local);
}

Eigen::Vector3d toLocal(const Data& d, int body, const Eigen::Vector3d& world)
{
    return body < 0 ? world : Eigen::Vector3d(d.X_wb[body].inverse() * world);
}

void addLoad(Data& d, int body, const Eigen::Vector3d& p, const Eigen::Vector3d& f)
{
    if (body < 0) return;
    d.fext[body].head<3>() += (p - d.X_wb[body].translation()).cross(f);
    d.fext[body].tail<3>() += f;
}

/// Calls f with `g` as its FCL primitive type; false for a mesh.
template <class F>
bool asPrimitive(const fcl::CollisionGeometryd& g, F&& f)
{
    switch (g.getNodeType()) {
    case fcl::GEOM_BOX: f(static_cast<const fcl::Boxd&>(g)); return true;
    case fcl::GEOM_SPHERE: f(static_cast<const fcl::Sphered&>(g)); return true;
    case fcl::GEOM_ELLIPSOID: f(static_cast<const fcl::Ellipsoidd&>(g)); return true;
    case fcl::GEOM_CYLINDER: f(static_cast<const fcl::Cylinderd&>(g)); return true;
    case fcl::GEOM_CONE: f(static_cast<const fcl::Coned&>(g)); return true;
    default: return false;
    }
}

/// A triangle mesh (TUBE, PRISM, MESH) `mesh` against a primitive `other` (its FCL
/// shape `shape`): their contact points into s.points, the normals from `first` (one of
/// the two) to the other. What fcl::collide does for the pair (its OBB-tree traversal,
/// libccd on each triangle near the primitive), without fitting a bounding volume to the
/// primitive's corners through a covariance and an eigen-decomposition at every call
/// (FCL 0.7's generic RSS): the traversal's tests read only the primitive's oriented
/// box, which FCL gives directly; its swept-sphere rectangle is made from that box.
template <class Shape>
void meshAgainst(Scratch& s, const fcl::CollisionObjectd& mesh, const fcl::BVHModel<fcl::OBBRSSd>& model,
                 const fcl::CollisionObjectd& other, const Shape& shape, const fcl::CollisionObjectd& first)
{
    using Node = fcl::detail::MeshShapeCollisionTraversalNodeOBBRSS<Shape, fcl::detail::GJKSolver_libccd<double>>;
    Node node;
    node.model1 = &model;
    node.tf1 = mesh.getTransform();
    node.model2 = &shape;
    node.tf2 = other.getTransform();
    node.nsolver = &s.solver;
    fcl::OBBd& obb = node.model2_bv.obb;
    fcl::computeBV(shape, node.tf2, obb);
    // the swept-sphere rectangle: the box's two longest sides, its half-thinnest the radius
    fcl::RSSd& rss = node.model2_bv.rss;
    int order[3] = {0, 1, 2};
    std::sort(order, order + 3, [&](int i, int j) { return obb.extent[i] > obb.extent[j]; });
    rss.axis.col(0) = obb.axis.col(order[0]);
    rss.axis.col(1) = obb.axis.col(order[1]);
    rss.axis.col(2) = rss.axis.col(0).cross(rss.axis.col(1));
    rss.l[0] = 2 * obb.extent[order[0]];
    rss.l[1] = 2 * obb.extent[order[1]];
    rss.r = obb.extent[order[2]];
    rss.To = obb.To - obb.extent[order[0]] * rss.axis.col(0) - obb.extent[order[1]] * rss.axis.col(1);
    node.vertices = model.vertices;
    node.tri_indices = model.tri_indices;
    node.request = s.request;
    s.result.clear();
    node.result = &s.result;
    node.cost_density = model.cost_density * shape.cost_density;
    fcl::detail::collide(&node);
    s.points.clear();
    // FCL's normals point from its first object (the mesh) to the second. Its
    // sphere–triangle test gives the depth negated: a sphere 5 cm into the bore came back
    // −5 cm, no force, and a ball fell through the mill's shell. Its normal and point are
    // right.
    const double towards = &first == &mesh ? 1.0 : -1.0;
    const double depthSign = std::is_same_v<Shape, fcl::Sphered> ? -1.0 : 1.0;
    for (std::size_t i = 0; i < s.result.numContacts(); ++i) {
        const fcl::Contactd& c = s.result.getContact(i);
        s.points.emplace_back(Eigen::Vector3d(towards * c.normal), c.pos, depthSign * c.penetration_depth);
    }
}

/// meshAgainst when `mesh` is a triangle mesh and `other` a primitive; false otherwise.
bool meshAgainstPrimitive(Scratch& s, const fcl::CollisionObjectd& mesh, const fcl::CollisionObjectd& other,
                          const fcl::CollisionObjectd& first)
{
    if (mesh.collisionGeometry()->getNodeType() != fcl::BV_OBBRSS) return false;
    const auto& model = static_cast<const fcl::BVHModel<fcl::OBBRSSd>&>(*mesh.collisionGeometry());
    if (model.getModelType() != fcl::BVH_MODEL_TRIANGLES) return false;
    return asPrimitive(*other.collisionGeometry(),
                       [&](const auto& shape) { meshAgainst(s, mesh, model, other, shape, first); });
}

/// The contact points of shapes a and b into s.points (normals from a to b). Two
/// primitives go straight to FCL's narrow-phase solver with the preallocated list
/// (fcl::collide would allocate its own each call); a mesh against a primitive through
/// meshAgainst; two meshes through fcl::collide.
void contactPoints(Scratch& s, int a, int b)
{
    s.points.clear();
    const fcl::CollisionObjectd& oa = *s.objects[a];
    const fcl::CollisionObjectd& ob = *s.objects[b];
    if (oa.collisionGeometry()->getNodeType() == fcl::GEOM_BOX && ob.collisionGeometry()->getNodeType() == fcl::GEOM_BOX) {
        // what shapeIntersect does, into our list (boxBoxIntersect copies from a vector of its own)
        Eigen::Vector3d normal = Eigen::Vector3d::Zero();
        double depth = 0;
        int code = 0;
        fcl::detail::boxBox2(static_cast<const fcl::Boxd&>(*oa.collisionGeometry()).side, oa.getTransform(),
                             static_cast<const fcl::Boxd&>(*ob.collisionGeometry()).side, ob.getTransform(), normal,
                             &depth, &code, 4, s.points);
        return;
    }
    // a cylinder or a cone against a box, a cylinder or a cone: sampled points
    if (sampledContactPoints(*oa.collisionGeometry(), oa.getTransform(), *ob.collisionGeometry(), ob.getTransform(),
                             kPointsPerPair, s.points))
        return;
    if (meshAgainstPrimitive(s, oa, ob, oa) || meshAgainstPrimitive(s, ob, oa, oa)) return;
    bool primitives = false;
    asPrimitive(*oa.collisionGeometry(), [&](const auto& sa) {
        primitives = asPrimitive(*ob.collisionGeometry(), [&](const auto& sb) {
            // FCL's libccd pairs (cylinders, cones, ellipsoids) add a point even when the
            // shapes do not touch, its fields unset: only a hit's points count
            if (!s.solver.shapeIntersect(sa, oa.getTransform(), sb, ob.getTransform(), &s.points)) s.points.clear();
        });
    });
    if (primitives) return;
    s.points.clear();
    s.result.clear();
    fcl::collide(&oa, &ob, s.request, s.result);  // two meshes
    for (std::size_t i = 0; i < s.result.numContacts(); ++i) {
        const fcl::Contactd& c = s.result.getContact(i);
        // fcl: the normal points from o1 to o2; o1 may be either of ours
        const bool swapped = c.o1 != oa.collisionGeometry().get();
        s.points.emplace_back(swapped ? Eigen::Vector3d(-c.normal) : Eigen::Vector3d(c.normal), c.pos, c.penetration_depth);
    }
}

/// The narrow phase of shapes a and b (a on a moving body; not excluded) and their
/// contact forces.
void touch(Scratch& s, int a, int b)
{
    const ContactGeometry& g = *s.geometry;
    Data& d = *s.data;
    const CompiledContact& law = *s.model->contact;
    contactPoints(s, a, b);
    // the points that are contacts, kept in front (at most kPointsPerPair). FCL's normals
    // are unit and its points lie where both solids' boxes meet; a point that is not such
    // is not a contact (valgrind: FCL's primitive routines can hand back a point whose
    // values were never set, which once gave a NaN step); nor is a point less deep than
    // kLeastDepth (faces that a joint holds together, apart by rounding)
    int n = 0;
    for (const fcl::ContactPoint<double>& fc : s.points) {
        if (n == kPointsPerPair) break;
        if (!(std::abs(fc.normal.norm() - 1) < 1e-6) || !(std::abs(fc.penetration_depth) < 1) || !fc.pos.allFinite())
            continue;
        if (fc.penetration_depth <= kLeastDepth) continue;
        if (!s.objects[static_cast<std::size_t>(a)]->getAABB().contain(fc.pos) &&
            !s.objects[static_cast<std::size_t>(b)]->getAABB().contain(fc.pos))
            continue;
        s.points[static_cast<std::size_t>(n++)] = fc;
    }
    if (n == 0) return;
    const int ba = g.shapes[a].body, bb = g.shapes[b].body;
    const double ma = ba >= 0 ? g.mass[ba] : 0, mb = bb >= 0 ? g.mass[bb] : 0;
    const double meff = ba < 0 ? mb : bb < 0 ? ma : ma * mb / (ma + mb);
    const double k = meff * law.omega * law.omega / n;
    const double c = 2 * law.dampingRatio * meff * law.omega / n;
    const double ct = 2 * meff * law.omega / n;
    for (int i = 0; i < n; ++i) {
        if (static_cast<int>(d.contacts.size()) >= kMaxContacts) return;
        const fcl::ContactPoint<double>& fc = s.points[static_cast<std::size_t>(i)];
        const Eigen::Vector3d normal = fc.normal.normalized();
        const Eigen::Vector3d p = fc.pos;
        const double depth = fc.penetration_depth;
        const Eigen::Vector3d vrel = pointVelocity(d, bb, p) - pointVelocity(d, ba, p);  // B relative to A
        const double vn = vrel.dot(normal);  // > 0: separating
        const double spring = k * std::min(depth, law.depthCap);
        const double N = std::max(0.0, spring + std::clamp(-c * vn, -kDamperCap * spring, kDamperCap * spring));
        const Eigen::Vector3d vt = vrel - vn * normal;
        // the anchor: the nearest of this pair's within kAnchorMatch
        int anchor = -1;
        double best = kAnchorMatch;
        for (std::size_t j = 0; j < s.state->contacts.size(); ++j) {
            const ContactAnchor& an = s.state->contacts[j];
            if (an.shapeA != a || an.shapeB != b) continue;
            const double dist = (toWorld(d, ba, an.onA) - p).norm();
            if (dist < best) {
                best = dist;
                anchor = static_cast<int>(j);
            }
        }
        Eigen::Vector3d ft = -ct * vt;
        if (anchor >= 0) {
            const ContactAnchor& an = s.state->contacts[static_cast<std::size_t>(anchor)];
            Eigen::Vector3d sep = toWorld(d, bb, an.onB) - toWorld(d, ba, an.onA);
            sep -= sep.dot(normal) * normal;
            ft -= k * sep;
        }
        const double limit = law.mu * N;
        const double ftNorm = ft.norm();
        const bool sticking = ftNorm <= limit;
        if (!sticking) ft *= limit / ftNorm;
        const Eigen::Vector3d f = N * normal + ft;
        addLoad(d, bb, p, f);
        addLoad(d, ba, p, -f);
        d.contacts.push_back({.shapeA = a, .shapeB = b, .point = p, .normal = normal, .depth = depth, .force = f,
                              .stiffness = k, .normalSpeed = vn, .sticking = sticking && anchor >= 0, .anchor = anchor});
    }
}

/// The still shapes whose boxes meet the queried body's box, into s.candidates.
bool candidateCallback(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* cdata)
{
    auto* s = static_cast<Scratch*>(cdata);
    const auto i1 = static_cast<int>(reinterpret_cast<std::intptr_t>(o1->getUserData()));
    const auto i2 = static_cast<int>(reinterpret_cast<std::intptr_t>(o2->getUserData()));
    s->candidates.push_back(i1 < 0 ? i2 : i1);
    return false;  // all of them
}

/// How far a point of shape i may have moved at most since the pairs were made: its
/// frame's origin moved |Δt|, and a point r from it moves at most ‖ΔR‖·r more.
double movedSinceMade(const Scratch& s, int i)
{
    const std::size_t k = static_cast<std::size_t>(i);
    const Eigen::Isometry3d& now = s.objects[k]->getTransform();
    const Eigen::Isometry3d& then = s.made[k];
    return (now.translation() - then.translation()).norm() + (now.linear() - then.linear()).norm() * s.reach[k];
}

/// Shape i's oriented bounding box (its local box in its frame), grown by `grow`.
fcl::OBBd orientedBox(const Scratch& s, int i, double grow)
{
    const fcl::CollisionObjectd& o = *s.objects[static_cast<std::size_t>(i)];
    const fcl::AABBd& local = o.collisionGeometry()->aabb_local;
    fcl::OBBd box;
    box.axis = o.getTransform().linear();
    box.To = o.getTransform() * local.center();
    box.extent = 0.5 * (local.max_ - local.min_) + Eigen::Vector3d::Constant(grow);
    return box;
}

/// At most the distance between two oriented boxes: their largest gap along one of
/// the six face normals (0 when none separates them).
double gapBetween(const fcl::OBBd& a, const fcl::OBBd& b)
{
    const Eigen::Vector3d t = b.To - a.To;
    double gap = 0;
    auto along = [&](const Eigen::Vector3d& axis) {
        const double ra = a.extent.dot((a.axis.transpose() * axis).cwiseAbs());
        const double rb = b.extent.dot((b.axis.transpose() * axis).cwiseAbs());
        gap = std::max(gap, std::abs(axis.dot(t)) - ra - rb);
    };
    for (int i = 0; i < 3; ++i) {
        along(a.axis.col(i));
        along(b.axis.col(i));
    }
    return gap;
}

/// The pairs that may touch while no moving shape has moved farther than kPairMargin:
/// each moving shape's axis-aligned and oriented bounding boxes, grown by the margin,
/// meet the other's (grown too when it moves). Any two solids that touch before one
/// of them has moved that far are among them.
void makePairs(Scratch& s)
{
    const ContactGeometry& g = *s.geometry;
    s.pairs.clear();
    const Eigen::Vector3d margin = Eigen::Vector3d::Constant(kPairMargin);
    for (int i : g.moving) {
        const fcl::CollisionObjectd& o = *s.objects[static_cast<std::size_t>(i)];
        s.fat[static_cast<std::size_t>(i)] = fcl::AABBd(o.getAABB().min_ - margin, o.getAABB().max_ + margin);
        s.made[static_cast<std::size_t>(i)] = o.getTransform();
    }
    // the still shapes: one query of their tree per moving body, then shape by shape
    for (Scratch::Group& gr : s.groups) {
        fcl::AABBd box = s.fat[static_cast<std::size_t>(gr.shapes.front())];
        for (int i : gr.shapes) box += s.fat[static_cast<std::size_t>(i)];
        gr.box->side = box.max_ - box.min_;
        gr.box->computeLocalAABB();  // what the object's computeAABB reads
        gr.query->setTranslation(box.center());
        gr.query->computeAABB();
        s.candidates.clear();
        s.still.collide(gr.query.get(), &s, candidateCallback);
        std::sort(s.candidates.begin(), s.candidates.end());  // the tree's order depends on the query
        for (int a : gr.shapes) {
            const fcl::OBBd oa = orientedBox(s, a, kPairMargin);
            const fcl::OBBd exact = orientedBox(s, a, 0);
            for (int b : s.candidates) {
                if (!s.fat[static_cast<std::size_t>(a)].overlap(s.objects[static_cast<std::size_t>(b)]->getAABB()))
                    continue;
                const fcl::OBBd ob = orientedBox(s, b, 0);
                if (oa.overlap(ob) && !g.isExcluded(a, b)) s.pairs.push_back({a, b, true, gapBetween(exact, ob)});
            }
        }
    }
    // the moving pairs
    for (std::size_t m = 0; m < g.moving.size(); ++m) {
        const int a = g.moving[m];
        const fcl::OBBd oa = orientedBox(s, a, kPairMargin);
        const fcl::OBBd exact = orientedBox(s, a, 0);
        for (std::size_t n = m + 1; n < g.moving.size(); ++n) {
            const int b = g.moving[n];
            if (g.shapes[a].body == g.shapes[b].body) continue;
            if (!s.fat[static_cast<std::size_t>(a)].overlap(s.fat[static_cast<std::size_t>(b)])) continue;
            if (oa.overlap(orientedBox(s, b, kPairMargin)) && !g.isExcluded(a, b))
                s.pairs.push_back({a, b, false, gapBetween(exact, orientedBox(s, b, 0))});
        }
    }
    s.pairsMade = true;
    ++s.searches;
}

/// applyContacts' work: the broad phase (the pairs, made again only when a solid has
/// moved out of its margin), the narrow phase and the forces.
void findContacts(const Model& model, const State& state, Data& data, Scratch& s)
{
    const ContactGeometry& g = *s.geometry;
    s.model = &model;
    s.state = &state;
    s.data = &data;
    data.contacts.clear();
    bool inside = s.pairsMade;
    for (int i : g.moving) {
        const int body = g.shapes[i].body;
        fcl::CollisionObjectd& o = *s.objects[static_cast<std::size_t>(i)];
        o.setTransform(data.X_wb[body] * g.shapes[i].local);
        o.computeAABB();
        if (inside) {
            s.moved[static_cast<std::size_t>(i)] = movedSinceMade(s, i);
            inside = s.moved[static_cast<std::size_t>(i)] <= kPairMargin;
        }
    }
    if (!inside) {
        makePairs(s);
        for (int i : g.moving) s.moved[static_cast<std::size_t>(i)] = 0;
    }
    for (const Scratch::Pair& p : s.pairs) {
        // apart by more than the two have moved (with 0.1 mm to spare for rounding)
        if (p.gap > s.moved[static_cast<std::size_t>(p.a)] + s.moved[static_cast<std::size_t>(p.b)] + kGapSlack) continue;
        const fcl::AABBd& box = s.objects[static_cast<std::size_t>(p.a)]->getAABB();
        if (!box.overlap(s.objects[static_cast<std::size_t>(p.b)]->getAABB())) continue;
        // the mill's shell: a solid inside its bore cannot touch it (its AABB holds every other)
        if (p.still) {
            const ContactShape& o = g.shapes[static_cast<std::size_t>(p.b)];
            if (o.tube && clearOfTube(o, box.center(), 0.5 * (box.max_ - box.min_).norm())) continue;
        }
        touch(s, p.a, p.b);
    }
}

}  // namespace

std::unique_ptr<ContactScratch> makeContactScratch(const ContactGeometry& geometry)
{
    return std::make_unique<Scratch>(geometry);
}

void applyContacts(const Model& model, const State& state, Data& data)
{
    if (!model.contact || !data.contactScratch) return;
    auto& s = static_cast<Scratch&>(*data.contactScratch);
    if (!s.timing) {
        findContacts(model, state, data, s);
        return;
    }
    const auto t0 = std::chrono::steady_clock::now();
    findContacts(model, state, data, s);
    s.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void setContactTiming(const Data& data, bool on)
{
    if (!data.contactScratch) return;
    auto& s = static_cast<Scratch&>(*data.contactScratch);
    s.timing = on;
    s.seconds = 0;
}

double contactSeconds(const Data& data)
{
    return data.contactScratch ? static_cast<const Scratch&>(*data.contactScratch).seconds : 0.0;
}

long contactPairSearches(const Data& data)
{
    return data.contactScratch ? static_cast<const Scratch&>(*data.contactScratch).searches : 0;
}

void updateContactAnchors(const Model& model, Data& data, std::vector<ContactAnchor>& anchors)
{
    if (!model.contact || !data.contactScratch) return;
    auto& s = static_cast<Scratch&>(*data.contactScratch);
    const auto t0 = s.timing ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
    const ContactGeometry& g = *s.geometry;
    s.anchors.clear();
    for (const ContactPoint& c : data.contacts) {
        const int ba = g.shapes[c.shapeA].body, bb = g.shapes[c.shapeB].body;
        if (c.sticking) {
            s.anchors.push_back(anchors[static_cast<std::size_t>(c.anchor)]);
            continue;
        }
        // a new contact, or one that slipped: the spring left carrying the friction force
        const Eigen::Vector3d ft = c.force - c.force.dot(c.normal) * c.normal;
        ContactAnchor an;
        an.shapeA = c.shapeA;
        an.shapeB = c.shapeB;
        an.onA = toLocal(data, ba, c.point);
        an.onB = toLocal(data, bb, c.anchor >= 0 && c.stiffness > 0 ? Eigen::Vector3d(c.point - ft / c.stiffness)
                                                                    : c.point);
        s.anchors.push_back(an);
    }
    anchors.assign(s.anchors.begin(), s.anchors.end());
    if (s.timing) s.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace solver
