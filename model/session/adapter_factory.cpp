#include "adapter_factory.h"

#include "access/canopen_adapter.h"
#include "access/hart_adapter.h"
#include "access/hcs_rows.h"
#include "access/modbus_adapter.h"
#include "access/node_image_adapter.h"

namespace vt::model {

std::unique_ptr<dev::access::ProtocolAdapter> makeAdapter(AdapterKind kind,
                                                          const std::string &hcsFamily)
{
    using namespace dev::access;
    const auto family = hcsFamilyOf(hcsFamily);
    switch (kind) {
    case AdapterKind::ModbusRtu: return std::make_unique<ModbusRtuAdapter>(family);
    case AdapterKind::ModbusTcp: return std::make_unique<ModbusTcpAdapter>(family);
    case AdapterKind::NodeImage: return std::make_unique<NodeImageAdapter>(family);
    case AdapterKind::Hart: return std::make_unique<HartAdapter>();
    case AdapterKind::CanopenHcs: return std::make_unique<CanopenAdapter>(CanopenProfile::Hcs);
    case AdapterKind::CanopenDsp408:
        return std::make_unique<CanopenAdapter>(CanopenProfile::Dsp408);
    }
    return nullptr;
}

const char *adapterKey(AdapterKind kind)
{
    switch (kind) {
    case AdapterKind::ModbusRtu: return "modbus-rtu";
    case AdapterKind::ModbusTcp: return "modbus-tcp";
    case AdapterKind::NodeImage: return "node-image";
    case AdapterKind::Hart: return "hart";
    case AdapterKind::CanopenHcs:
    case AdapterKind::CanopenDsp408: return "canopen";
    }
    return "?";
}

} // namespace vt::model
