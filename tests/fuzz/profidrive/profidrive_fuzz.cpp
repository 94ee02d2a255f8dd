// fuzz_profidrive: PROFIdrive telegram 1 and the OPAT manual §5.6 mixed image through the decoders
// and describe(). Input: selector byte (bit 0 = response, bits 1-2 = layout 0 auto / 1 telegram 1
// / 2 mixed, bit 3 = DMA family for the CMD 15 part) + image. Properties: no crash; describe and
// decode agree; decoded images re-encode to the same bytes; N2 conversions stay finite.
#include "fuzz_require.h"
#include "profidrive/describe.h"
#include "profidrive/mixed.h"
#include "profidrive/telegram1.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;
using namespace vt::dev::profidrive;

namespace {

using vt::fuzz::require;

template<typename R> bool sameBytes(const R &encoded, std::span<const std::uint8_t> image)
{
    return std::equal(encoded.begin(), encoded.end(), image.begin(), image.end());
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const std::uint8_t selector = data[0];
    const std::span<const std::uint8_t> image(data + 1, size - 1);
    DescribeOptions o;
    o.direction = (selector & 1) != 0 ? Direction::Response : Direction::Request;
    const unsigned layout = (selector >> 1) & 3u;
    o.layout = layout == 1 ? Layout::Telegram1 : layout == 2 ? Layout::MixedCmd15 : Layout::Auto;
    o.node.family = (selector & 8) != 0 ? hcs::Family::Dma : hcs::Family::Opat;
    const Description d = describe(image, o);
    for (const FieldSpan &f : d.fields)
        require(f.offset + f.length <= image.size() && f.text.complete());

    const bool mixed = o.layout == Layout::MixedCmd15 ||
                       (o.layout == Layout::Auto && image.size() > kTelegram1Size);
    const hcs::DecodeOptions dop{o.node.family, false};
    if (o.direction == Direction::Request) {
        if (mixed) {
            auto m = decodeMixedRequest(image, dop);
            require(m.ok() == d.ok());
            if (m.ok()) {
                auto back = encode(*m, o.node.family);
                require(back.ok() && sameBytes(*back, image));
            }
        } else {
            auto s = decodeSetpoint(image);
            require(s.ok() == d.ok());
            if (s.ok()) {
                require(sameBytes(encode(*s), image));
                require(std::isfinite(n2ToVolts(s->nsollA)) &&
                        voltsToN2(n2ToVolts(s->nsollA)) == s->nsollA);
            }
        }
    } else {
        if (mixed) {
            auto m = decodeMixedResponse(image, dop);
            require(m.ok() == d.ok());
            if (m.ok())
                require(sameBytes(encode(*m), image));
        } else {
            auto a = decodeActual(image);
            require(a.ok() == d.ok());
            if (a.ok())
                require(sameBytes(encode(*a), image));
        }
    }
    return 0;
}
