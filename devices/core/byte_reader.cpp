#include "byte_reader.h"

namespace vt::dev {

std::uint16_t ByteReader::u16le()
{
    if (!take(2))
        return 0;
    const auto v = static_cast<std::uint16_t>(m_data[m_pos] | (m_data[m_pos + 1] << 8));
    m_pos += 2;
    return v;
}

std::uint32_t ByteReader::u32be()
{
    if (!take(4))
        return 0;
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
        v = (v << 8) | m_data[m_pos + static_cast<std::size_t>(i)];
    m_pos += 4;
    return v;
}

std::span<const std::uint8_t> ByteReader::bytes(std::size_t n)
{
    if (!take(n))
        return {};
    auto out = m_data.subspan(m_pos, n);
    m_pos += n;
    return out;
}

} // namespace vt::dev
