// DSP-408 PKW parameter channel (ED1/SD1 PROFIBUS-DP manual §4.6): the 8-byte PKE/IND/Res/PWE
// block that reads or writes exactly one parameter per telegram, with its request/response ids.
//
// Byte order: the manual says words travel "in the little endian format" (§1.4, repeated in §4.5),
// yet its worked examples (§4.6.1) put 450 = 01h C2h into bytes 6..7 high byte first and PNU 49h
// into the low byte of PKE. The examples win (ARCHITECTURE.md "Byte order"): big-endian.
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/field_span.h"
#include "core/local_text.h"
#include "core/result.h"
#include "dsp408/options.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vt::dev::dsp408 {

inline constexpr std::size_t kPkwSize = 8;
inline constexpr std::uint16_t kMaxPnu = 0x07FF; // PKE bits 10..0

// ED1/SD1 manual §4.6, table "instruction / response signatures" (AK, PKE bits 15..12).
enum class RequestId : std::uint8_t {
    None = 0,
    Read = 1,
    WriteWord = 2,
    WriteDoubleWord = 3,
    WriteByte = 10, // 4..9 reserved
};
enum class ResponseId : std::uint8_t {
    None = 0,
    Word = 1,
    DoubleWord = 2,
    Error = 7, // error code in PWE bytes 6..7
    Byte = 11,
};

// ED1/SD1 manual §4.6, error codes of a response with AK 7.
enum class PkwError : std::uint16_t {
    UndefinedPnu = 0,
    NotChangeable = 1,
    ValueRange = 2,
    DataType = 5,
    Other = 18,
};

// ED1/SD1 manual §4.6, table "data type / parameter length".
enum class ParamLength : std::uint8_t { Byte = 1, Word = 2, DoubleWord = 4 };
enum class DataType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float };
ParamLength paramLength(DataType type);

// The PKW block as it sits on the wire; decode → encode reproduces every bit.
struct Pkw
{
    std::uint8_t ak = 0;   // PKE bits 15..12: RequestId (master → slave) or ResponseId
    bool pkeSpare = false; // PKE bit 11 ("Res")
    std::uint16_t pnu = 0; // PKE bits 10..0: parameter number
    std::uint8_t ind = 0;  // block number
    std::uint8_t res = 0;  // reserved byte beside IND
    std::uint32_t pwe = 0; // bytes 4..7 big-endian: byte value = byte 7, word = bytes 6..7

    bool operator==(const Pkw &) const = default;
};

// Builders for the master (requests) and the simulator (responses), §4.6 value placement.
Pkw readRequest(std::uint8_t ind, std::uint16_t pnu);
Pkw writeRequest(std::uint8_t ind, std::uint16_t pnu, ParamLength length, std::uint32_t value);
Pkw valueResponse(std::uint8_t ind, std::uint16_t pnu, ParamLength length, std::uint32_t value);
Pkw errorResponse(std::uint8_t ind, std::uint16_t pnu, std::uint16_t errorCode);

bool isKnownRequestId(std::uint8_t ak);
bool isKnownResponseId(std::uint8_t ak);
std::optional<ParamLength> requestLength(std::uint8_t ak);  // write ids only
std::optional<ParamLength> responseLength(std::uint8_t ak); // 1, 2, 11
std::uint8_t writeRequestId(ParamLength length);
std::uint8_t valueResponseId(ParamLength length);
// The value in the PWE bytes that `length` occupies (byte 7, bytes 6..7 or bytes 4..7).
std::uint32_t pweValue(std::uint32_t pwe, ParamLength length);
// Error code of a response with AK 7, nullopt for any other response.
std::optional<std::uint16_t> errorCode(const Pkw &response);
// True when `response` may answer `request` (§4.6 table: same IND and PNU, allowed response id).
bool answers(const Pkw &response, const Pkw &request);

// Encoding checks the fields fit (AK ≤ 15, PNU ≤ 0x7FF): BadValue otherwise.
Result<Bytes, DecodeError> encodePkw(const Pkw &pkw, const Options &options = {});
// Exactly 8 bytes; an AK the direction does not define is UnexpectedCommand.
Result<Pkw, DecodeError> decodePkw(std::span<const std::uint8_t> bytes,
                                   const Options &options = {});

// Rows for a PKW block that starts at `offset` of a larger telegram.
void describePkwFields(const Pkw &pkw, std::size_t offset, const Options &options,
                       std::vector<FieldSpan> &out);
LocalText pkwSummary(const Pkw &pkw, Direction direction);
Description describePkw(std::span<const std::uint8_t> bytes, const Options &options = {});

// Texts (texts.cpp): AK meaning per direction and the §4.6 error codes.
LocalText requestIdText(std::uint8_t ak);
LocalText responseIdText(std::uint8_t ak);
LocalText pkwErrorText(std::uint16_t code);

} // namespace vt::dev::dsp408
