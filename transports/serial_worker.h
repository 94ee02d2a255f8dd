// SerialWorker: the blocking half of SerialLink. It owns the open port (serial_port_io.h:
// libserialport where it can open the port, POSIX termios for any other terminal) and lives on
// SerialLink's worker QThread; SerialLink reaches it only through queued calls and it answers
// only through queued signals (STYLE.md rule 9). Every call and signal carries the session id of
// the open() it belongs to, so the link can ignore what a previous session left in flight.
// Created and destroyed by SerialLink; touched only on the worker thread once moved there.
#pragma once

#include "transports/serial_settings.h"

#include <QByteArray>
#include <QObject>
#include <QString>
#include <memory>

class QSocketNotifier;

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
    void openPort(quint64 session, const vt::link::SerialSettings &settings);
    // Silent: the link already considers itself closed.
    void closePort();
    // Writes all bytes or fails; a write of the current session only.
    void write(quint64 session, const QByteArray &bytes);

    // The sentence failed() carries when the port of `settings` did not open.
    static QString openFailureText(const OpenFailure &failure, const SerialSettings &settings);

signals:
    void opened(quint64 session);
    void failed(quint64 session, const QString &reason);
    void received(quint64 session, const QByteArray &bytes);

private:
    void onReadable();
    void fail(const QString &reason);
    void release();
    void warnIfNotApplied() const;

    std::unique_ptr<SerialPortIo> m_port;
    QSocketNotifier *m_notifier = nullptr;
    quint64 m_session = 0;
    SerialSettings m_settings;
};

} // namespace vt::link
