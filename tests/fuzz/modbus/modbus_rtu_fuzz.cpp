// fuzz_modbus_rtu: Modbus RTU ADUs through the decoders and describeRtu(). Input: selector byte
// (bit 0 = response) + ADU. Properties: no crash; describe and decode agree; decoded frames
// re-encode to the same bytes; rows stay inside the frame.
#include "fuzz_require.h"
#include "modbus/describe.h"
#include "modbus/rtu.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;
using namespace vt::dev::modbus;

using vt::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const Direction direction = (data[0] & 1) != 0 ? Direction::Response : Direction::Request;
    const std::span<const std::uint8_t> adu(data + 1, size - 1);
    DescribeOptions o;
    o.direction = direction;
    o.requestStart = 0xFFF0;
    o.family = (data[0] & 2) != 0 ? hcs::Family::Opat : hcs::Family::Dma;
    const Description d = describeRtu(adu, o);
    for (const FieldSpan &f : d.fields)
        require(f.offset + f.length <= adu.size() && f.text.complete());
    if (direction == Direction::Request) {
        auto q = decodeRtuRequest(adu);
        require(q.ok() == d.ok());
        if (q.ok()) {
            auto back = encodeRtu(*q);
            require(back.ok() && std::equal(back->begin(), back->end(), adu.begin(), adu.end()));
        }
    } else {
        auto a = decodeRtuResponse(adu);
        require(a.ok() == d.ok());
        if (a.ok()) {
            auto back = encodeRtu(*a);
            require(back.ok() && std::equal(back->begin(), back->end(), adu.begin(), adu.end()));
        }
    }
    return 0;
}
