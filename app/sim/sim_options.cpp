// valvetune-sim's command line: QCommandLineParser for the syntax, then the combinations a
// simulator can honestly serve (which protocol on which endpoint for which device).
#include "sim_options.h"

#include "app/cli/exit_codes.h"
#include "app/cmdline/dsp408_options.h"
#include "dict/dictionary_loader.h"
#include "sim/hcs_module.h"
#include "sim/node_config.h"

#include <QCommandLineParser>
#include <QHostAddress>
#include <algorithm>
#include <net/if.h>

namespace vt::simapp {
namespace {

using dev::LinkProtocol;

// DMA Profinet manual §1.5: CMD 15 (the node image's cyclic telegram) reaches modules 1..5 only.
constexpr std::size_t kDmaImageModules = 5;
constexpr int kBauds[] = {1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400};
// CiA 301 §7.3.1: node-IDs 1..127 (0 is reserved).
constexpr uint kMaxNode = 127;

OptionsExit usage(const std::string &message)
{
    return {cli::kExitUsage, "valvetune-sim: " + message};
}

std::string joined(const std::vector<std::string> &list)
{
    std::string out;
    for (const std::string &s : list)
        out += (out.empty() ? "" : ", ") + s;
    return out;
}

// "HOST:PORT", ":PORT", "PORT" or "[v6]:PORT"; the host defaults to loopback.
bool parseTcp(const QString &text, SimOptions &o, std::string &why)
{
    QString host, port = text;
    const qsizetype colon = text.lastIndexOf(QLatin1Char(':'));
    if (colon >= 0) {
        host = text.left(colon);
        port = text.mid(colon + 1);
    }
    if (host.startsWith(QLatin1Char('[')) && host.endsWith(QLatin1Char(']')))
        host = host.mid(1, host.size() - 2);
    bool ok = false;
    const uint value = port.toUInt(&ok);
    if (!ok || value > 65535) {
        why = "--tcp '" + text.toStdString() + "': expected HOST:PORT, :PORT or PORT (0..65535)";
        return false;
    }
    o.tcpPort = static_cast<quint16>(value);
    if (host.isEmpty())
        return true;
    if (host == QLatin1String("localhost")) {
        o.tcpHost = QStringLiteral("127.0.0.1");
        return true;
    }
    if (QHostAddress(host).isNull()) {
        why = "--tcp '" + text.toStdString() + "': the host must be an IP address or localhost";
        return false;
    }
    o.tcpHost = host;
    return true;
}

// The device, protocol and endpoint fit together (the options are syntactically fine).
std::optional<std::string> checkCombination(const dev::Dictionary &dict, SimOptions &o,
                                            bool protocolGiven, bool modeGiven, bool modulesGiven)
{
    const bool tcp = o.endpoint == Endpoint::Tcp;
    const bool can = o.isCan();
    const std::string oneDevice =
        "--mode and --modules apply to HCS families; " + o.family + " is one device";
    if (dict.protocol == dev::DeviceProtocol::Dsp408) {
        // ARCHITECTURE.md "Wandfluh ED1/SD1 online": its PROFIBUS image over TCP (raw or behind
        // a gateway's Modbus TCP registers), or its CiA 408 objects on CAN.
        if (!can && !tcp)
            return o.family + " talks PROFIBUS DP (DSP-408 profile): serve its image on --tcp "
                              "(--protocol dsp408-image or dsp408-gateway) or its CiA 408 "
                              "objects on --can IFACE";
        if (!protocolGiven)
            o.protocol = can ? LinkProtocol::Canopen : LinkProtocol::Dsp408Image;
        if (can && o.protocol != LinkProtocol::Canopen)
            return o.family + " on a CAN bus is served over CANopen only (--protocol canopen)";
        if (tcp && !dev::isDsp408Link(o.protocol))
            return o.family + " over TCP is served as dsp408-image or dsp408-gateway";
        if (modeGiven || modulesGiven)
            return oneDevice;
        return std::nullopt;
    }
    if (dict.protocol == dev::DeviceProtocol::Hart) {
        if (!protocolGiven)
            o.protocol = LinkProtocol::Hart;
        if (o.protocol != LinkProtocol::Hart)
            return o.family + " speaks HART only (--protocol hart)";
        if (tcp || can)
            return "HART runs on a serial line: use --pty or --serial PATH";
        if (modeGiven || modulesGiven)
            return oneDevice;
        return std::nullopt;
    }
    if (!protocolGiven)
        o.protocol = can   ? LinkProtocol::Canopen
                     : tcp ? LinkProtocol::ModbusTcp
                           : LinkProtocol::ModbusRtu;
    if (can && o.protocol != LinkProtocol::Canopen)
        return std::string(dev::key(o.protocol)) +
               " does not run on a CAN bus; --can and --can-fd serve --protocol canopen";
    switch (o.protocol) {
    case LinkProtocol::Hart:
        return o.family + " is an HCS device; HART is the Wandfluh SD7's protocol";
    case LinkProtocol::Canopen:
        if (!can)
            return "canopen runs on a CAN bus: use --can IFACE (or --can-fd N)";
        // One SDO server answers for one node id; a node of several modules would need a
        // mapping of modules to node ids that neither manual defines.
        if (o.modules > 1)
            return "canopen serves one module per node id (--node N), not --modules " +
                   std::to_string(o.modules) + "; start one valvetune-sim per module";
        break;
    case LinkProtocol::ModbusRtu:
        if (tcp)
            return "modbus-rtu runs on --pty or --serial; over TCP use --protocol modbus-tcp";
        break;
    case LinkProtocol::ModbusTcp:
    case LinkProtocol::NodeImage:
        if (!tcp)
            return std::string(dev::key(o.protocol)) + " needs --tcp HOST:PORT";
        break;
    case LinkProtocol::Dsp408Image:
    case LinkProtocol::Dsp408Gateway:
        return std::string(dev::key(o.protocol)) +
               " carries the Wandfluh ED1 (--device "
               "wandfluh-ed1), not " +
               o.family;
    }
    if (o.protocol == LinkProtocol::NodeImage &&
        dev::sim::hcsFamilyOf(dict) == dev::hcs::Family::Dma && o.modules > kDmaImageModules)
        return "node-image: CMD 15 reaches DMA modules 1..5 only (DMA Profinet manual §1.5), not " +
               std::to_string(o.modules) + "; use --protocol modbus-tcp for more";
    return std::nullopt;
}

} // namespace

dev::Result<SimOptions, OptionsExit> parseSimOptions(const QStringList &arguments)
{
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral(
        "Serves a simulated device on a pseudo terminal, a serial port, a TCP port or a CAN bus.\n"
        "Prints 'listening on <path, host:port or can:IFACE node N>' when ready; stops on\n"
        "SIGINT / SIGTERM.\n"
        "TCP: Modbus TCP serves any number of clients at once on one node, as a gateway does;\n"
        "the node image belongs to one master, and a second client is closed at once.\n"
        "Exit codes: 0 ok, 1 internal error, 2 usage error, 3 connection error."));
    const QCommandLineOption device(
        QStringLiteral("device"),
        QStringLiteral("Dictionary family (opat, dma-pn-v51, wandfluh-sd7, ...)."),
        QStringLiteral("FAMILY"));
    const QCommandLineOption mode(
        QStringLiteral("mode"),
        QStringLiteral("HCS mode (E00) of every module; default the family's first."),
        QStringLiteral("M"));
    const QCommandLineOption modules(QStringLiteral("modules"),
                                     QStringLiteral("HCS modules of the node (default 1)."),
                                     QStringLiteral("N"));
    const QCommandLineOption factory(
        QStringLiteral("factory"),
        QStringLiteral("HCS: start every module from the bare dictionary defaults instead of a "
                       "commissioned machine (docs/SIMULATOR.md)."));
    const QCommandLineOption pty(
        QStringLiteral("pty"),
        QStringLiteral("Serve on a new pseudo terminal (its path is printed)."));
    const QCommandLineOption serial(QStringLiteral("serial"),
                                    QStringLiteral("Serve on a serial port."),
                                    QStringLiteral("PATH"));
    const QCommandLineOption tcp(
        QStringLiteral("tcp"),
        QStringLiteral(
            "Serve on TCP (HOST:PORT, :PORT or PORT; host 127.0.0.1 by default, port 0 = any)."),
        QStringLiteral("ADDR"));
    const QCommandLineOption can(
        QStringLiteral("can"),
        QStringLiteral("Serve CANopen SDO on a SocketCAN interface (can0, vcan0)."),
        QStringLiteral("IFACE"));
    const QCommandLineOption canFd(
        QStringLiteral("can-fd"),
        QStringLiteral("Serve CANopen SDO on an open descriptor carrying struct can_frame "
                       "datagrams (tests: one end of a SOCK_SEQPACKET socketpair)."),
        QStringLiteral("N"));
    const QCommandLineOption node(QStringLiteral("node"),
                                  QStringLiteral("CANopen node id, 1..127 (default 1)."),
                                  QStringLiteral("N"));
    const QCommandLineOption protocol(
        QStringLiteral("protocol"),
        QStringLiteral("modbus-rtu | modbus-tcp | node-image | hart | canopen | dsp408-image | "
                       "dsp408-gateway."),
        QStringLiteral("P"));
    const QCommandLineOption unit(
        QStringLiteral("unit"),
        QStringLiteral("dsp408-gateway: the gateway's Modbus unit id (default 1)."),
        QStringLiteral("N"));
    QList<QCommandLineOption> dsp408;
    for (const char *name : cmdline::kDsp408Options)
        dsp408.append(
            QCommandLineOption(QString::fromLatin1(name).mid(2),
                               QStringLiteral("ED1 image over TCP (docs/SIMULATOR-WANDFLUH.md)."),
                               QStringLiteral("V")));
    const QCommandLineOption fault(
        QStringLiteral("fault"),
        QStringLiteral("Faults on the answers: drop=P,corrupt=P,delay=MS,cut=N,seed=S."),
        QStringLiteral("SPEC"));
    const QCommandLineOption seed(
        QStringLiteral("seed"),
        QStringLiteral("Seed of the fault schedule (overrides the spec's)."), QStringLiteral("S"));
    const QCommandLineOption baud(QStringLiteral("baud"),
                                  QStringLiteral("Serial baud rate (HCS 19200, HART 1200)."),
                                  QStringLiteral("B"));
    const QCommandLineOption parity(QStringLiteral("parity"),
                                    QStringLiteral("none | even | odd (HCS even, HART odd)."),
                                    QStringLiteral("P"));
    const QCommandLineOption wire(
        QStringLiteral("wire"),
        QStringLiteral("Modbus RTU on --pty / --serial: keep wire time. Each answer byte takes its "
                       "character time at --baud, answers follow the request after --turnaround, "
                       "and a request starting before the line was quiet for 3.5 characters is "
                       "ignored and counted, as a strict slave does."));
    const QCommandLineOption noWire(QStringLiteral("no-wire"),
                                    QStringLiteral("Answer at once, without wire time (default)."));
    const QCommandLineOption turnaround(
        QStringLiteral("turnaround"),
        QStringLiteral("--wire: the device's time from the request's last byte to its answer, in "
                       "milliseconds (default 3, decimals allowed)."),
        QStringLiteral("MS"));
    const QCommandLineOption verbose(QStringList{QStringLiteral("v"), QStringLiteral("verbose")},
                                     QStringLiteral("Log every frame in and out on stderr."));
    p.addOptions({device, mode,   modules, factory,  pty,        serial, tcp,
                  can,    canFd,  node,    protocol, unit,       fault,  seed,
                  baud,   parity, wire,    noWire,   turnaround, verbose});
    p.addOptions(dsp408);
    const QCommandLineOption help = p.addHelpOption();
    // Not addVersionOption(): its -v would clash with --verbose.
    const QCommandLineOption version(QStringLiteral("version"), QStringLiteral("Program version."));
    p.addOption(version);

    if (!p.parse(arguments))
        return usage(p.errorText().toStdString());
    if (p.isSet(help))
        return OptionsExit{cli::kExitOk, p.helpText().toStdString()};
    if (p.isSet(version))
        return OptionsExit{cli::kExitOk, "valvetune-sim " VT_VERSION "\n"};
    if (!p.positionalArguments().isEmpty())
        return usage("unexpected argument '" + p.positionalArguments().first().toStdString() + "'");

    SimOptions o;
    if (!p.isSet(device))
        return usage("--device FAMILY is required (see --help)");
    o.family = p.value(device).toStdString();
    o.verbose = p.isSet(verbose);

    const int endpoints = int(p.isSet(pty)) + int(p.isSet(serial)) + int(p.isSet(tcp)) +
                          int(p.isSet(can)) + int(p.isSet(canFd));
    if (endpoints != 1)
        return usage(
            "give exactly one of --pty, --serial PATH, --tcp HOST:PORT, --can IFACE, --can-fd N");
    bool ok = true;
    if (p.isSet(serial)) {
        o.endpoint = Endpoint::Serial;
        o.serialPath = p.value(serial);
    } else if (p.isSet(tcp)) {
        o.endpoint = Endpoint::Tcp;
        std::string why;
        if (!parseTcp(p.value(tcp), o, why))
            return usage(why);
    } else if (p.isSet(can)) {
        o.endpoint = Endpoint::Can;
        o.canInterface = p.value(can).toStdString();
        if (o.canInterface.empty() || o.canInterface.size() >= IFNAMSIZ)
            return usage("--can '" + o.canInterface + "': expected an interface name of 1.." +
                         std::to_string(IFNAMSIZ - 1) + " characters");
    } else if (p.isSet(canFd)) {
        o.endpoint = Endpoint::CanFd;
        o.canFd = p.value(canFd).toInt(&ok);
        if (!ok || o.canFd < 0)
            return usage("--can-fd '" + p.value(canFd).toStdString() +
                         "': expected an open file descriptor number");
    }
    if ((o.endpoint == Endpoint::Tcp || o.isCan()) && (p.isSet(baud) || p.isSet(parity)))
        return usage("--baud and --parity are for --pty and --serial");
    if (p.isSet(node)) {
        if (!o.isCan())
            return usage("--node is the CANopen node id of --can / --can-fd");
        const uint n = p.value(node).toUInt(&ok);
        if (!ok || n == 0 || n > kMaxNode)
            return usage("--node '" + p.value(node).toStdString() + "': expected 1..127");
        o.node = static_cast<std::uint8_t>(n);
    }

    const bool protocolGiven = p.isSet(protocol);
    if (protocolGiven) {
        const QString name = p.value(protocol);
        const auto parsed = dev::fromKey<dev::LinkProtocol>(name.toStdString());
        if (!parsed)
            return usage("unknown protocol '" + name.toStdString() +
                         "' (modbus-rtu, modbus-tcp, node-image, hart, canopen, dsp408-image, "
                         "dsp408-gateway)");
        o.protocol = *parsed;
    }
    if (p.isSet(mode)) {
        o.mode = p.value(mode).toInt(&ok);
        if (!ok || o.mode < 0)
            return usage("--mode '" + p.value(mode).toStdString() + "': expected a mode number");
    }
    if (p.isSet(modules)) {
        const uint n = p.value(modules).toUInt(&ok);
        if (!ok || n == 0)
            return usage("--modules '" + p.value(modules).toStdString() + "': expected 1 or more");
        o.modules = n;
    }

    o.factory = p.isSet(factory);

    const auto &set = dev::builtinDictionaries();
    if (!set.ok())
        return OptionsExit{cli::kExitDeviceError,
                           "valvetune-sim: the built-in dictionaries do not load"};
    const dev::Dictionary *dict = set->find(o.family);
    if (!dict || dict->abstract) {
        std::vector<std::string> known = dev::sim::simulatedFamilies(*set);
        known.push_back("wandfluh-ed1");
        known.push_back("wandfluh-sd7");
        return usage("unknown device family '" + o.family + "' (" + joined(known) + ")");
    }
    if (auto why = checkCombination(*dict, o, protocolGiven, p.isSet(mode), p.isSet(modules)))
        return usage(*why);
    const bool ed1Image = dev::isDsp408Link(o.protocol);
    for (const QCommandLineOption &option : dsp408) {
        if (!p.isSet(option))
            continue;
        const QString name = QStringLiteral("--") + option.names().first();
        if (!ed1Image)
            return usage(name.toStdString() + " goes with --protocol dsp408-image or "
                                              "dsp408-gateway");
        if (auto why = cmdline::applyDsp408Option(name, p.value(option), o.dsp408))
            return usage(*why);
    }
    if (p.isSet(unit)) {
        if (o.protocol != LinkProtocol::Dsp408Gateway)
            return usage("--unit is the Modbus unit of --protocol dsp408-gateway");
        const uint n = p.value(unit).toUInt(&ok);
        if (!ok || n > 255)
            return usage("--unit '" + p.value(unit).toStdString() + "': expected 0..255");
        o.gatewayUnit = static_cast<std::uint8_t>(n);
    }

    if (o.isHart()) {
        o.baud = 1200; // ARCHITECTURE.md "HART": 1200 baud 8O1 through a HART modem
        o.parity = link::Parity::Odd;
    }
    if (p.isSet(baud)) {
        o.baud = p.value(baud).toInt(&ok);
        if (!ok || std::find(std::begin(kBauds), std::end(kBauds), o.baud) == std::end(kBauds))
            return usage("--baud '" + p.value(baud).toStdString() +
                         "': one of 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400");
    }
    if (p.isSet(parity)) {
        const QString v = p.value(parity);
        if (v == QLatin1String("none"))
            o.parity = link::Parity::None;
        else if (v == QLatin1String("even"))
            o.parity = link::Parity::Even;
        else if (v == QLatin1String("odd"))
            o.parity = link::Parity::Odd;
        else
            return usage("--parity '" + v.toStdString() + "': none, even or odd");
    }

    if (p.isSet(wire) && p.isSet(noWire))
        return usage("give --wire or --no-wire, not both");
    o.wire = p.isSet(wire);
    if (o.wire && (o.protocol != LinkProtocol::ModbusRtu ||
                   (o.endpoint != Endpoint::Pty && o.endpoint != Endpoint::Serial)))
        return usage("--wire is for --protocol modbus-rtu on --pty or --serial");
    if (p.isSet(turnaround)) {
        if (!o.wire)
            return usage("--turnaround goes with --wire");
        const double ms = p.value(turnaround).toDouble(&ok);
        if (!ok || ms < 0 || ms > 1000)
            return usage("--turnaround '" + p.value(turnaround).toStdString() +
                         "': expected milliseconds 0..1000");
        o.turnaroundUs = static_cast<std::int64_t>(ms * 1000 + 0.5);
    }

    if (p.isSet(fault)) {
        auto spec = link::parseFaultSpec(p.value(fault));
        if (!spec.ok())
            return usage(spec.error().text().toStdString());
        o.fault = *spec;
        // A plain key sets both directions; only a tx.* key makes them differ.
        if (!o.fault.tx.isNull() && o.fault.tx != o.fault.rx)
            return usage(
                "--fault: valvetune-sim disturbs its answers only; use plain or rx. keys, not tx.");
        o.seed = o.fault.seed;
    }
    if (p.isSet(seed)) {
        const uint s = p.value(seed).toUInt(&ok);
        if (!ok)
            return usage("--seed '" + p.value(seed).toStdString() + "': expected 0..4294967295");
        o.seed = s;
    }
    return o;
}

} // namespace vt::simapp
