#include "adapter_factory.h"

#include "access/canopen_adapter.h"
#include "access/hart_adapter.h"
#include "access/hcs_rows.h"
#include "access/modbus_adapter.h"
#include "access/node_image_adapter.h"

namespace vt::model {

std::unique_ptr<dev::access::ProtocolAdapter>
makeAdapter(dev::LinkProtocol protocol, const std::string &hcsFamily, dev::DeviceProtocol device,
            const dev::access::Dsp408LinkOptions &dsp408)
{
    using namespace dev::access;
    const auto family = hcsFamilyOf(hcsFamily);
    switch (protocol) {
    case dev::LinkProtocol::ModbusRtu: return std::make_unique<ModbusRtuAdapter>(family);
    case dev::LinkProtocol::ModbusTcp: return std::make_unique<ModbusTcpAdapter>(family);
    case dev::LinkProtocol::NodeImage: return std::make_unique<NodeImageAdapter>(family);
    case dev::LinkProtocol::Hart: return std::make_unique<HartAdapter>();
    case dev::LinkProtocol::Canopen:
        return std::make_unique<CanopenAdapter>(canopenProfileOf(device));
    case dev::LinkProtocol::Dsp408Image:
    case dev::LinkProtocol::Dsp408Gateway: return std::make_unique<Dsp408Adapter>(protocol, dsp408);
    }
    return nullptr;
}

} // namespace vt::model
