#include "hex.h"

#include <cctype>

namespace vt::dev {
namespace {

bool isSeparator(char c)
{
    return std::isspace(static_cast<unsigned char>(c)) || c == ',' || c == ':' || c == '-' ||
           c == ';';
}

} // namespace

Result<Bytes, HexError> parseHex(std::string_view text)
{
    Bytes out;
    std::size_t i = 0;
    while (i < text.size()) {
        if (isSeparator(text[i])) {
            ++i;
            continue;
        }
        // A token runs to the next separator; "0x" prefixes one token.
        std::size_t start = i;
        if (text.size() - i >= 2 && text[i] == '0' && (text[i + 1] == 'x' || text[i + 1] == 'X'))
            i += 2;
        const std::size_t digits = i;
        while (i < text.size() && !isSeparator(text[i])) {
            if (hexDigitValue(text[i]) < 0)
                return HexError{i, std::string("not a hex digit: '") + text[i] + "'"};
            ++i;
        }
        const std::size_t n = i - digits;
        if (n == 0)
            return HexError{start, "empty 0x prefix"};
        if (n % 2 != 0) {
            if (n != 1)
                return HexError{start, "odd number of hex digits"};
            out.push_back(static_cast<std::uint8_t>(hexDigitValue(text[digits])));
            continue;
        }
        for (std::size_t k = digits; k < i; k += 2)
            out.push_back(static_cast<std::uint8_t>(hexDigitValue(text[k]) << 4 |
                                                    hexDigitValue(text[k + 1])));
    }
    return out;
}

std::string toHex(std::span<const std::uint8_t> bytes, char separator)
{
    static constexpr char kDigits[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(bytes.size() * 3);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        if (i != 0 && separator != '\0')
            out.push_back(separator);
        out.push_back(kDigits[bytes[i] >> 4]);
        out.push_back(kDigits[bytes[i] & 0x0F]);
    }
    return out;
}

std::string hexByte(std::uint8_t b)
{
    return "0x" + toHex(std::span<const std::uint8_t>(&b, 1));
}

std::string hexWord(std::uint16_t w)
{
    const std::uint8_t b[2] = {static_cast<std::uint8_t>(w >> 8), static_cast<std::uint8_t>(w)};
    return "0x" + toHex(b, '\0');
}

int hexDigitValue(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

} // namespace vt::dev
