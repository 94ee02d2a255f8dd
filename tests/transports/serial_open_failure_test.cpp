// A serial port the user may not open: the failure names the group to join and the command that
// joins it, whichever way (libserialport, termios) refused the port. The errno mapping and the
// sentence are checked directly; a real EACCES comes from a pty slave with mode 000 opened by an
// unprivileged process (root opens anything, so as root a child drops to nobody first).
#include "pty_pair.h"
#include "transports/serial_port_io.h"
#include "transports/serial_worker.h"

#include <QFile>
#include <QTemporaryDir>
#include <cerrno>
#include <grp.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using vt::link::OpenFailure;
using vt::link::SerialSettings;
using vt::link::SerialWorker;

constexpr char kDialoutAdvice[] =
    "Cannot open /dev/ttyUSB0: permission denied. Serial ports are for the members of the group "
    "dialout: add your user to it with \"sudo usermod -aG dialout $USER\", then log out and log "
    "in again.";

TEST(SerialOpenFailure, ErrnoDecidesTheKind)
{
    EXPECT_EQ(vt::link::openFailureKind(EACCES), OpenFailure::Kind::PermissionDenied);
    EXPECT_EQ(vt::link::openFailureKind(EPERM), OpenFailure::Kind::PermissionDenied);
    EXPECT_EQ(vt::link::openFailureKind(ENOENT), OpenFailure::Kind::NotFound);
    EXPECT_EQ(vt::link::openFailureKind(EBUSY), OpenFailure::Kind::CannotOpen);
}

TEST(SerialOpenFailure, PermissionDeniedSaysWhichGroupAndHowToJoinIt)
{
    const auto settings = SerialSettings::hcsDefault(QStringLiteral("/dev/ttyUSB0"));
    const OpenFailure failure{OpenFailure::Kind::PermissionDenied,
                              QStringLiteral("Permission denied"), QStringLiteral("dialout")};
    EXPECT_EQ(SerialWorker::openFailureText(failure, settings).toStdString(), kDialoutAdvice);
    // Other failures keep the system's reason.
    const OpenFailure busy{
        OpenFailure::Kind::CannotOpen, QStringLiteral("Device or resource busy"), {}};
    EXPECT_EQ(SerialWorker::openFailureText(busy, settings),
              "Cannot open /dev/ttyUSB0: Device or resource busy");
}

// The group comes from the device when it lets its group read and write (uucp on Arch); a device
// that does not falls back to Debian's dialout.
TEST(SerialOpenFailure, TheGroupIsTheDevicesOwnWhenItGrantsReadAndWrite)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("ttyFAKE"));
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.close();
    const QByteArray local = path.toLocal8Bit();
    ASSERT_EQ(::chmod(local.constData(), 0600), 0);
    EXPECT_EQ(vt::link::serialPortGroup(path), "dialout");

    const group *uucp = ::getgrnam("uucp");
    if (!uucp || ::chown(local.constData(), static_cast<uid_t>(-1), uucp->gr_gid) != 0)
        GTEST_SKIP() << "cannot give the file to group uucp (not root, or no such group)";
    ASSERT_EQ(::chmod(local.constData(), 0660), 0);
    EXPECT_EQ(vt::link::serialPortGroup(path), "uucp");
    EXPECT_EQ(vt::link::openFailure(path, EACCES, QStringLiteral("Permission denied")).group,
              "uucp");
}

// A real refusal: a pty slave with mode 000, opened through the product's termios way by a
// process without privileges. The child reports the kind and the group through a pipe.
TEST(SerialOpenFailure, ARealPermissionDeniedOnATerminal)
{
    vt::test::PtyPair pty;
    ASSERT_TRUE(pty.ok()) << pty.error().toStdString();
    const QByteArray slave = pty.slavePath().toLocal8Bit();
    ASSERT_EQ(::chmod(slave.constData(), 0), 0);
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::close(fds[0]);
        constexpr gid_t kNogroup = 65534;
        constexpr uid_t kNobody = 65534;
        if (::geteuid() == 0 &&
            (::setgroups(0, nullptr) != 0 || ::setgid(kNogroup) != 0 || ::setuid(kNobody) != 0))
            ::_exit(3);
        OpenFailure failure;
        const auto port = vt::link::openWithTermios(
            SerialSettings::hcsDefault(QString::fromLocal8Bit(slave)), &failure);
        const QByteArray report = port ? QByteArray("opened")
                                       : QByteArray::number(static_cast<int>(failure.kind)) + ' ' +
                                             failure.group.toLocal8Bit();
        const bool written =
            ::write(fds[1], report.constData(), static_cast<size_t>(report.size())) ==
            static_cast<ssize_t>(report.size());
        ::_exit(written ? 0 : 4);
    }
    ::close(fds[1]);
    char buffer[128] = {};
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer - 1);
    ::close(fds[0]);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "child status " << status;
    ASSERT_GT(n, 0);
    const QByteArray expected =
        QByteArray::number(static_cast<int>(OpenFailure::Kind::PermissionDenied)) + " dialout";
    EXPECT_EQ(QByteArray(buffer, static_cast<int>(n)), expected);
}

} // namespace
