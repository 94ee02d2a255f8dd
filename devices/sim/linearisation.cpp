#include "sim/linearisation.h"

#include <algorithm>
#include <cmath>

namespace vt::dev::sim {

namespace {
constexpr double kFullScale = 10.0;
constexpr std::array<double, 5> kCurveExponent{1.2, 1.4, 1.6, 1.8, 2.0};
} // namespace

double Linearisation::numberedCurve(int curve, double x)
{
    if (curve < 1 || curve > static_cast<int>(kCurveExponent.size()))
        return x;
    const double exponent = kCurveExponent[static_cast<std::size_t>(curve - 1)];
    const double magnitude = std::min(std::abs(x), kFullScale);
    return std::copysign(kFullScale * std::pow(magnitude / kFullScale, exponent), x);
}

double Linearisation::customCurve(const CustomCurve &points, double x)
{
    const double magnitude = std::abs(x);
    double y = points.front().y;
    CurvePoint last = points.front();
    for (std::size_t i = 1; i < points.size(); ++i) {
        const CurvePoint &p = points[i];
        if (p.x <= last.x)
            continue; // a point that does not move right cannot bound a segment
        if (magnitude <= p.x) {
            const double t = (magnitude - last.x) / (p.x - last.x);
            return std::copysign(last.y + t * (p.y - last.y), x);
        }
        last = p;
        y = p.y;
    }
    return std::copysign(y, x);
}

} // namespace vt::dev::sim
