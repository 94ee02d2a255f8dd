// Streaming HART de-framer: bytes go in as the modem delivers them (split frames, several frames
// per read, noise between them) and whole frames or error events come out. HART-7 manual §2.3:
// preambles (0xFF) synchronise, the delimiter and byte count give the length, the XOR checksum
// closes the frame. Memory is bounded by one maximum frame (kMaxFrameSize).
#pragma once

#include "core/byte_writer.h"
#include "core/decode_error.h"
#include "hart/frame.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vt::dev::hart {

struct DeframerEvent
{
    enum class Kind { Frame, Error };
    Kind kind = Kind::Frame;
    Frame frame;       // Kind::Frame
    DecodeError error; // Kind::Error: BadChecksum, BadValue (delimiter), BadLength, Truncated
    Bytes raw;         // the bytes concerned: preambles (up to 255) + delimiter … checksum
};

// Owned by one reader (a link's worker thread); not thread-safe.
class Deframer
{
public:
    struct Options
    {
        // Preambles needed before a delimiter is trusted. HART receivers sync on 2; the manual's
        // "three or more" is what senders send.
        std::size_t minPreambles = 2;
    };

    Deframer() = default;
    explicit Deframer(Options options) : m_options(options) {}

    // Feeds bytes as they arrive; returns the events they complete, in order. After a bad
    // checksum the bytes after the false delimiter are scanned again, so a real frame hidden in
    // a broken one is still found.
    std::vector<DeframerEvent> feed(std::span<const std::uint8_t> bytes);
    // End of a burst of bytes (inter-character gap): a frame still incomplete becomes a
    // Truncated error and its bytes are scanned again.
    std::vector<DeframerEvent> flush();
    void reset();

    bool midFrame() const { return !m_frame.empty(); }
    std::size_t discardedBytes() const { return m_discarded; } // noise dropped while hunting

private:
    void push(std::uint8_t byte, std::vector<DeframerEvent> &events,
              std::vector<std::uint8_t> &replay);
    void drain(std::vector<DeframerEvent> &events, std::vector<std::uint8_t> &replay);
    void finish(std::vector<DeframerEvent> &events, std::vector<std::uint8_t> &replay);
    void fail(DecodeError error, std::vector<DeframerEvent> &events,
              std::vector<std::uint8_t> &replay);
    Bytes rawFrame() const;

    Options m_options;
    std::size_t m_preambles = 0; // 0xFF run before the current delimiter (saturates at 255)
    Bytes m_frame;               // delimiter … so far
    std::size_t m_need = 0;      // total bytes the current frame needs (known after the header)
    bool m_haveCount = false;    // m_need includes the byte count
    std::size_t m_discarded = 0;
};

} // namespace vt::dev::hart
