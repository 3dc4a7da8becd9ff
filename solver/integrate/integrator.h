#pragma once
// Integrator: one small interface over SUNDIALS for y' = f(t, y) with event
// detection (root finding). Independent of the multibody code: the dynamics plug
// in through OdeSystem. No SUNDIALS type appears here (pimpl). integrator.cpp checks
// the calls and hands them to a backend (integrator_backend.h): rk4.cpp, or
// sundials_backends.cpp, the only file that includes SUNDIALS.
//
// Methods (IntegrationMethod):
//   Rk4Fixed       the real-time integrator: classic 4-stage Runge–Kutta with a
//                  fixed step, written out in rk4.cpp (no SUNDIALS: its
//                  general machinery cost as much as a small machine's dynamics;
//                  docs/performance.md), with the same events as below (Illinois on
//                  the step's cubic Hermite interpolant). 4 evaluations of f per
//                  step, f and g evaluated together at the step's end when there are
//                  events (OdeSystem::rhsAndRoots), 3 more per step when reset() is
//                  given f and g.
//   Adaptive       the accuracy integrator for the (non-stiff) multibody equations:
//                  ARKODE ARKStep explicit, Dormand–Prince 5(4), error-controlled
//                  by rtol/atol. A one-step method restarts for free after an event
//                  or an input change, which Padrob does every output step.
//   AdaptiveStiff  CVODE BDF (orders 1–5) with a dense direct linear solver and a
//                  difference-quotient Jacobian, for stiff models (stiff springs,
//                  dampers). Each reset() restarts it at order 1 with a small step:
//                  reset every 10 ms it needs 14 times the evaluations it needs
//                  without resets (oscillator, rtol 1e-10).
//
// Events: OdeSystem::roots() gives g(t, y) (dim rootCount()); a root is a sign change
// of a component of g. advanceTo() stops at the first root, located by SUNDIALS'
// root finder (Illinois method) on the method's interpolant, and returns the state
// there. The caller may change the state (a bounce) and must then call reset().
//
// Discontinuities: call reset(t, y) whenever the state jumps or f changes
// discontinuously (new inputs read at an output step, a drive switching mode).
// Without it CVODE keeps a multistep history built on the old f (it then fails
// with CV_ERR_FAILURE or loses accuracy), and ARKODE, although each step uses the
// new f, locates roots on an interpolant that mixes old and new f (measured: a
// root 1.6e-5 s off after an input change, exact with reset()).
//
// Units: time t [s]; y and its tolerances in the system's own units.
// Threads: one Integrator per thread; an Integrator and its OdeSystem are not shared.

#include "solver/core/diagnostic.h"

#include <memory>
#include <span>
#include <string>

namespace solver {

/// The system y' = f(t, y), with optional event functions g(t, y).
/// Called from inside SUNDIALS: implementations must not throw (an exception is
/// caught and turned into a failure) and should not allocate.
class OdeSystem {
public:
    virtual ~OdeSystem() = default;

    /// Number of state components n (> 0, constant for the life of an Integrator).
    virtual int size() const = 0;

    /// ydot = f(t, y). y and ydot have dim size(). Returns false when f cannot be
    /// evaluated (e.g. a NaN appeared); advanceTo() then fails at once, without
    /// retrying a smaller step. A non-finite component of ydot is treated the same.
    virtual bool rhs(double t, const double* y, double* ydot) = 0;

    /// Number of event functions (>= 0, constant for the life of an Integrator).
    virtual int rootCount() const { return 0; }

    /// g(t, y), dim rootCount(). Returns false on failure (the step fails).
    /// Must be continuous in t along a solution, or roots are found where g jumps.
    virtual bool roots(double t, const double* y, double* g)
    {
        (void)t;
        (void)y;
        (void)g;
        return true;
    }

    /// f and g at one state, for a system that computes both from the same work (the
    /// RK4 integrator asks for both at every step's end). The default calls rhs, then roots.
    virtual bool rhsAndRoots(double t, const double* y, double* ydot, double* g)
    {
        return rhs(t, y, ydot) && roots(t, y, g);
    }

    /// True when the RK4 integrator should evaluate f at every step's end through
    /// rhsAndRoots even without event functions (a system that keeps that evaluation for
    /// its own use, as Simulation does for its outputs). It is then also the next step's
    /// first stage.
    virtual bool evaluateAtStepEnds() const { return false; }

    /// Rk4Fixed: into how many equal sub-steps to cut the next step of length h (≥ 1),
    /// asked at the start of every step, after the system's last evaluation (a stiff
    /// part, such as a fluid-power circuit, keeps the fixed step stable this way). The
    /// default: 1.
    virtual int substeps(double h)
    {
        (void)h;
        return 1;
    }

    /// Which crossings of g_i to report: +1 only rising (g_i goes from − to +),
    /// −1 only falling, 0 both (the default). Read once, by the Integrator constructor.
    virtual int rootDirection(int i) const
    {
        (void)i;
        return 0;
    }
};

enum class IntegrationMethod { Rk4Fixed, Adaptive, AdaptiveStiff };

const char* integrationMethodName(IntegrationMethod m);  ///< "rk4", "adaptive", "adaptive-stiff"

struct IntegratorOptions {
    IntegrationMethod method = IntegrationMethod::Rk4Fixed;
    double step = 1e-3;  ///< Rk4Fixed: the step [s] (> 0); a step that would pass tout ends there
    double rtol = 1e-8;  ///< adaptive methods: relative tolerance (> 0)
    double atol = 1e-10;  ///< adaptive methods: absolute tolerance, every component (> 0)
    int maxSteps = 100000;  ///< most internal steps in one advanceTo() call (> 0)
    /// Adaptive methods: the longest internal step [s]; 0 = unlimited. Event functions
    /// are only sampled at step ends, so an event shorter than this can be missed.
    double maxStep = 0;
};

/// Counters since construction (reset() does not clear them), for benchmarks.
struct IntegratorStats {
    long steps = 0;  ///< accepted internal steps
    long rhsEvals = 0;  ///< calls of OdeSystem::rhs, including those for Jacobians
    long rootEvals = 0;  ///< calls of OdeSystem::roots
    long rootReturns = 0;  ///< advanceTo() calls that returned AdvanceStatus::Root
    long resets = 0;  ///< reset() calls
};

enum class AdvanceStatus {
    Reached,  ///< t == tout exactly; y is the state at tout
    Root,  ///< an event: t (<= tout) is the root time, y the state there
    Failed,  ///< SUNDIALS gave up (see message); t, y and time() are left as before the call
};

struct AdvanceResult {
    AdvanceStatus status = AdvanceStatus::Reached;
    double t = 0;  ///< time reached [s]
    /// Root only: per event function, +1 if g_i crossed rising, −1 falling, 0 if it
    /// did not fire (dim rootCount()). Points into the Integrator; valid until its
    /// next advanceTo() or reset(). Empty for Reached and Failed.
    std::span<const int> rootsFired;
    /// Failed only: the SUNDIALS flag name, the time SUNDIALS reports (for ARKODE
    /// the failing stage's time) and the cause, e.g. "ARK_RHSFUNC_FAIL at t = 0.25 s:
    /// the right-hand side gave a non-finite value in component 1 (nan) at t = 0.25 s
    /// [ARKODE: At t = 0.25, the right-hand side routine failed in an unrecoverable manner.]".
    std::string message;
    /// Failed only: `message`, translatable (the flag name, numbers and SUNDIALS' own
    /// text stay plain): messageText.english() == message.
    Text messageText;
    /// Failed only: the state component whose derivative was not finite, or −1.
    int badComponent = -1;
    /// Failed only: the time SUNDIALS reports for the failure [s] (ARKODE: the
    /// failing stage's time; CVODE: the last successful step's), >= t.
    double failureTime = 0;

    bool ok() const { return status != AdvanceStatus::Failed; }
};

/// RAII owner of one SUNDIALS solver (context, vectors, solver memory, linear
/// solver) for one OdeSystem. Not copyable; movable (a moved-from Integrator may
/// only be destroyed or assigned to).
class Integrator {
public:
    /// Sets up the solver for `system` (kept by reference; must outlive the
    /// Integrator). Reads size(), rootCount() and rootDirection() once.
    /// Throws std::invalid_argument for bad options or sizes, std::runtime_error
    /// when SUNDIALS cannot be set up. Call reset() before advanceTo().
    Integrator(OdeSystem& system, const IntegratorOptions& options);
    ~Integrator();
    Integrator(Integrator&&) noexcept;
    Integrator& operator=(Integrator&&) noexcept;
    Integrator(const Integrator&) = delete;
    Integrator& operator=(const Integrator&) = delete;

    /// (Re)starts the integration at t0 [s] (finite) from y0 (dim size()): at the
    /// start, after an event changed the state, or when f changed discontinuously
    /// (see top of file). Clears a previous failure. Cheap for Rk4Fixed and Adaptive
    /// (one f evaluation); AdaptiveStiff restarts its multistep history. A y0 that is
    /// not finite is not checked here: the next advanceTo() fails.
    ///
    /// `ydot0` and `g0`, when given, are f(t0, y0) and g(t0, y0) (dim size() and
    /// rootCount()), which the caller has already computed: RK4 takes them instead of
    /// evaluating them again; the SUNDIALS methods ignore them.
    void reset(double t0, const double* y0, const double* ydot0 = nullptr, const double* g0 = nullptr);

    /// Integrates from the current time to tout [s] (>= time(), finite), stopping
    /// exactly at tout (never stepping past it, so inputs read per output step are
    /// honoured) or earlier at a root. Writes the state at the returned time into y
    /// (dim size()); on Failed y is not written. After Failed, further calls fail
    /// until reset().
    /// Throws std::logic_error before the first reset(), std::invalid_argument for
    /// tout < time() or a non-finite tout.
    AdvanceResult advanceTo(double tout, double* y);

    double time() const;  ///< the time last returned by advanceTo() or set by reset() [s]
    int size() const;  ///< n
    int rootCount() const;
    const IntegratorOptions& options() const;
    const IntegratorStats& stats() const;

private:
    class Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace solver
