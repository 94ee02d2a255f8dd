#include "hart/data_types.h"

#include "core/byte_reader.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace vt::dev::hart {

std::string unpackAscii(std::span<const std::uint8_t> bytes)
{
    std::string out;
    ByteReader r(bytes);
    while (r.remaining() >= 3) {
        const std::uint32_t group =
            static_cast<std::uint32_t>(r.u8()) << 16 | static_cast<std::uint32_t>(r.u16be());
        for (int shift = 18; shift >= 0; shift -= 6) {
            const auto v = static_cast<std::uint8_t>((group >> shift) & 0x3F);
            // 0x20..0x3F stand for themselves, 0x00..0x1F for 0x40..0x5F.
            out.push_back(static_cast<char>(v < 0x20 ? v + 0x40 : v));
        }
    }
    while (!out.empty() && out.back() == ' ')
        out.pop_back();
    return out;
}

Bytes packAscii(std::string_view text, std::size_t size)
{
    ByteWriter w;
    for (std::size_t g = 0; g < (size + 2) / 3; ++g) {
        std::uint32_t group = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            const std::size_t i = g * 4 + k;
            char c = i < text.size() ? text[i] : ' ';
            if (c >= 'a' && c <= 'z')
                c = static_cast<char>(c - 'a' + 'A');
            if (c < 0x20 || c > 0x5F)
                c = '?';
            group = group << 6 | (static_cast<std::uint32_t>(c) & 0x3F);
        }
        w.u8(static_cast<std::uint8_t>(group >> 16)).u16be(static_cast<std::uint16_t>(group));
    }
    Bytes out = w.take();
    out.resize(size);
    return out;
}

std::string latin1ToUtf8(std::span<const std::uint8_t> bytes)
{
    std::string out;
    std::size_t keep = 0; // length of `out` up to the last byte that is not NUL padding
    for (std::uint8_t b : bytes) {
        if (b < 0x80) {
            out.push_back(static_cast<char>(b));
        } else {
            out.push_back(static_cast<char>(0xC0 | (b >> 6)));
            out.push_back(static_cast<char>(0x80 | (b & 0x3F)));
        }
        if (b != 0)
            keep = out.size();
    }
    out.resize(keep);
    return out;
}

Bytes utf8ToLatin1(std::string_view text, std::size_t size)
{
    Bytes out;
    for (std::size_t i = 0; i < text.size() && out.size() < size;) {
        const auto b = static_cast<std::uint8_t>(text[i]);
        if (b < 0x80) {
            out.push_back(b);
            ++i;
            continue;
        }
        // Two-byte sequences C2/C3 xx are U+0080..U+00FF; everything else is outside Latin-1.
        std::size_t len = (b & 0xE0) == 0xC0   ? 2
                          : (b & 0xF0) == 0xE0 ? 3
                          : (b & 0xF8) == 0xF0 ? 4
                                               : 1;
        if (len == 2 && i + 1 < text.size() && (b == 0xC2 || b == 0xC3)) {
            const auto c = static_cast<std::uint8_t>(text[i + 1]);
            out.push_back(static_cast<std::uint8_t>((b & 0x03) << 6 | (c & 0x3F)));
        } else {
            out.push_back('?');
        }
        i += std::min(len, text.size() - i);
    }
    out.resize(size, 0);
    return out;
}

std::string formatDate(const Date &date)
{
    char buf[16];
    std::snprintf(buf, sizeof buf, "%04d-%02u-%02u", date.year(), static_cast<unsigned>(date.month),
                  static_cast<unsigned>(date.day));
    return buf;
}

float floatFromBits(std::uint32_t bits)
{
    return std::bit_cast<float>(bits);
}

std::uint32_t bitsFromFloat(float value)
{
    return std::bit_cast<std::uint32_t>(value);
}

std::string formatFloat(float value)
{
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value < 0 ? "-inf" : "inf";
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, res.ptr);
}

} // namespace vt::dev::hart
