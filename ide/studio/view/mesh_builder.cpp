#include "ide/studio/view/mesh_builder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <unordered_map>

namespace studio {

using Eigen::Vector2d;
using Eigen::Vector3d;

void MeshBuilder::setTransform(const Eigen::Affine3d& transform)
{
    m_transform = transform;
    const Eigen::Matrix3d linear = transform.linear();
    const double det = linear.determinant();
    m_normalMatrix = std::abs(det) > 1e-300 ? Eigen::Matrix3d(linear.inverse().transpose())
                                            : Eigen::Matrix3d::Identity();
}

std::uint32_t MeshBuilder::vertex(const Vector3d& p, const Vector3d& n)
{
    const Vector3d q = m_transform * p;
    Vector3d m = m_normalMatrix * n;
    const double len = m.norm();
    m = len > 1e-300 ? Vector3d(m / len) : Vector3d::UnitZ();
    MeshVertex v{};
    for (int k = 0; k < 3; ++k) {
        v.position[k] = static_cast<float>(q[k]);
        v.normal[k] = static_cast<float>(m[k]);
        v.color[k] = m_color[k];
    }
    vertices.push_back(v);
    return static_cast<std::uint32_t>(vertices.size() - 1);
}

void MeshBuilder::triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c)
{
    indices.push_back(a);
    indices.push_back(b);
    indices.push_back(c);
}

void MeshBuilder::quad(const Vector3d& a, const Vector3d& b, const Vector3d& c, const Vector3d& d,
                       const Vector3d& n)
{
    const std::uint32_t i0 = vertex(a, n), i1 = vertex(b, n), i2 = vertex(c, n), i3 = vertex(d, n);
    triangle(i0, i1, i2);
    triangle(i0, i2, i3);
}

int MeshBuilder::pieces(double length, const Vector3d& direction) const
{
    if (!(m_maxEdge > 0)) return 1;
    const double placed = std::abs(length) * (m_transform.linear() * direction).norm();
    // at most 64 a side: a face far larger than the lamps' reach needs no finer grid
    return static_cast<int>(std::clamp(std::ceil(placed / m_maxEdge - 1e-9), 1.0, 64.0));
}

void MeshBuilder::grid(const Vector3d& a, const Vector3d& b, const Vector3d& d, const Vector3d& n, int nab,
                       int nad)
{
    if (nab <= 1 && nad <= 1) {
        quad(a, b, b + d - a, d, n);
        return;
    }
    const std::uint32_t first = static_cast<std::uint32_t>(vertices.size());
    const Vector3d ab = b - a, ad = d - a;
    for (int j = 0; j <= nad; ++j) {
        for (int i = 0; i <= nab; ++i) vertex(a + ab * (double(i) / nab) + ad * (double(j) / nad), n);
    }
    const auto row = static_cast<std::uint32_t>(nab + 1);
    for (int j = 0; j < nad; ++j) {
        for (int i = 0; i < nab; ++i) {
            const std::uint32_t p = first + static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
            triangle(p, p + 1, p + row + 1);
            triangle(p, p + row + 1, p + row);
        }
    }
}

void MeshBuilder::box(const Vector3d& size)
{
    const Vector3d h = 0.5 * size;
    // cut alike along each axis on every face, so that neighbouring faces share their edges
    std::array<int, 3> cuts{};
    for (int axis = 0; axis < 3; ++axis) {
        cuts[static_cast<std::size_t>(axis)] = pieces(size[axis], Vector3d::Unit(axis));
    }
    // one quad (or grid) per face, counter-clockwise seen from outside
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const int nu = cuts[static_cast<std::size_t>(u)], nv = cuts[static_cast<std::size_t>(v)];
        for (int s = -1; s <= 1; s += 2) {
            Vector3d n = Vector3d::Zero();
            n[axis] = s;
            auto corner = [&](double cu, double cv) {
                Vector3d p;
                p[axis] = s * h[axis];
                p[u] = cu * h[u];
                p[v] = cv * h[v];
                return p;
            };
            if (s > 0) grid(corner(-1, -1), corner(1, -1), corner(-1, 1), n, nu, nv);
            else grid(corner(-1, -1), corner(-1, 1), corner(1, -1), n, nv, nu);
        }
    }
}

void MeshBuilder::wall(double r, double z0, double z1, int segments, bool inward)
{
    const double step = 2 * std::numbers::pi / segments;
    const int rows = pieces(z1 - z0, Vector3d::UnitZ());
    const double sign = inward ? -1 : 1;
    const std::uint32_t first = static_cast<std::uint32_t>(vertices.size());
    for (int j = 0; j <= rows; ++j) {
        const double z = z0 + (z1 - z0) * j / rows;
        for (int k = 0; k <= segments; ++k) {
            const double c = std::cos(k * step), s = std::sin(k * step);
            vertex(Vector3d(r * c, r * s, z), sign * Vector3d(c, s, 0));
        }
    }
    const auto row = static_cast<std::uint32_t>(segments + 1);
    for (int j = 0; j < rows; ++j) {
        for (int k = 0; k < segments; ++k) {
            const std::uint32_t p = first + static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(k);
            // counter-clockwise seen from the side the normal points to
            if (inward) {
                triangle(p, p + row + 1, p + 1);
                triangle(p, p + row, p + row + 1);
            } else {
                triangle(p, p + 1, p + row + 1);
                triangle(p, p + row + 1, p + row);
            }
        }
    }
}

void MeshBuilder::disc(double r0, double r1, double z, bool up, int segments)
{
    const double step = 2 * std::numbers::pi / segments;
    const int rings = std::max(pieces(r1 - r0, Vector3d::UnitX()), pieces(r1 - r0, Vector3d::UnitY()));
    const Vector3d n(0, 0, up ? 1 : -1);
    const auto row = static_cast<std::uint32_t>(segments + 1);
    const bool fan = !(r0 > 0);
    const std::uint32_t centre = fan ? vertex(Vector3d(0, 0, z), n) : 0;
    const std::uint32_t first = static_cast<std::uint32_t>(vertices.size());
    for (int j = fan ? 1 : 0; j <= rings; ++j) {
        const double r = r0 + (r1 - r0) * j / rings;
        for (int k = 0; k <= segments; ++k) vertex(Vector3d(r * std::cos(k * step), r * std::sin(k * step), z), n);
    }
    auto face = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (up) triangle(a, b, c);
        else triangle(a, c, b);
    };
    // rows of the ring vertices from the inside out; the centre's fan first
    if (fan) {
        for (int k = 0; k < segments; ++k) {
            const std::uint32_t p = first + static_cast<std::uint32_t>(k);
            face(centre, p, p + 1);
        }
    }
    const int quadRows = fan ? rings - 1 : rings;
    for (int j = 0; j < quadRows; ++j) {
        for (int k = 0; k < segments; ++k) {
            const std::uint32_t in = first + static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(k);
            const std::uint32_t out = in + row;
            // inner k, outer k, outer k+1, inner k+1: counter-clockwise seen from +z
            face(in, out, out + 1);
            face(in, out + 1, in + 1);
        }
    }
}

void MeshBuilder::bar(const Vector3d& a, const Vector3d& b, double width)
{
    const double len = (b - a).norm();
    if (!(len > 0)) return;
    const Eigen::Affine3d saved = m_transform;
    Eigen::Affine3d f = frameAlong(a, b);
    f.translate(Vector3d(0, 0, 0.5 * len));
    setTransform(saved * f);
    box(Vector3d(width, width, len));
    setTransform(saved);
}

void MeshBuilder::cylinder(double r, double z0, double z1, int segments)
{
    // side: smooth normals; caps: flat
    wall(r, z0, z1, segments, false);
    disc(0, r, z0, false, segments);
    disc(0, r, z1, true, segments);
}

void MeshBuilder::tube(double ro, double ri, double l, int segments)
{
    const double z0 = -0.5 * l, z1 = 0.5 * l;
    wall(ro, z0, z1, segments, false);
    wall(ri, z0, z1, segments, true);  // the inner wall faces the axis
    // annular ends
    disc(ri, ro, z0, false, segments);
    disc(ri, ro, z1, true, segments);
}

void MeshBuilder::ellipsoid(double a, double b, double c, int slices, int stacks)
{
    const std::uint32_t first = static_cast<std::uint32_t>(vertices.size());
    for (int i = 0; i <= stacks; ++i) {
        const double phi = std::numbers::pi * i / stacks;  // from the +z pole
        for (int j = 0; j <= slices; ++j) {
            const double th = 2 * std::numbers::pi * j / slices;
            const Vector3d u(std::sin(phi) * std::cos(th), std::sin(phi) * std::sin(th), std::cos(phi));
            // the normal of x²/a² + y²/b² + z²/c² = 1 is the gradient (x/a², y/b², z/c²)
            vertex(Vector3d(a * u.x(), b * u.y(), c * u.z()), Vector3d(u.x() / a, u.y() / b, u.z() / c));
        }
    }
    const int row = slices + 1;
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const std::uint32_t p = first + static_cast<std::uint32_t>(i * row + j);
            const std::uint32_t q = p + static_cast<std::uint32_t>(row);
            if (i > 0) triangle(p, q, p + 1);
            if (i < stacks - 1) triangle(p + 1, q, q + 1);
        }
    }
}

void MeshBuilder::cone(double r, double l, int segments)
{
    const double step = 2 * std::numbers::pi / segments;
    const double slant = std::hypot(r, l);
    // side: smooth normals (l cos, l sin, r) / slant; the apex gets one vertex per segment
    const std::uint32_t first = static_cast<std::uint32_t>(vertices.size());
    for (int k = 0; k <= segments; ++k) {
        const double c = std::cos(k * step), s = std::sin(k * step);
        const double cm = std::cos((k + 0.5) * step), sm = std::sin((k + 0.5) * step);
        vertex(Vector3d(r * c, r * s, 0), Vector3d(l * c, l * s, r) / slant);
        vertex(Vector3d(0, 0, l), Vector3d(l * cm, l * sm, r) / slant);
    }
    for (int k = 0; k < segments; ++k) {
        const std::uint32_t a = first + 2 * k;
        triangle(a, a + 2, a + 1);
    }
    disc(0, r, 0, false, segments);
}

bool MeshBuilder::prism(double h, const std::vector<double>& xy)
{
    std::vector<Vector2d> poly;
    for (std::size_t k = 0; k + 1 < xy.size(); k += 2) {
        const Vector2d p(xy[k], xy[k + 1]);
        if (poly.empty() || (p - poly.back()).norm() > 1e-12) poly.push_back(p);
    }
    while (poly.size() > 1 && (poly.front() - poly.back()).norm() <= 1e-12) poly.pop_back();
    if (poly.size() < 3) return false;
    // make the outline counter-clockwise
    double area2 = 0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const Vector2d& p = poly[k];
        const Vector2d& q = poly[(k + 1) % poly.size()];
        area2 += p.x() * q.y() - q.x() * p.y();
    }
    if (area2 < 0) std::reverse(poly.begin(), poly.end());
    const std::vector<int> ccw = triangulatePolygon(poly);
    if (ccw.empty()) return false;
    // caps
    for (int end = 0; end < 2; ++end) {
        const double z = end ? h : 0;
        const Vector3d n(0, 0, end ? 1 : -1);
        const std::uint32_t first = static_cast<std::uint32_t>(vertices.size());
        for (const Vector2d& p : poly) vertex(Vector3d(p.x(), p.y(), z), n);
        for (std::size_t k = 0; k + 2 < ccw.size(); k += 3) {
            const auto a = first + static_cast<std::uint32_t>(ccw[k]);
            const auto b = first + static_cast<std::uint32_t>(ccw[k + 1]);
            const auto c = first + static_cast<std::uint32_t>(ccw[k + 2]);
            if (end) triangle(a, b, c);
            else triangle(a, c, b);
        }
    }
    // sides: one flat quad per edge, outward normal (dy, −dx) for a counter-clockwise outline
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const Vector2d& p = poly[k];
        const Vector2d& q = poly[(k + 1) % poly.size()];
        const Vector2d d = q - p;
        const Vector3d n = Vector3d(d.y(), -d.x(), 0).normalized();
        quad(Vector3d(p.x(), p.y(), 0), Vector3d(q.x(), q.y(), 0), Vector3d(q.x(), q.y(), h),
             Vector3d(p.x(), p.y(), h), n);
    }
    return true;
}

void MeshBuilder::triangles(const solver::TriangleMesh& mesh)
{
    vertices.reserve(vertices.size() + 3 * mesh.triangles.size());
    indices.reserve(indices.size() + 3 * mesh.triangles.size());
    const int nv = static_cast<int>(mesh.vertices.size());
    for (const auto& t : mesh.triangles) {
        if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= nv || t[1] >= nv || t[2] >= nv) continue;
        const Vector3d& a = mesh.vertices[static_cast<std::size_t>(t[0])];
        const Vector3d& b = mesh.vertices[static_cast<std::size_t>(t[1])];
        const Vector3d& c = mesh.vertices[static_cast<std::size_t>(t[2])];
        const Vector3d n = (b - a).cross(c - a);
        if (!(n.norm() > 0)) continue;
        const Vector3d u = n.normalized();
        const std::uint32_t i = vertex(a, u);
        vertex(b, u);
        vertex(c, u);
        triangle(i, i + 1, i + 2);
    }
}

void MeshBuilder::triad(double thickness)
{
    const Eigen::Affine3d saved = m_transform;
    const Eigen::Vector3f savedColor = m_color;
    for (int axis = 0; axis < 3; ++axis) {
        Vector3d rgb = Vector3d::Zero();
        rgb[axis] = 1;
        if (axis == 0) rgb = Vector3d(0.90, 0.15, 0.12);
        if (axis == 1) rgb = Vector3d(0.15, 0.80, 0.20);
        if (axis == 2) rgb = Vector3d(0.20, 0.40, 1.00);
        setColor(rgb);
        Vector3d size = Vector3d::Constant(thickness);
        size[axis] = 1;
        Vector3d centre = Vector3d::Zero();
        centre[axis] = 0.5;
        Eigen::Affine3d t = saved;
        t.translate(centre);
        setTransform(t);
        box(size);
    }
    setTransform(saved);
    m_color = savedColor;
}

void MeshBuilder::line(const Vector3d& a, const Vector3d& b)
{
    const std::uint32_t i = vertex(a, Vector3d::UnitZ());
    vertex(b, Vector3d::UnitZ());
    indices.push_back(i);
    indices.push_back(i + 1);
}

void MeshBuilder::append(const MeshBuilder& other)
{
    const auto offset = static_cast<std::uint32_t>(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    indices.reserve(indices.size() + other.indices.size());
    for (std::uint32_t i : other.indices) indices.push_back(i + offset);
}

Eigen::AlignedBox3d MeshBuilder::bounds() const
{
    Eigen::AlignedBox3d box;
    for (const MeshVertex& v : vertices) box.extend(Vector3d(v.position[0], v.position[1], v.position[2]));
    return box;
}

std::vector<int> triangulatePolygon(const std::vector<Vector2d>& polygon)
{
    const int n = static_cast<int>(polygon.size());
    std::vector<int> out;
    if (n < 3) return out;
    double area2 = 0;
    for (int k = 0; k < n; ++k) {
        const Vector2d& p = polygon[static_cast<std::size_t>(k)];
        const Vector2d& q = polygon[static_cast<std::size_t>((k + 1) % n)];
        area2 += p.x() * q.y() - q.x() * p.y();
    }
    if (!(std::abs(area2) > 1e-18)) return out;
    // work on a counter-clockwise list of indices
    std::vector<int> ring(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) ring[static_cast<std::size_t>(k)] = area2 > 0 ? k : n - 1 - k;
    auto at = [&](int i) -> const Vector2d& { return polygon[static_cast<std::size_t>(i)]; };
    auto cross = [](const Vector2d& a, const Vector2d& b, const Vector2d& c) {
        return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    };
    auto inside = [&](const Vector2d& p, const Vector2d& a, const Vector2d& b, const Vector2d& c) {
        return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
    };
    int guard = 0;
    while (ring.size() > 3 && guard < 4 * n * n) {
        ++guard;
        bool clipped = false;
        const int m = static_cast<int>(ring.size());
        for (int k = 0; k < m; ++k) {
            const int ia = ring[static_cast<std::size_t>((k + m - 1) % m)];
            const int ib = ring[static_cast<std::size_t>(k)];
            const int ic = ring[static_cast<std::size_t>((k + 1) % m)];
            if (cross(at(ia), at(ib), at(ic)) <= 0) continue;  // reflex or flat corner: not an ear
            bool empty = true;
            for (int other : ring) {
                if (other == ia || other == ib || other == ic) continue;
                if (inside(at(other), at(ia), at(ib), at(ic))) {
                    empty = false;
                    break;
                }
            }
            if (!empty) continue;
            out.insert(out.end(), {ia, ib, ic});
            ring.erase(ring.begin() + k);
            clipped = true;
            break;
        }
        if (!clipped) {
            // not simple (or only flat corners left): fan out what remains
            for (std::size_t k = 1; k + 1 < ring.size(); ++k) out.insert(out.end(), {ring[0], ring[k], ring[k + 1]});
            return out;
        }
    }
    if (ring.size() == 3) out.insert(out.end(), {ring[0], ring[1], ring[2]});
    return out;
}

Eigen::Affine3d frameAlong(const Vector3d& a, const Vector3d& b)
{
    Eigen::Affine3d f = Eigen::Affine3d::Identity();
    f.translation() = a;
    const Vector3d d = b - a;
    if (d.norm() > 0) f.linear() = Eigen::Quaterniond::FromTwoVectors(Vector3d::UnitZ(), d).toRotationMatrix();
    return f;
}

int closedWinding(const MeshBuilder& mesh, std::uint32_t first, std::uint32_t count, double tolerance)
{
    if (count < 12 || count % 3 != 0 || !(tolerance > 0)) return 0;  // fewest: a tetrahedron
    if (std::size_t(first) + count > mesh.indices.size()) return 0;
    // weld: vertices in the same cell of a grid of `tolerance` are one (twins on either
    // side of a cell's border are not, and the part then counts as open: only slower)
    struct CellHash {
        std::size_t operator()(const std::array<long long, 3>& c) const
        {
            std::size_t h = 1469598103934665603ull;
            for (long long v : c) h = (h ^ std::size_t(v)) * 1099511628211ull;
            return h;
        }
    };
    std::unordered_map<std::array<long long, 3>, int, CellHash> cells;
    std::vector<Vector3d> points;
    auto weld = [&](std::uint32_t index) {
        const MeshVertex& v = mesh.vertices[index];
        const Vector3d p(v.position[0], v.position[1], v.position[2]);
        const std::array<long long, 3> cell{std::llround(p.x() / tolerance), std::llround(p.y() / tolerance),
                                             std::llround(p.z() / tolerance)};
        const auto [it, added] = cells.emplace(cell, static_cast<int>(points.size()));
        if (added) points.push_back(p);
        return it->second;
    };
    std::vector<std::array<int, 3>> triangles;
    triangles.reserve(count / 3);
    for (std::uint32_t k = first; k < first + count; k += 3) {
        const std::array<int, 3> t{weld(mesh.indices[k]), weld(mesh.indices[k + 1]), weld(mesh.indices[k + 2])};
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;  // degenerate (a pole): draws nothing
        triangles.push_back(t);
    }
    if (triangles.size() < 4) return 0;
    // every directed edge once, and its reverse once
    auto key = [](int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); };
    std::unordered_map<std::uint64_t, int> edges;
    edges.reserve(3 * triangles.size());
    for (const auto& t : triangles) {
        for (int e = 0; e < 3; ++e) {
            if (++edges[key(t[e], t[(e + 1) % 3])] > 1) return 0;
        }
    }
    for (const auto& [k, n] : edges) {
        if (!edges.count(key(int(std::uint32_t(k)), int(k >> 32)))) return 0;
    }
    // connected surfaces (union-find), and the volume each encloses (signed: > 0 when
    // wound counter-clockwise seen from outside)
    std::vector<int> parent(points.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int a) {
        while (parent[a] != a) a = parent[a] = parent[parent[a]];
        return a;
    };
    for (const auto& t : triangles) {
        parent[root(t[1])] = root(t[0]);
        parent[root(t[2])] = root(t[0]);
    }
    Eigen::AlignedBox3d box;
    for (const Vector3d& p : points) box.extend(p);
    const Vector3d c = box.center();  // (about the middle: fewer digits cancel)
    std::unordered_map<int, double> volumes;
    for (const auto& t : triangles) {
        volumes[root(t[0])] += (points[t[0]] - c).dot((points[t[1]] - c).cross(points[t[2]] - c)) / 6;
    }
    const double tiny = 1e-9 * std::pow(box.diagonal().norm(), 3);
    int sign = 0;
    for (const auto& [r, volume] : volumes) {
        if (!(std::abs(volume) > tiny)) return 0;
        const int s = volume > 0 ? 1 : -1;
        if (sign != 0 && s != sign) return 0;
        sign = s;
    }
    return sign;
}

}  // namespace studio
