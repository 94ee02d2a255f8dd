// ActuatorLedger: the rows that can move the actuator (set values, the set-value source, control
// words) which this tool changed on the connected node, each with what it held before the first
// change — so that stop, disconnect and quit can offer to put them back. Fed by the device image:
// every acknowledged write of such a row, whichever window sent it, is in here.
// Owner: the workspace (GUI) next to its DeviceImage, which must outlive it; GUI thread.
#pragma once

#include "model/session/device_image.h"
#include "model/session/write_record.h"

#include <QObject>
#include <map>
#include <optional>
#include <vector>

namespace vt::model {

struct ActuatorChange
{
    int module = 0;
    const dev::ParamMeta *row = nullptr;
    std::optional<dev::RawValue> original; // before the first change; unknown when never read
    dev::RawValue now;
};

class ActuatorLedger : public QObject
{
    Q_OBJECT
public:
    explicit ActuatorLedger(DeviceImage &image, QObject *parent = nullptr);
    ~ActuatorLedger() override;

    const std::vector<ActuatorChange> &changes() const { return m_changes; }
    bool empty() const { return m_changes.empty(); }
    void clear();

    // The writes that put every change with a known original back, per module address.
    std::map<int, std::vector<WriteItem>> restorePlan() const;
    // Changes whose original value is unknown: they cannot be put back.
    std::vector<ActuatorChange> unrestorable() const;

signals:
    void changed();

private:
    void onImageChanged(int module, const std::vector<ImageChange> &rows);

    DeviceImage &m_image;
    std::vector<ActuatorChange> m_changes;
};

} // namespace vt::model
