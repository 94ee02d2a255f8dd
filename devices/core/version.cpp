#include "core/version.h"

#include <charconv>

namespace vt::dev {

std::string majorVersion(std::string_view version)
{
    std::size_t n = 0;
    while (n < version.size() && version[n] >= '0' && version[n] <= '9')
        ++n;
    return std::string(version.substr(0, n));
}

int majorVersionNumber(std::string_view version)
{
    const std::string major = majorVersion(version);
    int value = 0;
    const auto [end, error] = std::from_chars(major.data(), major.data() + major.size(), value);
    return error == std::errc() && end != major.data() ? value : 0;
}

} // namespace vt::dev
