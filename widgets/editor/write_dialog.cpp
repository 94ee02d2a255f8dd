#include "write_dialog.h"

#include "model/params/parameter_tree_model.h"
#include "model/text_language.h"
#include "widgets/actuator_confirm.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace vt::ui {
namespace {

enum Col { ColModule, ColName, ColLabel, ColBefore, ColAfter, ColResult, ColCount };

} // namespace

WriteDialog::WriteDialog(model::DeviceAccess &access, model::ParameterDocument &document,
                         std::vector<model::ModuleWriteResult> plan, QWidget *parent)
    : QDialog(parent), m_document(document)
{
    setObjectName(QStringLiteral("writeDialog"));
    setWindowTitle(tr("Write Changes"));
    m_job = new model::WriteChangesJob(access, document, std::move(plan), this);
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    m_table = new QTableWidget(0, ColCount, this);
    m_table->setObjectName(QStringLiteral("writeTable"));
    m_table->setHorizontalHeaderLabels(
        {tr("Module"), tr("Name"), tr("Parameter"), tr("Device"), tr("New value"), tr("Result")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_progress = new QProgressBar(this);
    m_progress->hide();
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Write"));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_intro);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_progress);
    layout->addWidget(m_buttons);
    resize(900, 500);

    connect(m_buttons, &QDialogButtonBox::accepted, this, [this] {
        if (m_finished)
            accept();
        else
            confirm();
    });
    connect(m_buttons, &QDialogButtonBox::rejected, this, &WriteDialog::reject);
    connect(m_job, &model::WriteChangesJob::progress, this, [this](int done, int total) {
        m_progress->setMaximum(qMax(total, 1));
        m_progress->setValue(done);
    });
    connect(m_job, &model::WriteChangesJob::itemChanged, this, [this](int module, int index) {
        for (std::size_t p = 0; p < m_job->results().size(); ++p)
            if (m_job->results()[p].module == module)
                showItem(static_cast<int>(p), index);
    });
    connect(m_job, &model::WriteChangesJob::finished, this, [this](bool complete) {
        m_finished = true;
        for (std::size_t p = 0; p < m_job->results().size(); ++p)
            for (std::size_t i = 0; i < m_job->results()[p].items.size(); ++i)
                showItem(static_cast<int>(p), static_cast<int>(i));
        m_intro->setText(
            complete
                ? tr("Every change is on the device.")
                : tr("Not every change reached the device: see the result of each parameter."));
        m_buttons->setStandardButtons(QDialogButtonBox::Close);
        m_buttons->button(QDialogButtonBox::Close)->setDefault(true);
        emit writeFinished(complete);
    });
    fillConfirmation();
}

WriteDialog::~WriteDialog() = default;

bool WriteDialog::isWriting() const
{
    return m_job->isRunning();
}

void WriteDialog::fillConfirmation()
{
    const dev::Language lang = m_document.language();
    int count = 0;
    for (std::size_t p = 0; p < m_job->results().size(); ++p) {
        const model::ModuleWriteResult &r = m_job->results()[p];
        for (std::size_t i = 0; i < r.items.size(); ++i) {
            const model::WriteItem &item = r.items[i];
            const int row = m_table->rowCount();
            m_table->insertRow(row);
            m_rowOf.emplace_back(static_cast<int>(p), static_cast<int>(i));
            auto set = [&](int col, const QString &text) {
                m_table->setItem(row, col, new QTableWidgetItem(text));
            };
            set(ColModule, QString::number(m_document.module(r.module).address));
            set(ColName, QString::fromStdString(item.row->name));
            set(ColLabel, QString::fromStdString(item.row->label.in(lang)));
            set(ColBefore,
                item.before ? model::formatRaw(*item.row, *item.before, lang) : tr("(unknown)"));
            set(ColAfter, model::formatRaw(*item.row, item.value, lang));
            set(ColResult, QString());
            ++count;
        }
    }
    m_intro->setText(
        tr("%n change(s) will be written to the device, one at a time, each read back.", nullptr,
           count));
}

void WriteDialog::showItem(int planIndex, int index)
{
    for (std::size_t row = 0; row < m_rowOf.size(); ++row) {
        if (m_rowOf[row] != std::pair(planIndex, index))
            continue;
        const model::WriteItem &item = m_job->results()[static_cast<std::size_t>(planIndex)]
                                           .items[static_cast<std::size_t>(index)];
        QString text = model::writeStatusText(item.status);
        // The device's refusal in the language shown now (the dialog is window-modal: the
        // language cannot change while it is open).
        if (const QString reason = model::writeReasonText(item, model::textLanguage());
            !reason.isEmpty())
            text += QStringLiteral(": ") + reason;
        auto *cell = new QTableWidgetItem(text);
        if (item.status == model::WriteStatus::Verified ||
            item.status == model::WriteStatus::Written ||
            item.status == model::WriteStatus::Unchanged)
            cell->setForeground(QColor(0, 110, 0));
        else if (item.status != model::WriteStatus::Pending)
            cell->setForeground(QColor(170, 0, 0));
        m_table->setItem(static_cast<int>(row), ColResult, cell);
    }
}

void WriteDialog::confirm()
{
    if (m_started)
        return;
    // Rows that can move the valve (the set-value source …) are named once more on their own.
    QStringList moving;
    for (const model::ModuleWriteResult &r : m_job->results())
        for (const model::WriteItem &item : r.items)
            if (item.row->movesActuator)
                moving << actuatorWriteLine(m_document.module(r.module).address, *item.row,
                                            item.before, item.value, m_document.language());
    confirmActuatorWrites(this, moving, [this, guard = QPointer<WriteDialog>(this)] {
        if (guard)
            start();
    });
}

void WriteDialog::start()
{
    if (m_started)
        return;
    m_started = true;
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
    m_progress->show();
    m_intro->setText(tr("Writing…"));
    m_job->start();
}

void WriteDialog::reject()
{
    if (m_job->isRunning()) {
        m_job->cancel(); // stops after the exchange on the wire; rows not done stay "not sent"
        return;
    }
    QDialog::reject();
}

} // namespace vt::ui
