#include "solver/contact/shapes.h"

#include "solver/inertia/solid_inertia.h"
#include "solver/inertia/triangle_mesh.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/geometry/shape/sphere.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace solver {

namespace {

using Geometry = std::shared_ptr<fcl::CollisionGeometryd>;
using Mesh = fcl::BVHModel<fcl::OBBRSSd>;

Geometry meshGeometry(const std::vector<Eigen::Vector3d>& vertices, const std::vector<std::array<int, 3>>& triangles)
{
    std::vector<fcl::Vector3d> points(vertices.begin(), vertices.end());
    std::vector<fcl::Triangle> tris;
    tris.reserve(triangles.size());
    for (const auto& t : triangles) tris.emplace_back(std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2]));
    auto mesh = std::make_shared<Mesh>();
    mesh->beginModel(int(tris.size()), int(points.size()));
    mesh->addSubModel(points, tris);
    mesh->endModel();
    mesh->computeLocalAABB();
    return mesh;
}

/// A closed tube (outer and inner walls, two end rings), axis z, centred. The walls are
/// cut along the axis into rings about as long as a segment is wide: long thin triangles
/// make poor bounding volumes (a query inside the mill's shell would visit most of them).
Geometry tubeGeometry(double ro, double ri, double length, int segments = kTubeSegments)
{
    std::vector<Eigen::Vector3d> v;
    std::vector<std::array<int, 3>> t;
    const double h = length / 2;
    const double arc = 2 * std::numbers::pi * ro / segments;
    const int rings = std::clamp(int(std::ceil(length / arc)), 1, 64);
    const int perRing = 2 * segments;  // outer then inner
    for (int r = 0; r <= rings; ++r) {
        const double z = -h + length * r / rings;
        for (int wall = 0; wall < 2; ++wall) {
            const double radius = wall == 0 ? ro : ri;
            for (int k = 0; k < segments; ++k) {
                const double a = 2 * std::numbers::pi * k / segments;
                v.emplace_back(radius * std::cos(a), radius * std::sin(a), z);
            }
        }
    }
    auto at = [&](int ring, int wall, int k) { return ring * perRing + wall * segments + (k % segments); };
    for (int r = 0; r < rings; ++r) {
        for (int k = 0; k < segments; ++k) {
            t.push_back({at(r, 0, k), at(r, 0, k + 1), at(r + 1, 0, k + 1)});  // outer wall
            t.push_back({at(r, 0, k), at(r + 1, 0, k + 1), at(r + 1, 0, k)});
            t.push_back({at(r, 1, k), at(r + 1, 1, k + 1), at(r, 1, k + 1)});  // inner wall
            t.push_back({at(r, 1, k), at(r + 1, 1, k), at(r + 1, 1, k + 1)});
        }
    }
    for (int k = 0; k < segments; ++k) {
        t.push_back({at(rings, 0, k), at(rings, 0, k + 1), at(rings, 1, k + 1)});  // top ring
        t.push_back({at(rings, 0, k), at(rings, 1, k + 1), at(rings, 1, k)});
        t.push_back({at(0, 0, k), at(0, 1, k + 1), at(0, 0, k + 1)});  // bottom ring
        t.push_back({at(0, 0, k), at(0, 1, k), at(0, 1, k + 1)});
    }
    return meshGeometry(v, t);
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c)
{
    return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

/// Ear clipping of a simple polygon (either winding): triangles as index triples.
std::vector<std::array<int, 3>> triangulate(const std::vector<Eigen::Vector2d>& p)
{
    std::vector<std::array<int, 3>> out;
    const int n = int(p.size());
    if (n < 3) return out;
    double area = 0;
    for (int i = 0; i < n; ++i) area += p[i].x() * p[(i + 1) % n].y() - p[(i + 1) % n].x() * p[i].y();
    std::vector<int> idx(n);
    for (int i = 0; i < n; ++i) idx[i] = area >= 0 ? i : n - 1 - i;  // counter-clockwise
    int guard = 0;
    while (idx.size() > 3 && guard++ < 10 * n) {
        bool clipped = false;
        for (std::size_t i = 0; i < idx.size(); ++i) {
            const int a = idx[(i + idx.size() - 1) % idx.size()], b = idx[i], c = idx[(i + 1) % idx.size()];
            if (cross2(p[a], p[b], p[c]) <= 0) continue;  // reflex
            bool inside = false;
            for (int q : idx) {
                if (q == a || q == b || q == c) continue;
                if (cross2(p[a], p[b], p[q]) >= 0 && cross2(p[b], p[c], p[q]) >= 0 && cross2(p[c], p[a], p[q]) >= 0) {
                    inside = true;
                    break;
                }
            }
            if (inside) continue;
            out.push_back({a, b, c});
            idx.erase(idx.begin() + std::ptrdiff_t(i));
            clipped = true;
            break;
        }
        if (!clipped) break;  // not simple: what is left is fanned
    }
    for (std::size_t i = 1; i + 1 < idx.size(); ++i) out.push_back({idx[0], idx[i], idx[i + 1]});
    return out;
}

/// PRISM H x1 y1 …: the outline extruded over z = 0 … H.
Geometry prismGeometry(const std::vector<double>& dims)
{
    const double h = dims[0];
    std::vector<Eigen::Vector2d> outline;
    for (std::size_t i = 1; i + 1 < dims.size(); i += 2) outline.emplace_back(dims[i], dims[i + 1]);
    const int n = int(outline.size());
    std::vector<Eigen::Vector3d> v;
    for (const auto& q : outline) v.emplace_back(q.x(), q.y(), 0.0);
    for (const auto& q : outline) v.emplace_back(q.x(), q.y(), h);
    std::vector<std::array<int, 3>> t;
    for (const auto& tri : triangulate(outline)) {
        t.push_back({tri[0], tri[2], tri[1]});
        t.push_back({n + tri[0], n + tri[1], n + tri[2]});
    }
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        t.push_back({i, j, n + j});
        t.push_back({i, n + j, n + i});
    }
    return meshGeometry(v, t);
}

}  // namespace

std::optional<int> graphicBody(const GraphicSpec& g, const Model& model, bool isScene)
{
    if (g.body == 0) return -1;
    if (isScene) return std::nullopt;
    const int body = model.bodyIndex(g.body);
    if (body < 0) return std::nullopt;
    return body;
}

GraphicShape graphicShape(const GraphicSpec& g, const ModelSpec& spec)
{
    GraphicShape out;
    Geometry geom;
    Eigen::Isometry3d shapeFrame = Eigen::Isometry3d::Identity();
    const auto& d = g.dims;
    switch (g.shape) {
    case ShapeKind::Box: geom = std::make_shared<fcl::Boxd>(d[0], d[1], d[2]); break;
    case ShapeKind::Sphere: geom = std::make_shared<fcl::Sphered>(d[0]); break;
    case ShapeKind::Ellipsoid: geom = std::make_shared<fcl::Ellipsoidd>(d[0], d[1], d[2]); break;
    case ShapeKind::Cylinder: geom = std::make_shared<fcl::Cylinderd>(d[0], d[1]); break;
    case ShapeKind::Cone:
        geom = std::make_shared<fcl::Coned>(d[0], d[1]);
        shapeFrame.translation() = Eigen::Vector3d(0, 0, d[1] / 2);  // FCL's cone is centred
        break;
    case ShapeKind::Tube: geom = tubeGeometry(d[0], d[1], d[2]); break;
    case ShapeKind::Prism: geom = prismGeometry(d); break;
    case ShapeKind::Mesh: {
        const std::filesystem::path dir = std::filesystem::path(spec.file).parent_path();
        const MeshLoad load = loadTriangleMesh((dir / g.meshFile).string(), g.hasScale ? g.scale : 1.0);
        if (!load.mesh) {
            out.error = load.errorText;
            return out;
        }
        geom = meshGeometry(load.mesh->vertices, load.mesh->triangles);
        break;
    }
    }
    out.geometry = std::move(geom);
    out.local.linear() = shapeRotation(g);
    out.local.translation() = g.position;
    out.local = out.local * shapeFrame;
    return out;
}

}  // namespace solver
