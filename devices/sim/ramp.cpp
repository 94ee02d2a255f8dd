#include "sim/ramp.h"

#include <cmath>

namespace vt::dev::sim {

void Ramp::reset(double value)
{
    m_value = value;
    m_target = value;
    m_quadrant = Quadrant::None;
    m_segmentStart = value;
}

Ramp::Quadrant Ramp::quadrantOf(double from, double target)
{
    if (target == from)
        return Quadrant::None;
    if (from > 0.0 || (from == 0.0 && target > 0.0))
        return target > from ? Quadrant::ZeroToPos : Quadrant::PosToZero;
    return target < from ? Quadrant::ZeroToNeg : Quadrant::NegToZero;
}

double Ramp::timeOf(Quadrant q, const RampTimes &times)
{
    switch (q) {
    case Quadrant::ZeroToNeg: return times.zeroToNeg;
    case Quadrant::NegToZero: return times.negToZero;
    case Quadrant::ZeroToPos: return times.zeroToPos;
    case Quadrant::PosToZero: return times.posToZero;
    case Quadrant::None: break;
    }
    return 0.0;
}

double Ramp::step(double target, const RampTimes &times, RampKind kind, double dt)
{
    if (target != m_target) {
        // A new target starts a new segment: the time-constant ramp measures from here.
        m_target = target;
        m_quadrant = Quadrant::None;
    }
    double left = dt;
    // At most two segments per step: towards 0, then away from it on the other side.
    for (int segment = 0; segment < 3 && m_value != m_target; ++segment) {
        const Quadrant q = quadrantOf(m_value, m_target);
        if (q != m_quadrant) {
            m_quadrant = q;
            m_segmentStart = m_value;
        }
        // A segment never crosses 0: the way back to 0 and the way out of it have own times.
        const bool towardsZero = q == Quadrant::NegToZero || q == Quadrant::PosToZero;
        const bool crosses = towardsZero && (m_target > 0.0) != (m_value > 0.0) && m_target != 0.0;
        const double end = crosses ? 0.0 : m_target;
        const double time = timeOf(q, times);
        if (time <= 0.0) {
            m_value = end; // ramp function off: the set value passes at once
            continue;
        }
        const double span =
            kind == RampKind::RiseConstant ? kFullScale : std::abs(end - m_segmentStart);
        const double rate = span / time;
        const double distance = std::abs(end - m_value);
        if (rate <= 0.0 || left <= 0.0)
            break;
        if (rate * left >= distance) {
            left -= distance / rate;
            m_value = end;
        } else {
            m_value += (end > m_value ? 1.0 : -1.0) * rate * left;
            left = 0.0;
        }
    }
    return m_value;
}

} // namespace vt::dev::sim
