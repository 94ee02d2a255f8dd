// Streaming de-framers: bytes as the transport delivers them (a frame over many reads, several
// frames in one read, line noise) become whole Modbus RTU / TCP ADUs.
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "core/direction.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vt::dev::modbus {

// RTU has no length field and no start byte; a frame is recognised by its header (function code,
// byte count) and its CRC. Bytes that cannot start a valid frame are dropped one at a time until
// a CRC-valid frame lines up (resynchronisation by CRC). The direction says which layout to
// expect: a client reads Responses, a server (simulator) reads Requests. Function codes 3 and 6
// (and exceptions 0x83 / 0x86 in responses) are framed; anything else counts as garbage.
// Owned by one link worker; not thread-safe.
class RtuDeframer
{
public:
    explicit RtuDeframer(Direction direction) : m_direction(direction) {}

    // Appends `bytes`; returns every complete CRC-valid frame now available, oldest first.
    std::vector<Bytes> feed(std::span<const std::uint8_t> bytes);

    // The line was silent for ≥ 3.5 characters (Modbus over Serial Line §2.5.1.1): whatever is
    // buffered can no longer become a frame. Drops it (counted in discarded()).
    void silence();

    std::size_t buffered() const { return m_buffer.size(); }
    // The bytes buffered: the start of a frame whose rest has not arrived (after feed()).
    std::span<const std::uint8_t> pending() const { return m_buffer; }
    std::size_t discarded() const { return m_discarded; } // garbage bytes dropped so far

private:
    std::optional<std::size_t> laterFrame() const;
    void drop(std::size_t n, bool garbage);

    Direction m_direction;
    Bytes m_buffer;
    std::size_t m_checked = 0; // later-frame candidates ending at or before this were rejected
    std::size_t m_discarded = 0;
};

// Modbus TCP frames by the MBAP length field. A header that cannot be right (protocol id ≠ 0,
// length outside 2..254, i.e. an ADU over 260 bytes) means the stream is out of step: the
// de-framer latches the error and delivers nothing more until reset() (after a reconnect).
// Owned by one link worker; not thread-safe.
class TcpDeframer
{
public:
    std::vector<Bytes> feed(std::span<const std::uint8_t> bytes);

    const std::optional<DecodeError> &error() const { return m_error; }
    std::size_t buffered() const { return m_buffer.size(); }
    void reset();

private:
    Bytes m_buffer;
    std::optional<DecodeError> m_error;
};

} // namespace vt::dev::modbus
