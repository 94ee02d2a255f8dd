// Layout settings shared by the DSP-408 PKW/PZD codecs. Defaults follow the worked examples of the
// ED1/SD1 PROFIBUS-DP manual (§4.6.1); ARCHITECTURE.md "Byte order" makes the rest configurable.
#pragma once

#include "core/direction.h"

#include <cstdint>
#include <optional>

namespace vt::dev::dsp408 {

// Who sent the bytes (core/direction.h): the AK ids and the PZD words mean different things in
// each direction (request = master → slave, response = slave → master).
using vt::dev::Direction;

// ED1/SD1 manual §4.6 PKW table: word 1 = IND | Res. Example 1 of §4.6.1 sends IND 03h in byte 2
// and Res 00h in byte 3, so byte 2 is the default; Byte3 serves masters that swap the pair.
enum class IndPosition : std::uint8_t { Byte2, Byte3 };

// ED1/SD1 manual §4.5.1: dpc_SetpointVal / dpc_ActualVal fill PZD words 1 and 2. §1.4 claims
// "little endian" (low word first) while every worked example is big-endian (high first); the
// examples win (ARCHITECTURE.md "Byte order"), LowWordFirst stays available as a setting.
enum class WordOrder : std::uint8_t { HighWordFirst, LowWordFirst };

// ED1/SD1 manual §4.5.1 "Telegram types".
enum class TelegramType : std::uint8_t {
    PkwAndPzd = 1, // 4 PKW words + 3 PZD words (14 bytes)
    PzdOnly = 2,   // 3 PZD words (6 bytes)
};

struct Options
{
    Direction direction = Direction::Request;
    IndPosition indPosition = IndPosition::Byte2;
    WordOrder pzdWordOrder = WordOrder::HighWordFirst;
    // Telegram type for whole telegrams; unset = by length (14 bytes → 1, 6 bytes → 2).
    std::optional<TelegramType> telegramType;
};

} // namespace vt::dev::dsp408
