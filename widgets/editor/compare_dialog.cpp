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
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton *all = buttons->addButton(tr("Take All"), QDialogButtonBox::ActionRole);
    QPushButton *none = buttons->addButton(tr("Take None"), QDialogButtonBox::ActionRole);
    QPushButton *apply = buttons->addButton(tr("Apply Chosen"), QDialogButtonBox::ApplyRole);
    apply->setObjectName(QStringLiteral("compareApply"));
    connect(all, &QPushButton::clicked, this, [this] { m_model->setAllTaken(true); });
    connect(none, &QPushButton::clicked, this, [this] { m_model->setAllTaken(false); });
    connect(apply, &QPushButton::clicked, this, [this] {
        m_model->applyTaken();
        updateSummary();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    resize(900, 500);
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
    m_summary->setText(n == 0 ? tr("No differences.")
                              : tr("%n parameter(s) differ. Tick \"Take other\" for each value to "
                                   "take into this document.",
                                   nullptr, n));
}

} // namespace vt::ui
