#pragma once
// MeshBuilder: triangle meshes for the 3D viewport, built on the CPU once per model
// (no GL here). Every shape of the model language's G statement is tessellated in its
// shape frame (docs/model-language.md "Graphics": BOX and CYL centred, CONE with its
// base at the origin, PRISM extruded from 0 to H along z) and placed with the current
// transform; vertices carry a position, a normal and a colour.
//
// Normals are per face (flat) for boxes, prisms, caps and meshes and per vertex
// (smooth) on round surfaces. Triangle winding is not relied on: the shader lights
// the side that faces the viewer.

#include "solver/inertia/triangle_mesh.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace studio {

/// One vertex as the GPU reads it (location 0: position, 1: normal, 2: colour).
struct MeshVertex {
    float position[3];
    float normal[3];
    float color[3];
};

class MeshBuilder {
public:
    std::vector<MeshVertex> vertices;
    std::vector<std::uint32_t> indices;  ///< triangles (or line pairs for lines())

    /// Colour of the vertices added from now on (r, g, b in [0, 1]).
    void setColor(const Eigen::Vector3d& rgb) { m_color = rgb.cast<float>(); }
    /// Transform applied to the positions added from now on (normals get the inverse
    /// transpose of its linear part).
    void setTransform(const Eigen::Affine3d& transform);
    void resetTransform() { setTransform(Eigen::Affine3d::Identity()); }

    /// Longest edge wanted across flat and round faces [m, after the transform]; 0 (the
    /// default): none. Boxes, cylinders, tubes and cones added from now on have their
    /// faces cut into a grid no coarser than this (shared edges cut alike, so solids stay
    /// closed), so that light computed at the vertices (Viewport's per-vertex shading)
    /// still shows a lamp's pool of light across a large face.
    void setMaxEdge(double length) { m_maxEdge = length > 0 ? length : 0; }
    double maxEdge() const { return m_maxEdge; }

    /// Adds a vertex (shape frame) and returns its index.
    std::uint32_t vertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n);
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    /// A flat quad a-b-c-d (in order around it) with normal n.
    void quad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
              const Eigen::Vector3d& d, const Eigen::Vector3d& n);
    /// The parallelogram a, b, b + d − a, d (counter-clockwise seen from where n points),
    /// cut into nab × nad quads.
    void grid(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& d,
              const Eigen::Vector3d& n, int nab, int nad);

    /// Box with full edge lengths `size`, centred at the origin.
    void box(const Eigen::Vector3d& size);
    /// Box of square section `width` from `a` to `b` (a bar); nothing when a = b.
    void bar(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double width);
    /// Cylinder of radius r along z from z0 to z1, with caps.
    void cylinder(double r, double z0, double z1, int segments = 32);
    /// Tube (outer radius ro, inner ri) along z, centred, length l.
    void tube(double ro, double ri, double l, int segments = 32);
    /// Ellipsoid with semi-axes a, b, c (a sphere when equal), centred.
    void ellipsoid(double a, double b, double c, int slices = 32, int stacks = 16);
    /// Cone: base of radius r at z = 0, apex at z = l.
    void cone(double r, double l, int segments = 32);
    /// Prism: the polygon (x, y pairs, either winding, simple) extruded from z = 0 to h.
    /// False (and nothing added) when it has fewer than 3 vertices or no area.
    bool prism(double h, const std::vector<double>& xy);
    /// Every triangle of `mesh` with its own face normal.
    void triangles(const solver::TriangleMesh& mesh);
    /// Axes triad: boxes of length 1 and thickness `thickness` along x (red), y (green), z (blue).
    void triad(double thickness);
    /// Line segment a-b (for GL_LINES ranges; the normal is unused).
    void line(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

    /// Appends `other` (its indices shifted).
    void append(const MeshBuilder& other);

    /// Bounds of the vertices added so far (in the frame they were placed in).
    Eigen::AlignedBox3d bounds() const;

private:
    /// Into how many pieces a length (shape frame) along `direction` is cut: 1 without
    /// a maximum edge.
    int pieces(double length, const Eigen::Vector3d& direction) const;
    /// The round wall of radius r along z from z0 to z1, its normals outwards (or towards
    /// the axis), cut along z.
    void wall(double r, double z0, double z1, int segments, bool inward);
    /// The flat ring r0 ≤ ρ ≤ r1 (a disc when r0 = 0) at height z, facing +z when `up`,
    /// cut into rings.
    void disc(double r0, double r1, double z, bool up, int segments);

    Eigen::Vector3f m_color{0.6f, 0.6f, 0.6f};
    double m_maxEdge = 0;
    Eigen::Affine3d m_transform = Eigen::Affine3d::Identity();
    Eigen::Matrix3d m_normalMatrix = Eigen::Matrix3d::Identity();
};

/// How the triangles indices[first, first + count) of `mesh` bound a solid: +1 when they
/// form closed surfaces wound counter-clockwise seen from outside (every edge shared by
/// two triangles, in opposite directions; vertices less than about `tolerance` apart
/// are one; every connected surface encloses a volume on the same side), −1 when they
/// are closed but wound clockwise seen from outside, 0 otherwise (open, inconsistently
/// wound, flat). Seen from outside such a solid, only the triangles facing the eye can
/// show, so the others may be culled (unless the solid is cut open, e.g. by a clip plane).
int closedWinding(const MeshBuilder& mesh, std::uint32_t first, std::uint32_t count, double tolerance);

/// Triangulates a simple polygon (x, y pairs) by ear clipping: index triples into it,
/// counter-clockwise. Empty when it has fewer than 3 vertices or no area.
std::vector<int> triangulatePolygon(const std::vector<Eigen::Vector2d>& polygon);

/// The rigid frame whose z axis runs from `a` towards `b`, with its origin at `a`
/// (x and y perpendicular, any turn about z).
Eigen::Affine3d frameAlong(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

}  // namespace studio
