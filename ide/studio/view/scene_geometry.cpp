#include "ide/studio/view/scene_geometry.h"

#include "ide/i18n/diagnostic_text.h"
#include "solver/core/data.h"
#include "solver/core/state.h"
#include "solver/inertia/solid_inertia.h"
#include "solver/kinematics/kinematics.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <tuple>

namespace studio {

using Eigen::Affine3d;
using Eigen::Isometry3d;
using Eigen::Vector3d;

namespace {

// colours of the schematic mode (thesis §2.3: bodies purple, revolute green, prismatic grey)
const Vector3d kBodyPurple(0.52, 0.24, 0.78);
const Vector3d kRevoluteGreen(0.20, 0.72, 0.28);
const Vector3d kRailGrey(0.58, 0.58, 0.60);
const Vector3d kSliderGrey(0.74, 0.74, 0.76);
const Vector3d kAnchorGrey(0.32, 0.32, 0.34);
const Vector3d kPlaceholder(0.95, 0.20, 0.85);

/// The longest edge of a graphic's faces [m]: the viewport may light at the vertices
/// (on software OpenGL), and a lamp's pool of light on a large face (a mill's liner, its
/// floor) needs vertices this close to show.
constexpr double kLitEdge = 1.0;

/// A loaded mesh file, kept while the file is unchanged (reloading a model after an
/// edit does not read its meshes again).
struct MeshCacheKey {
    QString path;
    double scale = 1;
    qint64 size = 0;
    qint64 modified = 0;
    bool operator<(const MeshCacheKey& o) const
    {
        return std::tie(path, scale, size, modified) < std::tie(o.path, o.scale, o.size, o.modified);
    }
};

std::shared_ptr<const solver::MeshLoad> loadMeshCached(const QString& path, double scale)
{
    static std::map<MeshCacheKey, std::shared_ptr<const solver::MeshLoad>> cache;
    const QFileInfo info(path);
    const MeshCacheKey key{info.absoluteFilePath(), scale, info.size(),
                           info.lastModified().toMSecsSinceEpoch()};
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    auto load = std::make_shared<const solver::MeshLoad>(solver::loadTriangleMesh(path.toStdString(), scale));
    if (cache.size() >= 32) cache.clear();
    cache.emplace(key, load);
    return load;
}

int slotOf(int treeBody) { return treeBody + 1; }

/// Indices of a minimum spanning tree's edges over `points` (Prim, O(n²)).
std::vector<std::pair<int, int>> spanningTree(const std::vector<Vector3d>& points)
{
    const int n = static_cast<int>(points.size());
    std::vector<std::pair<int, int>> edges;
    if (n < 2) return edges;
    std::vector<char> in(n, 0);
    std::vector<double> best(n, std::numeric_limits<double>::infinity());
    std::vector<int> from(n, -1);
    best[0] = 0;
    for (int step = 0; step < n; ++step) {
        int u = -1;
        for (int k = 0; k < n; ++k) {
            if (!in[k] && (u < 0 || best[k] < best[u])) u = k;
        }
        in[u] = 1;
        if (from[u] >= 0) edges.emplace_back(from[u], u);
        for (int k = 0; k < n; ++k) {
            const double d = (points[k] - points[u]).norm();
            if (!in[k] && d < best[k]) {
                best[k] = d;
                from[k] = u;
            }
        }
    }
    return edges;
}

void addUnique(std::vector<Vector3d>& points, const Vector3d& p, double tolerance)
{
    for (const Vector3d& q : points) {
        if ((q - p).norm() <= tolerance) return;
    }
    points.push_back(p);
}

/// Rotation taking z onto the joint frame's axis `column` (0 = A, 1 = R) of `frame`.
Affine3d alongJointAxis(const Isometry3d& frame, int column)
{
    Affine3d t = Affine3d::Identity();
    t.translation() = frame.translation();
    const Vector3d dir = frame.linear().col(column);
    t.linear() = Eigen::Quaterniond::FromTwoVectors(Vector3d::UnitZ(), dir).toRotationMatrix();
    return t;
}

/// Draws one G statement into `m` (body frame). False when its shape could not be built.
bool addGraphic(MeshBuilder& m, const solver::GraphicSpec& g, const QString& modelDir, double placeholderSize,
                QStringList& problems)
{
    Affine3d t = Affine3d::Identity();
    t.translation() = g.position;
    t.linear() = solver::shapeRotation(g);
    m.setTransform(t);
    m.setColor(g.color);
    m.setMaxEdge(kLitEdge);
    const std::vector<double>& d = g.dims;
    auto need = [&](std::size_t n) { return d.size() >= n; };
    using solver::ShapeKind;
    switch (g.shape) {
    case ShapeKind::Box:
        if (!need(3)) return false;
        m.box(Vector3d(d[0], d[1], d[2]));
        return true;
    case ShapeKind::Cylinder:
        if (!need(2)) return false;
        m.cylinder(d[0], -0.5 * d[1], 0.5 * d[1]);
        return true;
    case ShapeKind::Tube:
        if (!need(3)) return false;
        m.tube(d[0], d[1], d[2]);
        return true;
    case ShapeKind::Sphere:
        if (!need(1)) return false;
        m.ellipsoid(d[0], d[0], d[0]);
        return true;
    case ShapeKind::Cone:
        if (!need(2)) return false;
        m.cone(d[0], d[1]);
        return true;
    case ShapeKind::Ellipsoid:
        if (!need(3)) return false;
        m.ellipsoid(d[0], d[1], d[2]);
        return true;
    case ShapeKind::Prism: {
        if (!need(7)) return false;
        return m.prism(d[0], std::vector<double>(d.begin() + 1, d.end()));
    }
    case ShapeKind::Mesh: {
        const QString file = QString::fromStdString(g.meshFile);
        const QString path = QFileInfo(file).isAbsolute() ? file : QDir(modelDir).filePath(file);
        QString why;
        if (file.isEmpty()) {
            why = QCoreApplication::translate("studio::Viewport", "no file named");
        } else if (!QFileInfo(path).isFile()) {
            why = QCoreApplication::translate("studio::Viewport", "the file was not found (looked for %1)")
                      .arg(QDir::toNativeSeparators(path));
        } else {
            const auto load = loadMeshCached(path, g.hasScale ? g.scale : 1.0);
            if (load->mesh && !load->mesh->triangles.empty()) {
                m.triangles(*load->mesh);
                return true;
            }
            why = load->mesh ? QCoreApplication::translate("studio::Viewport", "the file holds no triangles")
                             : QCoreApplication::translate("studio::Viewport", "it cannot be read: %1")
                                   .arg(i18n::text(load->errorText));
        }
        problems << QCoreApplication::translate("studio::Viewport",
                                                "Graphic %1 (body %2): mesh \"%3\" is drawn as a box: %4.")
                        .arg(g.id)
                        .arg(g.body)
                        .arg(file, why);
        m.setColor(kPlaceholder);
        m.box(Vector3d::Constant(placeholderSize));
        return true;
    }
    }
    return false;
}

}  // namespace

std::vector<Isometry3d> initialPoses(const solver::Model& model)
{
    const solver::State state = solver::makeState(model);
    solver::Data data(model);
    solver::forwardKinematics(model, state, data);
    return data.X_wb;
}

std::shared_ptr<SceneGeometry> buildSceneGeometry(const ModelBundle* bundle, const std::vector<Isometry3d>& initial)
{
    auto out = std::make_shared<SceneGeometry>();
    SceneGeometry& g = *out;
    const solver::Model* model = bundle ? bundle->model.get() : nullptr;
    const int nb = model ? model->nb : 0;
    const int slotTotal = nb + 1;
    g.nb = nb;
    g.dressed.assign(slotTotal, {});
    g.dressedParts.assign(slotTotal, {});
    g.bars.assign(slotTotal, {});
    g.schematic.assign(slotTotal, {});
    g.bounds.assign(slotTotal, {});
    g.schematicBounds.assign(slotTotal, {});
    g.jointPieces.assign(nb, {});
    auto poseOf = [&](int body) -> Isometry3d {
        return body < 0 || body >= static_cast<int>(initial.size()) ? Isometry3d::Identity()
                                                                     : initial[body];
    };

    // ---- attach points per body: joint points, actuator ends -------------------------
    std::vector<std::vector<Vector3d>> points(slotTotal);
    Eigen::AlignedBox3d pointBox;
    if (model) {
        for (int i = 0; i < nb; ++i) {
            if (model->freeSlot[i] >= 0) {
                // a free body hangs on nothing: only its own joint point, where its mark is
                if (model->freeSlot[i] == solver::kFreeJointCoordinates - 1) {
                    points[slotOf(i)].push_back(model->X_cj[i].translation());
                }
                continue;
            }
            points[slotOf(model->parent[i])].push_back(
                model->X_pj[i].translation());
            points[slotOf(i)].push_back(model->X_cj[i].translation());
            if (model->jointType[i] == solver::JointType::Actuator) {
                ActuatorLine a;
                a.joint = i;
                const bool forward = model->axisSign[i] > 0;
                a.body1 = forward ? model->parent[i] : i;
                a.body2 = forward ? i : model->parent[i];
                a.cl1 = model->cl1[i];
                a.cl2 = model->cl2[i];
                g.actuators.push_back(a);
            }
        }
        for (const solver::CutJoint& c : model->cuts) {
            points[slotOf(c.body1)].push_back(c.X_1.translation());
            points[slotOf(c.body2)].push_back(c.X_2.translation());
            if (c.type == solver::JointType::Actuator) g.actuators.push_back({-1, c.body1, c.body2, c.cl1, c.cl2});
        }
        for (const ActuatorLine& a : g.actuators) {
            points[slotOf(a.body1)].push_back(a.cl1);
            points[slotOf(a.body2)].push_back(a.cl2);
        }
        for (int s = 0; s < slotTotal; ++s) {
            for (const Vector3d& p : points[s]) pointBox.extend(poseOf(s - 1) * p);
        }
        for (int b = 0; b < nb; ++b) pointBox.extend(poseOf(b) * model->com[b]);
    }
    // the schematic's size: the joints' spread, or half the dressing's (a body
    // whose joint sits at its centre of mass has no spread)
    Eigen::AlignedBox3d dressedBox;
    if (bundle) {
        for (const solver::GraphicSpec& gr : bundle->spec().graphics) {
            const int b = gr.body == 0 ? -1 : model->bodyIndex(gr.body);
            if (gr.body != 0 && b < 0) continue;
            dressedBox.extend(poseOf(b) * gr.position);
            for (double d : gr.dims) {
                dressedBox.extend(poseOf(b) * Vector3d(gr.position + Vector3d::Constant(0.5 * d)));
                dressedBox.extend(poseOf(b) * Vector3d(gr.position - Vector3d::Constant(0.5 * d)));
            }
        }
    }
    const double pointRadius = pointBox.isEmpty() ? 0.0 : 0.5 * pointBox.diagonal().norm();
    const double dressedRadius = dressedBox.isEmpty() ? 0.0 : 0.5 * dressedBox.diagonal().norm();
    const double charLength = std::max({pointRadius, 0.5 * dressedRadius, 0.05});
    const double w = 0.04 * charLength;
    g.schematicWidth = w;
    const double tol = 1e-6 * charLength;

    // ---- dressed: the G statements, per slot ---------------------------------------
    std::vector<MeshBuilder> dressed(slotTotal);
    std::vector<std::vector<CullPart>> dressedParts(slotTotal);  // ranges within dressed[slot]
    if (bundle) {
        const QString modelDir = bundle->filePath.isEmpty() ? QDir::currentPath()
                                                            : QFileInfo(bundle->filePath).absolutePath();
        for (const solver::GraphicSpec& gr : bundle->spec().graphics) {
            int slot = 0;
            if (gr.body != 0) {
                const int b = model->bodyIndex(gr.body);
                if (b < 0) continue;
                slot = slotOf(b);
            }
            MeshBuilder& m = dressed[slot];
            CullPart part;
            part.range.first = static_cast<std::uint32_t>(m.indices.size());
            addGraphic(m, gr, modelDir, 4 * w, g.problems);
            part.range.count = static_cast<std::uint32_t>(m.indices.size()) - part.range.first;
            if (part.range.empty()) continue;
            for (std::uint32_t i = part.range.first; i < part.range.first + part.range.count; ++i) {
                const MeshVertex& v = m.vertices[m.indices[i]];
                part.box.extend(Vector3d(v.position[0], v.position[1], v.position[2]));
            }
            part.winding = closedWinding(m, part.range.first, part.range.count, 1e-5 * part.box.diagonal().norm());
            dressedParts[slot].push_back(part);
        }
    }

    // ---- schematic: bars per body ---------------------------------------------------
    std::vector<MeshBuilder> bars(slotTotal);
    for (int s = 0; s < slotTotal; ++s) {
        MeshBuilder& m = bars[s];
        std::vector<Vector3d> pts;
        for (const Vector3d& p : points[s]) addUnique(pts, p, tol);
        if (s == 0) {
            // ground: an anchor block at each point
            m.setColor(kAnchorGrey);
            for (const Vector3d& p : pts) {
                m.setTransform(Affine3d(Eigen::Translation3d(p)));
                m.box(Vector3d::Constant(1.8 * w));
            }
            m.resetTransform();
            continue;
        }
        m.setColor(kBodyPurple);
        const Vector3d com = model->com[s - 1];
        if (pts.size() == 1 && (com - pts[0]).norm() > tol) pts.push_back(com);
        if (pts.size() == 1) {
            // a joint at the centre of mass: a block there (larger than a slider's section)
            m.setTransform(Affine3d(Eigen::Translation3d(pts[0])));
            m.box(Vector3d::Constant(2.4 * w));
            m.resetTransform();
        } else {
            for (const auto& [a, b] : spanningTree(pts)) m.bar(pts[a], pts[b], w);
            // the centre of mass: a ball
            m.setTransform(Affine3d(Eigen::Translation3d(com)));
            m.ellipsoid(1.1 * w, 1.1 * w, 1.1 * w, 16, 8);
            m.resetTransform();
        }
    }

    // ---- schematic: joint marks, on the bodies that carry them ----------------------
    std::vector<MeshBuilder> marks(slotTotal);
    struct PendingPiece {
        int joint, slot;
        std::uint32_t first, count;
    };
    std::vector<PendingPiece> pending;
    auto beginPiece = [&](int slot) { return static_cast<std::uint32_t>(marks[slot].indices.size()); };
    auto endPiece = [&](int joint, int slot, std::uint32_t first) {
        const auto end = static_cast<std::uint32_t>(marks[slot].indices.size());
        if (joint >= 0 && end > first) pending.push_back({joint, slot, first, end - first});
    };
    auto revolute = [&](int joint, int slot, const Isometry3d& frame) {
        MeshBuilder& m = marks[slot];
        const std::uint32_t first = beginPiece(slot);
        m.setColor(kRevoluteGreen);
        m.setTransform(alongJointAxis(frame, 0));
        m.cylinder(w, -2 * w, 2 * w, 24);
        m.resetTransform();
        endPiece(joint, slot, first);
    };
    auto prismatic = [&](int joint, int parentSlot, const Isometry3d& parentFrame, int childSlot,
                         const Isometry3d& childFrame, double lo, double hi) {
        // the rail on the parent over the joint's travel (σθ along R), the slider on the child
        MeshBuilder& p = marks[parentSlot];
        std::uint32_t first = beginPiece(parentSlot);
        p.setColor(kRailGrey);
        p.setTransform(Affine3d(parentFrame));
        p.bar(Vector3d(0, lo - w, 0), Vector3d(0, hi + w, 0), 0.7 * w);
        p.resetTransform();
        endPiece(joint, parentSlot, first);
        MeshBuilder& c = marks[childSlot];
        first = beginPiece(childSlot);
        c.setColor(kSliderGrey);
        c.setTransform(Affine3d(childFrame));
        c.box(Vector3d(1.4 * w, 3.4 * w, 1.4 * w));
        c.resetTransform();
        endPiece(joint, childSlot, first);
    };
    auto travel = [&](double lower, double upper, double sign, double theta0, double& lo, double& hi) {
        const double reach = 0.25 * charLength;
        // an open end: a little beyond the initial place (or the other limit)
        const double a = std::isfinite(lower) ? lower
                                              : std::min(theta0, std::isfinite(upper) ? upper : theta0) - reach;
        const double b = std::isfinite(upper) ? upper
                                              : std::max(theta0, std::isfinite(lower) ? lower : theta0) + reach;
        lo = std::min(sign * a, sign * b);
        hi = std::max(sign * a, sign * b);
    };
    if (model) {
        for (int i = 0; i < nb; ++i) {
            const auto k = static_cast<std::size_t>(i);
            if (model->freeSlot[k] >= 0) {
                // a free joint: no rail, no pin; a ball at the free body's joint point
                // (highlighted as the joint: its first coordinate)
                if (model->freeSlot[k] == solver::kFreeJointCoordinates - 1) {
                    const int joint = i - model->freeSlot[k];
                    MeshBuilder& m = marks[slotOf(i)];
                    const std::uint32_t first = beginPiece(slotOf(i));
                    m.setColor(kRevoluteGreen);
                    m.setTransform(Affine3d(Eigen::Translation3d(model->X_cj[k].translation())));
                    m.ellipsoid(2 * w, 2 * w, 2 * w, 24, 12);
                    m.resetTransform();
                    endPiece(joint, slotOf(i), first);
                }
                continue;
            }
            const int ps = slotOf(model->parent[k]);
            if (model->jointType[k] == solver::JointType::Prismatic) {
                double lo = 0, hi = 0;
                travel(model->lower[k], model->upper[k], model->axisSign[k], model->theta0[k], lo, hi);
                prismatic(i, ps, model->X_pj[k], slotOf(i), model->X_cj[k], lo, hi);
            } else {
                revolute(i, slotOf(i), model->X_cj[k]);
            }
        }
        for (const solver::CutJoint& c : model->cuts) {
            if (c.type == solver::JointType::Prismatic) {
                const double reach = 0.25 * charLength;
                // the slider's place along the rail at the initial pose
                const Vector3d rel = (poseOf(c.body1) * c.X_1).inverse() * (poseOf(c.body2) * c.X_2.translation());
                prismatic(-1, slotOf(c.body1), c.X_1, slotOf(c.body2), c.X_2, std::min(0.0, rel.y()) - reach,
                          std::max(0.0, rel.y()) + reach);
            } else {
                revolute(-1, slotOf(c.body2), c.X_2);
            }
        }
    }

    // ---- one buffer: per slot dressed, then bars + marks ----------------------------
    MeshBuilder& all = g.mesh;
    auto put = [&](const MeshBuilder& part) {
        DrawRange r;
        r.first = static_cast<std::uint32_t>(all.indices.size());
        all.append(part);
        r.count = static_cast<std::uint32_t>(all.indices.size()) - r.first;
        return r;
    };
    for (int s = 0; s < slotTotal; ++s) {
        const auto k = static_cast<std::size_t>(s);
        g.dressed[k] = put(dressed[k]);
        for (CullPart part : dressedParts[k]) {
            part.range.first += g.dressed[k].first;
            g.dressedParts[k].push_back(part);
        }
        g.bars[k] = put(bars[k]);
        const DrawRange markRange = put(marks[k]);
        g.schematic[k] = {g.bars[k].first, g.bars[k].count + markRange.count};
        for (const PendingPiece& p : pending) {
            if (p.slot == s) g.jointPieces[p.joint].push_back({s - 1, {markRange.first + p.first, p.count}});
        }
        Eigen::AlignedBox3d box = bars[k].bounds();
        box.extend(marks[k].bounds());
        g.schematicBounds[k] = box;
        box.extend(dressed[k].bounds());
        g.bounds[k] = box;
    }

    // ---- shared unit shapes ---------------------------------------------------------
    {
        MeshBuilder m;
        m.setColor(Vector3d(0.85, 0.47, 0.12));
        m.cylinder(1.0, 0.0, 1.0, 16);
        g.unitCylinder = put(m);
    }
    {
        MeshBuilder m;
        m.triad(0.04);
        g.unitTriad = put(m);
    }

    // ---- grid, seat ---------------------------------------------------------------------
    g.initialBounds = worldBounds(g, initial);
    const Eigen::AlignedBox3d& box = g.initialBounds;
    const double radius = box.isEmpty() ? 1.0 : std::max(0.5 * box.diagonal().norm(), 0.05);
    g.gridZ = box.isEmpty() ? 0.0 : std::min(0.0, box.min().z());
    const double reach = box.isEmpty() ? 0.0 : std::max(box.min().head<2>().cwiseAbs().maxCoeff(),
                                                        box.max().head<2>().cwiseAbs().maxCoeff());
    g.gridExtent = std::clamp(std::ceil((reach + 2 * radius) / 10.0) * 10.0, 10.0, 200.0);
    {
        MeshBuilder m;
        const int n = static_cast<int>(g.gridExtent);
        const double e = g.gridExtent, z = g.gridZ;
        for (int major = 0; major < 2; ++major) {
            m.setColor(major ? Vector3d(0.60, 0.61, 0.64) : Vector3d(0.40, 0.41, 0.44));
            for (int k = -n; k <= n; ++k) {
                if ((k % 10 == 0) != (major == 1)) continue;
                m.line(Vector3d(k, -e, z), Vector3d(k, e, z));
                m.line(Vector3d(-e, k, z), Vector3d(e, k, z));
            }
        }
        g.grid = put(m);
    }
    // the seat: behind and above the model's base (its ground joints), looking along +y
    Vector3d base = box.isEmpty() ? Vector3d(Vector3d::Zero()) : Vector3d(box.center());
    if (!points[0].empty()) {
        base = Vector3d::Zero();
        for (const Vector3d& p : points[0]) base += p;
        base /= static_cast<double>(points[0].size());
    }
    // behind everything and above it, so that the whole machine is ahead
    const double behind = box.isEmpty() ? base.y() : std::min(box.min().y(), base.y());
    const double top = box.isEmpty() ? base.z() : std::max(box.max().z(), base.z());
    g.seatEye = Vector3d(base.x(), behind - 0.5 * radius, top + 0.4 * radius);
    const Vector3d centre = box.isEmpty() ? Vector3d(Vector3d::Zero()) : Vector3d(box.center());
    const double ahead = std::max(centre.y() - g.seatEye.y(), 0.3 * radius);
    g.seatPitch = std::clamp(std::atan2(centre.z() - g.seatEye.z(), ahead), -0.8, 0.2);
    return out;
}

std::shared_ptr<const SceneGeometry> sceneGeometry(const std::shared_ptr<const ModelBundle>& bundle)
{
    static std::map<quint64, std::weak_ptr<const SceneGeometry>> cache;
    static std::shared_ptr<const SceneGeometry> empty;
    if (!bundle || !bundle->model) {
        if (!empty) empty = buildSceneGeometry(nullptr, {});
        return empty;
    }
    auto it = cache.find(bundle->serial);
    if (it != cache.end()) {
        if (auto g = it->second.lock()) return g;
    }
    std::shared_ptr<const SceneGeometry> g = buildSceneGeometry(bundle.get(), initialPoses(*bundle->model));
    for (auto e = cache.begin(); e != cache.end();) e = e->second.expired() ? cache.erase(e) : std::next(e);
    cache[bundle->serial] = g;
    return g;
}

bool isLamp(const solver::GraphicSpec& graphic)
{
    const Vector3d& c = graphic.color;
    return graphic.hasColor && c.minCoeff() >= 0.7 && c.sum() >= 2.6;
}

std::shared_ptr<const SceneDressing> sceneDressing(const std::shared_ptr<const ModelBundle>& scene)
{
    static std::map<quint64, std::weak_ptr<const SceneDressing>> cache;
    if (!scene || !scene->compiled) return nullptr;
    auto it = cache.find(scene->serial);
    if (it != cache.end()) {
        if (auto d = it->second.lock()) return d;
    }
    auto out = std::make_shared<SceneDressing>();
    const QString dir = scene->filePath.isEmpty() ? QDir::currentPath() : QFileInfo(scene->filePath).absolutePath();
    // each graphic on its own, then drawn smallest first: small things mostly stand in
    // front of large ones (walls, floors), whose hidden parts the depth test then skips
    std::vector<std::pair<double, MeshBuilder>> solids;
    MeshBuilder lamps;
    for (const solver::GraphicSpec& g : scene->spec().graphics) {
        if (g.body != 0) {
            ++out->skippedGraphics;
            continue;
        }
        if (isLamp(g)) {
            addGraphic(lamps, g, dir, 0.2, out->problems);
            out->lights.push_back(g.position);
            continue;
        }
        MeshBuilder m;
        addGraphic(m, g, dir, 0.2, out->problems);
        const Eigen::AlignedBox3d box = m.bounds();
        solids.emplace_back(box.isEmpty() ? 0.0 : box.diagonal().norm(), std::move(m));
    }
    std::stable_sort(solids.begin(), solids.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    auto put = [&](const MeshBuilder& part) {
        DrawRange r;
        r.first = static_cast<std::uint32_t>(out->mesh.indices.size());
        out->mesh.append(part);
        r.count = static_cast<std::uint32_t>(out->mesh.indices.size()) - r.first;
        return r;
    };
    out->lamps = put(lamps);
    out->solids.first = static_cast<std::uint32_t>(out->mesh.indices.size());
    for (const auto& part : solids) {
        CullPart p;
        p.range = put(part.second);
        if (p.range.empty()) continue;
        p.box = part.second.bounds();
        p.winding = closedWinding(part.second, 0, p.range.count, 1e-5 * p.box.diagonal().norm());
        out->solidParts.push_back(p);
    }
    out->solids.count = static_cast<std::uint32_t>(out->mesh.indices.size()) - out->solids.first;
    out->bounds = out->mesh.bounds();
    for (auto e = cache.begin(); e != cache.end();) e = e->second.expired() ? cache.erase(e) : std::next(e);
    cache[scene->serial] = out;
    return out;
}

int planeSide(const MeshBuilder& mesh, const CullPart& part, const Eigen::Vector4d& plane)
{
    bool kept = false, cut = false;
    const std::uint32_t end = std::min<std::uint32_t>(part.range.first + part.range.count,
                                                      static_cast<std::uint32_t>(mesh.indices.size()));
    for (std::uint32_t i = part.range.first; i < end; ++i) {
        const float* p = mesh.vertices[mesh.indices[i]].position;
        const double s = plane.x() * p[0] + plane.y() * p[1] + plane.z() * p[2] + plane.w();
        (s >= -1e-6 ? kept : cut) = true;
        if (kept && cut) return 0;
    }
    return cut ? -1 : 1;
}

namespace {

/// The position of the vertex that index i of the mesh's index array names.
Vector3d indexedVertex(const MeshBuilder& mesh, std::uint32_t i)
{
    const float* p = mesh.vertices[mesh.indices[i]].position;
    return Vector3d(p[0], p[1], p[2]);
}

/// Where the ray (o, d) meets the triangle (a, b, c), either face (Möller–Trumbore):
/// the distance along it in units of |d|, or −1 when it misses it or runs along its plane.
double rayTriangle(const Vector3d& o, const Vector3d& d, const Vector3d& a, const Vector3d& b, const Vector3d& c)
{
    const Vector3d e1 = b - a, e2 = c - a;
    const Vector3d h = d.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-15) return -1;
    const Vector3d s = o - a;
    const double u = s.dot(h) / det;
    if (u < 0 || u > 1) return -1;
    const Vector3d q = s.cross(e1);
    const double v = d.dot(q) / det;
    if (v < 0 || u + v > 1) return -1;
    return e2.dot(q) / det;
}

}  // namespace

bool solidClearOf(const MeshBuilder& mesh, const CullPart& part, const std::array<Vector3d, 4>& quad,
                  double margin)
{
    Eigen::AlignedBox3d near;
    for (const Vector3d& q : quad) near.extend(q);
    near.min().array() -= margin;
    near.max().array() += margin;
    if (!near.intersects(part.box)) return true;
    const std::uint32_t end = std::min<std::uint32_t>(part.range.first + part.range.count,
                                                      static_cast<std::uint32_t>(mesh.indices.size()));
    auto at = [&](std::uint32_t i) { return indexedVertex(mesh, i); };
    for (std::uint32_t i = part.range.first; i + 2 < end; i += 3) {
        Eigen::AlignedBox3d t(at(i));
        t.extend(at(i + 1));
        t.extend(at(i + 2));
        if (t.intersects(near)) return false;
    }
    // none near it: the quad is all inside the solid or all outside; a ray from its
    // centre (in a direction no edge of a box or a round shape lies along) crosses the
    // surface an odd number of times from inside
    const Vector3d origin = 0.25 * (quad[0] + quad[1] + quad[2] + quad[3]);
    const Vector3d dir = Vector3d(0.5771, 0.5774, 0.5779).normalized();
    int crossings = 0;
    for (std::uint32_t i = part.range.first; i + 2 < end; i += 3) {
        if (rayTriangle(origin, dir, at(i), at(i + 1), at(i + 2)) > 0) ++crossings;
    }
    return crossings % 2 == 0;
}

namespace {

/// Distance along the ray (o, d) to where it meets the box, or +∞ (slab test).
double rayBox(const Eigen::AlignedBox3d& box, const Vector3d& o, const Vector3d& d)
{
    if (box.isEmpty()) return std::numeric_limits<double>::infinity();
    double near = 0, far = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-300) {
            if (o[a] < box.min()[a] || o[a] > box.max()[a]) return std::numeric_limits<double>::infinity();
            continue;
        }
        double t0 = (box.min()[a] - o[a]) / d[a], t1 = (box.max()[a] - o[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        near = std::max(near, t0);
        far = std::min(far, t1);
        if (near > far) return std::numeric_limits<double>::infinity();
    }
    return near;
}

/// The nearest distance along the ray (o, d) at which it meets a triangle of `range`
/// (either face), if below `best`.
void rayRange(const MeshBuilder& mesh, const DrawRange& range, const Vector3d& o, const Vector3d& d, double& best)
{
    for (std::uint32_t k = range.first; k + 2 < range.first + range.count; k += 3) {
        const double t = rayTriangle(o, d, indexedVertex(mesh, k), indexedVertex(mesh, k + 1), indexedVertex(mesh, k + 2));
        if (t > 0 && t < best) best = t;
    }
}

}  // namespace

bool pickBody(const SceneGeometry& geometry, const std::vector<Isometry3d>& X_wb, const Vector3d& origin,
              const Vector3d& direction, bool schematic, bool dressed, int& body, Vector3d& point)
{
    const SceneGeometry& g = geometry;
    if (static_cast<int>(X_wb.size()) != g.nb || !(direction.norm() > 0)) return false;
    const Vector3d d = direction.normalized();
    double best = std::numeric_limits<double>::infinity();
    int found = -1;
    for (int b = 0; b < g.nb; ++b) {
        const auto slot = static_cast<std::size_t>(b + 1);
        // the ray in the body's frame (its meshes are there); distances are kept
        const Isometry3d& X = X_wb[static_cast<std::size_t>(b)];
        const Vector3d o = X.inverse() * origin;
        const Vector3d db = X.linear().transpose() * d;
        if (rayBox(g.bounds[slot], o, db) >= best) continue;
        double t = best;
        if (dressed) rayRange(g.mesh, g.dressed[slot].empty() ? g.bars[slot] : g.dressed[slot], o, db, t);
        if (schematic) rayRange(g.mesh, g.schematic[slot], o, db, t);
        if (t < best) {
            best = t;
            found = b;
        }
    }
    if (found < 0) return false;
    body = found;
    point = origin + best * d;
    return true;
}

Eigen::AlignedBox3d worldBounds(const SceneGeometry& geometry, const std::vector<Isometry3d>& X_wb,
                                bool schematicOnly)
{
    Eigen::AlignedBox3d out;
    auto pose = [&](int body) -> Isometry3d {
        return body < 0 || body >= static_cast<int>(X_wb.size()) ? Isometry3d::Identity()
                                                                 : X_wb[body];
    };
    for (int s = 0; s < geometry.slotCount(); ++s) {
        const Eigen::AlignedBox3d& b = (schematicOnly ? geometry.schematicBounds : geometry.bounds)[s];
        if (b.isEmpty()) continue;
        const Isometry3d X = pose(s - 1);
        for (int c = 0; c < 8; ++c) out.extend(X * b.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
    }
    for (const ActuatorLine& a : geometry.actuators) {
        out.extend(pose(a.body1) * a.cl1);
        out.extend(pose(a.body2) * a.cl2);
    }
    return out;
}

}  // namespace studio
