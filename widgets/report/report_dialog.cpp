#include "report_dialog.h"

#include "model/report/report_render.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPrintPreviewDialog>
#include <QPrinter>
#include <QPushButton>
#include <QSettings>
#include <QTextDocument>

namespace vt::ui {

namespace {

const char kGroup[] = "report";

} // namespace

ReportDialog::ReportDialog(const QStringList &runTitles, dev::Language lang, ReportMaker maker,
                           QWidget *parent)
    : QDialog(parent), m_maker(std::move(maker))
{
    setObjectName(QStringLiteral("reportDialog"));
    setWindowTitle(tr("Commissioning Report"));
    QSettings settings;
    settings.beginGroup(QLatin1String(kGroup));
    const auto line = [&](const char *key, const char *name) {
        auto *edit = new QLineEdit(settings.value(QLatin1String(key)).toString(), this);
        edit->setObjectName(QLatin1String(name));
        return edit;
    };
    m_customer = line("customer", "reportCustomer");
    m_machine = line("machine", "reportMachine");
    m_axis = line("axis", "reportAxis");
    m_operator = line("operator", "reportOperator");
    m_comment = new QPlainTextEdit(settings.value(QStringLiteral("comment")).toString(), this);
    m_comment->setObjectName(QStringLiteral("reportComment"));
    m_comment->setFixedHeight(70);

    m_runs = new QListWidget(this);
    m_runs->setObjectName(QStringLiteral("reportRuns"));
    for (const QString &title : runTitles) {
        auto *item = new QListWidgetItem(title, m_runs);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(Qt::Unchecked);
    }
    if (runTitles.isEmpty()) {
        auto *item = new QListWidgetItem(tr("No workbench runs in this session."), m_runs);
        item->setFlags(Qt::NoItemFlags);
    }
    m_runs->setFixedHeight(90);

    m_reference = new QLineEdit(this);
    m_reference->setObjectName(QStringLiteral("reportReference"));
    m_reference->setPlaceholderText(tr("none"));
    auto *browse = new QPushButton(tr("Browse…"), this);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString path =
            QFileDialog::getOpenFileName(this, tr("Reference parameter file"), m_reference->text(),
                                         tr("Parameter files (*.vtpar)"));
        if (!path.isEmpty())
            m_reference->setText(path);
    });
    auto *referenceRow = new QHBoxLayout;
    referenceRow->addWidget(m_reference, 1);
    referenceRow->addWidget(browse);

    m_drift = new QCheckBox(this);
    m_drift->setObjectName(QStringLiteral("reportDrift"));
    m_drift->setVisible(false);

    m_lang = new QComboBox(this);
    m_lang->setObjectName(QStringLiteral("reportLanguage"));
    m_lang->addItem(QStringLiteral("English"), QStringLiteral("en"));
    m_lang->addItem(QStringLiteral("Deutsch"), QStringLiteral("de"));
    m_lang->setCurrentIndex(lang == dev::Language::German ? 1 : 0);
    m_format = new QComboBox(this);
    m_format->setObjectName(QStringLiteral("reportFormat"));
    m_format->addItem(tr("PDF document (*.pdf)"), QStringLiteral("pdf"));
    m_format->addItem(tr("HTML page (*.html)"), QStringLiteral("html"));
    m_format->addItem(tr("JSON data (*.json)"), QStringLiteral("json"));
    m_format->setCurrentIndex(
        std::max(0, m_format->findData(settings.value(QStringLiteral("format")).toString())));

    auto *form = new QFormLayout;
    form->addRow(tr("Customer:"), m_customer);
    form->addRow(tr("Machine:"), m_machine);
    form->addRow(tr("Axis:"), m_axis);
    form->addRow(tr("Operator:"), m_operator);
    form->addRow(tr("Comment:"), m_comment);
    form->addRow(tr("Workbench runs:"), m_runs);
    form->addRow(tr("Reference file:"), referenceRow);
    form->addRow(QString(), m_drift);
    form->addRow(tr("Language:"), m_lang);
    form->addRow(tr("Format:"), m_format);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    auto *previewButton = buttons->addButton(tr("Print Preview…"), QDialogButtonBox::ActionRole);
    previewButton->setObjectName(QStringLiteral("reportPreview"));
    auto *saveButton = buttons->addButton(tr("Save…"), QDialogButtonBox::AcceptRole);
    saveButton->setObjectName(QStringLiteral("reportSave"));
    connect(previewButton, &QPushButton::clicked, this, &ReportDialog::preview);
    connect(saveButton, &QPushButton::clicked, this, &ReportDialog::save);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
    resize(560, sizeHint().height());
}

ReportDialog::~ReportDialog() = default;

void ReportDialog::offerDrift(const QString &what)
{
    m_drift->setText(tr("Drift against the reference fingerprint %1").arg(what));
    m_drift->setChecked(true);
    m_drift->setVisible(true);
}

ReportChoice ReportDialog::choice() const
{
    ReportChoice c;
    c.header = {m_customer->text(), m_machine->text(), m_axis->text(), m_operator->text(),
                m_comment->toPlainText()};
    for (int i = 0; i < m_runs->count(); ++i)
        if ((m_runs->item(i)->flags() & Qt::ItemIsUserCheckable) &&
            m_runs->item(i)->checkState() == Qt::Checked)
            c.runs.push_back(i);
    c.referenceFile = m_reference->text().trimmed();
    c.drift = !m_drift->isHidden() && m_drift->isChecked();
    c.lang = m_lang->currentData().toString() == QLatin1String("de") ? dev::Language::German
                                                                     : dev::Language::English;
    return c;
}

void ReportDialog::remember() const
{
    QSettings settings;
    settings.beginGroup(QLatin1String(kGroup));
    settings.setValue(QStringLiteral("customer"), m_customer->text());
    settings.setValue(QStringLiteral("machine"), m_machine->text());
    settings.setValue(QStringLiteral("axis"), m_axis->text());
    settings.setValue(QStringLiteral("operator"), m_operator->text());
    settings.setValue(QStringLiteral("comment"), m_comment->toPlainText());
    settings.setValue(QStringLiteral("format"), m_format->currentData());
}

void ReportDialog::paint(QPrinter *printer)
{
    const QString why = m_maker(choice(), [&](const model::Report &report) {
        QTextDocument doc;
        model::fillReportDocument(doc, report, *printer);
        model::paintReportPages(doc, *printer, report);
    });
    if (!why.isEmpty())
        QMessageBox::warning(this, windowTitle(), why);
}

void ReportDialog::preview()
{
    remember();
    QPrinter printer(QPrinter::HighResolution);
    printer.setPageSize(QPageSize(QPageSize::A4));
    printer.setPageMargins(QMarginsF(15, 12, 15, 10), QPageLayout::Millimeter);
    QPrintPreviewDialog dialog(&printer, this);
    dialog.setObjectName(QStringLiteral("reportPrintPreview"));
    dialog.setWindowTitle(tr("Commissioning Report"));
    connect(&dialog, &QPrintPreviewDialog::paintRequested, this, &ReportDialog::paint);
    dialog.resize(900, 1000);
    dialog.exec();
}

QString ReportDialog::saveTo(const QString &path)
{
    remember();
    QString error;
    const QString why = m_maker(choice(), [&](const model::Report &report) {
        if (const auto failed = model::writeReport(report, path))
            error = *failed;
    });
    return why.isEmpty() ? error : why;
}

void ReportDialog::save()
{
    const QString suffix = m_format->currentData().toString();
    QString path = QFileDialog::getSaveFileName(this, tr("Save Commissioning Report"),
                                                tr("commissioning-report.%1").arg(suffix),
                                                m_format->currentText());
    if (path.isEmpty())
        return;
    if (!path.endsWith(QLatin1Char('.') + suffix, Qt::CaseInsensitive))
        path += QLatin1Char('.') + suffix;
    const QString why = saveTo(path);
    if (!why.isEmpty()) {
        QMessageBox::warning(this, windowTitle(), why);
        return;
    }
    accept();
}

} // namespace vt::ui
