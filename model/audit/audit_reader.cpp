#include "model/audit/audit_reader.h"

#include <QFile>

namespace vt::model {

namespace {

QDateTime timeOf(const std::string &text)
{
    return QDateTime::fromString(QString::fromStdString(text), Qt::ISODateWithMs);
}

} // namespace

AuditLogContents readAuditLog(const QString &path, const AuditLimits &limits)
{
    AuditLogContents contents;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        contents.error = file.errorString();
        return contents;
    }
    if (file.size() > static_cast<qint64>(limits.maxBytes)) {
        contents.error = QStringLiteral("the session log is larger than %1 bytes")
                             .arg(static_cast<qulonglong>(limits.maxBytes));
        return contents;
    }
    // One byte more than the limit: a file that grew since size() is still refused.
    const QByteArray bytes = file.read(static_cast<qint64>(limits.maxBytes) + 1);
    const AuditParse parsed = parseAuditLog(
        std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), limits);
    contents.error = QString::fromStdString(parsed.error);
    if (!parsed.ok)
        return contents;
    contents.ok = true;
    contents.program = QString::fromStdString(parsed.header.program);
    contents.version = QString::fromStdString(parsed.header.version);
    contents.connection = QString::fromStdString(parsed.header.connection);
    contents.pid = parsed.header.pid;
    contents.started = timeOf(parsed.header.started);
    for (const AuditConnectionRecord &c : parsed.connections)
        contents.connections.push_back(QString::fromStdString(c.connection));
    for (const AuditWriteRecord &w : parsed.writes) {
        AuditEntry e;
        e.time = timeOf(w.time);
        e.module = w.module;
        e.row = QString::fromStdString(w.row);
        e.name = QString::fromStdString(w.name);
        e.unit = QString::fromStdString(w.unit);
        e.oldText = QString::fromStdString(w.oldValue.text);
        e.oldRaw = QString::fromStdString(w.oldValue.raw);
        e.newText = QString::fromStdString(w.newValue.text);
        e.newRaw = QString::fromStdString(w.newValue.raw);
        e.status = QString::fromStdString(w.status);
        e.readBack = QString::fromStdString(w.readBack.text);
        e.reason = {w.reasonEn, w.reasonDe};
        e.origin = QString::fromStdString(w.origin);
        contents.entries.push_back(std::move(e));
    }
    contents.skipped = parsed.skipped;
    contents.truncatedTail = parsed.truncatedTail;
    return contents;
}

} // namespace vt::model
