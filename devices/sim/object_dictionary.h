// ObjectDictionary: what a simulated device offers a CANopen SDO server (CiA 301 §7.4: objects by
// 16-bit index and 8-bit sub-index). The SDO server (canopen_sdo_server.h) does the protocol; a
// device model says what an object holds and whether an access is allowed, so any device — the
// Wandfluh ED1 with its CiA 408 objects (canopen_dsp408_objects.h), an HCS module with its
// manufacturer objects 0x2000 + ID (canopen_hcs_objects.h, ARCHITECTURE.md "CAN") — plugs in.
// Single-threaded, like the device behind it.
#pragma once

#include "core/result.h"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace vt::dev::sim {

// CiA 301 §7.2.4.3.17 abort codes the simulators use (texts: canopen::abortCodeText()).
namespace sdo_abort {
inline constexpr std::uint32_t kCommandSpecifier = 0x05040001; // unknown / unsupported command
inline constexpr std::uint32_t kUnsupportedAccess = 0x06010000;
inline constexpr std::uint32_t kWriteOnly = 0x06010001;      // attempt to read a write-only object
inline constexpr std::uint32_t kReadOnly = 0x06010002;       // attempt to write a read-only object
inline constexpr std::uint32_t kNoObject = 0x06020000;       // object does not exist
inline constexpr std::uint32_t kLengthMismatch = 0x06070010; // data type / length does not match
inline constexpr std::uint32_t kLengthTooHigh = 0x06070012;
inline constexpr std::uint32_t kLengthTooLow = 0x06070013;
inline constexpr std::uint32_t kNoSubindex = 0x06090011;   // sub-index does not exist
inline constexpr std::uint32_t kInvalidValue = 0x06090030; // value range of parameter exceeded
inline constexpr std::uint32_t kValueTooHigh = 0x06090031;
inline constexpr std::uint32_t kValueTooLow = 0x06090032;
inline constexpr std::uint32_t kGeneral = 0x08000000;
inline constexpr std::uint32_t kNotStored = 0x08000020;   // cannot be transferred / stored now
inline constexpr std::uint32_t kDeviceState = 0x08000022; // not allowed in the present state
} // namespace sdo_abort

struct SdoAbort
{
    std::uint32_t code = sdo_abort::kGeneral;
    bool operator==(const SdoAbort &) const = default;
};

// An object's value as the expedited transfer carries it: `size` bytes (1, 2 or 4) of `bits`,
// little-endian on the wire (CiA 301 §7.1.3.1), zero-extended here.
struct ObjectValue
{
    std::uint32_t bits = 0;
    std::size_t size = 4;
    bool operator==(const ObjectValue &) const = default;
};

// A download's stated length against the object's width in bytes (CiA 301: length of service
// parameter too high / too low); `size` 0 (not stated) always fits.
inline std::optional<SdoAbort> lengthAbort(std::size_t size, std::size_t width)
{
    if (size == 0 || size == width)
        return std::nullopt;
    return SdoAbort{size > width ? sdo_abort::kLengthTooHigh : sdo_abort::kLengthTooLow};
}

class ObjectDictionary
{
public:
    virtual ~ObjectDictionary() = default;

    // Upload: the value or the abort code (no object, no sub-index, write-only, …).
    virtual Result<ObjectValue, SdoAbort> read(std::uint16_t index, std::uint8_t subindex) = 0;
    // Download: `bits` zero-extended; `size` = bytes the client sent, 0 when it did not say.
    // nullopt on success, else the abort code (read-only, length, value range, device state, …).
    virtual std::optional<SdoAbort> write(std::uint16_t index, std::uint8_t subindex,
                                          std::uint32_t bits, std::size_t size) = 0;
};

} // namespace vt::dev::sim
