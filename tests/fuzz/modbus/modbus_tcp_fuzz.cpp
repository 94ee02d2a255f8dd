// fuzz_modbus_tcp: Modbus TCP ADUs through the decoders and describeTcp(). Input: selector byte
// (bit 0 = response) + ADU. Same properties as fuzz_modbus_rtu.
#include "fuzz_require.h"
#include "modbus/describe.h"
#include "modbus/tcp.h"

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
    const Description d = describeTcp(adu, o);
    for (const FieldSpan &f : d.fields)
        require(f.offset + f.length <= adu.size() && f.text.complete());
    (void)decodeMbap(adu);
    if (direction == Direction::Request) {
        auto q = decodeTcpRequest(adu);
        require(q.ok() == d.ok());
        if (q.ok()) {
            auto back = encodeTcp(*q);
            require(back.ok() && std::equal(back->begin(), back->end(), adu.begin(), adu.end()));
        }
    } else {
        auto a = decodeTcpResponse(adu);
        require(a.ok() == d.ok());
        if (a.ok()) {
            auto back = encodeTcp(*a);
            require(back.ok() && std::equal(back->begin(), back->end(), adu.begin(), adu.end()));
        }
    }
    return 0;
}
