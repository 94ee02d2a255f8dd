// The session log reader on arbitrary input (STYLE.md rule 12: never crash on a bad file; a log
// cut by a kill or damaged on disk still reads), with small limits so the bounds are exercised,
// and for every log it accepts: what it read, written again, reads back the same.
#include "model/audit/audit_record.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

using namespace vt::model;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char *>(data), size);
    AuditLimits limits;
    limits.maxBytes = 1 << 16;
    limits.maxLine = 1 << 10;
    const AuditParse parsed = parseAuditLog(text, limits);
    if (!parsed.ok)
        return 0;
    if (parsed.skipped < 0)
        __builtin_trap();

    std::string again = formatAuditLine(parsed.header);
    for (const AuditConnectionRecord &c : parsed.connections)
        again += formatAuditLine(c);
    for (const AuditWriteRecord &w : parsed.writes)
        again += formatAuditLine(w);
    const AuditParse back = parseAuditLog(again);
    if (!back.ok || back.skipped != 0 || back.truncatedTail || !(back.header == parsed.header) ||
        back.connections != parsed.connections || back.writes != parsed.writes)
        __builtin_trap();
    return 0;
}
