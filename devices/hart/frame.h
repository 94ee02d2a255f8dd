// HART-7 link-layer frames (Wandfluh "HART-7 Interface" manual §2.3 "Telegram structure"):
// preambles, delimiter, short or long address, command, byte count, status, data, XOR checksum.
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/result.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace vt::dev::hart {

inline constexpr std::uint8_t kPreamble = 0xFF;
inline constexpr std::uint8_t kMaxPollAddress = 63;         // 6 bits in HART 7 (manual: 0..15)
inline constexpr std::uint16_t kMaxLongDeviceType = 0x3FFF; // bits 37..24 of the long address
inline constexpr std::uint32_t kMaxDeviceId = 0xFFFFFF;     // bits 23..0
inline constexpr std::size_t kMaxExpansionBytes = 3;
inline constexpr std::size_t kMaxPreambles = 255; // our bound; masters send 5..20
inline constexpr std::size_t kMaxByteCount = 255;
// Delimiter + long address + expansion + command + byte count + data + checksum.
inline constexpr std::size_t kMaxFrameSize = 1 + 5 + kMaxExpansionBytes + 2 + kMaxByteCount + 1;

// Delimiter bits 2..0 (manual §2.3 "Start byte (SD)": who sends).
enum class FrameType : std::uint8_t {
    Back = 1, // burst frame, field device → masters
    Stx = 2,  // master → field device
    Ack = 6,  // field device → master
};

// Manual §2.3 "Address (AD)": one byte (short frame) or five bytes (long frame); both carry the
// master bit (1 = primary master) and the burst bit.
struct Address
{
    bool isLong = false;
    bool primaryMaster = true;
    bool burst = false;
    std::uint8_t pollAddress = 0;         // short frame, bits 5..0
    std::uint16_t expandedDeviceType = 0; // long frame, the 14 bits on the wire (bits 37..24)
    std::uint32_t deviceId = 0;           // long frame, 24 bits (bits 23..0)

    bool operator==(const Address &) const = default;
};

Address shortAddress(std::uint8_t pollAddress, bool primaryMaster = true);
// The long address of a device: its expanded device type (the 2 top bits give way to the master
// and burst bits, manual §2.3 "38 bits") and its device id.
Address longAddress(std::uint16_t expandedDeviceType, std::uint32_t deviceId,
                    bool primaryMaster = true);

struct Frame
{
    std::size_t preambles = 5; // leading 0xFF bytes (manual §2.3: "three or more")
    FrameType type = FrameType::Stx;
    std::uint8_t physicalLayer = 0; // delimiter bits 4..3 (0 = asynchronous, FSK)
    Address address;
    Bytes expansion; // 0..3 bytes, count in delimiter bits 6..5
    std::uint8_t command = 0;
    std::uint8_t responseCode = 0; // first status byte, responses (ACK, BACK) only
    std::uint8_t deviceStatus = 0; // second status byte, responses only
    Bytes data;

    bool isResponse() const { return type != FrameType::Stx; }
    bool operator==(const Frame &) const = default;
};

// Builders: a master request (STX) and a field-device response (ACK) to the same address.
Frame makeRequest(const Address &address, std::uint8_t command, Bytes data = {});
Frame makeResponse(const Address &address, std::uint8_t command, std::uint8_t responseCode,
                   std::uint8_t deviceStatus, Bytes data = {});

// The 1 or 5 address bytes (missing bytes read as 0).
Address decodeAddress(std::span<const std::uint8_t> bytes, bool isLong);

std::uint8_t delimiterOf(const Frame &frame);
bool isValidDelimiter(std::uint8_t delimiter);
// Bytes between the delimiter and the byte count (address + expansion + command) for a delimiter.
std::size_t headerSize(std::uint8_t delimiter);
// Manual §2.3 "Parity": longitudinal parity (XOR) of every byte from the delimiter on.
std::uint8_t checksum(std::span<const std::uint8_t> bytes);

// BadValue when a field does not fit (poll address, device type, device id, expansion, byte count).
Result<Bytes, DecodeError> encodeFrame(const Frame &frame);
// One whole frame: any number of preambles (0 too, as HART-IP carries it), then delimiter …
// checksum and nothing after it. Layout only: the data is not interpreted.
Result<Frame, DecodeError> decodeFrame(std::span<const std::uint8_t> bytes);

} // namespace vt::dev::hart
