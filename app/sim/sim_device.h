// SimDevice: what valvetune-sim simulates and the front end that serves it, built from the
// options — an HCS node behind Modbus RTU, Modbus TCP or the node image; one HCS module or the
// Wandfluh ED1 behind a CANopen SDO server (ARCHITECTURE.md "CAN"); the SD7 behind HART.
// SimHost moves the bytes and drives the clock. Owner: SimHost; single-threaded (main thread).
// The SimClock must outlive it.
#pragma once

#include "app/sim/sim_options.h"
#include "core/byte_server.h"
#include "core/result.h"

#include <memory>
#include <optional>
#include <string>

namespace vt::dev {
struct Dictionary;
}

namespace vt::dev::sim {
class Dsp408Device;
class HartDevice;
class HartServer;
class HcsNode;
class ModbusRtuServer;
class ModbusTcpServer;
class NodeImageServer;
class ObjectDictionary;
class SimClock;
} // namespace vt::dev::sim

namespace vt::simapp {

struct HostError
{
    int exitCode = 1; // app/cli/exit_codes.h: 2 for a device the options cannot build, 3 for I/O
    std::string message;
};

class SimDevice
{
public:
    static dev::Result<std::unique_ptr<SimDevice>, HostError> build(const SimOptions &options,
                                                                    dev::sim::SimClock &clock);
    ~SimDevice();
    SimDevice(const SimDevice &) = delete;
    SimDevice &operator=(const SimDevice &) = delete;

    dev::ByteServer &server() { return *m_server; }
    // The serial line has been quiet for 3.5 characters: the Modbus RTU de-framer ends a frame
    // (Modbus over Serial Line §2.5.1.1), the HART de-framer gives up a broken one.
    void gap();
    // A new TCP client: de-framing starts afresh (a half MBAP header is not the new client's).
    void reset();

private:
    explicit SimDevice(dev::sim::SimClock &clock);
    std::optional<HostError> buildHcs(const SimOptions &options);
    std::optional<HostError> buildHart(const dev::Dictionary &dict);
    std::optional<HostError> buildEd1(const dev::Dictionary &dict, const SimOptions &options);

    dev::sim::SimClock &m_clock;
    std::unique_ptr<dev::sim::HcsNode> m_node;
    std::unique_ptr<dev::sim::HartDevice> m_hart;
    std::unique_ptr<dev::sim::Dsp408Device> m_ed1;
    std::unique_ptr<dev::sim::ObjectDictionary> m_objects; // CANopen: the node's objects
    std::unique_ptr<dev::ByteServer> m_server;             // declared last: destroyed first
    // The concrete front end behind m_server, for gap / reset (at most one is set).
    dev::sim::ModbusRtuServer *m_rtu = nullptr;
    dev::sim::ModbusTcpServer *m_mbtcp = nullptr;
    dev::sim::NodeImageServer *m_image = nullptr;
    dev::sim::HartServer *m_hartServer = nullptr;
};

} // namespace vt::simapp
