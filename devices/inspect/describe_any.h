// describeAny: one entry point that explains a frame of any protocol ValveTune speaks, for the
// telegram inspector's paste box and `valvetune-cli decode`. It only dispatches to the codecs'
// own describe() functions; the options a protocol does not use are ignored.
#pragma once

#include "core/direction.h"
#include "core/field_span.h"
#include "core/result.h"
#include "dict/dictionary.h"
#include "hcs/types.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vt::dev {

enum class Protocol { Gateway, ModbusRtu, ModbusTcp, Profidrive, Pkw, Pzd, Hart, Canopen };

const std::vector<Protocol> &allProtocols();
const char *protocolName(Protocol protocol); // "gateway", "modbus-rtu", …
std::optional<Protocol> protocolFromName(std::string_view name);

struct AnyOptions
{
    Protocol protocol = Protocol::Gateway;
    hcs::Family family = hcs::Family::Dma; // gateway, Modbus exception texts
    Direction direction = Direction::Request;
    std::string profile; // gateway CMD 15 layout key (hcs::allProfiles()); empty = default
    std::optional<std::uint32_t> cobId; // CANopen: the frame's COB-ID (decides the direction)
    // HCS parameter names and cooked values ("ID 0x0030 (C1.07 …)", "1.000 V"); nullptr = raw.
    const Dictionary *dictionary = nullptr;
};

// Fails only for options that make no sense (an unknown CMD 15 profile key); a frame that does
// not decode is a Description with `error` set.
Result<Description, std::string> describeAny(std::span<const std::uint8_t> bytes,
                                             const AnyOptions &options);

} // namespace vt::dev
