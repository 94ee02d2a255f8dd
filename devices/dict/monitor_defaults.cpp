#include "monitor_defaults.h"

namespace vt::dev {

const MonitorDefaults &MonitorPlan::forMode(const std::string &mode) const
{
    const auto it = byMode.find(mode);
    return it == byMode.end() ? all : it->second;
}

} // namespace vt::dev
