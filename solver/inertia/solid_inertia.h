#pragma once
// The inertia calculator: mass properties of the solids a model's graphics describe
// (`G … MASS m` or `G … RHO ρ`, docs/model-language.md "Graphics"), and of a body as the
// sum of its solids.
//
// Each solid is computed in its own shape frame (textbook closed forms; prisms by Green's
// theorem on the outline; meshes by surface integrals, see triangle_mesh.h), then placed in
// the body frame with POS/AXIS/ROT: r_body = POS + R_rot · R_axis · r_shape, where R_axis is
// the shortest rotation taking z onto AXIS (a half turn about x for AXIS = −z) and R_rot the
// turn of ROT's degrees about ROT's axis. Solids are combined with the parallel-axis theorem
// (Steiner): I_O = I_G + m (|c|² E − c cᵀ).
//
// Textbook formulas: e.g. F. P. Beer, E. R. Johnston, "Vector Mechanics for Engineers:
// Dynamics", table of mass moments of inertia (box, cylinder, sphere, cone, ellipsoid).

#include "solver/core/diagnostic.h"
#include "solver/spec/model_spec.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace solver {

/// Mass, centre of mass and inertia tensor about the centre of mass.
struct MassProperties {
    double mass = 0;                                      ///< [kg]
    Eigen::Vector3d com = Eigen::Vector3d::Zero();        ///< centre of mass [m]
    /// Inertia tensor about `com`, axes of the frame `com` is given in [kg m^2]:
    /// I = [[Ixx Ixy Ixz][Ixy Iyy Iyz][Ixz Iyz Izz]], Ixx = ∫(y²+z²) dm, Ixy = −∫xy dm.
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

/// Principal moments (ascending) [kg m^2] and axes (columns, a right-handed rotation).
struct PrincipalAxes {
    Eigen::Vector3d moments = Eigen::Vector3d::Zero();
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
};

/// Volume [m^3], centroid [m] and second moments ∫ r rᵀ dV about the centroid [m^5] of a
/// graphic's shape in its own frame (before POS/AXIS/ROT), unit density. Meshes are loaded
/// from `modelDir`/file. Errors (added to `diags` at the statement's positions):
/// `mesh-not-found`, `mesh-unreadable` (corrupt or not a mesh), `mesh-not-closed` ("the mesh
/// is not closed: N open edges", counted after merging identical vertices),
/// `mesh-not-oriented` (faces that disagree on inside and outside), `mesh-no-volume`.
/// A mesh whose normals point inwards (negative volume) is used with its volume's absolute
/// value and a warning `mesh-inverted`. On error the volume is 0.
struct ShapeVolume {
    double volume = 0;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
};
ShapeVolume shapeVolume(const GraphicSpec& g, const std::string& modelDir, Diagnostics& diags);

/// The rotation from a graphic's shape frame to its body's frame: R_rot · R_axis.
Eigen::Matrix3d shapeRotation(const GraphicSpec& g);

/// Mass properties of one solid in its body's frame. Density ρ = RHO, or MASS / volume.
/// A graphic with neither counts as no solid (mass 0). `not-positive` for RHO ≤ 0,
/// `negative-mass` for MASS < 0 (errors, as the model checks give them).
MassProperties solidMassProperties(const GraphicSpec& g, const std::string& modelDir, Diagnostics& diags);

/// Sum of solids given in one frame: mass, centre of mass, inertia about that centre
/// (parallel-axis theorem). An empty list or zero total mass gives zeros.
MassProperties combine(const std::vector<MassProperties>& parts);

/// Body `bodyId`'s mass properties from its graphics with MASS or RHO, in the body's local
/// axes (meshes relative to the folder of `spec.file`). None → nullopt; also nullopt when one
/// of them has an error (in `diags`).
std::optional<MassProperties> bodyMassProperties(const ModelSpec& spec, int bodyId, Diagnostics& diags);

/// Principal moments and axes of a symmetric inertia tensor (Eigen::SelfAdjointEigenSolver).
PrincipalAxes principalAxes(const Eigen::Matrix3d& inertia);

}  // namespace solver
