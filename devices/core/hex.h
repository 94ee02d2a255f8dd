// Hex text <-> bytes for the CLI, the inspector's paste box and test vectors. Accepts the
// notations PLC programmers paste: "23 00 03", "0x23,0x00", "230003", "23-00-03".
#pragma once

#include "byte_writer.h"
#include "result.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace vt::dev {

struct HexError
{
    std::size_t position = 0; // character index of the problem
    std::string reason;
};

Result<Bytes, HexError> parseHex(std::string_view text);
std::string toHex(std::span<const std::uint8_t> bytes, char separator = ' ');
std::string hexByte(std::uint8_t b);  // "0x23"
std::string hexWord(std::uint16_t w); // "0x03E8"
int hexDigitValue(char c);            // '0'..'9', 'a'..'f', 'A'..'F' → 0..15; -1 otherwise

} // namespace vt::dev
