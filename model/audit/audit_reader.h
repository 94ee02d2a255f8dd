// readAuditLog(): a session log (audit_log.h) read back for a report — the header, the connection
// lines and every write entry, bounded (file size, line length); a line cut by a kill is
// reported, bad lines are skipped and counted. A value; any thread.
#pragma once

#include "core/local_text.h"
#include "model/audit/audit_record.h"

#include <QDateTime>
#include <QString>
#include <vector>

namespace vt::model {

// A write line as the report shows it (readAuditLog()).
struct AuditEntry
{
    QDateTime time; // with its offset from UTC, as logged
    int module = 0;
    QString row, name, unit;
    QString oldText, newText; // display texts ("1.000 V"); oldText empty when unknown
    QString oldRaw, newRaw;
    QString status;   // writeStatusKey()
    QString readBack; // display text of the value read back; empty when not read back
    dev::LocalText reason;
    QString origin; // auditOriginKey()
};

struct AuditLogContents
{
    bool ok = false;
    QString error; // why not ok: not readable, too large, no session header
    QString program, version, connection;
    qint64 pid = 0;
    QDateTime started;
    std::vector<QString> connections; // every connection line, in order (empty: disconnected)
    std::vector<AuditEntry> entries;
    int skipped = 0;            // lines that could not be read
    bool truncatedTail = false; // the last line was cut (the program was killed writing it)
};

// Reads a session log, bounded by `limits` (a larger file is not read).
AuditLogContents readAuditLog(const QString &path, const AuditLimits &limits = {});

} // namespace vt::model
