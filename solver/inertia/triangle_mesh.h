#pragma once
// Closed triangle meshes for the inertia calculator: loading a mesh file with assimp
// (every format it reads), merging coincident vertices, checking that the surface is
// closed and consistently oriented, and its volume integrals.
//
// assimp's headers stay in triangle_mesh.cpp: nothing here exposes an assimp type.

#include "solver/core/diagnostic.h"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace solver {

/// An indexed triangle mesh [m]. Triangles are counter-clockwise seen from outside
/// when the normals point out.
struct TriangleMesh {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<std::array<int, 3>> triangles;
};

/// Result of loading a mesh file.
struct MeshLoad {
    std::optional<TriangleMesh> mesh;  ///< set on success
    std::string error;                 ///< why it failed (English), when `mesh` is empty
    Text errorText;                    ///< the same, translatable (assimp's own message is plain)
};

/// Loads every mesh of the file's scene (node transforms applied) with assimp, post-processing
/// aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_ValidateDataStructure;
/// vertices are multiplied by `scale` and then merged when their coordinates are identical
/// (so per-face normals, as STL has, do not split the surface).
MeshLoad loadTriangleMesh(const std::string& path, double scale);

/// Edges used by exactly one triangle (a closed surface has none).
int openEdgeCount(const TriangleMesh& mesh);

/// Edges that two triangles run in the same direction (the faces around them are not
/// consistently oriented, so their volume integrals would be wrong).
int misorientedEdgeCount(const TriangleMesh& mesh);

/// Volume integrals of the solid a closed, consistently oriented surface encloses, with unit
/// density: ∫1, ∫x, ∫y, ∫z, ∫x², ∫y², ∫z², ∫xy, ∫yz, ∫zx dV, in that order [m^3 … m^5].
/// Negative when the triangles turn clockwise seen from outside (inverted normals).
/// Source: D. Eberly, "Polyhedral Mass Properties (Revisited)", Geometric Tools, 2002/2009
/// (divergence theorem on each triangle; after B. Mirtich, J. Graphics Tools 1(2), 1996).
std::array<double, 10> meshVolumeIntegrals(const TriangleMesh& mesh);

}  // namespace solver
