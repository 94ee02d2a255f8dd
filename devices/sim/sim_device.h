// SimDevice: a simulated device and the front end that serves it over one link protocol — an
// HCS node behind Modbus RTU, Modbus TCP or the node image; one HCS module or the Wandfluh ED1
// behind a CANopen SDO server (ARCHITECTURE.md "CAN"); the SD7 behind HART. valvetune-sim puts
// it on a pty, serial port, TCP port or CAN socket; the in-process simulator link
// (model/session/sim_endpoint.h) talks to it directly. docs/SIMULATOR.md.
// Owner: whoever builds it; single-threaded. The clock and the dictionaries must outlive it.
#pragma once

#include "access/dsp408_adapter.h"
#include "core/byte_server.h"
#include "core/link_protocol.h"
#include "core/result.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace vt::dev {
struct Dictionary;
class DictionarySet;
} // namespace vt::dev

namespace vt::dev::sim {

class Dsp408Device;
class Dsp408GatewayImage;
class Dsp408GatewayServer;
class Dsp408Server;
class HartDevice;
class HartServer;
class HcsNode;
class ModbusRtuServer;
class ModbusTcpServer;
class NodeImageServer;
class ObjectDictionary;
class SimClock;

struct SimDeviceSpec
{
    std::string family;      // dictionary family: "opat", "dma-pn-v51", "wandfluh-sd7" …
    std::size_t modules = 1; // HCS node size
    int mode = 0;            // HCS: E00 of every module; 0: the family's first mode
    // HCS: false starts every module commissioned (sim/commissioned_preset.h); true leaves the
    // bare dictionary defaults (`--factory`).
    bool factory = false;
    std::optional<LinkProtocol> protocol; // nullopt: defaultSimProtocol
    std::uint8_t canNode = 1;             // CANopen node id (SDO 0x600 + node / 0x580 + node)
    // ED1 over its PROFIBUS image (Dsp408Image, Dsp408Gateway): image layout, gateway registers,
    // the gateway's Modbus unit.
    access::Dsp408LinkOptions dsp408;
    std::uint8_t gatewayUnit = 1;
};

// The link protocol a family is served over when none is asked for: HART for a HART device,
// the raw PROFIBUS image for a DSP-408 one (ARCHITECTURE.md "Wandfluh ED1/SD1 online"); one HCS
// module on a point-to-point Modbus RTU line, a node of several behind Modbus TCP — its gateway,
// where every module is a unit; on an RTU line the OPAT master (SADR 0) would be unit 0, the
// broadcast address no device answers.
LinkProtocol defaultSimProtocol(const Dictionary &dictionary, std::size_t modules);

enum class SimBuildErrc {
    UnknownFamily, // no such dictionary, or an abstract one
    BadNode,       // makeNode refused the module count or mode
    NotServed,     // the family is not served over the protocol
};

struct SimBuildError
{
    SimBuildErrc code = SimBuildErrc::UnknownFamily;
    std::string message; // English, one line (valvetune-sim prints it)
};

class SimDevice
{
public:
    static Result<std::unique_ptr<SimDevice>, SimBuildError>
    build(SimClock &clock, const DictionarySet &dictionaries, SimDeviceSpec spec);
    ~SimDevice();
    SimDevice(const SimDevice &) = delete;
    SimDevice &operator=(const SimDevice &) = delete;

    // The spec with the protocol filled in.
    const SimDeviceSpec &spec() const { return m_spec; }
    LinkProtocol protocol() const { return *m_spec.protocol; }
    ByteServer &server() { return *m_server; }
    HcsNode *node() const { return m_node.get(); } // HCS families
    HartDevice *hart() const { return m_hart.get(); }
    Dsp408Device *ed1() const { return m_ed1.get(); }

    std::size_t moduleCount() const;
    // The address a master uses for module `index`: the Modbus unit (1 for the only module of a
    // point-to-point RTU line), the node's SADR, the HART poll address (0), the CANopen node; -1
    // for an index out of range.
    int moduleAddress(std::size_t index) const;

    // The serial line has been quiet for 3.5 characters: the Modbus RTU de-framer ends a frame
    // (Modbus over Serial Line §2.5.1.1), the HART de-framer gives up a broken one.
    void gap();
    // A new TCP client: de-framing starts afresh (a half MBAP header is not the new client's).
    void reset();
    // Modbus TCP: one more front end on the same node, for one more client connection. A gateway
    // serves several connections at once and answers each request on the connection it came in
    // on, with that request's transaction id (Modbus Messaging on TCP/IP Implementation Guide
    // V1.0b §3.1.3, §4.2.1); each connection de-frames its own stream. The ED1's gateway
    // likewise (every connection reaches the one image). nullptr for every other protocol: a
    // line has one peer, the node image and the ED1's raw image one master (docs/SIMULATOR.md).
    std::unique_ptr<ByteServer> connectionServer();

private:
    SimDevice(SimClock &clock, SimDeviceSpec spec);
    std::optional<SimBuildError> buildHcs(const DictionarySet &dictionaries);
    std::optional<SimBuildError> buildHart(const Dictionary &dictionary);
    std::optional<SimBuildError> buildEd1(const Dictionary &dictionary);

    SimClock &m_clock;
    SimDeviceSpec m_spec;
    std::unique_ptr<HcsNode> m_node;
    std::unique_ptr<HartDevice> m_hart;
    std::unique_ptr<Dsp408Device> m_ed1;
    std::unique_ptr<ObjectDictionary> m_objects;   // CANopen: the served objects
    std::unique_ptr<Dsp408GatewayImage> m_gateway; // Dsp408Gateway: the gateway's registers
    std::unique_ptr<ByteServer> m_server;          // declared last: destroyed first
    // The concrete front end behind m_server, for gap / reset (at most one is set).
    ModbusRtuServer *m_rtu = nullptr;
    ModbusTcpServer *m_mbtcp = nullptr;
    NodeImageServer *m_image = nullptr;
    HartServer *m_hartServer = nullptr;
    Dsp408GatewayServer *m_gatewayServer = nullptr;
    Dsp408Server *m_imageServer = nullptr;
};

} // namespace vt::dev::sim
