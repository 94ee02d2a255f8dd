#include "connection.h"

#include "access/transaction.h"
#include "core/vt_assert.h"
#include "dict/dictionary.h"
#include "modbus/rtu_timing.h"
#include "model/audit/write_audit.h"
#include "model/session/adapter_factory.h"
#include "sim/sim_device.h"
#include "transports/can_link.h"
#include "transports/fault_link.h"
#include "transports/serial_link.h"
#include "transports/sim_link.h"
#include "transports/tcp_link.h"

#include <QLocale>
#include <QStringList>

namespace vt::model {

namespace {

// HART-7: 1200 baud and a device that may take a few hundred ms to answer. The manuals name no
// figure; ours, overridable through ConnectionSpec::turnaround.
constexpr std::chrono::milliseconds kHartTurnaround{300};
// The ED1's PKW handshake takes several PROFIBUS cycles of the gateway or the PLC (ED1/SD1
// manual §4.6.1 names none); ours, overridable as above.
constexpr std::chrono::milliseconds kDsp408Turnaround{300};
constexpr int kModbusMaxUnit = 32; // HCS: E22 / DIP addresses of one RS485 line (DMA 1..32)
constexpr int kHartMaxPollAddress = 15;
constexpr int kCanMaxNode = 127;

dev::HcsProduct productOfFamily(const std::string &family)
{
    if (family.rfind("opat", 0) == 0)
        return dev::HcsProduct::Opat;
    if (family.rfind("dma-pn-", 0) == 0)
        return dev::HcsProduct::DmaProfinet;
    if (family.rfind("dma-pb-", 0) == 0)
        return dev::HcsProduct::DmaProfibus;
    return dev::HcsProduct::Unknown;
}

// The HCS exception table to use: OPAT or DMA codes.
std::string hcsFamilyHint(const ConnectionSpec &spec)
{
    if (spec.kind == ConnectionKind::Sim)
        return spec.sim.family;
    return spec.product == dev::HcsProduct::Opat ? "opat" : "dma";
}

std::vector<int> range(int first, int last)
{
    std::vector<int> out;
    for (int a = first; a <= last; ++a)
        out.push_back(a);
    return out;
}

} // namespace

const char *connectionKindKey(ConnectionKind kind)
{
    switch (kind) {
    case ConnectionKind::Sim: return "sim";
    case ConnectionKind::Serial: return "serial";
    case ConnectionKind::Tcp: return "tcp";
    case ConnectionKind::Can: return "can";
    case ConnectionKind::Hart: return "hart";
    }
    return "?";
}

SessionOptions sessionOptionsFor(const ConnectionSpec &spec)
{
    SessionOptions options;
    if (spec.kind == ConnectionKind::Serial || spec.kind == ConnectionKind::Hart) {
        options.baudRate = spec.serial.baudRate;
        options.bitsPerCharacter = spec.serial.bitsPerCharacter();
        if (spec.serial.silentInterval || spec.serial.frameEndBySilence)
            options.lineSilence = std::chrono::microseconds(
                dev::modbus::silentIntervalUs(options.baudRate, options.bitsPerCharacter));
    } else if (spec.kind == ConnectionKind::Sim && spec.sim.baudRate > 0) {
        options.baudRate = spec.sim.baudRate;
        options.bitsPerCharacter = spec.sim.bitsPerCharacter;
    }
    if (spec.kind == ConnectionKind::Hart ||
        (spec.kind == ConnectionKind::Sim && spec.sim.protocol == dev::LinkProtocol::Hart))
        options.turnaround = kHartTurnaround;
    if ((spec.kind == ConnectionKind::Tcp && dev::isDsp408Link(spec.tcpProtocol)) ||
        (spec.kind == ConnectionKind::Sim && spec.sim.protocol &&
         dev::isDsp408Link(*spec.sim.protocol)))
        options.turnaround = kDsp408Turnaround;
    if (spec.turnaround)
        options.turnaround = *spec.turnaround;
    if (spec.retries)
        options.retries = *spec.retries;
    return options;
}

Connection::Connection(ConnectionSpec spec, QObject *parent)
    : QObject(parent), m_spec(std::move(spec))
{
}

Connection::~Connection()
{
    // The session and the access refer to the link: they go first. The session before the
    // access: the completions its end runs may still read or write through the access (what
    // they submit then ends cancelled as well, session.h).
    m_session.reset();
    m_access.reset();
    if (m_link) {
        m_closing = true;
        m_link->disconnect(this);
    }
}

dev::Result<std::unique_ptr<Connection>, QString>
Connection::create(ConnectionSpec spec, const dev::DictionarySet &dictionaries,
                   std::unique_ptr<link::Link> link)
{
    dev::LinkProtocol protocol = dev::LinkProtocol::ModbusRtu;
    dev::DeviceProtocol device = dev::DeviceProtocol::Hcs;
    SimEndpoint *sim = nullptr;
    switch (spec.kind) {
    case ConnectionKind::Sim: {
        // The simulator's default protocol for the family (an unknown family: makeSimLink says
        // so), also when the caller brings its own link to the simulator.
        const dev::Dictionary *dict = dictionaries.find(spec.sim.family);
        if (dict && !spec.sim.protocol)
            spec.sim.protocol = dev::sim::defaultSimProtocol(*dict, spec.sim.modules);
        if (dict)
            device = dict->protocol;
        spec.sim.dsp408 = spec.dsp408;
        if (!link) {
            auto made = makeSimLink(spec.sim, &dictionaries);
            if (!made.ok())
                return made.error();
            sim = simEndpointOf(**made);
            spec.sim = sim->spec(); // the protocol the simulator chose
            link = std::move(made).value();
        } else if (auto *simLink = qobject_cast<link::SimLink *>(link.get())) {
            sim = simEndpointOf(*simLink);
        }
        if (spec.product == dev::HcsProduct::Unknown)
            spec.product = productOfFamily(spec.sim.family);
        protocol = spec.sim.protocol.value_or(dev::LinkProtocol::ModbusRtu);
        break;
    }
    case ConnectionKind::Serial:
        if (const auto problem = spec.serial.problem())
            return *problem;
        if (!link)
            link = std::make_unique<link::SerialLink>(spec.serial);
        protocol = dev::LinkProtocol::ModbusRtu;
        break;
    case ConnectionKind::Hart:
        if (const auto problem = spec.serial.problem())
            return *problem;
        if (!link)
            link = std::make_unique<link::SerialLink>(spec.serial);
        protocol = dev::LinkProtocol::Hart;
        break;
    case ConnectionKind::Tcp:
        if (spec.host.isEmpty() || spec.port == 0)
            return tr("a TCP connection needs a host and a port");
        if (!link)
            link = std::make_unique<link::TcpLink>(spec.host, spec.port);
        protocol = spec.tcpProtocol;
        if (dev::isDsp408Link(protocol))
            device = dev::DeviceProtocol::Dsp408;
        break;
    case ConnectionKind::Can:
        if (spec.canNode < 1 || spec.canNode > kCanMaxNode)
            return tr("CANopen node %1 is not 1..127").arg(spec.canNode);
        if (!link) {
            if (spec.canInterface.isEmpty())
                return tr("a CAN connection needs an interface (can0, vcan0 …)");
            link = std::make_unique<link::CanLink>(spec.canInterface);
        }
        protocol = dev::LinkProtocol::Canopen;
        device = spec.canDsp408 ? dev::DeviceProtocol::Dsp408 : dev::DeviceProtocol::Hcs;
        break;
    }
    if (spec.unit && (*spec.unit < 0 || *spec.unit > 255))
        return tr("module address %1 is not 0..255").arg(*spec.unit);

    auto made = makeAdapter(protocol, hcsFamilyHint(spec), device, spec.dsp408);
    VT_ASSERT(made, return QStringLiteral("no protocol adapter for %1") // every protocol has one
                        .arg(QString::fromLatin1(dev::key(protocol))));

    auto c = std::unique_ptr<Connection>(new Connection(std::move(spec)));
    c->m_sim = sim;
    if (c->m_spec.fault && !c->m_spec.fault->isNull()) {
        auto fault = std::make_unique<link::FaultLink>(std::move(link), *c->m_spec.fault);
        c->m_fault = fault.get();
        c->m_link = std::move(fault);
    } else {
        c->m_link = std::move(link);
    }
    c->m_session =
        std::make_unique<Session>(c->m_link.get(), std::move(made), sessionOptionsFor(c->m_spec));
    c->m_access = std::make_unique<DeviceAccess>(*c->m_session, dictionaries, c->m_spec.product);
    connect(c->m_link.get(), &link::Link::failed, c.get(), &Connection::onLinkFailed);
    connect(c->m_link.get(), &link::Link::stateChanged, c.get(), &Connection::onLinkState);
    return c;
}

void Connection::open()
{
    m_closing = false;
    m_link->open();
}

void Connection::close()
{
    m_closing = true;
    m_link->close();
}

bool Connection::isOpen() const
{
    return m_link->state() == link::LinkState::Open;
}

dev::LinkProtocol Connection::protocol() const
{
    return m_session->adapter().protocol();
}

QString Connection::protocolKey() const
{
    return QString::fromLatin1(dev::key(protocol()));
}

void Connection::onLinkFailed(const QString &reason)
{
    if (m_wasOpen) {
        m_wasOpen = false;
        auditConnection({});
        emit lost(reason);
    } else {
        emit failed(reason);
    }
}

void Connection::onLinkState(link::LinkState state)
{
    if (state == link::LinkState::Open) {
        m_wasOpen = true;
        auditConnection(describe()); // the session log names what the writes went to
        emit opened();
    } else if (state == link::LinkState::Closed && m_wasOpen) {
        m_wasOpen = false;
        auditConnection({});
        if (!m_closing)
            emit lost(tr("the link closed"));
    }
}

std::vector<int> Connection::moduleAddresses() const
{
    if (m_sim) {
        std::vector<int> all;
        for (std::size_t i = 0; i < m_sim->moduleCount(); ++i)
            all.push_back(m_sim->moduleAddress(i));
        if (!m_spec.unit)
            return all;
        return {*m_spec.unit};
    }
    if (m_spec.unit)
        return {*m_spec.unit};
    switch (m_spec.kind) {
    case ConnectionKind::Hart: return {0};
    case ConnectionKind::Can: return {m_spec.canNode};
    case ConnectionKind::Sim:
    case ConnectionKind::Serial:
    case ConnectionKind::Tcp: break;
    }
    return {1};
}

std::vector<int> Connection::scanAddresses() const
{
    if (m_sim) {
        std::vector<int> all;
        for (std::size_t i = 0; i < m_sim->moduleCount(); ++i)
            all.push_back(m_sim->moduleAddress(i));
        return all;
    }
    switch (protocol()) {
    case dev::LinkProtocol::Hart: return range(0, kHartMaxPollAddress);
    case dev::LinkProtocol::Canopen: return range(1, kCanMaxNode);
    case dev::LinkProtocol::ModbusRtu: return range(1, kModbusMaxUnit);
    case dev::LinkProtocol::ModbusTcp:
    case dev::LinkProtocol::NodeImage: break;
    case dev::LinkProtocol::Dsp408Image:
    case dev::LinkProtocol::Dsp408Gateway:
        // One slave behind the image; the gateway's unit is configured, not searched for.
        return moduleAddresses();
    }
    return range(0, kModbusMaxUnit);
}

QString Connection::describe() const
{
    QStringList addresses;
    for (int a : moduleAddresses())
        addresses << QString::number(a);
    QString where;
    if (m_sim)
        where = QStringLiteral("sim %1 ×%2")
                    .arg(QString::fromStdString(m_spec.sim.family))
                    .arg(m_sim->moduleCount());
    else
        where = (m_fault ? m_fault->inner() : *m_link).description();
    QString text =
        QStringLiteral("%1, %2, %3 %4")
            .arg(where, protocolKey(),
                 addresses.size() == 1 ? QStringLiteral("module") : QStringLiteral("modules"),
                 addresses.join(QStringLiteral(", ")));
    if (m_fault)
        text += QStringLiteral(" [fault %1]").arg(m_spec.fault->toString());
    return text;
}

QString Connection::displayText() const
{
    QStringList addresses;
    const QLocale locale;
    for (int a : moduleAddresses())
        addresses << locale.toString(a);
    const QString where =
        m_sim ? tr("simulated %1 ×%2")
                    .arg(QString::fromStdString(m_spec.sim.family))
                    .arg(locale.toString(static_cast<qulonglong>(m_sim->moduleCount())))
              : (m_fault ? m_fault->inner() : *m_link).description();
    QString text = addresses.isEmpty() ? tr("%1, %2").arg(where, protocolKey())
                   : addresses.size() == 1
                       ? tr("%1, %2, module %3").arg(where, protocolKey(), addresses.front())
                       : tr("%1, %2, modules %3")
                             .arg(where, protocolKey(), addresses.join(QStringLiteral(", ")));
    if (m_fault)
        text = tr("%1 [fault %2]").arg(text, m_spec.fault->toString());
    return text;
}

} // namespace vt::model
