// A session log (model/audit, one JSON line per write) as the report's write log: every write the
// tool made in that session, from any window or the CLI, with how it ended — read back from disk,
// so a report can be made after a crash or a lost link. The log keeps the raw values: the report
// names each parameter and says its values in the report's language, through the dictionary of
// the module's family in `settings`; a module or row it does not know keeps the log's English
// words. Any thread.
#pragma once

#include "dict/dictionary.h"
#include "files/param_file.h"
#include "model/audit/audit_reader.h"
#include "model/report/report_data.h"

#include <vector>

namespace vt::model {

std::vector<ReportWrite> reportWrites(const AuditLogContents &log,
                                      const dev::files::ParamFile &settings,
                                      const dev::DictionarySet &dictionaries, dev::Language lang);

} // namespace vt::model
