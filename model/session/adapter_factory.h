// Builds the protocol adapter a connection needs. Pure function; any thread. The caller owns the
// adapter (it goes to one Session).
#pragma once

#include "access/dsp408_adapter.h"
#include "core/link_protocol.h"
#include "dict/device_protocol.h"

#include <memory>
#include <string>

namespace vt::dev::access {
class ProtocolAdapter;
}

namespace vt::model {

// `hcsFamily`: a dictionary family or product prefix ("opat", "dma-pn-v51", "dma"); it picks the
// HCS exception table (OPAT and DMA codes differ). Ignored by HART and CANopen DSP-408.
// `device`: on CANopen, which objects the module has (HCS 0x2000 + ID or CiA 408).
// `dsp408`: the ED1 image's layout and gateway registers (Dsp408Image, Dsp408Gateway).
std::unique_ptr<dev::access::ProtocolAdapter>
makeAdapter(dev::LinkProtocol protocol, const std::string &hcsFamily,
            dev::DeviceProtocol device = dev::DeviceProtocol::Hcs,
            const dev::access::Dsp408LinkOptions &dsp408 = {});

} // namespace vt::model
