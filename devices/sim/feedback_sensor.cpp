#include "sim/feedback_sensor.h"

#include <algorithm>

namespace vt::dev::sim {

std::optional<SensorType> SensorType::fromSelection(int c109)
{
    auto mA = [](double lo, double hi, bool twoSided, bool onlyPositive = false) {
        return SensorType{true, lo, hi, twoSided, onlyPositive};
    };
    auto V = [](double lo, double hi, bool twoSided, bool onlyPositive = false) {
        return SensorType{false, lo, hi, twoSided, onlyPositive};
    };
    switch (c109) {
    case 1: return mA(0, 20, false);   // 0 … 20 mA
    case 2: return mA(4, 20, false);   // 4 … 20 mA
    case 3: return mA(4, 20, true);    // 12 mA ± 8 mA
    case 4: return V(0, 10, false);    // 0 … 10 V
    case 5: return V(-10, 10, true);   // 0 … ±10 V
    case 6: return V(3.5, 8.5, true);  // 6 V ± 2.5 V
    case 7: return V(5, 10, true);     // 7.5 V ± 2.5 V
    case 8: return V(1, 11, true);     // 6 V ± 5 V
    case 9: return V(2.5, 12.5, true); // 7.5 V ± 5 V
    case 10: return mA(0, 20, false, true);
    case 11: return mA(4, 20, false, true);
    case 12: return V(0, 10, false, true);
    case 14: return V(2, 8, true); // OPAT: 5 V ± 3.0 V
    case 21: return V(-10, 10, true);
    case 22: return V(0, 10, false);
    case 23: return V(0, 10, false, true);
    case 24: return mA(4, 20, true);
    case 25: return mA(4, 20, false);
    case 26: return mA(4, 20, false, true);
    default: return std::nullopt;
    }
}

double SensorType::toVolts(double s) const
{
    const double unit = (s - low) / (high - low);
    return bipolar ? 20.0 * unit - 10.0 : 10.0 * unit;
}

FeedbackReading readFeedback(const FeedbackSettings &s, double fraction, SensorFault fault,
                             bool closedLoop)
{
    FeedbackReading r;
    double raw = s.busFeedback; // C1.09 = 0: "used for Profibus application" (A1.02)
    if (const auto type = SensorType::fromSelection(s.sensor)) {
        r.positiveOnly = type->positiveOnly;
        r.signal = type->signal(std::clamp(fraction, 0.0, 1.0));
        if (fault == SensorFault::WireBreak)
            r.signal = 0.0;
        if (fault == SensorFault::Overload)
            r.signal = type->current ? 24.0 : 12.0;
        const bool watching = s.fractureDetection == 1 || (s.fractureDetection == 2 && closedLoop);
        r.fracture = watching && type->fractured(r.signal);
        r.overload = type->overloaded(r.signal);
        raw = type->toVolts(r.signal);
    }
    const double gain = raw < 0.0 ? s.gain * s.negativeGain : s.gain;
    r.volts = std::clamp(static_cast<double>(s.sign) * gain * raw + s.offset, -9.999, 9.999);
    return r;
}

} // namespace vt::dev::sim
