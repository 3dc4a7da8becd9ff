#include "solver/compile/topology.h"

#include "solver/compile/coordinates.h"
#include "solver/compile/mass_check.h"
#include "solver/compile/spanning_tree.h"
#include "solver/kinematics/joint_geometry.h"
#include "solver/kinematics/loop_closure.h"
#include "solver/kinematics/positions.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

// The global analysis of a model, in order:
//   1. spanning tree, cut joints, chains (spanning_tree.cpp)
//   2. bodies that ground does not reach
//   3. T 1 lengths: reachable, not constant, no dead point inside the stroke
//   4. initial configuration: QI, loop-closure rank, dependent coordinates, Newton
//   5. every joint (or loop) moves mass: the mass matrix at q0 is not singular
//   6. total mass

namespace solver {

namespace {

constexpr double kLoopTolerance = 1e-10;  // Newton convergence [m, -]
constexpr double kLoopFailure = 1e-8;  // larger residual: not satisfiable
constexpr double kRankTolerance = 1e-9;  // relative, on the scaled Φ_θ
constexpr double kMassTolerance = 1e-12;  // relative eigenvalue tolerance of M
// above this many tree joints the mass check looks at M's diagonal only (O(n), not O(n³))
constexpr Eigen::Index kDenseMassCheckLimit = 1500;

std::string num(double v, int digits = 6)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

std::string quoted(const std::string& name)
{
    return name.empty() ? std::string() : " \"" + name + "\"";
}

// "joint 3" or "joint 3 "boom""
Text jointLabel(const JointSpec& j)
{
    return trText("Diagnostics", "joint %1").with(std::to_string(j.id) + quoted(j.name));
}

// "joint 1", "joints 1 and 2", "joints 1, 2 and 3"
Text jointList(const ModelSpec& spec, const std::vector<int>& joints)
{
    auto item = [&](std::size_t i) {
        return std::to_string(spec.joints[joints[i]].id) + quoted(spec.joints[joints[i]].name);
    };
    if (joints.size() == 1) return trText("Diagnostics", "joint %1").with(item(0));
    std::string most;
    for (std::size_t i = 0; i + 1 < joints.size(); ++i) most += (i > 0 ? ", " : "") + item(i);
    return trText("Diagnostics", "joints %1 and %2").with(most).with(item(joints.size() - 1));
}

// "a, b, c": a list of translatable items
Text joinList(const std::vector<Text>& items)
{
    if (items.empty()) return {};
    Text out = items[0];
    for (std::size_t i = 1; i < items.size(); ++i) out = trText("Diagnostics", "%1, %2").with(std::move(out)).with(items[i]);
    return out;
}

const BodySpec* bodyById(const ModelSpec& spec, int id)
{
    for (const BodySpec& b : spec.bodies) {
        if (b.id == id) return &b;
    }
    return nullptr;
}

bool isDriven(const ModelSpec& spec, int joint)
{
    return std::any_of(spec.drives.begin(), spec.drives.end(),
                       [&](const DriveSpec& d) { return d.joint == spec.joints[joint].id; });
}

// ---------------------------------------------------------------- bodies

void checkConnected(const ModelSpec& spec, const Topology& topo, const std::vector<bool>& reached,
                    Diagnostics& diags)
{
    for (std::size_t b = 1; b < reached.size(); ++b) {
        if (reached[b]) continue;
        const BodySpec* body = bodyById(spec, topo.bodyIds[b]);
        const Text who =
            trText("Diagnostics", "body %1").with(std::to_string(topo.bodyIds[b]) + quoted(body ? body->name : ""));
        diags.error("body-not-connected", body ? body->src.pos : SourcePos{},
                    trText("Diagnostics", "%1 is not connected to ground: no chain of joints leads from body 0 to it")
                        .with(who),
                    trText("Diagnostics", "add a joint (C) that connects it to ground or to a connected body"));
    }
}

// ---------------------------------------------------------------- T 1 actuators

// Checks a T 1 joint's lengths and returns its initial length and angle.
void analyzeActuator(const JointSpec& joint, const JointGeometry& geometry, Diagnostics& diags,
                     double& q, double& theta)
{
    const ActuatorLengthLaw law = geometry.lengthLaw();
    auto who = [&] { return trText("Diagnostics", "joint %1's actuator").with(std::to_string(joint.id)); };

    // constant length: CL1 or CL2 on the axis
    if (!(law.rho() > 1e-9 * std::max(law.c0, 1e-12))) {
        diags.error("actuator-constant-length", joint.src.where("CL1"),
                    trText("Diagnostics", "%1 keeps the same length %2 m whatever the joint angle: CL1 or CL2 lies "
                                          "on the joint axis A, so the actuator cannot turn the joint")
                        .with(who())
                        .with(num(law.length(0))),
                    trText("Diagnostics", "place CL1 (on body %1) and CL2 (on body %2) away from the joint axis, so "
                                          "that the actuator length changes as the joint turns")
                        .with(std::to_string(joint.side1.body))
                        .with(std::to_string(joint.side2.body)));
        q = joint.qi.value_or(law.length(0));
        theta = 0;
        return;
    }

    const double lmin = law.minLength(), lmax = law.maxLength();
    const double tol = 1e-9 * std::max(1.0, lmax);
    auto reachable = [&](double v) { return v >= lmin - tol && v <= lmax + tol; };

    // LL, UL, QI within reach
    struct Limit {
        const char* key;
        const std::optional<double>& value;
    };
    for (const Limit& lim : {Limit{"LL", joint.ll}, Limit{"UL", joint.ul}, Limit{"QI", joint.qi}}) {
        if (!lim.value || reachable(*lim.value)) continue;
        Text hint = std::string_view(lim.key) == "QI"
                        ? trText("Diagnostics", "the actuator length |CL2 − CL1| goes from %1 m to %2 m as the joint "
                                                "turns; choose %3 within that range, or check CL1, CL2 and the joint "
                                                "points P1, P2 (a reachable QI is taken at the joint angle nearest to 0)")
                        : trText("Diagnostics", "the actuator length |CL2 − CL1| goes from %1 m to %2 m as the joint "
                                                "turns; choose %3 within that range, or check CL1, CL2 and the joint "
                                                "points P1, P2");
        hint.arg(num(lmin)).arg(num(lmax)).arg(lim.key);
        diags.error("actuator-unreachable", joint.src.where(lim.key),
                    trText("Diagnostics", "%1 = %2 m is beyond the reach of %3 (%4 m .. %5 m)")
                        .with(lim.key)
                        .with(num(*lim.value))
                        .with(who())
                        .with(num(lmin))
                        .with(num(lmax)),
                    std::move(hint));
    }

    // the stroke: written limits, else the reachable range
    const double lo = std::clamp(joint.ll.value_or(lmin), lmin, lmax);
    const double hi = std::clamp(joint.ul.value_or(lmax), lmin, lmax);
    q = joint.qi && reachable(*joint.qi) ? std::clamp(*joint.qi, lmin, lmax) : 0.5 * (lo + hi);
    theta = law.angle(q).value_or(0);
    if (joint.qi && !reachable(*joint.qi)) q = *joint.qi;  // keep what was written

    // dead points (dL/dθ = 0) strictly inside (LL, UL)
    // (limits out of reach, already reported, count as the reachable ends)
    const double strokeLo = joint.ll ? lo : -INFINITY;
    const double strokeHi = joint.ul ? hi : INFINITY;
    struct Extremum {
        double length;
        double angle;
        Text which;
        const char* limit;
        bool upper;
    };
    for (const Extremum& e :
         {Extremum{lmax, law.angleOfMaxLength(), trText("Diagnostics", "longest"), "UL", true},
          Extremum{lmin, law.angleOfMinLength(), trText("Diagnostics", "shortest"), "LL", false}}) {
        if (!(e.length > strokeLo + tol && e.length < strokeHi - tol)) continue;
        const bool unlimited = e.upper ? !joint.ul : !joint.ll;
        Text msg = unlimited ? trText("Diagnostics", "%1 reaches a dead point inside its stroke: its length is %2 "
                                                     "(%3 m) at joint angle %4 rad, and no %5 stops it before")
                             : trText("Diagnostics", "%1 reaches a dead point inside its stroke: its length is %2 "
                                                     "(%3 m) at joint angle %4 rad, between LL and UL");
        msg.arg(who()).arg(e.which).arg(num(e.length)).arg(num(e.angle));
        if (unlimited) msg.arg(e.limit);
        Text hint = e.upper ? trText("Diagnostics", "the cylinder cannot drive the joint through that point "
                                                    "(dL/dθ = 0 there); set %1 below %2 m")
                            : trText("Diagnostics", "the cylinder cannot drive the joint through that point "
                                                    "(dL/dθ = 0 there); set %1 above %2 m");
        hint.arg(e.limit).arg(num(e.length));
        diags.warning("actuator-dead-point", joint.src.pos, std::move(msg), std::move(hint));
    }
}

// ---------------------------------------------------------------- loops

// Size of the mechanism: the diagonal of the box around the world joint points [m].
double lengthScale(const Topology& topo, const std::vector<JointGeometry>& geometry,
                   const std::vector<Eigen::Isometry3d>& X_wb)
{
    Eigen::AlignedBox3d box;
    auto add = [&](int j) {
        box.extend(X_wb[topo.side1Body[j]] * geometry[j].side1.origin);
        box.extend(X_wb[topo.side2Body[j]] * geometry[j].side2.origin);
    };
    for (int j : topo.treeJoints) add(j);
    for (int j : topo.loopJoints) add(j);
    const double d = box.isEmpty() ? 0.0 : box.diagonal().norm();
    return d > 1e-9 ? d : 1.0;
}

// Φ_θ with length rows divided by the scale and prismatic columns multiplied by it.
Eigen::MatrixXd scaledJacobian(const Topology& topo, const std::vector<JointGeometry>& geometry,
                               const Eigen::MatrixXd& jac, double scale)
{
    Eigen::MatrixXd js = jac;
    for (std::size_t k = 0; k < topo.loopJoints.size(); ++k) {
        const JointType type = geometry[topo.loopJoints[k]].type;
        for (int r = 0; r < kClosureEquations; ++r) {
            if (closureRowIsLength(type, r)) js.row(kClosureEquations * k + r) /= scale;
        }
    }
    for (std::size_t c = 0; c < topo.treeJoints.size(); ++c) {
        if (geometry[topo.treeJoints[c]].type == JointType::Prismatic) js.col(c) *= scale;
    }
    return js;
}

void reportUnsatisfiedLoops(const ModelSpec& spec, const Topology& topo,
                            const std::vector<JointGeometry>& geometry,
                            const Eigen::VectorXd& residual, const Eigen::MatrixXd& jac,
                            const std::vector<int>& independentCols, Diagnostics& diags)
{
    // the cut joints whose own equations are not met (at least the worst one)
    std::vector<std::size_t> failed;
    std::size_t worst = 0;
    for (std::size_t k = 0; k < topo.loopJoints.size(); ++k) {
        const double r = residual.segment<kClosureEquations>(kClosureEquations * k).norm();
        if (r > kLoopFailure) failed.push_back(k);
        if (r > residual.segment<kClosureEquations>(kClosureEquations * worst).norm()) worst = k;
    }
    if (failed.empty()) failed.push_back(worst);

    for (std::size_t k : failed) {
        const int c = topo.loopJoints[k];
        const JointSpec& joint = spec.joints[c];
        const Eigen::Matrix<double, kClosureEquations, 1> rows =
            residual.segment<kClosureEquations>(kClosureEquations * k);

        // what is off: distance and angle parts
        std::vector<Text> detail;
        double gap = 0, angle = 0;
        if (geometry[c].type == JointType::Prismatic) {
            angle = rows.head<3>().norm();
            gap = rows.tail<2>().norm();
        } else {
            gap = rows.head<3>().norm();
            angle = rows.tail<2>().norm();
        }
        const bool prismatic = geometry[c].type == JointType::Prismatic;
        if (gap > kLoopFailure) {
            detail.push_back(prismatic ? trText("Diagnostics", "P2 lies %1 m off the sliding line through P1")
                                             .with(num(gap, 3))
                                       : trText("Diagnostics", "P1 and P2 stay %1 m apart").with(num(gap, 3)));
        }
        if (angle > kLoopFailure) {
            const std::string rad = num(std::asin(std::min(1.0, angle)), 3);
            detail.push_back(prismatic ? trText("Diagnostics", "the joint frames are turned by about %1 rad").with(rad)
                                       : trText("Diagnostics", "the axes A1 and A2 are %1 rad out of line").with(rad));
        }

        // the independent coordinates that move this loop
        std::vector<int> drivers;
        for (int col : independentCols) {
            if (jac.block<kClosureEquations, 1>(kClosureEquations * k, col).norm() > 1e-12) {
                drivers.push_back(topo.treeJoints[col]);
            }
        }
        std::sort(drivers.begin(), drivers.end());
        Text hint = drivers.empty()
                        ? trText("Diagnostics", "check the joint points P1, P2 and the link lengths of the loop")
                        : trText("Diagnostics", "check the joint points P1, P2 and the link lengths of the loop, and "
                                                "the QI of its independent coordinates (%1)")
                              .with(jointList(spec, drivers));

        Text message = detail.empty()
                           ? trText("Diagnostics", "the loop closed by %1 cannot be assembled at the initial "
                                                   "configuration: its closure equations keep a residual of %2")
                           : trText("Diagnostics", "the loop closed by %1 cannot be assembled at the initial "
                                                   "configuration: its closure equations keep a residual of %2 (%3)");
        message.arg(jointLabel(joint)).arg(num(rows.norm(), 3));
        if (!detail.empty()) message.arg(joinList(detail));
        diags.error("loop-unsatisfiable", joint.src.pos, std::move(message), std::move(hint));
    }
}

// ---------------------------------------------------------------- mass

void checkMass(const ModelSpec& spec, const Topology& topo, const Eigen::MatrixXd& massTree,
               const Eigen::MatrixXd& g, const std::vector<int>& independentCols,
               Diagnostics& diags)
{
    const Eigen::MatrixXd m = g.transpose() * massTree * g;
    const auto n = m.rows();
    if (n == 0) return;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> all(m, Eigen::EigenvaluesOnly);
    const double tol = kMassTolerance * std::max(1.0, all.eigenvalues().maxCoeff());
    if (all.eigenvalues().minCoeff() >= tol) return;

    const Text hint = trText("Diagnostics", "give the bodies it moves a mass (B id m Ixx Iyy Izz), or remove the joint");
    auto jointOf = [&](Eigen::Index i) { return topo.treeJoints[independentCols[i]]; };

    // single joints that move nothing with mass
    std::vector<Eigen::Index> rest;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (m(i, i) >= tol) {
            rest.push_back(i);
            continue;
        }
        const int j = jointOf(i);
        const JointSpec& joint = spec.joints[j];

        // the dependent joints this one drives through loops
        std::vector<int> carried;
        for (Eigen::Index r = 0; r < g.rows(); ++r) {
            if (r != independentCols[i] && std::abs(g(r, i)) > 1e-9)
                carried.push_back(topo.treeJoints[r]);
        }
        std::sort(carried.begin(), carried.end());
        const Text why = joint.type == JointType::Prismatic
                             ? trText("Diagnostics", "the bodies it moves have no mass")
                             : trText("Diagnostics", "the bodies it moves have no mass, or only mass on its axis "
                                                     "and no inertia about it");
        Text message = carried.empty()
                           ? trText("Diagnostics", "%1 moves no mass: %2, so the mass matrix is singular at the "
                                                   "initial configuration")
                                 .with(jointLabel(joint))
                                 .with(why)
                           : trText("Diagnostics", "%1 and the loop it drives (%2) move no mass: %3, so the mass "
                                                   "matrix is singular at the initial configuration")
                                 .with(jointLabel(joint))
                                 .with(jointList(spec, carried))
                                 .with(why);
        diags.error("joint-moves-no-mass", joint.src.pos, std::move(message), hint);
    }
    if (rest.empty()) return;

    // combinations of joints that together move nothing with mass
    const auto nr = static_cast<Eigen::Index>(rest.size());
    Eigen::MatrixXd mr(nr, nr);
    for (Eigen::Index a = 0; a < nr; ++a) {
        for (Eigen::Index b = 0; b < nr; ++b) mr(a, b) = m(rest[a], rest[b]);
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(mr);
    std::vector<int> reported;
    for (Eigen::Index e = 0; e < nr; ++e) {
        if (eig.eigenvalues()[e] >= tol) continue;
        Eigen::VectorXd v = eig.eigenvectors().col(e);
        const double vmax = v.cwiseAbs().maxCoeff();
        std::vector<int> joints;
        for (Eigen::Index a = 0; a < nr; ++a) {
            if (std::abs(v[a]) < 0.5 * vmax) continue;
            if (joints.empty()) v /= v[a];  // first large component = 1
            joints.push_back(jointOf(rest[a]));
        }
        std::sort(joints.begin(), joints.end());
        std::vector<Text> rates;
        for (Eigen::Index a = 0; a < nr; ++a) {
            if (std::abs(v[a]) < 1e-9) continue;
            rates.push_back(trText("Diagnostics", "%1 for joint %2")
                                .with(num(v[a], 3))
                                .with(std::to_string(spec.joints[jointOf(rest[a])].id)));
        }
        for (int j : joints) {
            if (std::find(reported.begin(), reported.end(), j) != reported.end()) continue;
            reported.push_back(j);
            diags.error("joint-moves-no-mass", spec.joints[j].src.pos,
                        trText("Diagnostics", "%1 together move no mass: the motion with rates %2 leaves every body "
                                              "with mass at rest, so the mass matrix is singular at the initial "
                                              "configuration")
                            .with(jointList(spec, joints))
                            .with(joinList(rates)),
                        hint);
        }
    }
}

}  // namespace

std::optional<Topology> analyzeTopology(const ModelSpec& spec, Diagnostics& diags)
{
    const std::size_t errorsBefore = diags.errorCount();
    const std::size_t nj = spec.joints.size();

    // 1-2. spanning tree; bodies that ground does not reach
    Topology topo;
    const std::vector<bool> reached = buildSpanningTree(spec, topo);
    checkConnected(spec, topo, reached, diags);

    // 3. joint geometry, T 1 checks, QI
    const std::vector<JointGeometry> geometry = makeJointGeometries(spec);
    Eigen::VectorXd theta = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nj));
    topo.q0.assign(nj, 0.0);
    for (std::size_t j = 0; j < nj; ++j) {
        const JointSpec& joint = spec.joints[j];
        if (joint.type == JointType::Actuator) {
            analyzeActuator(joint, geometry[j], diags, topo.q0[j], theta[j]);
        } else {
            topo.q0[j] = joint.qi.value_or(0.0);
            theta[j] = topo.q0[j];
        }
    }

    // 4. loops: rank, dependent coordinates, assembly at QI
    const auto nt = static_cast<Eigen::Index>(topo.treeJoints.size());
    std::vector<int> independentCols, dependentCols;
    Eigen::MatrixXd jac;
    bool loopsAssembled = true;
    std::vector<Eigen::Isometry3d> X_wb = bodyPoses(topo, geometry, theta);
    if (!topo.loopJoints.empty() && nt > 0) {
        const double scale = lengthScale(topo, geometry, X_wb);
        ClosureSolveOptions options;
        options.tolerance = kLoopTolerance;
        options.lengthScale = scale;
        auto scaledJacobianAt = [&](const Eigen::VectorXd& th) {
            Eigen::MatrixXd j;
            closureJacobian(topo, geometry, bodyPoses(topo, geometry, th), j);
            return scaledJacobian(topo, geometry, j, scale);
        };

        // the rank is that of an assembled configuration: QI may not be assembled, and may sit
        // on a singular one (a straight chain); assemble first moving every tree coordinate
        std::vector<int> allTree(topo.treeJoints.begin(), topo.treeJoints.end());
        Eigen::VectorXd thetaFree = theta;
        const bool freeAssembled =
            solveClosure(topo, geometry, allTree, thetaFree, options).residualNorm <= kLoopFailure;
        Eigen::MatrixXd reference = scaledJacobianAt(thetaFree);
        if (!freeAssembled) {
            const Eigen::MatrixXd atQi = scaledJacobianAt(theta);
            if (numericalRank(atQi, kRankTolerance) > numericalRank(reference, kRankTolerance))
                reference = atQi;
        }

        // preference for dependent: undriven before driven, later in the file first
        std::vector<int> preference(static_cast<std::size_t>(nt));
        for (Eigen::Index c = 0; c < nt; ++c) preference[c] = static_cast<int>(c);
        std::sort(preference.begin(), preference.end(), [&](int a, int b) {
            const int ja = topo.treeJoints[a], jb = topo.treeJoints[b];
            const bool da = isDriven(spec, ja), db = isDriven(spec, jb);
            if (da != db) return !da;
            return ja > jb;
        });
        const CoordinatePartition part =
            partitionCoordinates(reference, preference, kRankTolerance);
        independentCols = part.independent;
        dependentCols = part.dependent;
        topo.closureRank = part.rank;

        // Newton on the dependent coordinates, independent ones held at QI: from the dependent
        // ones' QI, else from where the free assembly put them
        std::vector<int> unknowns;
        for (int c : dependentCols) unknowns.push_back(topo.treeJoints[c]);
        const Eigen::VectorXd guess = theta;
        ClosureSolveResult solved = solveClosure(topo, geometry, unknowns, theta, options);
        if (solved.residualNorm > kLoopFailure && freeAssembled) {
            Eigen::VectorXd retry = guess;
            for (int j : unknowns) retry[j] = thetaFree[j];
            const ClosureSolveResult second =
                solveClosure(topo, geometry, unknowns, retry, options);
            if (second.residualNorm < solved.residualNorm) {
                solved = second;
                theta = retry;
            }
        }

        // revolute angles: the turn nearest to the guess
        for (int j : unknowns) {
            if (geometry[j].isRotational()) theta[j] = guess[j] + wrapAngle(theta[j] - guess[j]);
        }
        bodyPoses(topo, geometry, theta, X_wb);
        closureJacobian(topo, geometry, X_wb, jac);
        loopsAssembled = solved.residualNorm <= kLoopFailure;
        if (!loopsAssembled) {
            reportUnsatisfiedLoops(spec, topo, geometry, solved.residual, jac, independentCols,
                                   diags);
        }
        for (int j : unknowns) topo.q0[j] = geometry[j].coordinateFromKinematic(theta[j]);
    } else {
        for (Eigen::Index c = 0; c < nt; ++c) independentCols.push_back(static_cast<int>(c));
        jac.setZero(0, nt);
    }
    for (int c : independentCols) topo.independent.push_back(topo.treeJoints[c]);
    for (int c : dependentCols) topo.dependent.push_back(topo.treeJoints[c]);
    std::sort(topo.independent.begin(), topo.independent.end());
    std::sort(topo.dependent.begin(), topo.dependent.end());
    topo.dof = static_cast<int>(nt) - topo.closureRank;

    // cut joints' own coordinates, measured at the assembled configuration
    for (int c : topo.loopJoints) {
        const Eigen::Isometry3d& X_w1 = X_wb[topo.side1Body[c]];
        const Eigen::Isometry3d& X_w2 = X_wb[topo.side2Body[c]];
        theta[c] = geometry[c].measureKinematic(X_w1, X_w2);
        topo.q0[c] = geometry[c].measureCoordinate(X_w1, X_w2);
    }
    topo.theta0.assign(theta.data(), theta.data() + theta.size());

    // 5. the mass matrix at q0, on the independent coordinates
    std::vector<BodyInertia> inertia(topo.bodyIds.size());
    for (std::size_t b = 1; b < topo.bodyIds.size(); ++b) {
        const BodySpec* body = bodyById(spec, topo.bodyIds[b]);
        if (!body || !body->hasMass) continue;
        inertia[b].mass = body->mass;
        inertia[b].cg = body->cg;
        inertia[b].inertia = body->inertiaTensor();
    }
    if (nt > kDenseMassCheckLimit) {
        // too large for a dense n×n check: each joint must move some inertia along its axis
        const std::vector<bool> none = jointsMovingNoMass(topo, geometry, X_wb, inertia);
        for (int j : topo.treeJoints) {
            if (!none[static_cast<std::size_t>(j)]) continue;
            const JointSpec& joint = spec.joints[static_cast<std::size_t>(j)];
            diags.error("joint-moves-no-mass", joint.src.pos,
                        trText("Diagnostics", "%1 moves no mass: %2, so the mass matrix is singular at the initial "
                                              "configuration")
                            .with(jointLabel(joint))
                            .with(trText("Diagnostics", "the bodies it moves have no mass, or only mass on its axis "
                                                        "and no inertia about it")),
                        trText("Diagnostics", "give the bodies it moves a mass (B id m Ixx Iyy Izz), or remove the joint"));
        }
    } else if (nt > 0) {
        const Eigen::MatrixXd massTree = treeMassMatrix(topo, geometry, X_wb, inertia);
        // rates of all tree joints from the independent ones (through the loops when they close)
        const Eigen::MatrixXd g = loopsAssembled
                                      ? nullSpaceBasis(jac, independentCols, dependentCols)
                                      : nullSpaceBasis(jac, independentCols, {});
        checkMass(spec, topo, massTree, g, independentCols, diags);
    }

    // 6. total mass
    for (std::size_t b = 1; b < topo.bodyIds.size(); ++b) topo.totalMass += inertia[b].mass;

    if (diags.errorCount() > errorsBefore) return std::nullopt;
    return topo;
}

}  // namespace solver
