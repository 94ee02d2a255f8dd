#include "dsp408/scaling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vt::dev::dsp408 {
namespace {

std::int32_t truncateToInt32(double x)
{
    if (!std::isfinite(x))
        return 0;
    const double nudged = x + std::copysign(1e-9 * std::max(1.0, std::fabs(x)), x);
    const double t = std::trunc(nudged);
    constexpr double lo = std::numeric_limits<std::int32_t>::min();
    constexpr double hi = std::numeric_limits<std::int32_t>::max();
    if (t <= lo)
        return std::numeric_limits<std::int32_t>::min();
    if (t >= hi)
        return std::numeric_limits<std::int32_t>::max();
    return static_cast<std::int32_t>(t);
}

} // namespace

double factReference(double maxReferenceValue, double maxInterfaceRange, double maxInterfaceValue)
{
    if (maxInterfaceValue == 0.0)
        return 0.0;
    return maxReferenceValue * maxInterfaceRange / (maxInterfaceValue * 4096.0);
}

std::int32_t scaleToRaw(double value, double factor)
{
    if (!(factor > 0.0))
        return 0;
    return truncateToInt32(value / factor);
}

std::int32_t scaleFromRaw(std::int32_t raw, double factor)
{
    if (!(factor > 0.0))
        return 0;
    return truncateToInt32(static_cast<double>(raw) * factor);
}

} // namespace vt::dev::dsp408
