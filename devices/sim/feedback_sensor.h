// Feedback path of a closed-loop branch: the sensor signal selected by C1.09 (mA or V over the
// measuring range), the card's conversion to ±10 V, gain C1.10 (OPAT C1.36 for negative values),
// sign C1.12 and offset C1.11, and the cable fracture / overload checks (C1.26).
#pragma once

#include <optional>

namespace vt::dev::sim {

enum class SensorFault {
    None,
    WireBreak, // cable fracture: the card sees 0 mA / 0 V
    Overload,  // short to the supply: the card sees 24 mA / 12 V
};

// One C1.09 selection (the values are the same in every HCS family: DMA Profinet manual §6
// ID 0x32, DMA Profibus Anleitung §7, OPAT manual §7).
struct SensorType
{
    bool current = false;      // mA, else V
    double low = 0, high = 10; // signal at 0 % and 100 % of the measuring range
    bool bipolar = false;      // the card maps low..high to −10 … +10 V (else 0 … 10 V)
    bool positiveOnly = false; // "no negative controller output possible" (10..12, OPAT 23, 26)

    // C1.09 = 0 (feedback via the bus, A1.02) and unknown values: nothing.
    // ASSUMPTION for OPAT 21..26 (semi-automatic calibration): bipolar ±10 V, unipolar 0..10 V,
    // bipolar "(internal) current" 12 mA ± 8 mA, unipolar current 4..20 mA.
    static std::optional<SensorType> fromSelection(int c109);

    double signal(double fraction) const { return low + fraction * (high - low); }
    double toVolts(double signal) const;
    // A live zero lets the card see a broken cable: the signal falls below half of it. Half of
    // 4 mA is the DMA manuals' 2 mA wire break threshold (§4.5.1.1, errors 2 and 4).
    bool canDetectFracture() const { return low > 0.0; }
    bool fractured(double signal) const { return canDetectFracture() && signal < low / 2.0; }
    // OPAT manual §7 ERR 5/6: "Overload of current > 22 mA sensor 1/2".
    bool overloaded(double signal) const { return current && signal > 22.0; }
};

struct FeedbackSettings
{
    int sensor = 0;            // C1.09
    double gain = 1.0;         // C1.10
    double negativeGain = 1.0; // OPAT C1.36, relative to C1.10, for values < 0
    double offset = 0.0;       // C1.11, V
    int sign = 1;              // C1.12: −1, 0 = off, +1
    int fractureDetection = 0; // C1.26: 0 off, 1 on, 2 on only in closed loop (OPAT)
    double busFeedback = 0.0;  // A1.02, V: used when C1.09 = 0
};

struct FeedbackReading
{
    double volts = 0;  // d1.11
    double signal = 0; // mA or V at the terminal
    bool fracture = false;
    bool overload = false;
    bool positiveOnly = false;
};

// fraction: the measured quantity as a fraction of the sensor's range (axis position, pressure).
FeedbackReading readFeedback(const FeedbackSettings &s, double fraction, SensorFault fault,
                             bool closedLoop);

} // namespace vt::dev::sim
