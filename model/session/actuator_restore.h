// ActuatorRestore: puts an ActuatorLedger's original values back, module after module, through
// the safe write (range check, pacing, read back), and keeps per row what happened — for the
// report after stop, disconnect or quit. GUI thread; the DeviceAccess must outlive it.
#pragma once

#include "dict/dictionary.h"
#include "model/session/device_access.h"
#include "model/session/write_job.h"

#include <QObject>
#include <map>
#include <memory>
#include <vector>

namespace vt::model {

struct RestoredRow
{
    int module = 0;
    WriteItem item; // status says whether it is back on the device
};

class ActuatorRestore : public QObject
{
    Q_OBJECT
public:
    // `plan`: ActuatorLedger::restorePlan(); `dictionaries`: each module's dictionary.
    ActuatorRestore(DeviceAccess &access, std::map<int, std::vector<WriteItem>> plan,
                    std::map<int, const dev::Dictionary *> dictionaries, QObject *parent = nullptr);
    ~ActuatorRestore() override;

    void start();
    const std::vector<RestoredRow> &results() const { return m_results; }
    bool complete() const;

signals:
    void finished(bool complete);

private:
    void next();

    DeviceAccess &m_access;
    std::map<int, std::vector<WriteItem>> m_plan;
    std::map<int, const dev::Dictionary *> m_dictionaries;
    std::unique_ptr<WriteJob> m_job;
    std::vector<RestoredRow> m_results;
};

} // namespace vt::model
