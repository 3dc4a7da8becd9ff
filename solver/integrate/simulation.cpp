#include "solver/integrate/simulation.h"

#include "solver/contact/contact_forces.h"
#include "solver/contact/contact_geometry.h"
#include "solver/dynamics/applied_forces.h"
#include "solver/dynamics/constraints.h"
#include "solver/dynamics/drives.h"
#include "solver/dynamics/forward_dynamics.h"
#include "solver/dynamics/mass_matrix.h"
#include "solver/hydraulics/circuit.h"
#include "solver/kinematics/kinematics.h"

#include <Eigen/Cholesky>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace solver {

namespace {

constexpr int kRootsPerJoint = 4;  // lower limit, upper limit, relief extending, relief retracting
// relative: a relief valve opens above (1 + this)·its setting, and closes when the rate
// passes the commanded rate by this much (relative to 1 + |command|)
constexpr double kReliefMargin = 1e-8;

bool isHydraulic(const Model& m, int j) { return m.drive[j].type == DriveType::Hydraulic; }

const char* unitOf(JointType t) { return t == JointType::Revolute ? "rad" : "m"; }

std::string fmt(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

/// Runs kinematics, applied forces and the hybrid dynamics at `state`.
void evaluateAll(const Model& model, const State& state, Data& data)
{
    hydraulics::evaluateHydraulics(model, state, data);
    forwardKinematics(model, state, data);
    applyForces(model, state, data);
    hybridDynamics(model, state, data);
}

Text bodyLabelText(const Model& m, int b)
{
    if (b < 0) return trText("Diagnostics", "the ground");
    if (m.bodyName[b].empty()) return trText("Diagnostics", "body %1").with(std::to_string(m.bodyId[b]));
    return trText("Diagnostics", "body %1 %2").with(std::to_string(m.bodyId[b])).with(m.bodyName[b]);
}

/// Sets a failure's English `error` and, when asked for, its translatable `errorText`.
void setError(Text text, std::string& error, Text* errorText)
{
    error = text.english();
    if (errorText) *errorText = std::move(text);
}

/// The commanded rate of joint j's hydraulic drive in the modeler's coordinate.
double commandRate(const Model& m, const State& s, int j) { return hydraulicCommandRate(m.drive[j], s.u[j]); }

}  // namespace

std::string SimulationEvent::describe(const Model& model) const { return describeText(model).english(); }

Text SimulationEvent::describeText(const Model& model) const
{
    char t0[32];
    std::snprintf(t0, sizeof t0, "%.6f", t);
    switch (kind) {
    case Kind::Weld:
        return trText("Diagnostics", "t=%1 s: %2 welded to %3").with(t0).with(bodyLabelText(model, body2)).with(bodyLabelText(model, body));
    case Kind::Release:
        return trText("Diagnostics", "t=%1 s: %2 released from %3").with(t0).with(bodyLabelText(model, body2)).with(bodyLabelText(model, body));
    case Kind::PumpSaturation: {
        std::string who = pump >= 0 && pump < static_cast<int>(model.pumps.size()) ? std::to_string(model.pumps[pump].id) : "?";
        if (pump >= 0 && pump < static_cast<int>(model.pumps.size()) && !model.pumps[pump].name.empty())
            who += " " + model.pumps[pump].name;
        return (side > 0 ? trText("Diagnostics", "t=%1 s: pump %2 saturated: the valves ask for %3 L/min, more than it gives")
                         : trText("Diagnostics", "t=%1 s: pump %2 no longer saturated (%3 L/min asked)"))
            .with(t0).with(who).with(fmt(value * 60000));
    }
    case Kind::Cavitation: {
        std::string who = std::to_string(model.jointId[joint]);
        if (!model.jointName[joint].empty()) who += " " + model.jointName[joint];
        return (side > 0 ? trText("Diagnostics", "t=%1 s: joint %2 cavitates: a chamber's pressure fell to 0 (the load runs "
                                                 "ahead of the oil)")
                         : trText("Diagnostics", "t=%1 s: joint %2 no longer cavitates"))
            .with(t0).with(who);
    }
    case Kind::DeepContact: {
        const ContactGeometry* g = model.contact ? model.contact->geometry.get() : nullptr;
        auto solid = [g](int shape) {
            if (!g || shape < 0 || shape >= static_cast<int>(g->shapes.size())) return plainText("?");
            const ContactShape& s = g->shapes[static_cast<std::size_t>(shape)];
            return (s.scene ? trText("Diagnostics", "scene G %1") : trText("Diagnostics", "G %1"))
                .with(std::to_string(s.graphicId));
        };
        char mm[32];
        std::snprintf(mm, sizeof mm, "%.1f", value * 1000);
        return (side > 0 ? trText("Diagnostics", "t=%1 s: %2 and %3 overlap by %4 mm, deeper than the contact pushes "
                                                 "back for (a drive stronger than the contact, or a fast hit): they are "
                                                 "pushed apart gently")
                         : trText("Diagnostics", "t=%1 s: %2 and %3 no longer overlap deeply (%4 mm)"))
            .with(t0).with(solid(shapeA)).with(solid(shapeB)).with(mm);
    }
    case Kind::LoopLocked: {
        std::string joints;
        for (const CutJoint& c : model.cuts) {
            joints += (joints.empty() ? "" : ", ") + std::to_string(c.jointId);
            if (!c.name.empty()) joints += " " + c.name;
        }
        return trText("Diagnostics", "t=%1 s: the closed loops (closing joints %2) locked up: a singular "
                                     "configuration, the mechanism cannot move on").with(t0).with(joints);
    }
    default: break;
    }
    std::string who = std::to_string(model.jointId[joint]);
    if (!model.jointName[joint].empty()) who += " " + model.jointName[joint];
    const char* unit = unitOf(model.jointType[joint]);
    const char* forceUnit = model.jointType[joint] == JointType::Revolute ? "N m" : "N";
    // side is on θ; for a T 1 joint whose length shrinks as its angle grows, the
    // lower limit on θ is the upper limit on the length the modeler wrote
    int written = side;
    if (kind == Kind::LimitHit || kind == Kind::LimitLeave) {
        const double limit = side < 0 ? model.lower[joint] : model.upper[joint];
        if (std::isfinite(limit) && model.coordinateRate(joint, limit) < 0) written = -side;
    }
    const std::string v = fmt(value);
    switch (kind) {
    case Kind::LimitHit:
        return (written < 0 ? trText("Diagnostics", "t=%1 s: joint %2 hit its lower limit %3 %4")
                            : trText("Diagnostics", "t=%1 s: joint %2 hit its upper limit %3 %4"))
            .with(t0).with(who).with(v).with(unit);
    case Kind::LimitLeave:
        return (written < 0 ? trText("Diagnostics", "t=%1 s: joint %2 left its lower limit %3 %4")
                            : trText("Diagnostics", "t=%1 s: joint %2 left its upper limit %3 %4"))
            .with(t0).with(who).with(v).with(unit);
    case Kind::ReliefOpen:
        return (side > 0 ? trText("Diagnostics", "t=%1 s: joint %2 relief valve opened extending at %3 %4")
                         : trText("Diagnostics", "t=%1 s: joint %2 relief valve opened retracting at %3 %4"))
            .with(t0).with(who).with(v).with(forceUnit);
    case Kind::ReliefClose:
        return (side > 0 ? trText("Diagnostics", "t=%1 s: joint %2 relief valve closed extending")
                         : trText("Diagnostics", "t=%1 s: joint %2 relief valve closed retracting"))
            .with(t0).with(who);
    default: break;
    }
    return plainText(t0);
}

/// The number of state components: θ, θ̇, servo integral per joint, then the fluid states.
static int stateSize(const Model& m) { return 3 * m.nb + kFluidStates * static_cast<int>(m.circuits.size()); }

/// The ODE y = [θ; θ̇; servo integral; fluid states] (dim stateSize) with the event functions of the
/// current modes (kRootsPerJoint per joint, then the loop lock; each valid while positive).
class Simulation::System : public OdeSystem {
public:
    System(const Model& model, State& modes, bool limits, const std::vector<char>& faulted)
        : m_model(&model), m_modes(modes), m_work(modes), m_data(model), m_limits(limits), m_faulted(faulted)
    {
        if (model.contact) m_work.contacts.reserve(kMaxContacts);
        for (int j = 0; j < model.nb; ++j) {
            if ((limits && (std::isfinite(model.lower[j]) || std::isfinite(model.upper[j]))) || isHydraulic(model, j))
                m_needRoots = true;
        }
        if (!model.cuts.empty()) m_needRoots = true;
    }

    /// Rank of the constraint Jacobian over the free coordinates that the loop-lock
    /// event watches (set at every mode change).
    int expectedRank = 0;

    int size() const override { return stateSize(*m_model); }
    int rootCount() const override { return m_needRoots ? kRootsPerJoint * m_model->nb + 1 : 0; }
    int rootDirection(int) const override { return -1; }
    bool evaluateAtStepEnds() const override { return true; }  // the outputs (takeEvaluation)

    /// An integrator's stage: θ̈ only (no reactions); with every joint's acceleration
    /// prescribed, from the drive laws alone.
    bool rhs(double t, const double* y, double* ydot) override
    {
        load(t, y);
        m_fullValid = false;
        hydraulics::evaluateHydraulics(*m_model, m_work, m_data);
        if (!kinematicAccelerations(*m_model, m_work, m_data)) {
            forwardKinematics(*m_model, m_work, m_data);
            applyForces(*m_model, m_work, m_data);
            hybridDynamics(*m_model, m_work, m_data, DynamicsOutputs::Accelerations);
        }
        derivative(*m_model, m_work, m_data, m_faulted, ydot);
        return true;
    }

    bool roots(double t, const double* y, double* g) override
    {
        full(t, y);
        eventFunctions(*m_model, m_work, m_data, m_limits, expectedRank, g);
        return true;
    }

    bool rhsAndRoots(double t, const double* y, double* ydot, double* g) override
    {
        full(t, y);
        // a step's end (or start): the contacts' anchors for the next step
        if (m_model->contact) updateContactAnchors(*m_model, m_data, m_modes.contacts);
        derivative(*m_model, m_work, m_data, m_faulted, ydot);
        if (rootCount() > 0) eventFunctions(*m_model, m_work, m_data, m_limits, expectedRank, g);
        return true;
    }

    /// The real-time step's sub-steps for the fluid circuits, from the last evaluation.
    int substeps(double h) override
    {
        if (m_model->circuits.empty()) return 1;
        return hydraulics::substeps(*m_model, m_work, m_data, h);
    }

    /// The fixed step whose oil springs the evaluations keep resolved (Data::oilSpringStep).
    void setOilSpringStep(double h)
    {
        m_data.oilSpringStep = h;
        m_data.inertiaFloor.setZero(m_model->nb);
    }

    /// The model the dynamics run on from now on (same size: the simulation's, after a
    /// drive fault was set or cleared; the number of event functions does not change).
    void setModel(const Model& model) { m_model = &model; }

    /// y' at a state whose θ̈ `data` holds; `faulted` (per joint): drives whose law is a
    /// fault's, whose servo integral stays as it is.
    static void derivative(const Model& model, const State& s, const Data& data, const std::vector<char>& faulted,
                           double* ydot)
    {
        const int nb = model.nb;
        for (int j = 0; j < nb; ++j) {
            ydot[j] = s.qd[j];
            ydot[nb + j] = data.qdd[j];
            ydot[2 * nb + j] = faulted[static_cast<std::size_t>(j)] ? 0.0 : servoError(model, s, j);
        }
        for (Eigen::Index k = 0; k < data.fluidRate.size(); ++k) ydot[3 * nb + k] = data.fluidRate[k];
    }

    /// Hands over the whole evaluation (kinematics, dynamics, reactions) of the state
    /// (t, y) when the last thing this system did was to evaluate exactly there (the
    /// RK4 step's end), swapping it into `out`; false otherwise.
    bool takeEvaluation(double t, const double* y, Data& out)
    {
        if (!m_fullValid || t != m_fullT) return false;
        if (!std::equal(y, y + size(), m_fullY.begin())) return false;
        std::swap(out, m_data);
        m_fullValid = false;
        return true;
    }

    /// The event functions at a state whose dynamics `data` holds (dim 4·nb + 1).
    static void eventFunctions(const Model& model, const State& s, const Data& data, bool limits, int rank,
                               double* g)
    {
        // the loop lock: the smallest expected singular value, relative, above kLoopLockRatio
        double& lock = g[kRootsPerJoint * model.nb];
        lock = 1.0;
        const Eigen::VectorXd& sv = data.constraintSingular;
        if (rank > 0 && sv.size() >= rank && sv[0] > 0) lock = sv[rank - 1] / sv[0] - kLoopLockRatio;

        for (int j = 0; j < model.nb; ++j) {
            double* gj = g + kRootsPerJoint * j;
            gj[0] = gj[1] = gj[2] = gj[3] = 1.0;
            const bool hyd = isHydraulic(model, j);
            if (limits) {
                switch (s.limit[j]) {
                case LimitState::Free:
                    if (std::isfinite(model.lower[j])) gj[0] = s.q[j] - model.lower[j];
                    if (std::isfinite(model.upper[j])) gj[1] = model.upper[j] - s.q[j];
                    break;
                case LimitState::AtLower:
                    if (!hyd) gj[0] = data.limitForce[j];
                    break;
                case LimitState::AtUpper:
                    if (!hyd) gj[1] = -data.limitForce[j];
                    break;
                }
            }
            if (!hyd || s.limit[j] != LimitState::Free) continue;
            const CompiledDrive& d = model.drive[j];
            const double rate = s.qd[j] * model.coordinateRate(j, s.q[j]);  // q̇ in the modeler's coordinate
            switch (s.relief[j]) {
            case ReliefState::Closed:
                // (kReliefMargin: a force that only grazes the setting, rising to it and
                // falling back within the root finder's tolerance, leaves the valve closed
                // instead of opening and closing it forever at one instant)
                if (std::isfinite(d.fmax)) gj[2] = d.fmax * (1 + kReliefMargin) - data.driveForce[j];
                if (std::isfinite(d.fmin)) gj[3] = d.fmin * (1 + kReliefMargin) + data.driveForce[j];
                break;
            // (open: closes when the rate is back at the command; the margin keeps g > 0 at
            // the instant it opened, when the rate still equals the command — a zero there
            // would be taken for a root at once)
            case ReliefState::OpenExtending: {
                const double cmd = hydraulicCommandRate(d, s.u[j]);
                gj[2] = cmd - rate + kReliefMargin * (1 + std::abs(cmd));
                break;
            }
            case ReliefState::OpenRetracting: {
                const double cmd = hydraulicCommandRate(d, s.u[j]);
                gj[3] = rate - cmd + kReliefMargin * (1 + std::abs(cmd));
                break;
            }
            }
        }
    }

private:
    const Model* m_model;  // the simulation's (with its drive faults)
    State& m_modes;        // the simulation's state: modes, commands, contact anchors (set at step ends)
    State m_work;          // modes copied from m_modes, values from y
    Data m_data;
    bool m_limits;
    const std::vector<char>& m_faulted;  // per joint: a drive fault (no servo integral)
    bool m_needRoots = false;
    // the last whole evaluation (roots, rhsAndRoots) and where it was
    bool m_fullValid = false;
    double m_fullT = 0;
    std::vector<double> m_fullY = std::vector<double>(static_cast<std::size_t>(stateSize(*m_model)), 0.0);

    void full(double t, const double* y)
    {
        load(t, y);
        evaluateAll(*m_model, m_work, m_data);
        m_fullValid = true;
        m_fullT = t;
        std::copy(y, y + size(), m_fullY.begin());
    }

    void load(double t, const double* y)
    {
        const int nb = m_model->nb;
        m_work.t = t;
        for (int j = 0; j < nb; ++j) {
            m_work.q[j] = y[j];
            m_work.qd[j] = y[nb + j];
            m_work.servoIntegral[j] = y[2 * nb + j];
            m_work.u[j] = m_modes.u[j];
            m_work.limit[j] = m_modes.limit[j];
            m_work.relief[j] = m_modes.relief[j];
        }
        for (Eigen::Index k = 0; k < m_work.fluid.size(); ++k) m_work.fluid[k] = y[3 * nb + k];
        // the free joints' base orientations: not integrated (constant between folds)
        for (Eigen::Index k = nb; k < m_work.q.size(); ++k) m_work.q[k] = m_modes.q[k];
        m_work.welds = m_modes.welds;
        m_work.push = m_modes.push;
        m_work.constraintRank = m_modes.constraintRank;
        if (m_model->contact) m_work.contacts = m_modes.contacts;
    }
};

namespace {

/// The model the options ask for: drives removed (--passive) or limits removed (--no-limits).
std::shared_ptr<const Model> adapt(std::shared_ptr<const Model> model, const SimulationOptions& o)
{
    if (o.drives && o.limits) return model;
    auto m = std::make_shared<Model>(*model);
    if (!o.drives) {
        // no drives: no circuits either (nothing would act on the joints)
        m->pumps.clear();
        m->circuits.clear();
    }
    for (int j = 0; j < m->nb; ++j) {
        if (!o.drives) m->drive[j] = CompiledDrive{};
        if (!o.limits) {
            m->lower[j] = -std::numeric_limits<double>::infinity();
            m->upper[j] = std::numeric_limits<double>::infinity();
        }
    }
    return m;
}

}  // namespace

Simulation::Simulation(std::shared_ptr<const Model> model, const SimulationOptions& options)
    : m_model(adapt(std::move(model), options)),
      m_base(m_model),
      m_options(options),
      m_state(makeState(*m_model)),
      m_data(*m_model),
      m_y(static_cast<std::size_t>(stateSize(*m_model)), 0.0)
{
    const auto nb = static_cast<std::size_t>(m_model->nb);
    m_g.assign(kRootsPerJoint * nb + 1, 0.0);
    m_fired.assign(m_g.size(), 0);
    m_ydot.assign(m_y.size(), 0.0);
    for (Eigen::VectorXd* v : {&m_qdBefore, &m_jump, &m_impulse, &m_dqd}) v->setZero(m_model->nb);
    m_positionsAt.setConstant(m_state.q.size(), std::numeric_limits<double>::quiet_NaN());  // none yet
    if (!m_options.limits) {
        for (LimitState& l : m_state.limit) l = LimitState::Free;
    }
    m_faults.assign(nb, DriveFault{});
    m_faulted.assign(nb, 0);
    m_system = std::make_unique<System>(*m_model, m_state, m_options.limits, m_faulted);
    IntegratorOptions io = m_options.integrator;
    if (io.method != IntegrationMethod::Rk4Fixed && io.maxStep == 0) io.maxStep = kDefaultMaxStep;
    // fluid power at the fixed step: light parts get their actuator's moving mass
    if (io.method == IntegrationMethod::Rk4Fixed && !m_model->circuits.empty()) {
        m_data.oilSpringStep = io.step;
        m_data.inertiaFloor.setZero(m_model->nb);
        m_system->setOilSpringStep(io.step);
    }
    if (m_model->nb > 0) m_integrator = std::make_unique<Integrator>(*m_system, io);
    // with loops, the initial rates of the dependent coordinates follow from the others'
    if (!m_model->cuts.empty()) {
        for (int j = 0; j < m_model->nb; ++j) {
            if (!m_model->dependent[j]) m_held.push_back(j);
        }
        assemble();
        m_held.clear();
    }
    initialPressures();
    evaluate();
    m_fluidRelief.assign(m_model->circuits.size(), 0);
    m_fluidCavitation.assign(m_model->circuits.size(), 0);
    m_pumpSaturated.assign(m_model->pumps.size(), 0);
    m_deepContacts.clear();
    if (m_model->contact) m_deepContacts.reserve(kMaxContacts);
}

void Simulation::initialPressures()
{
    const Model& m = *m_model;
    if (std::all_of(m.circuits.begin(), m.circuits.end(), [](const CompiledCircuit& c) { return c.hasP0; })) return;
    // every fluid-power joint held where it is, at rest: what each must carry
    State held = m_state;
    held.qd.setZero();
    for (const CompiledCircuit& c : m.circuits) {
        if (held.limit[c.joint] == LimitState::Free) held.limit[c.joint] = LimitState::AtLower;
    }
    for (std::size_t c = 0; c < m.circuits.size(); ++c) {
        if (m.circuits[c].hasP0) continue;
        held.fluid[kFluidStates * static_cast<Eigen::Index>(c) + 1] = 0;
        held.fluid[kFluidStates * static_cast<Eigen::Index>(c) + 2] = 0;
    }
    evaluateAll(m, held, m_data);
    for (std::size_t c = 0; c < m.circuits.size(); ++c) {
        const CompiledCircuit& k = m.circuits[c];
        if (k.hasP0) continue;
        const int j = k.joint;
        const double stop = m_data.limitForce[j];  // along θ: what holding takes, less the drive's P0 force
        const Eigen::Index i = kFluidStates * static_cast<Eigen::Index>(c);
        m_state.fluid[i + 1] = m_state.fluid[i + 2] = 0;
        // a joint that starts on its stop, pressed onto it, rests there: no pressure needed
        if ((m_state.limit[j] == LimitState::AtLower && stop >= 0) ||
            (m_state.limit[j] == LimitState::AtUpper && stop <= 0))
            continue;
        const double dq = m.coordinateRate(j, m_state.q[j]);
        if (dq == 0 || !std::isfinite(stop)) continue;
        // on a stop the load pulls away from, the actuator holds it there with 10 % to
        // spare (pressed onto the stop: exactly the load would leave the stop's force at
        // 0 and the joint on and off it with every rounding)
        const double spare = m_state.limit[j] == LimitState::Free ? 1.0 : 1.1;
        const double force = spare * stop / dq;  // along q
        if (force > 0) m_state.fluid[i + 1] = force / k.areaA;
        else m_state.fluid[i + 2] = -force / k.areaB;
    }
    m_positionsAt.setConstant(std::numeric_limits<double>::quiet_NaN());  // m_data was used as scratch
}

void Simulation::contactEvents(std::vector<SimulationEvent>& events)
{
    const double cap = m_model->contact->depthCap;
    auto deepest = [this](int a, int b) {
        double d = 0;
        for (const ContactPoint& c : m_data.contacts)
            if (c.shapeA == a && c.shapeB == b) d = std::max(d, c.depth);
        return d;
    };
    auto event = [&](int a, int b, int side, double depth) {
        SimulationEvent e;
        e.kind = SimulationEvent::Kind::DeepContact;
        e.t = m_state.t;
        e.joint = -1;
        e.side = side;
        e.value = depth;
        e.shapeA = a;
        e.shapeB = b;
        events.push_back(e);
    };
    // the pairs that came out of it (below half the cap: no chatter at the cap)
    for (std::size_t i = 0; i < m_deepContacts.size();) {
        const auto [a, b] = m_deepContacts[i];
        const double d = deepest(a, b);
        if (d < 0.5 * cap) {
            event(a, b, -1, d);
            m_deepContacts.erase(m_deepContacts.begin() + static_cast<std::ptrdiff_t>(i));
        } else {
            ++i;
        }
    }
    for (const ContactPoint& c : m_data.contacts) {
        if (c.depth <= cap) continue;
        const std::pair<int, int> pair(c.shapeA, c.shapeB);
        if (std::find(m_deepContacts.begin(), m_deepContacts.end(), pair) != m_deepContacts.end()) continue;
        if (m_deepContacts.size() < kMaxContacts) m_deepContacts.push_back(pair);
        event(c.shapeA, c.shapeB, +1, deepest(c.shapeA, c.shapeB));
    }
}

void Simulation::fluidEvents(std::vector<SimulationEvent>& events)
{
    const Model& m = *m_model;
    for (std::size_t p = 0; p < m.pumps.size(); ++p) {
        const double demand = m_data.pumpDemand[static_cast<Eigen::Index>(p)], qmax = m.pumps[p].qmax;
        const bool saturated = m_pumpSaturated[p] ? demand > 0.98 * qmax : demand > qmax * (1 + 1e-9);
        if (saturated == (m_pumpSaturated[p] != 0)) continue;
        m_pumpSaturated[p] = saturated ? 1 : 0;
        SimulationEvent e;
        e.kind = SimulationEvent::Kind::PumpSaturation;
        e.t = m_state.t;
        e.joint = -1;
        e.pump = static_cast<int>(p);
        e.side = saturated ? +1 : -1;
        e.value = demand;
        events.push_back(e);
    }
    for (std::size_t c = 0; c < m.circuits.size(); ++c) {
        const CompiledCircuit& k = m.circuits[c];
        const auto ci = static_cast<Eigen::Index>(c);
        const double pmax = m.pumps[static_cast<std::size_t>(k.pump)].pmax;
        const double pA = m_data.pressureA[ci], pB = m_data.pressureB[ci];
        int relief = m_fluidRelief[c];
        if (relief == 0) {
            relief = pA >= 0.98 * pmax ? +1 : pB >= 0.98 * pmax ? -1 : 0;
        } else if ((relief > 0 ? pA : pB) < 0.95 * pmax) {
            relief = 0;
        }
        if (relief != m_fluidRelief[c]) {
            const int side = relief != 0 ? relief : m_fluidRelief[c];
            SimulationEvent e;
            e.kind = relief != 0 ? SimulationEvent::Kind::ReliefOpen : SimulationEvent::Kind::ReliefClose;
            e.t = m_state.t;
            e.joint = k.joint;
            e.side = side;
            e.value = pmax * (side > 0 ? k.areaA : k.areaB);
            events.push_back(e);
            m_fluidRelief[c] = relief;
        }
        const int cav = m_data.cavitation[c];
        if ((cav != 0) != (m_fluidCavitation[c] != 0)) {
            SimulationEvent e;
            e.kind = SimulationEvent::Kind::Cavitation;
            e.t = m_state.t;
            e.joint = k.joint;
            e.side = cav != 0 ? +1 : -1;
            events.push_back(e);
        }
        m_fluidCavitation[c] = cav;
    }
}

void Simulation::assemble()
{
    std::vector<char> held(static_cast<std::size_t>(m_model->nb), 0);
    for (int j : m_held) held[static_cast<std::size_t>(j)] = 1;
    m_assemblyFailed = !project(held) && !project(std::vector<char>(held.size(), 0));
}

Simulation::~Simulation() = default;

void Simulation::setCommand(int joint, double u)
{
    u = std::isfinite(u) ? std::clamp(u, -1.0, 1.0) : 0.0;
    if (m_state.u[joint] != u) {
        m_state.u[joint] = u;
        // a fluid-power valve's spool is a state: a new command changes only the spool's
        // rate, which RK4 takes from its next stage on (no restart; the adaptive
        // integrators restart, as for any discontinuity)
        const bool spoolOnly = m_options.integrator.method == IntegrationMethod::Rk4Fixed &&
                               m_model->drive[joint].type == DriveType::FluidPower;
        if (!spoolOnly) m_restart = true;
    }
}

namespace {

/// The law a burst hose leaves (DriveFault): F = clamp(−damping·q̇, ±maxForce) in the
/// modeler's coordinate, which is the servo law with only its derivative term
/// (drives.h: kd·ė with ė = −q̇, clamped to ±servoFmax; no set-point, no integral).
CompiledDrive burstDrive(const DriveFault& f)
{
    CompiledDrive d;
    d.type = DriveType::Servo;
    d.kp = d.ki = 0;
    d.kd = f.damping;
    d.servoFmax = f.maxForce;
    return d;
}

}  // namespace

bool Simulation::setDriveFault(int joint, const DriveFault& fault)
{
    if (joint < 0 || joint >= m_base->nb) return false;
    if (!isHydraulic(*m_base, joint) && m_base->drive[joint].type != DriveType::FluidPower) return false;
    if (!(fault.damping >= 0) || !(fault.maxForce >= 0)) return false;  // (NaN fails too)
    m_faults[joint] = fault;
    m_faulted[joint] = 1;
    m_state.relief[joint] = ReliefState::Closed;
    m_state.servoIntegral[joint] = 0;
    applyFaults();
    return true;
}

bool Simulation::setPush(int body, const Eigen::Vector3d& localPoint, const Eigen::Vector3d& target)
{
    if (body < 0 || body >= m_model->nb || !localPoint.allFinite() || !target.allFinite()) return false;
    Push& p = m_state.push;
    if (p.body == body && p.point == localPoint && p.target == target) return true;
    p.body = body;
    p.point = localPoint;
    p.target = target;
    m_restart = true;  // a new load: the adaptive integrators restart, as for a command
    return true;
}

void Simulation::clearPush()
{
    if (m_state.push.body < 0) return;
    m_state.push = Push{};
    m_restart = true;
}

bool Simulation::clearDriveFault(int joint)
{
    if (joint < 0 || joint >= m_base->nb || !m_faulted[joint]) return false;
    m_faults[joint] = DriveFault{};
    m_faulted[joint] = 0;
    m_state.relief[joint] = ReliefState::Closed;
    m_state.servoIntegral[joint] = 0;
    applyFaults();
    return true;
}

const DriveFault* Simulation::driveFault(int joint) const
{
    if (joint < 0 || joint >= m_base->nb || !m_faulted[joint]) return nullptr;
    return &m_faults[joint];
}

void Simulation::applyFaults()
{
    if (std::none_of(m_faulted.begin(), m_faulted.end(), [](char f) { return f != 0; })) {
        m_model = m_base;
    } else {
        auto m = std::make_shared<Model>(*m_base);
        for (int j = 0; j < m->nb; ++j) {
            if (m_faulted[j]) m->drive[j] = burstDrive(m_faults[j]);
        }
        m_model = std::move(m);
    }
    m_system->setModel(*m_model);
    // the modes change (a prescribed rate becomes free, or the other way): the mode
    // rules settle them and the integrator restarts at the next advanceTo()
    m_restart = true;
    evaluate();
}

void Simulation::setInitial(int joint, double theta, double thetaDot)
{
    m_state.q[joint] = theta;
    m_state.qd[joint] = thetaDot;
    LimitState& l = m_state.limit[joint];
    l = LimitState::Free;
    if (m_options.limits && theta <= m_model->lower[joint]) l = LimitState::AtLower;
    if (m_options.limits && theta >= m_model->upper[joint]) l = LimitState::AtUpper;
    m_restart = true;
    if (hasConstraints(*m_model, m_state)) {
        // the loops close again around what was set (since the last step), moving the
        // dependent coordinates
        for (int j = 0; j < m_model->nb; ++j) {
            if (!m_model->dependent[j]) m_held.push_back(j);
        }
        m_setJoints.push_back(joint);
        for (int j : m_setJoints) m_held.push_back(j);
        assemble();
        m_held.clear();
    }
    evaluate();
}

void Simulation::evaluate() { evaluate(DynamicsOutputs::All); }

void Simulation::evaluate(DynamicsOutputs outputs)
{
    const Model& m = *m_model;
    // at the positions m_data was last evaluated at (the rules after a new command only
    // change rates) the position terms are kept: kinematics, body inertias
    if (!hasConstraints(m, m_state) && m_positionsAt == m_state.q) {
        hydraulics::evaluateHydraulics(m, m_state, m_data);
        velocityKinematics(m, m_state.qd, m_data);
        applyForces(m, m_state, m_data);
        hybridDynamicsSamePositions(m, m_state, m_data, outputs);
    } else {
        evaluateAll(m, m_state, m_data);
    }
    m_positionsAt = m_state.q;
}

void Simulation::packState()
{
    const int nb = m_model->nb;
    for (int j = 0; j < nb; ++j) {
        m_y[j] = m_state.q[j];
        m_y[nb + j] = m_state.qd[j];
        m_y[2 * nb + j] = m_state.servoIntegral[j];
    }
    for (Eigen::Index k = 0; k < m_state.fluid.size(); ++k) m_y[3 * nb + k] = m_state.fluid[k];
}

void Simulation::unpackState()
{
    const int nb = m_model->nb;
    for (int j = 0; j < nb; ++j) {
        m_state.q[j] = m_y[j];
        m_state.qd[j] = m_y[nb + j];
        m_state.servoIntegral[j] = m_y[2 * nb + j];
    }
    for (Eigen::Index k = 0; k < m_state.fluid.size(); ++k) m_state.fluid[k] = m_y[3 * nb + k];
}

std::vector<char> Simulation::freeMask() const
{
    std::vector<char> free(static_cast<std::size_t>(m_model->nb), 0);
    for (int j = 0; j < m_model->nb; ++j) free[j] = isPrescribed(*m_model, m_state, j) ? 0 : 1;
    return free;
}

bool Simulation::project(const std::vector<char>& held)
{
    const Model& m = *m_model;
    if (!hasConstraints(m, m_state)) return true;
    std::vector<int> free;
    const std::vector<char> mask = freeMask();
    for (int j = 0; j < m.nb; ++j) {
        if (mask[j] && !held[j]) free.push_back(j);
    }
    return projectOntoConstraints(m, m_state, m_data, free);
}

void Simulation::prescribeRates()
{
    const Model& m = *m_model;
    // the prescribed joints take their rates at once; the free joints receive the
    // impulse that this takes (momentum along the free coordinates is conserved):
    // M_FF Δθ̇_F = −M_FP Δθ̇_P
    Eigen::VectorXd& jump = m_jump;
    bool any = false, anyFree = false;
    for (int j = 0; j < m.nb; ++j) {
        jump[j] = 0;
        if (!isPrescribed(m, m_state, j)) {
            anyFree = true;
            continue;
        }
        const double rate = prescribedRate(m, m_state, j);
        jump[j] = rate - m_state.qd[j];
        m_state.qd[j] = rate;
        any = any || jump[j] != 0;
    }
    if (!hasConstraints(m, m_state)) {
        // a tree: the articulated-body algorithm with impulses, O(n), no allocation
        if (!any || !anyFree) return;
        forwardKinematics(m, m_state, m_data);
        m_impulse.setZero();
        impulseResponse(m, m_state, m_data, jump, m_impulse, m_dqd);
        for (int j = 0; j < m.nb; ++j) {
            if (!isPrescribed(m, m_state, j)) m_state.qd[j] += m_dqd[j];
        }
        return;
    }
    std::vector<int> free;
    for (int j = 0; j < m.nb; ++j) {
        if (!isPrescribed(m, m_state, j)) free.push_back(j);
    }
    // with constraints the rates must also satisfy them (after a weld, a projection)
    bool violated = false;
    if (hasConstraints(m, m_state) && !free.empty()) {
        const Eigen::MatrixXd G = constraintJacobianAt(m, m_state, m_data);
        violated = (G * m_state.qd).lpNorm<Eigen::Infinity>() > 1e-12 * (1.0 + m_state.qd.lpNorm<Eigen::Infinity>());
    }
    if ((!any && !violated) || free.empty()) return;
    const Eigen::MatrixXd M = massMatrixAt(m, m_state, m_data);
    m_state.qd += freeResponse(M, free, -(M * jump), constraintJacobianAt(m, m_state, m_data), m_state.qd);
}

void Simulation::hitLimit(int j, int side)
{
    const Model& m = *m_model;
    m_state.q[j] = side < 0 ? m.lower[j] : m.upper[j];
    const double into = m_state.qd[j];
    if (side * into > 0) {
        // the generalized impulse p along θ_j that turns θ̇_j into −e·θ̇_j, the other
        // prescribed joints held: Δθ̇ = p·r with r = M_FF⁻¹ e_j (j counted free)
        Eigen::VectorXd& r = m_dqd;
        if (!hasConstraints(m, m_state)) {
            forwardKinematics(m, m_state, m_data);
            m_jump.setZero();
            m_impulse.setZero();
            m_impulse[j] = 1;
            impulseResponse(m, m_state, m_data, m_jump, m_impulse, r, j);
        } else {
            std::vector<int> free;
            for (int k = 0; k < m.nb; ++k) {
                if (k == j || !isPrescribed(m, m_state, k)) free.push_back(k);
            }
            r = freeResponse(massMatrixAt(m, m_state, m_data), free, Eigen::VectorXd::Unit(m.nb, j),
                             constraintJacobianAt(m, m_state, m_data), Eigen::VectorXd::Zero(m.nb));
        }
        if (r[j] > 0) m_state.qd += (-(1.0 + m.restitution) * into / r[j]) * r;
    }
    if (m.restitution == 0 || side * m_state.qd[j] >= 0) {
        m_state.qd[j] = 0;
        m_state.limit[j] = side < 0 ? LimitState::AtLower : LimitState::AtUpper;
    }
}

void Simulation::handleRoots(std::span<const int> fired, std::vector<SimulationEvent>& events)
{
    const Model& m = *m_model;
    for (std::size_t i = 0; i < fired.size(); ++i) {
        if (fired[i] == 0) continue;
        if (static_cast<int>(i) == kRootsPerJoint * m.nb) {
            SimulationEvent e;
            e.kind = SimulationEvent::Kind::LoopLocked;
            e.t = m_state.t;
            events.push_back(e);
            m_locked = true;
            continue;
        }
        const int j = static_cast<int>(i) / kRootsPerJoint;
        const int k = static_cast<int>(i) % kRootsPerJoint;
        SimulationEvent e;
        e.t = m_state.t;
        e.joint = j;
        if (k < 2) {
            const int side = k == 0 ? -1 : +1;
            e.side = side;
            e.value = m.coordinate(j, side < 0 ? m.lower[j] : m.upper[j]);
            if (m_state.limit[j] == LimitState::Free) {
                hitLimit(j, side);
                e.kind = SimulationEvent::Kind::LimitHit;
            } else {
                m_state.limit[j] = LimitState::Free;
                e.kind = SimulationEvent::Kind::LimitLeave;
            }
        } else {
            const int side = k == 2 ? +1 : -1;
            e.side = side;
            if (m_state.relief[j] == ReliefState::Closed) {
                m_state.relief[j] = side > 0 ? ReliefState::OpenExtending : ReliefState::OpenRetracting;
                e.kind = SimulationEvent::Kind::ReliefOpen;
                e.value = side > 0 ? m.drive[j].fmax : -m.drive[j].fmin;
            } else {
                m_state.relief[j] = ReliefState::Closed;
                e.kind = SimulationEvent::Kind::ReliefClose;
            }
        }
        events.push_back(e);
    }
}

bool Simulation::applyModeRules(std::vector<SimulationEvent>& events)
{
    const Model& m = *m_model;
    // settle: a mode whose event function is already negative switches now
    // (at the start, after an event, after a command); a few rounds at most
    constexpr double tol = 1e-12;
    std::vector<double>& g = m_g;
    // a relief valve that opens now opens before the commanded rate is reached: the
    // joint keeps the rate it had when the rules were applied, and so do the joints
    // that its rate jump would have pushed
    const Eigen::VectorXd& qdBefore = m_qdBefore;
    m_qdBefore = m_state.qd;
    for (int round = 0; round < 8; ++round) {
        bool changed = false;
        // a hydraulic joint on a limit leaves it when its command turns it away
        for (int j = 0; j < m.nb; ++j) {
            if (!isHydraulic(m, j) || m_state.limit[j] == LimitState::Free) continue;
            const double rate = commandRate(m, m_state, j) * (m.coordinateRate(j, m_state.q[j]) < 0 ? -1 : 1);
            const int side = m_state.limit[j] == LimitState::AtLower ? -1 : +1;
            if (side * rate < 0) {
                m_state.limit[j] = LimitState::Free;
                events.push_back({SimulationEvent::Kind::LimitLeave, m_state.t, j, side,
                                  m.coordinate(j, side < 0 ? m.lower[j] : m.upper[j])});
                changed = true;
            }
        }
        // a joint without a hydraulic drive resting on a limit, joined by constraints to
        // joints that now move (a liner lying on its stop, welded to claws that lift it),
        // leaves the limit when those rates would carry it away from the stop: counted
        // free, the impulse of the prescribed rates moves it off the stop (else it stays)
        if (hasConstraints(m, m_state)) {
            for (int j = 0; j < m.nb; ++j) {
                if (isHydraulic(m, j) || m_state.limit[j] == LimitState::Free) continue;
                const LimitState was = m_state.limit[j];
                const Eigen::VectorXd qdKept = m_state.qd;
                m_state.limit[j] = LimitState::Free;
                prescribeRates();
                const int side = was == LimitState::AtLower ? -1 : +1;
                if (side * m_state.qd[j] < -1e-12) {
                    events.push_back({SimulationEvent::Kind::LimitLeave, m_state.t, j, side,
                                      m.coordinate(j, side < 0 ? m.lower[j] : m.upper[j])});
                    changed = true;
                } else {
                    m_state.limit[j] = was;
                    m_state.qd = qdKept;
                }
            }
        }
        prescribeRates();
        m_state.constraintRank = -1;  // found anew, here on the constraints
        // (the forces the event functions need; the reactions follow at the step's end,
        // or advanceTo() evaluates them when it ends here)
        evaluate(DynamicsOutputs::Forces);
        m_state.constraintRank = m_data.constraintRank;
        m_expectedRank = m_data.constraintRank;
        m_system->expectedRank = m_expectedRank;
        System::eventFunctions(m, m_state, m_data, m_options.limits, m_expectedRank, g.data());
        std::vector<int>& fired = m_fired;
        std::fill(fired.begin(), fired.end(), 0);
        bool any = false;
        for (std::size_t i = 0; i < g.size(); ++i) {
            const int j = static_cast<int>(i) / kRootsPerJoint;
            const int k = static_cast<int>(i) % kRootsPerJoint;
            if (!(g[i] < -tol)) continue;
            if (j == m.nb) {  // the loop lock
                fired[i] = -1;
                any = true;
                continue;
            }
            // a free joint past a limit only stops when it moves into it
            if (k < 2 && m_state.limit[j] == LimitState::Free) {
                const int side = k == 0 ? -1 : 1;
                if (side * m_state.qd[j] < 0) continue;
            }
            fired[i] = -1;
            any = true;
        }
        if (any) {
            const std::size_t first = events.size();
            handleRoots(fired, events);
            if (m_locked) return false;
            // the rates return to where they were, and the next round prescribes the
            // still-closed valves' rates again (with their impulses) from there
            for (std::size_t e = first; e < events.size(); ++e) {
                if (events[e].kind == SimulationEvent::Kind::ReliefOpen) m_state.qd = qdBefore;
            }
            changed = true;
        }
        if (!changed) {
            System::derivative(m, m_state, m_data, m_faulted, m_ydot.data());
            return true;
        }
    }
    return false;
}

namespace {

Text lockMessage(double t)
{
    return trText("Diagnostics", "the closed loops locked up at t = %1 s (a singular configuration: the loop-closure "
                                 "equations lost rank, so the mechanism cannot move on there); drive it another way or "
                                 "change the geometry")
        .with(fmt(t));
}

/// Why a simulation probably diverged on tree joint `joint`: the stiffest spring on its
/// body or a body below it when it is too stiff for the fixed step (RK4 is unstable past
/// ω·h ≈ 2.8; beyond ω·h ≈ 1 it is already far from the physics), else the usual suspects.
Text divergenceCause(const Model& m, const IntegratorOptions& io, int joint)
{
    const bool fixed = io.method == IntegrationMethod::Rk4Fixed;
    const CompiledForce* stiffest = nullptr;
    double omega = 0.0;
    int on = -1;
    for (const CompiledForce& f : m.forces) {
        if (f.kind != ForceKind::Spring || !(f.stiffness > 0)) continue;
        for (const int b : {f.body, f.body2}) {
            bool below = false;
            for (int x = b; x >= 0 && !below; x = m.parent[static_cast<std::size_t>(x)]) below = x == joint;
            if (!below || !(m.mass[static_cast<std::size_t>(b)] > 0)) continue;
            const double w = std::sqrt(f.stiffness / m.mass[static_cast<std::size_t>(b)]);
            if (w > omega) {
                omega = w;
                stiffest = &f;
                on = b;
            }
        }
    }
    if (fixed && stiffest && omega * io.step > 1.0) {
        return trText("Diagnostics", "the likely cause: spring force %1 (K = %2 N/m on a body of %3 kg, a natural period of "
                                     "%4 s) is too stiff for the step of %5 s; use a step under %6 s or the adaptive "
                                     "integrator, or soften the spring")
            .with(std::to_string(stiffest->id))
            .with(fmt(stiffest->stiffness))
            .with(fmt(m.mass[static_cast<std::size_t>(on)]))
            .with(fmt(2 * std::numbers::pi / omega))
            .with(fmt(io.step))
            .with(fmt(0.5 / omega));
    }
    return fixed ? trText("Diagnostics", "the likely cause: a spring, force or hydraulic drive too stiff for the step of %1 s, "
                                         "or a body too light for the forces on it; try a smaller step or the adaptive "
                                         "integrator, and check the masses and force magnitudes")
                       .with(fmt(io.step))
                 : trText("Diagnostics", "the likely cause: a force or spring that grows without bound, or a body too light "
                                         "for the forces on it; check the masses and force magnitudes");
}

}  // namespace

bool Simulation::advanceTo(double tEnd, std::vector<SimulationEvent>& events, std::string& error, Text* errorText)
{
    if (m_model->freeJoints.empty() || m_locked) return advanceSpan(tEnd, events, error, errorText);
    // free bodies: their three turns are folded into the base orientation before they
    // grow large (at most every kFreeFoldSpan, and only those above kFreeFoldAngle), so
    // that they stay far from the angles' gimbal lock at π/2 (core/model.h)
    constexpr double kFreeFoldSpan = 0.02;   // [s]
    constexpr double kFreeFoldAngle = 0.25;  // [rad]
    while (true) {
        // (the restart's mode rules evaluate the folded state)
        if (foldFreeRotations(*m_model, m_state, kFreeFoldAngle)) m_restart = true;
        const double next = tEnd - m_state.t > kFreeFoldSpan ? m_state.t + kFreeFoldSpan : tEnd;
        if (!advanceSpan(next, events, error, errorText)) return false;
        if (!(tEnd > m_state.t)) return true;
    }
}

bool Simulation::advanceSpan(double tEnd, std::vector<SimulationEvent>& events, std::string& error, Text* errorText)
{
    if (m_model->nb == 0) {
        m_state.t = tEnd;
        return true;
    }
    if (m_locked) {
        setError(lockMessage(m_state.t), error, errorText);
        return false;
    }
    const bool constrained = hasConstraints(*m_model, m_state);
    bool dataCurrent = false;  // m_data holds the evaluation of the state reached
    int eventCount = 0;
    while (true) {
        m_setJoints.clear();
        if (m_assemblyFailed) {
            setError(trText("Diagnostics", "the closed loops cannot be closed at t = %1 s from the coordinates given: "
                                           "set coordinates the loops can reach")
                         .with(fmt(m_state.t)),
                     error, errorText);
            return false;
        }
        if (m_restart) {
            const std::size_t before = events.size();
            const bool settled = applyModeRules(events);
            eventCount += static_cast<int>(events.size() - before);
            if (m_locked) {
                evaluate();
                setError(lockMessage(m_state.t), error, errorText);
                return false;
            }
            packState();
            resetIntegrator(settled);
            m_restart = false;
        }
        if (!(tEnd > m_state.t)) break;
        AdvanceResult r = m_integrator->advanceTo(tEnd, m_y.data());
        if (r.status == AdvanceStatus::Failed) {
            const int nb = m_model->nb;
            // a fluid state (pressures, spool): the drive that owns it
            int circuit = r.badComponent >= 3 * nb ? (r.badComponent - 3 * nb) / kFluidStates : -1;
            int joint = r.badComponent >= 0 ? (circuit >= 0 ? m_model->circuits[circuit].joint : r.badComponent % nb) : -1;
            for (int j = 0; joint < 0 && j < nb; ++j) {
                if (!std::isfinite(m_y[j]) || !std::isfinite(m_y[nb + j])) joint = j;
            }
            const std::string t0 = fmt(r.failureTime);
            if (circuit >= 0) {
                std::string who = std::to_string(m_model->jointId[joint]);
                if (!m_model->jointName[joint].empty()) who += " (" + m_model->jointName[joint] + ")";
                setError(trText("Diagnostics", "the simulation failed at t = %1 s: the pressures of the drive on joint "
                                               "%2 are no longer finite (%3); check its volumes, valve and pump data")
                             .with(t0)
                             .with(who)
                             .with(r.messageText),
                         error, errorText);
            } else if (joint < 0) {
                setError(trText("Diagnostics", "the simulation failed at t = %1 s: %2").with(t0).with(r.messageText),
                         error, errorText);
            } else if (m_model->jointName[joint].empty()) {
                setError(trText("Diagnostics", "the simulation failed at t = %1 s, joint %2: %3; %4")
                             .with(t0)
                             .with(std::to_string(m_model->jointId[joint]))
                             .with(r.messageText)
                             .with(divergenceCause(*m_model, m_options.integrator, joint)),
                         error, errorText);
            } else {
                setError(trText("Diagnostics", "the simulation failed at t = %1 s, joint %2 (%3): %4; %5")
                             .with(t0)
                             .with(std::to_string(m_model->jointId[joint]))
                             .with(m_model->jointName[joint])
                             .with(r.messageText)
                             .with(divergenceCause(*m_model, m_options.integrator, joint)),
                         error, errorText);
            }
            return false;
        }
        m_state.t = r.t;
        unpackState();
        if (constrained) {
            // back onto the constraints. A step may also end past a lock-up that the
            // root finder could not see coming (the motion ends there in finite time):
            // then the loops do not close again, or close near-singular.
            const bool closed = project(std::vector<char>(static_cast<std::size_t>(m_model->nb), 0));
            evaluate();
            const Eigen::VectorXd& sv = m_data.constraintSingular;
            const int rank = m_expectedRank;
            const bool nearSingular = rank > 0 && (sv.size() < rank || !(sv[rank - 1] >= kLoopLockRatio * sv[0]));
            if (!closed || nearSingular) {
                SimulationEvent e;
                e.kind = SimulationEvent::Kind::LoopLocked;
                e.t = m_state.t;
                events.push_back(e);
                m_locked = true;
                setError(lockMessage(m_state.t), error, errorText);
                return false;
            }
            if (r.status == AdvanceStatus::Reached) {
                // the evaluation just made is the outputs here and the next step's start
                // (the same state, the same modes and rank as the integrator's stages use)
                packState();
                System::eventFunctions(*m_model, m_state, m_data, m_options.limits, m_expectedRank, m_g.data());
                System::derivative(*m_model, m_state, m_data, m_faulted, m_ydot.data());
                m_integrator->reset(m_state.t, m_y.data(), m_ydot.data(),
                                    m_system->rootCount() > 0 ? m_g.data() : nullptr);
                dataCurrent = true;
            }
        }
        if (r.status == AdvanceStatus::Reached) break;
        const std::size_t before = events.size();
        handleRoots(r.rootsFired, events);
        bool settled = false;
        if (!m_locked) settled = applyModeRules(events);
        eventCount += static_cast<int>(events.size() - before);
        if (m_locked) {
            evaluate();
            setError(lockMessage(m_state.t), error, errorText);
            return false;
        }
        if (eventCount > m_options.maxEventsPerAdvance) {
            setError(trText("Diagnostics", "more than %1 events before t = %2 s: the joints keep switching (chattering)")
                         .with(std::to_string(m_options.maxEventsPerAdvance))
                         .with(fmt(tEnd)),
                     error, errorText);
            return false;
        }
        packState();
        resetIntegrator(settled);
    }
    // the integrator's last evaluation was the step's end, where we are: take it
    if (!dataCurrent) {
        if (m_system->takeEvaluation(m_state.t, m_y.data(), m_data)) {
            m_positionsAt = m_state.q;
        } else {
            evaluate();
        }
    }
    if (!m_model->circuits.empty()) fluidEvents(events);
    if (m_model->contact) contactEvents(events);
    return true;
}

void Simulation::resetIntegrator(bool settled)
{
    // the mode rules' last evaluation is f and g here (without constraints: with them
    // the rank the rules found may truncate differently from the integrator's)
    if (settled && !hasConstraints(*m_model, m_state)) {
        m_integrator->reset(m_state.t, m_y.data(), m_ydot.data(), m_system->rootCount() > 0 ? m_g.data() : nullptr);
    } else {
        m_integrator->reset(m_state.t, m_y.data());
    }
}

namespace {

bool inWeld(const State& s, int body)
{
    for (const Weld& w : s.welds) {
        if (w.bodyA == body || w.bodyB == body) return true;
    }
    return false;
}

}  // namespace

bool Simulation::weld(int a, int b, std::vector<SimulationEvent>& events, std::string& error, Text* errorText)
{
    const Model& m = *m_model;
    if (b < 0 || b >= m.nb || a < -1 || a >= m.nb) {
        setError(trText("Diagnostics", "cannot weld: no such body"), error, errorText);
        return false;
    }
    if (a == b) {
        setError(trText("Diagnostics", "cannot weld %1 to itself").with(bodyLabelText(m, b)), error, errorText);
        return false;
    }
    for (int body : {a, b}) {
        if (body >= 0 && inWeld(m_state, body)) {
            setError(trText("Diagnostics", "cannot weld %1 to %2: %3 is already welded (release that weld first)")
                         .with(bodyLabelText(m, b))
                         .with(bodyLabelText(m, a))
                         .with(bodyLabelText(m, body)),
                     error, errorText);
            return false;
        }
    }
    forwardKinematics(m, m_state, m_data);
    const Eigen::Isometry3d X_wa = a < 0 ? Eigen::Isometry3d::Identity() : m_data.X_wb[a];
    Weld w;
    w.bodyA = a;
    w.bodyB = b;
    w.X_ab = X_wa.inverse(Eigen::Isometry) * m_data.X_wb[b];
    m_state.welds.push_back(w);
    // the bodies' relative velocity goes, as in a plastic impact (momentum kept)
    m_state.constraintRank = -1;  // more rows: found anew at the next mode change
    project(std::vector<char>(static_cast<std::size_t>(m.nb), 0));
    SimulationEvent e;
    e.kind = SimulationEvent::Kind::Weld;
    e.t = m_state.t;
    e.body = a;
    e.body2 = b;
    events.push_back(e);
    m_restart = true;
    evaluate();
    return true;
}

bool Simulation::release(int a, int b, std::vector<SimulationEvent>& events, std::string& error, Text* errorText)
{
    const Model& m = *m_model;
    auto it = std::find_if(m_state.welds.begin(), m_state.welds.end(),
                           [&](const Weld& w) { return w.bodyA == a && w.bodyB == b; });
    if (it == m_state.welds.end()) {
        const bool ok = b >= 0 && b < m.nb && a >= -1 && a < m.nb;
        setError(ok ? trText("Diagnostics", "cannot release: %1 is not welded to %2")
                          .with(bodyLabelText(m, b))
                          .with(bodyLabelText(m, a))
                    : trText("Diagnostics", "cannot release: no such body"),
                 error, errorText);
        return false;
    }
    m_state.welds.erase(it);
    m_state.constraintRank = -1;
    SimulationEvent e;
    e.kind = SimulationEvent::Kind::Release;
    e.t = m_state.t;
    e.body = a;
    e.body2 = b;
    events.push_back(e);
    m_restart = true;
    evaluate();
    return true;
}

}  // namespace solver
