// The major version of a software version text, as dictionaries list versions ("34", "51").
#pragma once

#include <string>
#include <string_view>

namespace vt::dev {

// The leading digits: "34.03" → "34", "22" → "22"; "" when the text does not start with a digit
// ("SD7 device type 58352", "").
std::string majorVersion(std::string_view version);
// The same as a number; 0 when there is none.
int majorVersionNumber(std::string_view version);

} // namespace vt::dev
