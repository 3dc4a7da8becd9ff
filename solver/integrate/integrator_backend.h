#pragma once
// Private to solver/integrate: what the Integrator (integrator.cpp) shares with its
// backends, the fixed-step RK4 (rk4.cpp) and the SUNDIALS methods
// (sundials_backends.cpp). No SUNDIALS type appears here.
//
// Integrator::Impl owns one IntegratorShared (the system, the options, the counters,
// the time last returned, the failure) and one IntegratorBackend, which keeps a
// reference to it. Integrator checks the arguments and a previous failure, then makes
// one virtual call per reset() or advanceTo(); inside a step the backend calls the
// system through IntegratorShared's checked calls, which are not virtual.

#include "solver/core/diagnostic.h"
#include "solver/integrate/integrator.h"

#include <memory>
#include <string>
#include <vector>

namespace solver::detail {

/// How an OdeSystem call failed.
enum class FailureKind { None, RhsFalse, RhsNonFinite, RhsThrew, RootsFalse, RootsNonFinite, RootsThrew };

struct Failure {
    FailureKind kind = FailureKind::None;
    double t = 0;        ///< the time of the failing call [s]
    int component = -1;  ///< the non-finite component (NonFinite kinds), or −1
    double value = 0;    ///< its value
};

/// The state an Integrator and its backend share, and the checked calls of the system.
/// Everything here is written in integrator.cpp, once for all backends.
struct IntegratorShared {
    /// Reads size(), rootCount() and rootDirection() once. Throws std::invalid_argument
    /// for bad options or sizes (the Integrator constructor's contract).
    IntegratorShared(OdeSystem& system, const IntegratorOptions& options);

    OdeSystem& system;
    IntegratorOptions options;
    int n;                  ///< system.size()
    int nroots;             ///< system.rootCount()
    std::vector<int> dirs;  ///< per event function: +1 rising only, −1 falling only, 0 both
    IntegratorStats stats;
    std::vector<int> rootInfo;  ///< dim nroots; what AdvanceResult::rootsFired views

    double time = 0;  ///< the time last returned [s]
    bool initialised = false;
    bool failed = false;
    std::string failMessage;
    Text failText;  ///< failMessage, translatable
    int badComponent = -1;
    double failureTime = 0;
    Failure failure;  ///< why the last checked call returned false

    // The checked calls: the system's function, with an exception caught (SUNDIALS
    // must not see one) and every value tested for finiteness; false, with `failure`
    // set, on any failure. Each counts in `stats`.

    /// f(t, y) into ydot (dim n).
    bool callRhs(double t, const double* y, double* ydot);
    /// g(t, y) into g (dim nroots).
    bool callRoots(double t, const double* y, double* g);
    /// f and g at one state (OdeSystem::rhsAndRoots).
    bool callRhsAndRoots(double t, const double* y, double* ydot, double* g);

    /// The failure of the current advanceTo(): records it (advanceTo() fails from now
    /// on until reset()) and returns it at `time` (which the backend has left at
    /// the last return). `name` is the flag's name, `when` the time the backend
    /// reports [s], `userFunction` true when the system's call failed (`failure` says
    /// how), `backendMessage` the backend's own message (English, plain; "" when none).
    AdvanceResult fail(const std::string& name, bool userFunction, double when, const char* backendMessage);
};

/// One integration method behind Integrator. Integrator has already checked the
/// arguments (t0 and tout finite, tout > time() by more than a few ulps) and that no
/// failure is pending, cleared `failure` and `rootInfo` before advanceTo(), and does
/// the bookkeeping common to every reset() after it.
class IntegratorBackend {
public:
    virtual ~IntegratorBackend() = default;

    /// Restarts at t0 from y0 (dim n); ydot0 and g0 as for Integrator::reset (may be
    /// null). Throws std::runtime_error when the method cannot restart.
    virtual void reset(double t0, const double* y0, const double* ydot0, const double* g0) = 0;

    /// Integrates to tout or to the first root, as Integrator::advanceTo; sets the
    /// shared `time`, counters and failure.
    virtual AdvanceResult advanceTo(double tout, double* y) = 0;

    /// The state at the shared `time` (dim n).
    virtual const double* state() const = 0;
};

/// The fixed-step RK4 (rk4.cpp). Keeps `shared` by reference.
std::unique_ptr<IntegratorBackend> makeRk4Backend(IntegratorShared& shared);

/// ARKODE (Adaptive) or CVODE (AdaptiveStiff) after shared.options.method
/// (sundials_backends.cpp). Keeps `shared` by reference. Throws std::runtime_error
/// when SUNDIALS cannot be set up.
std::unique_ptr<IntegratorBackend> makeSundialsBackend(IntegratorShared& shared);

}  // namespace solver::detail
