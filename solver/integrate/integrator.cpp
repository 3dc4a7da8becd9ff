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

struct ButcherTableDeleter {
    void operator()(ARKodeButcherTable b) const { ARKodeButcherTable_Free(b); }
};
using ButcherTablePtr =
    std::unique_ptr<std::remove_pointer_t<ARKodeButcherTable>, ButcherTableDeleter>;

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

/// ARKODE ARKStep, explicit: classic RK4 with a fixed step, or Dormand–Prince 5(4)
/// with error control.
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
        if (opt.method == IntegrationMethod::Rk4Fixed) {
            // the classic RK4 (not among 6.4's built-in tables); no embedding
            sunrealtype c[4] = {0.0, 0.5, 0.5, 1.0};
            sunrealtype a[16] = {0.0, 0.0, 0.0, 0.0,  //
                                 0.5, 0.0, 0.0, 0.0,  //
                                 0.0, 0.5, 0.0, 0.0,  //
                                 0.0, 0.0, 1.0, 0.0};
            sunrealtype b[4] = {1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0};
            const ButcherTablePtr rk4(ARKodeButcherTable_Create(4, 4, 0, c, a, b, nullptr));
            if (!rk4) throw std::runtime_error("ARKodeButcherTable_Create failed");
            check(ARKStepSetTables(mem, 4, 0, nullptr, rk4.get()), "ARKStepSetTables");  // copies
            check(ARKStepSetFixedStep(mem, opt.step), "ARKStepSetFixedStep");
        } else {
            check(ARKStepSStolerances(mem, opt.rtol, opt.atol), "ARKStepSStolerances");
            if (opt.maxStep > 0) check(ARKStepSetMaxStep(mem, opt.maxStep), "ARKStepSetMaxStep");
            check(ARKStepSetTableNum(mem, ARKODE_DIRK_NONE, ARKODE_DORMAND_PRINCE_7_4_5),
                  "ARKStepSetTableNum");
        }
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

    void reset(double t0, const double* y0)
    {
        if (!std::isfinite(t0)) throw std::invalid_argument("Integrator::reset: t0 is not finite");
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
        double* yv = N_VGetArrayPointer(m_y.get());
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
            m_failText = failureMessage(flag, tret);
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
    Text failureMessage(int flag, double tret) const
    {
        Text cause;
        if (isUserFunctionFailure(flag)) {
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
        const std::string name = m_backend->flagName(flag), when = formatTime(tret);
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

    static int rhsTrampoline(sunrealtype t, N_Vector y, N_Vector ydot, void* userData)
    {
        auto* self = static_cast<Impl*>(userData);
        ++self->m_stats.rhsEvals;
        const double* yv = N_VGetArrayPointer(y);
        double* yd = N_VGetArrayPointer(ydot);
        bool ok = false;
        try {
            ok = self->m_system.rhs(t, yv, yd);
        } catch (...) {
            self->recordFailure(FailureKind::RhsThrew, t);
            return -1;
        }
        if (!ok) {
            self->recordFailure(FailureKind::RhsFalse, t);
            return -1;
        }
        for (int i = 0; i < self->m_n; ++i) {
            if (!std::isfinite(yd[i])) {
                self->recordFailure(FailureKind::RhsNonFinite, t, i, yd[i]);
                return -1;
            }
        }
        return 0;
    }

    static int rootsTrampoline(sunrealtype t, N_Vector y, sunrealtype* g, void* userData)
    {
        auto* self = static_cast<Impl*>(userData);
        ++self->m_stats.rootEvals;
        bool ok = false;
        try {
            ok = self->m_system.roots(t, N_VGetArrayPointer(y), g);
        } catch (...) {
            self->recordFailure(FailureKind::RootsThrew, t);
            return -1;
        }
        if (!ok) {
            self->recordFailure(FailureKind::RootsFalse, t);
            return -1;
        }
        for (int i = 0; i < self->m_nroots; ++i) {
            if (!std::isfinite(g[i])) {
                self->recordFailure(FailureKind::RootsNonFinite, t, i, g[i]);
                return -1;
            }
        }
        return 0;
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

void Integrator::reset(double t0, const double* y0)
{
    m_impl->reset(t0, y0);
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
