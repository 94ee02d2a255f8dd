// HART data encodings used by the universal commands (HART-7 manual §2.3 "Data", §5.1): packed
// ASCII, ISO Latin-1 strings, dates and IEEE 754 floats, all big-endian.
#pragma once

#include "core/byte_writer.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace vt::dev::hart {

// Packed ASCII: four 6-bit characters (0x20..0x5F) in three bytes. Unpacking keeps every
// character except trailing spaces (the padding).
std::string unpackAscii(std::span<const std::uint8_t> bytes);
// Packs into exactly `size` bytes (a multiple of 3 gives whole characters): lowercase letters are
// upper-cased, characters outside 0x20..0x5F become '?', the rest is padded with spaces.
Bytes packAscii(std::string_view text, std::size_t size);

// ISO Latin-1 fields (long tag, HART 7) travel as UTF-8 in our structs. Decoding drops trailing
// NUL padding; encoding pads with NUL to `size` and writes '?' for characters outside Latin-1.
std::string latin1ToUtf8(std::span<const std::uint8_t> bytes);
Bytes utf8ToLatin1(std::string_view text, std::size_t size);

// HART date: day, month, year − 1900 (HART-7 manual §5.1.11: "Date (day, month, year)").
struct Date
{
    std::uint8_t day = 1;
    std::uint8_t month = 1;
    std::uint8_t yearSince1900 = 0;

    int year() const { return 1900 + yearSince1900; }
    bool operator==(const Date &) const = default;
};
std::string formatDate(const Date &date); // "2024-03-17"

// IEEE 754 single precision, transmitted big-endian (HART-7 manual §2.3).
float floatFromBits(std::uint32_t bits);
std::uint32_t bitsFromFloat(float value);
std::string formatFloat(float value); // shortest round-trip text, "nan"/"inf" included

} // namespace vt::dev::hart
