#pragma once
// Simulation: advances a State of a compiled Model in time — applied forces,
// hybrid dynamics, drives, relief valves and joint limits as events — through
// the Integrator (SUNDIALS). One per thread: the solver thread, a test or the
// `padrob simulate` command each own theirs; the Model is shared read-only.
//
// Modes and events (issue 3 items 4 and 6):
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
// Each switch is reported as a SimulationEvent.
//
// Commands (u per joint in [−1, 1]) are read at the start of every advanceTo():
// a new command sets the prescribed rates at once (the valve spool moves) and
// restarts the integrator there. The free joints take the impulse of that jump
// (M_FF Δθ̇_F = −M_FP Δθ̇_P): a load hanging from a boom that starts to slew keeps
// its velocity in the world at that instant and starts to swing.

#include "solver/core/data.h"
#include "solver/core/model.h"
#include "solver/core/state.h"
#include "solver/integrate/integrator.h"

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
    enum class Kind { LimitHit, LimitLeave, ReliefOpen, ReliefClose };
    Kind kind = Kind::LimitHit;
    double t = 0;    ///< [s]
    int joint = 0;   ///< tree index
    int side = 0;    ///< limits: −1 lower, +1 upper; relief: +1 extending (fmax), −1 retracting (fmin)
    double value = 0;  ///< the limit (modeler coordinate) or the relief force [N or N m]

    /// One line, e.g. "t=1.2345 s: joint 2 LEVANTE PLUMA hit its upper limit 1.617 m".
    std::string describe(const Model& model) const;
};

/// The longest adaptive step a Simulation takes unless told otherwise [s].
inline constexpr double kDefaultMaxStep = 0.01;

class Simulation {
public:
    /// Starts at the model's initial state (makeState). Throws std::invalid_argument
    /// for bad integrator options.
    Simulation(std::shared_ptr<const Model> model, const SimulationOptions& options);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    const Model& model() const { return *m_model; }
    const State& state() const { return m_state; }
    /// Values derived at the current state (kinematics, forces, dynamics, reactions)
    /// after the last advanceTo() or evaluate().
    const Data& data() const { return m_data; }

    /// Sets joint i's command u in [−1, 1] (clamped), read by the next advanceTo().
    void setCommand(int joint, double u);
    /// Before the first advanceTo(): the initial θ and θ̇ of joint i (overrides QI/VI).
    void setInitial(int joint, double theta, double thetaDot);

    /// Integrates to time t (≥ current time). Events on the way are appended to
    /// `events`. Returns false with `error` set when the integration fails (a
    /// non-finite state names the time and the joint) or events chatter.
    bool advanceTo(double t, std::vector<SimulationEvent>& events, std::string& error);

    /// Recomputes data() at the current state.
    void evaluate();

private:
    class System;
    std::shared_ptr<const Model> m_model;
    SimulationOptions m_options;
    State m_state;
    Data m_data;
    std::unique_ptr<System> m_system;
    std::unique_ptr<Integrator> m_integrator;
    std::vector<double> m_y;
    bool m_restart = true;  // the integrator must be reset before the next step

    void applyModeRules(std::vector<SimulationEvent>& events);
    void handleRoots(std::span<const int> fired, std::vector<SimulationEvent>& events);
    void hitLimit(int joint, int side);
    void prescribeRates();
    Eigen::MatrixXd massMatrixNow();  ///< M at the current positions (events only: allocates)
    void packState();
    void unpackState();
};

}  // namespace solver
