// DeviceStateControl: drives the DSP-408 device state machine of a Wandfluh ED1/SD1 or SD7
// (ED1/SD1 manual and HART-7 manual §4.2.2: INIT, DISABLED, HOLD, DEVICE_MODE_ACTIVE;
// db_ControlWord bits D, H, M, "reset fault") and where the device takes its control word and set
// value from ("Device local" db_Local, "Device mode" db_DeviceMode) from the node view — each a
// valve-moving write, so it is confirmed first (widgets/actuator_confirm.h), written through a
// WriteJob (range check, read back where the row is readable; the image records it for the
// actuator ledger) and journalled like every other write.
// Owner: the main window; GUI thread. The workspace must outlive it.
#pragma once

#include "model/session/write_record.h"

#include <QObject>
#include <QPointer>
#include <memory>
#include <vector>

class QWidget;

namespace vt::model {
class WriteJob;
}

namespace vt::app {

class Workspace;

class DeviceStateControl : public QObject
{
    Q_OBJECT
public:
    DeviceStateControl(Workspace &workspace, QWidget *window);
    ~DeviceStateControl() override;

    // Asks, then writes `controlWord` to db_ControlWord of the document's module `moduleIndex`
    // (online, DSP-408). "Reset fault" is the last control word written with bit R set, so the
    // 0 → 1 edge of §4.2.2 TR_10 / TR_11 reaches the device without changing D, H, M.
    void request(int moduleIndex, quint16 controlWord);
    void resetFault(int moduleIndex);
    // Asks, then writes raw `value` to `rowName` (db_Local, db_DeviceMode) and reads it back.
    void requestValue(int moduleIndex, const QString &rowName, double value);

signals:
    void statusMessage(const QString &text);
    void written(int address, const std::vector<vt::model::WriteItem> &items);

private:
    void write(int moduleIndex, const dev::ParamMeta &row, double value);

    Workspace &m_workspace;
    QPointer<QWidget> m_window;
    std::unique_ptr<model::WriteJob> m_job;
};

} // namespace vt::app
