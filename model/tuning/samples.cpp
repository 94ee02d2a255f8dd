#include "samples.h"

#include "core/vt_assert.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>

namespace vt::model {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool usable(const Samples &s)
{
    VT_ASSERT(s.t.size() == s.y.size(), return false);
    return !s.t.empty();
}

} // namespace

std::size_t firstAfter(const Samples &s, double time)
{
    return static_cast<std::size_t>(
        std::distance(s.t.begin(), std::upper_bound(s.t.begin(), s.t.end(), time)));
}

double valueAt(const Samples &s, double time)
{
    if (!usable(s))
        return kNaN;
    const std::size_t k = firstAfter(s, time);
    if (k == 0)
        return s.y.front();
    if (k == s.t.size())
        return s.y.back();
    // t[k − 1] ≤ time < t[k], so the interval has a length.
    const double w = (time - s.t[k - 1]) / (s.t[k] - s.t[k - 1]);
    return s.y[k - 1] + w * (s.y[k] - s.y[k - 1]);
}

double heldValueAt(const Samples &s, double time)
{
    if (!usable(s))
        return kNaN;
    const std::size_t k = firstAfter(s, time);
    return k == 0 ? s.y.front() : s.y[k - 1];
}

double meanOver(const Samples &s, double from, double to)
{
    if (!usable(s))
        return kNaN;
    from = std::max(from, s.t.front());
    to = std::min(to, s.t.back());
    if (!(to > from))
        return valueAt(s, to);
    double area = 0;
    double prevT = from;
    double prevY = valueAt(s, from);
    for (std::size_t i = firstAfter(s, from); i < s.t.size() && s.t[i] < to; ++i) {
        area += 0.5 * (prevY + s.y[i]) * (s.t[i] - prevT);
        prevT = s.t[i];
        prevY = s.y[i];
    }
    area += 0.5 * (prevY + valueAt(s, to)) * (to - prevT);
    return area / (to - from);
}

double averageRateHz(const Samples &s)
{
    if (s.t.size() < 2)
        return 0;
    const double span = s.t.back() - s.t.front();
    return span > 0 ? static_cast<double>(s.t.size() - 1) / span : 0;
}

} // namespace vt::model
