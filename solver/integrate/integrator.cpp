#include "solver/integrate/integrator.h"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher_dirk.h>
#include <arkode/arkode_butcher_erk.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_version.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace solver {

// the flag values the code below tests are the same in ARKODE and CVODE
static_assert(ARK_SUCCESS == CV_SUCCESS && ARK_TSTOP_RETURN == CV_TSTOP_RETURN &&
              ARK_ROOT_RETURN == CV_ROOT_RETURN && ARK_WARNING == CV_WARNING);
static_assert(ARK_RHSFUNC_FAIL == CV_RHSFUNC_FAIL &&
              ARK_FIRST_RHSFUNC_ERR == CV_FIRST_RHSFUNC_ERR &&
              ARK_REPTD_RHSFUNC_ERR == CV_REPTD_RHSFUNC_ERR &&
              ARK_UNREC_RHSFUNC_ERR == CV_UNREC_RHSFUNC_ERR && ARK_RTFUNC_FAIL == CV_RTFUNC_FAIL);
static_assert(std::is_same_v<sunrealtype, double>, "Padrob needs SUNDIALS built with double");

const char* integrationMethodName(IntegrationMethod m)
{
    switch (m) {
    case IntegrationMethod::Rk4Fixed: return "rk4";
    case IntegrationMethod::Adaptive: return "adaptive";
    case IntegrationMethod::AdaptiveStiff: return "adaptive-stiff";
    }
    return "?";
}

namespace {

// ---- RAII owners of SUNDIALS objects ------------------------------------------

struct ContextDeleter {
    void operator()(SUNContext ctx) const { SUNContext_Free(&ctx); }
};
using ContextPtr = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter>;

struct VectorDeleter {
    void operator()(N_Vector v) const { N_VDestroy(v); }
};
using VectorPtr = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;

struct MatrixDeleter {
    void operator()(SUNMatrix a) const { SUNMatDestroy(a); }
};
using MatrixPtr = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;

struct LinearSolverDeleter {
    void operator()(SUNLinearSolver ls) const { SUNLinSolFree(ls); }
};
using LinearSolverPtr =
    std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, LinearSolverDeleter>;

struct ArkodeMemDeleter {
    void operator()(void* mem) const { ARKStepFree(&mem); }
};
struct CvodeMemDeleter {
    void operator()(void* mem) const { CVodeFree(&mem); }
};

ContextPtr makeContext()
{
    SUNContext ctx = nullptr;
#if SUNDIALS_VERSION_MAJOR >= 7
    const int flag = SUNContext_Create(SUN_COMM_NULL, &ctx);
#else
    const int flag = SUNContext_Create(nullptr, &ctx);
#endif
    if (flag != 0 || ctx == nullptr) throw std::runtime_error("SUNContext_Create failed");
    return ContextPtr(ctx);
}

/// The flag's name; the SUNDIALS getters return a malloc'd string.
std::string flagName(char* (*getName)(long int), int flag)
{
    char* name = getName(flag);
    std::string s = name != nullptr ? name : "UNKNOWN_FLAG";
    std::free(name);
    return s;
}

std::string formatTime(double t)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", t);
    return buf;
}

// ---- the solver behind the interface -------------------------------------------

/// One SUNDIALS package driven through the few calls Integrator needs.
/// Every function returns the package's flag.
class Backend {
public:
    virtual ~Backend() = default;
    virtual int reinit(double t0, N_Vector y0) = 0;
    virtual int setStopTime(double tstop) = 0;
    virtual int evolve(double tout, N_Vector yout, double* tret) = 0;
    /// The solver's internal time (may be past the last returned one).
    virtual double currentTime() = 0;
    /// Steps since creation (ARKODE) or since the last reinit (CVODE).
    virtual long numSteps() = 0;
    virtual int rootInfo(int* info) = 0;
    virtual std::string flagName(int flag) const = 0;
};

struct Callbacks {
    void* userData;
    ARKRhsFn rhs;  // same signature as CVRhsFn
    ARKRootFn roots;  // same signature as CVRootFn
    ARKErrHandlerFn errorHandler;  // same signature as CVErrHandlerFn
    const char* (*lastError)(void* userData);
};

/// ARKODE ARKStep, explicit: Dormand–Prince 5(4) with error control.
class ArkodeBackend final : public Backend {
public:
    ArkodeBackend(SUNContext ctx, N_Vector y, const IntegratorOptions& opt, std::vector<int> dirs,
                  const Callbacks& cb)
        : m_cb(cb)
    {
        m_mem.reset(ARKStepCreate(cb.rhs, nullptr, 0.0, y, ctx));
        if (!m_mem) throw std::runtime_error("ARKStepCreate failed");
        void* mem = m_mem.get();
        check(ARKStepSetErrHandlerFn(mem, cb.errorHandler, cb.userData), "ARKStepSetErrHandlerFn");
        check(ARKStepSetUserData(mem, cb.userData), "ARKStepSetUserData");
        check(ARKStepSetMaxNumSteps(mem, opt.maxSteps), "ARKStepSetMaxNumSteps");
        check(ARKStepSStolerances(mem, opt.rtol, opt.atol), "ARKStepSStolerances");
        if (opt.maxStep > 0) check(ARKStepSetMaxStep(mem, opt.maxStep), "ARKStepSetMaxStep");
        check(ARKStepSetTableNum(mem, ARKODE_DIRK_NONE, ARKODE_DORMAND_PRINCE_7_4_5), "ARKStepSetTableNum");
        if (!dirs.empty()) {
            check(ARKStepRootInit(mem, static_cast<int>(dirs.size()), cb.roots), "ARKStepRootInit");
            check(ARKStepSetRootDirection(mem, dirs.data()), "ARKStepSetRootDirection");
            check(ARKStepSetNoInactiveRootWarn(mem), "ARKStepSetNoInactiveRootWarn");
        }
    }

    int reinit(double t0, N_Vector y0) override { return ARKStepReset(m_mem.get(), t0, y0); }
    int setStopTime(double tstop) override { return ARKStepSetStopTime(m_mem.get(), tstop); }
    int evolve(double tout, N_Vector yout, double* tret) override
    {
        return ARKStepEvolve(m_mem.get(), tout, yout, tret, ARK_NORMAL);
    }
    double currentTime() override
    {
        sunrealtype t = 0;
        ARKStepGetCurrentTime(m_mem.get(), &t);
        return t;
    }
    long numSteps() override
    {
        long n = 0;
        ARKStepGetNumSteps(m_mem.get(), &n);
        return n;
    }
    int rootInfo(int* info) override { return ARKStepGetRootInfo(m_mem.get(), info); }
    std::string flagName(int flag) const override
    {
        return solver::flagName(ARKStepGetReturnFlagName, flag);
    }

private:
    void check(int flag, const char* call) const
    {
        if (flag == ARK_SUCCESS) return;
        throw std::runtime_error(std::string(call) + " failed: " + flagName(flag) + " " +
                                 m_cb.lastError(m_cb.userData));
    }

    Callbacks m_cb;
    std::unique_ptr<void, ArkodeMemDeleter> m_mem;
};

/// CVODE BDF with a dense direct linear solver (difference-quotient Jacobian).
class CvodeBackend final : public Backend {
public:
    CvodeBackend(SUNContext ctx, N_Vector y, const IntegratorOptions& opt, std::vector<int> dirs,
                 const Callbacks& cb)
        : m_cb(cb)
    {
        const sunindextype n = N_VGetLength(y);
        m_a.reset(SUNDenseMatrix(n, n, ctx));
        if (!m_a) throw std::runtime_error("SUNDenseMatrix failed");
        m_ls.reset(SUNLinSol_Dense(y, m_a.get(), ctx));
        if (!m_ls) throw std::runtime_error("SUNLinSol_Dense failed");
        m_mem.reset(CVodeCreate(CV_BDF, ctx));
        if (!m_mem) throw std::runtime_error("CVodeCreate failed");
        void* mem = m_mem.get();
        check(CVodeSetErrHandlerFn(mem, cb.errorHandler, cb.userData), "CVodeSetErrHandlerFn");
        check(CVodeInit(mem, cb.rhs, 0.0, y), "CVodeInit");
        check(CVodeSetUserData(mem, cb.userData), "CVodeSetUserData");
        check(CVodeSStolerances(mem, opt.rtol, opt.atol), "CVodeSStolerances");
        check(CVodeSetMaxNumSteps(mem, opt.maxSteps), "CVodeSetMaxNumSteps");
        if (opt.maxStep > 0) check(CVodeSetMaxStep(mem, opt.maxStep), "CVodeSetMaxStep");
        check(CVodeSetLinearSolver(mem, m_ls.get(), m_a.get()), "CVodeSetLinearSolver");
        if (!dirs.empty()) {
            check(CVodeRootInit(mem, static_cast<int>(dirs.size()), cb.roots), "CVodeRootInit");
            check(CVodeSetRootDirection(mem, dirs.data()), "CVodeSetRootDirection");
            check(CVodeSetNoInactiveRootWarn(mem), "CVodeSetNoInactiveRootWarn");
        }
    }

    int reinit(double t0, N_Vector y0) override { return CVodeReInit(m_mem.get(), t0, y0); }
    int setStopTime(double tstop) override { return CVodeSetStopTime(m_mem.get(), tstop); }
    int evolve(double tout, N_Vector yout, double* tret) override
    {
        return CVode(m_mem.get(), tout, yout, tret, CV_NORMAL);
    }
    double currentTime() override
    {
        sunrealtype t = 0;
        CVodeGetCurrentTime(m_mem.get(), &t);
        return t;
    }
    long numSteps() override
    {
        long n = 0;
        CVodeGetNumSteps(m_mem.get(), &n);
        return n;
    }
    int rootInfo(int* info) override { return CVodeGetRootInfo(m_mem.get(), info); }
    std::string flagName(int flag) const override
    {
        return solver::flagName(CVodeGetReturnFlagName, flag);
    }

private:
    void check(int flag, const char* call) const
    {
        if (flag == CV_SUCCESS) return;
        throw std::runtime_error(std::string(call) + " failed: " + flagName(flag) + " " +
                                 m_cb.lastError(m_cb.userData));
    }

    Callbacks m_cb;
    MatrixPtr m_a;
    LinearSolverPtr m_ls;
    std::unique_ptr<void, CvodeMemDeleter> m_mem;  // freed first
};

bool isUserFunctionFailure(int flag)
{
    return flag == ARK_RHSFUNC_FAIL || flag == ARK_FIRST_RHSFUNC_ERR ||
           flag == ARK_REPTD_RHSFUNC_ERR || flag == ARK_UNREC_RHSFUNC_ERR ||
           flag == ARK_RTFUNC_FAIL;
}

}  // namespace

// ---- Integrator ----------------------------------------------------------------

class Integrator::Impl {
public:
    Impl(OdeSystem& system, const IntegratorOptions& options)
        : m_system(system), m_options(options), m_n(system.size()), m_nroots(system.rootCount())
    {
        validate();
        m_rootInfo.assign(static_cast<std::size_t>(m_nroots), 0);
        std::vector<int> dirs(static_cast<std::size_t>(m_nroots), 0);
        for (int i = 0; i < m_nroots; ++i) {
            const int d = system.rootDirection(i);
            dirs[static_cast<std::size_t>(i)] = d > 0 ? 1 : (d < 0 ? -1 : 0);
        }

        m_dirs = dirs;
        m_endEvaluation = system.evaluateAtStepEnds();
        if (m_options.method == IntegrationMethod::Rk4Fixed) {
            // the real-time integrator is written out here (see Rk4 below): no SUNDIALS
            for (std::vector<double>* v : {&m_yt, &m_ya, &m_fa, &m_yb, &m_fb, &m_k2, &m_k3, &m_k4, &m_stage, &m_yi})
                v->assign(static_cast<std::size_t>(m_n), 0.0);
            for (std::vector<double>* v : {&m_gt, &m_gb, &m_glo, &m_ghi, &m_gmid})
                v->assign(static_cast<std::size_t>(m_nroots), 0.0);
            return;
        }
        m_ctx = makeContext();
        m_y.reset(N_VNew_Serial(m_n, m_ctx.get()));
        if (!m_y) throw std::runtime_error("N_VNew_Serial failed");
        N_VConst(0.0, m_y.get());

        const Callbacks cb{this, &Impl::rhsTrampoline, &Impl::rootsTrampoline, &Impl::errorHandler,
                           &Impl::lastError};
        if (m_options.method == IntegrationMethod::AdaptiveStiff) {
            m_backend = std::make_unique<CvodeBackend>(m_ctx.get(), m_y.get(), m_options, dirs, cb);
        } else {
            m_backend =
                std::make_unique<ArkodeBackend>(m_ctx.get(), m_y.get(), m_options, dirs, cb);
        }
    }

    void reset(double t0, const double* y0, const double* ydot0, const double* g0)
    {
        if (!std::isfinite(t0)) throw std::invalid_argument("Integrator::reset: t0 is not finite");
        if (!m_backend) {
            rk4Reset(t0, y0, ydot0, g0);
            return;
        }
        std::copy(y0, y0 + m_n, N_VGetArrayPointer(m_y.get()));
        m_sundialsMessage[0] = '\0';
        const int flag = m_backend->reinit(t0, m_y.get());
        if (flag < 0) {
            throw std::runtime_error("Integrator::reset: " + m_backend->flagName(flag) + " " +
                                     m_sundialsMessage);
        }
        m_stepsSeen = m_backend->numSteps();
        m_t = t0;
        m_initialised = true;
        m_failed = false;
        m_failMessage.clear();
        m_failText = {};
        m_badComponent = -1;
        std::fill(m_rootInfo.begin(), m_rootInfo.end(), 0);
        ++m_stats.resets;
    }

    AdvanceResult advanceTo(double tout, double* y)
    {
        if (!m_initialised) throw std::logic_error("Integrator::advanceTo before reset()");
        if (!std::isfinite(tout))
            throw std::invalid_argument("Integrator::advanceTo: tout is not finite");
        if (tout < m_t) {
            throw std::invalid_argument("Integrator::advanceTo: tout " + formatTime(tout) +
                                        " is behind the current time " + formatTime(m_t));
        }
        AdvanceResult r;
        if (m_failed) {
            r.status = AdvanceStatus::Failed;
            r.t = m_t;
            r.message = m_failMessage;
            r.messageText = m_failText;
            r.badComponent = m_badComponent;
            r.failureTime = m_failureTime;
            return r;
        }
        if (!m_backend) return rk4Advance(tout, y);
        double* yv = N_VGetArrayPointer(m_y.get());
        // a step of a few ulps is refused by SUNDIALS (TOO_CLOSE); it changes nothing
        if (tout - m_t <= 4 * DBL_EPSILON * std::max(std::abs(tout), std::abs(m_t))) {
            m_t = tout;
            r.t = tout;
            std::copy(yv, yv + m_n, y);
            return r;
        }

        m_failure = {};
        m_sundialsMessage[0] = '\0';
        std::fill(m_rootInfo.begin(), m_rootInfo.end(), 0);
        // never step past tout; when the last step already passed it (after a root
        // return) the solver interpolates and a stop time behind it would be refused
        int flag = ARK_SUCCESS;
        if (tout > m_backend->currentTime()) flag = m_backend->setStopTime(tout);
        double tret = m_t;
        if (flag == ARK_SUCCESS) flag = m_backend->evolve(tout, m_y.get(), &tret);

        const long steps = m_backend->numSteps();
        m_stats.steps += steps - m_stepsSeen;
        m_stepsSeen = steps;

        if (flag < 0) {
            // y and time() stay those of the previous return: on failure ARKODE
            // reports the failing stage's time with the state from the step's start
            m_failed = true;
            m_failText = failureMessage(m_backend->flagName(flag), isUserFunctionFailure(flag), tret);
            m_failMessage = m_failText.english();
            m_badComponent = isUserFunctionFailure(flag) ? m_failure.component : -1;
            m_failureTime = std::max(tret, m_t);
            r.status = AdvanceStatus::Failed;
            r.t = m_t;
            r.message = m_failMessage;
            r.messageText = m_failText;
            r.badComponent = m_badComponent;
            r.failureTime = m_failureTime;
            return r;
        }
        if (flag == ARK_ROOT_RETURN) {
            m_backend->rootInfo(m_rootInfo.data());
            ++m_stats.rootReturns;
            m_t = tret;
            r.status = AdvanceStatus::Root;
            r.t = tret;
            r.rootsFired = std::span<const int>(m_rootInfo);
        } else {
            m_t = tout;  // tret == tout at a stop-time or interpolated return
            r.t = tout;
        }
        std::copy(yv, yv + m_n, y);
        return r;
    }

    double time() const { return m_t; }
    int size() const { return m_n; }
    int rootCount() const { return m_nroots; }
    const IntegratorOptions& options() const { return m_options; }
    const IntegratorStats& stats() const { return m_stats; }

private:
    enum class FailureKind {
        None,
        RhsFalse,
        RhsNonFinite,
        RhsThrew,
        RootsFalse,
        RootsNonFinite,
        RootsThrew
    };
    struct Failure {
        FailureKind kind = FailureKind::None;
        double t = 0;
        int component = -1;
        double value = 0;
    };

    void validate() const
    {
        auto bad = [](const std::string& what) {
            throw std::invalid_argument("Integrator: " + what);
        };
        if (m_n <= 0) bad("the system's size() must be positive");
        if (m_nroots < 0) bad("the system's rootCount() must not be negative");
        if (!(m_options.maxSteps > 0)) bad("maxSteps must be positive");
        if (!(m_options.maxStep >= 0) || !std::isfinite(m_options.maxStep))
            bad("maxStep must be zero (unlimited) or positive");
        if (m_options.method == IntegrationMethod::Rk4Fixed) {
            if (!(std::isfinite(m_options.step) && m_options.step > 0))
                bad("step must be positive and finite");
        } else {
            if (!(std::isfinite(m_options.rtol) && m_options.rtol > 0))
                bad("rtol must be positive and finite");
            if (!(std::isfinite(m_options.atol) && m_options.atol > 0))
                bad("atol must be positive and finite");
        }
    }

    void recordFailure(FailureKind kind, double t, int component = -1, double value = 0)
    {
        m_failure = Failure{kind, t, component, value};
    }

    /// Why the last step failed: the flag's name and time, the cause when it was
    /// OdeSystem's, and SUNDIALS' own message (English, plain) in brackets.
    Text failureMessage(const std::string& name, bool userFunctionFailure, double tret) const
    {
        Text cause;
        if (userFunctionFailure) {
            const Failure& f = m_failure;
            const std::string at = formatTime(f.t);
            char value[40];
            std::snprintf(value, sizeof value, "%g", f.value);
            switch (f.kind) {
            case FailureKind::RhsFalse:
                cause = trText("Diagnostics", "the right-hand side reported a failure at t = %1 s").with(at);
                break;
            case FailureKind::RhsNonFinite:
                cause = trText("Diagnostics", "the right-hand side gave a non-finite value in component %1 (%2) at t = %3 s")
                            .with(std::to_string(f.component))
                            .with(value)
                            .with(at);
                break;
            case FailureKind::RhsThrew:
                cause = trText("Diagnostics", "the right-hand side threw an exception at t = %1 s").with(at);
                break;
            case FailureKind::RootsFalse:
                cause = trText("Diagnostics", "the event functions reported a failure at t = %1 s").with(at);
                break;
            case FailureKind::RootsNonFinite:
                cause = trText("Diagnostics", "event function %1 is not finite (%2) at t = %3 s")
                            .with(std::to_string(f.component))
                            .with(value)
                            .with(at);
                break;
            case FailureKind::RootsThrew:
                cause = trText("Diagnostics", "the event functions threw an exception at t = %1 s").with(at);
                break;
            case FailureKind::None: break;
            }
        }
        const std::string when = formatTime(tret);
        const bool sundials = m_sundialsMessage[0] != '\0';
        if (cause.empty()) {
            if (!sundials) return trText("Diagnostics", "%1 at t = %2 s").with(name).with(when);
            return trText("Diagnostics", "%1 at t = %2 s [%3]").with(name).with(when).with(m_sundialsMessage);
        }
        if (!sundials) return trText("Diagnostics", "%1 at t = %2 s: %3").with(name).with(when).with(std::move(cause));
        return trText("Diagnostics", "%1 at t = %2 s: %3 [%4]")
            .with(name)
            .with(when)
            .with(std::move(cause))
            .with(m_sundialsMessage);
    }

    // ---- trampolines: SUNDIALS calls these with user_data = this ---------------
    // Every failure is unrecoverable (return −1). A recoverable one (> 0) makes an
    // adaptive method retry smaller steps; when f fails from a fixed time on, CVODE
    // then creeps towards that time until mxstep (measured: 276 000 evaluations and
    // CV_TOO_MUCH_WORK instead of the cause).

    /// Calls `f` (the system's rhs, roots or both) as SUNDIALS would: an exception is
    /// `threw`, a false return `failed`; true when it returned true. m_failure says why not.
    template <class F>
    bool guarded(F&& f, double t, FailureKind threw, FailureKind failed)
    {
        bool ok = false;
        try {
            ok = f();
        } catch (...) {
            recordFailure(threw, t);
            return false;
        }
        if (!ok) recordFailure(failed, t);
        return ok;
    }

    /// True when the n values are finite; else records `kind` at the first that is not.
    bool finite(const double* values, int n, FailureKind kind, double t)
    {
        for (int i = 0; i < n; ++i) {
            if (!std::isfinite(values[i])) {
                recordFailure(kind, t, i, values[i]);
                return false;
            }
        }
        return true;
    }

    /// f(t, y) into ydot, checked; false (with m_failure set) on any failure.
    bool callRhs(double t, const double* y, double* ydot)
    {
        ++m_stats.rhsEvals;
        return guarded([&] { return m_system.rhs(t, y, ydot); }, t, FailureKind::RhsThrew, FailureKind::RhsFalse) &&
               finite(ydot, m_n, FailureKind::RhsNonFinite, t);
    }

    /// g(t, y) into g, checked; false (with m_failure set) on any failure.
    bool callRoots(double t, const double* y, double* g)
    {
        ++m_stats.rootEvals;
        return guarded([&] { return m_system.roots(t, y, g); }, t, FailureKind::RootsThrew,
                       FailureKind::RootsFalse) &&
               finite(g, m_nroots, FailureKind::RootsNonFinite, t);
    }

    /// f and g at one state (OdeSystem::rhsAndRoots), checked.
    bool callRhsAndRoots(double t, const double* y, double* ydot, double* g)
    {
        ++m_stats.rhsEvals;
        if (m_nroots > 0) ++m_stats.rootEvals;
        return guarded([&] { return m_system.rhsAndRoots(t, y, ydot, g); }, t, FailureKind::RhsThrew,
                       FailureKind::RhsFalse) &&
               finite(ydot, m_n, FailureKind::RhsNonFinite, t) && finite(g, m_nroots, FailureKind::RootsNonFinite, t);
    }

    static int rhsTrampoline(sunrealtype t, N_Vector y, N_Vector ydot, void* userData)
    {
        auto* self = static_cast<Impl*>(userData);
        return self->callRhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)) ? 0 : -1;
    }

    static int rootsTrampoline(sunrealtype t, N_Vector y, sunrealtype* g, void* userData)
    {
        auto* self = static_cast<Impl*>(userData);
        return self->callRoots(t, N_VGetArrayPointer(y), g) ? 0 : -1;
    }

    // ---- RK4 ------------------------------------------------------------------------
    // The classic four-stage Runge–Kutta method with a fixed step, written out: for the
    // real-time step of a machine of a few bodies ARKODE's general machinery (vector
    // operations through function tables, its root-finding and interpolation
    // bookkeeping, the extra evaluations around a reset) cost as much as the dynamics
    // (docs/performance.md). The same behaviour as the ARKODE version it replaces:
    //   - a step of options.step, shortened to end exactly at tout;
    //   - events: g is evaluated at every step's end (together with f there, which is
    //     the next step's first stage); a sign change in the allowed direction is
    //     located by the Illinois method on the step's cubic Hermite interpolant (as
    //     SUNDIALS does), to 100 ulps of t; the state there is returned with the
    //     components that fired. The step already taken is kept: the next call goes on
    //     from the root (further roots in the same step, or the interpolant up to an
    //     earlier tout) without changing the grid of steps;
    //   - a g_i exactly zero at the start of an interval does not fire until it has
    //     left zero (a root just returned is not returned again).
    // After reset(t, y, f, g) with f and g given, the first step needs no evaluation at
    // its start: 3 evaluations of f and one of f and g together per step.

    void rk4Reset(double t0, const double* y0, const double* ydot0, const double* g0)
    {
        std::copy(y0, y0 + m_n, m_ya.begin());
        std::copy(y0, y0 + m_n, m_yt.begin());
        m_ta = t0;
        m_t = t0;
        m_haveFa = ydot0 != nullptr;
        if (m_haveFa) std::copy(ydot0, ydot0 + m_n, m_fa.begin());
        m_haveGt = g0 != nullptr && m_nroots > 0;
        if (m_haveGt) std::copy(g0, g0 + m_nroots, m_gt.begin());
        m_pending = false;
        m_initialised = true;
        m_failed = false;
        m_failMessage.clear();
        m_failText = {};
        m_badComponent = -1;
        std::fill(m_rootInfo.begin(), m_rootInfo.end(), 0);
        ++m_stats.resets;
    }

    /// The cubic Hermite interpolant of the pending step [m_ta, m_tb] at t, into out.
    void hermite(double t, double* out) const
    {
        const double h = m_tb - m_ta;
        const double s = (t - m_ta) / h;
        const double s2 = s * s, s3 = s2 * s;
        const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s;
        const double h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
        for (int i = 0; i < m_n; ++i) {
            out[i] = h00 * m_ya[i] + h10 * h * m_fa[i] + h01 * m_yb[i] + h11 * h * m_fb[i];
        }
        if (t == m_tb) std::copy(m_yb.begin(), m_yb.end(), out);
        if (t == m_ta) std::copy(m_ya.begin(), m_ya.end(), out);
    }

    /// Did g_i cross zero from lo to hi in the direction allowed? +1 rising, −1 falling, 0 not.
    int crossing(int i, double lo, double hi) const
    {
        int c = 0;
        if (lo < 0 && hi >= 0) c = +1;
        if (lo > 0 && hi <= 0) c = -1;
        const int dir = m_dirs[static_cast<std::size_t>(i)];
        return dir == 0 || dir == c ? c : 0;
    }

    bool anyCrossing(const std::vector<double>& lo, const std::vector<double>& hi) const
    {
        for (int i = 0; i < m_nroots; ++i) {
            if (crossing(i, lo[i], hi[i]) != 0) return true;
        }
        return false;
    }

    /// Fails the call: the message, the time, the component; y and time() untouched.
    AdvanceResult rk4Fail(const char* name, bool userFunction, double when)
    {
        m_t = m_callStart;  // time() stays that of the last return (the steps taken are void)
        m_failed = true;
        m_failText = failureMessage(name, userFunction, when);
        m_failMessage = m_failText.english();
        m_badComponent = userFunction ? m_failure.component : -1;
        m_failureTime = std::max(when, m_t);
        AdvanceResult r;
        r.status = AdvanceStatus::Failed;
        r.t = m_t;
        r.message = m_failMessage;
        r.messageText = m_failText;
        r.badComponent = m_badComponent;
        r.failureTime = m_failureTime;
        return r;
    }

    AdvanceResult rk4UserFailure()
    {
        const bool roots = m_failure.kind == FailureKind::RootsFalse || m_failure.kind == FailureKind::RootsNonFinite ||
                           m_failure.kind == FailureKind::RootsThrew;
        return rk4Fail(roots ? "RK4_RTFUNC_FAIL" : "RK4_RHSFUNC_FAIL", true, m_failure.t);
    }

    AdvanceResult rk4Advance(double tout, double* y)
    {
        AdvanceResult r;
        // a step of a few ulps changes nothing
        if (tout - m_t <= 4 * DBL_EPSILON * std::max(std::abs(tout), std::abs(m_t))) {
            m_t = tout;
            r.t = tout;
            std::copy(m_yt.begin(), m_yt.end(), y);
            return r;
        }
        m_failure = {};
        std::fill(m_rootInfo.begin(), m_rootInfo.end(), 0);
        m_callStart = m_t;
        long steps = 0;
        while (true) {
            if (!m_pending) {
                // a new step from (m_ta, m_ya) = (m_t, m_yt)
                if (steps >= m_options.maxSteps) {
                    return rk4Fail("RK4_TOO_MUCH_WORK", false, m_ta);
                }
                double h = m_options.step;
                double tb = m_ta + h;
                if (tb >= tout - 4 * DBL_EPSILON * std::abs(tout)) {
                    tb = tout;
                    h = tout - m_ta;
                }
                if (!m_haveFa || (m_nroots > 0 && !m_haveGt)) {
                    const bool ok = m_nroots > 0 ? callRhsAndRoots(m_ta, m_ya.data(), m_fa.data(), m_gt.data())
                                                 : callRhs(m_ta, m_ya.data(), m_fa.data());
                    if (!ok) return rk4UserFailure();
                    m_haveFa = true;
                    m_haveGt = m_nroots > 0;
                }
                const double* ya = m_ya.data();
                const double* k1 = m_fa.data();
                double* st = m_stage.data();
                for (int i = 0; i < m_n; ++i) st[i] = ya[i] + 0.5 * h * k1[i];
                if (!callRhs(m_ta + 0.5 * h, st, m_k2.data())) return rk4UserFailure();
                const double* k2 = m_k2.data();
                for (int i = 0; i < m_n; ++i) st[i] = ya[i] + 0.5 * h * k2[i];
                if (!callRhs(m_ta + 0.5 * h, st, m_k3.data())) return rk4UserFailure();
                const double* k3 = m_k3.data();
                for (int i = 0; i < m_n; ++i) st[i] = ya[i] + h * k3[i];
                if (!callRhs(tb, st, m_k4.data())) return rk4UserFailure();
                const double* k4 = m_k4.data();
                for (int i = 0; i < m_n; ++i) m_yb[i] = ya[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
                m_tb = tb;
                ++steps;
                ++m_stats.steps;
                // f there (the next step's first stage) with g, when there are events
                m_haveFb = false;
                if (m_nroots > 0 || m_endEvaluation) {
                    if (!callRhsAndRoots(tb, m_yb.data(), m_fb.data(), m_gb.data())) return rk4UserFailure();
                    m_haveFb = true;
                }
                m_pending = true;
            }

            // the pending step [m_ta, m_tb], returned up to m_t (g there: m_gt)
            const double tEnd = std::min(m_tb, tout);
            if (m_nroots > 0) {
                if (tEnd == m_tb) {
                    m_ghi = m_gb;
                } else {
                    if (!ensureFb()) return rk4UserFailure();
                    hermite(tEnd, m_yi.data());
                    if (!callRoots(tEnd, m_yi.data(), m_ghi.data())) return rk4UserFailure();
                }
                if (anyCrossing(m_gt, m_ghi)) {
                    if (!ensureFb()) return rk4UserFailure();
                    return rk4Root(tEnd, y);
                }
            }
            if (tEnd < m_tb) {
                // tout inside the step (after a root): the interpolant there
                if (!ensureFb()) return rk4UserFailure();
                hermite(tout, m_yt.data());
                if (m_nroots > 0) m_gt = m_ghi;
                m_t = tout;
                r.t = tout;
                std::copy(m_yt.begin(), m_yt.end(), y);
                return r;
            }
            // the step is done: the next one starts at its end
            m_ta = m_tb;
            m_t = m_tb;
            std::swap(m_ya, m_yb);
            m_yt = m_ya;
            m_haveFa = m_haveFb;
            if (m_haveFa) std::swap(m_fa, m_fb);
            if (m_nroots > 0) m_gt = m_gb;
            m_haveGt = m_nroots > 0;
            m_pending = false;
            if (m_tb == tout) {
                r.t = tout;
                std::copy(m_yt.begin(), m_yt.end(), y);
                return r;
            }
        }
    }

    /// f at the pending step's end, for the interpolant (evaluated when not yet known).
    bool ensureFb()
    {
        if (m_haveFb) return true;
        if (!callRhs(m_tb, m_yb.data(), m_fb.data())) return false;
        m_haveFb = true;
        return true;
    }

    /// A root of g between m_t (g = m_gt) and tHi (g = m_ghi) on the interpolant: the
    /// Illinois method (SUNDIALS' arkRootfind/cvRootfind), to 100 ulps of t.
    AdvanceResult rk4Root(double tHi, double* y)
    {
        double tlo = m_t, thi = tHi;
        m_glo = m_gt;
        const double ttol = 100 * DBL_EPSILON * (std::abs(m_tb) + std::abs(m_tb - m_ta));
        double alpha = 1;
        int sidePrev = 0;
        for (int iter = 0; iter < 200 && thi - tlo > ttol; ++iter) {
            // the component whose (secant) root comes first
            int imax = -1;
            double best = -1;
            for (int i = 0; i < m_nroots; ++i) {
                if (crossing(i, m_glo[i], m_ghi[i]) == 0) continue;
                const double frac = std::abs(m_ghi[i] / (m_ghi[i] - alpha * m_glo[i]));
                if (frac > best) {
                    best = frac;
                    imax = i;
                }
            }
            double tmid = thi - (thi - tlo) * m_ghi[imax] / (m_ghi[imax] - alpha * m_glo[imax]);
            if (!(tmid > tlo + 0.5 * ttol)) tmid = tlo + 0.5 * ttol;
            if (!(tmid < thi - 0.5 * ttol)) tmid = thi - 0.5 * ttol;
            hermite(tmid, m_yi.data());
            if (!callRoots(tmid, m_yi.data(), m_gmid.data())) return rk4UserFailure();
            int side = 0;
            if (anyCrossing(m_glo, m_gmid)) {
                thi = tmid;
                m_ghi = m_gmid;
                side = 1;
            } else {
                tlo = tmid;
                m_glo = m_gmid;
                side = 2;
            }
            if (side == sidePrev) {
                alpha = side == 2 ? alpha * 2 : alpha * 0.5;
            } else {
                alpha = 1;
            }
            sidePrev = side;
        }
        for (int i = 0; i < m_nroots; ++i) m_rootInfo[static_cast<std::size_t>(i)] = crossing(i, m_glo[i], m_ghi[i]);
        hermite(thi, m_yt.data());
        m_gt = m_ghi;
        m_t = thi;
        if (thi == m_tb) {
            // the root is the step's end: the step is done there
            m_ta = m_tb;
            std::swap(m_ya, m_yb);
            m_haveFa = m_haveFb;
            if (m_haveFa) std::swap(m_fa, m_fb);
            m_haveGt = true;
            m_pending = false;
        }
        ++m_stats.rootReturns;
        AdvanceResult r;
        r.status = AdvanceStatus::Root;
        r.t = thi;
        r.rootsFired = std::span<const int>(m_rootInfo);
        std::copy(m_yt.begin(), m_yt.end(), y);
        return r;
    }

    /// Keeps the last error message instead of printing it; warnings are dropped.
    static void errorHandler(int code, const char* /*module*/, const char* function, char* msg,
                             void* userData)
    {
        if (code == ARK_WARNING) return;
        auto* self = static_cast<Impl*>(userData);
        std::snprintf(self->m_sundialsMessage, sizeof self->m_sundialsMessage, "%s: %s",
                      function != nullptr ? function : "?", msg != nullptr ? msg : "");
    }

    static const char* lastError(void* userData)
    {
        return static_cast<Impl*>(userData)->m_sundialsMessage;
    }

    OdeSystem& m_system;
    IntegratorOptions m_options;
    int m_n;
    int m_nroots;
    std::vector<int> m_dirs;  ///< per event function: +1 rising only, −1 falling only, 0 both

    // RK4 (no SUNDIALS): the state at m_t; the step [m_ta, m_tb] (pending: taken, and
    // returned only up to m_t); its ends' states and derivatives; g at m_t and at m_tb
    std::vector<double> m_yt, m_ya, m_fa, m_yb, m_fb, m_k2, m_k3, m_k4, m_stage, m_yi;
    std::vector<double> m_gt, m_gb, m_glo, m_ghi, m_gmid;
    double m_ta = 0, m_tb = 0;
    double m_callStart = 0;  ///< m_t when advanceTo() was called
    bool m_haveFa = false, m_haveFb = false, m_haveGt = false, m_pending = false;
    bool m_endEvaluation = false;  ///< OdeSystem::evaluateAtStepEnds()
    IntegratorStats m_stats;
    std::vector<int> m_rootInfo;  ///< dim m_nroots; what AdvanceResult::rootsFired views

    double m_t = 0;  ///< the time last returned
    bool m_initialised = false;
    bool m_failed = false;
    std::string m_failMessage;
    Text m_failText;  ///< m_failMessage, translatable
    int m_badComponent = -1;
    double m_failureTime = 0;
    long m_stepsSeen = 0;
    Failure m_failure;
    char m_sundialsMessage[512] = {};

    // destroyed in reverse order: solver before vector before context
    ContextPtr m_ctx;
    VectorPtr m_y;  ///< the state handed to and returned by SUNDIALS
    std::unique_ptr<Backend> m_backend;
};

Integrator::Integrator(OdeSystem& system, const IntegratorOptions& options)
    : m_impl(std::make_unique<Impl>(system, options))
{
}

Integrator::~Integrator() = default;
Integrator::Integrator(Integrator&&) noexcept = default;
Integrator& Integrator::operator=(Integrator&&) noexcept = default;

void Integrator::reset(double t0, const double* y0, const double* ydot0, const double* g0)
{
    m_impl->reset(t0, y0, ydot0, g0);
}
AdvanceResult Integrator::advanceTo(double tout, double* y)
{
    return m_impl->advanceTo(tout, y);
}
double Integrator::time() const
{
    return m_impl->time();
}
int Integrator::size() const
{
    return m_impl->size();
}
int Integrator::rootCount() const
{
    return m_impl->rootCount();
}
const IntegratorOptions& Integrator::options() const
{
    return m_impl->options();
}
const IntegratorStats& Integrator::stats() const
{
    return m_impl->stats();
}

}  // namespace solver
