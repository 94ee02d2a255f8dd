// The set value side of a branch: the sources (SetValueInputs) summed to d1.01, then the ramps
// r1.01..r1.04 under E08 to d1.02, the set value (open loop) or desired value (closed loop).
#pragma once

#include "sim/ramp.h"
#include "sim/set_value_inputs.h"

#include <array>

namespace vt::dev::sim {

struct SetValuePathIds
{
    SetValueIds inputs;
    std::array<ParamRef, 4> ramps; // r1.01 0⇒−, r1.02 −⇒0, r1.03 0⇒+, r1.04 +⇒0
    ParamRef rampSelection;        // E08
    ParamRef sum, postRamp;        // d1.01, d1.02

    static SetValuePathIds resolve(const Dictionary &dict, int branch);
};

struct SetValuePathValues
{
    double sum = 0;      // d1.01
    double postRamp = 0; // d1.02
    PlantErrors errors;  // wire break / over current of current inputs
};

class SetValuePath
{
public:
    explicit SetValuePath(SetValuePathIds ids);

    void reset() { m_ramp.reset(); }
    // enabled false: the ramp is held at 0 (the card discards set values while disabled or in
    // error); d1.01 keeps showing what arrives, so a missing set value can still be diagnosed.
    const SetValuePathValues &step(const ParamReader &params, bool enabled, double dt);
    void publish(ParamPublisher &out) const;

    SetValueInputs &inputs() { return m_inputs; }
    const SetValuePathValues &values() const { return m_values; }

private:
    SetValuePathIds m_ids;
    SetValueInputs m_inputs;
    Ramp m_ramp;
    SetValuePathValues m_values;
};

} // namespace vt::dev::sim
