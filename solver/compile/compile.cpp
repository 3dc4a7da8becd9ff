#include "solver/compile/compile.h"

#include "solver/compile/initial_configuration.h"
#include "solver/contact/contact_geometry.h"
#include "solver/core/data.h"
#include "solver/kinematics/joint_geometry.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <unordered_map>

namespace solver {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;

// The angle whose actuator length is `length` on the monotonic branch of L(θ) that
// contains theta0, unwrapped to the turn nearest theta0. The branches are
// (φ − π, φ) (L grows with θ) and (φ, φ + π) (L shrinks).
double angleOnBranch(const ActuatorLengthLaw& law, double length, double theta0)
{
    const double rho = law.rho();
    if (!(rho > 0)) return theta0;
    const double k = std::clamp((length * length - law.c0) / rho, -1.0, 1.0);
    const double side = wrapAngle(theta0 - law.phi()) >= 0 ? 1.0 : -1.0;
    const double angle = law.phi() + side * std::acos(k);
    return theta0 + wrapAngle(angle - theta0);
}

// limits on θ of a T 1 joint from its length limits
void actuatorLimits(const JointSpec& joint, const ActuatorLengthLaw& law, double theta0,
                    double& lower, double& upper)
{
    lower = -kInf;
    upper = kInf;
    // on θ0's branch, L grows with θ when θ0 − φ lies in (−π, 0)
    const bool growing = wrapAngle(theta0 - law.phi()) < 0;
    if (joint.ll) {
        const double t = angleOnBranch(law, *joint.ll, theta0);
        (growing ? lower : upper) = t;
    }
    if (joint.ul) {
        const double t = angleOnBranch(law, *joint.ul, theta0);
        (growing ? upper : lower) = t;
    }
    if (lower > upper) std::swap(lower, upper);
}

CompiledDrive compileDrive(const DriveSpec& spec, const JointSpec& joint, const ActuatorLengthLaw& law)
{
    CompiledDrive d;
    switch (spec.kind) {
    case DriveKind::Hydraulic: {
        const DriveSpec::Hydraulic h = spec.hydraulic();
        d.type = DriveType::Hydraulic;
        d.vmax = h.vmax;
        d.vmin = h.vmin;
        d.fmax = h.fmax;
        d.fmin = h.fmin;
        break;
    }
    case DriveKind::Motor:
        d.type = DriveType::Motor;
        d.t0 = spec.param("T0").value_or(0);
        d.w0 = spec.param("W0").value_or(0);
        break;
    case DriveKind::Pneumatic:
        d.type = DriveType::Pneumatic;
        d.force = spec.param("F").value_or(0);
        break;
    case DriveKind::Cylinder:
    case DriveKind::HydraulicMotor: break;  // compileFluidPower
    case DriveKind::Servo: {
        d.type = DriveType::Servo;
        d.kp = spec.param("KP").value_or(0);
        d.ki = spec.param("KI").value_or(0);
        d.kd = spec.param("KD").value_or(0);
        d.servoFmax = spec.param("FMAX").value_or(kInf);
        // set-point range in the modeler's coordinate
        const bool actuator = joint.type == JointType::Actuator;
        const double lo = actuator ? law.minLength() : -kPi;
        const double hi = actuator ? law.maxLength() : kPi;
        d.setLow = joint.ll.value_or(lo);
        d.setHigh = joint.ul.value_or(hi);
        if (!(d.setLow < d.setHigh)) {
            // one limit beyond the default range on the other side: a range as wide as the default
            if (joint.ll) d.setHigh = d.setLow + (hi - lo);
            else d.setLow = d.setHigh - (hi - lo);
        }
        break;
    }
    }
    return d;
}

/// The fluid, the pumps and one circuit per CYL/HMOTOR drive (in joint id order).
template <class TreeJoint>
void compileFluidPower(const ModelSpec& spec, TreeJoint treeJoint, Model& m)
{
    if (spec.fluid) {
        m.fluid.bulk = spec.fluid->bulk.value_or(kDefaultBulkModulus);
        m.fluid.laminar = spec.fluid->laminar.value_or(kDefaultLaminarPressure);
    }
    for (const PumpSpec& p : spec.pumps) {
        CompiledPump cp;
        cp.id = p.id;
        cp.name = p.name;
        cp.qmax = p.flow;
        cp.pmax = p.pressure;
        cp.loadSensing = p.margin.has_value();
        cp.margin = p.margin.value_or(0);
        m.pumps.push_back(std::move(cp));
    }
    std::vector<const DriveSpec*> fluid;
    for (const DriveSpec& d : spec.drives) {
        if (d.isFluidPower() && treeJoint(d.joint) >= 0) fluid.push_back(&d);
    }
    std::sort(fluid.begin(), fluid.end(), [](const DriveSpec* a, const DriveSpec* b) { return a->joint < b->joint; });
    for (const DriveSpec* d : fluid) {
        const int i = treeJoint(d->joint);
        const JointSpec& joint = *spec.joint(d->joint);
        CompiledCircuit c;
        c.joint = i;
        const int pumpId = static_cast<int>(d->param("PUMP").value_or(0));
        for (std::size_t p = 0; p < m.pumps.size(); ++p) {
            if (m.pumps[p].id == pumpId) c.pump = static_cast<int>(p);
        }
        c.kind = d->kind == DriveKind::Cylinder ? ActuatorKind::Cylinder : ActuatorKind::Motor;
        c.qn = d->param("VALVE").value_or(0);
        c.dpn = d->param("DP").value_or(1);
        c.k = c.qn / std::sqrt(c.dpn);
        c.tau = d->param("TAU").value_or(kDefaultSpoolTau);
        c.comp = d->compensation == "PRE"    ? Compensation::Pre
                 : d->compensation == "POST" ? Compensation::Post
                                             : Compensation::None;
        c.friction = d->param("FRICTION").value_or(0);
        const double pmax = c.pump >= 0 ? m.pumps[static_cast<std::size_t>(c.pump)].pmax : 0;
        c.reliefGain = pmax > 0 ? c.qn / (kReliefOverride * pmax) : 0;
        if (c.kind == ActuatorKind::Cylinder) {
            const double bore = d->param("BORE").value_or(0), rod = d->param("ROD").value_or(0);
            c.areaA = kPi / 4 * bore * bore;
            c.areaB = c.areaA - kPi / 4 * rod * rod;
            c.lower = joint.ll.value_or(0);
            c.upper = joint.ul.value_or(0);
            const double stroke = std::max(0.0, c.upper - c.lower);
            const auto dead = d->pair("DEAD");
            c.deadA = dead ? dead->first : kDefaultDeadVolume + kDefaultDeadFraction * c.areaA * stroke;
            c.deadB = dead ? dead->second : kDefaultDeadVolume + kDefaultDeadFraction * c.areaB * stroke;
        } else {
            c.areaA = c.areaB = d->param("DISP").value_or(0);
            const auto volume = d->pair("VOLUME");
            c.deadA = volume ? volume->first : kDefaultMotorLineVolume;
            c.deadB = volume ? volume->second : kDefaultMotorLineVolume;
        }
        if (const auto p0 = d->pair("P0")) {
            c.hasP0 = true;
            c.p0A = p0->first;
            c.p0B = p0->second;
        }
        m.drive[static_cast<std::size_t>(i)] = CompiledDrive{};
        m.drive[static_cast<std::size_t>(i)].type = DriveType::FluidPower;
        m.drive[static_cast<std::size_t>(i)].circuit = static_cast<int>(m.circuits.size());
        m.circuits.push_back(c);
    }
    for (std::size_t p = 0; p < m.pumps.size(); ++p) {
        const auto fed = [p](const CompiledCircuit& c) { return c.pump == static_cast<int>(p); };
        m.pumps[p].allPost = std::any_of(m.circuits.begin(), m.circuits.end(), fed) &&
                             std::all_of(m.circuits.begin(), m.circuits.end(), [&](const CompiledCircuit& c) {
                                 return !fed(c) || c.comp == Compensation::Post;
                             });
    }
}

/// The joint frames of a free joint's coordinate `slot` (0–5) in its parent and child
/// bodies, from the free joint's frames F1 (in B1) and F2 (in B2). A prismatic joint
/// shifts along its frame's y axis and a revolute one turns about its x axis, so each
/// slot's frame carries the axis it moves along there; the massless bodies between the
/// slots keep F1's axes (turned by the base orientation and the turns before them):
///   slots 0, 1, 2: shifts along F1's x (A), y (R), z (T);
///   slot 3: turn about x of the base (kinematics.cpp turns its parent frame by the
///   base quaternion); slots 4, 5: turns about y, z; slot 5's child is B2, at F2.
void freeSlotFrames(int slot, const Eigen::Isometry3d& f1, const Eigen::Isometry3d& f2, Eigen::Isometry3d& X_pj,
                    Eigen::Isometry3d& X_cj)
{
    using Eigen::AngleAxisd;
    using Eigen::Vector3d;
    const double half = kPi / 2;
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();  // the slot's axis onto y (shifts) or x (turns)
    switch (slot) {
    case 0: r = AngleAxisd(-half, Vector3d::UnitZ()).toRotationMatrix(); break;  // y → x
    case 2: r = AngleAxisd(half, Vector3d::UnitX()).toRotationMatrix(); break;   // y → z
    case 4: r = AngleAxisd(half, Vector3d::UnitZ()).toRotationMatrix(); break;   // x → y
    case 5: r = AngleAxisd(-half, Vector3d::UnitY()).toRotationMatrix(); break;  // x → z
    default: break;
    }
    r = r.array().round().matrix();  // exactly 0 and ±1: no 6e-17 leaking across axes
    const Eigen::Isometry3d turn(r);
    X_pj = slot == 0 ? Eigen::Isometry3d(f1 * turn) : turn;
    X_cj = slot == kFreeJointCoordinates - 1 ? Eigen::Isometry3d(f2 * turn) : turn;
}

}  // namespace

CompileResult compileModel(const ModelSpec& spec, Diagnostics& diags, const ModelSpec* scene)
{
    const std::size_t errorsBefore = diags.errorCount();

    // 1-2. the graph; T 1 checks and the initial guess of every coordinate (per spec joint)
    Topology topo = analyzeTopology(spec, diags);
    const std::vector<JointGeometry> geometry = makeJointGeometries(spec);
    Eigen::VectorXd theta;
    initialGuess(spec, geometry, topo, theta, diags);

    // 3. cut joints
    // a loop-closure joint is a constraint, not a coordinate: it cannot carry a drive,
    // and its limits are not enforced (the spanning tree takes driven joints first, so
    // this only happens when every joint of a loop is driven)
    bool driveOnCut = false;
    for (int j : topo.loopJoints) {
        const JointSpec& cut = spec.joints[static_cast<std::size_t>(j)];
        auto who = [&] {
            return trText("Diagnostics", "joint %1")
                .with(std::to_string(cut.id) + (cut.name.empty() ? std::string() : " \"" + cut.name + "\""));
        };
        for (const DriveSpec& d : spec.drives) {
            if (d.joint != cut.id) continue;
            diags.error("loop-joint-driven", d.src.pos,
                        trText("Diagnostics", "the drive on %1 cannot act: the joint closes a loop, so it is a "
                                              "constraint, not a coordinate").with(who()),
                        trText("Diagnostics", "move the drive to another joint of the loop, or leave one joint of "
                                              "the loop passive"));
            driveOnCut = true;
        }
        if (cut.ll || cut.ul) {
            diags.warning("loop-joint-limits-ignored", cut.src.pos,
                          trText("Diagnostics", "%1 closes a loop: its limits LL/UL are not enforced").with(who()),
                          trText("Diagnostics", "put the limits on another joint of the loop (a tree joint)"));
        }
    }
    auto model = std::make_shared<Model>();
    Model& m = *model;
    const int nb = static_cast<int>(topo.treeJoints.size());
    const auto nbs = static_cast<std::size_t>(nb);
    m.nb = nb;
    m.gravity = spec.gravity;
    m.restitution = spec.restitution;

    // tree index of every body index and spec joint
    std::vector<int> treeOfBody(topo.bodyIds.size(), -1);
    std::vector<int> treeOfJoint(spec.joints.size(), -1);
    std::vector<int> childBody(nbs);
    // (a free joint's six tree joints: its body is slot 5's child, the joint is slot 0)
    std::vector<int> slot(nbs, -1);
    for (int i = 0; i < nb; ++i) {
        const int j = topo.treeJoints[static_cast<std::size_t>(i)];
        const int child = topo.reversed[j] ? topo.side1Body[j] : topo.side2Body[j];
        if (spec.joints[static_cast<std::size_t>(j)].type == JointType::Free) {
            slot[i] = i > 0 && topo.treeJoints[static_cast<std::size_t>(i - 1)] == j ? slot[i - 1] + 1 : 0;
        }
        if (slot[i] < 0 || slot[i] == kFreeJointCoordinates - 1) treeOfBody[child] = i;
        if (slot[i] <= 0) treeOfJoint[j] = i;
        childBody[i] = child;
    }
    std::unordered_map<int, const BodySpec*> bodyById;
    for (const BodySpec& b : spec.bodies) bodyById.emplace(b.id, &b);
    std::unordered_map<int, int> treeBodyById;
    for (std::size_t b = 1; b < topo.bodyIds.size(); ++b) treeBodyById.emplace(topo.bodyIds[b], treeOfBody[b]);
    auto treeBody = [&](int id) {
        auto it = treeBodyById.find(id);
        return it == treeBodyById.end() ? -1 : it->second;
    };
    std::unordered_map<int, int> jointById;
    for (int i = 0; i < nb; ++i) jointById.emplace(spec.joints[topo.treeJoints[i]].id, i);
    auto treeJoint = [&](int id) {
        auto it = jointById.find(id);
        return it == jointById.end() ? -1 : it->second;
    };

    m.parent.resize(nbs);
    m.bodyId.resize(nbs);
    m.jointId.resize(nbs);
    m.bodyName.resize(nbs);
    m.jointName.resize(nbs);
    m.jointType.resize(nbs);
    m.X_pj.resize(nbs);
    m.X_cj.resize(nbs);
    m.X_jc.resize(nbs);
    m.axisSign.resize(nbs);
    m.lengthLaw.resize(nbs);
    m.cl1.assign(nbs, Eigen::Vector3d::Zero());
    m.cl2.assign(nbs, Eigen::Vector3d::Zero());
    m.lower.resize(nbs);
    m.upper.resize(nbs);
    m.mass.assign(nbs, 0.0);
    m.com.assign(nbs, Eigen::Vector3d::Zero());
    m.inertia.assign(nbs, Eigen::Matrix3d::Zero());
    m.drive.assign(nbs, CompiledDrive{});
    m.theta0.resize(nbs);
    m.thetaDot0.resize(nbs);
    m.dependent.assign(nbs, 0);
    m.freeSlot = slot;
    m.freeBase.assign(nbs, -1);
    m.nq = nb;
    for (int i = 0; i < nb; ++i) {
        if (slot[i] == 0) m.freeJoints.push_back(i);
        if (slot[i] == 3) {
            m.freeBase[i] = m.nq;
            m.nq += 4;
        }
    }

    for (int i = 0; i < nb; ++i) {
        const int j = topo.treeJoints[static_cast<std::size_t>(i)];
        const JointSpec& joint = spec.joints[static_cast<std::size_t>(j)];
        const int child = childBody[i];
        const bool reversed = topo.reversed[j];

        // numbering
        const int s = slot[i];
        m.parent[i] = s > 0 ? i - 1 : treeOfBody[topo.parentBody[child]];
        assert(m.parent[i] < i);
        const bool massless = s >= 0 && s < kFreeJointCoordinates - 1;
        m.bodyId[i] = massless ? -1 : topo.bodyIds[child];
        m.jointId[i] = joint.id;
        m.jointName[i] = joint.name;
        m.jointType[i] = s < 0 ? joint.type : s < 3 ? JointType::Prismatic : JointType::Revolute;

        // frames: parent side, child side
        const JointGeometry& g = geometry[static_cast<std::size_t>(j)];
        m.X_pj[i] = (reversed ? g.side2 : g.side1).pose();
        m.X_cj[i] = (reversed ? g.side1 : g.side2).pose();
        if (s >= 0) freeSlotFrames(s, g.side1.pose(), g.side2.pose(), m.X_pj[i], m.X_cj[i]);
        m.X_jc[i] = m.X_cj[i].inverse(Eigen::Isometry);
        m.axisSign[i] = reversed ? -1.0 : 1.0;

        // body
        if (auto it = bodyById.find(m.bodyId[i]); !massless && it != bodyById.end()) {
            const BodySpec& body = *it->second;
            m.bodyName[i] = body.name;
            if (body.hasMass) {
                m.mass[i] = body.mass;
                m.com[i] = body.cg;
                m.inertia[i] = body.inertiaTensor();
            }
        }

        // the initial guess (the loops are closed below)
        m.theta0[i] = theta[j];

        // T 1 length law
        if (joint.type == JointType::Actuator) {
            m.lengthLaw[i] = g.lengthLaw();
            m.cl1[i] = joint.cl1;
            m.cl2[i] = joint.cl2;
        }
    }

    // loop-closure joints; the length scale of the constraints
    double size = 0;
    for (int i = 0; i < nb; ++i) {
        size = std::max({size, m.X_pj[i].translation().norm(), m.X_cj[i].translation().norm()});
    }
    for (int j : topo.loopJoints) {
        const JointSpec& joint = spec.joints[static_cast<std::size_t>(j)];
        const JointGeometry& g = geometry[static_cast<std::size_t>(j)];
        CutJoint cut;
        cut.jointId = joint.id;
        cut.name = joint.name;
        cut.type = joint.type;
        cut.body1 = treeOfBody[static_cast<std::size_t>(topo.side1Body[j])];
        cut.body2 = treeOfBody[static_cast<std::size_t>(topo.side2Body[j])];
        cut.X_1 = g.side1.pose();
        cut.X_2 = g.side2.pose();
        cut.cl1 = joint.cl1;
        cut.cl2 = joint.cl2;
        size = std::max({size, cut.X_1.translation().norm(), cut.X_2.translation().norm()});
        m.cuts.push_back(std::move(cut));
    }
    m.lengthScale = std::max(size, 1e-3);

    // drives
    for (const DriveSpec& d : spec.drives) {
        const int i = treeJoint(d.joint);
        if (i < 0) continue;
        const JointSpec& joint = spec.joints[static_cast<std::size_t>(topo.treeJoints[i])];
        m.drive[i] = compileDrive(d, joint, m.lengthLaw[i]);
    }
    compileFluidPower(spec, treeJoint, m);

    // forces
    m.forces.reserve(spec.forces.size());
    for (const ForceSpec& fs : spec.forces) {
        CompiledForce f;
        f.id = fs.id;
        f.kind = fs.kind;
        f.body = fs.body >= 0 ? treeBody(fs.body) : -1;
        f.body2 = fs.body2 >= 0 ? treeBody(fs.body2) : -1;
        f.joint = fs.joint >= 0 ? treeJoint(fs.joint) : -1;
        f.point = fs.point;
        f.point2 = fs.point2;
        const double n = fs.dir.norm();
        f.dir = n > 0 ? Eigen::Vector3d(fs.dir / n) : fs.dir;
        f.local = fs.local;
        f.stiffness = fs.stiffness;
        f.restLength = fs.restLength;
        f.damping = fs.hasDamping ? fs.damping : 0.0;
        f.area = fs.area;
        f.cd = fs.cd;
        f.cl = fs.hasCl ? fs.cl : 0.0;
        f.rho = fs.hasRho ? fs.rho : 1.225;

        // magnitude
        const MagnitudeSpec& ms = fs.mag;
        CompiledMagnitude& mag = f.mag;
        mag.kind = ms.kind;
        mag.value = ms.value;
        mag.amplitude = ms.amplitude;
        mag.frequency = ms.frequency;
        mag.phase = ms.phase;
        mag.offset = ms.hasOffset ? ms.offset : 0.0;
        mag.joint = ms.kind == MagnitudeSpec::Kind::TableJoint ? treeJoint(ms.joint) : -1;
        mag.x.reserve(ms.table.size());
        mag.y.reserve(ms.table.size());
        for (const auto& [x, y] : ms.table) {
            mag.x.push_back(x);
            mag.y.push_back(y);
        }
        m.forces.push_back(std::move(f));
    }

    // 5. the initial configuration: loops closed at QI, dependent coordinates
    Data data(m);
    const LoopAssembly loops = assembleInitialConfiguration(spec, topo, m, data, theta, diags);
    for (int c : loops.dependent) m.dependent[static_cast<std::size_t>(c)] = 1;

    // 6. limits on θ, and the initial rates, at θ0
    for (int i = 0; i < nb; ++i) {
        const JointSpec& joint = spec.joints[static_cast<std::size_t>(topo.treeJoints[static_cast<std::size_t>(i)])];
        const double theta0 = m.theta0[i];
        const double vi = joint.vi.value_or(0.0);
        if (joint.type == JointType::Actuator) {
            actuatorLimits(joint, m.lengthLaw[i], theta0, m.lower[i], m.upper[i]);
            const double rate = m.lengthLaw[i].lengthRate(theta0);
            m.thetaDot0[i] = rate != 0 ? vi / rate : 0.0;
        } else {
            m.lower[i] = joint.ll.value_or(-kInf);
            m.upper[i] = joint.ul.value_or(kInf);
            m.thetaDot0[i] = vi;
        }
    }

    // the free joints' base orientations: the start's
    m.theta0.resize(static_cast<std::size_t>(m.nq), 0.0);
    for (int i = 0; i < nb; ++i) {
        if (m.freeBase[i] >= 0) m.theta0[static_cast<std::size_t>(m.freeBase[i])] = 1.0;
    }

    // 7. every joint moves mass; the total mass
    checkMovesMass(spec, topo, m, data, loops, diags);
    for (const BodySpec& b : spec.bodies) {
        if (b.id != 0 && b.hasMass) topo.totalMass += b.mass;
    }

    // 8. CONTACT: the solids' shapes and the pairs that never touch (contact/contact_geometry.h)
    if (spec.contact && diags.errorCount() == errorsBefore) m.contact = compileContact(spec, scene, m, diags);

    CompileResult result;
    if (driveOnCut || diags.errorCount() > errorsBefore) return result;
    result.topology = std::move(topo);
    result.model = std::move(model);
    return result;
}

}  // namespace solver
