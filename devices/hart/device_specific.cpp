#include "hart/device_specific.h"

#include "core/byte_reader.h"
#include "core/hex.h"
#include "hart/data_types.h"

#include <string>

namespace vt::dev::hart {
namespace {

constexpr std::size_t kRefSize = 3;

bool carriesValue(std::uint8_t command, bool response)
{
    return response || isWriteCommand(command);
}

std::uint32_t maskTo(std::uint32_t raw, std::size_t width)
{
    return width >= 4 ? raw : raw & ((1u << (8 * width)) - 1u);
}

std::string hexValue(std::uint32_t raw, std::size_t width)
{
    if (width == 1)
        return hexByte(static_cast<std::uint8_t>(raw));
    if (width == 2)
        return hexWord(static_cast<std::uint16_t>(raw));
    return hexWord(static_cast<std::uint16_t>(raw >> 16)) +
           hexWord(static_cast<std::uint16_t>(raw)).substr(2);
}

} // namespace

bool isParameterCommand(std::uint8_t command)
{
    return command >= kReadByte && command <= kWriteDoubleWord;
}

bool isWriteCommand(std::uint8_t command)
{
    return isParameterCommand(command) && (command & 1u) != 0;
}

std::size_t valueWidth(std::uint8_t command)
{
    switch (command) {
    case kReadByte:
    case kWriteByte: return 1;
    case kReadWord:
    case kWriteWord: return 2;
    case kReadDoubleWord:
    case kWriteDoubleWord: return 4;
    default: return 0;
    }
}

std::size_t valueWidth(ValueType type)
{
    switch (type) {
    case ValueType::Int8:
    case ValueType::UInt8: return 1;
    case ValueType::Int16:
    case ValueType::UInt16: return 2;
    case ValueType::Int32:
    case ValueType::UInt32:
    case ValueType::Float: return 4;
    }
    return 4;
}

std::uint8_t readCommand(ValueType type)
{
    switch (valueWidth(type)) {
    case 1: return kReadByte;
    case 2: return kReadWord;
    default: return kReadDoubleWord;
    }
}

std::uint8_t writeCommand(ValueType type)
{
    return static_cast<std::uint8_t>(readCommand(type) + 1);
}

ParamAccess readParam(ValueType type, ParamRef ref)
{
    return ParamAccess{readCommand(type), ref, std::nullopt};
}

ParamAccess writeParam(ValueType type, ParamRef ref, std::uint32_t raw)
{
    return ParamAccess{writeCommand(type), ref, maskTo(raw, valueWidth(type))};
}

std::int32_t asSigned(std::uint32_t raw, std::size_t width)
{
    switch (width) {
    case 1: return static_cast<std::int8_t>(static_cast<std::uint8_t>(raw));
    case 2: return static_cast<std::int16_t>(static_cast<std::uint16_t>(raw));
    default: return static_cast<std::int32_t>(raw);
    }
}

float asFloat(std::uint32_t raw)
{
    return floatFromBits(raw);
}

std::uint32_t rawFromSigned(std::int32_t value, std::size_t width)
{
    return maskTo(static_cast<std::uint32_t>(value), width);
}

Result<ParamAccess, DecodeError> decodeParamAccess(std::uint8_t command, bool response,
                                                   std::span<const std::uint8_t> data)
{
    const std::size_t width = valueWidth(command);
    if (width == 0)
        return DecodeError{DecodeErrc::UnexpectedCommand, 0, command,
                           "command " + std::to_string(command) + " is not 128..133"};
    const std::size_t expected = kRefSize + (carriesValue(command, response) ? width : 0);
    if (data.size() < expected)
        return DecodeError{DecodeErrc::BadLength, data.size(), 0,
                           "command " + std::to_string(command) + " needs " +
                               std::to_string(expected) + " data bytes, got " +
                               std::to_string(data.size())};
    if (data.size() > expected)
        return DecodeError{DecodeErrc::TooLong, expected, 0,
                           std::to_string(data.size() - expected) + " bytes after the value"};
    ByteReader r(data);
    ParamAccess a;
    a.command = command;
    a.ref.ind = r.u8();
    a.ref.pnu = r.u8();
    a.ref.instance = r.u8();
    if (carriesValue(command, response)) {
        std::uint32_t v = 0;
        for (std::uint8_t b : r.bytes(width))
            v = v << 8 | b;
        a.raw = v;
    }
    return a;
}

Result<Bytes, DecodeError> encodeParamAccess(const ParamAccess &access, bool response)
{
    const std::size_t width = valueWidth(access.command);
    if (width == 0)
        return DecodeError{DecodeErrc::BadValue, 0, access.command, "command is not 128..133"};
    const bool value = carriesValue(access.command, response);
    if (value && !access.raw)
        return DecodeError{DecodeErrc::BadValue, 0, access.command, "value missing"};
    ByteWriter w;
    w.u8(access.ref.ind).u8(access.ref.pnu).u8(access.ref.instance);
    if (value) {
        const std::uint32_t v = maskTo(*access.raw, width);
        for (std::size_t i = width; i-- > 0;)
            w.u8(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    return w.take();
}

std::optional<DecodeError> describeParamAccess(std::uint8_t command, bool response,
                                               std::span<const std::uint8_t> data,
                                               std::size_t offset, int depth,
                                               std::vector<FieldSpan> &out)
{
    auto decoded = decodeParamAccess(command, response, data);
    ByteReader r(data);
    const LocalText texts[3] = {{"block number (IND)", "Blocknummer (IND)"},
                                {"parameter number (PNU)", "Parameternummer (PNU)"},
                                {"instance number (channel − 1)", "Instanznummer (Kanal − 1)"}};
    const char *keys[3] = {"hart.param.ind", "hart.param.pnu", "hart.param.instance"};
    for (int i = 0; i < 3; ++i) {
        const std::size_t at = r.offset();
        const std::uint8_t v = r.u8();
        if (r.failed())
            break;
        out.push_back({keys[i], offset + at, 1, depth, std::to_string(v), texts[i]});
    }
    const std::size_t width = valueWidth(command);
    if (decoded.ok() && decoded->raw) {
        const std::uint32_t raw = *decoded->raw;
        std::string value = std::to_string(raw) + " (" + hexValue(raw, width) + ")";
        if (asSigned(raw, width) < 0)
            value += ", signed " + std::to_string(asSigned(raw, width));
        if (width == 4)
            value += ", float " + formatFloat(asFloat(raw));
        out.push_back({"hart.param.value",
                       offset + kRefSize,
                       width,
                       depth,
                       value,
                       {"value (" + std::to_string(width) + " bytes, type from the parameter list)",
                        "Wert (" + std::to_string(width) + " Byte, Typ laut Parameterliste)"}});
    }
    if (!decoded.ok()) {
        DecodeError e = decoded.error();
        e.offset += offset;
        return e;
    }
    return std::nullopt;
}

} // namespace vt::dev::hart
