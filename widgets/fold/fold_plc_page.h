// Fold wizard page 7: the PLC configuration of the plan (GSD/GSDML file and module, output and
// input image byte by byte, control and status bits per module, example CMD 15 telegram) as the
// printable sheet, with export to PDF, HTML and CSV and saving the plan as a .vtfold file.
#pragma once

#include "widgets/fold/fold_page.h"

#include <QString>

class QLabel;
class QPushButton;
class QTextBrowser;

namespace vt::ui {

class FoldPlcPage : public FoldPage
{
    Q_OBJECT
public:
    explicit FoldPlcPage(QWidget *parent = nullptr);
    void initializePage() override;

    // Each returns an empty string on success, else why (in the UI language).
    QString exportPdf(const QString &path);
    QString exportHtml(const QString &path);
    QString exportCsv(const QString &path);
    QString savePlan(const QString &path);

    QString sheetHtml() const { return m_html; }

protected:
    void retranslate() override;

private:
    void refresh();
    void ask(const QString &title, const QString &filter, const QString &suffix,
             QString (FoldPlcPage::*write)(const QString &));

    QTextBrowser *m_view = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_pdf = nullptr;
    QPushButton *m_htmlButton = nullptr;
    QPushButton *m_csv = nullptr;
    QPushButton *m_save = nullptr;
    QString m_html;
};

} // namespace vt::ui
