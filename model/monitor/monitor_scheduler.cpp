#include "monitor_scheduler.h"

#include "dict/monitor_defaults.h"

#include <QPointer>
#include <algorithm>
#include <cmath>

namespace vt::model {

namespace {

constexpr qint64 kSecondNs = 1'000'000'000;

} // namespace

std::vector<const dev::ParamMeta *> defaultMonitorRows(const dev::Dictionary &dictionary,
                                                       const std::string &mode)
{
    std::vector<const dev::ParamMeta *> rows;
    for (const std::string &name : dictionary.monitor.forMode(mode).channels) {
        const dev::ParamMeta *row = dictionary.find(name);
        if (row && row->readable() && !row->isString())
            rows.push_back(row);
    }
    return rows;
}

MonitorScheduler::MonitorScheduler(DeviceAccess &access, QObject *parent)
    : QObject(parent), m_access(access), m_accessAlive(&access)
{
    qRegisterMetaType<vt::model::MonitorSample>();
}

MonitorScheduler::~MonitorScheduler()
{
    stop();
}

void MonitorScheduler::setModule(int module, std::vector<const dev::ParamMeta *> rows, double hz)
{
    if (rows.empty()) {
        removeModule(module);
        return;
    }
    auto &slot = m_channels[module];
    if (!slot) {
        slot = std::make_unique<Channel>();
        slot->timer = std::make_unique<QTimer>();
        slot->timer->setSingleShot(true);
        slot->timer->setTimerType(Qt::PreciseTimer);
        connect(slot->timer.get(), &QTimer::timeout, this, [this, module] { poll(module); });
    }
    slot->module = module;
    slot->rows = std::move(rows);
    slot->hz = std::isfinite(hz) && hz > 0 ? std::min(hz, 10'000.0) : 0;
    slot->recent.clear();
    if (m_running) {
        slot->nextDueNs = m_access.session().elapsedNs();
        arm(*slot);
    }
}

void MonitorScheduler::removeModule(int module)
{
    auto it = m_channels.find(module);
    if (it == m_channels.end())
        return;
    if (it->second->handle)
        it->second->handle->cancel();
    m_channels.erase(it);
}

void MonitorScheduler::start()
{
    if (m_running)
        return;
    m_running = true;
    const qint64 now = m_access.session().elapsedNs();
    for (auto &[module, channel] : m_channels) {
        channel->nextDueNs = now;
        channel->recent.clear();
        arm(*channel);
    }
}

void MonitorScheduler::stop()
{
    m_running = false;
    for (auto &[module, channel] : m_channels) {
        channel->timer->stop();
        if (channel->handle)
            channel->handle->cancel();
    }
}

void MonitorScheduler::arm(Channel &channel)
{
    if (!m_running || channel.inFlight || !m_accessAlive)
        return;
    const qint64 now = m_access.session().elapsedNs();
    const qint64 waitNs = std::max<qint64>(0, channel.nextDueNs - now);
    channel.timer->start(static_cast<int>(waitNs / 1'000'000));
}

void MonitorScheduler::poll(int module)
{
    auto it = m_channels.find(module);
    if (!m_running || it == m_channels.end() || !m_accessAlive)
        return;
    Channel &channel = *it->second;
    if (channel.inFlight) {
        ++channel.skipped;
        return;
    }
    const qint64 now = m_access.session().elapsedNs();
    if (channel.hz > 0) {
        const auto periodNs = static_cast<qint64>(std::llround(1e9 / channel.hz));
        channel.nextDueNs += periodNs;
        if (channel.nextDueNs < now) { // behind: skip the missed slots, keep the phase
            const qint64 missed = (now - channel.nextDueNs) / periodNs + 1;
            channel.skipped += static_cast<quint64>(missed);
            channel.nextDueNs += missed * periodNs;
        }
    }
    channel.inFlight = true;
    channel.handle = m_access.read(
        module, channel.rows, Priority::Monitor,
        [this, self = QPointer<MonitorScheduler>(this), module](const ReadResult &result) {
            // The answer on the wire when the scheduler went still completes (cancelled).
            if (!self)
                return;
            auto found = m_channels.find(module);
            if (found == m_channels.end())
                return;
            Channel &ch = *found->second;
            ch.inFlight = false;
            ch.handle.reset();
            // The connection is gone (its session ended every read): nothing to poll.
            if (!m_accessAlive)
                return;
            const qint64 t = m_access.session().elapsedNs();
            if (result.values.size() == ch.rows.size() && !ch.rows.empty()) {
                ++ch.samples;
                ch.recent.push_back(t);
                while (!ch.recent.empty() && ch.recent.front() < t - kSecondNs)
                    ch.recent.pop_front();
                MonitorSample sample;
                sample.module = module;
                sample.seconds = static_cast<double>(t) * 1e-9;
                sample.rows = ch.rows;
                for (const RowValue &v : result.values)
                    sample.values.push_back(v.value);
                emit sampled(sample);
            } else if (!result.cancelled) {
                ++ch.failed;
                const QString reason = result.failures.empty()
                                           ? tr("incomplete answer")
                                           : result.failures.front().outcome.reason;
                emit pollFailed(module, reason);
            }
            if (ch.hz <= 0)
                ch.nextDueNs = t;
            arm(ch);
        });
}

double MonitorScheduler::achievedRate(int module) const
{
    const Channel *channel = find(module);
    if (!channel || channel->recent.size() < 2)
        return 0;
    const qint64 span = channel->recent.back() - channel->recent.front();
    return span > 0
               ? static_cast<double>(channel->recent.size() - 1) * 1e9 / static_cast<double>(span)
               : 0;
}

double MonitorScheduler::requestedRate(int module) const
{
    const Channel *channel = find(module);
    return channel ? channel->hz : 0;
}

quint64 MonitorScheduler::samples(int module) const
{
    const Channel *channel = find(module);
    return channel ? channel->samples : 0;
}

quint64 MonitorScheduler::skipped(int module) const
{
    const Channel *channel = find(module);
    return channel ? channel->skipped : 0;
}

quint64 MonitorScheduler::failed(int module) const
{
    const Channel *channel = find(module);
    return channel ? channel->failed : 0;
}

const MonitorScheduler::Channel *MonitorScheduler::find(int module) const
{
    auto it = m_channels.find(module);
    return it == m_channels.end() ? nullptr : it->second.get();
}

} // namespace vt::model
