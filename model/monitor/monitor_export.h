// The monitor's CSV export: the samples of every monitored module in one SampleStore
// CSV (SampleStore's format, docs/MONITOR.md), with the tuning journal's markers. Modules poll on
// their own, so their rows are merged in time order and each row leaves the other modules' cells
// empty. GUI thread (reads the stores).
#pragma once

#include "model/monitor/monitor_session.h"

#include <optional>

class QIODevice;

namespace vt::model {

// One store holding the rows with t0 <= time <= t1 of every monitored module, plus the journal
// markers of that range. Channel ids are the row names ("d1.11"); with several modules they are
// prefixed with the address ("2/d1.11"). Nullopt when nothing is monitored.
std::optional<SampleStore> mergedRecording(const MonitorSession &session, double t0, double t1);

// Writes mergedRecording() as CSV. False (and *error) when there is nothing to write or the
// device fails.
bool writeMonitorCsv(const MonitorSession &session, QIODevice &out, double t0, double t1,
                     QString *error = nullptr);

} // namespace vt::model
