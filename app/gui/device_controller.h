// DeviceController: Device ▸ Connect / Disconnect / Scan / Read All / Write Changes / Revert /
// Compare with Device for the main window — progress dialogs, confirmations and results around
// the Workspace's connection and the editor's jobs. Dialogs open window-modal and non-blocking
// (open(), not exec()), so the tests drive the same code. GUI thread.
#pragma once

#include "model/session/connection.h"
#include "model/session/write_record.h"

#include <QObject>
#include <QPointer>
#include <functional>

class QProgressDialog;
class QWidget;

namespace vt::model {
class ReadAllJob;
}

namespace vt::ui {
class CompareDialog;
class WriteDialog;
} // namespace vt::ui

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
    // Opens the write confirmation. Rows whose device value is not known now are read first
    // (progress, cancel): the confirmation never offers a row "(unknown)". Returns the dialog
    // when nothing had to be read, else nullptr and writeDialogOpened() follows; nullptr and
    // no dialog when there is nothing to write (the status says why).
    ui::WriteDialog *writeChanges();
    // Reads the compared rows (every readable setting of the online modules) from the device
    // first, then opens the comparison (compareDialogOpened()).
    void compareWithDevice();

    model::ReadAllJob *readJob() const { return m_read; }

signals:
    void statusMessage(const QString &text);
    void readFinished(bool complete);
    void writeDialogOpened(vt::ui::WriteDialog *dialog);
    void compareDialogOpened(vt::ui::CompareDialog *dialog);
    // A write ended; the monitor's tuning journal marks what reached the device.
    void written(int address, const std::vector<vt::model::WriteItem> &items);

private:
    // Reads rows of the document's online modules (all readable rows without `rows`) with a
    // progress dialog; `then(complete, problems)` after.
    void readRows(const QString &label, std::function<std::vector<const dev::ParamMeta *>(int)> rows,
                  std::function<void(bool, const QStringList &)> then);
    ui::WriteDialog *openWriteDialog();

    Workspace &m_workspace;
    AppSettings &m_settings;
    QWidget *m_window;
    model::ReadAllJob *m_read = nullptr;
    QPointer<QProgressDialog> m_progress;
};

} // namespace vt::app
