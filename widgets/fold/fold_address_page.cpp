#include "widgets/fold/fold_address_page.h"

#include "model/fold/module_guide.h"
#include "widgets/fold/fold_wizard.h"
#include "widgets/number_box.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace vt::ui {

namespace {

enum Column { ColModule, ColAddress, ColGuide, ColCount };

// OPAT manual §7, E24 "Profibus Address": 0..126, 126 = address setting by the PROFIBUS master.
constexpr int kE24Max = 126;

} // namespace

FoldAddressPage::FoldAddressPage(QWidget *parent) : FoldPage(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_rule = new QLabel(this);
    m_rule->setWordWrap(true);
    layout->addWidget(m_rule);
    m_table = new QTableWidget(0, ColCount, this);
    m_table->setObjectName(QStringLiteral("addresses"));
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setWordWrap(true);
    layout->addWidget(m_table);
    m_number = new QPushButton(this);
    m_number->setObjectName(QStringLiteral("numberLeftToRight"));
    auto *row = new QHBoxLayout;
    row->addWidget(m_number);
    row->addStretch();
    layout->addLayout(row);
    auto *e24Row = new QHBoxLayout;
    m_setE24 = new QCheckBox(this);
    m_setE24->setObjectName(QStringLiteral("setE24"));
    m_e24 = new WholeNumberBox(this);
    m_e24->setObjectName(QStringLiteral("e24"));
    m_e24->setRange(0, kE24Max);
    e24Row->addWidget(m_setE24);
    e24Row->addWidget(m_e24);
    e24Row->addStretch();
    layout->addLayout(e24Row);
    m_e24Note = new QLabel(this);
    m_e24Note->setWordWrap(true);
    m_e24Note->setObjectName(QStringLiteral("e24Note"));
    layout->addWidget(m_e24Note);
    connect(m_number, &QPushButton::clicked, this, &FoldAddressPage::numberLeftToRight);
    const auto storeE24 = [this] {
        if (m_filling)
            return;
        model::FoldPlan &plan = fold()->editPlan();
        if (plan.node != model::FoldNode::Opat || plan.modules.empty())
            return;
        plan.modules.front().options.e24 =
            m_setE24->isChecked() ? std::optional<int>(m_e24->value()) : std::nullopt;
        m_e24->setEnabled(m_setE24->isChecked());
        updateGuide();
    };
    connect(m_setE24, &QCheckBox::toggled, this, storeE24);
    connect(m_e24, &QSpinBox::valueChanged, this, storeE24);
    retranslate();
}

void FoldAddressPage::initializePage()
{
    const model::FoldPlan &plan = fold()->plan();
    const bool opat = plan.node == model::FoldNode::Opat;
    m_rule->setText(model::nodeAddressRule(plan.node));
    m_filling = true;
    m_setE24->setVisible(opat);
    m_e24->setVisible(opat);
    m_e24Note->setVisible(opat);
    const std::optional<int> e24 =
        opat && !plan.modules.empty() ? plan.modules.front().options.e24 : std::nullopt;
    m_setE24->setChecked(e24.has_value());
    m_e24->setValue(e24.value_or(kE24Max));
    m_e24->setEnabled(e24.has_value());
    m_filling = false;
    fillTable();
}

void FoldAddressPage::fillTable()
{
    const model::FoldPlan &plan = fold()->plan();
    const bool opat = plan.node == model::FoldNode::Opat;
    m_filling = true;
    m_table->setRowCount(static_cast<int>(plan.modules.size()));
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const auto index = static_cast<std::size_t>(row);
        auto *item = new QTableWidgetItem(tr("Module %1").arg(row + 1));
        item->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, ColModule, item);
        auto *spin = new WholeNumberBox(m_table);
        // DMA: E22 0..32 (0 = no bus function); OPAT: master 0, slaves 1..7 (OPAT manual §1.4).
        // Out-of-range values stay enterable so the check page can explain them.
        spin->setRange(0, opat ? 7 : 32);
        spin->setValue(plan.modules[index].address);
        spin->setEnabled(!(opat && row == 0));
        m_table->setCellWidget(row, ColAddress, spin);
        connect(spin, &QSpinBox::valueChanged, this, [this, index](int value) {
            if (m_filling)
                return;
            model::FoldPlan &p = fold()->editPlan();
            if (index < p.modules.size())
                p.modules[index].address = value;
            updateGuide();
        });
        auto *guide = new QTableWidgetItem;
        guide->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, ColGuide, guide);
    }
    m_filling = false;
    updateGuide();
    m_table->resizeColumnsToContents();
}

void FoldAddressPage::updateGuide()
{
    const model::FoldPlan &plan = fold()->plan();
    for (int row = 0; row < m_table->rowCount(); ++row)
        if (auto *guide = m_table->item(row, ColGuide))
            guide->setText(model::moduleAddressGuide(plan, static_cast<std::size_t>(row)));
    const QString note = model::profibusAddressNote(plan);
    m_e24Note->setText(note.isEmpty() ? tr("E24 stays as it is on the master.") : note);
}

void FoldAddressPage::numberLeftToRight()
{
    model::FoldPlan &plan = fold()->editPlan();
    for (std::size_t i = 0; i < plan.modules.size(); ++i)
        plan.modules[i].address = static_cast<int>(plan.node == model::FoldNode::Opat ? i : i + 1);
    fillTable();
}

void FoldAddressPage::retranslate()
{
    setTitle(tr("Addresses"));
    setSubTitle(tr("Which address each module answers to, and how to set it."));
    m_table->setHorizontalHeaderLabels({tr("Module"), tr("Address"), tr("What to do")});
    m_number->setText(tr("Number 1, 2, 3 … from the left"));
    m_setE24->setText(tr("Set the master's PROFIBUS address E24 to"));
    m_e24->setSpecialValueText(QString());
    m_e24->setToolTip(tr("126 = the PROFIBUS master sets the address over the bus"));
    if (fold()) {
        m_rule->setText(model::nodeAddressRule(fold()->plan().node));
        updateGuide();
    }
}

} // namespace vt::ui
