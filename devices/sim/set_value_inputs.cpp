#include "sim/set_value_inputs.h"

#include <algorithm>

namespace vt::dev::sim {

SetValueIds SetValueIds::resolve(const Dictionary &dict, int branch)
{
    SetValueIds ids;
    ids.busSetValues[0] = findParam(dict, branchName("A1.01", branch));
    // DMA Profibus Anleitung §7 ID 0x27 (and the dma-pn-v13 row): "in Modus 1 auch für Zweig 1".
    const bool modeOneOnly = dict.modes.size() == 1 && dict.modes.front() == "1";
    if (branch == 1 && modeOneOnly)
        ids.busSetValues[1] = findParam(dict, "A2.01");
    ids.busSetValues[2] = findParam(dict, branchName("B1.01", branch));
    if (branch == 1) {
        // The analogue inputs feed branch 1; the manuals give branch 2 no analogue set value.
        ids.selectS106 = findParam(dict, "E15");
        ids.selectS105 = findParam(dict, "E16");
    }
    ids.activation = findParam(dict, "E17");
    return ids;
}

void SetValueInputs::setInput(AnalogueInput input, double physical)
{
    (input == AnalogueInput::S1_06 ? m_s106 : m_s105) = physical;
}

double SetValueInputs::input(AnalogueInput input) const
{
    return input == AnalogueInput::S1_06 ? m_s106 : m_s105;
}

double SetValueInputs::toVolts(int selection, double physical)
{
    switch (selection) {
    case 0: return physical;        // voltage input, ±10 V
    case 1: return physical / 2.0;  // 0 … 20 mA -> 0 … 10 V
    case 2: return physical - 10.0; // 10 mA ± 10 mA -> ±10 V
    case 3:
    case 4: return (physical - 4.0) * 10.0 / 16.0; // 4 … 20 mA -> 0 … 10 V
    case 5:
    case 6: return (physical - 12.0) * 10.0 / 8.0; // 12 mA ± 8 mA -> ±10 V
    case 7: return (physical - 5.0) * 2.0;         // OPAT: 5 V ± 5 V -> ±10 V
    default: return physical;
    }
}

SetValueSum SetValueInputs::evaluate(const ParamReader &params) const
{
    SetValueSum sum;
    for (const ParamRef &ref : m_ids.busSetValues)
        sum.digital += params.value(ref, 0.0);

    // E17 = 2: "only the digital (bus) set value is active" (OPAT manual §7 ID 0x70).
    const bool analogueActive = params.raw(m_ids.activation, 0) != 2;
    struct Input
    {
        const ParamRef &select;
        double physical;
        PlantError wireBreak, overCurrent;
    };
    const Input inputs[] = {
        {m_ids.selectS106, m_s106, PlantError::SetValueWireBreak, PlantError::SetValueOverCurrent},
        {m_ids.selectS105, m_s105, PlantError::SetValueWireBreak2,
         PlantError::SetValueOverCurrent2},
    };
    for (const Input &in : inputs) {
        if (!in.select.valid() || !analogueActive)
            continue;
        const int selection = params.raw(in.select, 0);
        if (detectsWireBreak(selection)) {
            if (in.physical < kWireBreakMilliAmp)
                sum.errors.set(in.wireBreak);
            if (in.physical > kOverCurrentMilliAmp)
                sum.errors.set(in.overCurrent);
        }
        sum.analogue += std::clamp(toVolts(selection, in.physical), -10.0, 10.0);
    }
    return sum;
}

} // namespace vt::dev::sim
