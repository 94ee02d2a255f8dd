// describeAny: one entry point that explains a frame of any protocol ValveTune speaks, for the
// telegram inspector's paste box and `valvetune-cli decode`. It only dispatches to the codecs'
// own describe() functions; the options a protocol does not use are ignored.
#pragma once

#include "core/direction.h"
#include "core/enum_key.h"
#include "core/field_span.h"
#include "core/link_protocol.h"
#include "core/result.h"
#include "dict/dictionary.h"
#include "dsp408/gateway.h"
#include "dsp408/options.h"
#include "hcs/types.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vt::dev {

// The frame layouts describeAny explains: finer than LinkProtocol (a PKW or PZD telegram, a
// PROFIdrive telegram, a bare gateway telegram travel over links ValveTune does not drive).
// Dsp408Gateway: a Modbus TCP ADU of a PROFIBUS-master gateway carrying the ED1's image.
enum class FrameFormat {
    Gateway,
    ModbusRtu,
    ModbusTcp,
    Profidrive,
    Pkw,
    Pzd,
    Hart,
    Canopen,
    Dsp408Gateway
};

inline constexpr std::array kFrameFormats{
    FrameFormat::Gateway,    FrameFormat::ModbusRtu, FrameFormat::ModbusTcp,
    FrameFormat::Profidrive, FrameFormat::Pkw,       FrameFormat::Pzd,
    FrameFormat::Hart,       FrameFormat::Canopen,   FrameFormat::Dsp408Gateway};

// "gateway", "modbus-rtu", "modbus-tcp", "profidrive", "pkw", "pzd", "hart", "canopen",
// "dsp408-gateway".
const char *key(FrameFormat format);
template<> std::optional<FrameFormat> fromKey<FrameFormat>(std::string_view key);

// The layout of the frames a link of `protocol` carries (the node image carries the gateway
// telegrams of the manuals, padded to the image size: DMA Profinet manual §4.5.4).
FrameFormat frameFormatOf(LinkProtocol protocol);

struct AnyOptions
{
    FrameFormat protocol = FrameFormat::Gateway;
    hcs::Family family = hcs::Family::Dma; // gateway, Modbus exception texts
    Direction direction = Direction::Request;
    std::string profile; // gateway CMD 15 layout key (hcs::allProfiles()); empty = default
    std::optional<std::uint32_t> cobId; // CANopen: the frame's COB-ID (decides the direction)
    // HCS parameter names and cooked values ("ID 0x0030 (C1.07 …)", "1.000 V"); nullptr = raw.
    const Dictionary *dictionary = nullptr;
    // PKW / PZD / dsp408-gateway: the IND byte and PZD word order and the gateway's register byte
    // order the link was configured with (ARCHITECTURE.md "Byte order"); the direction is
    // `direction` above.
    dsp408::Options dsp408;
    dsp408::RegisterByteOrder registerBytes = dsp408::RegisterByteOrder::FirstByteHigh;
};

// Fails only for options that make no sense (an unknown CMD 15 profile key); a frame that does
// not decode is a Description with `error` set.
Result<Description, std::string> describeAny(std::span<const std::uint8_t> bytes,
                                             const AnyOptions &options);

} // namespace vt::dev
