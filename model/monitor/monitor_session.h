// MonitorSession: the live monitor's model — which d-values of which modules are
// polled, at what rate, into one bounded SampleStore per module (display units), plus the tuning
// journal of parameter writes on the same time axis (Session::elapsedNs, in seconds).
// Owner: the MonitorView; GUI thread. It owns the MonitorScheduler it creates and stops it on
// clearConnection(); the stores survive a disconnect so the recording can still be exported.
#pragma once

#include "model/monitor/monitor_scheduler.h"
#include "model/monitor/sample_store.h"
#include "model/monitor/tuning_journal.h"
#include "model/session/device_access.h"

#include <QObject>
#include <map>
#include <memory>
#include <vector>

namespace vt::model {

class Connection;

// Every readable d-value of the module's version and mode (the channel chooser's list).
std::vector<const dev::ParamMeta *> monitorableRows(const ModuleInfo &module);

class MonitorSession : public QObject
{
    Q_OBJECT
public:
    explicit MonitorSession(QObject *parent = nullptr);
    ~MonitorSession() override;

    // `modules` are identified, each with its dictionary. Selects the default channels of the
    // first module; polling starts only with start().
    void setConnection(Connection *connection, std::vector<ModuleInfo> modules);
    // Stops polling and forgets the connection; the recorded samples stay. Call it before the
    // connection is destroyed: connection() would dangle (the scheduler itself is safe either way).
    void clearConnection();
    Connection *connection() const { return m_connection; }
    const std::vector<ModuleInfo> &modules() const { return m_modules; }
    const ModuleInfo *module(int address) const;

    // Rows per module store (default 1 h at 200 Hz). Rebuilds the stores: the recording is lost.
    void setStoreCapacity(qsizetype rows);
    qsizetype storeCapacity() const { return m_capacity; }
    // Channel names of new stores and journal texts.
    void setLanguage(dev::Language lang) { m_lang = lang; }
    dev::Language language() const { return m_lang; }

    // The rows polled from `module` (empty: none). Rebuilds that module's store, because a
    // store's rows share one timestamp per poll (SampleStore), so its earlier samples are lost.
    void setChannels(int module, std::vector<const dev::ParamMeta *> rows);
    std::vector<const dev::ParamMeta *> channels(int module) const;
    std::vector<int> monitoredModules() const; // with at least one channel, in address order
    const SampleStore *store(int module) const;
    // Every store's ring, channel list and markers (the stores' memory bound).
    qint64 memoryBytes() const;

    // 0 = back to back, as fast as the link allows.
    void setRate(double hz);
    double rate() const { return m_hz; }
    void start();
    void stop();
    bool isRunning() const { return m_scheduler && m_scheduler->isRunning(); }
    double achievedRate(int module) const;
    quint64 samples(int module) const;
    const MonitorScheduler *scheduler() const { return m_scheduler.get(); }

    // Seconds on the samples' time axis now; without a connection the last sample's time.
    double now() const;
    double firstTime() const; // earliest sample of all stores (NaN when empty)
    double lastTime() const;  // latest sample of all stores (NaN when empty)

    // Marks the items of a finished write that reached the device (TuningJournal::addWrites).
    void journalWrites(int module, const std::vector<WriteItem> &items);
    const TuningJournal &journal() const { return m_journal; }

    // Clears samples and journal (keeps channels and connection).
    void clearRecording();

signals:
    void sampled(int module);
    void channelsChanged();
    void journalChanged();
    void runningChanged(bool running);
    void pollFailed(int module, const QString &reason);

private:
    struct Recording
    {
        std::vector<const dev::ParamMeta *> rows;
        std::unique_ptr<SampleStore> store;
        QMetaObject::Connection feed;
    };

    void rebuild(int module, Recording &recording);
    void applyToScheduler(int module);

    Connection *m_connection = nullptr;
    std::vector<ModuleInfo> m_modules;
    std::unique_ptr<MonitorScheduler> m_scheduler;
    std::map<int, Recording> m_recordings;
    TuningJournal m_journal;
    qsizetype m_capacity = SampleStore::kDefaultCapacity;
    double m_hz = 50;
    dev::Language m_lang = dev::Language::English;
};

} // namespace vt::model
