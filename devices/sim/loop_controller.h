// The P-PT1-I-DT1 controller of a branch's C block (C1.00 = 1): lag error e = w − x (d1.12) in,
// controller output (d1.13) out. Parameters as the dictionaries describe them (OPAT manual §7
// IDs 0x36..0x3D, 0xB4; DMA Profinet manual §6 IDs 0x36..0x3D, 0xB3).
#pragma once

namespace vt::dev::sim {

struct LoopSettings
{
    double kp1 = 1.0;          // C1.13 P-portion KP1
    double pt1Time = 0.0;      // C1.14 s, PT1 of the KP2 portion ("T-Portion for PT1 (to C1.16)")
    double threshold = 0.0;    // C1.15 V, between KP1 and KP2
    double kp2 = 1.0;          // C1.16 P-portion KP2
    double ki = 0.0;           // C1.17 I-portion, V/s per V of lag error
    double kd = 0.0;           // C1.18 D-portion, Vs
    double dt1Time = 0.0;      // C1.19 s
    double pGain = 1.0;        // C1.20 additional gain for C1.13 and C1.16
    double iLimit = 9.999;     // C1.33 V, limit of the I-portion's output
    bool positiveOnly = false; // C1.09 = 10..12: "no negative controller output possible"
};

// How the parts add up (the manuals name the parts but give no block diagram; our reading):
//  * P: KP2 acts on the lag error inside ±C1.15, through the PT1 C1.14; KP1 on the part beyond
//    the threshold. With the default threshold 0 only KP1 (C1.13) acts, which makes C1.13 "the"
//    proportional gain, as the Device simulator issue expects. Both are multiplied by C1.20.
//  * I: u_I' = C1.17 · e, clamped to ±C1.33 (anti wind-up as the manual describes it: "Limits the
//    output of the I-portion").
//  * DT1: u_D = C1.18 · s / (1 + C1.19 · s) · e.
//  * Output: sum, clamped to ±9.999 V (0 … 9.999 V with a positive-only sensor).
class LoopController
{
public:
    static constexpr double kOutputLimit = 9.999; // V

    void reset();
    double step(double error, const LoopSettings &s, double dt);

    double output() const { return m_output; }
    double pPart() const { return m_p; }
    double iPart() const { return m_i; }
    double dPart() const { return m_d; }

private:
    double m_pt1 = 0; // filtered KP2 input
    double m_i = 0;
    double m_d = 0;
    double m_p = 0;
    double m_previousError = 0;
    bool m_primed = false;
    double m_output = 0;
};

} // namespace vt::dev::sim
