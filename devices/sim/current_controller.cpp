#include "sim/current_controller.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vt::dev::sim {

void CurrentController::reset()
{
    m_mean = m_current = m_demand = m_peak = 0;
    m_deviationTime = 0;
}

void CurrentController::step(double demand, const DitherSettings &dither, double dt,
                             std::int64_t timeUs)
{
    m_demand = std::max(demand, 0.0);
    double target = m_demand;
    double tau = m_c.timeConstant;
    if (m_fault == SolenoidFault::OpenCircuit)
        target = 0.0;
    if (m_fault == SolenoidFault::ShortCircuit) {
        target = m_c.shortCircuitCurrent;
        tau = m_c.shortCircuitTimeConstant;
    }
    // Exact discretisation of the first-order lag: stable for any dt and independent of how many
    // steps the caller groups, because the clock's step is fixed.
    const double a = tau > 0.0 ? std::exp(-dt / tau) : 0.0;
    m_mean = target + (m_mean - target) * a;

    // The dither is superposed on an energised solenoid only (a de-energised stage carries no
    // current to modulate). Its phase comes from the integer simulated time, so it is exact.
    double ripple = 0.0;
    if (dither.amplitude > 0.0 && dither.frequency > 0.0 && m_mean > 0.0 &&
        m_fault == SolenoidFault::None) {
        const auto periodUs = static_cast<std::int64_t>(std::llround(1e6 / dither.frequency));
        const double phase =
            periodUs > 0 ? static_cast<double>(timeUs % periodUs) / static_cast<double>(periodUs)
                         : 0.0;
        ripple = dither.amplitude * std::sin(2.0 * std::numbers::pi * phase);
    }
    m_current = std::max(m_mean + ripple, 0.0);
    m_peak = std::max(m_peak, m_current);

    // The stage compares desired and actual current; the dither is part of neither (the card
    // would otherwise trip on its own dither).
    if (std::abs(m_demand - m_mean) > kDeviationLimit)
        m_deviationTime += dt;
    else
        m_deviationTime = 0.0;
}

} // namespace vt::dev::sim
