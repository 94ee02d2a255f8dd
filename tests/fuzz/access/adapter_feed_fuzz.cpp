// fuzz_adapter_feed: the reply paths of the protocol adapters (devices/access/) — what the
// session feeds them from the link, in the chunks the link delivers.
// Input: byte 0 picks the adapter (bits 2..0: node image DMA / OPAT, HART, CANopen HCS / DSP-408,
// Modbus RTU / TCP) and the transaction (bits 4..3: identify, read, write, raw; bit 5: a retry
// with resetFraming() halfway; bit 6: the line goes quiet after every chunk, lineQuiet() with the
// transaction awaited, as a serial link that ends frames by silence reports); byte 1: bit 7
// replaces the adapter by the ED1's image adapter (bit 6: gateway registers, else the raw image),
// bits 5..0 are the chunk-size seed; the rest is the byte stream. Progress replies hand their next
// bytes nowhere, as a session whose link is gone would. Properties: no crash, no sanitizer report;
// an Ok reply carries one value per row (reads) or one value (writes); the reply's frame is never
// longer than the bytes fed.
#include "access/canopen_adapter.h"
#include "access/dsp408_adapter.h"
#include "access/hart_adapter.h"
#include "access/modbus_adapter.h"
#include "access/node_image_adapter.h"
#include "fuzz_require.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

using namespace vt::dev;
using namespace vt::dev::access;

namespace {

using vt::fuzz::require;

ParamMeta row(RawType type, int id, int ind, int pnu, std::optional<CanObject> object = {})
{
    ParamMeta p;
    p.name = "fuzz" + std::to_string(id);
    p.id = id;
    p.ind = ind;
    p.pnu = pnu;
    p.type = type;
    p.access = Access::ReadWrite;
    p.min = -1000;
    p.max = 1000;
    p.canopen = object;
    return p;
}

// Eight consecutive HCS IDs (one CMD 3 / FC 3 block) with every numeric type, so the HART and
// CANopen DSP-408 paths see 1-, 2- and 4-byte values and floats.
const std::vector<ParamMeta> &rows()
{
    static const std::vector<ParamMeta> kRows = [] {
        std::vector<ParamMeta> r;
        const RawType types[] = {RawType::Int16, RawType::Int8,   RawType::UInt8,   RawType::UInt16,
                                 RawType::Int32, RawType::UInt32, RawType::Float32, RawType::Int16};
        for (int i = 0; i < 8; ++i)
            r.push_back(row(types[i], 0x30 + i, 250, 6 + i,
                            CanObject{0x6040, static_cast<std::uint8_t>(i)}));
        return r;
    }();
    return kRows;
}

struct Setup
{
    std::unique_ptr<ProtocolAdapter> adapter;
    int module = 1;
};

Setup makeAdapter(std::uint8_t pick)
{
    switch (pick % 7) {
    case 0: return {std::make_unique<NodeImageAdapter>(hcs::Family::Dma), 1};
    case 1: return {std::make_unique<NodeImageAdapter>(hcs::Family::Opat), 0};
    case 2: {
        auto hart = std::make_unique<HartAdapter>();
        hart->setLongAddress(0, hart::longAddress(58352, 2412345)); // reads need the unique id
        return {std::move(hart), 0};
    }
    case 3: return {std::make_unique<CanopenAdapter>(CanopenProfile::Hcs), 5};
    case 4: return {std::make_unique<CanopenAdapter>(CanopenProfile::Dsp408), 5};
    case 5: return {std::make_unique<ModbusRtuAdapter>(hcs::Family::Dma), 1};
    default: return {std::make_unique<ModbusTcpAdapter>(hcs::Family::Opat), 1};
    }
}

Transaction makeTransaction(const ProtocolAdapter &adapter, int module, std::uint8_t kind)
{
    std::vector<const ParamMeta *> all;
    for (const ParamMeta &p : rows())
        all.push_back(&p);
    switch (kind % 4) {
    case 0: return adapter.planIdentify(module).front();
    case 1: {
        auto plan = adapter.planRead(module, all);
        return plan.empty() ? adapter.planIdentify(module).front() : plan.front();
    }
    case 2: return adapter.planWrite(module, rows()[kind % 8], 7.0);
    default: return Transaction{TransactionKind::Raw, module, {}, {}, 0, {0x01, 0x03}, true};
    }
}

void check(const std::optional<Reply> &reply, const Transaction &t, std::size_t fed)
{
    if (!reply)
        return;
    require(reply->frame.size() <= fed);
    if (reply->status != ReplyStatus::Ok)
        return;
    if (t.kind == TransactionKind::Read)
        require(reply->values.size() == t.rows.size());
    if (t.kind == TransactionKind::Write)
        require(reply->values.size() == 1);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 2)
        return 0;
    const std::uint8_t pick = data[0];
    const std::size_t chunk = (data[1] & 0x3Fu) == 0 ? size : (data[1] & 0x3Fu) + 1u;
    const std::span<const std::uint8_t> stream(data + 2, size - 2);

    Setup setup = makeAdapter(pick & 0x07);
    if ((data[1] & 0x80u) != 0)
        setup = {std::make_unique<Dsp408Adapter>((data[1] & 0x40u) != 0
                                                     ? LinkProtocol::Dsp408Gateway
                                                     : LinkProtocol::Dsp408Image),
                 1};
    ProtocolAdapter &adapter = *setup.adapter;
    const Transaction t =
        makeTransaction(adapter, setup.module, static_cast<std::uint8_t>(pick >> 3));
    const bool retry = (pick & 0x20) != 0;
    const bool quiet = (pick & 0x40) != 0;
    require(!adapter.encode(t).empty() || t.kind == TransactionKind::Raw);
    require(adapter.expectedReplyBytes(t) > 0);

    std::size_t at = 0;
    std::size_t fed = 0;
    while (at < stream.size()) {
        const std::size_t n = std::min(chunk, stream.size() - at);
        if (retry && at <= stream.size() / 2 && at + n > stream.size() / 2) {
            adapter.resetFraming(); // the session's timeout, then a fresh attempt
            (void)adapter.encode(t);
        }
        fed += n;
        check(adapter.feed(stream.subspan(at, n), t), t, fed);
        if (quiet)
            adapter.lineQuiet(&t);
        at += n;
    }
    return 0;
}
