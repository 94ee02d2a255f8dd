// SimHost: valvetune-sim's engine room. Puts the SimDevice's ByteServer on a pty, a serial port,
// a TCP port or a CAN socket (SocketCAN CAN_RAW or an adopted descriptor carrying can_frame
// datagrams), drives the SimClock in real time (1 ms timer), passes the answers through the
// --fault schedule and logs frames with -v. Over Modbus TCP any number of clients at once, as a
// gateway serves them: one node, and per connection its own de-framer, answers and fault
// schedule. The node image has one master; a second client is refused while it is connected.
// The ED1's raw PROFIBUS image has one master too, the newest connection (a tool reconnecting
// must not be locked out by its own half-closed connection).
// The endpoints and their I/O are in sim_endpoints.cpp.
// Owner: main(); lives on the main thread with the event loop.
#pragma once

#include "app/sim/fault_filter.h"
#include "app/sim/host_error.h"
#include "app/sim/sim_options.h"
#include "app/sim/wire_line.h"
#include "core/byte_server.h"
#include "sim/sim_clock.h"
#include "sim/sim_device.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

class QSocketNotifier;
class QTcpServer;
class QTcpSocket;

namespace vt::simapp {

class SimHost : public QObject
{
    Q_OBJECT

public:
    explicit SimHost(SimOptions options, QObject *parent = nullptr);
    ~SimHost() override;

    // Builds the device and opens the endpoint; on success what to print after "listening on"
    // (the pty's slave path, the serial port, HOST:PORT with the real port, "can:IFACE node N"
    // or "can-fd N node N").
    dev::Result<QString, HostError> start();

signals:
    // The simulator ends on its own: a fault cut on a pty / serial port / CAN socket (0) or the
    // endpoint was lost (3). The message is already on stderr.
    void finished(int exitCode);

private:
    // sim_endpoints.cpp: opening the endpoints and moving their bytes.
    std::optional<HostError> openPty(QString &where);
    std::optional<HostError> openSerial(QString &where);
    std::optional<HostError> openTcp(QString &where);
    std::optional<HostError> openCan(QString &where);
    void watchFd();
    void closeFd();
    void onFdReadable();
    void onFdWritable();
    void readCanFrames();
    void writeLine(const std::vector<std::uint8_t> &bytes); // pty / serial
    void writeCan(const std::vector<std::uint8_t> &bytes);
    void flushCan();
    bool lineDrained(std::int64_t nowUs); // pty / serial / CAN: every byte written has left
    // One TCP connection: the front end that de-frames its stream and queues its answers (its
    // own for Modbus TCP, the device's for the node image) and its --fault schedule.
    struct TcpClient
    {
        QTcpSocket *socket = nullptr;
        dev::ByteServer *server = nullptr;
        std::unique_ptr<dev::ByteServer> ownServer; // Modbus TCP
        FaultFilter faults;
        int number = 0;  // 1, 2, … in the order they connected
        std::string tag; // " (client N)" on its -v lines
    };
    void onNewConnection();
    void refuse(QTcpSocket *socket, const std::string &peer);
    // The ED1's raw image: the newest connection becomes its master, the older ones are closed.
    void takeOver(const std::string &peer);
    void onClientReadyRead(QTcpSocket *socket);
    void onClientGone(QTcpSocket *socket);
    TcpClient *clientOf(const QTcpSocket *socket);

    void tick();
    void received(std::span<const std::uint8_t> bytes); // pty / serial / CAN
    void arrived(std::span<const std::uint8_t> bytes, const std::string &tag);
    void serve();
    // The server's answers through `faults` to `send`; true when the schedule's cut is due.
    bool deliver(dev::ByteServer &server, FaultFilter &faults, const std::string &tag,
                 const std::function<void(const std::vector<std::uint8_t> &)> &send);
    void send(const std::vector<std::uint8_t> &bytes); // pty / serial / CAN
    void cut();
    void cutClient(QTcpSocket *socket);
    void finishCut();
    void fail(const std::string &message);

    std::int64_t nowUs() const { return m_elapsed.nsecsElapsed() / 1000; }
    void logFrame(const char *direction, std::span<const std::uint8_t> bytes,
                  const char *note = "");
    void logLine(const std::string &text);
    void note(const std::string &text); // one line on stderr, -v or not
    void flushInLog();

    SimOptions m_options;
    dev::sim::SimClock m_clock;
    std::unique_ptr<dev::sim::SimDevice> m_device; // after the clock: destroyed before it
    FaultFilter m_faults;

    QElapsedTimer m_elapsed;
    QTimer m_timer;

    // --pty / --serial / --can / --can-fd: the descriptor (pty master, serial port, socket) and,
    // for a pty, the slave kept open so the master never sees a hang-up between clients.
    int m_fd = -1;
    int m_slaveFd = -1;
    QString m_where;
    QSocketNotifier *m_readNotifier = nullptr;
    QSocketNotifier *m_writeNotifier = nullptr;
    // Not yet taken by a full pty / serial buffer; on CAN whole 16-byte images.
    std::vector<std::uint8_t> m_outPending;
    std::int64_t m_gapUs = 0;       // 3.5 characters at the line's baud
    std::optional<WireLine> m_wire; // --wire
    std::int64_t m_lastByteUs = 0;
    bool m_burst = false; // bytes arrived since the last gap

    QTcpServer *m_tcp = nullptr;
    std::vector<std::unique_ptr<TcpClient>> m_clients; // in the order they connected
    int m_clientsSeen = 0;

    std::vector<std::uint8_t> m_inLog; // -v: the incoming burst not yet logged
    bool m_ending = false;
    bool m_cutPending = false; // pty / serial / CAN: cut, waiting for the last answer to leave
    std::int64_t m_cutEarliestUs = 0;
    std::int64_t m_cutLatestUs = 0;
    bool m_cutSeenQueued = false;     // pty: the last answer was seen waiting for the client
    std::int64_t m_quietSinceUs = -1; // pty: since when nothing has been seen waiting
    std::size_t m_lastSentBytes = 0;
};

} // namespace vt::simapp
