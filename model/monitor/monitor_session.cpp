#include "monitor_session.h"

#include "model/monitor/monitor_recording.h"
#include "model/session/connection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vt::model {

std::vector<const dev::ParamMeta *> monitorableRows(const ModuleInfo &module)
{
    std::vector<const dev::ParamMeta *> rows;
    if (!module.dictionary)
        return rows;
    const auto readable =
        readableRows(*module.dictionary, module.identification.version, module.identification.mode);
    // HCS display values are block d; the Wandfluh dictionaries have no d block, their live
    // values are the read-only rows.
    const bool hasDisplayBlock =
        std::any_of(readable.begin(), readable.end(),
                    [](const dev::ParamMeta *row) { return row->block == "d"; });
    for (const dev::ParamMeta *row : readable) {
        if (row->isString())
            continue;
        if (hasDisplayBlock ? row->block == "d" : row->access == dev::Access::Read)
            rows.push_back(row);
    }
    return rows;
}

MonitorSession::MonitorSession(QObject *parent) : QObject(parent)
{
}

MonitorSession::~MonitorSession()
{
    // The stores' feeds are connections on the scheduler: it goes first.
    m_scheduler.reset();
}

void MonitorSession::setConnection(Connection *connection, std::vector<ModuleInfo> modules)
{
    clearConnection();
    m_connection = connection;
    m_modules = std::move(modules);
    m_recordings.clear();
    m_journal.clear();
    if (!m_connection)
        return;
    m_scheduler = std::make_unique<MonitorScheduler>(m_connection->access());
    connect(m_scheduler.get(), &MonitorScheduler::sampled, this,
            [this](const MonitorSample &sample) { emit sampled(sample.module); });
    connect(m_scheduler.get(), &MonitorScheduler::pollFailed, this, &MonitorSession::pollFailed);
    for (const ModuleInfo &info : m_modules) {
        if (info.dictionary) {
            setChannels(info.address,
                        defaultMonitorRows(*info.dictionary, info.identification.mode));
            break;
        }
    }
    emit channelsChanged();
}

void MonitorSession::clearConnection()
{
    const bool wasRunning = isRunning();
    for (auto &[module, recording] : m_recordings) {
        QObject::disconnect(recording.feed);
        recording.feed = {};
    }
    m_scheduler.reset(); // stops polling, cancels the read on the wire
    m_connection = nullptr;
    if (wasRunning)
        emit runningChanged(false);
}

const ModuleInfo *MonitorSession::module(int address) const
{
    for (const ModuleInfo &info : m_modules) {
        if (info.address == address)
            return &info;
    }
    return nullptr;
}

void MonitorSession::setStoreCapacity(qsizetype rows)
{
    m_capacity = std::max<qsizetype>(1, rows);
    for (auto &[module, recording] : m_recordings)
        rebuild(module, recording);
    emit channelsChanged();
}

void MonitorSession::rebuild(int module, Recording &recording)
{
    QObject::disconnect(recording.feed);
    recording.feed = {};
    recording.store =
        std::make_unique<SampleStore>(monitorChannels(recording.rows, m_lang), m_capacity);
    if (m_scheduler)
        recording.feed = recordSamples(*m_scheduler, module, *recording.store);
    if (isRunning())
        recording.store->makeResident();
}

void MonitorSession::setChannels(int module, std::vector<const dev::ParamMeta *> rows)
{
    if (rows.empty()) {
        auto it = m_recordings.find(module);
        if (it != m_recordings.end()) {
            QObject::disconnect(it->second.feed);
            m_recordings.erase(it);
        }
    } else {
        Recording &recording = m_recordings[module];
        recording.rows = std::move(rows);
        rebuild(module, recording);
    }
    applyToScheduler(module);
    emit channelsChanged();
}

void MonitorSession::applyToScheduler(int module)
{
    if (!m_scheduler)
        return;
    auto it = m_recordings.find(module);
    if (it == m_recordings.end())
        m_scheduler->removeModule(module);
    else
        m_scheduler->setModule(module, it->second.rows, m_hz);
}

std::vector<const dev::ParamMeta *> MonitorSession::channels(int module) const
{
    auto it = m_recordings.find(module);
    return it == m_recordings.end() ? std::vector<const dev::ParamMeta *>{} : it->second.rows;
}

std::vector<int> MonitorSession::monitoredModules() const
{
    std::vector<int> out;
    for (const auto &[module, recording] : m_recordings)
        out.push_back(module);
    return out;
}

const SampleStore *MonitorSession::store(int module) const
{
    auto it = m_recordings.find(module);
    return it == m_recordings.end() ? nullptr : it->second.store.get();
}

qint64 MonitorSession::memoryBytes() const
{
    qint64 bytes = 0;
    for (const auto &[module, recording] : m_recordings)
        bytes += recording.store->memoryBytes();
    return bytes;
}

void MonitorSession::setRate(double hz)
{
    m_hz = std::isfinite(hz) && hz > 0 ? hz : 0;
    for (const auto &[module, recording] : m_recordings)
        applyToScheduler(module);
}

void MonitorSession::start()
{
    if (!m_scheduler || m_scheduler->isRunning())
        return;
    // The stores' hour becomes resident now, not 28 B a poll over the hour (docs/PERFORMANCE.md,
    // "GUI resident memory over 30 minutes").
    for (auto &[module, recording] : m_recordings)
        recording.store->makeResident();
    m_scheduler->start();
    emit runningChanged(true);
}

void MonitorSession::stop()
{
    if (!m_scheduler || !m_scheduler->isRunning())
        return;
    m_scheduler->stop();
    emit runningChanged(false);
}

double MonitorSession::achievedRate(int module) const
{
    return m_scheduler ? m_scheduler->achievedRate(module) : 0.0;
}

quint64 MonitorSession::samples(int module) const
{
    return m_scheduler ? m_scheduler->samples(module) : 0;
}

double MonitorSession::now() const
{
    if (m_connection)
        return static_cast<double>(m_connection->session().elapsedNs()) / 1e9;
    const double last = lastTime();
    return std::isnan(last) ? 0.0 : last;
}

double MonitorSession::firstTime() const
{
    double t = std::numeric_limits<double>::quiet_NaN();
    for (const auto &[module, recording] : m_recordings) {
        const double first = recording.store->firstTime();
        if (!std::isnan(first) && (std::isnan(t) || first < t))
            t = first;
    }
    return t;
}

double MonitorSession::lastTime() const
{
    double t = std::numeric_limits<double>::quiet_NaN();
    for (const auto &[module, recording] : m_recordings) {
        const double last = recording.store->lastTime();
        if (!std::isnan(last) && (std::isnan(t) || last > t))
            t = last;
    }
    return t;
}

void MonitorSession::journalWrites(int module, const std::vector<WriteItem> &items)
{
    if (m_journal.addWrites(now(), module, items, m_lang, m_modules.size() > 1) > 0)
        emit journalChanged();
}

void MonitorSession::clearRecording()
{
    for (auto &[module, recording] : m_recordings)
        recording.store->clear();
    m_journal.clear();
    emit journalChanged();
    emit channelsChanged();
}

} // namespace vt::model
