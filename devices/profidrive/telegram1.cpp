#include "telegram1.h"

#include "core/byte_reader.h"
#include "core/decode_helpers.h"

#include <cmath>
#include <string>

namespace vt::dev::profidrive {
namespace {

template<typename T>
Result<T, DecodeError> decodeWords(std::span<const std::uint8_t> bytes, bool allowTrailing,
                                   const char *what)
{
    ByteReader r(bytes);
    const std::uint16_t word = r.u16be();
    const std::int16_t value = r.i16be();
    if (r.failed())
        return truncated(r, std::string(what) + " has 4 bytes (2 words)");
    if (!r.atEnd() && !allowTrailing)
        return tooLong(r, std::to_string(bytes.size() - r.offset()) + " bytes after telegram 1");
    return T{word, value};
}

std::int16_t clampToI16(double v)
{
    if (!std::isfinite(v))
        return 0;
    const double rounded = std::round(v);
    if (rounded > 32767.0)
        return 32767;
    if (rounded < -32768.0)
        return -32768;
    return static_cast<std::int16_t>(rounded);
}

} // namespace

Bytes encode(const Setpoint &s)
{
    ByteWriter w;
    w.u16be(s.stw1).u16be(static_cast<std::uint16_t>(s.nsollA));
    return w.take();
}

Bytes encode(const Actual &a)
{
    ByteWriter w;
    w.u16be(a.zsw1).u16be(static_cast<std::uint16_t>(a.nistA));
    return w.take();
}

Result<Setpoint, DecodeError> decodeSetpoint(std::span<const std::uint8_t> bytes,
                                             bool allowTrailing)
{
    return decodeWords<Setpoint>(bytes, allowTrailing, "STW1 + NSOLL_A");
}

Result<Actual, DecodeError> decodeActual(std::span<const std::uint8_t> bytes, bool allowTrailing)
{
    return decodeWords<Actual>(bytes, allowTrailing, "ZSW1 + NIST_A");
}

double n2ToPercent(std::int16_t n2)
{
    return n2 * 100.0 / kN2FullScale;
}

double n2ToVolts(std::int16_t n2, double voltsAt100)
{
    return n2 * voltsAt100 / kN2FullScale;
}

std::int16_t percentToN2(double percent)
{
    return clampToI16(percent * kN2FullScale / 100.0);
}

std::int16_t voltsToN2(double volts, double voltsAt100)
{
    if (voltsAt100 == 0.0)
        return 0;
    return clampToI16(volts * kN2FullScale / voltsAt100);
}

int n2ToMillivolts(std::int16_t n2, double voltsAt100)
{
    const double mv = std::round(n2ToVolts(n2, voltsAt100) * 1000.0);
    if (!std::isfinite(mv))
        return 0;
    if (mv > 2.0e9)
        return 2000000000;
    if (mv < -2.0e9)
        return -2000000000;
    return static_cast<int>(mv);
}

} // namespace vt::dev::profidrive
