#include "sim/axis_model.h"

#include <algorithm>
#include <cmath>

namespace vt::dev::sim {

void ValveModel::step(double command, double dt)
{
    const double target = std::clamp(command, -1.0, 1.0);
    const double a = m_c.spoolTimeConstant > 0.0 ? std::exp(-dt / m_c.spoolTimeConstant) : 0.0;
    m_spool = target + (m_spool - target) * a;
}

double ValveModel::flow() const
{
    const double s = m_spool + m_c.nullBias;
    const double lap = std::clamp(m_c.overlap, 0.0, 0.9);
    const double open = std::max(std::abs(s) - lap, 0.0) / (1.0 - lap);
    return std::copysign(std::min(open, 1.0), s);
}

CylinderAxis::CylinderAxis(CylinderConstants c) : m_c(c)
{
    reset(c.start);
}

void CylinderAxis::reset(double fraction)
{
    m_position = std::clamp(fraction, 0.0, 1.0);
    m_velocity = 0;
    m_acceleration = 0;
}

void CylinderAxis::step(double flow, double dt)
{
    const double w = m_c.naturalFrequency;
    const double commanded = m_c.maxSpeed * flow;
    // Semi-implicit Euler: the oscillator keeps its energy at ω·dt = 0.02 (0.5 ms steps).
    m_acceleration +=
        (w * w * (commanded - m_velocity) - 2.0 * m_c.damping * w * m_acceleration) * dt;
    m_velocity += m_acceleration * dt;
    m_position += m_velocity * dt;
    if (m_position <= 0.0 || m_position >= 1.0) {
        m_position = std::clamp(m_position, 0.0, 1.0);
        const bool intoStop = (m_position == 0.0) == (m_velocity < 0.0);
        if (intoStop) {
            m_velocity = 0;
            m_acceleration = 0;
        }
    }
}

void PressureAxis::step(double flow, double dt)
{
    const double target = m_c.gain * flow;
    const double a = m_c.timeConstant > 0.0 ? std::exp(-dt / m_c.timeConstant) : 0.0;
    m_pressure = std::clamp(target + (m_pressure - target) * a, 0.0, m_c.relief);
}

bool isPressureBranch(int mode, int branch)
{
    return mode == 4 || mode == 8 || (mode == 6 && branch == 2);
}

std::unique_ptr<AxisModel> makeAxisForMode(int mode, int branch)
{
    if (isPressureBranch(mode, branch))
        return std::make_unique<PressureAxis>();
    return std::make_unique<CylinderAxis>();
}

} // namespace vt::dev::sim
