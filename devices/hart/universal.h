// Typed payloads of the HART universal commands the SD7 supports (HART-7 manual §5.1: commands
// 0, 1, 2, 3, 6, 7, 8, 9, 11–22, 38, 48), their encoders, decoders and field descriptions.
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/field_span.h"
#include "core/result.h"
#include "hart/data_types.h"
#include "hart/frame.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace vt::dev::hart {

// Commands 0, 11, 21 response (§5.1.1, §5.1.9, §5.1.19). HART 5/6 devices send fewer than the
// 22 bytes of HART 7: `length` says how many were present (≥ 12); absent fields stay 0.
struct Identity
{
    std::uint8_t expansionCode = 254;
    std::uint16_t expandedDeviceType = 0;
    std::uint8_t minRequestPreambles = 5;
    std::uint8_t hartRevision = 7;
    std::uint8_t deviceRevision = 0;
    std::uint8_t softwareRevision = 0;
    std::uint8_t hardwareRevisionAndSignaling = 0; // revision in bits 7..3, signaling code 2..0
    std::uint8_t flags = 0;
    std::uint32_t deviceId = 0; // 24 bits
    std::uint8_t minResponsePreambles = 5;
    std::uint8_t maxDeviceVariables = 0;
    std::uint16_t configChangeCounter = 0;
    std::uint8_t extendedStatus = 0;
    std::uint16_t manufacturerId = 0; // Wandfluh: 24835 = 0x6103 (§3.4)
    std::uint16_t privateLabel = 0;
    std::uint8_t deviceProfile = 0;
    std::size_t length = 22;

    std::uint8_t hardwareRevision() const { return hardwareRevisionAndSignaling >> 3; }
    std::uint8_t physicalSignaling() const { return hardwareRevisionAndSignaling & 0x07; }
    // The long-frame address of this device (§2.3, §3.4 "Device Type … bits 24..37").
    Address address(bool primaryMaster = true) const
    {
        return longAddress(expandedDeviceType, deviceId, primaryMaster);
    }
    bool operator==(const Identity &) const = default;
};

// Unit code + IEEE 754 value: command 1 response (§5.1.2), the variables of command 3.
struct UnitValue
{
    std::uint8_t unit = 250; // 250 = "not used"
    float value = 0.0f;
    bool operator==(const UnitValue &) const = default;
};

// Command 2 response (§5.1.3).
struct LoopCurrent
{
    float currentMa = 0.0f;
    float percentOfRange = 0.0f;
    bool operator==(const LoopCurrent &) const = default;
};

// Command 3 response (§5.1.4): loop current + up to four dynamic variables (PV, SV, TV, QV).
struct DynamicVariables
{
    float loopCurrentMa = 0.0f;
    std::vector<UnitValue> variables;
    bool operator==(const DynamicVariables &) const = default;
};

// Command 6 request/response, command 7 response (§5.1.5, §5.1.6).
struct LoopConfiguration
{
    std::uint8_t pollAddress = 0;
    std::uint8_t loopCurrentMode = 1; // HART 5 masters send no second byte; decoded as 1 (enabled)
    bool operator==(const LoopConfiguration &) const = default;
};

// Command 8 response (§5.1.7): PV, SV, TV, QV classification codes.
struct VariableClassifications
{
    std::array<std::uint8_t, 4> codes{};
    bool operator==(const VariableClassifications &) const = default;
};

// Command 9 request (§5.1.8): 1..8 device variable codes.
struct DeviceVariableCodes
{
    std::vector<std::uint8_t> codes;
    bool operator==(const DeviceVariableCodes &) const = default;
};

// Command 9 response (§5.1.8): extended status, 8 bytes per slot, slot-0 time stamp.
struct DeviceVariableSlot
{
    std::uint8_t code = 0;
    std::uint8_t classification = 0;
    std::uint8_t unit = 250;
    float value = 0.0f;
    std::uint8_t status = 0;
    bool operator==(const DeviceVariableSlot &) const = default;
};
struct DeviceVariables
{
    std::uint8_t extendedStatus = 0;
    std::vector<DeviceVariableSlot> variableSlots;
    std::optional<std::uint32_t> timestamp; // 1/32 ms units
    bool operator==(const DeviceVariables &) const = default;
};

// Command 11 request (§5.1.9): tag, 6 bytes packed ASCII (8 characters).
struct Tag
{
    std::string tag;
    bool operator==(const Tag &) const = default;
};

// Command 12 response, 17 request/response (§5.1.10, §5.1.15): 24 bytes packed (32 characters).
struct Message
{
    std::string text;
    bool operator==(const Message &) const = default;
};

// Command 13 response, 18 request/response (§5.1.11, §5.1.16).
struct TagDescriptorDate
{
    std::string tag;        // bytes 0..5, packed ASCII, 8 characters
    std::string descriptor; // bytes 6..17, packed ASCII, 16 characters
    Date date;              // bytes 18..20
    bool operator==(const TagDescriptorDate &) const = default;
};

// Command 14 response (§5.1.12).
struct TransducerInfo
{
    std::uint32_t serialNumber = 0; // 24 bits
    std::uint8_t unit = 250;
    float upperLimit = 0.0f;
    float lowerLimit = 0.0f;
    float minimumSpan = 0.0f;
    bool operator==(const TransducerInfo &) const = default;
};

// Command 15 response (§5.1.13).
struct DeviceInfo
{
    std::uint8_t alarmSelection = 0;
    std::uint8_t transferFunction = 0;
    std::uint8_t rangeUnit = 250;
    float upperRange = 0.0f;
    float lowerRange = 0.0f;
    float damping = 0.0f;
    std::uint8_t writeProtect = 251;
    std::uint8_t reserved = 250;
    std::uint8_t analogChannelFlags = 0;
    bool operator==(const DeviceInfo &) const = default;
};

// Command 16 response, 19 request/response (§5.1.14, §5.1.17): 24-bit number.
struct FinalAssemblyNumber
{
    std::uint32_t number = 0;
    bool operator==(const FinalAssemblyNumber &) const = default;
};

// Command 20 response, 21 request, 22 request/response (§5.1.18–§5.1.20): 32 bytes Latin-1.
struct LongTag
{
    std::string text;
    bool operator==(const LongTag &) const = default;
};

// Command 38 request/response (§5.1.21); HART 5/6 masters send no counter.
struct ConfigChangeCounter
{
    std::optional<std::uint16_t> counter;
    bool operator==(const ConfigChangeCounter &) const = default;
};

// Command 48 request/response (§5.1.22): up to 25 status bytes, kept as sent.
struct AdditionalStatus
{
    Bytes bytes;
    std::uint8_t at(std::size_t i) const { return i < bytes.size() ? bytes[i] : 0; }
    std::uint8_t extendedStatus() const { return at(6); }
    std::uint8_t operatingMode() const { return at(7); }
    bool operator==(const AdditionalStatus &) const = default;
};

using Payload =
    std::variant<std::monostate, Identity, UnitValue, LoopCurrent, DynamicVariables,
                 LoopConfiguration, VariableClassifications, DeviceVariableCodes, DeviceVariables,
                 Tag, Message, TagDescriptorDate, TransducerInfo, DeviceInfo, FinalAssemblyNumber,
                 LongTag, ConfigChangeCounter, AdditionalStatus>;

// True for the universal commands of the HART-7 manual §5.1.
bool isUniversal(std::uint8_t command);

// Data bytes (after the status bytes of a response) of a universal command. monostate for
// commands without data in that direction. Short data is BadLength; extra bytes are ignored, as
// HART masters must accept newer devices' longer replies. Others: UnexpectedCommand.
Result<Payload, DecodeError> decodeUniversal(std::uint8_t command, bool response,
                                             std::span<const std::uint8_t> data);
// The data bytes of a payload (monostate: none).
Bytes encodePayload(const Payload &payload);

// Rows for the data of a universal command starting at `offset`; the error when it is malformed.
std::optional<DecodeError> describeUniversal(std::uint8_t command, bool response,
                                             std::span<const std::uint8_t> data, std::size_t offset,
                                             int depth, std::vector<FieldSpan> &out);

} // namespace vt::dev::hart
