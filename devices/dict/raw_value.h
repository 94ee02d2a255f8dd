// RawValue: one parameter value as it travels on the wire — a number (every integer type of the
// dictionaries fits a double exactly, float32 too) or a string row's text. Shared by the session,
// the parameter files and the simulator; cooking (cooking.h) turns the number into display units.
#pragma once

#include <string>
#include <variant>

namespace vt::dev {

using RawValue = std::variant<double, std::string>;

inline bool isText(const RawValue &value)
{
    return std::holds_alternative<std::string>(value);
}
inline double rawNumber(const RawValue &value)
{
    const double *number = std::get_if<double>(&value);
    return number ? *number : 0.0;
}

} // namespace vt::dev
