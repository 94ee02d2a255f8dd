// DeviceProtocol: the application protocol a device family speaks, a property of its dictionary
// (the "protocol" field): HCS parameter telegrams, the DSP-408 profile (PKW/PZD, CiA 408
// objects) or HART commands. It is not the link: an HCS module is reached over Modbus RTU,
// Modbus TCP, the node image or CANopen (LinkProtocol).
#pragma once

#include "core/enum_key.h"

#include <array>
#include <optional>
#include <string_view>

namespace vt::dev {

enum class DeviceProtocol { Hcs, Dsp408, Hart };

inline constexpr std::array kDeviceProtocols{DeviceProtocol::Hcs, DeviceProtocol::Dsp408,
                                             DeviceProtocol::Hart};

// "hcs", "dsp408", "hart" (the dictionaries' "protocol" field).
const char *key(DeviceProtocol protocol);
template<> std::optional<DeviceProtocol> fromKey<DeviceProtocol>(std::string_view key);

} // namespace vt::dev
