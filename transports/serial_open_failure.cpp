// Why a serial port did not open (serial_port_io.h), from the errno of the open() that refused
// it: both ways of opening a port (libserialport, termios) report through here, so "permission
// denied" names the group to join whichever way was tried.
#include "serial_port_io.h"

#include <cerrno>
#include <grp.h>
#include <sys/stat.h>

namespace vt::link {

namespace {

// Debian's udev rules give serial devices (ttyS, ttyUSB, ttyACM) to this group, mode 0660.
constexpr char kUsualSerialGroup[] = "dialout";

} // namespace

OpenFailure::Kind openFailureKind(int code)
{
    switch (code) {
    case ENOENT: return OpenFailure::Kind::NotFound;
    case EACCES:
    case EPERM: return OpenFailure::Kind::PermissionDenied;
    default: return OpenFailure::Kind::CannotOpen;
    }
}

QString serialPortGroup(const QString &path)
{
    struct stat info
    {
    };
    const QByteArray name = path.toLocal8Bit();
    constexpr mode_t groupReadWrite = S_IRGRP | S_IWGRP;
    if (::stat(name.constData(), &info) == 0 && info.st_gid != 0 &&
        (info.st_mode & groupReadWrite) == groupReadWrite) {
        if (const group *g = ::getgrgid(info.st_gid); g && g->gr_name)
            return QString::fromLocal8Bit(g->gr_name);
    }
    return QString::fromLatin1(kUsualSerialGroup);
}

OpenFailure openFailure(const QString &path, int code, const QString &systemText)
{
    OpenFailure failure{openFailureKind(code), systemText, {}};
    if (failure.kind == OpenFailure::Kind::PermissionDenied)
        failure.group = serialPortGroup(path);
    return failure;
}

} // namespace vt::link
