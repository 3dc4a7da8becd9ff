#pragma once
// SceneGeometry: everything the viewport draws for one model, built once per
// ModelBundle on the CPU (no GL) and shared read-only by every viewport showing that
// bundle (the three screens of a ViewportLayout build it once).
//
// All meshes sit in one vertex and one index array; each body has ranges in it, in
// its own body frame, so a frame draws every body with one model matrix (its pose
// X_wb) and never rebuilds a buffer. "Slots" number the bodies for drawing: slot 0 is
// the ground (world frame), slot b + 1 the body of tree index b.
//
//  - dressed:   the G statements' shapes in their COLOR (MESH files loaded relative to
//               the model file's folder; one that fails is a magenta placeholder box
//               and a message in `problems`).
//  - schematic: as the thesis draws PADROB's generic mode (§2.3): each body a purple
//               bar between its joint points (a minimum spanning tree over them; a body
//               with one joint: a bar from it to the centre of mass), revolute joints
//               (T 0, T 1) green cylinders along their axis A, prismatic joints (T 2) a
//               grey rail along R on the parent over the joint's range and a grey
//               slider on the child, ground joints dark grey anchors. T 1 actuators are
//               drawn per frame between CL1 and CL2 (they join two bodies).

#include "ide/studio/model/model_bundle.h"
#include "ide/studio/view/mesh_builder.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <QStringList>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace studio {

/// Indices [first, first + count) of SceneGeometry::mesh.indices.
struct DrawRange {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    bool empty() const { return count == 0; }
};

/// One G statement's triangles within a range drawn as a whole, and whether its back
/// faces may be culled (closedWinding: +1 or −1 for a closed solid, 0 when not).
struct CullPart {
    DrawRange range;
    Eigen::AlignedBox3d box;  ///< of its vertices, in the range's frame
    int winding = 0;
};

/// Where a part's triangles (indices of `mesh`) lie against a plane (n, d) of the
/// part's own frame, kept where n·x + d ≥ 0: +1 all kept, −1 all cut away, 0 cut through.
int planeSide(const MeshBuilder& mesh, const CullPart& part, const Eigen::Vector4d& plane);

/// True when a closed solid (a part whose winding is not 0) neither crosses nor holds
/// the quad (its corners in order, in the part's frame, grown by `margin`): the near
/// plane's visible rectangle, which then shows none of the solid's inside, so that its
/// back faces may be culled. Conservative: a triangle whose box meets the quad's counts
/// as crossing it; inside or out is told by how many triangles a ray from the quad's
/// centre crosses.
bool solidClearOf(const MeshBuilder& mesh, const CullPart& part, const std::array<Eigen::Vector3d, 4>& quad,
                  double margin);

/// Part of a joint's schematic drawn on one body (to highlight the joint).
struct JointPiece {
    int body = -1;  ///< tree index, −1 = ground
    DrawRange range;
};

/// A pivoted linear actuator (T 1): a cylinder between CL1 on body1 and CL2 on body2.
struct ActuatorLine {
    int joint = -1;  ///< tree index of the joint, −1 for a loop-closing (cut) joint
    int body1 = -1, body2 = -1;  ///< tree indices, −1 = ground
    Eigen::Vector3d cl1 = Eigen::Vector3d::Zero(), cl2 = Eigen::Vector3d::Zero();  ///< body-local [m]
};

struct SceneGeometry {
    MeshBuilder mesh;  ///< every vertex and index (triangles, and the grid's line pairs)
    int nb = 0;        ///< moving bodies; slots = nb + 1

    // per slot (dim nb + 1), in the slot's body frame
    std::vector<DrawRange> dressed;    ///< G shapes
    std::vector<std::vector<CullPart>> dressedParts;  ///< dressed[slot], one part per G statement, in order
    std::vector<DrawRange> bars;       ///< schematic body bars (ground: anchors)
    std::vector<DrawRange> schematic;  ///< bars + the joint marks on this body (contiguous)
    std::vector<Eigen::AlignedBox3d> bounds;  ///< everything drawn on the slot (empty box: nothing)
    std::vector<Eigen::AlignedBox3d> schematicBounds;  ///< the schematic drawn on the slot

    std::vector<std::vector<JointPiece>> jointPieces;  ///< per tree joint (dim nb)
    std::vector<ActuatorLine> actuators;

    DrawRange unitCylinder;  ///< radius 1 along z from 0 to 1 (actuators)
    DrawRange unitTriad;     ///< axes of length 1 (world axes, body frames)
    DrawRange grid;          ///< GL_LINES: 1 m cells, every 10th line brighter, at z = gridZ

    double schematicWidth = 0.05;  ///< bar width [m]; the schematic's other sizes follow it
    double gridZ = 0;       ///< height of the ground grid [m]: 0, or the scene's lowest point
    double gridExtent = 10; ///< the grid covers |x|, |y| ≤ gridExtent [m]

    Eigen::AlignedBox3d initialBounds;  ///< the whole scene at the initial pose (world)
    Eigen::Vector3d seatEye = Eigen::Vector3d(0, -5, 2);  ///< default operator seat [m]
    double seatPitch = -0.3;  ///< its default pitch [rad] (it looks along +y)

    QStringList problems;  ///< meshes that could not be drawn (translated, one line each)

    int slotCount() const { return nb + 1; }
};

/// A scene's drawing: the ground graphics (G … B 0) of a model file drawn around the
/// model (e.g. resources/scenes/sag_mill.pad, the mill the liner manipulator works
/// in), in world coordinates, dressed in every display mode. Its lamps — G statements
/// whose COLOR is near white (isLamp) — are drawn glowing and light the model and the
/// scene (a few point lights), the rest is lit dimly (an interior). Graphics on moving
/// bodies are not drawn (`skippedGraphics`).
struct SceneDressing {
    MeshBuilder mesh;
    DrawRange solids;  ///< every ground graphic but the lamps
    std::vector<CullPart> solidParts;  ///< solids, one part per G statement, in order
    DrawRange lamps;   ///< the lamps
    std::vector<Eigen::Vector3d> lights;  ///< the lamps' centres [m, world]
    Eigen::AlignedBox3d bounds;           ///< of everything drawn [m, world]
    int skippedGraphics = 0;              ///< G statements on moving bodies
    QStringList problems;                 ///< meshes that could not be drawn (as SceneGeometry)
};

/// True for a scene graphic drawn as a lamp: a COLOR with every channel ≥ 0.7 and a
/// sum ≥ 2.6 (white or warm white; a yellow hard hat is not one).
bool isLamp(const solver::GraphicSpec& graphic);

/// The drawing of `scene` (nullptr for nullptr). Built on the first call for a bundle
/// and shared while any viewport holds it. GUI thread only.
std::shared_ptr<const SceneDressing> sceneDressing(const std::shared_ptr<const ModelBundle>& scene);

/// The geometry of `bundle` (an empty scene with the grid for nullptr). Built on the
/// first call for a bundle and shared while any viewport holds it. GUI thread only.
std::shared_ptr<const SceneGeometry> sceneGeometry(const std::shared_ptr<const ModelBundle>& bundle);

/// Builds the geometry (no cache). `initial` = body poses at the initial state.
std::shared_ptr<SceneGeometry> buildSceneGeometry(const ModelBundle* bundle,
                                                  const std::vector<Eigen::Isometry3d>& initial);

/// Body poses X_wb at the model's initial state (solver::makeState + forwardKinematics).
std::vector<Eigen::Isometry3d> initialPoses(const solver::Model& model);

/// The body a ray meets first (picking: the ray under the cursor, Camera::rayThrough):
/// its triangles as drawn with the bodies at `X_wb` (by tree index) — the dressed
/// shapes (a body without any: its bar) when `dressed`, the schematic when
/// `schematic`. Sets `body` (tree index) and `point` (the hit, world [m]) and returns
/// true; false when the ray meets no moving body (the ground is never picked).
bool pickBody(const SceneGeometry& geometry, const std::vector<Eigen::Isometry3d>& X_wb,
              const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, bool schematic, bool dressed,
              int& body, Eigen::Vector3d& point);

/// World bounds of everything drawn (dressed and schematic; or the schematic only) with
/// the bodies at `X_wb` (poses by tree index; the actuators' ends included). Empty box
/// when nothing is drawn.
Eigen::AlignedBox3d worldBounds(const SceneGeometry& geometry, const std::vector<Eigen::Isometry3d>& X_wb,
                                bool schematicOnly = false);

}  // namespace studio
