#include "hart/deframer.h"

#include "core/hex.h"

#include <algorithm>
#include <deque>
#include <string>

namespace vt::dev::hart {

std::vector<DeframerEvent> Deframer::feed(std::span<const std::uint8_t> bytes)
{
    std::vector<DeframerEvent> events;
    std::vector<std::uint8_t> replay;
    for (std::uint8_t b : bytes) {
        push(b, events, replay);
        drain(events, replay);
    }
    return events;
}

void Deframer::drain(std::vector<DeframerEvent> &events, std::vector<std::uint8_t> &replay)
{
    // Replayed bytes come before the rest of the input; a failure inside them puts its own
    // replay in front again. Each failure drops one false delimiter, so this ends, and the queue
    // never holds more than one maximum frame. Nothing to replay (nearly every byte): no queue.
    if (replay.empty())
        return;
    std::deque<std::uint8_t> work(replay.begin(), replay.end());
    replay.clear();
    while (!work.empty()) {
        const std::uint8_t b = work.front();
        work.pop_front();
        push(b, events, replay);
        if (!replay.empty()) {
            work.insert(work.begin(), replay.begin(), replay.end());
            replay.clear();
        }
    }
}

std::vector<DeframerEvent> Deframer::flush()
{
    std::vector<DeframerEvent> events;
    std::vector<std::uint8_t> replay;
    while (!m_frame.empty()) {
        fail(DecodeError{DecodeErrc::Truncated, m_preambles + m_frame.size(), 0,
                         "frame ended after " + std::to_string(m_frame.size()) + " bytes"},
             events, replay);
        drain(events, replay);
    }
    m_discarded += m_preambles; // a preamble run does not survive the gap
    m_preambles = 0;
    return events;
}

void Deframer::reset()
{
    m_preambles = 0;
    m_frame.clear();
    m_need = 0;
    m_haveCount = false;
}

Bytes Deframer::rawFrame() const
{
    Bytes raw(m_preambles, kPreamble);
    raw.insert(raw.end(), m_frame.begin(), m_frame.end());
    return raw;
}

void Deframer::push(std::uint8_t byte, std::vector<DeframerEvent> &events,
                    std::vector<std::uint8_t> &replay)
{
    if (m_frame.empty()) {
        // Hunting: count the preamble run, then judge the first other byte.
        if (byte == kPreamble) {
            m_preambles = std::min<std::size_t>(m_preambles + 1, kMaxPreambles);
            return;
        }
        if (m_preambles < m_options.minPreambles) {
            m_discarded += m_preambles + 1;
            m_preambles = 0;
            return;
        }
        if (!isValidDelimiter(byte)) {
            DeframerEvent e;
            e.kind = DeframerEvent::Kind::Error;
            e.error = DecodeError{DecodeErrc::BadValue, m_preambles, byte,
                                  "delimiter " + hexByte(byte) + " after " +
                                      std::to_string(m_preambles) + " preambles"};
            e.raw = Bytes(m_preambles, kPreamble);
            e.raw.push_back(byte);
            events.push_back(std::move(e));
            m_discarded += m_preambles + 1;
            m_preambles = 0;
            return;
        }
        m_frame.push_back(byte);
        m_need = 1 + headerSize(byte) + 1; // delimiter, address, expansion, command, byte count
        m_haveCount = false;
        return;
    }
    m_frame.push_back(byte);
    if (m_frame.size() < m_need)
        return;
    if (!m_haveCount) {
        m_need += static_cast<std::size_t>(byte) + 1; // status + data, then the checksum
        m_haveCount = true;
        return;
    }
    finish(events, replay);
}

void Deframer::finish(std::vector<DeframerEvent> &events, std::vector<std::uint8_t> &replay)
{
    const std::uint8_t sum = m_frame.back();
    const std::uint8_t expected =
        checksum(std::span<const std::uint8_t>(m_frame).first(m_frame.size() - 1));
    if (sum != expected) {
        fail(DecodeError{DecodeErrc::BadChecksum, m_preambles + m_frame.size() - 1, sum,
                         "checksum " + hexByte(sum) + ", computed " + hexByte(expected)},
             events, replay);
        return;
    }
    DeframerEvent e;
    e.raw = rawFrame();
    auto frame = decodeFrame(e.raw);
    if (frame.ok()) {
        e.frame = std::move(frame).value();
    } else {
        // Checksum fine but the layout is not (a response with byte count < 2): a real, bad frame.
        e.kind = DeframerEvent::Kind::Error;
        e.error = frame.error();
    }
    events.push_back(std::move(e));
    reset();
}

void Deframer::fail(DecodeError error, std::vector<DeframerEvent> &events,
                    std::vector<std::uint8_t> &replay)
{
    DeframerEvent e;
    e.kind = DeframerEvent::Kind::Error;
    e.error = std::move(error);
    e.raw = rawFrame();
    events.push_back(std::move(e));
    // The delimiter was false; everything after it may hold the real frame.
    replay.insert(replay.begin(), m_frame.begin() + 1, m_frame.end());
    m_discarded += m_preambles + 1;
    reset();
}

} // namespace vt::dev::hart
