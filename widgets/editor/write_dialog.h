// WriteDialog: Device ▸ Write Changes — first a confirmation listing every change in display
// units (module, parameter, device value → new value), then the write's progress and a result
// per parameter (verified / refused with the device's reason / failed …), cancellable. The job
// itself is model::WriteChangesJob; this dialog only shows it. GUI thread.
#pragma once

#include "model/params/device_jobs.h"

#include <QDialog>

class QDialogButtonBox;
class QLabel;
class QProgressBar;
class QTableWidget;

namespace vt::ui {

class WriteDialog : public QDialog
{
    Q_OBJECT
public:
    WriteDialog(model::DeviceAccess &access, model::ParameterDocument &document,
                std::vector<model::ModuleWriteResult> plan, QWidget *parent = nullptr);
    ~WriteDialog() override;

    // What the "Write" button does: rows that can move the valve are confirmed once more on
    // their own, then the write starts.
    void confirm();
    bool isWriting() const;
    bool finishedWriting() const { return m_finished; }
    QTableWidget *table() const { return m_table; }
    const model::WriteChangesJob &job() const { return *m_job; }

signals:
    // The write ended; every row's outcome is in job().results().
    void writeFinished(bool complete);

protected:
    void reject() override;

private:
    void start();
    void fillConfirmation();
    void showItem(int module, int index);

    model::ParameterDocument &m_document;
    model::WriteChangesJob *m_job = nullptr;
    std::vector<std::pair<int, int>> m_rowOf; // table row → (plan entry, item index)
    QLabel *m_intro = nullptr;
    QTableWidget *m_table = nullptr;
    QProgressBar *m_progress = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    bool m_started = false;
    bool m_finished = false;
};

} // namespace vt::ui
