// The test process's resident memory (Linux: /proc/self/statm), for tests that check memory
// becomes resident when it should and does not creep afterwards (issue #21, endurance).
#pragma once

#include <QFile>
#include <QList>
#include <unistd.h>

namespace vt::test {

// AddressSanitizer keeps freed memory in quarantine and puts redzones around every allocation:
// resident memory then grows with every temporary and says nothing about the program's own use.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kResidentMemoryIsMeaningful = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kResidentMemoryIsMeaningful = false;
#else
inline constexpr bool kResidentMemoryIsMeaningful = true;
#endif
#else
inline constexpr bool kResidentMemoryIsMeaningful = true;
#endif

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
