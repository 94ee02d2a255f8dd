#include "model/report/report_writes.h"

namespace vt::model {

std::vector<ReportWrite> reportWrites(const AuditLogContents &log)
{
    std::vector<ReportWrite> writes;
    writes.reserve(log.entries.size());
    for (const AuditEntry &e : log.entries)
        writes.push_back({e.time, e.module, e.row, e.name, e.unit, e.oldText, e.newText, e.status,
                          QString::fromStdString(e.reason.en),
                          QString::fromStdString(e.reason.de)});
    return writes;
}

} // namespace vt::model
