#include "sim_endpoint.h"

#include "dict/dictionary_loader.h"
#include "sim/hart_device.h"
#include "sim/hart_server.h"
#include "sim/hcs_node.h"
#include "sim/modbus_rtu_server.h"
#include "sim/modbus_tcp_server.h"
#include "sim/node_config.h"
#include "sim/node_image_server.h"
#include "transports/sim_link.h"

namespace vt::model {

dev::Result<SimSpec, QString> parseSimSpec(const QString &text)
{
    SimSpec spec;
    const QStringList parts = text.split(QLatin1Char(':'));
    if (parts.size() > 2 || parts.front().isEmpty())
        return SimEndpoint::tr("expected FAMILY or FAMILY:MODULES, got '%1'").arg(text);
    spec.family = parts.front().toStdString();
    if (parts.size() == 2) {
        bool ok = false;
        const int n = parts[1].toInt(&ok);
        if (!ok || n < 1 || n > 32)
            return SimEndpoint::tr("module count '%1' is not 1..32").arg(parts[1]);
        spec.modules = static_cast<std::size_t>(n);
    }
    return spec;
}

SimEndpoint::SimEndpoint(SimSpec spec, QObject *parent) : QObject(parent), m_spec(std::move(spec))
{
    m_timer.setInterval(1);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SimEndpoint::tick);
}

SimEndpoint::~SimEndpoint()
{
    if (m_hart)
        m_clock.detach(*m_hart);
}

int SimEndpoint::moduleAddress(std::size_t index) const
{
    if (m_hart)
        return 0; // HART poll address 0 (point-to-point)
    if (!m_node || index >= m_node->moduleCount())
        return -1;
    if (m_spec.protocol == "modbus-rtu" && m_node->moduleCount() == 1)
        return 1; // point-to-point line: unit 1 reaches the one module
    return m_node->module(index).address();
}

std::size_t SimEndpoint::moduleCount() const
{
    if (m_hart)
        return 1;
    return m_node ? m_node->moduleCount() : 0;
}

void SimEndpoint::setRunning(bool running)
{
    if (running == m_timer.isActive())
        return;
    if (running) {
        m_offsetUs = m_clock.nowUs();
        m_elapsed.start();
        m_timer.start();
    } else {
        m_timer.stop();
    }
}

void SimEndpoint::tick()
{
    m_clock.advanceTo(m_offsetUs + m_elapsed.nsecsElapsed() / 1000);
    if (m_link)
        m_link->pump();
}

dev::Result<std::unique_ptr<link::SimLink>, QString> makeSimLink(const SimSpec &specIn,
                                                                 const dev::DictionarySet *set)
{
    using namespace dev::sim;
    SimSpec spec = specIn;
    if (!set) {
        const auto &builtin = dev::builtinDictionaries();
        if (!builtin.ok())
            return SimEndpoint::tr("the built-in dictionaries do not load");
        set = &*builtin;
    }
    const dev::Dictionary *dict = set->find(spec.family);
    if (!dict)
        return SimEndpoint::tr("unknown device family '%1'")
            .arg(QString::fromStdString(spec.family));

    auto endpoint = std::unique_ptr<SimEndpoint>(new SimEndpoint(spec, nullptr));
    std::shared_ptr<dev::ByteServer> server;
    if (dict->protocol == dev::DeviceProtocol::Hart) {
        if (spec.protocol.empty())
            spec.protocol = "hart";
        if (spec.protocol != "hart")
            return SimEndpoint::tr("%1 speaks HART only").arg(QString::fromStdString(spec.family));
        endpoint->m_hart = std::make_unique<HartDevice>(*dict);
        endpoint->m_hartServer = std::make_shared<HartServer>(*endpoint->m_hart);
        endpoint->m_clock.attach(*endpoint->m_hart);
        server = endpoint->m_hartServer;
    } else if (dict->protocol == dev::DeviceProtocol::Hcs) {
        // One module: a point-to-point Modbus RTU line. A node: Modbus TCP to its gateway, where
        // every module is a unit — on an RTU line the OPAT master (SADR 0) would be unit 0, the
        // broadcast address no device answers.
        if (spec.protocol.empty())
            spec.protocol = spec.modules == 1 ? "modbus-rtu" : "modbus-tcp";
        NodeConfig config;
        config.family = spec.family;
        config.modules = spec.modules;
        config.mode = spec.mode;
        auto node = makeNode(endpoint->m_clock, *set, config);
        if (!node.ok())
            return QString::fromStdString(node.error());
        endpoint->m_node = std::move(node).value();
        HcsNode &n = *endpoint->m_node;
        if (spec.protocol == "modbus-rtu") {
            ModbusUnitOptions units;
            if (n.moduleCount() == 1)
                units.pointToPointUnit = 1;
            server = std::make_shared<ModbusRtuServer>(endpoint->m_clock, n, units);
        } else if (spec.protocol == "modbus-tcp") {
            server = std::make_shared<ModbusTcpServer>(endpoint->m_clock, n);
        } else if (spec.protocol == "node-image") {
            server = std::make_shared<NodeImageServer>(endpoint->m_clock, n);
        } else {
            return SimEndpoint::tr("the simulator does not serve %1 over '%2'")
                .arg(QString::fromStdString(spec.family), QString::fromStdString(spec.protocol));
        }
    } else {
        return SimEndpoint::tr(
                   "%1 cannot be simulated over a PC link yet (DSP-408 needs PROFIBUS or CANopen)")
            .arg(QString::fromStdString(spec.family));
    }
    endpoint->m_spec = spec;

    auto link = std::make_unique<link::SimLink>(server, QString::fromStdString(spec.family));
    if (spec.baudRate > 0)
        link->setWireTiming(spec.baudRate, spec.bitsPerCharacter);
    endpoint->m_link = link.get();
    endpoint->setParent(link.get());
    endpoint.release()->setRunning(true);
    return link;
}

SimEndpoint *simEndpointOf(const link::SimLink &link)
{
    return link.findChild<SimEndpoint *>(QString(), Qt::FindDirectChildrenOnly);
}

} // namespace vt::model
