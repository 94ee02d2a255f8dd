// DSP-408 process data (PZD) and whole cyclic telegrams of types 1 (PKW + PZD) and 2 (PZD only),
// ED1/SD1 PROFIBUS-DP manual §4.5, with the control and status word bits of §4.8.2/§4.8.3.
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/field_span.h"
#include "core/local_text.h"
#include "core/result.h"
#include "dsp408/options.h"
#include "dsp408/pkw.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace vt::dev::dsp408 {

inline constexpr std::size_t kPzdSize = 6;
inline constexpr std::size_t kTelegram1Size = kPkwSize + kPzdSize;

// ED1/SD1 manual §4.8.2 db_ControlWord (IND 0, PNU 37, PZD signal 001).
namespace control {
inline constexpr std::uint16_t kDisable = 1u << 0;          // D
inline constexpr std::uint16_t kHoldEnable = 1u << 1;       // H
inline constexpr std::uint16_t kDeviceModeActive = 1u << 2; // M
inline constexpr std::uint16_t kResetFault = 1u << 3;       // R
inline constexpr std::uint16_t kStop = 1u << 14;
} // namespace control

// ED1/SD1 manual §4.8.3 db_StatusWord (IND 0, PNU 38, PZD signal 002).
namespace status {
inline constexpr std::uint16_t kDisable = 1u << 0;          // D
inline constexpr std::uint16_t kHoldEnable = 1u << 1;       // H
inline constexpr std::uint16_t kDeviceModeActive = 1u << 2; // M
inline constexpr std::uint16_t kReady = 1u << 3;            // R
inline constexpr std::uint16_t kLocal = 1u << 4;
inline constexpr std::uint16_t kWarning = 1u << 5;
inline constexpr std::uint16_t kInTargetWindow = 1u << 12;
} // namespace status

// §4.5.2 receive data (master → slave): db_ControlWord + dpc_SetpointVal (int32, 2 words).
struct PzdSetpoint
{
    std::uint16_t controlWord = 0;
    std::int32_t setpoint = 0;
    bool operator==(const PzdSetpoint &) const = default;
};

// §4.5.3 transmit data (slave → master): db_StatusWord + dpc_ActualVal (int32, 2 words).
struct PzdActual
{
    std::uint16_t statusWord = 0;
    std::int32_t actualValue = 0;
    bool operator==(const PzdActual &) const = default;
};

// A whole cyclic telegram; `pkw` is present in telegram type 1 only.
struct RequestTelegram
{
    std::optional<Pkw> pkw;
    PzdSetpoint pzd;
    bool operator==(const RequestTelegram &) const = default;
};

struct ResponseTelegram
{
    std::optional<Pkw> pkw;
    PzdActual pzd;
    bool operator==(const ResponseTelegram &) const = default;
};

Bytes encodePzd(const PzdSetpoint &pzd, const Options &options = {});
Bytes encodePzd(const PzdActual &pzd, const Options &options = {});
Result<PzdSetpoint, DecodeError> decodePzdSetpoint(std::span<const std::uint8_t> bytes,
                                                   const Options &options = {});
Result<PzdActual, DecodeError> decodePzdActual(std::span<const std::uint8_t> bytes,
                                               const Options &options = {});

// Telegram type = 1 when `pkw` is set, else 2.
Result<Bytes, DecodeError> encodeTelegram(const RequestTelegram &telegram,
                                          const Options &options = {});
Result<Bytes, DecodeError> encodeTelegram(const ResponseTelegram &telegram,
                                          const Options &options = {});
// Telegram type from options.telegramType, else by length (14 → 1, 6 → 2).
Result<RequestTelegram, DecodeError> decodeRequestTelegram(std::span<const std::uint8_t> bytes,
                                                           const Options &options = {});
Result<ResponseTelegram, DecodeError> decodeResponseTelegram(std::span<const std::uint8_t> bytes,
                                                             const Options &options = {});

// Describes a type 1 or type 2 telegram (or the 6 PZD bytes alone) in options.direction.
Description describeTelegram(std::span<const std::uint8_t> bytes, const Options &options = {});

// Texts (texts.cpp); bits without a meaning in the manual read "reserved".
LocalText controlBitText(int bit);
LocalText statusBitText(int bit);

} // namespace vt::dev::dsp408
