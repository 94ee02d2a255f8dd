#include "dict/device_protocol.h"

#include "core/key_lookup.h"

namespace vt::dev {

const char *key(DeviceProtocol protocol)
{
    switch (protocol) {
    case DeviceProtocol::Hcs: return "hcs";
    case DeviceProtocol::Dsp408: return "dsp408";
    case DeviceProtocol::Hart: return "hart";
    }
    return "?";
}

template<> std::optional<DeviceProtocol> fromKey<DeviceProtocol>(std::string_view text)
{
    return keyLookup<DeviceProtocol>(kDeviceProtocols, text);
}

} // namespace vt::dev
