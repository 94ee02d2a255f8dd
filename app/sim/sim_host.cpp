// SimHost: see sim_host.h. Time: the SimClock follows a QElapsedTimer, so EEPROM commits and the
// plants run in real time; answers go out as soon as the clock has reached them.
#include "sim_host.h"

#include "app/cli/exit_codes.h"
#include "app/sim/can_socket.h"
#include "dict/dictionary_loader.h"
#include "modbus/rtu_timing.h"
#include "transports/byte_span.h"

#include <QTcpServer>
#include <QTcpSocket>
#include <cmath>
#include <cstdio>

namespace vt::simapp {
namespace {

constexpr int kTickMs = 1;
// --fault cut on a pty / serial port / CAN socket: how long the last answer may wait to leave.
constexpr std::int64_t kCutGraceUs = 2'000'000;

} // namespace

SimHost::SimHost(SimOptions options, QObject *parent)
    : QObject(parent), m_options(std::move(options)),
      m_faults(m_options.fault.rx, m_options.fault.cutAfterFrames, m_options.seed)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(kTickMs);
    connect(&m_timer, &QTimer::timeout, this, &SimHost::tick);
}

SimHost::~SimHost()
{
    if (m_wire) // the count a test or benchmark reads once the simulator has stopped
        note("wire: " + std::to_string(m_wire->refusals()) + " requests refused, " +
             std::to_string(m_wire->collisions()) + " collisions");
    m_timer.stop();
    closeFd();
}

dev::Result<QString, HostError> SimHost::start()
{
    const auto &dictionaries = dev::builtinDictionaries();
    if (!dictionaries.ok())
        return HostError{cli::kExitDeviceError, "the built-in dictionaries do not load"};
    dev::sim::SimDeviceSpec spec;
    spec.family = m_options.family;
    spec.modules = m_options.modules;
    spec.mode = m_options.mode;
    spec.factory = m_options.factory;
    spec.protocol = m_options.protocol;
    spec.canNode = m_options.node;
    spec.dsp408 = m_options.dsp408;
    spec.gatewayUnit = m_options.gatewayUnit;
    auto device = dev::sim::SimDevice::build(m_clock, *dictionaries, spec);
    if (!device.ok())
        return HostError{device.error().code == dev::sim::SimBuildErrc::UnknownFamily
                             ? cli::kExitDeviceError
                             : cli::kExitUsage,
                         device.error().message};
    m_device = std::move(device).value();
    // 3.5 characters of start + 8 data + parity + one stop bit (Modbus over Serial Line
    // §2.5.1.1, fixed 1.75 ms above 19200 baud); the HART de-framer uses 3.5 characters too to
    // give up a broken frame.
    const int bits = 10 + (m_options.parity == link::Parity::None ? 0 : 1);
    m_gapUs = m_options.isHart()
                  ? static_cast<std::int64_t>(std::ceil(3.5 * bits * 1e6 / m_options.baud))
                  : dev::modbus::silentIntervalUs(m_options.baud, bits);
    QString where;
    std::optional<HostError> error;
    switch (m_options.endpoint) {
    case Endpoint::Pty: error = openPty(where); break;
    case Endpoint::Serial: error = openSerial(where); break;
    case Endpoint::Tcp: error = openTcp(where); break;
    case Endpoint::Can:
    case Endpoint::CanFd: error = openCan(where); break;
    }
    if (error)
        return *error;
    m_where = where;
    m_elapsed.start();
    if (m_options.wire)
        m_wire.emplace(
            m_fd, m_options.baud, bits, m_options.turnaroundUs, [this] { return nowUs(); },
            [this](const std::string &text) { note(text); });
    m_timer.start();
    return where;
}

void SimHost::received(std::span<const std::uint8_t> bytes)
{
    const bool forDevice = !m_wire || m_wire->arrived(bytes.size(), nowUs());
    arrived(bytes, "");
    if (m_wire) // the request's bytes are still on the wire: its gap counts from their end
        m_lastByteUs = m_wire->receiveEndsAtUs();
    if (!forDevice)
        return; // a strict slave ignores a request that did not wait for the silent interval
    m_device->server().receive(bytes);
    serve();
}

void SimHost::arrived(std::span<const std::uint8_t> bytes, const std::string &tag)
{
    const std::int64_t now = nowUs();
    m_clock.advanceTo(now); // the request arrives at this time, its answer is stamped with it
    m_lastByteUs = now;
    m_burst = true;
    if (m_options.verbose) {
        if (m_tcp || m_options.isCan())
            logFrame("<-", bytes, tag.c_str()); // TCP keeps no gaps: one line per segment
        else
            m_inLog.insert(m_inLog.end(), bytes.begin(), bytes.end());
    }
}

void SimHost::tick()
{
    const std::int64_t now = nowUs();
    m_clock.advanceTo(now);
    if (m_options.isCan() && !m_outPending.empty())
        flushCan(); // images an interface with a full transmit queue refused (ENOBUFS)
    if (m_cutPending) {
        if ((now >= m_cutEarliestUs && lineDrained(now)) || now >= m_cutLatestUs)
            finishCut();
        return;
    }
    if (m_burst && now - m_lastByteUs >= m_gapUs) {
        m_burst = false;
        flushInLog();
        m_device->gap();
    }
    serve();
}

void SimHost::serve()
{
    if (m_ending || m_cutPending)
        return;
    if (!m_tcp) {
        if (deliver(m_device->server(), m_faults, "",
                    [this](const std::vector<std::uint8_t> &bytes) { send(bytes); }))
            cut();
        return;
    }
    std::vector<QTcpSocket *> due;
    for (const auto &client : m_clients) {
        QTcpSocket *socket = client->socket;
        if (deliver(*client->server, client->faults, client->tag,
                    [socket](const std::vector<std::uint8_t> &bytes) {
                        socket->write(link::toByteArray(bytes));
                    }))
            due.push_back(socket);
    }
    for (QTcpSocket *socket : due)
        cutClient(socket);
}

bool SimHost::deliver(dev::ByteServer &server, FaultFilter &faults, const std::string &tag,
                      const std::function<void(const std::vector<std::uint8_t> &)> &send)
{
    const std::int64_t now = m_clock.nowUs();
    std::vector<std::uint8_t> answer = server.drain();
    if (!answer.empty()) {
        flushInLog();
        const std::vector<std::uint8_t> copy =
            m_options.verbose ? answer : std::vector<std::uint8_t>{};
        switch (faults.push(std::move(answer), now)) {
        case FaultFilter::Verdict::Passed: break;
        case FaultFilter::Verdict::Dropped:
            logFrame("->", copy, (tag + " (fault: dropped)").c_str());
            break;
        case FaultFilter::Verdict::AfterCut:
            logFrame("->", copy, (tag + " (fault: after the cut)").c_str());
            break;
        }
    }
    for (const FaultFilter::Answer &a : faults.release(nowUs())) {
        const char *fault =
            a.corrupted ? (a.delayed ? " (fault: corrupted, delayed)" : " (fault: corrupted)")
                        : (a.delayed ? " (fault: delayed)" : "");
        logFrame("->", a.bytes, (tag + fault).c_str());
        send(a.bytes);
    }
    return faults.cutDue();
}

void SimHost::send(const std::vector<std::uint8_t> &bytes)
{
    if (m_fd < 0)
        return;
    m_lastSentBytes = bytes.size();
    if (m_options.isCan())
        writeCan(bytes);
    else
        writeLine(bytes);
}

void SimHost::cut()
{
    const std::string count = std::to_string(m_faults.answers());
    // A pty or serial port closed at once would lose the last answer (a hang-up flushes the
    // queues): like a cable pulled after the bytes left, close once they are out. On CAN the
    // node leaves the bus once its last answer has been sent.
    if (m_cutPending)
        return;
    note("fault cut after " + count + " answers: closing " + m_where.toStdString());
    m_cutPending = true;
    m_cutSeenQueued = false;
    m_quietSinceUs = -1;
    const std::int64_t charUs = m_gapUs * 2 / 7; // one character
    m_cutEarliestUs = nowUs() + m_gapUs + static_cast<std::int64_t>(m_lastSentBytes) * charUs;
    m_cutLatestUs = m_cutEarliestUs + kCutGraceUs;
}

// A TCP client's schedule reached its cut: that connection closes, the others go on.
void SimHost::cutClient(QTcpSocket *socket)
{
    TcpClient *client = clientOf(socket);
    if (!client)
        return;
    note("fault cut after " + std::to_string(client->faults.answers()) +
         " answers: closing the connection" + client->tag);
    socket->disconnect(this); // its last bytes are not served
    connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
    std::erase_if(m_clients, [socket](const auto &c) { return c->socket == socket; });
    socket->disconnectFromHost(); // after the answers already written
}

void SimHost::finishCut()
{
    m_ending = true;
    m_timer.stop();
    closeFd();
    emit finished(cli::kExitOk);
}

void SimHost::fail(const std::string &message)
{
    if (m_ending)
        return;
    note(message);
    m_ending = true;
    m_timer.stop();
    closeFd();
    emit finished(cli::kExitConnection);
}

void SimHost::flushInLog()
{
    if (m_inLog.empty())
        return;
    logFrame("<-", m_inLog);
    m_inLog.clear();
}

void SimHost::logFrame(const char *direction, std::span<const std::uint8_t> bytes, const char *note)
{
    if (!m_options.verbose)
        return;
    if (m_options.isCan()) { // candump notation: "601#4000200000000000"
        logLine(std::string(direction) + ' ' + candumpText(bytes) + note);
        return;
    }
    std::string hex;
    hex.reserve(bytes.size() * 3);
    static const char kDigits[] = "0123456789ABCDEF";
    for (const std::uint8_t b : bytes) {
        hex += hex.empty() ? "" : " ";
        hex += kDigits[b >> 4];
        hex += kDigits[b & 0x0F];
    }
    logLine(std::string(direction) + ' ' + hex + note);
}

void SimHost::note(const std::string &text)
{
    std::fprintf(stderr, "valvetune-sim: %s\n", text.c_str());
}

void SimHost::logLine(const std::string &text)
{
    // Monotonic seconds since the start, then the text: one line per event on stderr.
    const std::int64_t us = m_elapsed.isValid() ? nowUs() : 0;
    std::fprintf(stderr, "[%5lld.%06lld] %s\n", static_cast<long long>(us / 1'000'000),
                 static_cast<long long>(us % 1'000'000), text.c_str());
}

} // namespace vt::simapp
