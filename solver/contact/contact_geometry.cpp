#include "solver/contact/contact_geometry.h"

#include "solver/contact/contact_forces.h"
#include "solver/contact/shapes.h"
#include "solver/core/data.h"
#include "solver/core/state.h"
#include "solver/kinematics/kinematics.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace solver {

bool ContactGeometry::isExcluded(int a, int b) const
{
    const std::pair<int, int> key(std::min(a, b), std::max(a, b));
    return std::binary_search(excluded.begin(), excluded.end(), key);
}

bool clearOfTube(const ContactShape& t, const Eigen::Vector3d& c, double r)
{
    const Eigen::Vector3d p = t.tubeInverse * c;
    const double radial = std::hypot(p.x(), p.y());
    return radial + r < t.tubeInner || radial - r > t.tubeOuter || std::abs(p.z()) - r > t.tubeHalfLength;
}

std::vector<std::pair<int, int>> contactExcludedBodies(const CompiledContact& contact)
{
    std::vector<std::pair<int, int>> out;
    if (!contact.geometry) return out;
    const ContactGeometry& g = *contact.geometry;
    for (const auto& [a, b] : g.excluded) {
        const int ba = g.shapes[a].body, bb = g.shapes[b].body;
        out.emplace_back(std::min(ba, bb), std::max(ba, bb));
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

namespace {

/// The exit speed per unit entry speed of the unit oscillator x'' = −F, F = max(0, x +
/// clamp(2ζx', ±β·x)) (contact_forces.h: the damper held within β times the spring, the
/// force ≥ 0). The law is homogeneous in (x, x'): e does not depend on the speed.
double clampedRestitution(double zeta)
{
    double x = 0, v = 1;  // penetration and its rate
    const double h = 1e-4;
    auto force = [zeta](double x_, double v_) {
        return std::max(0.0, x_ + std::clamp(2 * zeta * v_, -kDamperCap * x_, kDamperCap * x_));
    };
    for (int i = 0; i < 200000; ++i) {
        // RK4 on (x, v)
        const double k1x = v, k1v = -force(x, v);
        const double k2x = v + 0.5 * h * k1v, k2v = -force(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        const double k3x = v + 0.5 * h * k2v, k3v = -force(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        const double k4x = v + h * k3v, k4v = -force(x + h * k3x, v + h * k3v);
        x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        if (x <= 0 || force(x, v) <= 0) return std::max(0.0, -v);
    }
    return 0;
}

/// A depth [m] in millimetres, to 0.1 mm.
std::string millimetres(double d)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", d * 1000);
    return buf;
}

/// Whether two bodies (tree indices, −1: the ground and the scene) are joined to each
/// other: one is the other's parent through a joint (a pin in its bore, a turret on its
/// base plate), or a loop's closing joint joins them. A free joint (T 3) joins nothing:
/// a free body placed inside what should carry it is a mistake.
bool joined(const Model& model, int a, int b)
{
    auto jointParent = [&model](int body) {
        if (body < 0 || model.freeSlot[body] == 5) return -2;  // the ground, a free body: no parent
        return model.parent[body];
    };
    if (a == b) return true;
    if (jointParent(a) == b || jointParent(b) == a) return true;
    for (const CutJoint& c : model.cuts)
        if ((c.body1 == a && c.body2 == b) || (c.body1 == b && c.body2 == a)) return true;
    return false;
}

}  // namespace

double dampingRatioFor(double e)
{
    const double target = std::max(e, kLeastRestitution);
    double lo = 0, hi = kMostDamping;  // e falls as ζ grows
    if (clampedRestitution(hi) >= target) return hi;
    for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (clampedRestitution(mid) > target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

std::shared_ptr<const CompiledContact> compileContact(const ModelSpec& spec, const ModelSpec* scene,
                                                      const Model& model, Diagnostics& diags)
{
    if (!spec.contact) return nullptr;
    auto geometry = std::make_shared<ContactGeometry>();
    bool ok = true;
    std::vector<SourcePos> where;  // per shape: its G statement
    auto add = [&](const GraphicSpec& g, const ModelSpec& from, bool isScene) {
        if (g.noContact) return;
        const std::optional<int> on = graphicBody(g, model, isScene);
        if (!on) return;
        const int body = *on;
        GraphicShape shape = graphicShape(g, from);
        if (!shape.geometry) {
            ok = false;
            diags.error("contact-shape", g.src.pos,
                        trText("Diagnostics", "G %1 cannot serve as a contact shape: %2")
                            .with(std::to_string(g.id))
                            .with(shape.error),
                        trText("Diagnostics", "fix the mesh file, or mark the graphic NOCONTACT (drawn only)"));
            return;
        }
        const int index = static_cast<int>(geometry->shapes.size());
        ContactShape cs{std::move(shape.geometry), shape.local, body, g.id, isScene};
        if (g.shape == ShapeKind::Tube && body < 0) {
            cs.tube = true;
            cs.tubeInverse = shape.local.inverse();
            cs.tubeOuter = g.dims[0];
            cs.tubeInner = g.dims[1] * std::cos(std::numbers::pi / kTubeSegments);
            cs.tubeHalfLength = g.dims[2] / 2;
        }
        geometry->shapes.push_back(std::move(cs));
        where.push_back(isScene ? SourcePos{} : g.src.pos);
        (body >= 0 ? geometry->moving : geometry->still).push_back(index);
    };
    for (const GraphicSpec& g : spec.graphics) add(g, spec, false);
    if (scene)
        for (const GraphicSpec& g : scene->graphics) add(g, *scene, true);
    if (!ok) return nullptr;

    // the mass each body's contacts move: its own and its descendants'
    geometry->mass.assign(static_cast<std::size_t>(model.nb), 0.0);
    for (int i = model.nb - 1; i >= 0; --i) {
        geometry->mass[i] += model.mass[i];
        if (model.parent[i] >= 0) geometry->mass[model.parent[i]] += geometry->mass[i];
    }
    for (double& m : geometry->mass) m = std::max(m, 1e-3);

    // the pairs already overlapping at the initial pose never touch each other
    {
        const State state = makeState(model);
        Data data(model);
        forwardKinematics(model, state, data);
        std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
        for (const ContactShape& s : geometry->shapes) {
            const Eigen::Isometry3d pose = s.body >= 0 ? data.X_wb[s.body] * s.local : s.local;
            objects.push_back(std::make_unique<fcl::CollisionObjectd>(s.geometry, pose));
            objects.back()->computeAABB();
        }
        fcl::CollisionRequestd request(64, true);
        for (int a : geometry->moving) {
            for (std::size_t b = 0; b < geometry->shapes.size(); ++b) {
                const int ib = static_cast<int>(b);
                if (ib == a || geometry->shapes[b].body == geometry->shapes[a].body) continue;
                if (geometry->shapes[b].body >= 0 && ib < a) continue;  // moving pairs once
                if (!objects[a]->getAABB().overlap(objects[b]->getAABB())) continue;
                fcl::CollisionResultd result;
                fcl::collide(objects[a].get(), objects[b].get(), request, result);
                double depth = 0;
                for (std::size_t k = 0; k < result.numContacts(); ++k)
                    depth = std::max(depth, result.getContact(k).penetration_depth);
                if (depth <= kInitialOverlap) continue;
                geometry->excluded.emplace_back(std::min(a, ib), std::max(a, ib));
                const ContactShape& sa = geometry->shapes[a];
                const ContactShape& sb = geometry->shapes[b];
                const Text what =
                    trText("Diagnostics", "G %1 and %2 overlap by %3 mm at the initial pose: they never touch "
                                          "each other")
                        .with(std::to_string(sa.graphicId))
                        .with((sb.scene ? trText("Diagnostics", "scene G %1") : trText("Diagnostics", "G %1"))
                                  .with(std::to_string(sb.graphicId)))
                        .with(millimetres(depth));
                // two solids joined by a joint are meant to (a pin in its bore); others
                // were placed inside each other by mistake
                if (joined(model, sa.body, sb.body)) {
                    diags.add(Severity::Note, "contact-overlap", where[a], what,
                              trText("Diagnostics", "a pin in its bore is meant to; solids placed inside each other "
                                                    "by mistake: move one out"));
                } else {
                    diags.add(Severity::Warning, "contact-deep-overlap", where[a], what,
                              trText("Diagnostics", "these solids are not joined to each other: they start inside "
                                                    "each other and will pass through each other; move one out (or "
                                                    "mark one NOCONTACT if it is only drawn)"));
                }
            }
        }
        std::sort(geometry->excluded.begin(), geometry->excluded.end());
    }

    auto contact = std::make_shared<CompiledContact>();
    contact->mu = spec.contact->mu.value_or(kDefaultContactFriction);
    contact->restitution = spec.contact->e.value_or(0.0);
    contact->dampingRatio = dampingRatioFor(contact->restitution);
    contact->geometry = std::move(geometry);
    contact->makeScratch = &makeContactScratch;
    return contact;
}

}  // namespace solver
