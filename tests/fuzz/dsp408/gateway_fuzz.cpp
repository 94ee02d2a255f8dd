// fuzz_dsp408_gateway: Modbus TCP ADUs of a PROFIBUS-master gateway carrying the ED1's image
// (dsp408/gateway.h, modbus/register_image.h) through cutAdu, the register PDU decoders and
// describeGatewayAdu. Input: selector byte (bit 0 = response, bit 1 = swapped register bytes,
// bit 2 = low PZD word first) + ADU.
// Properties: no crash, no sanitizer report; every field lies inside the ADU and has both texts;
// a PDU that decodes encodes back to the same bytes, and its ADU to the same ADU.
#include "dsp408/gateway.h"
#include "fuzz_require.h"
#include "modbus/register_image.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

using namespace vt::dev;

using vt::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const bool response = (data[0] & 1) != 0;
    dsp408::Options o;
    o.direction = response ? Direction::Response : Direction::Request;
    o.pzdWordOrder =
        (data[0] & 4) != 0 ? dsp408::WordOrder::LowWordFirst : dsp408::WordOrder::HighWordFirst;
    const auto order = (data[0] & 2) != 0 ? dsp408::RegisterByteOrder::FirstByteLow
                                          : dsp408::RegisterByteOrder::FirstByteHigh;
    const std::span<const std::uint8_t> adu(data + 1, size - 1);
    const Description d = dsp408::describeGatewayAdu(adu, o, order);
    for (const FieldSpan &f : d.fields)
        require(f.offset + f.length <= adu.size() && f.text.complete());

    const auto cut = modbus::cutAdu(adu);
    if (!cut.ok() || !*cut)
        return 0;
    const modbus::AduCut &frame = **cut;
    require(frame.size <= adu.size() && frame.pdu.size() + modbus::kMbapSize == frame.size);
    const auto again = modbus::wrapAdu(frame.header.transaction, frame.header.unit, frame.pdu);
    const auto whole = adu.first(frame.size);
    require(std::equal(again.begin(), again.end(), whole.begin(), whole.end()));
    if (response) {
        const auto r = modbus::decodeRegisterResponse(frame.pdu);
        if (r.ok()) {
            const auto back = modbus::encodeRegisterPdu(*r);
            require(back.ok() &&
                    std::equal(back->begin(), back->end(), frame.pdu.begin(), frame.pdu.end()));
        }
    } else {
        const auto q = modbus::decodeRegisterRequest(frame.pdu);
        if (q.ok()) {
            const auto back = modbus::encodeRegisterPdu(*q);
            require(back.ok() &&
                    std::equal(back->begin(), back->end(), frame.pdu.begin(), frame.pdu.end()));
            if (const auto *w = std::get_if<modbus::RegisterWrite>(&*q)) {
                const Bytes bytes = dsp408::fromRegisters(w->values, order);
                const auto registers = dsp408::toRegisters(bytes, order);
                require(registers == w->values);
            }
        }
    }
    return 0;
}
