// SerialWorker: the blocking half of SerialLink. It owns the open port (serial_port_io.h:
// libserialport where it can open the port, POSIX termios for any other terminal) and lives on
// SerialLink's worker QThread; SerialLink reaches it only through queued calls and it answers
// only through queued signals (STYLE.md rule 9). Every call and signal carries the session id of
// the open() it belongs to, so the link can ignore what a previous session left in flight.
// With the Modbus RTU line timing on (SerialSettings), a write waits on this thread until the
// line was quiet for t3.5, and what arrives is read until the line is quiet for t3.5 and handed
// on as one frame (Modbus over Serial Line §2.5.1.1): the worker blocks for at most one frame's
// time plus t3.5, which is what it is for (STYLE.md rule 9).
// Without the line timing nothing on the port waits: the worker then moves itself to the link's
// thread once the port is open (openPort's `exchangeThread`), writes without waiting (what the
// driver cannot take at once goes on when the port can take more, within the same bound) and
// hands frames on directly — no thread hop per exchange. Opening and closing stay on the worker
// thread (an open may wait: a Bluetooth port connects, an adapter enumerates).
// Created and destroyed by SerialLink; touched only on the thread it lives on.
#pragma once

#include "modbus/rtu_timing.h"
#include "transports/serial_settings.h"

#include <QByteArray>
#include <QObject>
#include <QString>
#include <deque>
#include <memory>
#include <optional>

class QSocketNotifier;
class QThread;
class QTimer;

namespace vt::link {

class SerialPortIo;
struct OpenFailure;

class SerialWorker : public QObject
{
    Q_OBJECT
public:
    explicit SerialWorker(QObject *parent = nullptr);
    ~SerialWorker() override;

    // Closes whatever is open, then opens and configures the port: opened() or failed().
    // `exchangeThread` (settings without line timing): the thread to move to once open.
    void openPort(quint64 session, const vt::link::SerialSettings &settings,
                  QThread *exchangeThread = nullptr);
    // Silent: the link already considers itself closed.
    void closePort();
    // Writes all bytes or fails; a write of the current session only. With the frame end by
    // silence, an answer of `replyBytes` (> 0) is handed on once that long, not t3.5 later.
    void write(quint64 session, const QByteArray &bytes, qsizetype replyBytes = 0);

    // The sentence failed() carries when the port of `settings` did not open.
    static QString openFailureText(const OpenFailure &failure, const SerialSettings &settings);

signals:
    void opened(quint64 session);
    void failed(quint64 session, const QString &reason);
    // `quiet`: the line went quiet for t3.5 after these bytes (the frame has ended).
    void received(quint64 session, const QByteArray &bytes, bool quiet);
    // The driver took the first byte of the oldest frame write() was given and not reported yet
    // at this steady_clock time (ns since its epoch): with the line timing, after the t3.5 wait.
    void wrote(quint64 session, qint64 steadyNs);

private:
    void onReadable();
    // Without line timing: queues `bytes` and writes what the driver takes now (writeOut()).
    void writeWithoutWaiting(const QByteArray &bytes, unsigned timeoutMs);
    void writeOut();
    // Reads until the line is quiet for t3.5 (or a bound of bytes); false when the port failed.
    bool readFrame(QByteArray &frame, bool &quiet);
    // Blocks until t3.5 after the last byte on the line, handing on what arrives meanwhile.
    void waitForSilence();
    void fail(const QString &reason);
    void release();
    void warnIfNotApplied() const;

    std::unique_ptr<SerialPortIo> m_port;
    QSocketNotifier *m_notifier = nullptr;
    QSocketNotifier *m_writeNotifier = nullptr; // while m_output waits for room in the driver
    QTimer *m_outputDeadline = nullptr;         // m_output not written by then: the write failed
    QByteArray m_output;                        // written without waiting, not taken yet
    std::deque<qsizetype> m_frameStarts; // where in m_output the frames not reported yet start
    quint64 m_session = 0;
    SerialSettings m_settings;
    std::optional<dev::modbus::RtuLineClock> m_line; // the open port's line timing
    qsizetype m_replyBytes = 0; // the awaited answer's size (write()); 0 once handed on
};

} // namespace vt::link
