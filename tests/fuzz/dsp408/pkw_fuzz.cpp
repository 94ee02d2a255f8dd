// fuzz_dsp408_pkw: arbitrary bytes as a PKW block in every direction / IND layout.
// Properties: no crash; a decoded PKW encodes back to exactly the input (lossless layout);
// describe never points past the input and always explains an error.
#include "dsp408/pkw.h"
#include "fuzz_require.h"

#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;
using namespace vt::dev::dsp408;

namespace {

using vt::fuzz::require;

void checkDescription(const Description &d, std::size_t size)
{
    for (const FieldSpan &f : d.fields)
        require(f.offset + f.length <= size && f.text.complete());
    require(d.ok() || !d.summary.en.empty());
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::span<const std::uint8_t> bytes(data, size);
    for (Direction direction : {Direction::Request, Direction::Response}) {
        for (IndPosition ind : {IndPosition::Byte2, IndPosition::Byte3}) {
            Options o;
            o.direction = direction;
            o.indPosition = ind;
            auto pkw = decodePkw(bytes, o);
            if (pkw.ok()) {
                auto again = encodePkw(*pkw, o);
                require(again.ok() && again->size() == size &&
                        std::equal(again->begin(), again->end(), bytes.begin()));
                (void)pkwSummary(*pkw, direction);
            }
            checkDescription(describePkw(bytes, o), size);
        }
    }
    return 0;
}
