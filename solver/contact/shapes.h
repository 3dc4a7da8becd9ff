#pragma once
// The FCL shape of a graphic (G statement), one place for the clearance checks
// (solver/collision/) and the contact dynamics (solver/contact/):
//   BOX, SPHERE, ELLIPSOID, CYL, CONE → FCL's primitives (CONE shifted: FCL's is centred);
//   TUBE → a closed triangle mesh (64 segments round, rings about as long as they are
//          wide: the bore is hollow, as drawn: the mill's shell is worked inside);
//   PRISM → its outline (ear-clipped) extruded to a triangle mesh;
//   MESH  → the file's triangles (assimp, SCALE applied).
// Meshes are OBBRSS bounding-volume hierarchies. The shape is placed in its body's
// frame by POS/AXIS/ROT as the inertia calculator places it (shapeRotation).

#include "solver/core/diagnostic.h"
#include "solver/core/model.h"
#include "solver/spec/model_spec.h"

#include <fcl/geometry/collision_geometry.h>

#include <Eigen/Geometry>

#include <memory>
#include <optional>

namespace solver {

/// Segments round a TUBE's triangle mesh (its walls are regular polygons inscribed in
/// the circles of radii RO and RI).
inline constexpr int kTubeSegments = 64;

struct GraphicShape {
    std::shared_ptr<fcl::CollisionGeometryd> geometry;  ///< null: it could not be made
    Eigen::Isometry3d local = Eigen::Isometry3d::Identity();  ///< the shape in its body's frame
    Text error;  ///< why not (a mesh that does not load), when geometry is null
};

/// The tree index of the body graphic `g` is on (−1: the ground), or nothing when it
/// is left out: a scene's graphic on a body (a scene is ground graphics only), or an
/// unknown body.
std::optional<int> graphicBody(const GraphicSpec& g, const Model& model, bool isScene);

/// The shape of graphic `g` of `spec` (mesh files relative to spec.file).
GraphicShape graphicShape(const GraphicSpec& g, const ModelSpec& spec);

}  // namespace solver
