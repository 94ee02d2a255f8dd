// Set value ramp of one branch, r1.01..r1.04 (r2.xx for branch 2): one time per quadrant
// 0⇒−, −⇒0, 0⇒+, +⇒0; "1 == 10 ms; 0 == ramp function off" (OPAT manual §7 IDs 0x1B..0x1E,
// DMA Profinet manual §6, DMA Profibus Anleitung §7). E08 selects how the time is meant.
#pragma once

namespace vt::dev::sim {

struct RampTimes
{
    double zeroToNeg = 0; // r1.01, seconds; 0 = no ramp
    double negToZero = 0; // r1.02
    double zeroToPos = 0; // r1.03
    double posToZero = 0; // r1.04
};

enum class RampKind {
    // E08 = 0, "digital set values (time constant)": every change of the target takes the
    // quadrant's time, whatever its size (a change across 0 takes the time of each quadrant).
    TimeConstant,
    // E08 = 1, "all set values (rise constant)": constant slope, the quadrant's time for a
    // full-scale change of kFullScale (the manuals state no reference; full scale is our reading).
    RiseConstant,
};

class Ramp
{
public:
    static constexpr double kFullScale = 10.0; // V: ±10 V set value range (9.999 V displayed)

    void reset(double value = 0.0);
    // Moves the output towards `target` for dt seconds and returns it.
    double step(double target, const RampTimes &times, RampKind kind, double dt);
    double value() const { return m_value; }

private:
    enum class Quadrant { None, ZeroToNeg, NegToZero, ZeroToPos, PosToZero };
    static Quadrant quadrantOf(double from, double target);
    static double timeOf(Quadrant q, const RampTimes &times);

    double m_value = 0.0;
    double m_target = 0.0;
    Quadrant m_quadrant = Quadrant::None;
    double m_segmentStart = 0.0; // output when the current quadrant segment began
};

} // namespace vt::dev::sim
