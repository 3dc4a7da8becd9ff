#include "solver/inertia/triangle_mesh.h"

#include <Eigen/Geometry>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <filesystem>
#include <map>
#include <utility>

namespace solver {

namespace {

/// Lexicographic order of points, for merging identical vertices.
struct PointLess {
    bool operator()(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const
    {
        if (a.x() != b.x()) return a.x() < b.x();
        if (a.y() != b.y()) return a.y() < b.y();
        return a.z() < b.z();
    }
};

void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, double scale,
             std::map<Eigen::Vector3d, int, PointLess>& index, TriangleMesh& out)
{
    const aiMatrix4x4 toScene = parent * node.mTransformation;
    for (unsigned k = 0; k < node.mNumMeshes; ++k) {
        const aiMesh& m = *scene.mMeshes[node.mMeshes[k]];
        std::vector<int> ids(m.mNumVertices);
        for (unsigned v = 0; v < m.mNumVertices; ++v) {
            const aiVector3D p = toScene * m.mVertices[v];
            const Eigen::Vector3d q = scale * Eigen::Vector3d(p.x, p.y, p.z);
            auto [it, added] = index.emplace(q, static_cast<int>(out.vertices.size()));
            if (added) out.vertices.push_back(q);
            ids[v] = it->second;
        }
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines enclose no volume
            const std::array<int, 3> t{ids[face.mIndices[0]], ids[face.mIndices[1]], ids[face.mIndices[2]]};
            if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;  // degenerate after merging
            out.triangles.push_back(t);
        }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) collect(scene, *node.mChildren[c], toScene, scale, index, out);
}

/// Directed edge counts: (a, b) → how many triangles run from a to b.
std::map<std::pair<int, int>, int> directedEdges(const TriangleMesh& mesh)
{
    std::map<std::pair<int, int>, int> e;
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) ++e[{t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]}];
    }
    return e;
}

/// Eberly's subexpressions for one coordinate of a triangle's vertices.
void subexpressions(double w0, double w1, double w2, double& f1, double& f2, double& f3, double& g0, double& g1,
                    double& g2)
{
    const double temp0 = w0 + w1;
    f1 = temp0 + w2;
    const double temp1 = w0 * w0;
    const double temp2 = temp1 + w1 * temp0;
    f2 = temp2 + w2 * f1;
    f3 = w0 * temp1 + w1 * temp2 + w2 * f2;
    g0 = f2 + w0 * (f1 + w0);
    g1 = f2 + w1 * (f1 + w1);
    g2 = f2 + w2 * (f1 + w2);
}

}  // namespace

MeshLoad loadTriangleMesh(const std::string& path, double scale)
{
    MeshLoad r;
    auto fail = [&r](Text why) {
        r.error = why.english();
        r.errorText = std::move(why);
        return r;
    };
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return fail(trText("Diagnostics", "no such file"));
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(
        path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_ValidateDataStructure);
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode) {
        const std::string why = importer.GetErrorString();
        return fail(why.empty() ? trText("Diagnostics", "the file holds no scene") : plainText(why));
    }
    TriangleMesh mesh;
    std::map<Eigen::Vector3d, int, PointLess> index;
    collect(*scene, *scene->mRootNode, aiMatrix4x4(), scale, index, mesh);
    if (mesh.triangles.empty()) return fail(trText("Diagnostics", "the file holds no triangles"));
    r.mesh = std::move(mesh);
    return r;
}

int openEdgeCount(const TriangleMesh& mesh)
{
    const auto directed = directedEdges(mesh);
    std::map<std::pair<int, int>, int> undirected;
    for (const auto& [e, n] : directed) undirected[{std::min(e.first, e.second), std::max(e.first, e.second)}] += n;
    int open = 0;
    for (const auto& [e, n] : undirected) open += (n == 1);
    return open;
}

int misorientedEdgeCount(const TriangleMesh& mesh)
{
    int bad = 0;
    for (const auto& [e, n] : directedEdges(mesh)) bad += (n > 1);
    return bad;
}

std::array<double, 10> meshVolumeIntegrals(const TriangleMesh& mesh)
{
    std::array<double, 10> in{};
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d& p0 = mesh.vertices[static_cast<std::size_t>(t[0])];
        const Eigen::Vector3d& p1 = mesh.vertices[static_cast<std::size_t>(t[1])];
        const Eigen::Vector3d& p2 = mesh.vertices[static_cast<std::size_t>(t[2])];
        // edge vectors and the (unnormalised) face normal d = e1 × e2
        const Eigen::Vector3d d = (p1 - p0).cross(p2 - p0);
        double f1x, f2x, f3x, g0x, g1x, g2x, f1y, f2y, f3y, g0y, g1y, g2y, f1z, f2z, f3z, g0z, g1z, g2z;
        subexpressions(p0.x(), p1.x(), p2.x(), f1x, f2x, f3x, g0x, g1x, g2x);
        subexpressions(p0.y(), p1.y(), p2.y(), f1y, f2y, f3y, g0y, g1y, g2y);
        subexpressions(p0.z(), p1.z(), p2.z(), f1z, f2z, f3z, g0z, g1z, g2z);
        in[0] += d.x() * f1x;
        in[1] += d.x() * f2x;
        in[2] += d.y() * f2y;
        in[3] += d.z() * f2z;
        in[4] += d.x() * f3x;
        in[5] += d.y() * f3y;
        in[6] += d.z() * f3z;
        in[7] += d.x() * (p0.y() * g0x + p1.y() * g1x + p2.y() * g2x);
        in[8] += d.y() * (p0.z() * g0y + p1.z() * g1y + p2.z() * g2y);
        in[9] += d.z() * (p0.x() * g0z + p1.x() * g1z + p2.x() * g2z);
    }
    in[0] /= 6;
    for (int k = 1; k <= 3; ++k) in[static_cast<std::size_t>(k)] /= 24;
    for (int k = 4; k <= 6; ++k) in[static_cast<std::size_t>(k)] /= 60;
    for (int k = 7; k <= 9; ++k) in[static_cast<std::size_t>(k)] /= 120;
    return in;
}

}  // namespace solver
