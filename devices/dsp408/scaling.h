// DSP-408 scaling between engineering units and the integers on the bus (ED1/SD1 PROFIBUS-DP
// manual §4.7): raw = value / factor and value = raw × factor, both truncated as the device does.
#pragma once

#include <cstdint>

namespace vt::dev::dsp408 {

// ED1/SD1 manual §4.7.2–§4.7.4: fixed factors.
inline constexpr double kFactSolCurrent = 1.78;       // mA per step
inline constexpr double kFactPercentage = 97.65625;   // FactPercentage
inline constexpr double kFactInterface = 0.009765625; // V per step

// ED1/SD1 manual §4.7.1: FactReference = maxReferenceValue × maxInterfaceRange /
// (maxInterfaceValue × 4096); 0 when maxInterfaceValue is 0.
double factReference(double maxReferenceValue, double maxInterfaceRange, double maxInterfaceValue);

// ED1/SD1 manual §4.7 example: 60 mA / 1.78 = 33.7 → 33 on the bus. Truncates toward zero; a
// 1e-9 relative nudge keeps exact quotients (89 / 1.78 = 50) from dropping to 49 through binary
// rounding. Factor ≤ 0 or a non-finite result gives 0; results saturate at the int32 range.
std::int32_t scaleToRaw(double value, double factor);
// ED1/SD1 manual §4.7 example: 33 × 1.78 = 58.74 → 58 mA read back. Same truncation rules.
std::int32_t scaleFromRaw(std::int32_t raw, double factor);

} // namespace vt::dev::dsp408
