// The commissioning report from the GUI (File ▸ Commissioning Report…): makes the report of what
// the workspace holds — the device's values of every module paired with the node
// when connected, else the document (what Save would write) — with the workbench runs and the
// reference file the dialog chose, in the language it chose (widgets/report/report_dialog.h). The
// write log is this session's log on disk (model/audit: every write from any window); the drift is
// the Workbench's last comparison with a reference fingerprint, when the person keeps it ticked.
// Owner: the main window; GUI thread.
#pragma once

#include <QObject>
#include <QString>

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

private:
    Workspace &m_workspace;
    Language &m_language;
    ui::WorkbenchView &m_workbench;
};

} // namespace vt::app
