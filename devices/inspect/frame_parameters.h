// Which parameters a request frame addresses, for the inspector's linked navigation (frame →
// parameter, parameter → its last frames). Reads the request the way the device would.
#pragma once

#include "core/direction.h"
#include "core/link_protocol.h"
#include "dict/dictionary.h"
#include "dsp408/gateway.h"
#include "dsp408/options.h"
#include "hcs/types.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vt::dev::inspect {

struct CarriedParameters
{
    std::vector<std::uint16_t> ids; // HCS parameter IDs (gateway CMD 3/6, Modbus FC 3/6)
    struct IndPnu
    {
        int ind = 0, pnu = 0, instance = 0;
    };
    std::optional<IndPnu> indPnu;       // HART 128..133
    std::optional<CanObject> canObject; // CANopen SDO

    bool empty() const { return ids.empty() && !indPnu && !canObject; }
};

// How the link lays out the ED1's image (ARCHITECTURE.md "Byte order"): the PKW IND byte and the
// gateway's register byte order, as the connection was configured.
struct ImageLayout
{
    dsp408::Options dsp408;
    dsp408::RegisterByteOrder registerBytes = dsp408::RegisterByteOrder::FirstByteHigh;
};

// `link`: the protocol that carried the frame (a CANopen frame as a 16-byte SocketCAN image or
// bare SDO data). Only requests name parameters (a CMD 3 answer does not carry its IDs);
// anything that does not decode carries nothing.
CarriedParameters carriedBy(LinkProtocol link, std::span<const std::uint8_t> bytes,
                            Direction direction, hcs::Family family = hcs::Family::Dma,
                            const ImageLayout &layout = {});

// The dictionary rows behind them (unknown ones left out), in frame order.
std::vector<const ParamMeta *> rowsOf(const CarriedParameters &carried,
                                      const Dictionary &dictionary);

} // namespace vt::dev::inspect
