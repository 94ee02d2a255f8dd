// Fixed-point numbers as people read them in both product languages (header-only): raw 1000 with
// 3 decimals is "1.000 V" in English and "1,000 V" in German (ARCHITECTURE.md "Raw / cooked").
#pragma once

#include "local_text.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

namespace vt::dev {

// raw / 10^decimals, e.g. formatScaled(-3000, 3, "V") = {"-3.000 V", "-3,000 V"}. Empty unit: no
// space.
LocalText formatScaled(std::int64_t raw, int decimals, std::string_view unit = {});

// A double rounded to `decimals` digits (half away from zero), same layout as formatScaled.
LocalText formatDecimal(double value, int decimals, std::string_view unit = {});

inline LocalText formatScaled(std::int64_t raw, int decimals, std::string_view unit)
{
    if (decimals < 0)
        decimals = 0;
    if (decimals > 9)
        decimals = 9;
    std::uint64_t div = 1;
    for (int i = 0; i < decimals; ++i)
        div *= 10;
    const bool negative = raw < 0;
    // Magnitude without overflowing on INT64_MIN.
    const std::uint64_t mag = negative ? std::uint64_t{0} - static_cast<std::uint64_t>(raw)
                                       : static_cast<std::uint64_t>(raw);
    const std::string whole = (negative ? "-" : "") + std::to_string(mag / div);
    const std::string suffix = unit.empty() ? std::string() : " " + std::string(unit);
    if (decimals == 0)
        return {whole + suffix, whole + suffix};
    std::string frac = std::to_string(mag % div); // fewer than `decimals` digits: div > mag % div
    frac.insert(0, static_cast<std::size_t>(decimals) - frac.size(), '0');
    return {whole + "." + frac + suffix, whole + "," + frac + suffix};
}

inline LocalText formatDecimal(double value, int decimals, std::string_view unit)
{
    if (!std::isfinite(value))
        return {"–", "–"};
    if (decimals < 0)
        decimals = 0;
    if (decimals > 9)
        decimals = 9;
    const double scaled = std::round(value * std::pow(10.0, decimals));
    // Clamp to what fits an int64 (values here are small; this only keeps the cast defined).
    const double limit = 9.0e18;
    const double clamped = scaled > limit ? limit : (scaled < -limit ? -limit : scaled);
    return formatScaled(static_cast<std::int64_t>(clamped), decimals, unit);
}

} // namespace vt::dev
