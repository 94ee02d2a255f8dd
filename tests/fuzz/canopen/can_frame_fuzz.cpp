// fuzz_canopen_can_frame: arbitrary bytes as a SocketCAN struct can_frame and as candump text.
// Properties: no crash; decoded frames survive encode → decode unchanged; parsed candump text
// survives format → parse unchanged.
#include "canopen/can_frame.h"
#include "fuzz_require.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

using namespace vt::dev;
using namespace vt::dev::canopen;

using vt::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::span<const std::uint8_t> bytes(data, size);
    auto frame = fromSocketCan(bytes);
    if (frame.ok()) {
        auto again = fromSocketCan(toSocketCan(*frame));
        require(again.ok() && *again == *frame);
    }
    const std::string_view text(reinterpret_cast<const char *>(data), size);
    auto parsed = parseCandump(text);
    if (parsed.ok()) {
        auto again = parseCandump(formatCandump(*parsed));
        require(again.ok() && *again == *parsed);
    }
    return 0;
}
