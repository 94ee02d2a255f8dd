// A session log (model/audit, one JSON line per write) as the report's write log: every write the
// tool made in that session, from any window or the CLI, with how it ended — read back from disk,
// so a report can be made after a crash or a lost link. Any thread.
#pragma once

#include "model/audit/audit_reader.h"
#include "model/report/report_data.h"

#include <vector>

namespace vt::model {

std::vector<ReportWrite> reportWrites(const AuditLogContents &log);

} // namespace vt::model
