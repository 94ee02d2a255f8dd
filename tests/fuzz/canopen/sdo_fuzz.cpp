// fuzz_canopen_sdo: arbitrary data bytes as an SDO. Input: bytes 0..1 = COB-ID (big-endian),
// then the data. Properties: no crash; decode(encode(x)) == x for every decoded SDO; describe
// stays inside the data and explains every error.
#include "canopen/sdo.h"
#include "fuzz_require.h"

#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;
using namespace vt::dev::canopen;

using vt::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 2)
        return 0;
    const std::uint32_t cobId = static_cast<std::uint32_t>(data[0] << 8 | data[1]) & 0x7FF;
    const std::span<const std::uint8_t> bytes(data + 2, size - 2);
    for (Direction direction : {Direction::Request, Direction::Response}) {
        auto sdo = decodeSdo(bytes, direction);
        if (!sdo.ok())
            continue;
        auto encoded = encodeSdo(*sdo);
        require(encoded.ok() && encoded->size() == kSdoSize);
        auto again = decodeSdo(*encoded, direction);
        require(again.ok() && *again == *sdo);
        (void)commandText(*sdo);
    }
    DescribeOptions o;
    o.cobId = cobId;
    const Description d = describeSdo(bytes, o);
    for (const FieldSpan &f : d.fields)
        require(f.offset + f.length <= bytes.size() && f.text.complete());
    require(d.ok() || !d.summary.en.empty());
    if (bytes.size() <= 8) {
        const CanFrame frame = makeCanFrame(cobId, bytes);
        (void)describeSdo(frame);
        (void)fromCanFrame(frame);
    }
    return 0;
}
