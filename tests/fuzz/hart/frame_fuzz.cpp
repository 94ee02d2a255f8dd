// fuzz_hart_frame: arbitrary bytes as one HART frame (preambles … checksum).
// Properties: no crash; a decoded frame encodes back to exactly the input (the link layer is
// lossless); describe stays inside the input and explains every error.
#include "fuzz_require.h"
#include "hart/describe.h"
#include "hart/frame.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;
using namespace vt::dev::hart;

using vt::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::span<const std::uint8_t> bytes(data, size);
    auto frame = decodeFrame(bytes);
    if (frame.ok()) {
        auto again = encodeFrame(*frame);
        require(again.ok() && again->size() == size &&
                std::equal(again->begin(), again->end(), bytes.begin()));
    } else {
        require(frame.error().offset <= size);
    }
    const Description d = describeFrame(bytes);
    for (const FieldSpan &f : d.fields)
        require(f.offset + f.length <= size && f.text.complete());
    require(frame.ok() || !d.ok()); // a link-layer error is always reported
    require(d.ok() || !d.summary.en.empty());
    return 0;
}
