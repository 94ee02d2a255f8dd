// PtyPair: the far end of a serial line for SerialLink tests. The test holds the pty master;
// SerialLink opens the slave through a symlink path that libserialport accepts (see
// libserialportPath()). Reads from the master are collected by a QSocketNotifier, so tests wait
// on the event loop (test_wait.h), never sleep. Main thread only.
#pragma once

#include <QByteArray>
#include <QSocketNotifier>
#include <QString>
#include <memory>
#include <sys/types.h>
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
    // st_rdev of the slave, the key of vt::test::lastTermiosRequest().
    dev_t slaveDevice() const;

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

// libserialport's sp_get_port_by_name() wants "/dev/<name>" with a /sys/class/tty/<name> entry,
// which a pty lacks. For "/dev/../../..<abs symlink>" it reads the link
// "/sys/class/tty/../../..<abs symlink>" == "<abs symlink>", which exists, so the lookup
// succeeds; open() then resolves "/dev/../../..<abs symlink>" to the same symlink → the pty.
QString libserialportPath(const QString &absoluteSymlink);

} // namespace vt::test
