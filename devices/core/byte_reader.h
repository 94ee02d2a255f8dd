// ByteReader: the one bounds-checked way codecs read a frame (STYLE.md rule 6). It never reads
// past the end; the first failed read latches `failed()` and records the offset, and every
// later read returns 0, so a codec can read a whole layout and check once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace vt::dev {

class ByteReader
{
public:
    explicit ByteReader(std::span<const std::uint8_t> data) : m_data(data) {}

    // Inline: codecs call these per field, and the wire decoders sit on the receive path.
    std::uint8_t u8()
    {
        if (!take(1))
            return 0;
        return m_data[m_pos++];
    }
    std::uint16_t u16be()
    {
        if (!take(2))
            return 0;
        const auto v = static_cast<std::uint16_t>((m_data[m_pos] << 8) | m_data[m_pos + 1]);
        m_pos += 2;
        return v;
    }
    std::uint16_t u16le();
    std::uint32_t u32be();
    std::int16_t i16be() { return static_cast<std::int16_t>(u16be()); }
    std::int32_t i32be() { return static_cast<std::int32_t>(u32be()); }
    // Returns the next n bytes, or an empty span (and latches failure) when fewer remain.
    std::span<const std::uint8_t> bytes(std::size_t n);
    void skip(std::size_t n) { (void)bytes(n); }

    std::size_t offset() const { return m_pos; }
    std::size_t remaining() const { return m_failed ? 0 : m_data.size() - m_pos; }
    bool atEnd() const { return m_pos >= m_data.size(); }
    bool failed() const { return m_failed; }
    // Offset of the read that failed (the first byte that was missing).
    std::size_t failOffset() const { return m_failOffset; }
    std::span<const std::uint8_t> data() const { return m_data; }

private:
    bool take(std::size_t n)
    {
        if (m_failed)
            return false;
        if (n > m_data.size() - m_pos) {
            m_failed = true;
            m_failOffset = m_data.size();
            return false;
        }
        return true;
    }

    std::span<const std::uint8_t> m_data;
    std::size_t m_pos = 0;
    std::size_t m_failOffset = 0;
    bool m_failed = false;
};

} // namespace vt::dev
