// PtyPair: the far end of a serial line for SerialLink tests. The test holds the pty master;
// SerialLink opens the slave by its path (or a symlink to it), the way a user opens one end of a
// socat pair. Reads from the master are collected by a QSocketNotifier, so tests wait on the
// event loop (test_wait.h), never sleep. Main thread only.
#pragma once

#include <QByteArray>
#include <QSocketNotifier>
#include <QString>
#include <memory>
#include <termios.h>

namespace vt::test {

class PtyPair
{
public:
    PtyPair();
    ~PtyPair();
    PtyPair(const PtyPair &) = delete;
    PtyPair &operator=(const PtyPair &) = delete;

    bool ok() const { return m_master >= 0; }
    QString error() const { return m_error; }
    QString slavePath() const { return m_slavePath; }

    // Starts collecting what the link writes (call once the link has the slave open: a master
    // whose slave is closed polls as hung up).
    void startReading();
    const QByteArray &received() const { return m_received; }
    bool write(const QByteArray &bytes);
    // The slave's termios (on Linux, tcgetattr() on the master reports the slave's settings).
    bool slaveTermios(termios *out) const;
    // Pulls the plug: the slave sees a hang-up.
    void closeMaster();

private:
    void onReadable();

    int m_master = -1;
    QString m_slavePath;
    QString m_error;
    QByteArray m_received;
    std::unique_ptr<QSocketNotifier> m_notifier;
};

} // namespace vt::test
