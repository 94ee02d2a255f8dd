// fuzz_hart_deframer: a byte stream fed in chunks to the streaming de-framer, then flushed.
// Input: byte 0 (chunk-size seed), byte 1 (minimum preambles 1..4), then the stream.
// Properties: no crash; every frame event's raw bytes decode to that frame; no event is larger
// than the bound (255 preambles + one maximum frame); nothing stays buffered after flush().
#include "fuzz_require.h"
#include "hart/deframer.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;
using namespace vt::dev::hart;

namespace {

using vt::fuzz::require;

void check(const std::vector<DeframerEvent> &events)
{
    for (const DeframerEvent &e : events) {
        require(e.raw.size() <= kMaxPreambles + kMaxFrameSize);
        if (e.kind == DeframerEvent::Kind::Frame) {
            auto f = decodeFrame(e.raw);
            require(f.ok() && *f == e.frame);
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 2)
        return 0;
    const std::uint8_t seed = data[0];
    Deframer d(Deframer::Options{static_cast<std::size_t>(1 + data[1] % 4)});
    const std::span<const std::uint8_t> stream(data + 2, size - 2);
    std::size_t at = 0;
    for (unsigned k = 0; at < stream.size(); ++k) {
        const std::size_t chunk =
            std::min<std::size_t>(1 + (seed + k * 13u) % 41u, stream.size() - at);
        check(d.feed(stream.subspan(at, chunk)));
        at += chunk;
    }
    check(d.flush());
    require(!d.midFrame());
    return 0;
}
