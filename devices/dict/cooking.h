// Cooking: raw values on the wire <-> values as a person reads and types them, per the
// parameter's scale, unit, enum labels and the user's language ("1.000 V" / "1,000 V").
// Pure functions; safe from any thread.
#pragma once

#include "core/local_text.h"
#include "core/result.h"
#include "param_meta.h"

#include <optional>
#include <string>
#include <string_view>

namespace vt::dev {

struct CookError
{
    enum class Kind {
        Empty,
        NotANumber,
        WrongDecimalSign,
        UnknownLabel,
        BelowMin,
        AboveMax,
        NotWritable,
        TooLong
    };
    Kind kind = Kind::NotANumber;
    LocalText message; // names the limits in display units
};

// Effective raw limits: the row's own, narrowed by min_param / max_param when the caller knows
// those parameters' current values.
struct Limits
{
    double min = 0;
    double max = 0;
};
Limits rowLimits(const ParamMeta &meta);

// Display number of a raw value (raw × factor), rounded to the scale's decimals.
double toDisplay(const ParamMeta &meta, double raw);
// The number alone in the language's notation: "1.000" / "1,000".
std::string formatNumber(const ParamMeta &meta, double raw, Language lang);
// The value as shown in the editor and the CLI: enum label, or number and unit ("1.000 V").
std::string formatValue(const ParamMeta &meta, double raw, Language lang);
// A bit field's set bits as labels: "Enable active, Error"; raw bits without a label as "bit 9".
std::string formatBits(const ParamMeta &meta, std::uint32_t raw, Language lang);

// Typed text -> raw value: number in the language's notation with or without the unit, or an
// enum label in either language. Rejects the other language's decimal sign rather than
// guessing, and checks the range. DSP-408 scales truncate toward zero (ED1/SD1 manual §4.7:
// 60 mA / 1.78 = 33.7 -> 33); a typed value within half a display digit of a raw step (as
// shown by formatNumber) maps back to that step, so display -> parse round-trips.
Result<double, CookError> parseValue(const ParamMeta &meta, std::string_view text, Language lang,
                                     std::optional<Limits> limits = std::nullopt);

// Range check of a raw value (also for read-only rows, e.g. values in a file).
std::optional<CookError> checkRange(const ParamMeta &meta, double raw,
                                    std::optional<Limits> limits = std::nullopt);
// Before anything is sent: the row must be writable and the value in range.
std::optional<CookError> checkWrite(const ParamMeta &meta, double raw,
                                    std::optional<Limits> limits = std::nullopt);

} // namespace vt::dev
