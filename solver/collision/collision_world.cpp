#include "solver/collision/collision_world.h"

#include "solver/contact/shapes.h"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace solver {

std::string CollisionShape::describe() const
{
    std::string s = (scene ? "scene G " : "G ") + std::to_string(graphicId);
    if (body >= 0) s += " (body " + std::to_string(body) + ")";
    return s;
}

struct CollisionWorld::Impl {
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;  // parallel to shapes
    std::vector<Eigen::Isometry3d> local;                         // shape in its body's frame
    std::vector<int> moving;                                      // shapes on machine bodies
    std::vector<int> parent;                                      // the model's
    fcl::DynamicAABBTreeCollisionManagerd still;                  // scene and machine ground
    std::vector<char> excluded;                                   // per shape: out of `still`
    const std::vector<CollisionShape>* shapes = nullptr;
};

namespace {

/// Overlapping shapes: the plain query gives no points (its distance is −1); the signed
/// one gives the depth (negative) and the deepest points. Only then: it is less exact
/// (GJK/EPA tolerances) than the plain query on separate shapes.
void signedDistance(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, fcl::DistanceResultd& result)
{
    fcl::DistanceRequestd request;
    request.enable_nearest_points = true;
    request.enable_signed_distance = true;
    result.clear();
    fcl::distance(a, b, request, result);
    result.min_distance = std::min(result.min_distance, 0.0);
}

struct Query {
    const std::vector<CollisionShape>* shapes;
    const std::vector<int>* parent;
    int shape = -1;  // the moving one
    Clearance best;
};

bool distanceCallback(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data, double& dist)
{
    auto* q = static_cast<Query*>(data);
    // o1 is the queried (moving) object; o2 one of the manager's
    fcl::CollisionObjectd* other = o2;
    fcl::CollisionObjectd* mine = o1;
    auto otherIndex = int(reinterpret_cast<std::intptr_t>(other->getUserData()));
    if (otherIndex == q->shape) {
        std::swap(other, mine);
        otherIndex = int(reinterpret_cast<std::intptr_t>(other->getUserData()));
    }
    const CollisionShape& s = (*q->shapes)[std::size_t(otherIndex)];
    const CollisionShape& m = (*q->shapes)[std::size_t(q->shape)];
    // the machine's ground graphics do not count against a body joined to the ground
    if (!s.scene && s.body < 0 && m.body >= 0 && (*q->parent)[std::size_t(m.body)] < 0) {
        dist = q->best.distance;
        return false;
    }
    fcl::DistanceRequestd request;
    request.enable_nearest_points = true;
    // starting from the best so far, the pair's own traversal (a mesh's bounding volumes)
    // stops at once where it cannot do better: the mill's shell surrounds every query
    fcl::DistanceResultd result;
    result.min_distance = q->best.distance;
    fcl::distance(mine, other, request, result);
    if (result.min_distance < 0) signedDistance(mine, other, result);
    if (result.min_distance < q->best.distance) {
        q->best.distance = result.min_distance;
        q->best.shapeA = q->shape;
        q->best.shapeB = otherIndex;
        // distance(mine, other): point 0 is on mine (world frame, for shapes and meshes)
        q->best.pointA = result.nearest_points[0];
        q->best.pointB = result.nearest_points[1];
    }
    dist = q->best.distance;
    return dist <= 0;
}

}  // namespace

CollisionWorld::CollisionWorld(const ModelSpec& machineSpec, const Model& model, const ModelSpec* scene,
                               Diagnostics& diags)
    : m_impl(std::make_unique<Impl>())
{
    m_impl->parent = model.parent;
    m_impl->shapes = &m_shapes;
    auto add = [&](const GraphicSpec& g, const ModelSpec& spec, bool isScene) {
        const std::optional<int> on = graphicBody(g, model, isScene);
        if (!on) return;
        const int body = *on;
        GraphicShape shape = graphicShape(g, spec);
        if (!shape.geometry) {
            diags.add(Severity::Warning, "collision-shape", g.src.pos,
                      trText("Diagnostics", "G %1 is left out of the clearance checks: %2")
                          .with(std::to_string(g.id))
                          .with(shape.error));
            return;
        }
        const Eigen::Isometry3d& local = shape.local;
        const int index = int(m_shapes.size());
        m_shapes.push_back({g.id, body, isScene});
        auto object = std::make_unique<fcl::CollisionObjectd>(shape.geometry, local);
        object->setUserData(reinterpret_cast<void*>(std::intptr_t(index)));
        object->computeAABB();
        m_impl->local.push_back(local);
        if (body >= 0) m_impl->moving.push_back(index);
        else m_impl->still.registerObject(object.get());
        m_impl->objects.push_back(std::move(object));
    };
    for (const GraphicSpec& g : machineSpec.graphics) add(g, machineSpec, false);
    if (scene)
        for (const GraphicSpec& g : scene->graphics) add(g, *scene, true);
    m_impl->still.setup();
}

CollisionWorld::~CollisionWorld() = default;

void CollisionWorld::update(const Data& data)
{
    for (int i : m_impl->moving) {
        const std::size_t k = std::size_t(i);
        const int body = m_shapes[k].body;
        if (std::size_t(body) >= data.X_wb.size()) continue;
        m_impl->objects[k]->setTransform(data.X_wb[std::size_t(body)] * m_impl->local[k]);
        m_impl->objects[k]->computeAABB();
    }
}

Clearance CollisionWorld::sceneQuery(int body, const std::vector<char>* skip)
{
    // one running minimum over every shape's query: each broad-phase traversal prunes the
    // scene's boxes farther than the best found so far
    Query q{&m_shapes, &m_impl->parent, -1, {}};
    for (int i : m_impl->moving) {
        const int b = m_shapes[std::size_t(i)].body;
        if (body >= 0 && b != body) continue;
        if (skip && std::size_t(b) < skip->size() && (*skip)[std::size_t(b)]) continue;
        q.shape = i;
        m_impl->still.distance(m_impl->objects[std::size_t(i)].get(), &q, distanceCallback);
        if (q.best.distance <= 0) break;
    }
    return q.best;
}

Clearance CollisionWorld::bodyToScene(int body)
{
    return sceneQuery(body, nullptr);
}

Clearance CollisionWorld::machineToScene()
{
    return bodyToScene(-1);
}

namespace {

void closer(Clearance& best, fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, int ia, int ib)
{
    fcl::DistanceRequestd request;
    request.enable_nearest_points = true;
    fcl::DistanceResultd result;
    fcl::distance(a, b, request, result);
    if (result.min_distance < 0) signedDistance(a, b, result);
    if (result.min_distance < best.distance) {
        best.distance = result.min_distance;
        best.shapeA = ia;
        best.shapeB = ib;
        best.pointA = result.nearest_points[0];
        best.pointB = result.nearest_points[1];
    }
}

}  // namespace

Clearance CollisionWorld::between(int bodyA, int bodyB)
{
    Clearance best;
    for (std::size_t a = 0; a < m_shapes.size(); ++a) {
        if (m_shapes[a].scene || m_shapes[a].body != bodyA) continue;
        for (std::size_t b = 0; b < m_shapes.size(); ++b) {
            if (m_shapes[b].scene || m_shapes[b].body != bodyB || a == b) continue;
            closer(best, m_impl->objects[a].get(), m_impl->objects[b].get(), int(a), int(b));
        }
    }
    return best;
}

std::vector<int> CollisionWorld::sceneShapes(const std::vector<int>& graphicIds) const
{
    std::vector<int> out;
    for (std::size_t i = 0; i < m_shapes.size(); ++i) {
        if (!m_shapes[i].scene) continue;
        for (int id : graphicIds) {
            if (m_shapes[i].graphicId == id) out.push_back(int(i));
        }
    }
    return out;
}

void CollisionWorld::excludeFromScene(const std::vector<int>& shapeIndices)
{
    m_impl->excluded.resize(m_shapes.size(), 0);
    bool changed = false;
    for (int i : shapeIndices) {
        const std::size_t k = std::size_t(i);
        if (k >= m_shapes.size() || m_shapes[k].body >= 0 || m_impl->excluded[k]) continue;
        m_impl->still.unregisterObject(m_impl->objects[k].get());
        m_impl->excluded[k] = 1;
        changed = true;
    }
    if (changed) m_impl->still.setup();
}

void CollisionWorld::placeSceneShapes(const std::vector<int>& shapeIndices, const Eigen::Isometry3d& offset)
{
    bool registered = false;
    for (int i : shapeIndices) {
        const std::size_t k = std::size_t(i);
        if (k >= m_shapes.size() || m_shapes[k].body >= 0 || !m_shapes[k].scene) continue;
        fcl::CollisionObjectd* o = m_impl->objects[k].get();
        o->setTransform(offset * m_impl->local[k]);
        o->computeAABB();
        if (k >= m_impl->excluded.size() || !m_impl->excluded[k]) {
            m_impl->still.update(o);
            registered = true;
        }
    }
    if (registered) m_impl->still.setup();
}

Clearance CollisionWorld::bodyToShapes(int body, const std::vector<int>& shapeIndices, double cap)
{
    Clearance best;
    for (int i : m_impl->moving) {
        if (m_shapes[std::size_t(i)].body != body) continue;
        fcl::CollisionObjectd* a = m_impl->objects[std::size_t(i)].get();
        for (int j : shapeIndices) {
            if (std::size_t(j) >= m_shapes.size() || j == i) continue;
            fcl::CollisionObjectd* b = m_impl->objects[std::size_t(j)].get();
            // the boxes' distance is a lower bound of the shapes'
            if (a->getAABB().distance(b->getAABB()) >= std::min(best.distance, cap)) continue;
            closer(best, a, b, i, j);
        }
    }
    return best;
}

Clearance CollisionWorld::machineToScene(const std::vector<char>& skip)
{
    return sceneQuery(-1, &skip);
}

}  // namespace solver
