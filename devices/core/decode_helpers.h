// Small helpers every codec uses to turn ByteReader state into typed DecodeErrors, so that
// "truncated at the first missing byte" and "extra bytes after the frame" read the same everywhere.
#pragma once

#include "byte_reader.h"
#include "decode_error.h"

#include <cstddef>
#include <string>

namespace vt::dev {

inline DecodeError decodeError(DecodeErrc code, std::size_t offset, std::string detail = {})
{
    return DecodeError{code, offset, 0, std::move(detail)};
}

// The reader failed: the frame ends before a field; offset = first missing byte.
inline DecodeError truncated(const ByteReader &reader, std::string detail = {})
{
    return DecodeError{DecodeErrc::Truncated, reader.failOffset(), 0, std::move(detail)};
}

// Bytes left after a complete frame: TooLong at the first extra byte.
inline DecodeError tooLong(const ByteReader &reader, std::string detail = {})
{
    return DecodeError{DecodeErrc::TooLong, reader.offset(), 0, std::move(detail)};
}

} // namespace vt::dev
