// fuzz_hart_payload: arbitrary data bytes for every universal and device-specific command.
// Input: byte 0 = command, byte 1 bit 0 = response, then the data. Properties: no crash;
// describe stays inside the data; a decoded payload encodes to something that decodes again to
// the same payload (idempotent round trip).
#include "fuzz_require.h"
#include "hart/device_specific.h"
#include "hart/universal.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;
using namespace vt::dev::hart;

using vt::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 2)
        return 0;
    const std::uint8_t command = data[0];
    const bool response = (data[1] & 1) != 0;
    const std::span<const std::uint8_t> bytes(data + 2, size - 2);
    std::vector<FieldSpan> rows;
    (void)describeUniversal(command, response, bytes, 0, 1, rows);
    (void)describeParamAccess(command, response, bytes, 0, 1, rows);
    for (const FieldSpan &f : rows)
        require(f.offset + f.length <= bytes.size() && f.text.complete());

    auto universal = decodeUniversal(command, response, bytes);
    if (universal.ok()) {
        const Bytes encoded = encodePayload(*universal);
        auto again = decodeUniversal(command, response, encoded);
        require(again.ok());
        // Floats: NaN payloads compare unequal to themselves, so compare the bytes instead.
        require(encodePayload(*again) == encoded);
    }
    auto param = decodeParamAccess(command, response, bytes);
    if (param.ok()) {
        auto encoded = encodeParamAccess(*param, response);
        require(encoded.ok() &&
                std::equal(encoded->begin(), encoded->end(), bytes.begin(), bytes.end()));
    }
    return 0;
}
