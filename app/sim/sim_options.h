// SimOptions: the command line of valvetune-sim (device, endpoint, protocol, faults) parsed and
// checked against each other, so sim_host only ever sees a combination it can serve. Usage
// errors are one line for stderr with exit code 2 (app/cli/exit_codes.h).
// A plain value; the parser needs a QCoreApplication for QCommandLineParser's help text only.
#pragma once

#include "access/dsp408_adapter.h"
#include "core/link_protocol.h"
#include "core/result.h"
#include "transports/fault_spec.h"
#include "transports/serial_settings.h"

#include <QString>
#include <QStringList>
#include <cstddef>
#include <cstdint>
#include <string>

namespace vt::simapp {

enum class Endpoint { Pty, Serial, Tcp, Can, CanFd };

struct SimOptions
{
    std::string family;      // dictionary family id: an HCS family or "wandfluh-sd7"
    int mode = 0;            // HCS: E00 of every module; 0 = the family's first mode
    std::size_t modules = 1; // HCS: modules of the node
    bool factory = false;    // HCS: dictionary defaults instead of the commissioned preset
    Endpoint endpoint = Endpoint::Pty;
    QString serialPath;                            // --serial
    QString tcpHost = QStringLiteral("127.0.0.1"); // --tcp: loopback unless told otherwise
    quint16 tcpPort = 0;                           // 0: any free port (the real one is printed)
    std::string canInterface;                      // --can: a SocketCAN interface ("can0", "vcan0")
    int canFd = -1;        // --can-fd: an open descriptor carrying struct can_frame datagrams
    std::uint8_t node = 1; // --node: CANopen node id 1..127 (SDO 0x600 + node / 0x580 + node)
    dev::LinkProtocol protocol = dev::LinkProtocol::ModbusRtu;
    int baud = 19200; // serial line (on a pty it only sets the 3.5-character gap)
    link::Parity parity = link::Parity::Even; // serial line; a pty takes any parity
    // --wire (Modbus RTU on --pty / --serial): every answer byte held for its time on the wire,
    // answers `turnaroundUs` after the request's last byte, and a request that starts less than
    // t3.5 after the line's last byte is ignored, as a strict slave does (docs/SIMULATOR.md).
    bool wire = false;
    std::int64_t turnaroundUs = 3000; // --turnaround MS
    link::FaultSpec fault;            // applied to the device's answers (FaultSpec::rx)
    std::uint32_t seed = link::FaultSpec::kDefaultSeed; // --seed, else the spec's seed
    bool verbose = false;
    // The ED1's image over TCP: layout, gateway registers (app/cmdline/dsp408_options.h) and the
    // gateway's Modbus unit (--unit, default 1).
    dev::access::Dsp408LinkOptions dsp408;
    std::uint8_t gatewayUnit = 1;

    bool isHart() const { return protocol == dev::LinkProtocol::Hart; }
    bool isCan() const { return endpoint == Endpoint::Can || endpoint == Endpoint::CanFd; }
};

// What parsing ended with when it does not run the simulator: help / version text for stdout
// (exit 0) or a one-line usage error for stderr (exit 2).
struct OptionsExit
{
    int exitCode = 0;
    std::string text;
};

// `arguments` as QCoreApplication::arguments() (program name first).
dev::Result<SimOptions, OptionsExit> parseSimOptions(const QStringList &arguments);

} // namespace vt::simapp
