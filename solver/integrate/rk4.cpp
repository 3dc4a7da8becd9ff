// The real-time integrator (IntegrationMethod::Rk4Fixed): the classic four-stage
// Runge–Kutta method with a fixed step, written out: for the real-time step of a
// machine of a few bodies ARKODE's general machinery (vector operations through
// function tables, its root-finding and interpolation bookkeeping, the extra
// evaluations around a reset) cost as much as the dynamics (docs/performance.md).
// The same behaviour as the ARKODE version it replaces:
//   - a step of options.step, shortened to end exactly at tout, and cut into the
//     equal sub-steps OdeSystem::substeps() asks for (a stiff fluid circuit);
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

#include "solver/integrate/integrator_backend.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

namespace solver::detail {
namespace {

class Rk4Backend final : public IntegratorBackend {
public:
    explicit Rk4Backend(IntegratorShared& shared)
        : m_s(shared), m_n(shared.n), m_nroots(shared.nroots), m_endEvaluation(shared.system.evaluateAtStepEnds())
    {
        for (std::vector<double>* v : {&m_yt, &m_ya, &m_fa, &m_yb, &m_fb, &m_k2, &m_k3, &m_k4, &m_stage, &m_yi})
            v->assign(static_cast<std::size_t>(m_n), 0.0);
        for (std::vector<double>* v : {&m_gt, &m_gb, &m_glo, &m_ghi, &m_gmid})
            v->assign(static_cast<std::size_t>(m_nroots), 0.0);
    }

    void reset(double t0, const double* y0, const double* ydot0, const double* g0) override
    {
        std::copy(y0, y0 + m_n, m_ya.begin());
        std::copy(y0, y0 + m_n, m_yt.begin());
        m_ta = t0;
        m_haveFa = ydot0 != nullptr;
        if (m_haveFa) std::copy(ydot0, ydot0 + m_n, m_fa.begin());
        m_haveGt = g0 != nullptr && m_nroots > 0;
        if (m_haveGt) std::copy(g0, g0 + m_nroots, m_gt.begin());
        m_pending = false;
    }

    const double* state() const override { return m_yt.data(); }

    AdvanceResult advanceTo(double tout, double* y) override
    {
        AdvanceResult r;
        m_callStart = m_s.time;
        long steps = 0;
        while (true) {
            if (!m_pending) {
                // a new step from (m_ta, m_ya) = (t, m_yt)
                if (steps >= m_s.options.maxSteps) {
                    return fail("RK4_TOO_MUCH_WORK", false, m_ta);
                }
                const int parts = std::max(1, m_s.system.substeps(m_s.options.step));
                double h = m_s.options.step / parts;
                double tb = m_ta + h;
                if (tb >= tout - 4 * DBL_EPSILON * std::abs(tout)) {
                    tb = tout;
                    h = tout - m_ta;
                }
                if (!m_haveFa || (m_nroots > 0 && !m_haveGt)) {
                    const bool ok = m_nroots > 0 ? m_s.callRhsAndRoots(m_ta, m_ya.data(), m_fa.data(), m_gt.data())
                                                 : m_s.callRhs(m_ta, m_ya.data(), m_fa.data());
                    if (!ok) return userFailure();
                    m_haveFa = true;
                    m_haveGt = m_nroots > 0;
                }
                const double* ya = m_ya.data();
                const double* k1 = m_fa.data();
                double* st = m_stage.data();
                for (int i = 0; i < m_n; ++i) st[i] = ya[i] + 0.5 * h * k1[i];
                if (!m_s.callRhs(m_ta + 0.5 * h, st, m_k2.data())) return userFailure();
                const double* k2 = m_k2.data();
                for (int i = 0; i < m_n; ++i) st[i] = ya[i] + 0.5 * h * k2[i];
                if (!m_s.callRhs(m_ta + 0.5 * h, st, m_k3.data())) return userFailure();
                const double* k3 = m_k3.data();
                for (int i = 0; i < m_n; ++i) st[i] = ya[i] + h * k3[i];
                if (!m_s.callRhs(tb, st, m_k4.data())) return userFailure();
                const double* k4 = m_k4.data();
                for (int i = 0; i < m_n; ++i) m_yb[i] = ya[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
                m_tb = tb;
                ++steps;
                ++m_s.stats.steps;
                // f there (the next step's first stage) with g, when there are events
                m_haveFb = false;
                if (m_nroots > 0 || m_endEvaluation) {
                    if (!m_s.callRhsAndRoots(tb, m_yb.data(), m_fb.data(), m_gb.data())) return userFailure();
                    m_haveFb = true;
                }
                m_pending = true;
            }

            // the pending step [m_ta, m_tb], returned up to t (g there: m_gt)
            const double tEnd = std::min(m_tb, tout);
            if (m_nroots > 0) {
                if (tEnd == m_tb) {
                    m_ghi = m_gb;
                } else {
                    if (!ensureFb()) return userFailure();
                    hermite(tEnd, m_yi.data());
                    if (!m_s.callRoots(tEnd, m_yi.data(), m_ghi.data())) return userFailure();
                }
                if (anyCrossing(m_gt, m_ghi)) {
                    if (!ensureFb()) return userFailure();
                    return root(tEnd, y);
                }
            }
            if (tEnd < m_tb) {
                // tout inside the step (after a root): the interpolant there
                if (!ensureFb()) return userFailure();
                hermite(tout, m_yt.data());
                if (m_nroots > 0) m_gt = m_ghi;
                m_s.time = tout;
                r.t = tout;
                std::copy(m_yt.begin(), m_yt.end(), y);
                return r;
            }
            // the step is done: the next one starts at its end
            m_ta = m_tb;
            m_s.time = m_tb;
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

private:
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
        const int dir = m_s.dirs[static_cast<std::size_t>(i)];
        return dir == 0 || dir == c ? c : 0;
    }

    bool anyCrossing(const std::vector<double>& lo, const std::vector<double>& hi) const
    {
        for (int i = 0; i < m_nroots; ++i) {
            if (crossing(i, lo[i], hi[i]) != 0) return true;
        }
        return false;
    }

    /// Fails the call: the steps taken in it are void, time() stays that of the last return.
    AdvanceResult fail(const char* name, bool userFunction, double when)
    {
        m_s.time = m_callStart;
        return m_s.fail(name, userFunction, when, "");
    }

    AdvanceResult userFailure()
    {
        const FailureKind k = m_s.failure.kind;
        const bool roots = k == FailureKind::RootsFalse || k == FailureKind::RootsNonFinite ||
                           k == FailureKind::RootsThrew;
        return fail(roots ? "RK4_RTFUNC_FAIL" : "RK4_RHSFUNC_FAIL", true, m_s.failure.t);
    }

    /// f at the pending step's end, for the interpolant (evaluated when not yet known).
    bool ensureFb()
    {
        if (m_haveFb) return true;
        if (!m_s.callRhs(m_tb, m_yb.data(), m_fb.data())) return false;
        m_haveFb = true;
        return true;
    }

    /// A root of g between t (g = m_gt) and tHi (g = m_ghi) on the interpolant: the
    /// Illinois method (SUNDIALS' arkRootfind/cvRootfind), to 100 ulps of t.
    AdvanceResult root(double tHi, double* y)
    {
        double tlo = m_s.time, thi = tHi;
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
            if (!m_s.callRoots(tmid, m_yi.data(), m_gmid.data())) return userFailure();
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
        for (int i = 0; i < m_nroots; ++i) m_s.rootInfo[static_cast<std::size_t>(i)] = crossing(i, m_glo[i], m_ghi[i]);
        hermite(thi, m_yt.data());
        m_gt = m_ghi;
        m_s.time = thi;
        if (thi == m_tb) {
            // the root is the step's end: the step is done there
            m_ta = m_tb;
            std::swap(m_ya, m_yb);
            m_haveFa = m_haveFb;
            if (m_haveFa) std::swap(m_fa, m_fb);
            m_haveGt = true;
            m_pending = false;
        }
        ++m_s.stats.rootReturns;
        AdvanceResult r;
        r.status = AdvanceStatus::Root;
        r.t = thi;
        r.rootsFired = std::span<const int>(m_s.rootInfo);
        std::copy(m_yt.begin(), m_yt.end(), y);
        return r;
    }

    IntegratorShared& m_s;
    const int m_n;               ///< m_s.n, kept here for the loops
    const int m_nroots;          ///< m_s.nroots
    const bool m_endEvaluation;  ///< OdeSystem::evaluateAtStepEnds()

    // the state at the shared t; the step [m_ta, m_tb] (pending: taken, and returned
    // only up to t); its ends' states and derivatives; g at t and at m_tb
    std::vector<double> m_yt, m_ya, m_fa, m_yb, m_fb, m_k2, m_k3, m_k4, m_stage, m_yi;
    std::vector<double> m_gt, m_gb, m_glo, m_ghi, m_gmid;
    double m_ta = 0, m_tb = 0;
    double m_callStart = 0;  ///< t when advanceTo() was called
    bool m_haveFa = false, m_haveFb = false, m_haveGt = false, m_pending = false;
};

}  // namespace

std::unique_ptr<IntegratorBackend> makeRk4Backend(IntegratorShared& shared)
{
    return std::make_unique<Rk4Backend>(shared);
}

}  // namespace solver::detail
