// Set value sources of one branch and their sum (d1.01): the bus set value A1.01 (plus A2.01 in
// mode 1, plus the OPAT ProfiDrive set value B1.01) and the analogue inputs S1.06 (E15) and
// S1.05 (E16, DMA only), gated by E17; current inputs are checked for wire break / over current.
#pragma once

#include "sim/param_io.h"
#include "sim/plant_errors.h"

#include <array>
#include <utility>

namespace vt::dev::sim {

enum class AnalogueInput { S1_06, S1_05 };

struct SetValueIds
{
    std::array<ParamRef, 3> busSetValues; // A1.01, A2.01 (mode-1 families only), B1.01 (OPAT)
    ParamRef selectS106, selectS105;      // E15, E16
    ParamRef activation;                  // E17

    static SetValueIds resolve(const Dictionary &dict, int branch);
};

struct SetValueSum
{
    double digital = 0;  // V: bus set values ("digital (bus) set value", OPAT manual §7 E17)
    double analogue = 0; // V: analogue inputs, 0 when E17 = 2
    PlantErrors errors;
    double total() const { return digital + analogue; }
};

class SetValueInputs
{
public:
    explicit SetValueInputs(SetValueIds ids) : m_ids(std::move(ids)) {}

    // The physical signal at the terminal, in the unit E15/E16 selects: V for the voltage input,
    // mA for the current inputs. Unconnected inputs read 0.
    void setInput(AnalogueInput input, double physical);
    double input(AnalogueInput input) const;

    SetValueSum evaluate(const ParamReader &params) const;

    // DMA Profinet manual §4.5.1.1 / dictionary E15: wire break below 2 mA, over current above
    // 25 mA, both only for the selections "with cable fracture detection".
    static constexpr double kWireBreakMilliAmp = 2.0;
    static constexpr double kOverCurrentMilliAmp = 25.0;

    // The card's value in V for a physical signal under selection E15/E16 (0..7); ±10 V full scale.
    static double toVolts(int selection, double physical);
    static bool isCurrent(int selection) { return selection >= 1 && selection <= 6; }
    static bool detectsWireBreak(int selection) { return selection == 4 || selection == 6; }

private:
    SetValueIds m_ids;
    double m_s106 = 0, m_s105 = 0;
};

} // namespace vt::dev::sim
