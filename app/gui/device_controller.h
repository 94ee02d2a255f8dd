// DeviceController: Device ▸ Connect / Disconnect / Scan / Read All / Write Changes / Revert /
// Compare with Device for the main window — progress dialogs, confirmations and results around
// the Workspace's connection and the editor's jobs. Dialogs open window-modal and non-blocking
// (open(), not exec()), so the tests drive the same code. GUI thread.
#pragma once

#include "model/session/connection.h"
#include "model/session/write_record.h"

#include <QMessageBox>
#include <QObject>
#include <QPointer>
#include <functional>
class QProgressDialog;
class QWidget;

namespace vt::model {
class ActuatorRestore;
class ReadAllJob;
} // namespace vt::model

namespace vt::ui {
class CompareDialog;
class ConnectDialog;
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
    // The connect dialog opened on one kind of link (the welcome page's "simulator").
    void connectDialogOn(model::ConnectionKind kind);
    void connectTo(const model::ConnectionSpec &spec);
    // Offers to put back the actuator-moving values this tool changed, then disconnects.
    void disconnectFromDevice();
    // When the tool changed actuator-moving values on the node (set values, the set-value
    // source, control words): asks whether to put them back (default yes), writes them back and
    // reports what is back and what is not; then `then()`. `when`: the sentence that says why
    // ("Before disconnecting:"). Without such changes `then()` runs at once.
    void offerRestore(const QString &when, std::function<void()> then);
    // What offerRestore() would ask about, one line per change ("Module 1: A1.01 (…) 2.000 V →
    // 0.000 V", or why a change cannot be put back); empty when offline or nothing changed.
    QStringList restoreLines() const;
    // Puts back what the ledger holds, without asking; reports it (lastRestore(),
    // statusMessage()), then `then()` — at once when offline or nothing is to be put back, after
    // the running put-back when one is on its way.
    void putBack(std::function<void()> then);
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
    // The message that says why the last connect failed (nullptr when none is open).
    QMessageBox *connectFailure() const { return m_failure; }
    // The report of the last put-back ("Put back: A1.01 on module 1.").
    const QString &lastRestore() const { return m_lastRestore; }

signals:
    void statusMessage(const QString &text);
    void readFinished(bool complete);
    void writeDialogOpened(vt::ui::WriteDialog *dialog);
    void compareDialogOpened(vt::ui::CompareDialog *dialog);
    // A write ended; the monitor's tuning journal marks what reached the device.
    void written(int address, const std::vector<vt::model::WriteItem> &items);

private:
    void showConnectFailure(const QString &reason);
    ui::ConnectDialog *openConnectDialog();
    // Reads rows of the document's online modules (all readable rows without `rows`) with a
    // progress dialog; `then(complete, problems, warnings)` after (warnings: values that arrived
    // with a device warning).
    void readRows(const QString &label,
                  std::function<std::vector<const dev::ParamMeta *>(int)> rows,
                  std::function<void(bool, const QStringList &, const QStringList &)> then);
    ui::WriteDialog *openWriteDialog();

    Workspace &m_workspace;
    AppSettings &m_settings;
    QWidget *m_window;
    model::ReadAllJob *m_read = nullptr;
    model::ActuatorRestore *m_restore = nullptr;
    QString m_lastRestore;
    QPointer<QProgressDialog> m_progress;
    QPointer<QMessageBox> m_failure;
};

} // namespace vt::app
