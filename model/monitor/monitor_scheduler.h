// MonitorScheduler: polls the display values of modules at a requested rate per module (one
// request for d1.07..d1.13 on HCS: ARCHITECTURE.md "Monitor"), at monitor priority so user
// actions go first, and reports each sample and the rate actually achieved. A poll is never
// queued behind its own predecessor: when the link cannot keep up, samples are skipped and
// the achieved rate says so. Owner: whoever polls — a MonitorSession for the monitor, the GUI's
// Workspace for the editor's live display values; same thread as the DeviceAccess. It may go
// before the connection (its poll on the wire completes into nothing) or after it (the session's
// end completes that poll cancelled, and nothing is polled any more; only destroy it then).
#pragma once

#include "model/session/device_access.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <deque>
#include <map>
#include <memory>

namespace vt::model {

// The channels the family's dictionary names for `mode` ("monitor"."channels", docs/DICTIONARY.md
// "Monitor defaults"), in that order; empty when it names none.
std::vector<const dev::ParamMeta *> defaultMonitorRows(const dev::Dictionary &dictionary,
                                                       const std::string &mode);

struct MonitorSample
{
    int module = 0;
    double seconds = 0; // session time (Session::elapsedNs) when the answer arrived
    std::vector<const dev::ParamMeta *> rows;
    std::vector<dev::RawValue> values; // one per row
};

class MonitorScheduler : public QObject
{
    Q_OBJECT
public:
    explicit MonitorScheduler(DeviceAccess &access, QObject *parent = nullptr);
    ~MonitorScheduler() override;

    // Polls `rows` of `module` at `hz` (0: back to back, as fast as the link allows). Replaces
    // an earlier setting of the same module. Empty rows remove the module.
    void setModule(int module, std::vector<const dev::ParamMeta *> rows, double hz);
    void removeModule(int module);
    void start();
    void stop();
    bool isRunning() const { return m_running; }

    // Samples per second over the last second (0 before two samples).
    double achievedRate(int module) const;
    double requestedRate(int module) const;
    quint64 samples(int module) const;
    quint64 skipped(int module) const; // polls due while the previous one was still out
    quint64 failed(int module) const;

signals:
    void sampled(const vt::model::MonitorSample &sample);
    void pollFailed(int module, const QString &reason);

private:
    struct Channel
    {
        int module = 0;
        std::vector<const dev::ParamMeta *> rows;
        double hz = 0;
        bool inFlight = false;
        qint64 nextDueNs = 0;
        std::unique_ptr<QTimer> timer;
        std::deque<qint64> recent; // answer times within the last second
        quint64 samples = 0, skipped = 0, failed = 0;
        std::shared_ptr<DeviceAccess::ReadHandle> handle;
    };

    void arm(Channel &channel);
    void poll(int module);
    const Channel *find(int module) const;

    DeviceAccess &m_access;
    QPointer<DeviceAccess> m_accessAlive; // null once the connection destroyed the access
    std::map<int, std::unique_ptr<Channel>> m_channels;
    bool m_running = false;
};

} // namespace vt::model

Q_DECLARE_METATYPE(vt::model::MonitorSample)
