// The valve side of a branch, from the value after the ramps (open loop) or the controller output
// (closed loop) to the solenoid currents: linearisation C1.02 (d1.03) → sign/gain C1.05, offset
// C1.06, gains A/B C1.03/C1.04 (d1.04) → dead band compensation C1.07/C1.08 (d1.05/d1.06) →
// solenoid selection, current adaptation, initial current, dither → currents d1.07, d1.08, d1.09.
// Rows: OPAT manual §7 IDs 0x2B..0x31, 0x62..0x6D, 0x9B..0xA2; DMA Profinet manual §6 (same IDs).
#pragma once

#include "sim/current_controller.h"
#include "sim/linearisation.h"
#include "sim/param_io.h"

#include <array>
#include <map>

namespace vt::dev::sim {

struct ValveChainIds
{
    ParamRef linearisation;                      // C1.02
    std::array<ParamRef, 9> curveX, curveY;      // L1.x0..L1.x8, L1.y0..L1.y8
    ParamRef gainA, gainB;                       // C1.03, C1.04
    ParamRef signGain, offset;                   // C1.05, C1.06
    ParamRef deadBandA, deadBandB;               // C1.07, C1.08
    ParamRef solenoidA, solenoidB;               // E1.03 (OPAT E03), E2.03
    ParamRef adaptationA, adaptationB;           // E1.10 (OPAT E10), E2.10
    ParamRef initialA, initialB;                 // E11, E12
    ParamRef ditherAmplitudeA, ditherFrequencyA; // E1.13/E1.14 (OPAT E13/E14)
    ParamRef ditherAmplitudeB, ditherFrequencyB; // E2.13/E2.14
    // d1.03..d1.09
    ParamRef afterLinearisation, afterGain, signalA, signalB, currentA, currentB, currentTotal;

    // C1.02's value for the customized curve (OPAT "6 = Customized curve"), -1 if there is none.
    int customCurveValue = -1;
    // Rated current per solenoid selection value, from the enum labels ("2.7 A", "0.630 A").
    std::map<std::int64_t, double> ratedA, ratedB;

    static ValveChainIds resolve(const Dictionary &dict, int branch);
};

// What the chain shows, in display units (V, A).
struct ValveChainValues
{
    double afterLinearisation = 0;   // d1.03
    double afterGain = 0;            // d1.04
    double signalA = 0, signalB = 0; // d1.05, d1.06 (0 … 9.999 V = 0 … max. current)
    double currentA = 0, currentB = 0, currentTotal = 0; // d1.07..d1.09 (measured, with dither)
    double spoolCommand = 0; // −1 … 1: (I_A / rated A) − (I_B / rated B), without dither
};

class ValveChain
{
public:
    // ASSUMPTION: a solenoid selection whose label carries no current reads as this rated current.
    static constexpr double kFallbackRatedCurrent = 1.0; // A
    // The dead band jump happens once the value leaves zero by more than one raw step (1 mV), so
    // a value resting at 0 draws no current.
    static constexpr double kDeadBandThreshold = 0.001; // V
    static constexpr double kFullScale = 10.0;          // V: 9.999 V = max. current

    ValveChain(ValveChainIds ids, CurrentControllerConstants currentConstants = {});

    void reset();
    // input: V; outputsOn false = disabled or error: no current is demanded and the signals show 0.
    const ValveChainValues &step(double input, bool outputsOn, const ParamReader &params, double dt,
                                 std::int64_t timeUs);
    void publish(ParamPublisher &out) const;

    const ValveChainValues &values() const { return m_values; }
    CurrentController &solenoidA() { return m_a; }
    CurrentController &solenoidB() { return m_b; }
    const CurrentController &solenoidA() const { return m_a; }
    const CurrentController &solenoidB() const { return m_b; }
    double ratedCurrentA(const ParamReader &params) const;
    double ratedCurrentB(const ParamReader &params) const;

    // Pure pieces of the chain, for tests and the docs.
    double linearise(double x, const ParamReader &params) const;
    static double deadBand(double magnitude, double compensation);

private:
    ValveChainIds m_ids;
    CurrentController m_a, m_b;
    ValveChainValues m_values;
};

} // namespace vt::dev::sim
