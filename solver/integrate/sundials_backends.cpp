// The accuracy integrators: ARKODE ARKStep explicit, Dormand–Prince 5(4)
// (IntegrationMethod::Adaptive) and CVODE BDF with a dense direct linear solver
// (AdaptiveStiff). The only file that includes SUNDIALS: RAII owners of its objects,
// the trampolines it calls and the reading of its flags.

#include "solver/integrate/integrator_backend.h"

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
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace solver::detail {

// the flag values the code below tests are the same in ARKODE and CVODE
static_assert(ARK_SUCCESS == CV_SUCCESS && ARK_TSTOP_RETURN == CV_TSTOP_RETURN &&
              ARK_ROOT_RETURN == CV_ROOT_RETURN && ARK_WARNING == CV_WARNING);
static_assert(ARK_RHSFUNC_FAIL == CV_RHSFUNC_FAIL &&
              ARK_FIRST_RHSFUNC_ERR == CV_FIRST_RHSFUNC_ERR &&
              ARK_REPTD_RHSFUNC_ERR == CV_REPTD_RHSFUNC_ERR &&
              ARK_UNREC_RHSFUNC_ERR == CV_UNREC_RHSFUNC_ERR && ARK_RTFUNC_FAIL == CV_RTFUNC_FAIL);
static_assert(std::is_same_v<sunrealtype, double>, "Padrob needs SUNDIALS built with double");

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
std::string returnFlagName(char* (*getName)(long int), int flag)
{
    char* name = getName(flag);
    std::string s = name != nullptr ? name : "UNKNOWN_FLAG";
    std::free(name);
    return s;
}

bool isUserFunctionFailure(int flag)
{
    return flag == ARK_RHSFUNC_FAIL || flag == ARK_FIRST_RHSFUNC_ERR ||
           flag == ARK_REPTD_RHSFUNC_ERR || flag == ARK_UNREC_RHSFUNC_ERR ||
           flag == ARK_RTFUNC_FAIL;
}

// ---- what ARKODE and CVODE share -------------------------------------------------

/// One SUNDIALS package driven through the few calls Integrator needs (each returns
/// the package's flag); the context and the state vector it works on.
class SundialsBackend : public IntegratorBackend {
public:
    explicit SundialsBackend(IntegratorShared& shared) : m_s(shared)
    {
        m_ctx = makeContext();
        m_y.reset(N_VNew_Serial(m_s.n, m_ctx.get()));
        if (!m_y) throw std::runtime_error("N_VNew_Serial failed");
        N_VConst(0.0, m_y.get());
    }

    void reset(double t0, const double* y0, const double* /*ydot0*/, const double* /*g0*/) override
    {
        std::copy(y0, y0 + m_s.n, N_VGetArrayPointer(m_y.get()));
        m_message[0] = '\0';
        const int flag = reinit(t0, m_y.get());
        if (flag < 0) throw std::runtime_error("Integrator::reset: " + flagName(flag) + " " + m_message);
        m_stepsSeen = numSteps();
    }

    const double* state() const override { return N_VGetArrayPointer(m_y.get()); }

    AdvanceResult advanceTo(double tout, double* y) override
    {
        AdvanceResult r;
        double* yv = N_VGetArrayPointer(m_y.get());
        m_message[0] = '\0';
        // never step past tout; when the last step already passed it (after a root
        // return) the solver interpolates and a stop time behind it would be refused
        int flag = ARK_SUCCESS;
        if (tout > currentTime()) flag = setStopTime(tout);
        double tret = m_s.time;
        if (flag == ARK_SUCCESS) flag = evolve(tout, m_y.get(), &tret);

        const long steps = numSteps();
        m_s.stats.steps += steps - m_stepsSeen;
        m_stepsSeen = steps;

        if (flag < 0) {
            // y and time() stay those of the previous return: on failure ARKODE
            // reports the failing stage's time with the state from the step's start
            return m_s.fail(flagName(flag), isUserFunctionFailure(flag), tret, m_message);
        }
        if (flag == ARK_ROOT_RETURN) {
            rootInfo(m_s.rootInfo.data());
            ++m_s.stats.rootReturns;
            m_s.time = tret;
            r.status = AdvanceStatus::Root;
            r.t = tret;
            r.rootsFired = std::span<const int>(m_s.rootInfo);
        } else {
            m_s.time = tout;  // tret == tout at a stop-time or interpolated return
            r.t = tout;
        }
        std::copy(yv, yv + m_s.n, y);
        return r;
    }

protected:
    virtual int reinit(double t0, N_Vector y0) = 0;
    virtual int setStopTime(double tstop) = 0;
    virtual int evolve(double tout, N_Vector yout, double* tret) = 0;
    /// The solver's internal time (may be past the last returned one).
    virtual double currentTime() = 0;
    /// Steps since creation (ARKODE) or since the last reinit (CVODE).
    virtual long numSteps() = 0;
    virtual int rootInfo(int* info) = 0;
    virtual std::string flagName(int flag) const = 0;

    /// What the package's callbacks get as user data.
    void* userData() { return static_cast<SundialsBackend*>(this); }

    /// Throws std::runtime_error unless a setup call succeeded.
    void check(int flag, const char* call) const
    {
        if (flag == ARK_SUCCESS) return;
        throw std::runtime_error(std::string(call) + " failed: " + flagName(flag) + " " + m_message);
    }

    // ---- trampolines: SUNDIALS calls these with user_data = userData() -----------
    // Every failure is unrecoverable (return −1). A recoverable one (> 0) makes an
    // adaptive method retry smaller steps; when f fails from a fixed time on, CVODE
    // then creeps towards that time until mxstep (measured: 276 000 evaluations and
    // CV_TOO_MUCH_WORK instead of the cause).

    static int rhsTrampoline(sunrealtype t, N_Vector y, N_Vector ydot, void* userData)
    {
        auto* self = static_cast<SundialsBackend*>(userData);
        return self->m_s.callRhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)) ? 0 : -1;
    }

    static int rootsTrampoline(sunrealtype t, N_Vector y, sunrealtype* g, void* userData)
    {
        auto* self = static_cast<SundialsBackend*>(userData);
        return self->m_s.callRoots(t, N_VGetArrayPointer(y), g) ? 0 : -1;
    }

    /// Keeps the last error message instead of printing it; warnings are dropped.
    static void errorHandler(int code, const char* /*module*/, const char* function, char* msg,
                             void* userData)
    {
        if (code == ARK_WARNING) return;
        auto* self = static_cast<SundialsBackend*>(userData);
        std::snprintf(self->m_message, sizeof self->m_message, "%s: %s",
                      function != nullptr ? function : "?", msg != nullptr ? msg : "");
    }

    SUNContext context() const { return m_ctx.get(); }
    N_Vector vector() const { return m_y.get(); }

    IntegratorShared& m_s;

private:
    long m_stepsSeen = 0;
    char m_message[512] = {};  ///< SUNDIALS' last error message, "" when none

    // destroyed after the derived class's solver memory, vector before context
    ContextPtr m_ctx;
    VectorPtr m_y;  ///< the state handed to and returned by SUNDIALS
};

// ---- ARKODE ------------------------------------------------------------------------

/// ARKODE ARKStep, explicit: Dormand–Prince 5(4) with error control.
class ArkodeBackend final : public SundialsBackend {
public:
    explicit ArkodeBackend(IntegratorShared& shared) : SundialsBackend(shared)
    {
        const IntegratorOptions& opt = m_s.options;
        m_mem.reset(ARKStepCreate(&rhsTrampoline, nullptr, 0.0, vector(), context()));
        if (!m_mem) throw std::runtime_error("ARKStepCreate failed");
        void* mem = m_mem.get();
        check(ARKStepSetErrHandlerFn(mem, &errorHandler, userData()), "ARKStepSetErrHandlerFn");
        check(ARKStepSetUserData(mem, userData()), "ARKStepSetUserData");
        check(ARKStepSetMaxNumSteps(mem, opt.maxSteps), "ARKStepSetMaxNumSteps");
        check(ARKStepSStolerances(mem, opt.rtol, opt.atol), "ARKStepSStolerances");
        if (opt.maxStep > 0) check(ARKStepSetMaxStep(mem, opt.maxStep), "ARKStepSetMaxStep");
        check(ARKStepSetTableNum(mem, ARKODE_DIRK_NONE, ARKODE_DORMAND_PRINCE_7_4_5), "ARKStepSetTableNum");
        if (m_s.nroots > 0) {
            check(ARKStepRootInit(mem, m_s.nroots, &rootsTrampoline), "ARKStepRootInit");
            check(ARKStepSetRootDirection(mem, m_s.dirs.data()), "ARKStepSetRootDirection");
            check(ARKStepSetNoInactiveRootWarn(mem), "ARKStepSetNoInactiveRootWarn");
        }
    }

private:
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
        return returnFlagName(ARKStepGetReturnFlagName, flag);
    }

    std::unique_ptr<void, ArkodeMemDeleter> m_mem;
};

// ---- CVODE -------------------------------------------------------------------------

/// CVODE BDF with a dense direct linear solver (difference-quotient Jacobian).
class CvodeBackend final : public SundialsBackend {
public:
    explicit CvodeBackend(IntegratorShared& shared) : SundialsBackend(shared)
    {
        const IntegratorOptions& opt = m_s.options;
        const sunindextype n = N_VGetLength(vector());
        m_a.reset(SUNDenseMatrix(n, n, context()));
        if (!m_a) throw std::runtime_error("SUNDenseMatrix failed");
        m_ls.reset(SUNLinSol_Dense(vector(), m_a.get(), context()));
        if (!m_ls) throw std::runtime_error("SUNLinSol_Dense failed");
        m_mem.reset(CVodeCreate(CV_BDF, context()));
        if (!m_mem) throw std::runtime_error("CVodeCreate failed");
        void* mem = m_mem.get();
        check(CVodeSetErrHandlerFn(mem, &errorHandler, userData()), "CVodeSetErrHandlerFn");
        check(CVodeInit(mem, &rhsTrampoline, 0.0, vector()), "CVodeInit");
        check(CVodeSetUserData(mem, userData()), "CVodeSetUserData");
        check(CVodeSStolerances(mem, opt.rtol, opt.atol), "CVodeSStolerances");
        check(CVodeSetMaxNumSteps(mem, opt.maxSteps), "CVodeSetMaxNumSteps");
        if (opt.maxStep > 0) check(CVodeSetMaxStep(mem, opt.maxStep), "CVodeSetMaxStep");
        check(CVodeSetLinearSolver(mem, m_ls.get(), m_a.get()), "CVodeSetLinearSolver");
        if (m_s.nroots > 0) {
            check(CVodeRootInit(mem, m_s.nroots, &rootsTrampoline), "CVodeRootInit");
            check(CVodeSetRootDirection(mem, m_s.dirs.data()), "CVodeSetRootDirection");
            check(CVodeSetNoInactiveRootWarn(mem), "CVodeSetNoInactiveRootWarn");
        }
    }

private:
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
        return returnFlagName(CVodeGetReturnFlagName, flag);
    }

    MatrixPtr m_a;
    LinearSolverPtr m_ls;
    std::unique_ptr<void, CvodeMemDeleter> m_mem;  // freed first
};

}  // namespace

std::unique_ptr<IntegratorBackend> makeSundialsBackend(IntegratorShared& shared)
{
    if (shared.options.method == IntegrationMethod::AdaptiveStiff) return std::make_unique<CvodeBackend>(shared);
    return std::make_unique<ArkodeBackend>(shared);
}

}  // namespace solver::detail
