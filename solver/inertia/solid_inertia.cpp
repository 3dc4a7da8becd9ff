#include "solver/inertia/solid_inertia.h"

#include "solver/inertia/triangle_mesh.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <numbers>

namespace solver {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

/// ∫ r rᵀ dV about the centroid of a solid with principal second moments (∫x², ∫y², ∫z²).
ShapeVolume centred(double volume, const Vector3d& second)
{
    ShapeVolume s;
    s.volume = volume;
    s.second = second.asDiagonal();
    return s;
}

/// From integrals about the shape origin: volume, first moments ∫r dV, second moments ∫r rᵀ dV.
ShapeVolume fromOriginIntegrals(double volume, const Vector3d& first, const Matrix3d& secondAtOrigin)
{
    ShapeVolume s;
    s.volume = volume;
    s.centroid = first / volume;
    s.second = secondAtOrigin - volume * s.centroid * s.centroid.transpose();
    return s;
}

/// PRISM H x1 y1 …: the outline's area integrals by Green's theorem (either winding), extruded
/// over z ∈ [0, H]. Source: e.g. Steger, "On the calculation of arbitrary moments of polygons", 1996.
ShapeVolume prismVolume(const std::vector<double>& dims)
{
    const double h = dims[0];
    const std::size_t n = (dims.size() - 1) / 2;
    double a = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double x0 = dims[1 + 2 * k], y0 = dims[2 + 2 * k];
        const double x1 = dims[1 + 2 * ((k + 1) % n)], y1 = dims[2 + 2 * ((k + 1) % n)];
        const double c = x0 * y1 - x1 * y0;
        a += c;
        sx += (x0 + x1) * c;
        sy += (y0 + y1) * c;
        sxx += (x0 * x0 + x0 * x1 + x1 * x1) * c;
        syy += (y0 * y0 + y0 * y1 + y1 * y1) * c;
        sxy += (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * c;
    }
    a /= 2, sx /= 6, sy /= 6, sxx /= 12, syy /= 12, sxy /= 24;
    if (a < 0) a = -a, sx = -sx, sy = -sy, sxx = -sxx, syy = -syy, sxy = -sxy;  // clockwise outline
    // extrusion: ∫f(x,y) dV = H ∫f dA; ∫z dV = A H²/2; ∫z² dV = A H³/3; ∫x z dV = H²/2 ∫x dA
    Matrix3d s;
    s << h * sxx, h * sxy, sx * h * h / 2,
         h * sxy, h * syy, sy * h * h / 2,
         sx * h * h / 2, sy * h * h / 2, a * h * h * h / 3;
    return fromOriginIntegrals(a * h, Vector3d(h * sx, h * sy, a * h * h / 2), s);
}

ShapeVolume meshVolume(const GraphicSpec& g, const std::string& modelDir, Diagnostics& diags)
{
    const Text who = trText("Diagnostics", "graphic %1").with(std::to_string(g.id));
    const SourcePos at = g.src.where("dims");
    const std::filesystem::path path = std::filesystem::path(modelDir) / g.meshFile;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        diags.error("mesh-not-found", at,
                    trText("Diagnostics", "%1: mesh file '%2' not found (looked for %3)")
                        .with(who)
                        .with(g.meshFile)
                        .with(path.string()),
                    trText("Diagnostics", "mesh paths are relative to the model file's folder"));
        return {};
    }
    MeshLoad load = loadTriangleMesh(path.string(), g.hasScale ? g.scale : 1.0);
    if (!load.mesh) {
        diags.error("mesh-unreadable", at,
                    trText("Diagnostics", "%1: mesh file '%2' cannot be read: %3")
                        .with(who)
                        .with(g.meshFile)
                        .with(load.errorText),
                    trText("Diagnostics", "export the mesh again (STL, OBJ, PLY, …) or check that the file is not damaged"));
        return {};
    }
    const TriangleMesh& mesh = *load.mesh;
    if (const int open = openEdgeCount(mesh); open > 0) {
        diags.error("mesh-not-closed", at,
                    trText("Diagnostics", "%1: the mesh is not closed: %2 open edges")
                        .with(who)
                        .with(std::to_string(open)),
                    trText("Diagnostics", "a solid's surface must be watertight (every edge joins two triangles); close "
                                          "its holes in a mesh editor"));
        return {};
    }
    if (const int bad = misorientedEdgeCount(mesh); bad > 0) {
        diags.error("mesh-not-oriented", at,
                    trText("Diagnostics", "%1: the mesh's faces are not consistently oriented: %2 edges")
                        .with(who)
                        .with(std::to_string(bad)),
                    trText("Diagnostics", "recalculate the normals in a mesh editor so they all point outwards"));
        return {};
    }
    std::array<double, 10> in = meshVolumeIntegrals(mesh);
    // a bounding-box scale for "zero" volume
    Vector3d lo = mesh.vertices[0], hi = mesh.vertices[0];
    for (const Vector3d& v : mesh.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const double extent = (hi - lo).maxCoeff();
    if (!(std::abs(in[0]) > 1e-12 * extent * extent * extent) || !std::isfinite(in[0])) {
        diags.error("mesh-no-volume", at, trText("Diagnostics", "%1: the mesh encloses no volume").with(who),
                    trText("Diagnostics", "a solid needs a closed surface around a volume"));
        return {};
    }
    if (in[0] < 0) {
        diags.warning("mesh-inverted", at,
                      trText("Diagnostics", "%1: the mesh's normals point inwards (negative volume); its absolute value is used")
                          .with(who),
                      trText("Diagnostics", "flip the normals in a mesh editor"));
        for (double& v : in) v = -v;
    }
    Matrix3d s;
    s << in[4], in[7], in[9],
         in[7], in[5], in[8],
         in[9], in[8], in[6];
    return fromOriginIntegrals(in[0], Vector3d(in[1], in[2], in[3]), s);
}

}  // namespace

ShapeVolume shapeVolume(const GraphicSpec& g, const std::string& modelDir, Diagnostics& diags)
{
    const auto& d = g.dims;
    const double pi = std::numbers::pi;
    switch (g.shape) {
    case ShapeKind::Box: {
        // ∫x² dV = V X²/12
        const double v = d[0] * d[1] * d[2];
        return centred(v, v / 12 * Vector3d(d[0] * d[0], d[1] * d[1], d[2] * d[2]));
    }
    case ShapeKind::Cylinder: {
        // ∫x² dV = V R²/4, ∫z² dV = V L²/12
        const double v = pi * d[0] * d[0] * d[1];
        return centred(v, v * Vector3d(d[0] * d[0] / 4, d[0] * d[0] / 4, d[1] * d[1] / 12));
    }
    case ShapeKind::Tube: {
        // ∫x² dV = V (RO² + RI²)/4
        const double v = pi * (d[0] * d[0] - d[1] * d[1]) * d[2];
        const double r2 = (d[0] * d[0] + d[1] * d[1]) / 4;
        return centred(v, v * Vector3d(r2, r2, d[2] * d[2] / 12));
    }
    case ShapeKind::Sphere: {
        // ∫x² dV = V R²/5
        const double v = 4.0 / 3.0 * pi * d[0] * d[0] * d[0];
        return centred(v, v * Vector3d::Constant(d[0] * d[0] / 5));
    }
    case ShapeKind::Ellipsoid: {
        // ∫x² dV = V A²/5
        const double v = 4.0 / 3.0 * pi * d[0] * d[1] * d[2];
        return centred(v, v / 5 * Vector3d(d[0] * d[0], d[1] * d[1], d[2] * d[2]));
    }
    case ShapeKind::Cone: {
        // base at z = 0, apex at z = L: centroid L/4; about it ∫x² dV = 3/20 V R², ∫z² dV = 3/80 V L²
        const double v = pi * d[0] * d[0] * d[1] / 3;
        ShapeVolume s = centred(v, v * Vector3d(3.0 / 20 * d[0] * d[0], 3.0 / 20 * d[0] * d[0], 3.0 / 80 * d[1] * d[1]));
        s.centroid = Vector3d(0, 0, d[1] / 4);
        return s;
    }
    case ShapeKind::Prism:
        return prismVolume(d);
    case ShapeKind::Mesh:
        return meshVolume(g, modelDir, diags);
    }
    return {};
}

Eigen::Matrix3d shapeRotation(const GraphicSpec& g)
{
    Matrix3d rAxis = Matrix3d::Identity();
    if (g.hasAxis && g.axis.norm() > 1e-12) {
        const Vector3d a = g.axis.normalized();
        if (a.z() < -1 + 1e-12) rAxis = Vector3d(1, -1, -1).asDiagonal();  // AXIS = −z: a half turn about x
        else rAxis = Eigen::Quaterniond::FromTwoVectors(Vector3d::UnitZ(), a).toRotationMatrix();
    }
    Matrix3d rRot = Matrix3d::Identity();
    if (g.hasRot && g.rotAxis.norm() > 1e-12) {
        rRot = Eigen::AngleAxisd(g.rotDeg * std::numbers::pi / 180, g.rotAxis.normalized()).toRotationMatrix();
    }
    return rRot * rAxis;
}

MassProperties solidMassProperties(const GraphicSpec& g, const std::string& modelDir, Diagnostics& diags)
{
    if (!g.mass && !g.rho) return {};
    const Text who = trText("Diagnostics", "graphic %1").with(std::to_string(g.id));
    if (g.mass && *g.mass < 0) {
        diags.error("negative-mass", g.src.where("MASS"), trText("Diagnostics", "%1: MASS is negative").with(who),
                    trText("Diagnostics", "a mass is ≥ 0, in kg"));
        return {};
    }
    if (g.rho && !(*g.rho > 0)) {
        diags.error("not-positive", g.src.where("RHO"), trText("Diagnostics", "%1: RHO must be positive").with(who),
                    trText("Diagnostics", "a density in kg/m³ (steel: 7850)"));
        return {};
    }
    const ShapeVolume sv = shapeVolume(g, modelDir, diags);
    if (!(sv.volume > 0)) return {};
    const double rho = g.rho ? *g.rho : *g.mass / sv.volume;
    const Matrix3d r = shapeRotation(g);
    MassProperties p;
    p.mass = rho * sv.volume;
    p.com = g.position + r * sv.centroid;
    // I = tr(S) E − S for S = ∫ r rᵀ dm about the centre of mass; then turned into body axes
    const Matrix3d s = rho * sv.second;
    p.inertia = r * (s.trace() * Matrix3d::Identity() - s) * r.transpose();
    return p;
}

MassProperties combine(const std::vector<MassProperties>& parts)
{
    MassProperties total;
    Vector3d moment = Vector3d::Zero();
    for (const MassProperties& p : parts) {
        total.mass += p.mass;
        moment += p.mass * p.com;
    }
    if (!(total.mass > 0)) return {};
    total.com = moment / total.mass;
    for (const MassProperties& p : parts) {
        // parallel-axis theorem: I_G + m (|d|² E − d dᵀ), d from the common centre of mass
        const Vector3d d = p.com - total.com;
        total.inertia += p.inertia + p.mass * (d.squaredNorm() * Matrix3d::Identity() - d * d.transpose());
    }
    total.inertia = (total.inertia + total.inertia.transpose()) / 2;
    return total;
}

std::optional<MassProperties> bodyMassProperties(const ModelSpec& spec, int bodyId, Diagnostics& diags)
{
    const std::string modelDir = std::filesystem::path(spec.file).parent_path().string();
    const std::size_t errorsBefore = diags.errorCount();
    std::vector<MassProperties> parts;
    for (const GraphicSpec& g : spec.graphics) {
        if (g.body != bodyId || (!g.mass && !g.rho)) continue;
        parts.push_back(solidMassProperties(g, modelDir, diags));
    }
    if (parts.empty() || diags.errorCount() > errorsBefore) return std::nullopt;
    return combine(parts);
}

PrincipalAxes principalAxes(const Eigen::Matrix3d& inertia)
{
    Eigen::SelfAdjointEigenSolver<Matrix3d> es(inertia);
    PrincipalAxes p;
    p.moments = es.eigenvalues();
    p.axes = es.eigenvectors();
    if (p.axes.determinant() < 0) p.axes.col(2) = -p.axes.col(2);
    return p;
}

}  // namespace solver
