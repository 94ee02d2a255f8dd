// CompareDialog: File ▸ Compare — the open document against the device or another file, one row
// per differing parameter with a "take other" choice, applied to the document as one undo step.
#pragma once

#include "files/param_file.h"

#include <QDialog>

class QLabel;
class QPushButton;
class QTableView;

namespace vt::model {
class CompareModel;
class ParameterDocument;
} // namespace vt::model

namespace vt::ui {

class CompareDialog : public QDialog
{
    Q_OBJECT
public:
    CompareDialog(model::ParameterDocument &document, QWidget *parent = nullptr);

    model::CompareModel *compareModel() const { return m_model; }
    QTableView *table() const { return m_table; }
    // Sets the comparison; the dialog's summary line follows.
    void compareWithDevice();
    void compareWithFile(const dev::files::ParamFile &file, const QString &name);

    QPushButton *applyButton() const { return m_apply; }
    QPushButton *tickAllButton() const { return m_tickAll; }
    QPushButton *tickNoneButton() const { return m_tickNone; }
    QPushButton *closeButton() const { return m_close; }
    QLabel *effectLabel() const { return m_effect; }

private:
    void updateSummary();
    void updateApply();

    model::CompareModel *m_model = nullptr;
    QTableView *m_table = nullptr;
    QLabel *m_summary = nullptr;
    QLabel *m_effect = nullptr;
    QPushButton *m_apply = nullptr;
    QPushButton *m_tickAll = nullptr;
    QPushButton *m_tickNone = nullptr;
    QPushButton *m_close = nullptr;
};

} // namespace vt::ui
