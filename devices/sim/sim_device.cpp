#include "sim/sim_device.h"

#include "dict/dictionary.h"
#include "sim/canopen_dsp408_objects.h"
#include "sim/canopen_sdo_server.h"
#include "sim/commissioned_preset.h"
#include "sim/dsp408_device.h"
#include "sim/dsp408_gateway_server.h"
#include "sim/dsp408_server.h"
#include "sim/hart_device.h"
#include "sim/hart_server.h"
#include "sim/hcs_module_objects.h"
#include "sim/hcs_node.h"
#include "sim/modbus_rtu_server.h"
#include "sim/modbus_tcp_server.h"
#include "sim/node_config.h"
#include "sim/node_image_server.h"

namespace vt::dev::sim {
namespace {

// One module on a Modbus RTU line: a point-to-point line where unit 1 reaches it (the OPAT
// master's SADR 0 would be the broadcast address). More: a multi-drop line, unit = module address.
std::optional<std::uint8_t> pointToPointUnit(LinkProtocol protocol, std::size_t modules)
{
    if (protocol == LinkProtocol::ModbusRtu && modules == 1)
        return 1;
    return std::nullopt;
}

} // namespace

LinkProtocol defaultSimProtocol(const Dictionary &dictionary, std::size_t modules)
{
    switch (dictionary.protocol) {
    case DeviceProtocol::Hart: return LinkProtocol::Hart;
    case DeviceProtocol::Dsp408: return LinkProtocol::Dsp408Image;
    case DeviceProtocol::Hcs: break;
    }
    return modules == 1 ? LinkProtocol::ModbusRtu : LinkProtocol::ModbusTcp;
}

SimDevice::SimDevice(SimClock &clock, SimDeviceSpec spec) : m_clock(clock), m_spec(std::move(spec))
{
}

SimDevice::~SimDevice()
{
    m_server.reset(); // the front ends refer to the devices
    m_objects.reset();
    m_gateway.reset();
    if (m_hart)
        m_clock.detach(*m_hart);
    if (m_ed1)
        m_clock.detach(*m_ed1);
}

Result<std::unique_ptr<SimDevice>, SimBuildError>
SimDevice::build(SimClock &clock, const DictionarySet &dictionaries, SimDeviceSpec spec)
{
    const Dictionary *dict = dictionaries.find(spec.family);
    if (!dict)
        return SimBuildError{SimBuildErrc::UnknownFamily, "no built-in dictionary " + spec.family};
    if (!spec.protocol)
        spec.protocol = defaultSimProtocol(*dict, spec.modules);
    std::unique_ptr<SimDevice> device(new SimDevice(clock, std::move(spec)));
    std::optional<SimBuildError> error;
    switch (dict->protocol) {
    case DeviceProtocol::Hart: error = device->buildHart(*dict); break;
    case DeviceProtocol::Dsp408: error = device->buildEd1(*dict); break;
    case DeviceProtocol::Hcs: error = device->buildHcs(dictionaries); break;
    }
    if (error)
        return *error;
    return device;
}

std::optional<SimBuildError> SimDevice::buildHart(const Dictionary &dict)
{
    if (protocol() != LinkProtocol::Hart)
        return SimBuildError{SimBuildErrc::NotServed, m_spec.family + " speaks HART only"};
    m_hart = std::make_unique<HartDevice>(dict);
    m_clock.attach(*m_hart);
    auto server = std::make_unique<HartServer>(*m_hart);
    m_hartServer = server.get();
    m_server = std::move(server);
    return std::nullopt;
}

// ED1/SD1: its PROFIBUS image raw (Dsp408Server) or behind a gateway's Modbus TCP registers,
// or over CAN the CiA 408 objects of the dictionary's `canopen` fields — one Dsp408Device
// behind each.
std::optional<SimBuildError> SimDevice::buildEd1(const Dictionary &dict)
{
    const LinkProtocol p = protocol();
    if (p != LinkProtocol::Canopen && !isDsp408Link(p))
        return SimBuildError{SimBuildErrc::NotServed,
                             m_spec.family +
                                 " is served over dsp408-image, dsp408-gateway or canopen"};
    m_ed1 = std::make_unique<Dsp408Device>(dict);
    m_clock.attach(*m_ed1);
    if (p == LinkProtocol::Dsp408Image) {
        auto server = std::make_unique<Dsp408Server>(*m_ed1, m_spec.dsp408.layout);
        m_imageServer = server.get();
        m_server = std::move(server);
    } else if (p == LinkProtocol::Dsp408Gateway) {
        m_gateway = std::make_unique<Dsp408GatewayImage>(*m_ed1, m_spec.dsp408.layout,
                                                         m_spec.dsp408.gateway, m_spec.gatewayUnit);
        auto server = std::make_unique<Dsp408GatewayServer>(*m_gateway);
        m_gatewayServer = server.get();
        m_server = std::move(server);
    } else {
        m_objects = std::make_unique<Dsp408Objects>(*m_ed1);
        m_server = std::make_unique<CanopenSdoServer>(*m_objects, m_spec.canNode);
    }
    return std::nullopt;
}

std::optional<SimBuildError> SimDevice::buildHcs(const DictionarySet &dictionaries)
{
    if (protocol() == LinkProtocol::Hart)
        return SimBuildError{SimBuildErrc::NotServed, "HART is served for wandfluh-sd7 only"};
    NodeConfig config;
    config.family = m_spec.family;
    config.modules = m_spec.modules;
    config.mode = m_spec.mode;
    auto node = makeNode(m_clock, dictionaries, config);
    if (!node.ok())
        return SimBuildError{SimBuildErrc::BadNode, node.error()};
    m_node = std::move(node).value();
    if (!m_spec.factory)
        for (std::size_t i = 0; i < m_node->moduleCount(); ++i)
            applyCommissionedPreset(m_node->module(i));
    switch (protocol()) {
    case LinkProtocol::ModbusRtu: {
        ModbusUnitOptions units;
        units.pointToPointUnit = pointToPointUnit(protocol(), m_node->moduleCount());
        auto server = std::make_unique<ModbusRtuServer>(m_clock, *m_node, units);
        m_rtu = server.get();
        m_server = std::move(server);
        break;
    }
    case LinkProtocol::ModbusTcp: {
        auto server = std::make_unique<ModbusTcpServer>(m_clock, *m_node);
        m_mbtcp = server.get();
        m_server = std::move(server);
        break;
    }
    case LinkProtocol::NodeImage: {
        auto server = std::make_unique<NodeImageServer>(m_clock, *m_node);
        m_image = server.get();
        m_server = std::move(server);
        break;
    }
    case LinkProtocol::Canopen:
        // One SDO server answers for one node id: the first module, objects 0x2000 + ID, sub 0.
        m_objects = std::make_unique<HcsModuleObjects>(m_node->module(0));
        m_server = std::make_unique<CanopenSdoServer>(*m_objects, m_spec.canNode);
        break;
    case LinkProtocol::Hart: break; // refused above
    case LinkProtocol::Dsp408Image:
    case LinkProtocol::Dsp408Gateway:
        return SimBuildError{SimBuildErrc::NotServed,
                             std::string(key(protocol())) + " is the Wandfluh ED1's link"};
    }
    return std::nullopt;
}

std::size_t SimDevice::moduleCount() const
{
    if (m_node)
        return m_node->moduleCount();
    return m_server ? 1 : 0;
}

int SimDevice::moduleAddress(std::size_t index) const
{
    if (index >= moduleCount())
        return -1;
    if (m_hart)
        return 0; // HART poll address 0 (point-to-point)
    if (protocol() == LinkProtocol::Canopen)
        return m_spec.canNode;
    if (protocol() == LinkProtocol::Dsp408Gateway)
        return m_spec.gatewayUnit;
    if (protocol() == LinkProtocol::Dsp408Image)
        return 1; // one slave behind the image; the address is not on the wire
    if (const auto unit = pointToPointUnit(protocol(), moduleCount()))
        return *unit;
    return m_node->module(index).address();
}

void SimDevice::gap()
{
    if (m_rtu)
        m_rtu->silence();
    if (m_hartServer)
        m_hartServer->gap();
}

std::unique_ptr<ByteServer> SimDevice::connectionServer()
{
    if (m_gateway)
        return std::make_unique<Dsp408GatewayServer>(*m_gateway);
    if (protocol() != LinkProtocol::ModbusTcp || !m_node)
        return nullptr;
    return std::make_unique<ModbusTcpServer>(m_clock, *m_node);
}

void SimDevice::reset()
{
    if (m_mbtcp)
        m_mbtcp->reset();
    if (m_image)
        m_image->reset();
    if (m_gatewayServer)
        m_gatewayServer->reset();
    if (m_imageServer)
        m_imageServer->reset();
}

} // namespace vt::dev::sim
