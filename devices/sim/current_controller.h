// Current controller of one solenoid output stage: the measured current (d1.07 / d1.08) follows
// the demanded current as a first-order lag, with the dither on top, and watches the stage for
// the DMA manuals' output-stage errors (over current, open circuit, short circuit).
#pragma once

#include <cstdint>

namespace vt::dev::sim {

enum class SolenoidFault {
    None,
    OpenCircuit,  // wire break at the output stage: no current flows
    ShortCircuit, // short circuit: the current runs away to the supply limit
};

struct CurrentControllerConstants
{
    // ASSUMPTION: the cards publish only the PI settings E04..E07 (read-only, for the selected
    // solenoid), not the resulting dynamics; 3 ms is a typical closed current loop.
    double timeConstant = 0.003; // s
    // A shorted stage: the current rises with the wiring's own time constant to the limit of the
    // supply; 10 A passes the DMA's 8 A peak threshold, as a real short would.
    double shortCircuitCurrent = 10.0;        // A
    double shortCircuitTimeConstant = 0.0005; // s
};

struct DitherSettings
{
    double amplitude = 0;   // A, peak (E13 / E1.13: "3.000 V = 30 % of max. rated current")
    double frequency = 100; // Hz (E14 / E1.14)
};

class CurrentController
{
public:
    explicit CurrentController(CurrentControllerConstants constants = {}) : m_c(constants) {}

    void reset();
    // demand in A (>= 0); timeUs is the simulated time at the end of the step (dither phase).
    void step(double demand, const DitherSettings &dither, double dt, std::int64_t timeUs);

    void setFault(SolenoidFault fault) { m_fault = fault; }
    SolenoidFault fault() const { return m_fault; }

    double current() const { return m_current; } // A, what d1.07/d1.08 show (with dither)
    double mean() const { return m_mean; }       // A, without dither (what moves the spool)
    double demand() const { return m_demand; }   // A
    double peak() const { return m_peak; }       // A, highest current since reset()
    // DMA Profinet manual §4.5.1.1 error 8: "IError > 250 mA for tError approx. 100 ms".
    bool deviationError() const { return m_deviationTime >= kDeviationTime; }

    static constexpr double kDeviationLimit = 0.250; // A
    static constexpr double kDeviationTime = 0.100;  // s

private:
    CurrentControllerConstants m_c;
    SolenoidFault m_fault = SolenoidFault::None;
    double m_mean = 0, m_current = 0, m_demand = 0, m_peak = 0;
    double m_deviationTime = 0;
};

} // namespace vt::dev::sim
