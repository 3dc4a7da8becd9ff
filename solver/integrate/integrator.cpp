// Integrator: the argument checks, the state every method shares, the checked calls of
// the system, the failure messages, and the dispatch to one backend (integrator_backend.h):
// the fixed-step RK4 (rk4.cpp) or SUNDIALS (sundials_backends.cpp).

#include "solver/integrate/integrator.h"

#include "solver/integrate/integrator_backend.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace solver {

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

std::string formatTime(double t)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", t);
    return buf;
}

void validate(int n, int nroots, const IntegratorOptions& options)
{
    auto bad = [](const std::string& what) {
        throw std::invalid_argument("Integrator: " + what);
    };
    if (n <= 0) bad("the system's size() must be positive");
    if (nroots < 0) bad("the system's rootCount() must not be negative");
    if (!(options.maxSteps > 0)) bad("maxSteps must be positive");
    if (!(options.maxStep >= 0) || !std::isfinite(options.maxStep))
        bad("maxStep must be zero (unlimited) or positive");
    if (options.method == IntegrationMethod::Rk4Fixed) {
        if (!(std::isfinite(options.step) && options.step > 0))
            bad("step must be positive and finite");
    } else {
        if (!(std::isfinite(options.rtol) && options.rtol > 0))
            bad("rtol must be positive and finite");
        if (!(std::isfinite(options.atol) && options.atol > 0))
            bad("atol must be positive and finite");
    }
}

/// Why the last step failed: the flag's name and time, the cause when it was the
/// system's, and the backend's own message (English, plain) in brackets.
Text failureMessage(const detail::Failure& f, const std::string& name, bool userFunctionFailure, double tret,
                    const char* backendMessage)
{
    using detail::FailureKind;
    Text cause;
    if (userFunctionFailure) {
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
    const bool hasDetail = backendMessage[0] != '\0';
    if (cause.empty()) {
        if (!hasDetail) return trText("Diagnostics", "%1 at t = %2 s").with(name).with(when);
        return trText("Diagnostics", "%1 at t = %2 s [%3]").with(name).with(when).with(backendMessage);
    }
    if (!hasDetail) return trText("Diagnostics", "%1 at t = %2 s: %3").with(name).with(when).with(std::move(cause));
    return trText("Diagnostics", "%1 at t = %2 s: %3 [%4]")
        .with(name)
        .with(when)
        .with(std::move(cause))
        .with(backendMessage);
}

/// Calls `f` (the system's rhs, roots or both) as SUNDIALS would: an exception is
/// `threw`, a false return `failed`; true when it returned true. `failure` says why not.
template <class F>
bool guarded(F&& f, double t, detail::FailureKind threw, detail::FailureKind failed, detail::Failure& failure)
{
    bool ok = false;
    try {
        ok = f();
    } catch (...) {
        failure = detail::Failure{threw, t};
        return false;
    }
    if (!ok) failure = detail::Failure{failed, t};
    return ok;
}

/// True when the n values are finite; else records `kind` at the first that is not.
bool finite(const double* values, int n, detail::FailureKind kind, double t, detail::Failure& failure)
{
    for (int i = 0; i < n; ++i) {
        if (!std::isfinite(values[i])) {
            failure = detail::Failure{kind, t, i, values[i]};
            return false;
        }
    }
    return true;
}

}  // namespace

// ---- what every backend shares ---------------------------------------------------

namespace detail {

IntegratorShared::IntegratorShared(OdeSystem& sys, const IntegratorOptions& opts)
    : system(sys), options(opts), n(sys.size()), nroots(sys.rootCount())
{
    validate(n, nroots, options);
    rootInfo.assign(static_cast<std::size_t>(nroots), 0);
    dirs.assign(static_cast<std::size_t>(nroots), 0);
    for (int i = 0; i < nroots; ++i) {
        const int d = system.rootDirection(i);
        dirs[static_cast<std::size_t>(i)] = d > 0 ? 1 : (d < 0 ? -1 : 0);
    }
}

bool IntegratorShared::callRhs(double t, const double* y, double* ydot)
{
    ++stats.rhsEvals;
    return guarded([&] { return system.rhs(t, y, ydot); }, t, FailureKind::RhsThrew, FailureKind::RhsFalse,
                   failure) &&
           finite(ydot, n, FailureKind::RhsNonFinite, t, failure);
}

bool IntegratorShared::callRoots(double t, const double* y, double* g)
{
    ++stats.rootEvals;
    return guarded([&] { return system.roots(t, y, g); }, t, FailureKind::RootsThrew, FailureKind::RootsFalse,
                   failure) &&
           finite(g, nroots, FailureKind::RootsNonFinite, t, failure);
}

bool IntegratorShared::callRhsAndRoots(double t, const double* y, double* ydot, double* g)
{
    ++stats.rhsEvals;
    if (nroots > 0) ++stats.rootEvals;
    return guarded([&] { return system.rhsAndRoots(t, y, ydot, g); }, t, FailureKind::RhsThrew,
                   FailureKind::RhsFalse, failure) &&
           finite(ydot, n, FailureKind::RhsNonFinite, t, failure) &&
           finite(g, nroots, FailureKind::RootsNonFinite, t, failure);
}

AdvanceResult IntegratorShared::fail(const std::string& name, bool userFunction, double when, const char* backendMessage)
{
    failed = true;
    failText = failureMessage(failure, name, userFunction, when, backendMessage);
    failMessage = failText.english();
    badComponent = userFunction ? failure.component : -1;
    failureTime = std::max(when, time);
    AdvanceResult r;
    r.status = AdvanceStatus::Failed;
    r.t = time;
    r.message = failMessage;
    r.messageText = failText;
    r.badComponent = badComponent;
    r.failureTime = failureTime;
    return r;
}

}  // namespace detail

// ---- Integrator ----------------------------------------------------------------

class Integrator::Impl {
public:
    Impl(OdeSystem& system, const IntegratorOptions& options)
        : m_shared(system, options),
          m_backend(options.method == IntegrationMethod::Rk4Fixed ? detail::makeRk4Backend(m_shared)
                                                                    : detail::makeSundialsBackend(m_shared))
    {
    }

    void reset(double t0, const double* y0, const double* ydot0, const double* g0)
    {
        if (!std::isfinite(t0)) throw std::invalid_argument("Integrator::reset: t0 is not finite");
        m_backend->reset(t0, y0, ydot0, g0);
        detail::IntegratorShared& s = m_shared;
        s.time = t0;
        s.initialised = true;
        s.failed = false;
        s.failMessage.clear();
        s.failText = {};
        s.badComponent = -1;
        std::fill(s.rootInfo.begin(), s.rootInfo.end(), 0);
        ++s.stats.resets;
    }

    AdvanceResult advanceTo(double tout, double* y)
    {
        detail::IntegratorShared& s = m_shared;
        if (!s.initialised) throw std::logic_error("Integrator::advanceTo before reset()");
        if (!std::isfinite(tout))
            throw std::invalid_argument("Integrator::advanceTo: tout is not finite");
        if (tout < s.time) {
            throw std::invalid_argument("Integrator::advanceTo: tout " + formatTime(tout) +
                                        " is behind the current time " + formatTime(s.time));
        }
        AdvanceResult r;
        if (s.failed) {
            r.status = AdvanceStatus::Failed;
            r.t = s.time;
            r.message = s.failMessage;
            r.messageText = s.failText;
            r.badComponent = s.badComponent;
            r.failureTime = s.failureTime;
            return r;
        }
        // a step of a few ulps changes nothing (and SUNDIALS refuses it: TOO_CLOSE)
        if (tout - s.time <= 4 * DBL_EPSILON * std::max(std::abs(tout), std::abs(s.time))) {
            s.time = tout;
            r.t = tout;
            const double* state = m_backend->state();
            std::copy(state, state + s.n, y);
            return r;
        }
        s.failure = {};
        std::fill(s.rootInfo.begin(), s.rootInfo.end(), 0);
        return m_backend->advanceTo(tout, y);
    }

    double time() const { return m_shared.time; }
    int size() const { return m_shared.n; }
    int rootCount() const { return m_shared.nroots; }
    const IntegratorOptions& options() const { return m_shared.options; }
    const IntegratorStats& stats() const { return m_shared.stats; }

private:
    detail::IntegratorShared m_shared;
    std::unique_ptr<detail::IntegratorBackend> m_backend;  ///< keeps m_shared by reference
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
