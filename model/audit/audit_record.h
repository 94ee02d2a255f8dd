// The session log's lines as plain values, Qt-free so the libFuzzer build reads them too: a
// session header, a "connection" line on each connect and disconnect, and one "write" line per
// finished write item. Each line is one JSON object; formatAuditLine() writes it, parseAuditLog()
// reads a whole file's text back, bounded (the file size and each line's length are limited, a
// truncated last line is reported, bad lines are skipped and counted). A value; any thread.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vt::model {

// A value as the log keeps it: the display text (number and unit, or an enum label, in English)
// and the raw value as text (a number, or a text row's string).
struct AuditValue
{
    std::string text;
    std::string raw;
    bool operator==(const AuditValue &) const = default;
};

struct AuditHeaderRecord
{
    std::string program; // "valvetune", "valvetune-cli"
    std::string version;
    long long pid = 0;
    std::string started;    // ISO 8601 with milliseconds and offset
    std::string connection; // what the user connected to; empty: not connected
    bool operator==(const AuditHeaderRecord &) const = default;
};

struct AuditConnectionRecord
{
    std::string time;
    std::string connection; // empty: disconnected
    bool operator==(const AuditConnectionRecord &) const = default;
};

struct AuditWriteRecord
{
    std::string time; // ISO 8601 with milliseconds and offset, when the item finished
    int module = 0;   // module address
    std::string row;  // the dictionary's row name ("C1.07"); empty for a raw frame
    std::string name; // the row's English label
    std::string unit;
    AuditValue oldValue; // empty when the value before the write was not known
    AuditValue newValue;
    std::string status;   // model::writeStatusKey(): verified, refused, mismatch, uncertain …
    AuditValue readBack;  // empty when the row was not read back
    std::string reasonEn; // why it ended so (the device's or the application's words)
    std::string reasonDe; // the same in German, where known
    std::string origin;   // auditOriginKey(): editor, monitor, workbench, compose, cli-set …
    bool operator==(const AuditWriteRecord &) const = default;
};

struct AuditLimits
{
    std::size_t maxBytes = std::size_t{64} << 20; // a longer log is not read
    std::size_t maxLine = std::size_t{64} << 10;  // a longer line is skipped
};

struct AuditParse
{
    bool ok = false;   // false: no session header on the first line, or the text is too long
    std::string error; // why not ok (English, for the CLI and logs)
    AuditHeaderRecord header;
    std::vector<AuditConnectionRecord> connections;
    std::vector<AuditWriteRecord> writes; // in file order
    int skipped = 0;            // lines that are not a known record (bad JSON, too long …)
    bool truncatedTail = false; // the last line has no newline: it was being written
};

// One line of the log, with its trailing newline.
std::string formatAuditLine(const AuditHeaderRecord &header);
std::string formatAuditLine(const AuditConnectionRecord &connection);
std::string formatAuditLine(const AuditWriteRecord &write);

AuditParse parseAuditLog(std::string_view text, const AuditLimits &limits = {});

} // namespace vt::model
