// DeviceController: Device ▸ Connect / Disconnect / Scan / Read All / Write Changes / Revert /
// Compare with Device for the main window — progress dialogs, confirmations and results around
// the Workspace's connection and the editor's jobs. Dialogs open window-modal and non-blocking
// (open(), not exec()), so the tests drive the same code. GUI thread.
#pragma once

#include "model/session/connection.h"
#include "model/session/write_record.h"

#include <QObject>
#include <QPointer>

class QMessageBox;
class QProgressDialog;
class QWidget;

namespace vt::model {
class ReadAllJob;
}

namespace vt::ui {
class WriteDialog;
}

namespace vt::app {

class AppSettings;
class Workspace;

class DeviceController : public QObject
{
    Q_OBJECT
public:
    DeviceController(Workspace &workspace, AppSettings &settings, QWidget *window);
    ~DeviceController() override;

    void connectDialog();
    void connectTo(const model::ConnectionSpec &spec);
    void disconnectFromDevice();
    void scan();
    void readAll();
    // Opens the write confirmation (nullptr when there is nothing to write; the status says why).
    ui::WriteDialog *writeChanges();
    void compareWithDevice();

    model::ReadAllJob *readJob() const { return m_read; }
    // The message that says why the last connect failed (nullptr when none is open).
    QMessageBox *connectFailure() const { return m_failure; }

signals:
    void statusMessage(const QString &text);
    void readFinished(bool complete);
    // A write ended; the monitor's tuning journal marks what reached the device.
    void written(int address, const std::vector<vt::model::WriteItem> &items);

private:
    void showConnectFailure(const QString &reason);

    Workspace &m_workspace;
    AppSettings &m_settings;
    QWidget *m_window;
    model::ReadAllJob *m_read = nullptr;
    QPointer<QProgressDialog> m_progress;
    QPointer<QMessageBox> m_failure;
};

} // namespace vt::app
