// Typed decode errors shared by every codec (STYLE.md rule 5). Device exceptions keep their own
// codes in `deviceCode`; the codec that knows the family turns them into text.
#pragma once

#include "local_text.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace vt::dev {

enum class DecodeErrc {
    Truncated,         // frame ends before a field it announces
    TooLong,           // bytes after the end of a complete frame
    BadChecksum,       // CRC / LRC / XOR mismatch
    BadLength,         // a length or count field contradicts the frame
    BadValue,          // a field holds a value the protocol does not allow
    UnexpectedCommand, // a command / function code this codec does not know
    DeviceException,   // a well-formed exception response; see deviceCode
};

struct DecodeError
{
    DecodeErrc code = DecodeErrc::Truncated;
    std::size_t offset = 0;      // byte offset where decoding stopped
    std::uint8_t deviceCode = 0; // exception / response code for DeviceException
    std::string detail;          // short English detail for logs ("CNT 18 > 16")

    bool operator==(const DecodeError &) const = default;
};

LocalText errcText(DecodeErrc code);
// One line for people: "truncated at byte 5: CNT announces 4 data bytes".
LocalText describeError(const DecodeError &error);

} // namespace vt::dev
