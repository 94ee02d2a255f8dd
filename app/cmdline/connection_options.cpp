#include "connection_options.h"

#include "arg_parse.h"
#include "dsp408_options.h"
#include "transports/fault_spec.h"
#include "transports/tcp_link.h"

#include <utility>
#include <vector>

namespace vt::cmdline {

const char kConnectionSynopsis[] =
    "connection (one of):\n"
    "  --sim FAMILY[:MODULES] [--protocol modbus-rtu|modbus-tcp|node-image|dsp408-image|"
    "dsp408-gateway]\n"
    "       [--factory] (the simulator starts from the dictionary defaults, not commissioned)\n"
    "  --port PATH [--baud B] [--parity none|even|odd] [--stop 1|2]\n"
    "       [--no-silent-interval] [--frame-end silence|crc] (Modbus RTU line timing)\n"
    "  --tcp HOST:PORT [--protocol modbus-tcp|node-image|dsp408-image|dsp408-gateway]\n"
    "  --can IFACE --node N\n"
    "  --hart PATH\n"
    "and: [--unit ADDRESS] [--fault SPEC] [--product opat|dma-pn|dma-pb|ed1] [--turnaround MS]\n"
    "ED1 image (dsp408-image, dsp408-gateway; --unit = the gateway's unit, default 1):\n"
    "  [--out-register N] [--in-register N] [--in-function 3|4]\n"
    "  [--register-bytes high-first|low-first] [--pzd-words high-first|low-first] [--ind-byte 2|3]";

namespace {

using Error = std::string;

std::string text(const QString &s)
{
    return s.toStdString();
}

// Every option takeConnectionOptions() takes, with a value each.
const char *const kOptions[] = {"--sim",  "--port",   "--tcp",     "--can",        "--hart",
                                "--baud", "--parity", "--stop",    "--protocol",   "--node",
                                "--unit", "--fault",  "--product", "--turnaround", "--frame-end"};

} // namespace

bool hasConnectionOption(const QStringList &args)
{
    for (const char *option : kOptions)
        if (args.contains(QLatin1String(option)))
            return true;
    for (const char *option : kDsp408Options)
        if (args.contains(QLatin1String(option)))
            return true;
    return false;
}

dev::Result<model::ConnectionSpec, std::string> takeConnectionOptions(QStringList &args)
{
    bool missing = false;
    const auto sim = takeOption(args, "--sim", &missing);
    const auto port = takeOption(args, "--port", &missing);
    const auto tcp = takeOption(args, "--tcp", &missing);
    const auto can = takeOption(args, "--can", &missing);
    const auto hart = takeOption(args, "--hart", &missing);
    const auto baud = takeOption(args, "--baud", &missing);
    const auto parity = takeOption(args, "--parity", &missing);
    const auto stop = takeOption(args, "--stop", &missing);
    const auto protocol = takeOption(args, "--protocol", &missing);
    const auto node = takeOption(args, "--node", &missing);
    const auto unit = takeOption(args, "--unit", &missing);
    const auto fault = takeOption(args, "--fault", &missing);
    const auto product = takeOption(args, "--product", &missing);
    const auto turnaround = takeOption(args, "--turnaround", &missing);
    const auto frameEnd = takeOption(args, "--frame-end", &missing);
    const bool factory = takeFlag(args, "--factory");
    const bool noSilentInterval = takeFlag(args, "--no-silent-interval");
    std::vector<std::pair<QString, QString>> dsp408;
    for (const char *option : kDsp408Options)
        if (const auto value = takeOption(args, option, &missing))
            dsp408.emplace_back(QLatin1String(option), *value);
    if (missing)
        return Error("an option is missing its value");

    model::ConnectionSpec spec;
    const int kinds = int(sim.has_value()) + int(port.has_value()) + int(tcp.has_value()) +
                      int(can.has_value()) + int(hart.has_value());
    if (kinds == 0)
        return Error("no connection given: --sim, --port, --tcp, --can or --hart");
    if (kinds > 1)
        return Error("give one connection: --sim, --port, --tcp, --can or --hart");
    if ((baud || parity || stop) && !port)
        return Error("--baud, --parity and --stop go with --port");
    if ((frameEnd || noSilentInterval) && !port)
        return Error("--no-silent-interval and --frame-end go with --port");
    if (node && !can)
        return Error("--node goes with --can");
    if (protocol && !sim && !tcp)
        return Error("--protocol goes with --sim or --tcp");
    if (factory && !sim)
        return Error("--factory goes with --sim");

    if (sim) {
        spec.kind = model::ConnectionKind::Sim;
        auto parsed = model::parseSimSpec(*sim);
        if (!parsed.ok())
            return Error("--sim: " + text(parsed.error()));
        spec.sim = *parsed;
        spec.sim.factory = factory;
        if (protocol) {
            const auto p = dev::fromKey<dev::LinkProtocol>(protocol->toStdString());
            if (!p || *p == dev::LinkProtocol::Hart || *p == dev::LinkProtocol::Canopen)
                return Error("--protocol with --sim takes modbus-rtu, modbus-tcp, node-image, "
                             "dsp408-image or dsp408-gateway");
            spec.sim.protocol = p;
        }
    } else if (port) {
        spec.kind = model::ConnectionKind::Serial;
        spec.serial = link::SerialSettings::hcsDefault(*port);
        if (baud) {
            const auto b = parseInteger(*baud, 50, 4'000'000);
            if (!b)
                return Error("--baud takes a rate such as 19200 or 115200");
            spec.serial.baudRate = static_cast<int>(*b);
        }
        if (parity) {
            if (*parity == "none")
                spec.serial.parity = link::Parity::None;
            else if (*parity == "even")
                spec.serial.parity = link::Parity::Even;
            else if (*parity == "odd")
                spec.serial.parity = link::Parity::Odd;
            else
                return Error("--parity takes none, even or odd");
        }
        if (stop) {
            if (*stop != "1" && *stop != "2")
                return Error("--stop takes 1 or 2");
            spec.serial.stopBits = *stop == "2" ? link::StopBits::Two : link::StopBits::One;
        }
        // Modbus over Serial Line §2.5.1.1: t3.5 of silence before each request, and a frame
        // ends when the line goes quiet for t3.5 (or, with crc, as soon as its CRC is complete).
        spec.serial.silentInterval = !noSilentInterval;
        if (frameEnd) {
            if (*frameEnd != "silence" && *frameEnd != "crc")
                return Error("--frame-end takes silence or crc");
            spec.serial.frameEndBySilence = *frameEnd == "silence";
        }
    } else if (tcp) {
        spec.kind = model::ConnectionKind::Tcp;
        const auto endpoint = link::TcpLink::parseEndpoint(*tcp);
        if (!endpoint)
            return Error("--tcp takes HOST:PORT, e.g. 192.168.0.10:502");
        spec.host = endpoint->host;
        spec.port = endpoint->port;
        if (protocol) {
            const auto p = dev::fromKey<dev::LinkProtocol>(protocol->toStdString());
            if (p != dev::LinkProtocol::ModbusTcp && p != dev::LinkProtocol::NodeImage &&
                p != dev::LinkProtocol::Dsp408Image && p != dev::LinkProtocol::Dsp408Gateway)
                return Error("--protocol with --tcp takes modbus-tcp, node-image, dsp408-image or "
                             "dsp408-gateway");
            spec.tcpProtocol = *p;
        }
    } else if (can) {
        spec.kind = model::ConnectionKind::Can;
        spec.canInterface = *can;
        if (!node)
            return Error("--can needs --node N (the CANopen node id, 1..127)");
        const auto n = parseInteger(*node, 1, 127);
        if (!n)
            return Error("--node takes a CANopen node id 1..127");
        spec.canNode = static_cast<int>(*n);
    } else {
        spec.kind = model::ConnectionKind::Hart;
        spec.serial = link::SerialSettings::hart(*hart);
    }

    const bool ed1Image = (tcp && dev::isDsp408Link(spec.tcpProtocol)) ||
                          (sim && spec.sim.protocol && dev::isDsp408Link(*spec.sim.protocol));
    if (!dsp408.empty() && !ed1Image)
        return Error(dsp408.front().first.toStdString() +
                     " goes with --protocol dsp408-image or dsp408-gateway");
    for (const auto &[name, value] : dsp408)
        if (auto why = applyDsp408Option(name, value, spec.dsp408))
            return Error(*why);
    if (unit) {
        const auto u = parseInteger(*unit, 0, 255);
        if (!u)
            return Error("--unit takes a module address 0..255");
        spec.unit = static_cast<int>(*u);
    }
    if (fault) {
        auto parsed = link::parseFaultSpec(*fault);
        if (!parsed.ok())
            return Error("--fault: " + text(parsed.error().text()));
        spec.fault = *parsed;
    }
    if (product) {
        if (*product == "opat")
            spec.product = dev::HcsProduct::Opat;
        else if (*product == "dma-pn")
            spec.product = dev::HcsProduct::DmaProfinet;
        else if (*product == "dma-pb")
            spec.product = dev::HcsProduct::DmaProfibus;
        else if (*product == "ed1" && can)
            spec.canDsp408 = true;
        else if (*product == "ed1" && !ed1Image)
            return Error("--product ed1 goes with --can or --protocol dsp408-image / "
                         "dsp408-gateway");
        else
            return Error("--product takes opat, dma-pn, dma-pb or ed1");
    }
    if (turnaround) {
        const auto ms = parseInteger(*turnaround, 1, 60'000);
        if (!ms)
            return Error("--turnaround takes milliseconds 1..60000");
        spec.turnaround = std::chrono::milliseconds(*ms);
    }
    return spec;
}

} // namespace vt::cmdline
