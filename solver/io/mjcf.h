#pragma once
// MJCF export: a compiled tree Model as MuJoCo's XML model format (MJCF), for MuJoCo
// users and for `padrob bench`'s side-by-side run (ide/cli/mujoco_bench.h). The
// solver knows nothing of MuJoCo: this writes text only.
//
// What is written (docs/cli.md, "padrob export"):
//  - one nested <body> per body, in depth-first tree order, posed as at θ = 0 for
//    every joint: pos/quat = X_pj · X_jc, the child's body frame in its parent's
//    (the world for a root body). Each body's <joint> sits at the joint frame's
//    origin in the body frame (X_cj's translation): a hinge about σ·A for T 0 and
//    T 1, a slide along σ·R for T 2 (σ = axisSign, as in X_pc(θ) = X_pj·J(σθ)·X_jc).
//    So MuJoCo's qpos of each joint IS Padrob's θ (rad for hinges, T 1 included —
//    not the actuator length —, m for slides), qvel is θ̇, and qpos0 = 0 (ref 0);
//  - <inertial pos=com mass fullinertia="Ixx Iyy Izz Ixy Ixz Iyz"> (about the
//    centre of mass, body axes, tensor elements; MuJoCo's order of the six);
//  - <option timestep gravity integrator="RK4">, <flag contact="disable"/> (without
//    CONTACT), <compiler angle="radian" inertiafromgeom="false"/>;
//  - with CONTACT and MjcfOptions::spec: a <geom> per graphic (BOX, SPHERE,
//    ELLIPSOID, CYL as MuJoCo's primitives; CONE, PRISM and MESH as <mesh> vertices,
//    which MuJoCo collides as their convex hull; TUBE as a ring of boxes,
//    mjcfTubeSegments), NOCONTACT graphics as visual geoms (contype = conaffinity =
//    0), the scene's ground graphics as world geoms, the contact settings of
//    mjcfContact in <default>, and an <exclude> per body pair with solids
//    overlapping at the initial pose (Padrob excludes the two solids, MuJoCo the
//    two bodies);
//  - joint limits as range + limited="true" when both are finite (informative: the
//    hard stops, restitution and limit impulses of Padrob are not MuJoCo's soft
//    limits); a one-sided limit is only noted in a comment (MJCF ranges have two
//    ends); T 1 ranges are angles θ, converted from the stroke LL…UL;
//  - <keyframe><key name="initial" qpos=θ0 qvel=θ̇0>: the model's initial state;
//  - names from bodyName/jointName (see mjcfNames), a header comment saying what is
//    and is not exported (drives, relief valves, limit impulses, applied forces,
//    graphics: MuJoCo gets a passive model), and a comment per body with its ids.
//
// Placeholders: MuJoCo's compiler (2.2) refuses a moving body whose mass or any
// principal moment of inertia is ≤ 1e-15 ("mass and inertia of moving bodies must
// be larger than mjMINVAL") and principal moments breaking I1 + I2 ≥ I3 ("inertia
// must satisfy A + B >= C"). Padrob allows both (massless bodies such as Appendix
// A's turret, and the thesis's inertias that break the triangle inequality, a
// warning). Such a body is written with the nearest values MuJoCo accepts and an
// XML comment at the body giving the true ones (mjcfInertial):
//  - mass below kMjcfMinMass → kMjcfMinMass;
//  - principal moments breaking I1 + I2 ≥ I3 (beyond 1e-12 relative: MuJoCo
//    re-derives them from fullinertia) → moved to the nearest tensor that keeps it,
//    I1 + δ/3, I2 + δ/3, I3 − δ/3 with δ = I3 − I1 − I2 (the orthogonal projection
//    onto I1 + I2 = I3, which changes each moment least);
//  - principal moments below kMjcfMinInertia → kMjcfMinInertia;
// written as diaginertia (and quat, the principal axes, unless the true tensor is
// diagonal in body axes) so that MuJoCo reads them exactly. runMujoco puts the true
// values into the loaded mjModel.
//
// Loops (Model::cuts non-empty) cannot be exported: MuJoCo would need equality
// constraints for the cut joints, which this export does not write.

#include "solver/core/model.h"
#include "solver/spec/model_spec.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace solver {

/// Placeholder mass of a body MuJoCo would refuse as massless [kg].
inline constexpr double kMjcfMinMass = 1e-9;
/// Placeholder (smallest) principal moment of inertia [kg m^2].
inline constexpr double kMjcfMinInertia = 1e-12;

struct MjcfOptions {
    double timestep = 1e-3;  ///< <option timestep> [s] (> 0)
    bool limits = true;      ///< write joint ranges (limited="true") for two-sided limits
    std::string source;      ///< the model file, named in the header comment ("" = not named)
    /// The model's spec (its graphics), for the geoms: used only when the model has
    /// CONTACT (Model::contact); without either, no geoms and contacts off, as before.
    const ModelSpec* spec = nullptr;
    /// A scene (`--scene`) whose ground graphics become world geoms (with `spec`; the
    /// model compiled with it, so that its initial overlaps are known). May be null.
    const ModelSpec* scene = nullptr;
};

/// The contact settings the export writes for a model with CONTACT (docs/contact.md,
/// "MuJoCo"): per geom friction "μ 0.005 0.0001" (condim 3: sliding only, as Padrob),
/// solref "τ ζ" with MuJoCo's natural frequency 1/(τζ) equal to Padrob's ω (so τ =
/// 1/(ω ζ), at least 2 dt: MuJoCo's own floor), ζ = 1 for e = 0, else the linear
/// spring–damper's ζ of restitution e; solimp kMjcfSolimp; the friction cone elliptic
/// (Padrob's is circular); parent–child contacts not filtered (Padrob's are not).
struct MjcfContact {
    double mu = 0.5;
    double timeconst = 0;  ///< [s]
    double dampratio = 1;
};
MjcfContact mjcfContact(const CompiledContact& law, double timestep);
inline constexpr const char* kMjcfSolimp = "0.95 0.99 0.001";
/// Boxes in the ring that stands for a TUBE (its wall seen from inside or out).
int mjcfTubeSegments(double outerRadius);

/// The MJCF names of the bodies and joints, by tree index (dim nb each): the
/// modeler's NAME with every character other than ASCII letters, digits, '_', '-'
/// and '.' turned into '_' (Latin-1 letters lose their accents: "MUÑECA" → "MUNECA";
/// runs of '_' collapse, leading and trailing ones go), or "body<id>" / "joint<id>"
/// when empty; a name already taken gets "_<id>" appended. Unique among the bodies
/// (with "world" taken) and among the joints.
struct MjcfNames {
    std::vector<std::string> body, joint;
};
MjcfNames mjcfNames(const Model& model);

/// A body's mass properties as MuJoCo needs them: the true ones, their principal
/// decomposition, and what the export writes instead when MuJoCo would refuse them.
struct MjcfInertial {
    double mass = 0;                                 ///< true mass [kg]
    Eigen::Vector3d com = Eigen::Vector3d::Zero();   ///< centre of mass, body frame [m]
    /// True principal moments [kg m^2] about the axes of `principalAxes`; in body
    /// axes (x, y, z order, identity rotation) when the tensor is diagonal there.
    Eigen::Vector3d principal = Eigen::Vector3d::Zero();
    Eigen::Quaterniond principalAxes = Eigen::Quaterniond::Identity();  ///< body frame ← principal axes
    bool diagonal = true;  ///< the true tensor is diagonal in body axes

    bool placeholderMass = false;     ///< the written mass is kMjcfMinMass
    bool placeholderInertia = false;  ///< the written moments differ from `principal`
    double writtenMass = 0;                                   ///< [kg]
    Eigen::Vector3d writtenPrincipal = Eigen::Vector3d::Zero();  ///< about `principalAxes` [kg m^2]

    bool placeholder() const { return placeholderMass || placeholderInertia; }
};
/// Mass properties of body i (tree index) and their placeholders (header).
MjcfInertial mjcfInertial(const Model& model, int body);

/// The MJCF text of a tree model (see the header). Returns "" with `error` set when
/// the model has loops ("MJCF export needs a tree: the model closes 1 loop through
/// joint 4 "rocker pin B" …") or the options are invalid.
std::string toMjcf(const Model& model, const MjcfOptions& options, std::string& error);
/// toMjcf with the default options.
std::string toMjcf(const Model& model, std::string& error);

}  // namespace solver
