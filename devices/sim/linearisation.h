// Set value linearisation C1.02 (d1.03): 0 = linear; "customized curve" = piecewise linear
// through the L1.x0/L1.y0 … L1.x8/L1.y8 points (OPAT manual §7 IDs 0x2B, 0xC6..0xD7); the
// numbered curves 1..5 are not published, so they are documented approximations (below).
#pragma once

#include <array>

namespace vt::dev::sim {

struct CurvePoint
{
    double x = 0, y = 0; // V, 0 … 9.999
};

using CustomCurve = std::array<CurvePoint, 9>;

class Linearisation
{
public:
    // ASSUMPTION: curves 1..5 are y = 10 V · (|x| / 10 V)^p, p = 1.2, 1.4, 1.6, 1.8, 2.0: the
    // progressive shapes that flatten a valve's flow gain near zero. Replace when HCS publishes
    // them.
    static double numberedCurve(int curve, double x);
    // Piecewise linear through the points, mirrored for negative inputs (the L block only has
    // 0 … 9.999 V); beyond the last point the last y holds. Points whose x does not grow are
    // skipped.
    static double customCurve(const CustomCurve &points, double x);
};

} // namespace vt::dev::sim
