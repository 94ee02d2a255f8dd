#include "sim/loop_controller.h"

#include <algorithm>
#include <cmath>

namespace vt::dev::sim {

void LoopController::reset()
{
    *this = LoopController{};
}

double LoopController::step(double error, const LoopSettings &s, double dt)
{
    // P: split the error at the threshold, smooth the inner part with the PT1 (exact discrete
    // first-order lag, so a long time constant never destabilises the step).
    const double threshold = std::max(s.threshold, 0.0);
    const double inner = std::clamp(error, -threshold, threshold);
    const double outer = error - inner;
    const double a = s.pt1Time > 0.0 ? std::exp(-dt / s.pt1Time) : 0.0;
    m_pt1 = inner + (m_pt1 - inner) * a;
    m_p = s.pGain * (s.kp2 * m_pt1 + s.kp1 * outer);

    // I: forward Euler; the limit keeps the integrator from winding up beyond C1.33.
    const double iLimit = std::clamp(s.iLimit, 0.0, kOutputLimit);
    m_i = std::clamp(m_i + s.ki * error * dt, -iLimit, iLimit);

    // DT1: backward difference of Kd·s/(1 + T·s); with T = 0 a plain difference quotient.
    // The first step after a reset has no previous error: no derivative kick from the set value.
    const double de = m_primed ? error - m_previousError : 0.0;
    m_previousError = error;
    m_primed = true;
    const double t1 = std::max(s.dt1Time, 0.0);
    m_d = (t1 * m_d + s.kd * de) / (t1 + dt);

    const double low = s.positiveOnly ? 0.0 : -kOutputLimit;
    m_output = std::clamp(m_p + m_i + m_d, low, kOutputLimit);
    return m_output;
}

} // namespace vt::dev::sim
