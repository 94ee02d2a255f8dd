// MapReportDialog: shown when a file from another version (or with rows this dictionary does not
// know) is opened, or when its modules do not pair plainly with the connected node's — which
// document module goes to which device module, then per module the summary and every row that
// did not map plainly, with its reason. Rows that did not map stay in the file and are written
// back on save.
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
    // `pairing`: ParameterDocument::attachDevice's report (empty when not connected).
    MapReportDialog(const model::ParameterDocument &document, const QStringList &pairing = {},
                    QWidget *parent = nullptr);
    // True when something did not map or pair (the dialog is worth showing).
    static bool needed(const model::ParameterDocument &document, const QStringList &pairing = {});
    const QString &text() const { return m_text; }

private:
    QString m_text;
};

} // namespace vt::ui
