#include "ide/studio/sim/overrun_meter.h"

#include <QLocale>

#include <algorithm>

namespace studio {

void OverrunMeter::add(double now, long step, long overruns)
{
    if (!m_samples.empty() && (step < m_samples.back().step || overruns < m_samples.back().overruns)) m_samples.clear();
    m_samples.push_back({now, step, overruns});
    while (m_samples.size() > 2 && m_samples[1].now <= now - kWindow) m_samples.pop_front();
}

double OverrunMeter::percent() const
{
    if (m_samples.size() < 2) return 0.0;
    const long steps = m_samples.back().step - m_samples.front().step;
    const long late = m_samples.back().overruns - m_samples.front().overruns;
    return steps > 0 ? 100.0 * std::clamp(double(late) / double(steps), 0.0, 1.0) : 0.0;
}

QString OverrunMeter::text() const
{
    const double p = percent();
    if (p <= 0.0) return {};
    // below 1 %, one decimal: "0.3 %" says more than "0 %"
    return tr("%1 % of steps late").arg(QLocale().toString(p, 'f', p < 1.0 ? 1 : 0));
}

QString OverrunMeter::toolTip() const
{
    return tr("An overrun is a solver step that took longer to compute than the real time it simulates: the "
              "simulation falls behind the wall clock. The share shown is that of the last %1 s (%n overrun(s) "
              "since Run).\nA few are harmless. If the share stays high, this computer cannot keep up: lower "
              "the speed (Simulation ▸ Speed), close other programs, choose Settings ▸ Lighting ▸ At the "
              "vertices, or simplify the model.",
              nullptr, int(std::min<long>(total(), 1'000'000'000)))
        .arg(QLocale().toString(kWindow, 'f', 0));
}

}  // namespace studio
