#include "compare_dialog.h"

#include "model/params/compare_model.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace vt::ui {

CompareDialog::CompareDialog(model::ParameterDocument &document, QWidget *parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("compareDialog"));
    setWindowTitle(tr("Compare"));
    m_model = new model::CompareModel(document, this);
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("compareSummary"));
    m_table = new QTableView(this);
    m_table->setModel(m_model);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_effect = new QLabel(this);
    m_effect->setObjectName(QStringLiteral("compareEffect"));
    m_effect->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_close = buttons->button(QDialogButtonBox::Close);
    m_close->setObjectName(QStringLiteral("compareClose"));
    // Ticking only chooses; the Apply button says what it will do, with how many values.
    m_tickAll = buttons->addButton(tr("Tick All"), QDialogButtonBox::ActionRole);
    m_tickAll->setObjectName(QStringLiteral("compareTickAll"));
    m_tickNone = buttons->addButton(tr("Tick None"), QDialogButtonBox::ActionRole);
    m_tickNone->setObjectName(QStringLiteral("compareTickNone"));
    m_apply = buttons->addButton(QString(), QDialogButtonBox::ApplyRole);
    m_apply->setObjectName(QStringLiteral("compareApply"));
    for (QPushButton *b : {m_tickAll, m_tickNone, m_apply})
        b->setAutoDefault(false);
    connect(m_tickAll, &QPushButton::clicked, this, [this] { m_model->setAllTaken(true); });
    connect(m_tickNone, &QPushButton::clicked, this, [this] { m_model->setAllTaken(false); });
    connect(m_apply, &QPushButton::clicked, this, [this] {
        m_model->applyTaken();
        updateSummary();
    });
    connect(m_model, &QAbstractItemModel::dataChanged, this, &CompareDialog::updateApply);
    connect(m_model, &QAbstractItemModel::modelReset, this, &CompareDialog::updateApply);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_effect);
    layout->addWidget(buttons);
    resize(1000, 560);
    updateSummary();
}

void CompareDialog::updateApply()
{
    const int n = m_model->takenCount();
    m_apply->setText(tr("Apply %n Ticked Value(s)", nullptr, n));
    m_apply->setEnabled(n > 0);
    m_effect->setText(
        n == 0 ? tr("Tick the values to take; nothing changes until you apply them.")
               : tr("Apply puts %n ticked value(s) into this document as one step (Edit ▸ Undo "
                    "takes it back). Nothing is written to the device until Device ▸ Write "
                    "Changes.",
                    nullptr, n));
}

void CompareDialog::compareWithDevice()
{
    m_model->compareWithDevice();
    updateSummary();
}

void CompareDialog::compareWithFile(const dev::files::ParamFile &file, const QString &name)
{
    m_model->compareWithFile(file, name);
    updateSummary();
}

void CompareDialog::updateSummary()
{
    const int n = m_model->rowCount();
    // With nothing to choose, only Close makes sense: Enter closes the dialog.
    m_tickAll->setEnabled(n > 0);
    m_tickNone->setEnabled(n > 0);
    m_close->setDefault(n == 0);
    updateApply();
    m_summary->setText(n == 0 ? tr("No differences.")
                              : tr("%n parameter(s) differ. Tick \"Take other\" for each value to "
                                   "take into this document.",
                                   nullptr, n));
}

} // namespace vt::ui
