// Puts a MonitorScheduler's samples of one module into a bounded SampleStore, cooked to display
// units (raw × scale) so the plot and the CSV export read what the engineer reads. Same thread as
// the scheduler; the store must outlive the connection (disconnect it, or destroy the scheduler,
// before the store goes).
#pragma once

#include "core/local_text.h"
#include "model/monitor/monitor_scheduler.h"
#include "model/monitor/sample_store.h"

namespace vt::model {

// One channel per row: id = the row's name ("d1.11"), name = its label, unit = its unit.
QList<SampleChannel> monitorChannels(const std::vector<const dev::ParamMeta *> &rows,
                                     dev::Language lang);

// Appends every complete sample of `module` whose rows match the store's channels.
QMetaObject::Connection recordSamples(MonitorScheduler &scheduler, int module, SampleStore &store);

} // namespace vt::model
