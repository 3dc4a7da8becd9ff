#include "solver/compile/initial_configuration.h"

#include "solver/compile/coordinates.h"
#include "solver/dynamics/constraints.h"
#include "solver/dynamics/mass_matrix.h"
#include "solver/kinematics/joint_geometry.h"
#include "solver/kinematics/kinematics.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

namespace solver {

namespace {

constexpr double kLoopTolerance = 1e-10;  // Newton convergence [m, -]
constexpr double kLoopFailure = 1e-8;  // larger residual: not satisfiable
constexpr double kRankTolerance = 1e-9;  // relative, on the scaled Φ_θ
constexpr double kMassTolerance = 1e-12;  // relative eigenvalue tolerance of M
// above this many tree joints the mass check looks at M's diagonal only (O(n), not O(n³))
constexpr Eigen::Index kDenseMassCheckLimit = 1500;
constexpr int kClosureEquations = 5;  // rows of a cut joint's constraint (revolute or prismatic)

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

bool isDriven(const ModelSpec& spec, int joint)
{
    return std::any_of(spec.drives.begin(), spec.drives.end(),
                       [&](const DriveSpec& d) { return d.joint == spec.joints[joint].id; });
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

// pose of body b (−1: ground) at the last kinematics
Eigen::Isometry3d poseOf(const Data& data, int b)
{
    return b < 0 ? Eigen::Isometry3d::Identity() : data.X_wb[static_cast<std::size_t>(b)];
}

// Size of the mechanism: the diagonal of the box around the world joint points at
// the kinematics in `data` [m].
double mechanismSize(const Model& model, const Data& data)
{
    Eigen::AlignedBox3d box;
    for (int i = 0; i < model.nb; ++i) {
        box.extend(poseOf(data, model.parent[i]) * model.X_pj[i].translation());
        box.extend(data.X_wb[i] * model.X_cj[i].translation());
    }
    for (const CutJoint& c : model.cuts) {
        box.extend(poseOf(data, c.body1) * c.X_1.translation());
        box.extend(poseOf(data, c.body2) * c.X_2.translation());
    }
    const double d = box.isEmpty() ? 0.0 : box.diagonal().norm();
    return d > 1e-9 ? d : 1.0;
}

// Per row of the constraints in data.constraints: whether it is a length
std::vector<char> lengthRows(const Data& data)
{
    std::vector<char> out;
    for (const Constraint& c : data.constraints) {
        for (int r = 0; r < constraintRowCount(c.kind); ++r) out.push_back(constraintRowIsLength(c.kind, r) ? 1 : 0);
    }
    return out;
}

// G at θ (unscaled rows: m per unit coordinate, or dimensionless)
Eigen::MatrixXd unscaledJacobianAt(const Model& model, Data& data, const Eigen::VectorXd& theta)
{
    State at;
    at.q = theta;
    at.qd = Eigen::VectorXd::Zero(model.nb);
    Eigen::MatrixXd g = constraintJacobianAt(model, at, data);
    const std::vector<char> lengths = lengthRows(data);
    for (Eigen::Index r = 0; r < g.rows(); ++r) {
        if (lengths[static_cast<std::size_t>(r)]) g.row(r) *= model.lengthScale;  // back to m
    }
    return g;
}

// Φ_θ with length rows divided by `scale` and prismatic columns multiplied by it
Eigen::MatrixXd scaledJacobianAt(const Model& model, Data& data, const Eigen::VectorXd& theta, double scale)
{
    Eigen::MatrixXd js = unscaledJacobianAt(model, data, theta);
    const std::vector<char> lengths = lengthRows(data);
    for (Eigen::Index r = 0; r < js.rows(); ++r) {
        if (lengths[static_cast<std::size_t>(r)]) js.row(r) /= scale;
    }
    for (int i = 0; i < model.nb; ++i) {
        if (model.jointType[static_cast<std::size_t>(i)] == JointType::Prismatic) js.col(i) *= scale;
    }
    return js;
}

// one error per loop whose own equations are not met (at least the worst one);
// residual: unscaled, 5 rows per cut joint; jac: unscaled G (rows × nb)
void reportUnsatisfiedLoops(const ModelSpec& spec, const Topology& topo, const Eigen::VectorXd& residual,
                            const Eigen::MatrixXd& jac, const std::vector<int>& independentCols,
                            Diagnostics& diags)
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
        if (joint.type == JointType::Prismatic) {
            angle = rows.head<3>().norm();
            gap = rows.tail<2>().norm();
        } else {
            gap = rows.head<3>().norm();
            angle = rows.tail<2>().norm();
        }
        const bool prismatic = joint.type == JointType::Prismatic;
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

// Per tree joint: true when its diagonal mass-matrix entry is zero (its subtree has no
// mass off its axis and no inertia about it; for a prismatic joint, no mass), at the
// kinematics in `data`. O(n·depth) and exact: a sum of non-negative terms.
std::vector<bool> jointsMovingNoMass(const Model& model, const Data& data)
{
    const auto nb = static_cast<std::size_t>(model.nb);
    std::vector<double> sum(nb, 0.0), scale(nb, 0.0);
    std::vector<Eigen::Vector3d> axis(nb), point(nb);
    for (std::size_t i = 0; i < nb; ++i) {
        const bool rotational = model.jointType[i] != JointType::Prismatic;
        axis[i] = data.X_wj[i].linear().col(rotational ? 0 : 1);
        point[i] = data.X_wj[i].translation();
    }
    for (std::size_t b = 0; b < nb; ++b) {
        if (model.mass[b] == 0 && model.inertia[b].isZero()) continue;
        const Eigen::Vector3d c = data.X_wb[b] * model.com[b];
        const Eigen::Matrix3d I = data.X_wb[b].linear() * model.inertia[b] * data.X_wb[b].linear().transpose();
        for (int k = static_cast<int>(b); k >= 0; k = model.parent[static_cast<std::size_t>(k)]) {
            const auto j = static_cast<std::size_t>(k);
            if (model.jointType[j] != JointType::Prismatic) {
                const Eigen::Vector3d r = c - point[j];
                sum[j] += model.mass[b] * axis[j].cross(r).squaredNorm() + axis[j].dot(I * axis[j]);
                scale[j] += model.mass[b] * r.squaredNorm() + I.trace();
            } else {
                sum[j] += model.mass[b];
                scale[j] += model.mass[b];
            }
        }
    }
    std::vector<bool> none(nb, false);
    for (std::size_t j = 0; j < nb; ++j) none[j] = !(sum[j] > 1e-12 * scale[j]);
    return none;
}

}  // namespace

void initialGuess(const ModelSpec& spec, const std::vector<JointGeometry>& geometry, Topology& topo,
                  Eigen::VectorXd& theta, Diagnostics& diags)
{
    const std::size_t nj = spec.joints.size();
    theta = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nj));
    topo.q0.assign(nj, 0.0);
    for (std::size_t j = 0; j < nj; ++j) {
        const JointSpec& joint = spec.joints[j];
        if (joint.type == JointType::Actuator) {
            analyzeActuator(joint, geometry[j], diags, topo.q0[j], theta[static_cast<Eigen::Index>(j)]);
        } else {
            topo.q0[j] = joint.qi.value_or(0.0);
            theta[static_cast<Eigen::Index>(j)] = topo.q0[j];
        }
    }
}

LoopAssembly assembleInitialConfiguration(const ModelSpec& spec, Topology& topo, Model& model, Data& data,
                                          Eigen::VectorXd& theta, Diagnostics& diags)
{
    LoopAssembly out;
    const int nt = model.nb;
    Eigen::VectorXd th(nt);  // θ by tree index
    for (int i = 0; i < nt; ++i) th[i] = theta[topo.treeJoints[static_cast<std::size_t>(i)]];
    State at;
    at.q = th;
    at.qd = Eigen::VectorXd::Zero(nt);
    forwardKinematics(model, at, data);

    if (!model.cuts.empty() && nt > 0) {
        const double scale = mechanismSize(model, data);
        AssemblyOptions options;
        options.tolerance = kLoopTolerance;
        options.lengthScale = scale;

        // the rank is that of an assembled configuration: QI may not be assembled, and may sit
        // on a singular one (a straight chain); assemble first moving every tree coordinate
        std::vector<int> allTree(static_cast<std::size_t>(nt));
        std::iota(allTree.begin(), allTree.end(), 0);
        Eigen::VectorXd thFree = th;
        const bool freeAssembled = assembleLoops(model, data, allTree, thFree, options).residualNorm <= kLoopFailure;
        Eigen::MatrixXd reference = scaledJacobianAt(model, data, thFree, scale);
        if (!freeAssembled) {
            const Eigen::MatrixXd atQi = scaledJacobianAt(model, data, th, scale);
            if (numericalRank(atQi, kRankTolerance) > numericalRank(reference, kRankTolerance)) reference = atQi;
        }

        // preference for dependent: undriven before driven, later in the file first
        std::vector<int> preference = allTree;
        std::sort(preference.begin(), preference.end(), [&](int a, int b) {
            const int ja = topo.treeJoints[static_cast<std::size_t>(a)];
            const int jb = topo.treeJoints[static_cast<std::size_t>(b)];
            const bool da = isDriven(spec, ja), db = isDriven(spec, jb);
            if (da != db) return !da;
            return ja > jb;
        });
        const CoordinatePartition part = partitionCoordinates(reference, preference, kRankTolerance);
        out.independent = part.independent;
        out.dependent = part.dependent;
        topo.closureRank = part.rank;

        // the dependent coordinates solved, the independent ones held at QI: from the dependent
        // ones' QI, else from where the free assembly put them
        const std::vector<int>& unknowns = part.dependent;
        const Eigen::VectorXd guess = th;
        AssemblyResult solved = assembleLoops(model, data, unknowns, th, options);
        if (solved.residualNorm > kLoopFailure && freeAssembled) {
            Eigen::VectorXd retry = guess;
            for (int j : unknowns) retry[j] = thFree[j];
            const AssemblyResult second = assembleLoops(model, data, unknowns, retry, options);
            if (second.residualNorm < solved.residualNorm) {
                solved = second;
                th = retry;
            }
        }

        // revolute angles: the turn nearest to the guess
        for (int j : unknowns) {
            if (model.jointType[static_cast<std::size_t>(j)] != JointType::Prismatic) {
                th[j] = guess[j] + wrapAngle(th[j] - guess[j]);
            }
        }
        out.jacobian = unscaledJacobianAt(model, data, th);  // and the kinematics at th
        out.assembled = solved.residualNorm <= kLoopFailure;
        if (!out.assembled) {
            reportUnsatisfiedLoops(spec, topo, solved.residual, out.jacobian, out.independent, diags);
        }
        for (int j : unknowns) topo.q0[topo.treeJoints[static_cast<std::size_t>(j)]] = model.coordinate(j, th[j]);
    } else {
        out.independent = std::vector<int>(static_cast<std::size_t>(nt));
        std::iota(out.independent.begin(), out.independent.end(), 0);
        out.jacobian.setZero(0, nt);
    }
    topo.independent.clear();
    topo.dependent.clear();
    for (int c : out.independent) topo.independent.push_back(topo.treeJoints[static_cast<std::size_t>(c)]);
    for (int c : out.dependent) topo.dependent.push_back(topo.treeJoints[static_cast<std::size_t>(c)]);
    std::sort(topo.independent.begin(), topo.independent.end());
    std::sort(topo.dependent.begin(), topo.dependent.end());
    // (a free joint's six coordinates: one joint)
    topo.independent.erase(std::unique(topo.independent.begin(), topo.independent.end()), topo.independent.end());
    topo.dof = nt - topo.closureRank;

    // the initial θ; cut joints' own coordinates, measured at the assembled configuration
    // (data's kinematics are at th: set above without loops, by unscaledJacobianAt with them)
    for (int i = 0; i < nt; ++i) {
        theta[topo.treeJoints[static_cast<std::size_t>(i)]] = th[i];
        model.theta0[static_cast<std::size_t>(i)] = th[i];
    }
    for (std::size_t k = 0; k < topo.loopJoints.size(); ++k) {
        const int c = topo.loopJoints[k];
        const CutReading r = readCut(model, data, static_cast<int>(k));
        theta[c] = spec.joints[static_cast<std::size_t>(c)].type == JointType::Prismatic ? r.q : r.angle;
        topo.q0[static_cast<std::size_t>(c)] = r.q;
    }
    topo.theta0.assign(theta.data(), theta.data() + theta.size());
    return out;
}

void checkMovesMass(const ModelSpec& spec, const Topology& topo, const Model& model, const Data& data,
                    const LoopAssembly& loops, Diagnostics& diags)
{
    const int nt = model.nb;
    if (nt > kDenseMassCheckLimit) {
        // too large for a dense n×n check: each joint must move some inertia along its axis
        const std::vector<bool> none = jointsMovingNoMass(model, data);
        for (int i = 0; i < nt; ++i) {
            if (!none[static_cast<std::size_t>(i)]) continue;
            const JointSpec& joint = spec.joints[static_cast<std::size_t>(topo.treeJoints[static_cast<std::size_t>(i)])];
            diags.error("joint-moves-no-mass", joint.src.pos,
                        trText("Diagnostics", "%1 moves no mass: %2, so the mass matrix is singular at the initial "
                                              "configuration")
                            .with(jointLabel(joint))
                            .with(trText("Diagnostics", "the bodies it moves have no mass, or only mass on its axis "
                                                        "and no inertia about it")),
                        trText("Diagnostics", "give the bodies it moves a mass (B id m Ixx Iyy Izz), or remove the joint"));
        }
    } else if (nt > 0) {
        Eigen::MatrixXd massTree;
        massMatrix(model, data, massTree);
        // rates of all tree joints from the independent ones (through the loops when they close)
        const Eigen::MatrixXd g = loops.assembled ? nullSpaceBasis(loops.jacobian, loops.independent, loops.dependent)
                                                  : nullSpaceBasis(loops.jacobian, loops.independent, {});
        checkMass(spec, topo, massTree, g, loops.independent, diags);
    }
}

}  // namespace solver
