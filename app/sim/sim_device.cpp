// SimDevice: see sim_device.h.
#include "sim_device.h"

#include "app/cli/exit_codes.h"
#include "app/sim/hcs_module_objects.h"
#include "dict/dictionary_loader.h"
#include "sim/canopen_dsp408_objects.h"
#include "sim/canopen_sdo_server.h"
#include "sim/dsp408_device.h"
#include "sim/hart_device.h"
#include "sim/hart_server.h"
#include "sim/hcs_node.h"
#include "sim/modbus_rtu_server.h"
#include "sim/modbus_tcp_server.h"
#include "sim/node_config.h"
#include "sim/node_image_server.h"

namespace vt::simapp {

using namespace dev::sim;

SimDevice::SimDevice(SimClock &clock) : m_clock(clock)
{
}

SimDevice::~SimDevice()
{
    m_server.reset(); // the front ends refer to the devices
    m_objects.reset();
    if (m_hart)
        m_clock.detach(*m_hart);
    if (m_ed1)
        m_clock.detach(*m_ed1);
}

dev::Result<std::unique_ptr<SimDevice>, HostError> SimDevice::build(const SimOptions &options,
                                                                    SimClock &clock)
{
    const auto &set = dev::builtinDictionaries();
    const dev::Dictionary *dict = set.ok() ? set->find(options.family) : nullptr;
    if (!dict)
        return HostError{cli::kExitDeviceError, "no built-in dictionary " + options.family};
    std::unique_ptr<SimDevice> device(new SimDevice(clock));
    std::optional<HostError> error;
    switch (dict->protocol) {
    case dev::DeviceProtocol::Hart: error = device->buildHart(*dict); break;
    case dev::DeviceProtocol::Dsp408: error = device->buildEd1(*dict, options); break;
    default: error = device->buildHcs(options); break;
    }
    if (error)
        return *error;
    return device;
}

std::optional<HostError> SimDevice::buildHart(const dev::Dictionary &dict)
{
    m_hart = std::make_unique<HartDevice>(dict);
    m_clock.attach(*m_hart);
    auto server = std::make_unique<HartServer>(*m_hart);
    m_hartServer = server.get();
    m_server = std::move(server);
    return std::nullopt;
}

// ED1/SD1 over CAN: the CiA 408 objects of the dictionary's `canopen` fields, served through
// the same Dsp408Device the PKW/PZD telegrams would reach (sim_options.cpp allows CAN only).
std::optional<HostError> SimDevice::buildEd1(const dev::Dictionary &dict, const SimOptions &options)
{
    if (options.protocol != Protocol::Canopen)
        return HostError{cli::kExitUsage, options.family + " is served over CANopen only"};
    m_ed1 = std::make_unique<Dsp408Device>(dict);
    m_clock.attach(*m_ed1);
    m_objects = std::make_unique<Dsp408Objects>(*m_ed1);
    m_server = std::make_unique<CanopenSdoServer>(*m_objects, options.node);
    return std::nullopt;
}

std::optional<HostError> SimDevice::buildHcs(const SimOptions &options)
{
    NodeConfig config;
    config.family = options.family;
    config.modules = options.modules;
    config.mode = options.mode;
    auto node = makeNode(m_clock, config);
    if (!node.ok())
        return HostError{cli::kExitUsage, node.error()};
    m_node = std::move(node).value();
    switch (options.protocol) {
    case Protocol::ModbusRtu: {
        // One module: a point-to-point line where unit 1 reaches it (the OPAT master's SADR 0
        // would be the broadcast address). More: a multi-drop line, unit = module address.
        ModbusUnitOptions units;
        if (m_node->moduleCount() == 1)
            units.pointToPointUnit = 1;
        auto server = std::make_unique<ModbusRtuServer>(m_clock, *m_node, units);
        m_rtu = server.get();
        m_server = std::move(server);
        break;
    }
    case Protocol::ModbusTcp: {
        auto server = std::make_unique<ModbusTcpServer>(m_clock, *m_node);
        m_mbtcp = server.get();
        m_server = std::move(server);
        break;
    }
    case Protocol::NodeImage: {
        auto server = std::make_unique<NodeImageServer>(m_clock, *m_node);
        m_image = server.get();
        m_server = std::move(server);
        break;
    }
    case Protocol::Canopen:
        // One module per node id (sim_options.cpp refuses more): objects 0x2000 + ID, sub 0.
        m_objects = std::make_unique<HcsModuleObjects>(m_node->module(0));
        m_server = std::make_unique<CanopenSdoServer>(*m_objects, options.node);
        break;
    case Protocol::Hart: return HostError{cli::kExitUsage, "HART is served for wandfluh-sd7 only"};
    }
    return std::nullopt;
}

void SimDevice::gap()
{
    if (m_rtu)
        m_rtu->silence();
    if (m_hartServer)
        m_hartServer->gap();
}

void SimDevice::reset()
{
    if (m_mbtcp)
        m_mbtcp->reset();
    if (m_image)
        m_image->reset();
}

} // namespace vt::simapp
