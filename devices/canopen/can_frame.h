// One classic CAN frame, its Linux SocketCAN `struct can_frame` wire layout (so the CAN link can
// stay fd-based without kernel headers) and the candump text form "605#4040600000000000".
#pragma once

#include "core/decode_error.h"
#include "core/result.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace vt::dev::canopen {

inline constexpr std::uint32_t kMaxStandardId = 0x7FF;
inline constexpr std::uint32_t kMaxExtendedId = 0x1FFFFFFF;
inline constexpr std::size_t kSocketCanFrameSize = 16;

struct CanFrame
{
    std::uint32_t id = 0; // 11 bits (29 with `extended`)
    bool extended = false;
    bool rtr = false;
    bool errorFrame = false; // SocketCAN CAN_ERR_FLAG
    std::uint8_t dlc = 0;    // 0..8
    std::array<std::uint8_t, 8> data{};

    std::span<const std::uint8_t> payload() const
    {
        return std::span<const std::uint8_t>(data).first(dlc <= 8 ? dlc : 8);
    }
    bool operator==(const CanFrame &) const = default;
};

CanFrame makeCanFrame(std::uint32_t id, std::span<const std::uint8_t> payload); // payload ≤ 8 bytes

// Linux <linux/can.h> struct can_frame: can_id (u32, host byte order, flags EFF 0x80000000,
// RTR 0x40000000, ERR 0x20000000), len (u8), 3 pad/reserved bytes, data[8] — 16 bytes.
std::array<std::uint8_t, kSocketCanFrameSize> toSocketCan(const CanFrame &frame);
// Exactly 16 bytes; len > 8 (CAN FD) is BadLength, an id beyond its format's range BadValue.
Result<CanFrame, DecodeError> fromSocketCan(std::span<const std::uint8_t> bytes);

// candump notation: "<id>#<hex data>", 3 hex digits = standard id, 8 = extended, "R" = RTR.
Result<CanFrame, DecodeError> parseCandump(std::string_view text);
std::string formatCandump(const CanFrame &frame);

} // namespace vt::dev::canopen
