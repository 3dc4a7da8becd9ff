#pragma once
// Clearances between a machine and its scene (FCL, the Flexible Collision Library): the
// shapes a model's graphics describe (G statements), each on its body, and a scene's
// (a ground-graphics-only model such as resources/scenes/sag_mill.pad). Built once; then
// update() moves the machine's shapes to the bodies' poses and the queries give the
// smallest distance and the nearest points.
//
// Shapes (docs/model-language.md "Graphics"), placed in the body frame by POS/AXIS/ROT as
// the inertia calculator places them (shapeRotation):
//   BOX, SPHERE, ELLIPSOID, CYL, CONE → FCL's primitives (CONE shifted: FCL's is centred);
//   TUBE → a closed triangle mesh (64 segments round, rings about as long as they are
//          wide: the bore is hollow, as drawn);
//   PRISM → its outline (ear-clipped) extruded to a triangle mesh;
//   MESH  → the file's triangles (assimp, SCALE applied).
// Meshes go into OBBRSS bounding-volume hierarchies; the scene's shapes into a dynamic
// AABB tree (broad phase), queried once per machine shape.
//
// Which pairs count: every moving machine shape against every scene shape, and against
// the machine's own ground graphics (its pedestal…) except for bodies joined to the
// ground by a joint; never two shapes of one body, nor of bodies joined by a joint (pins
// and telescopes overlap by design).
//
// Threads: a CollisionWorld belongs to one thread (queries reuse its scratch); build one
// per thread that needs it. The solver thread does not use it; the tutorial checker and
// the benchmarks do.

#include "solver/core/data.h"
#include "solver/core/diagnostic.h"
#include "solver/core/model.h"
#include "solver/spec/model_spec.h"

#include <Eigen/Geometry>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace solver {

struct CollisionShape {
    int graphicId = 0;  ///< the G statement's id
    int body = -1;      ///< tree index of the machine body; −1: the ground (machine or scene)
    bool scene = false; ///< from the scene file
    std::string describe() const;  ///< e.g. "G 203 (body 3)" / "scene G 41"
};

struct Clearance {
    double distance = std::numeric_limits<double>::infinity();  ///< [m]; ≤ 0: touching or overlapping
    int shapeA = -1;  ///< index into shapes(): the machine's shape
    int shapeB = -1;  ///< the other
    Eigen::Vector3d pointA = Eigen::Vector3d::Zero(), pointB = Eigen::Vector3d::Zero();  ///< nearest points, world
    bool valid() const { return shapeA >= 0; }
};

class CollisionWorld {
public:
    /// The machine's shapes (graphics of `machineSpec`, bodies numbered by `model`) and
    /// the scene's (`scene`, may be nullptr: ground graphics; bodies there are ignored).
    /// Mesh files are read relative to each spec's file. A shape that cannot be made (a
    /// mesh that does not load) is left out with a warning `collision-shape` in `diags`.
    CollisionWorld(const ModelSpec& machineSpec, const Model& model, const ModelSpec* scene, Diagnostics& diags);
    ~CollisionWorld();
    CollisionWorld(const CollisionWorld&) = delete;
    CollisionWorld& operator=(const CollisionWorld&) = delete;

    const std::vector<CollisionShape>& shapes() const { return m_shapes; }

    /// Moves the machine's shapes to the bodies' poses (data.X_wb, after kinematics).
    void update(const Data& data);
    /// The smallest distance between a moving machine shape and the scene (or the
    /// machine's own ground graphics), over the pairs that count.
    Clearance machineToScene();
    /// The smallest distance between one body's shapes (tree index) and the scene.
    Clearance bodyToScene(int body);
    /// The smallest distance between two machine bodies' shapes (tree indices; −1: the
    /// machine's ground graphics), whatever joins them.
    Clearance between(int bodyA, int bodyB);

    /// Indices into shapes() of the scene's graphics with these G ids (those that exist).
    std::vector<int> sceneShapes(const std::vector<int>& graphicIds) const;
    /// Takes scene shapes out of bodyToScene() and machineToScene() (a tutorial checks
    /// the people in the mill on their own); bodyToShapes() still sees them.
    void excludeFromScene(const std::vector<int>& shapeIndices);
    /// Moves scene shapes (indices into shapes(); the machine's are left alone) to
    /// `offset` · their pose as the scene places them, for the queries that follow (a
    /// person walking into the work area); the identity puts them back. Shapes still in
    /// the scene's broad phase are updated there too.
    void placeSceneShapes(const std::vector<int>& shapeIndices, const Eigen::Isometry3d& offset);
    /// The smallest distance between one body's shapes (tree index) and the given shapes
    /// (indices into shapes()), pair by pair; pairs whose bounding boxes are farther apart
    /// than `cap` or than the best so far are not measured (invalid: none within `cap`).
    Clearance bodyToShapes(int body, const std::vector<int>& shapeIndices,
                           double cap = std::numeric_limits<double>::infinity());
    /// machineToScene() over the bodies whose entry in `skip` (per tree index) is 0: one
    /// running minimum, so each body's broad-phase query prunes by the others' best.
    Clearance machineToScene(const std::vector<char>& skip);

private:
    /// The running-minimum query of `body`'s shapes (−1: every moving shape) against the
    /// scene, leaving out the bodies marked in `skip` (may be nullptr).
    Clearance sceneQuery(int body, const std::vector<char>* skip);
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    std::vector<CollisionShape> m_shapes;
};

}  // namespace solver
