// Connection: everything between "connect to this device" and a ready DeviceAccess — the link
// (serial, TCP, CAN, HART modem, in-process simulator; behind a FaultLink when faults are asked
// for), the protocol adapter, the session with options fitting the wire, and the module addresses
// to talk to. The GUI's connect dialog and valvetune-cli build the same ConnectionSpec.
// Owner: whoever connects (GUI, CLI, tests); GUI thread (the link's), used only from there.
#pragma once

#include "core/link_protocol.h"
#include "core/result.h"
#include "dict/identify.h"
#include "model/session/device_access.h"
#include "model/session/session.h"
#include "model/session/session_options.h"
#include "model/session/sim_endpoint.h"
#include "transports/fault_spec.h"
#include "transports/link.h"
#include "transports/serial_settings.h"

#include <QObject>
#include <QString>
#include <chrono>
#include <memory>
#include <optional>
#include <vector>

namespace vt::link {
class FaultLink;
}

namespace vt::model {

enum class ConnectionKind { Sim, Serial, Tcp, Can, Hart };

// What to connect to. A plain value; any thread.
struct ConnectionSpec
{
    ConnectionKind kind = ConnectionKind::Sim;
    SimSpec sim; // Sim: family, modules, protocol (nullopt = the family's default)
    // Serial (Modbus RTU, HCS default 19200 8E1) and Hart (1200 8O1): port and line settings.
    link::SerialSettings serial;
    QString host; // Tcp
    quint16 port = 502;
    // Tcp: Modbus TCP, the node image, or the ED1's image raw / behind a gateway.
    dev::LinkProtocol tcpProtocol = dev::LinkProtocol::ModbusTcp;
    // dsp408-image / dsp408-gateway (Tcp, or Sim: copied to the simulator): image layout and the
    // gateway's registers. The gateway's Modbus unit is `unit` (default 1).
    dev::access::Dsp408LinkOptions dsp408;
    QString canInterface;   // Can: "can0", "vcan0"
    int canNode = 1;        // Can: CANopen node id 1..127
    bool canDsp408 = false; // Can: a Wandfluh ED1 (CiA 408 objects) instead of an HCS module
    // The one module address to talk to (Modbus unit / node SADR, HART poll address, CAN node);
    // unset: 1 for Modbus point-to-point, 0 for HART, canNode for CAN, every module of a sim.
    std::optional<int> unit;
    std::optional<link::FaultSpec> fault; // wrap the link in a FaultLink
    // Disambiguates HCS versions (identify.h) and picks the exception table; the sim knows it.
    dev::HcsProduct product = dev::HcsProduct::Unknown;
    std::optional<std::chrono::milliseconds> turnaround; // override SessionOptions::turnaround
    std::optional<int> retries;                          // override SessionOptions::retries
};

const char *connectionKindKey(ConnectionKind kind); // "sim", "serial", "tcp", "can", "hart"

// The session options fitting the spec's wire: serial baud and bits per character for the
// timeout, a device turnaround (HART slower), the spec's overrides.
SessionOptions sessionOptionsFor(const ConnectionSpec &spec);

class Connection : public QObject
{
    Q_OBJECT
public:
    // Builds link, adapter, session and access (nothing is opened yet). `dictionaries` must
    // outlive the connection. `link`: use this link instead of building one from the spec (a
    // CanLink on an adopted fd in tests); it is still wrapped in a FaultLink when asked for.
    static dev::Result<std::unique_ptr<Connection>, QString>
    create(ConnectionSpec spec, const dev::DictionarySet &dictionaries,
           std::unique_ptr<link::Link> link = {});
    ~Connection() override;

    // Opens the link: opened() or failed() follows from the event loop.
    void open();
    void close();
    bool isOpen() const;

    const ConnectionSpec &spec() const { return m_spec; }
    link::Link &link() const { return *m_link; }
    Session &session() const { return *m_session; }
    DeviceAccess &access() const { return *m_access; }
    SimEndpoint *simEndpoint() const { return m_sim; }     // Sim only
    link::FaultLink *faultLink() const { return m_fault; } // with a fault spec only
    // The protocol the session speaks on the link.
    dev::LinkProtocol protocol() const;
    // Its key, for status lines and logs: "modbus-rtu", "modbus-tcp", "node-image", "hart",
    // "canopen".
    QString protocolKey() const;

    // The module addresses to talk to (see ConnectionSpec::unit), in node order.
    std::vector<int> moduleAddresses() const;
    // The addresses a scan tries: Modbus RTU 1..32 (0 is broadcast), Modbus TCP and node image
    // 0..32 (no broadcast: 0 is the OPAT master), HART poll addresses 0..15, CANopen nodes
    // 1..127; a simulator: its modules.
    std::vector<int> scanAddresses() const;

    // For status lines and logs, untranslated like Link::description(): "sim dma-pn-v51 ×3,
    // modbus-tcp, modules 1, 2, 3", "serial /dev/ttyUSB0 19200 8E1, modbus-rtu, module 1 [fault
    // cut=5,seed=1]".
    QString describe() const;
    // The same facts for the UI, in its language: "simulated dma-pn-v51 ×3, modbus-tcp, modules
    // 1, 2, 3" / "simuliert dma-pn-v51 ×3, modbus-tcp, Module 1, 2, 3" (link descriptions, family
    // and protocol keys are names and stay as they are).
    QString displayText() const;

signals:
    void opened();
    // Opening failed (port missing, connection refused …).
    void failed(const QString &reason);
    // The link failed or closed after it was open (cable pulled, fault cut, peer closed).
    void lost(const QString &reason);

private:
    explicit Connection(ConnectionSpec spec, QObject *parent = nullptr);
    void onLinkFailed(const QString &reason);
    void onLinkState(link::LinkState state);

    ConnectionSpec m_spec;
    std::unique_ptr<link::Link> m_link; // the FaultLink when there is one (it owns the inner link)
    link::FaultLink *m_fault = nullptr;
    SimEndpoint *m_sim = nullptr;
    std::unique_ptr<Session> m_session;
    std::unique_ptr<DeviceAccess> m_access;
    bool m_wasOpen = false;
    bool m_closing = false;
};

} // namespace vt::model
