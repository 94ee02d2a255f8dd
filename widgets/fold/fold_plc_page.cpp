#include "widgets/fold/fold_plc_page.h"

#include "model/fold/fold_export.h"
#include "model/fold/fold_plan_file.h"
#include "model/text_language.h"
#include "widgets/fold/fold_wizard.h"

#include <QCoreApplication>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSaveFile>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace vt::ui {

namespace {

QString writeText(const QString &path, const QByteArray &bytes)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit())
        return QCoreApplication::translate("vt::ui::FoldPlcPage", "Cannot write %1: %2")
            .arg(path, file.errorString());
    return {};
}

} // namespace

FoldPlcPage::FoldPlcPage(QWidget *parent) : FoldPage(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_view = new QTextBrowser(this);
    m_view->setObjectName(QStringLiteral("sheet"));
    layout->addWidget(m_view);
    auto *buttons = new QHBoxLayout;
    m_pdf = new QPushButton(this);
    m_htmlButton = new QPushButton(this);
    m_csv = new QPushButton(this);
    m_save = new QPushButton(this);
    m_save->setObjectName(QStringLiteral("savePlan"));
    for (QPushButton *b : {m_pdf, m_htmlButton, m_csv, m_save})
        buttons->addWidget(b);
    buttons->addStretch();
    layout->addLayout(buttons);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    connect(m_pdf, &QPushButton::clicked, this, [this] {
        ask(tr("Export PDF"), tr("PDF (*.pdf)"), QStringLiteral("pdf"), &FoldPlcPage::exportPdf);
    });
    connect(m_htmlButton, &QPushButton::clicked, this, [this] {
        ask(tr("Export HTML"), tr("HTML (*.html)"), QStringLiteral("html"),
            &FoldPlcPage::exportHtml);
    });
    connect(m_csv, &QPushButton::clicked, this, [this] {
        ask(tr("Export CSV"), tr("CSV (*.csv)"), QStringLiteral("csv"), &FoldPlcPage::exportCsv);
    });
    connect(m_save, &QPushButton::clicked, this, [this] {
        ask(tr("Save fold plan"), tr("Fold plan (*.vtfold)"),
            QString::fromLatin1(model::kFoldPlanSuffix.data(),
                                static_cast<int>(model::kFoldPlanSuffix.size())),
            &FoldPlcPage::savePlan);
    });
    retranslate();
}

void FoldPlcPage::initializePage()
{
    refresh();
}

void FoldPlcPage::refresh()
{
    if (!fold())
        return;
    model::PlcText why;
    const auto sheet = model::makeFoldSheet(fold()->plan(), &why);
    const bool ok = sheet.has_value();
    for (QPushButton *b : {m_pdf, m_htmlButton, m_csv})
        b->setEnabled(ok);
    if (!ok) {
        m_html.clear();
        m_view->setPlainText(model::plcText(why, model::textLanguage()));
        return;
    }
    m_html = model::foldSheetHtml(*sheet, model::textLanguage());
    m_view->setHtml(m_html);
}

void FoldPlcPage::ask(const QString &title, const QString &filter, const QString &suffix,
                      QString (FoldPlcPage::*write)(const QString &))
{
    QString suggestion = fold()->planPath();
    if (suggestion.isEmpty())
        suggestion = fold()->plan().title.empty() ? tr("fold")
                                                  : QString::fromStdString(fold()->plan().title);
    else
        suggestion = suggestion.left(suggestion.lastIndexOf(QLatin1Char('.')));
    const QString path =
        QFileDialog::getSaveFileName(this, title, suggestion + QLatin1Char('.') + suffix, filter);
    if (path.isEmpty())
        return;
    const QString error = (this->*write)(path);
    m_status->setText(error.isEmpty() ? tr("Written: %1").arg(path) : error);
}

QString FoldPlcPage::exportPdf(const QString &path)
{
    model::PlcText why;
    const auto sheet = model::makeFoldSheet(fold()->plan(), &why);
    if (!sheet)
        return model::plcText(why, model::textLanguage());
    if (!model::writeFoldSheetPdf(*sheet, model::textLanguage(), path))
        return tr("Cannot write %1.").arg(path);
    return {};
}

QString FoldPlcPage::exportHtml(const QString &path)
{
    model::PlcText why;
    const auto sheet = model::makeFoldSheet(fold()->plan(), &why);
    if (!sheet)
        return model::plcText(why, model::textLanguage());
    return writeText(path, model::foldSheetHtml(*sheet, model::textLanguage()).toUtf8());
}

QString FoldPlcPage::exportCsv(const QString &path)
{
    model::PlcText why;
    const auto sheet = model::makeFoldSheet(fold()->plan(), &why);
    if (!sheet)
        return model::plcText(why, model::textLanguage());
    return writeText(path, model::foldSheetCsv(*sheet, model::textLanguage()).toUtf8());
}

QString FoldPlcPage::savePlan(const QString &path)
{
    if (const auto error = model::saveFoldPlanFile(fold()->plan(), path.toStdString()))
        return model::foldFileErrorText(*error);
    fold()->setPlanPath(path);
    return {};
}

void FoldPlcPage::retranslate()
{
    setTitle(tr("PLC configuration"));
    setSubTitle(tr("What the PLC programmer installs and configures. Export it or save the plan."));
    m_pdf->setText(tr("Export PDF …"));
    m_htmlButton->setText(tr("Export HTML …"));
    m_csv->setText(tr("Export CSV …"));
    m_save->setText(tr("Save plan …"));
    refresh();
}

} // namespace vt::ui
