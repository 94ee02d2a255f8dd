// CRC-16/MODBUS of an RTU frame (Modbus over Serial Line V1.02 §6.2.2: polynomial 0xA001
// reflected, initial value 0xFFFF, sent low byte first). Check value: "123456789" → 0x4B37.
#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace vt::dev::modbus {

namespace detail {
constexpr std::array<std::uint16_t, 256> makeCrcTable()
{
    std::array<std::uint16_t, 256> table{};
    for (unsigned i = 0; i < 256; ++i) {
        unsigned crc = i;
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 1u) != 0 ? (crc >> 1) ^ 0xA001u : crc >> 1;
        table[i] = static_cast<std::uint16_t>(crc);
    }
    return table;
}
inline constexpr std::array<std::uint16_t, 256> kCrcTable = makeCrcTable();
} // namespace detail

constexpr std::uint16_t crc16(std::span<const std::uint8_t> bytes)
{
    unsigned crc = 0xFFFF;
    for (std::uint8_t b : bytes)
        crc = (crc >> 8) ^ detail::kCrcTable[(crc ^ b) & 0xFFu];
    return static_cast<std::uint16_t>(crc);
}

} // namespace vt::dev::modbus
