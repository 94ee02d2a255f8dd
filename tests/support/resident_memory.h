// The test process's resident memory (Linux: /proc/self/statm), for tests that check memory
// becomes resident when it should and does not creep afterwards (issue #21, endurance).
#pragma once

#include <QFile>
#include <QList>
#include <unistd.h>

namespace vt::test {

// Resident bytes of this process now; -1 where /proc/self/statm cannot be read.
inline qint64 residentBytes()
{
    QFile statm(QStringLiteral("/proc/self/statm"));
    if (!statm.open(QIODevice::ReadOnly))
        return -1;
    const QList<QByteArray> fields = statm.readAll().split(' ');
    bool ok = false;
    const qint64 pages = fields.size() > 1 ? fields[1].toLongLong(&ok) : 0;
    return ok ? pages * static_cast<qint64>(sysconf(_SC_PAGESIZE)) : -1;
}

} // namespace vt::test
