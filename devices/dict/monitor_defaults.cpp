#include "monitor_defaults.h"

#include <cstdint>

namespace vt::dev {

bool SetValueActivation::holds(double held) const
{
    if (!state)
        return held == value;
    const auto word = static_cast<std::uint16_t>(static_cast<std::int64_t>(held));
    return dsp408::stateOfStatusWord(word) == state;
}

const MonitorDefaults &MonitorPlan::forMode(const std::string &mode) const
{
    const auto it = byMode.find(mode);
    return it == byMode.end() ? all : it->second;
}

} // namespace vt::dev
