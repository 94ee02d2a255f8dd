// fuzz_hcs_telegram: HCS node telegrams (CMD 3 / 6 / 15, error frames) through every decoder and
// describe(). Input: selector byte (bit 0 OPAT, bit 1 response, bit 2 padding allowed, bits 3-6
// CMD 15 profile) + frame. Properties: no crash; describe() and the decoders agree; a decoded
// frame re-encodes to the same bytes; rows stay inside the frame.
#include "fuzz_require.h"
#include "hcs/describe.h"
#include "hcs/telegram.h"

#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;
using namespace vt::dev::hcs;

using vt::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const std::uint8_t selector = data[0];
    const std::span<const std::uint8_t> frame(data + 1, size - 1);
    const Family family = (selector & 1) != 0 ? Family::Opat : Family::Dma;
    const Direction direction = (selector & 2) != 0 ? Direction::Response : Direction::Request;
    const bool padding = (selector & 4) != 0;
    const auto profiles = allProfiles();
    const std::size_t pick = (selector >> 3) % (profiles.size() + 1);

    DescribeOptions o;
    o.family = family;
    o.direction = direction;
    o.allowPadding = padding;
    if (pick < profiles.size())
        o.profile = profiles[pick].profile;
    o.firstId = 0xFFFA; // names DAT1.. near the top of the ID range
    const Description d = describe(frame, o);
    for (const FieldSpan &f : d.fields)
        require(f.offset + f.length <= frame.size() && f.text.complete());

    const DecodeOptions dop{family, padding};
    if (direction == Direction::Request) {
        auto q = decodeRequest(frame, dop);
        require(q.ok() == d.ok());
        if (q.ok() && !padding) {
            auto back = encode(*q, family);
            require(back.ok() &&
                    std::equal(back->begin(), back->end(), frame.begin(), frame.end()));
        }
        (void)decodeReadRequest(frame, dop);
        (void)decodeWriteRequest(frame, dop);
        (void)decodeCyclicRequest(frame, dop);
    } else {
        auto a = decodeResponse(frame, dop);
        require(a.ok() == d.ok());
        if (a.ok() && !padding) {
            auto back = encode(*a);
            require(back.ok() &&
                    std::equal(back->begin(), back->end(), frame.begin(), frame.end()));
        }
        (void)decodeReadResponse(frame, dop);
        (void)decodeWriteResponse(frame, dop);
        (void)decodeCyclicResponse(frame, dop);
        (void)decodeExceptionResponse(frame, dop);
    }
    if (!d.ok())
        require(d.error->offset <= frame.size());
    return 0;
}
