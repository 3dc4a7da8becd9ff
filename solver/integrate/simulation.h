#pragma once
// Simulation: advances a State of a compiled Model in time — applied forces,
// hybrid dynamics, drives, relief valves and joint limits as events — through
// the Integrator (SUNDIALS). One per thread: the solver thread, a test or the
// `padrob simulate` command each own theirs; the Model is shared read-only.
//
// Modes and events:
//  - A free joint with limits has two event functions θ − lower and upper − θ;
//    when one falls through zero the joint stops at the limit: θ̇ becomes −e·θ̇
//    (e = Model::restitution, 0 = inelastic) through a generalized impulse that
//    also changes the other free joints' rates (the joints with prescribed rates
//    stay as they are), and its acceleration is held at 0 (State::limit).
//  - A passive or force-driven joint leaves its limit when the stop's force
//    (Data::limitForce) falls through zero, i.e. when the dynamics pull it away.
//    A hydraulic joint at its limit stalls there (its cylinder carries the load)
//    and leaves it when the command turns it away from the stop.
//  - A hydraulic joint with its relief valve closed follows q̇ = u·vmax (u·vmin
//    retracting, held at u = 0). When the force it needs rises through fmax (or
//    falls through −fmin) the valve opens (State::relief): the joint is then
//    driven by that force, stalls or yields. It closes when the joint's rate
//    reaches the commanded rate again (the force is then within the limits).
//  - Closed loops and welds (Model::cuts, State::welds) are constraints of the
//    dynamics (solver/dynamics/constraints.h, the one implementation the compiler's
//    initial assembly uses too). After every step the state is projected back onto
//    them (projectOntoConstraints: positions
//    by Gauss–Newton, velocities by the plastic-impact projection, both weighted by
//    the mass matrix and moving only the free coordinates), so they drift by no
//    more than the projection's tolerance (1e-12, scaled). Velocity jumps (a new
//    command, a limit's impulse, a weld) keep the constraints too.
//  - A loop that locks up (the constraint Jacobian over the free coordinates loses
//    rank: a singular configuration, where the joint rates and forces would grow
//    without bound) is the event LoopLocked, raised when its smallest expected
//    singular value falls below kLoopLockRatio of its largest; the simulation stops
//    there (advanceTo() returns false with the reason; the state is kept).
//  - weld(a, b) holds body b at its current pose in body a's frame until release();
//    b's mass then loads a's chain through the weld's constraint force. Welding
//    bodies that move apart is a plastic impact: momentum is conserved.
// Each switch is reported as a SimulationEvent.
//
// Drive faults (setDriveFault): an instructor bursts a hydraulic drive's hose.
// The fault belongs to this Simulation and its state, never to the shared Model: the
// Simulation then runs on a private copy of the model whose faulted drives are
// replaced by their fault's law (model() stays the model as compiled). Like a new
// command it takes effect at the next advanceTo(), which restarts the integrator
// there; the step loop allocates no more with a fault than without.
//
// Commands (u per joint in [−1, 1]) are read at the start of every advanceTo():
// a new command sets the prescribed rates at once (the valve spool moves) and
// restarts the integrator there. The free joints take the impulse of that jump
// (M_FF Δθ̇_F = −M_FP Δθ̇_P): a load hanging from a boom that starts to slew keeps
// its velocity in the world at that instant and starts to swing.

#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/core/state.h"
#include "solver/dynamics/forward_dynamics.h"
#include "solver/integrate/integrator.h"

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace solver {

struct SimulationOptions {
    /// The integrator; an adaptive one with maxStep 0 gets kDefaultMaxStep, so that an
    /// overload or a force pulse shorter than its steps is not stepped over.
    IntegratorOptions integrator;
    bool drives = true;  ///< false: every joint passive (drives ignored)
    bool limits = true;  ///< false: joint limits ignored
    int maxEventsPerAdvance = 1000;  ///< more events in one advanceTo(): an error (chattering)
};

struct SimulationEvent {
    /// ReliefOpen/ReliefClose are also a fluid-power drive's: a chamber's pressure reached
    /// 98 % of its pump's p_max (the relief and the pump's cut-off open), and fell below 95 %
    /// again. PumpSaturation: a pump's sections draw more than its Qmax (side +1) or no
    /// longer do (side −1). Cavitation: a fluid-power chamber's pressure is held at 0 while
    /// the flow would take it lower (side +1), or no longer is (side −1).
    /// DeepContact (CONTACT): two solids overlap deeper than the contact law pushes for
    /// (CompiledContact::depthCap: a drive stronger than the contact, a fast hit), side +1,
    /// or again less than half that, side −1; shapeA, shapeB name them, value is the depth.
    enum class Kind { LimitHit, LimitLeave, ReliefOpen, ReliefClose, Weld, Release, LoopLocked, PumpSaturation, Cavitation,
                      DeepContact };
    Kind kind = Kind::LimitHit;
    double t = 0;    ///< [s]
    int joint = 0;   ///< tree index
    /// limits: −1 lower, +1 upper limit on θ (for a T 1 joint whose length shrinks as θ
    /// grows that is the upper limit on its length; describe() says the written one);
    /// relief: +1 extending (fmax), −1 retracting (fmin)
    int side = 0;
    double value = 0;  ///< the limit (modeler coordinate) or the relief force [N or N m]
    int body = -1, body2 = -1;  ///< Weld, Release: bodies a and b (tree indices, −1 = ground)
    int pump = -1;              ///< PumpSaturation: the pump's index in Model::pumps
    int shapeA = -1, shapeB = -1;  ///< DeepContact: the two solids (ContactGeometry::shapes)

    /// One line, e.g. "t=1.2345 s: joint 2 LEVANTE PLUMA hit its upper limit 1.617 m".
    std::string describe(const Model& model) const;
    /// The same, translatable (describe() is its English).
    Text describeText(const Model& model) const;
};

/// A burst hose on a hydraulic drive (Simulation::setDriveFault): the line has lost its
/// pressure, so the cylinder (or hydraulic motor) can neither hold nor push. Its relief
/// valve no longer matters and its rate is no longer prescribed: the joint becomes
/// force-driven (passive) with what is left of the drive, in the modeler's coordinate,
///     F = clamp(−damping · q̇, −maxForce, +maxForce),
/// the oil escaping through the break (viscous) bounded by what the residual pressure
/// can give. The defaults (no damping) leave a passive joint: the load falls under
/// gravity until a limit stops it, as a passive joint's would.
struct DriveFault {
    double damping = 0;  ///< [N s/m or N m s/rad] (≥ 0)
    double maxForce = std::numeric_limits<double>::infinity();  ///< [N or N m] (≥ 0)
};

/// The longest adaptive step a Simulation takes unless told otherwise [s].
inline constexpr double kDefaultMaxStep = 0.01;

/// A loop locks up when the ratio of its constraint Jacobian's smallest expected
/// singular value to its largest falls below this.
inline constexpr double kLoopLockRatio = 1e-4;

class Simulation {
public:
    /// Starts at the model's initial state (makeState). Throws std::invalid_argument
    /// for bad integrator options.
    Simulation(std::shared_ptr<const Model> model, const SimulationOptions& options);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    /// The model as compiled (with SimulationOptions' drives and limits applied), without
    /// drive faults: a burst drive is still hydraulic here (driveFault() tells).
    const Model& model() const { return *m_base; }
    const State& state() const { return m_state; }
    /// Values derived at the current state (kinematics, forces, dynamics, reactions)
    /// after the last advanceTo() or evaluate().
    const Data& data() const { return m_data; }

    /// Sets joint i's command u in [−1, 1] (clamped), read by the next advanceTo().
    void setCommand(int joint, double u);
    /// Pushes body `body` (tree index) with the mouse from the next advanceTo(): its
    /// point `localPoint` (body frame [m]) is pulled toward the world point `target` [m]
    /// by the spring–damper of applied_forces.h ("The push"), at every integrator stage,
    /// until clearPush(); a new call replaces the push (a new target each frame of a
    /// drag). Returns false, changing nothing, when the body is out of range or a
    /// coordinate is not finite. No allocation.
    bool setPush(int body, const Eigen::Vector3d& localPoint, const Eigen::Vector3d& target);
    /// Ends the push (the body moves freely again from the next advanceTo()).
    void clearPush();
    /// Bursts the hose of joint i's hydraulic drive (DriveFault), from the next
    /// advanceTo() until clearDriveFault(i); setting it again replaces the fault. The
    /// joint's rate is kept (no jump: the load starts from where it was moving), its
    /// relief valve is taken as closed and raises no events, its command (state().u)
    /// is kept but does nothing; at a limit it leaves the stop when the dynamics pull it
    /// away (as a passive joint). A fluid-power drive (CYL/HMOTOR) takes the same law:
    /// its chambers' pressures no longer act on the joint. Returns false, changing
    /// nothing, when i is out of range, the joint has no hydraulic or fluid-power drive,
    /// or a value is negative or not a number.
    /// Allocates (a copy of the model): call it between steps, not inside a step loop
    /// that must not allocate.
    bool setDriveFault(int joint, const DriveFault& fault);
    /// Repairs joint i's drive from the next advanceTo(): its rate is prescribed by its
    /// command again (u = 0: it holds where it is), the jump in rate taken by the free
    /// joints as for a new command; if holding needs more than the relief setting the
    /// valve opens at once (a ReliefOpen event). False when joint i has no fault.
    bool clearDriveFault(int joint);
    /// Joint i's fault, nullptr when its drive is sound (or i is out of range).
    const DriveFault* driveFault(int joint) const;

    /// Before the first advanceTo(): the initial θ and θ̇ of joint i (overrides QI/VI).
    void setInitial(int joint, double theta, double thetaDot);

    /// Integrates to time t (≥ current time). Events on the way are appended to
    /// `events`. Returns false with `error` set when the integration fails (a
    /// non-finite state names the time and the joint) or events chatter.
    ///
    /// Errors (here, weld() and release()) are given in English in `error` (what tests
    /// and logs read) and, when `errorText` is given, as a translatable Text (context
    /// "Diagnostics") with errorText->english() == error, which the front ends show in
    /// the operator's language (i18n::text).
    bool advanceTo(double t, std::vector<SimulationEvent>& events, std::string& error,
                   Text* errorText = nullptr);

    /// Recomputes data() at the current state.
    void evaluate();

    /// Welds body b to body a (tree indices; a = −1: the ground) at their current
    /// relative pose, from now on. Their relative velocity is taken away as in a
    /// plastic impact. Appends a Weld event. Returns false with `error` set, and
    /// changes nothing, when a = b, a body is out of range, or either body (other
    /// than the ground) is already in a weld.
    bool weld(int a, int b, std::vector<SimulationEvent>& events, std::string& error,
              Text* errorText = nullptr);
    /// Releases the weld of body b to body a. Returns false with `error` set, and
    /// changes nothing, when there is no such weld. Appends a Release event.
    bool release(int a, int b, std::vector<SimulationEvent>& events, std::string& error,
                 Text* errorText = nullptr);
    /// True after a LoopLocked event: advanceTo() fails until the simulation is rebuilt.
    bool locked() const { return m_locked; }

private:
    class System;
    /// The model the dynamics run on: m_base, or with drive faults a private copy of it
    /// whose faulted drives carry their fault's law.
    std::shared_ptr<const Model> m_model;
    std::shared_ptr<const Model> m_base;  // model(): as compiled, the options applied
    std::vector<DriveFault> m_faults;     // per joint (used where m_faulted)
    std::vector<char> m_faulted;          // per joint: 1 with a drive fault
    /// Makes m_model from m_base and the faults, and hands it to the system.
    void applyFaults();
    SimulationOptions m_options;
    State m_state;
    Data m_data;
    std::unique_ptr<System> m_system;
    std::unique_ptr<Integrator> m_integrator;
    std::vector<double> m_y;
    bool m_restart = true;  // the integrator must be reset before the next step
    bool m_locked = false;  // a loop locked up (LoopLocked)
    int m_expectedRank = 0; // rank of the free coordinates' constraint Jacobian since the last mode change
    std::vector<int> m_held;       // joints the assembly holds (independent ones, and those set)
    std::vector<int> m_setJoints;  // joints setInitial() set since the last step
    bool m_assemblyFailed = false;  // the loops could not be closed at the initial state

    // scratch of the mode rules and the rate jumps, sized once (the step loop of an
    // unconstrained model allocates nothing, even with a new command every step)
    std::vector<double> m_g;      // event functions (4 per joint + the loop lock)
    std::vector<int> m_fired;     // per event function: fired in this round
    std::vector<double> m_ydot;   // y' at the state the rules settled on
    Eigen::VectorXd m_qdBefore, m_jump, m_impulse, m_dqd;
    /// θ of m_data's position terms (kinematics, body inertias) as the last evaluate()
    /// left them: evaluate() at the same θ only updates the rates' terms. Every other
    /// writer of m_data's kinematics works at m_state.q, so a changed θ is seen here.
    Eigen::VectorXd m_positionsAt;

    /// Returns true when m_data, m_g and m_ydot hold the evaluation of the state it
    /// settled on (false: a mode changed after the last evaluation, or a loop locked).
    bool applyModeRules(std::vector<SimulationEvent>& events);
    void handleRoots(std::span<const int> fired, std::vector<SimulationEvent>& events);
    /// evaluate() with only some outputs (DynamicsOutputs: forward_dynamics.h).
    void evaluate(DynamicsOutputs outputs);
    /// Restarts the integrator at the current state; `settled`: applyModeRules' last
    /// evaluation is of this state (f and g are then handed over, not evaluated again).
    void resetIntegrator(bool settled);
    /// advanceTo() over a span in which no free joint's turns are folded.
    bool advanceSpan(double t, std::vector<SimulationEvent>& events, std::string& error, Text* errorText);
    void hitLimit(int joint, int side);
    void prescribeRates();
    /// Projects the state onto the constraints (positions, then velocities), moving
    /// the free coordinates that are not held. False when the positions cannot be
    /// brought within tolerance.
    bool project(const std::vector<char>& held);
    /// Per joint: 1 when its acceleration is not prescribed.
    std::vector<char> freeMask() const;
    /// project(), holding m_held (or nothing, when that fails).
    void assemble();
    void packState();
    void unpackState();
    /// Fluid power: the pressures that hold the initial pose at rest (the less-loaded
    /// chamber at 0) for every circuit without P0.
    void initialPressures();
    /// Fluid power: the relief, saturation and cavitation events since the last call,
    /// from data() at the current state.
    void fluidEvents(std::vector<SimulationEvent>& events);
    std::vector<int> m_fluidRelief;    // per circuit: +1 chamber A, −1 chamber B at the relief, 0
    std::vector<int> m_fluidCavitation;  // per circuit: Data::cavitation as last reported
    std::vector<char> m_pumpSaturated;   // per pump
    /// Contact: the deep overlaps since the last call (DeepContact), from data().
    void contactEvents(std::vector<SimulationEvent>& events);
    std::vector<std::pair<int, int>> m_deepContacts;  // the pairs reported deep (shape a, shape b)
};

}  // namespace solver
