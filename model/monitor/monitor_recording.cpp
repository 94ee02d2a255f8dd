#include "monitor_recording.h"

#include "dict/cooking.h"

#include <limits>

namespace vt::model {

QList<SampleChannel> monitorChannels(const std::vector<const dev::ParamMeta *> &rows,
                                     dev::Language lang)
{
    QList<SampleChannel> channels;
    for (const dev::ParamMeta *row : rows) {
        channels.append(SampleChannel{QString::fromStdString(row->name),
                                      QString::fromStdString(row->label.in(lang)),
                                      QString::fromStdString(row->unit)});
    }
    return channels;
}

QMetaObject::Connection recordSamples(MonitorScheduler &scheduler, int module, SampleStore &store)
{
    return QObject::connect(
        &scheduler, &MonitorScheduler::sampled, &scheduler,
        [module, &store](const MonitorSample &sample) {
            if (sample.module != module ||
                sample.rows.size() != static_cast<std::size_t>(store.channelCount()))
                return;
            std::vector<double> values;
            values.reserve(sample.rows.size());
            for (std::size_t i = 0; i < sample.rows.size(); ++i) {
                values.push_back(
                    dev::isText(sample.values[i])
                        ? std::numeric_limits<double>::quiet_NaN()
                        : dev::toDisplay(*sample.rows[i], dev::rawNumber(sample.values[i])));
            }
            store.append(sample.seconds, values);
        });
}

} // namespace vt::model
