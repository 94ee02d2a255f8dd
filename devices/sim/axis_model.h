// The hydraulics behind a closed-loop branch: a proportional valve (spool lag, flow with
// saturation) and the load it drives — a cylinder (mode 3: position, integrating, with the oil
// column's resonance) or a pressure volume (mode 4: first order with leakage). Every constant
// is an ASSUMPTION of a typical axis (the manuals describe the card, not the machine); all are
// in docs/SIMULATOR-PLANT.md and can be changed per simulated module.
#pragma once

#include <memory>

namespace vt::dev::sim {

struct ValveConstants
{
    double spoolTimeConstant = 0.010; // s: a direct-operated proportional valve, ~15 Hz at −3 dB
    // Zero offset of the spool (fraction of nominal flow at zero current): the null shift every
    // real valve has. It is the steady disturbance an I-portion exists for: without C1.17 the
    // loop holds a lag error of nullBias · 10 V / (C1.13 · C1.20).
    double nullBias = 0.01;
    // Zero-flow band of the spool (fraction of stroke). 0: a zero-lapped servo-proportional valve,
    // as closed loops use; open-loop valves have 10..20 %, which C1.07/C1.08 compensate.
    double overlap = 0.0;
};

// Spool position and flow, both as fractions of nominal (−1 … +1).
class ValveModel
{
public:
    explicit ValveModel(ValveConstants c = {}) : m_c(c) {}
    void reset() { m_spool = 0; }
    // command: (I_A / rated) − (I_B / rated), −1 … +1.
    void step(double command, double dt);
    double spool() const { return m_spool; }
    double flow() const; // with overlap, null bias and saturation at nominal flow

private:
    ValveConstants m_c;
    double m_spool = 0;
};

// The load: takes the valve's flow, gives the measured quantity as a fraction of the sensor range.
class AxisModel
{
public:
    virtual ~AxisModel() = default;
    virtual void reset(double fraction) = 0;
    virtual void step(double flow, double dt) = 0;
    virtual double measured() const = 0; // 0 … 1 of the sensor range
};

struct CylinderConstants
{
    // Speed at nominal flow in strokes per second: 100 mm at 0.5 m/s. With a 0 … 10 V sensor over
    // the stroke the loop gain is 5 /s per unit of C1.13 (10 V controller output = nominal flow).
    double maxSpeed = 5.0;
    // Oil column: mass on the compressible oil spring, ~7 Hz, lightly damped.
    double naturalFrequency = 45.0; // rad/s
    double damping = 0.3;
    double start = 0.5; // initial position, fraction of stroke
};

// Integrating cylinder with the hydraulic resonance between commanded and actual velocity:
// v'' = ω²·(v_cmd − v) − 2ζω·v', x' = v; mechanical end stops at 0 and 1 stop it dead.
class CylinderAxis : public AxisModel
{
public:
    explicit CylinderAxis(CylinderConstants c = {});
    void reset(double fraction) override;
    void step(double flow, double dt) override;
    double measured() const override { return m_position; }
    double velocity() const { return m_velocity; }

private:
    CylinderConstants m_c;
    double m_position = 0, m_velocity = 0, m_acceleration = 0;
};

struct PressureConstants
{
    double timeConstant = 0.050; // s: volume capacity against the leakage resistance
    double gain = 1.0;           // steady pressure at nominal flow, fraction of the sensor range
    double relief = 1.0;         // pressure relief valve, fraction of the sensor range
};

// Pressure in a volume with leakage: p' = (gain · q − p) / T, 0 ≤ p ≤ relief.
class PressureAxis : public AxisModel
{
public:
    explicit PressureAxis(PressureConstants c = {}) : m_c(c) {}
    void reset(double fraction) override { m_pressure = fraction; }
    void step(double flow, double dt) override;
    double measured() const override { return m_pressure; }

private:
    PressureConstants m_c;
    double m_pressure = 0;
};

// Mode 3 = position (cylinder), mode 4 = pressure; OPAT mode 6: branch 1 valve/position, branch 2
// process (pressure); mode 8: both processes. Unknown modes get a cylinder.
std::unique_ptr<AxisModel> makeAxisForMode(int mode, int branch);
// Whether makeAxisForMode gives branch `branch` of `mode` a pressure (else a cylinder).
bool isPressureBranch(int mode, int branch);

} // namespace vt::dev::sim
