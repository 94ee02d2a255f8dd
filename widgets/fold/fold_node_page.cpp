#include "widgets/fold/fold_node_page.h"

#include "model/text_language.h"
#include "widgets/fold/fold_wizard.h"

#include <QButtonGroup>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QVBoxLayout>
#include <algorithm>

namespace vt::ui {

namespace {

constexpr model::FoldNode kNodes[3] = {model::FoldNode::Opat, model::FoldNode::DmaProfibus,
                                       model::FoldNode::DmaProfinet};

} // namespace

FoldWizard *FoldPage::fold() const
{
    return qobject_cast<FoldWizard *>(wizard());
}

FoldNodePage::FoldNodePage(QWidget *parent) : FoldPage(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_group = new QButtonGroup(this);
    for (int i = 0; i < 3; ++i) {
        m_buttons[i] = new QRadioButton(this);
        m_buttons[i]->setObjectName(QString::fromLatin1(model::foldNodeKey(kNodes[i]).data()));
        m_group->addButton(m_buttons[i], i);
        layout->addWidget(m_buttons[i]);
    }
    m_details = new QLabel(this);
    m_details->setWordWrap(true);
    layout->addWidget(m_details);
    auto *form = new QFormLayout;
    m_productLabel = new QLabel(this);
    m_product = new QLineEdit(this);
    m_product->setObjectName(QStringLiteral("productNumber"));
    form->addRow(m_productLabel, m_product);
    layout->addLayout(form);
    layout->addStretch();
    connect(m_group, &QButtonGroup::idClicked, this, [this] { updateDetails(); });
    retranslate();
}

void FoldNodePage::initializePage()
{
    const model::FoldPlan &plan = fold()->plan();
    for (int i = 0; i < 3; ++i)
        m_buttons[i]->setChecked(kNodes[i] == plan.node);
    m_product->setText(QString::fromStdString(plan.productNumber));
    updateDetails();
}

bool FoldNodePage::validatePage()
{
    const int id = m_group->checkedId();
    if (id < 0)
        return false;
    model::FoldPlan &plan = fold()->editPlan();
    if (plan.node != kNodes[id]) {
        // Another node type: versions, addresses and options of the old plan mean nothing here.
        const std::size_t count =
            std::clamp<std::size_t>(plan.modules.size(), 1, model::foldMaxCmd15Modules(kNodes[id]));
        model::FoldPlan fresh = model::defaultFoldPlan(kNodes[id], count);
        fresh.title = plan.title;
        fresh.notes = plan.notes;
        plan = fresh;
        fold()->setFoundAddresses({});
    }
    plan.productNumber = kNodes[id] == model::FoldNode::DmaProfibus
                             ? m_product->text().trimmed().toStdString()
                             : std::string();
    return true;
}

void FoldNodePage::updateDetails()
{
    const int id = m_group->checkedId();
    const bool pb = id >= 0 && kNodes[id] == model::FoldNode::DmaProfibus;
    m_productLabel->setVisible(pb);
    m_product->setVisible(pb);
    if (id < 0) {
        m_details->clear();
        return;
    }
    switch (kNodes[id]) {
    case model::FoldNode::Opat:
        m_details->setText(
            tr("The OPAT master carries the PROFIBUS interface (SADR 0) and drives up to "
               "seven OPAT CAN slaves (SADR 1 to 7 by rotary switch). One CMD 15 "
               "telegram reaches all eight. (OPAT manual §1.4, §3)"));
        break;
    case model::FoldNode::DmaProfibus:
        m_details->setText(
            tr("DMA-2 modules behind a PROFIBUS node module; each module answers to its "
               "E22. CMD 15 reaches E22 = 1 to 5. The node's product number decides the "
               "GSD file. (DMA Profibus Anleitung §1.3, §4–5)"));
        break;
    case model::FoldNode::DmaProfinet:
        m_details->setText(
            tr("DMA-2 modules behind a PROFINET node module; each module answers to its "
               "E22. CMD 15 reaches E22 = 1 to 5. (DMA Profinet manual §1.3, §4–5)"));
        break;
    }
}

void FoldNodePage::retranslate()
{
    setTitle(tr("Node type"));
    setSubTitle(tr("Which kind of node are you setting up?"));
    for (int i = 0; i < 3; ++i)
        m_buttons[i]->setText(model::foldNodeTitle(kNodes[i]));
    m_productLabel->setText(tr("Product number of the node:"));
    m_product->setPlaceholderText(tr("e.g. 5 005 123 45"));
    updateDetails();
}

} // namespace vt::ui
