// fuzz_modbus_deframer: a byte stream fed in chunks to the RTU or TCP de-framer. Input: byte 0
// (bit 0 = response direction, bit 1 = TCP), byte 1 (chunk-size seed), then the stream.
// Properties: no crash; every RTU frame has a valid CRC and the length its header announces;
// every TCP frame has a valid MBAP header; nothing is lost or invented (frames + discarded +
// buffered = input for RTU); the buffers stay bounded.
#include "fuzz_require.h"
#include "modbus/deframer.h"
#include "modbus/rtu.h"
#include "modbus/tcp.h"

#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;
using namespace vt::dev::modbus;

using vt::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 2)
        return 0;
    const Direction direction = (data[0] & 1) != 0 ? Direction::Response : Direction::Request;
    const bool tcp = (data[0] & 2) != 0;
    const std::uint8_t seed = data[1];
    const std::span<const std::uint8_t> stream(data + 2, size - 2);

    RtuDeframer rtu(direction);
    TcpDeframer mbap;
    std::size_t framed = 0;
    std::size_t at = 0;
    for (unsigned k = 0; at < stream.size(); ++k) {
        const std::size_t chunk =
            std::min<std::size_t>(1 + (seed + k * 7u) % 23u, stream.size() - at);
        const auto piece = stream.subspan(at, chunk);
        at += chunk;
        if (tcp) {
            for (const Bytes &f : mbap.feed(piece)) {
                auto m = decodeMbap(f);
                require(m.ok() && m->aduSize() == f.size());
            }
            require(mbap.buffered() <= stream.size());
        } else {
            for (const Bytes &f : rtu.feed(piece)) {
                require(rtuCrcOk(f));
                require(rtuFrameLength(f, direction) == f.size());
                framed += f.size();
            }
            require(rtu.buffered() <= 300);
        }
        if (!tcp && (seed & 0x80) != 0 && k % 5 == 4)
            rtu.silence();
    }
    if (!tcp)
        require(framed + rtu.discarded() + rtu.buffered() == stream.size());
    return 0;
}
