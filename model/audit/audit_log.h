// AuditLog: the append-only session log on disk — every write the tool made in a session, from
// any window or the CLI, one JSON line each with its verification result (audit_record.h), so a
// commissioning report can be made after a crash or a lost link. One file per session,
// <dir>/<yyyyMMdd-HHmmss>-<program>-<pid>.jsonl, created at the first line after the header
// (a session that writes nothing leaves no file). Each line goes out in one write(2) on an
// O_APPEND descriptor: a kill loses at most the line being written, never an earlier one.
// Owner: the program's main() (valvetune) or the command's DeviceRun (valvetune-cli), installed
// as current() for its life; GUI thread only. Writers reach it through auditWrite() and friends
// (write_audit.h), never directly.
#pragma once

#include "model/audit/audit_record.h"

#include <QString>

namespace vt::model {

class AuditLog
{
public:
    // `directory` empty: defaultDirectory().
    AuditLog(QString program, QString version, QString directory = {});
    ~AuditLog();
    AuditLog(const AuditLog &) = delete;
    AuditLog &operator=(const AuditLog &) = delete;

    // $VT_AUDIT_DIR when set, else <GenericDataLocation>/ValveTune/sessions
    // (~/.local/share/ValveTune/sessions), shared by valvetune and valvetune-cli.
    static QString defaultDirectory();

    // The log writers use now; nullptr when none is installed (nothing is logged).
    static AuditLog *current();

    // Installs a log as current() for its own life and puts back the one before.
    class Scope
    {
    public:
        explicit Scope(AuditLog &log);
        ~Scope();
        Scope(const Scope &) = delete;
        Scope &operator=(const Scope &) = delete;

    private:
        AuditLog *m_previous;
    };

    // What the user is connected to (Connection::describe()); empty: disconnected. Goes into the
    // header when no line is written yet, else a "connection" line; the header keeps the last
    // connection of a session that disconnected before its first write.
    void setConnection(const QString &connection);
    // Appends one write line (creating the file with its header first). False when the file
    // cannot be written (error() says why; the session goes on).
    bool append(const AuditWriteRecord &write);

    QString directory() const { return m_directory; }
    QString path() const { return m_path; } // empty until the file exists
    QString error() const { return m_error; }
    // The current time as the log writes it: ISO 8601 with milliseconds and offset.
    static std::string now();

private:
    bool open();
    bool put(const std::string &line);

    QString m_directory;
    AuditHeaderRecord m_header;
    std::string m_disconnectedAt; // before the file existed; written after the header
    QString m_path;
    QString m_error;
    int m_fd = -1;
};

} // namespace vt::model
