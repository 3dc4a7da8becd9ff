#include "trainer/station/paced_loop.h"

namespace trainer {

PacedLoop::PacedLoop(PacedLoopOptions options, std::function<double()> clock)
    : m_o(options), m_clock(std::move(clock))
{
}

void PacedLoop::anchor(double simTime, double speed)
{
    m_speed = speed > 0 ? speed : 1.0;
    m_anchorWall = now();
    m_anchorSim = simTime;
    m_steps = 0;
    m_plannedWake = m_anchorWall - m_o.tick;
}

}  // namespace trainer
