#include "model/audit/audit_log.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace vt::model {

namespace {
AuditLog *g_current = nullptr; // GUI thread only, like the writers
} // namespace

AuditLog::AuditLog(QString program, QString version, QString directory)
    : m_directory(directory.isEmpty() ? defaultDirectory() : std::move(directory))
{
    m_header.program = program.toStdString();
    m_header.version = version.toStdString();
    m_header.pid = QCoreApplication::applicationPid();
    m_header.started = now();
}

AuditLog::~AuditLog()
{
    if (g_current == this)
        g_current = nullptr;
    if (m_fd >= 0)
        ::close(m_fd);
}

QString AuditLog::defaultDirectory()
{
    const QString env = qEnvironmentVariable("VT_AUDIT_DIR");
    if (!env.isEmpty())
        return env;
    // One folder for valvetune and valvetune-cli (their application names differ).
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
           QStringLiteral("/ValveTune/sessions");
}

AuditLog *AuditLog::current()
{
    return g_current;
}

AuditLog::Scope::Scope(AuditLog &log) : m_previous(g_current)
{
    g_current = &log;
}

AuditLog::Scope::~Scope()
{
    g_current = m_previous;
}

std::string AuditLog::now()
{
    const QDateTime local = QDateTime::currentDateTime();
    return local.toOffsetFromUtc(local.offsetFromUtc()).toString(Qt::ISODateWithMs).toStdString();
}

void AuditLog::setConnection(const QString &connection)
{
    const std::string text = connection.toStdString();
    if (m_fd < 0) {
        // The header names what the writes went to: a disconnect before the first line keeps it
        // and follows the header as a line of its own.
        m_disconnectedAt.clear();
        if (!text.empty())
            m_header.connection = text;
        else if (!m_header.connection.empty())
            m_disconnectedAt = now();
        return;
    }
    put(formatAuditLine(AuditConnectionRecord{now(), text}));
}

bool AuditLog::append(const AuditWriteRecord &write)
{
    if (m_fd < 0 && !open())
        return false;
    return put(formatAuditLine(write));
}

bool AuditLog::open()
{
    if (!m_error.isEmpty())
        return false; // tried once; a session does not retry a directory it cannot write
    if (!QDir().mkpath(m_directory)) {
        m_error = QStringLiteral("cannot create %1").arg(m_directory);
        return false;
    }
    const QString stem =
        QStringLiteral("%1/%2-%3-%4")
            .arg(m_directory,
                 QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")),
                 QString::fromStdString(m_header.program))
            .arg(m_header.pid);
    // Several sessions of one process in one second (the CLI's in-process runs) get "-2", "-3" ….
    for (int n = 1; n < 1000 && m_fd < 0; ++n) {
        const QString path = n == 1 ? stem + QStringLiteral(".jsonl")
                                    : QStringLiteral("%1-%2.jsonl").arg(stem).arg(n);
        m_fd = ::open(QFile::encodeName(path).constData(),
                      O_WRONLY | O_CREAT | O_EXCL | O_APPEND | O_CLOEXEC, 0644);
        if (m_fd >= 0)
            m_path = path;
        else if (errno != EEXIST)
            break;
    }
    if (m_fd < 0) {
        m_error = QStringLiteral("cannot create a session log in %1: %2")
                      .arg(m_directory, QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    if (!put(formatAuditLine(m_header)))
        return false;
    return m_disconnectedAt.empty() ||
           put(formatAuditLine(AuditConnectionRecord{m_disconnectedAt, {}}));
}

bool AuditLog::put(const std::string &line)
{
    // One write(2) per line: O_APPEND puts it whole at the end; a short write (a full disk)
    // is finished by a second call, the only case where a line is split.
    std::size_t done = 0;
    while (done < line.size()) {
        const ssize_t n = ::write(m_fd, line.data() + done, line.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            m_error = QStringLiteral("cannot write %1: %2")
                          .arg(m_path, QString::fromLocal8Bit(std::strerror(errno)));
            return false;
        }
        done += static_cast<std::size_t>(n);
    }
    return true;
}

} // namespace vt::model
