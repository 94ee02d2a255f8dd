// ByteWriter: appends big-endian fields to a frame being encoded (fieldbus byte order,
// ARCHITECTURE.md "Byte order").
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace vt::dev {

using Bytes = std::vector<std::uint8_t>;

class ByteWriter
{
public:
    ByteWriter &u8(std::uint8_t v)
    {
        m_out.push_back(v);
        return *this;
    }
    ByteWriter &u16be(std::uint16_t v)
    {
        return u8(static_cast<std::uint8_t>(v >> 8)).u8(static_cast<std::uint8_t>(v));
    }
    ByteWriter &u16le(std::uint16_t v)
    {
        return u8(static_cast<std::uint8_t>(v)).u8(static_cast<std::uint8_t>(v >> 8));
    }
    ByteWriter &u32be(std::uint32_t v)
    {
        return u16be(static_cast<std::uint16_t>(v >> 16)).u16be(static_cast<std::uint16_t>(v));
    }
    ByteWriter &bytes(std::span<const std::uint8_t> b)
    {
        m_out.insert(m_out.end(), b.begin(), b.end());
        return *this;
    }

    const Bytes &data() const { return m_out; }
    Bytes take() { return std::move(m_out); }

private:
    Bytes m_out;
};

} // namespace vt::dev
