// Builds the protocol adapter a connection needs. Pure function; any thread. The caller owns the
// adapter (it goes to one Session).
#pragma once

#include <memory>
#include <string>

namespace vt::dev::access {
class ProtocolAdapter;
}

namespace vt::model {

enum class AdapterKind { ModbusRtu, ModbusTcp, NodeImage, Hart, CanopenHcs, CanopenDsp408 };

// `hcsFamily`: a dictionary family or product prefix ("opat", "dma-pn-v51", "dma"); it picks the
// HCS exception table (OPAT and DMA codes differ). Ignored by HART and CANopen DSP-408.
std::unique_ptr<dev::access::ProtocolAdapter> makeAdapter(AdapterKind kind,
                                                          const std::string &hcsFamily);

// "modbus-rtu", "modbus-tcp", "node-image", "hart", "canopen" (ProtocolAdapter::protocolKey()).
const char *adapterKey(AdapterKind kind);

} // namespace vt::model
