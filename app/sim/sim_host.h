// SimHost: valvetune-sim's engine room. Builds the simulated device (an HCS node through
// makeNode, or the Wandfluh SD7 HART device), puts its ByteServer on a pty, a serial port or a TCP
// port, drives the SimClock in real time (1 ms timer), passes the answers through the --fault
// schedule and logs frames with -v. One TCP client at a time; each gets fresh de-framing state.
// Owner: main(); lives on the main thread with the event loop.
#pragma once

#include "app/sim/fault_filter.h"
#include "app/sim/sim_options.h"
#include "core/byte_server.h"
#include "sim/sim_clock.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

class QSocketNotifier;
class QTcpServer;
class QTcpSocket;

namespace vt::dev::sim {
class HcsNode;
class HartDevice;
class HartServer;
class ModbusRtuServer;
class ModbusTcpServer;
class NodeImageServer;
} // namespace vt::dev::sim

namespace vt::simapp {

struct HostError
{
    int exitCode = 1; // app/cli/exit_codes.h: 2 for a device the options cannot build, 3 for I/O
    std::string message;
};

class SimHost : public QObject
{
    Q_OBJECT

public:
    explicit SimHost(SimOptions options, QObject *parent = nullptr);
    ~SimHost() override;

    // Builds the device and opens the endpoint; on success what to print after "listening on"
    // (the pty's slave path, the serial port, or HOST:PORT with the real port).
    dev::Result<QString, HostError> start();

Q_SIGNALS:
    // The simulator ends on its own: a fault cut on a pty / serial port (0) or the port was
    // lost (3). The message is already on stderr.
    void finished(int exitCode);

private:
    std::optional<HostError> buildDevice();
    std::optional<HostError> openPty(QString &where);
    std::optional<HostError> openSerial(QString &where);
    std::optional<HostError> openTcp(QString &where);
    void watchFd();
    void closeFd();

    void onFdReadable();
    void onFdWritable();
    void onNewConnection();
    void onClientReadyRead();
    void onClientGone();

    void tick();
    void received(std::span<const std::uint8_t> bytes);
    void serve();
    void send(const std::vector<std::uint8_t> &bytes);
    void cut();
    bool lineDrained() const; // pty / serial: every byte written has left
    void finishCut();
    void fail(const std::string &message);
    void resetServer();

    std::int64_t nowUs() const { return m_elapsed.nsecsElapsed() / 1000; }
    void logFrame(const char *direction, std::span<const std::uint8_t> bytes,
                  const char *note = "");
    void logLine(const std::string &text);
    void note(const std::string &text); // one line on stderr, -v or not
    void flushInLog();

    SimOptions m_options;
    dev::sim::SimClock m_clock;
    std::unique_ptr<dev::sim::HcsNode> m_node;
    std::unique_ptr<dev::sim::HartDevice> m_hart;
    std::unique_ptr<dev::ByteServer> m_server;
    // The concrete front end behind m_server, for silence / gap / reset (one is set).
    dev::sim::ModbusRtuServer *m_rtu = nullptr;
    dev::sim::ModbusTcpServer *m_mbtcp = nullptr;
    dev::sim::NodeImageServer *m_image = nullptr;
    dev::sim::HartServer *m_hartServer = nullptr;
    FaultFilter m_faults;

    QElapsedTimer m_elapsed;
    QTimer m_timer;

    // --pty / --serial: the line's descriptor (pty master) and, for a pty, the slave kept open
    // so the master never sees a hang-up between clients.
    int m_fd = -1;
    int m_slaveFd = -1;
    QString m_where;
    QSocketNotifier *m_readNotifier = nullptr;
    QSocketNotifier *m_writeNotifier = nullptr;
    std::vector<std::uint8_t> m_outPending; // not yet taken by a full pty / serial buffer
    std::int64_t m_gapUs = 0;               // 3.5 characters at the line's baud
    std::int64_t m_lastByteUs = 0;
    bool m_burst = false; // bytes arrived since the last gap

    QTcpServer *m_tcp = nullptr;
    QTcpSocket *m_client = nullptr;

    std::vector<std::uint8_t> m_inLog; // -v: the incoming burst not yet logged
    bool m_ending = false;
    bool m_cutPending = false; // pty / serial: cut, waiting for the last answer to leave
    std::int64_t m_cutEarliestUs = 0;
    std::int64_t m_cutLatestUs = 0;
    std::size_t m_lastSentBytes = 0;
};

} // namespace vt::simapp
