#include "hart_universal_rows.h"

#include "hart/data_types.h"

#include <cmath>
#include <map>
#include <string>

namespace vt::dev::access {
namespace {

using E = UniversalEncoding;

// Command, offset, width, encoding, write command — HART-7 manual §5.1 (the tables "Data bytes
// read" / "Data bytes write" of each command); docs/dictionary-notes/sd7.md lists the same.
const std::map<std::string, UniversalField> &fields()
{
    static const std::map<std::string, UniversalField> kFields = {
        // §5.1.11 command 13 / §5.1.16 command 18: tag 0-5, descriptor 6-17, date 18-20.
        {"hart_Tag", {13, 0, 6, E::PackedAscii, 18}},
        {"hart_Descriptor", {13, 6, 12, E::PackedAscii, 18}},
        {"hart_DateDay", {13, 18, 1, E::UInt8, 18}},
        {"hart_DateMonth", {13, 19, 1, E::UInt8, 18}},
        {"hart_DateYear", {13, 20, 1, E::UInt8, 18}},
        // §5.1.10 command 12 / §5.1.15 command 17: message, 24 bytes packed ASCII.
        {"hart_Message", {12, 0, 24, E::PackedAscii, 17}},
        // §5.1.18 command 20 / §5.1.20 command 22: long tag, 32 bytes ISO Latin-1.
        {"hart_LongTag", {20, 0, 32, E::Latin1, 22}},
        // §5.1.14 command 16 / §5.1.17 command 19: final assembly number, 24 bits.
        {"hart_FinalAssemblyNumber", {16, 0, 3, E::UInt24, 19}},
        // §5.1.6 command 7. Written by command 6 (§5.1.5), which also moves the device to another
        // poll address: not a parameter write.
        {"hart_PollingAddress", {7, 0, 1, E::UInt8, std::nullopt}},
        {"hart_LoopCurrentMode", {7, 1, 1, E::UInt8, std::nullopt}},
        // §5.1.1 command 0 (also answered in a long frame).
        {"hart_ExpandedDeviceType", {0, 1, 2, E::UInt16, std::nullopt}},
        {"hart_MinRequestPreambles", {0, 3, 1, E::UInt8, std::nullopt}},
        {"hart_ProtocolRevision", {0, 4, 1, E::UInt8, std::nullopt}},
        {"hart_DeviceRevision", {0, 5, 1, E::UInt8, std::nullopt}},
        {"hart_SoftwareRevision", {0, 6, 1, E::UInt8, std::nullopt}},
        {"hart_HardwareRevision", {0, 7, 1, E::HighFiveBits, std::nullopt}},
        {"hart_Flags", {0, 8, 1, E::UInt8, std::nullopt}},
        {"hart_DeviceId", {0, 9, 3, E::UInt24, std::nullopt}},
        {"hart_MinResponsePreambles", {0, 12, 1, E::UInt8, std::nullopt}},
        {"hart_MaxDeviceVariables", {0, 13, 1, E::UInt8, std::nullopt}},
        {"hart_ConfigChangeCounter", {0, 14, 2, E::UInt16, std::nullopt}},
        {"hart_ExtendedDeviceStatus", {0, 16, 1, E::UInt8, std::nullopt}},
        {"hart_ManufacturerId", {0, 17, 2, E::UInt16, std::nullopt}},
        {"hart_PrivateLabelDistributor", {0, 19, 2, E::UInt16, std::nullopt}},
        {"hart_DeviceProfile", {0, 21, 1, E::UInt8, std::nullopt}},
        // §5.1.4 command 3: loop current, then PV, SV, TV, QV as unit code + IEEE 754.
        {"hart_LoopCurrent", {3, 0, 4, E::Float, std::nullopt}},
        {"hart_PvUnit", {3, 4, 1, E::UInt8, std::nullopt}},
        {"hart_PvValue", {3, 5, 4, E::Float, std::nullopt}},
        {"hart_SvUnit", {3, 9, 1, E::UInt8, std::nullopt}},
        {"hart_SvValue", {3, 10, 4, E::Float, std::nullopt}},
        {"hart_TvUnit", {3, 14, 1, E::UInt8, std::nullopt}},
        {"hart_TvValue", {3, 15, 4, E::Float, std::nullopt}},
        {"hart_QvUnit", {3, 19, 1, E::UInt8, std::nullopt}},
        {"hart_QvValue", {3, 20, 4, E::Float, std::nullopt}},
        // §5.1.3 command 2: loop current, percent of range.
        {"hart_PercentOfRange", {2, 4, 4, E::Float, std::nullopt}},
        // §5.1.12 command 14.
        {"hart_TransducerSerialNumber", {14, 0, 3, E::UInt24, std::nullopt}},
        {"hart_TransducerLimitsUnit", {14, 3, 1, E::UInt8, std::nullopt}},
        {"hart_UpperTransducerLimit", {14, 4, 4, E::Float, std::nullopt}},
        {"hart_LowerTransducerLimit", {14, 8, 4, E::Float, std::nullopt}},
        {"hart_MinimumSpan", {14, 12, 4, E::Float, std::nullopt}},
        // §5.1.13 command 15.
        {"hart_AlarmSelectCode", {15, 0, 1, E::UInt8, std::nullopt}},
        {"hart_TransferFunction", {15, 1, 1, E::UInt8, std::nullopt}},
        {"hart_RangeUnit", {15, 2, 1, E::UInt8, std::nullopt}},
        {"hart_UpperRangeValue", {15, 3, 4, E::Float, std::nullopt}},
        {"hart_LowerRangeValue", {15, 7, 4, E::Float, std::nullopt}},
        {"hart_Damping", {15, 11, 4, E::Float, std::nullopt}},
        {"hart_WriteProtectCode", {15, 15, 1, E::UInt8, std::nullopt}},
        {"hart_PvChannelFlags", {15, 17, 1, E::UInt8, std::nullopt}},
        // §5.1.22 command 48: device specific status bytes 0-5 (the first four here).
        {"hart_DeviceSpecificStatus", {48, 0, 4, E::UInt32, std::nullopt}},
        // §4.4.1 status byte 2, carried by every answer: read with command 48's.
        {"hart_FieldDeviceStatus", {48, 0, 0, E::DeviceStatusByte, std::nullopt}},
    };
    return kFields;
}

std::uint32_t bigEndian(std::span<const std::uint8_t> bytes)
{
    std::uint32_t v = 0;
    for (std::uint8_t b : bytes)
        v = (v << 8) | b;
    return v;
}

} // namespace

std::optional<UniversalField> universalField(const ParamMeta &row)
{
    if (row.block != "hart")
        return std::nullopt;
    const auto it = fields().find(row.name);
    if (it == fields().end())
        return std::nullopt;
    return it->second;
}

std::optional<RawValue> decodeUniversalField(const UniversalField &field,
                                             std::span<const std::uint8_t> data,
                                             std::uint8_t deviceStatus)
{
    if (field.encoding == E::DeviceStatusByte)
        return RawValue{double(deviceStatus)};
    if (data.size() < field.offset + field.width)
        return std::nullopt;
    const auto bytes = data.subspan(field.offset, field.width);
    switch (field.encoding) {
    case E::PackedAscii: return RawValue{hart::unpackAscii(bytes)};
    case E::Latin1: return RawValue{hart::latin1ToUtf8(bytes)};
    case E::Float: return RawValue{double(hart::floatFromBits(bigEndian(bytes)))};
    case E::HighFiveBits: return RawValue{double(bytes[0] >> 3)}; // §5.1.1 byte 7: bits 7..3
    case E::DeviceStatusByte: break;
    case E::UInt8:
    case E::UInt16:
    case E::UInt24:
    case E::UInt32: return RawValue{double(bigEndian(bytes))};
    }
    return std::nullopt;
}

bool encodeUniversalField(const UniversalField &field, const RawValue &value, Bytes &record)
{
    if (record.size() < field.offset + field.width)
        return false;
    Bytes bytes;
    switch (field.encoding) {
    case E::PackedAscii:
        if (!isText(value))
            return false;
        bytes = hart::packAscii(std::get<std::string>(value), field.width);
        break;
    case E::Latin1:
        if (!isText(value))
            return false;
        bytes = hart::utf8ToLatin1(std::get<std::string>(value), field.width);
        break;
    case E::UInt8:
    case E::UInt16:
    case E::UInt24:
    case E::UInt32: {
        const double v = rawNumber(value);
        const double limit = std::ldexp(1.0, int(8 * field.width));
        if (isText(value) || v < 0 || v >= limit || v != std::floor(v))
            return false;
        const auto n = static_cast<std::uint32_t>(v);
        for (std::size_t i = 0; i < field.width; ++i)
            bytes.push_back(static_cast<std::uint8_t>(n >> (8 * (field.width - 1 - i))));
        break;
    }
    case E::Float:
    case E::HighFiveBits:
    case E::DeviceStatusByte: return false; // read-only fields
    }
    std::copy(bytes.begin(), bytes.end(), record.begin() + std::ptrdiff_t(field.offset));
    return true;
}

int textCapacity(const ParamMeta &row)
{
    const auto field = universalField(row);
    if (field && field->encoding == E::PackedAscii)
        return static_cast<int>(field->width * 4 / 3);
    return row.length;
}

std::size_t universalRecordSize(std::uint8_t writeCommand)
{
    switch (writeCommand) {
    case 17: return 24; // §5.1.15
    case 18: return 21; // §5.1.16
    case 19: return 3;  // §5.1.17
    case 22: return 32; // §5.1.20
    default: return 0;
    }
}

} // namespace vt::dev::access
