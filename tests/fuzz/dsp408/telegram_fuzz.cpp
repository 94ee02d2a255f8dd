// fuzz_dsp408_telegram: arbitrary bytes as a DSP-408 telegram of type 1 or 2. Byte 0 picks the
// options (bit 0 direction, bit 1 word order, bit 2 IND byte, bits 3..4 telegram type), the rest
// is the telegram. Properties: no crash; decoded telegrams encode back to the input; describe
// stays inside the input.
#include "dsp408/pzd.h"
#include "fuzz_require.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;
using namespace vt::dev::dsp408;

namespace {

using vt::fuzz::require;

template<typename T>
void roundTrip(const Result<T, DecodeError> &t, std::span<const std::uint8_t> bytes,
               const Options &o)
{
    if (!t.ok())
        return;
    auto again = encodeTelegram(*t, o);
    require(again.ok() && again->size() == bytes.size() &&
            std::equal(again->begin(), again->end(), bytes.begin()));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 1)
        return 0;
    Options o;
    o.direction = (data[0] & 1) ? Direction::Response : Direction::Request;
    o.pzdWordOrder = (data[0] & 2) ? WordOrder::LowWordFirst : WordOrder::HighWordFirst;
    o.indPosition = (data[0] & 4) ? IndPosition::Byte3 : IndPosition::Byte2;
    switch ((data[0] >> 3) & 3) {
    case 1: o.telegramType = TelegramType::PkwAndPzd; break;
    case 2: o.telegramType = TelegramType::PzdOnly; break;
    default: break;
    }
    const std::span<const std::uint8_t> bytes(data + 1, size - 1);
    roundTrip(decodeRequestTelegram(bytes, o), bytes, o);
    roundTrip(decodeResponseTelegram(bytes, o), bytes, o);
    (void)decodePzdSetpoint(bytes, o);
    (void)decodePzdActual(bytes, o);
    const Description d = describeTelegram(bytes, o);
    for (const FieldSpan &f : d.fields)
        require(f.offset + f.length <= bytes.size() && f.text.complete());
    return 0;
}
