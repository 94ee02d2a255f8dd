// MapReportDialog: shown when a file from another version (or with rows this dictionary does not
// know) is opened — per module the summary and every row that did not map plainly, with its
// reason. Rows that did not map stay in the file and are written back on save.
#pragma once

#include "core/local_text.h"

#include <QDialog>

namespace vt::model {
class ParameterDocument;
}

namespace vt::ui {

class MapReportDialog : public QDialog
{
    Q_OBJECT
public:
    MapReportDialog(const model::ParameterDocument &document, QWidget *parent = nullptr);
    // True when something did not map (the dialog is worth showing).
    static bool needed(const model::ParameterDocument &document);
    const QString &text() const { return m_text; }

private:
    QString m_text;
};

} // namespace vt::ui
