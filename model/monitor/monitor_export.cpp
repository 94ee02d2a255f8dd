#include "monitor_export.h"

#include <QCoreApplication>
#include <QIODevice>
#include <algorithm>
#include <limits>

namespace vt::model {

namespace {

struct Source
{
    const SampleStore *store = nullptr;
    int firstColumn = 0; // of the merged store
    qsizetype next = 0;  // row
    qsizetype end = 0;
};

} // namespace

std::optional<SampleStore> mergedRecording(const MonitorSession &session, double t0, double t1)
{
    const std::vector<int> modules = session.monitoredModules();
    if (modules.empty())
        return std::nullopt;
    const bool prefix = modules.size() > 1;
    QList<SampleChannel> channels;
    std::vector<Source> sources;
    qsizetype rows = 0;
    for (int module : modules) {
        const SampleStore *store = session.store(module);
        Source source{store, static_cast<int>(channels.size()), store->lowerBound(t0),
                      store->upperBound(t1)};
        rows += source.end - source.next;
        sources.push_back(source);
        for (SampleChannel channel : store->channels()) {
            if (prefix)
                channel.id = QStringLiteral("%1/%2").arg(module).arg(channel.id);
            channels.append(channel);
        }
    }
    SampleStore merged(channels, std::max<qsizetype>(1, rows));
    std::vector<double> values(static_cast<std::size_t>(channels.size()));
    for (;;) {
        // The source whose next row is earliest; few modules, so a linear pick is enough.
        Source *pick = nullptr;
        for (Source &s : sources) {
            if (s.next < s.end &&
                (!pick || s.store->timeAt(s.next) < pick->store->timeAt(pick->next)))
                pick = &s;
        }
        if (!pick)
            break;
        std::fill(values.begin(), values.end(), std::numeric_limits<double>::quiet_NaN());
        for (int c = 0; c < pick->store->channelCount(); ++c)
            values[static_cast<std::size_t>(pick->firstColumn + c)] =
                pick->store->valueAt(c, pick->next);
        merged.append(pick->store->timeAt(pick->next), values);
        ++pick->next;
    }
    for (const SampleMarker &marker : session.journal().markersIn(t0, t1))
        merged.addMarker(marker.t, marker.text);
    return merged;
}

bool writeMonitorCsv(const MonitorSession &session, QIODevice &out, double t0, double t1,
                     QString *error)
{
    const auto merged = mergedRecording(session, t0, t1);
    if (!merged) {
        if (error)
            *error = QCoreApplication::translate("vt::model::MonitorSession",
                                                 "No channels are monitored.");
        return false;
    }
    return merged->writeCsv(out, error);
}

} // namespace vt::model
