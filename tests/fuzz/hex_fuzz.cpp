#include "core/hex.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char *>(data), size);
    auto r = vt::dev::parseHex(text);
    if (r.ok())
        (void)vt::dev::toHex(*r);
    return 0;
}
