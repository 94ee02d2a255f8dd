#include "dsp408/pkw.h"

#include "core/byte_reader.h"
#include "core/hex.h"

#include <string>

namespace vt::dev::dsp408 {
namespace {

constexpr std::uint8_t kMaxAk = 0x0F;

std::uint16_t pke(const Pkw &pkw)
{
    return static_cast<std::uint16_t>((pkw.ak & kMaxAk) << 12 | (pkw.pkeSpare ? 0x0800 : 0) |
                                      (pkw.pnu & kMaxPnu));
}

std::size_t indOffset(const Options &options)
{
    return options.indPosition == IndPosition::Byte2 ? 2 : 3;
}

std::size_t resOffset(const Options &options)
{
    return options.indPosition == IndPosition::Byte2 ? 3 : 2;
}

// Offset and length of the value inside the 8 PKW bytes (§4.6: byte 7, bytes 6..7, bytes 4..7).
std::pair<std::size_t, std::size_t> valueSpan(ParamLength length)
{
    switch (length) {
    case ParamLength::Byte: return {7, 1};
    case ParamLength::Word: return {6, 2};
    case ParamLength::DoubleWord: return {4, 4};
    }
    return {4, 4};
}

std::string lengthWord(ParamLength length, bool german)
{
    switch (length) {
    case ParamLength::Byte: return "Byte";
    case ParamLength::Word: return german ? "Wort" : "word";
    case ParamLength::DoubleWord: return german ? "Doppelwort" : "double word";
    }
    return {};
}

} // namespace

ParamLength paramLength(DataType type)
{
    switch (type) {
    case DataType::Int8:
    case DataType::UInt8: return ParamLength::Byte;
    case DataType::Int16:
    case DataType::UInt16: return ParamLength::Word;
    case DataType::Int32:
    case DataType::UInt32:
    case DataType::Float: return ParamLength::DoubleWord;
    }
    return ParamLength::DoubleWord;
}

bool isKnownRequestId(std::uint8_t ak)
{
    return ak <= 3 || ak == 10;
}

bool isKnownResponseId(std::uint8_t ak)
{
    return ak <= 2 || ak == 7 || ak == 11;
}

std::optional<ParamLength> requestLength(std::uint8_t ak)
{
    switch (ak) {
    case 2: return ParamLength::Word;
    case 3: return ParamLength::DoubleWord;
    case 10: return ParamLength::Byte;
    default: return std::nullopt;
    }
}

std::optional<ParamLength> responseLength(std::uint8_t ak)
{
    switch (ak) {
    case 1: return ParamLength::Word;
    case 2: return ParamLength::DoubleWord;
    case 11: return ParamLength::Byte;
    default: return std::nullopt;
    }
}

std::uint8_t writeRequestId(ParamLength length)
{
    switch (length) {
    case ParamLength::Byte: return static_cast<std::uint8_t>(RequestId::WriteByte);
    case ParamLength::Word: return static_cast<std::uint8_t>(RequestId::WriteWord);
    case ParamLength::DoubleWord: return static_cast<std::uint8_t>(RequestId::WriteDoubleWord);
    }
    return 0;
}

std::uint8_t valueResponseId(ParamLength length)
{
    switch (length) {
    case ParamLength::Byte: return static_cast<std::uint8_t>(ResponseId::Byte);
    case ParamLength::Word: return static_cast<std::uint8_t>(ResponseId::Word);
    case ParamLength::DoubleWord: return static_cast<std::uint8_t>(ResponseId::DoubleWord);
    }
    return 0;
}

std::uint32_t pweValue(std::uint32_t pwe, ParamLength length)
{
    switch (length) {
    case ParamLength::Byte: return pwe & 0xFFu;
    case ParamLength::Word: return pwe & 0xFFFFu;
    case ParamLength::DoubleWord: return pwe;
    }
    return pwe;
}

Pkw readRequest(std::uint8_t ind, std::uint16_t pnu)
{
    return Pkw{static_cast<std::uint8_t>(RequestId::Read), false, pnu, ind, 0, 0};
}

Pkw writeRequest(std::uint8_t ind, std::uint16_t pnu, ParamLength length, std::uint32_t value)
{
    return Pkw{writeRequestId(length), false, pnu, ind, 0, pweValue(value, length)};
}

Pkw valueResponse(std::uint8_t ind, std::uint16_t pnu, ParamLength length, std::uint32_t value)
{
    return Pkw{valueResponseId(length), false, pnu, ind, 0, pweValue(value, length)};
}

Pkw errorResponse(std::uint8_t ind, std::uint16_t pnu, std::uint16_t code)
{
    return Pkw{static_cast<std::uint8_t>(ResponseId::Error), false, pnu, ind, 0, code};
}

std::optional<std::uint16_t> errorCode(const Pkw &response)
{
    if (response.ak != static_cast<std::uint8_t>(ResponseId::Error))
        return std::nullopt;
    return static_cast<std::uint16_t>(response.pwe & 0xFFFFu);
}

bool answers(const Pkw &response, const Pkw &request)
{
    if (response.ind != request.ind || response.pnu != request.pnu)
        return false;
    const std::uint8_t r = response.ak;
    switch (request.ak) {
    case 0: return r == 0;
    case 1: return r == 1 || r == 2 || r == 11 || r == 7;
    case 2: return r == 1 || r == 7;
    case 3: return r == 2 || r == 7;
    case 10: return r == 11 || r == 7;
    default: return r == 7;
    }
}

Result<Bytes, DecodeError> encodePkw(const Pkw &pkw, const Options &options)
{
    if (pkw.ak > kMaxAk)
        return DecodeError{DecodeErrc::BadValue, 0, 0, "AK " + std::to_string(pkw.ak) + " > 15"};
    if (pkw.pnu > kMaxPnu)
        return DecodeError{DecodeErrc::BadValue, 0, 0,
                           "PNU " + std::to_string(pkw.pnu) + " > 2047"};
    ByteWriter w;
    w.u16be(pke(pkw));
    if (options.indPosition == IndPosition::Byte2)
        w.u8(pkw.ind).u8(pkw.res);
    else
        w.u8(pkw.res).u8(pkw.ind);
    w.u32be(pkw.pwe);
    return w.take();
}

namespace {

// The byte layout only; the AK is checked by decodePkw.
Result<Pkw, DecodeError> decodeLayout(std::span<const std::uint8_t> bytes, const Options &options)
{
    ByteReader r(bytes);
    const std::uint16_t word0 = r.u16be();
    const std::uint8_t byte2 = r.u8();
    const std::uint8_t byte3 = r.u8();
    const std::uint32_t pwe = r.u32be();
    if (r.failed())
        return DecodeError{DecodeErrc::Truncated, r.failOffset(), 0,
                           "PKW needs 8 bytes, got " + std::to_string(bytes.size())};
    if (!r.atEnd())
        return DecodeError{DecodeErrc::TooLong, kPkwSize, 0,
                           std::to_string(bytes.size() - kPkwSize) + " bytes after the PKW"};
    Pkw pkw;
    pkw.ak = static_cast<std::uint8_t>(word0 >> 12);
    pkw.pkeSpare = (word0 & 0x0800) != 0;
    pkw.pnu = static_cast<std::uint16_t>(word0 & kMaxPnu);
    pkw.ind = options.indPosition == IndPosition::Byte2 ? byte2 : byte3;
    pkw.res = options.indPosition == IndPosition::Byte2 ? byte3 : byte2;
    pkw.pwe = pwe;
    return pkw;
}

std::optional<DecodeError> checkAk(const Pkw &pkw, Direction direction)
{
    const bool known =
        direction == Direction::Request ? isKnownRequestId(pkw.ak) : isKnownResponseId(pkw.ak);
    if (known)
        return std::nullopt;
    return DecodeError{DecodeErrc::UnexpectedCommand, 0, pkw.ak,
                       "AK " + std::to_string(pkw.ak) + " is not defined for this direction"};
}

} // namespace

Result<Pkw, DecodeError> decodePkw(std::span<const std::uint8_t> bytes, const Options &options)
{
    auto pkw = decodeLayout(bytes, options);
    if (!pkw.ok())
        return pkw;
    if (auto error = checkAk(*pkw, options.direction))
        return *error;
    return pkw;
}

void describePkwFields(const Pkw &pkw, std::size_t offset, const Options &options,
                       std::vector<FieldSpan> &out)
{
    const bool request = options.direction == Direction::Request;
    out.push_back({"pkw.pke",
                   offset,
                   2,
                   0,
                   hexWord(pke(pkw)),
                   {"parameter signature (PKE)", "Parameterkennung (PKE)"}});
    out.push_back({"pkw.ak", offset, 1, 1, std::to_string(pkw.ak),
                   request ? requestIdText(pkw.ak) : responseIdText(pkw.ak)});
    if (pkw.pkeSpare)
        out.push_back({"pkw.pke_res",
                       offset,
                       1,
                       1,
                       "1",
                       {"reserved PKE bit 11 is set", "reserviertes PKE-Bit 11 ist gesetzt"}});
    out.push_back({"pkw.pnu",
                   offset,
                   2,
                   1,
                   std::to_string(pkw.pnu),
                   {"parameter number (PNU)", "Parameternummer (PNU)"}});
    out.push_back({"pkw.ind",
                   offset + indOffset(options),
                   1,
                   0,
                   std::to_string(pkw.ind),
                   {"block number (IND)", "Blocknummer (IND)"}});
    out.push_back({"pkw.res",
                   offset + resOffset(options),
                   1,
                   0,
                   hexByte(pkw.res),
                   {"reserved", "reserviert"}});
    out.push_back({"pkw.pwe",
                   offset + 4,
                   4,
                   0,
                   hexWord(static_cast<std::uint16_t>(pkw.pwe >> 16)) +
                       hexWord(static_cast<std::uint16_t>(pkw.pwe)).substr(2),
                   {"parameter value (PWE)", "Parameterwert (PWE)"}});
    if (auto code = request ? std::nullopt : errorCode(pkw)) {
        out.push_back({"pkw.error", offset + 6, 2, 1, std::to_string(*code), pkwErrorText(*code)});
        return;
    }
    const auto length = request ? requestLength(pkw.ak) : responseLength(pkw.ak);
    if (!length)
        return;
    const auto [at, len] = valueSpan(*length);
    out.push_back({"pkw.value",
                   offset + at,
                   len,
                   1,
                   std::to_string(pweValue(pkw.pwe, *length)),
                   {"value (" + lengthWord(*length, false) + ")",
                    "Wert (" + lengthWord(*length, true) + ")"}});
}

LocalText pkwSummary(const Pkw &pkw, Direction direction)
{
    const bool request = direction == Direction::Request;
    LocalText what = request ? requestIdText(pkw.ak) : responseIdText(pkw.ak);
    const std::string where = " IND " + std::to_string(pkw.ind) + " PNU " + std::to_string(pkw.pnu);
    what.en += where;
    what.de += where;
    if (auto code = request ? std::nullopt : errorCode(pkw)) {
        const LocalText e = pkwErrorText(*code);
        what.en += ": " + e.en;
        what.de += ": " + e.de;
        return what;
    }
    if (auto length = request ? requestLength(pkw.ak) : responseLength(pkw.ak)) {
        const std::string v = " = " + std::to_string(pweValue(pkw.pwe, *length));
        what.en += v;
        what.de += v;
    }
    return what;
}

Description describePkw(std::span<const std::uint8_t> bytes, const Options &options)
{
    Description d;
    d.protocol = "dsp408-pkw";
    auto pkw = decodeLayout(bytes, options);
    if (!pkw.ok()) {
        d.error = pkw.error();
        d.summary = describeError(pkw.error());
        return d;
    }
    describePkwFields(*pkw, 0, options, d.fields);
    d.error = checkAk(*pkw, options.direction);
    d.summary = d.error ? describeError(*d.error) : pkwSummary(*pkw, options.direction);
    return d;
}

} // namespace vt::dev::dsp408
