// The commissioning report from the GUI (File ▸ Commissioning Report…): keeps the writes of this
// session (every result DeviceController reports) for the report's write log, and makes the
// report of what the workspace holds — the device's values of every module paired with the node
// when connected, else the document (what Save would write) — with the workbench runs and the
// reference file the dialog chose, in the language it chose (widgets/report/report_dialog.h).
// Owner: the main window; GUI thread.
#pragma once

#include "model/report/report_data.h"
#include "model/session/write_record.h"

#include <QObject>
#include <QString>
#include <vector>

namespace vt::ui {
class WorkbenchView;
struct ReportChoice;
} // namespace vt::ui

namespace vt::app {

class Language;
class Workspace;

class ReportController : public QObject
{
    Q_OBJECT
public:
    ReportController(Workspace &workspace, Language &language, ui::WorkbenchView &workbench,
                     QObject *parent = nullptr);
    ~ReportController() override;

    void openDialog(QWidget *parent);
    // A write job's results for module `address`: one write log entry per row that was sent.
    void recordWrites(int address, const std::vector<model::WriteItem> &items);
    const std::vector<model::ReportWrite> &writes() const { return m_writes; }

private:
    Workspace &m_workspace;
    Language &m_language;
    ui::WorkbenchView &m_workbench;
    std::vector<model::ReportWrite> m_writes;
};

} // namespace vt::app
