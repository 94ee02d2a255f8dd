#include "widgets/fold/fold_check_page.h"

#include "widgets/fold/fold_wizard.h"
#include "widgets/number_box.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSpinBox>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace vt::ui {

FoldCheckPage::FoldCheckPage(QWidget *parent) : FoldPage(parent)
{
    auto *layout = new QVBoxLayout(this);
    auto *snumRow = new QHBoxLayout;
    m_hasSnum = new QCheckBox(this);
    m_hasSnum->setObjectName(QStringLiteral("hasSnum"));
    m_snum = new WholeNumberBox(this);
    m_snum->setObjectName(QStringLiteral("snum"));
    m_snum->setRange(0, 255);
    snumRow->addWidget(m_hasSnum);
    snumRow->addWidget(m_snum);
    snumRow->addStretch();
    layout->addLayout(snumRow);
    m_list = new QTreeWidget(this);
    m_list->setObjectName(QStringLiteral("findings"));
    m_list->setColumnCount(3);
    m_list->setRootIsDecorated(false);
    m_list->setWordWrap(true);
    m_list->header()->setStretchLastSection(true);
    layout->addWidget(m_list);
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("summary"));
    m_summary->setWordWrap(true);
    layout->addWidget(m_summary);
    const auto storeSnum = [this] {
        if (m_filling)
            return;
        fold()->editPlan().plcSnum =
            m_hasSnum->isChecked() ? std::optional<int>(m_snum->value()) : std::nullopt;
        m_snum->setEnabled(m_hasSnum->isChecked());
        recheck();
    };
    connect(m_hasSnum, &QCheckBox::toggled, this, storeSnum);
    connect(m_snum, &QSpinBox::valueChanged, this, storeSnum);
    retranslate();
}

void FoldCheckPage::initializePage()
{
    const model::FoldPlan &plan = fold()->plan();
    m_filling = true;
    m_hasSnum->setChecked(plan.plcSnum.has_value());
    m_snum->setValue(plan.plcSnum.value_or(0));
    m_snum->setEnabled(plan.plcSnum.has_value());
    m_filling = false;
    recheck();
}

bool FoldCheckPage::isComplete() const
{
    return !model::hasErrors(m_findings);
}

void FoldCheckPage::recheck()
{
    if (!fold())
        return;
    m_findings = model::checkFoldPlan(fold()->plan(), &fold()->dictionaries());
    if (fold()->nodeRead()) {
        // What the connected node reported when the wizard opened (FoldWizard::readNode).
        auto node = model::checkPlanAgainstNode(fold()->plan(), fold()->nodeModules());
        m_findings.insert(m_findings.end(), node.begin(), node.end());
    }
    m_list->clear();
    int errors = 0, warnings = 0;
    for (const model::FoldFinding &finding : m_findings) {
        auto *item = new QTreeWidgetItem(m_list);
        item->setText(0, model::foldSeverityText(finding.severity));
        item->setText(1, finding.module < 0 ? tr("Node") : tr("Module %1").arg(finding.module + 1));
        item->setText(2, model::foldFindingText(finding));
        item->setToolTip(2, item->text(2));
        item->setData(0, Qt::UserRole, static_cast<int>(finding.code));
        if (finding.severity == model::FoldSeverity::Error) {
            ++errors;
            item->setForeground(0, QBrush(Qt::red));
        } else if (finding.severity == model::FoldSeverity::Warning) {
            ++warnings;
        }
    }
    m_list->resizeColumnToContents(0);
    m_list->resizeColumnToContents(1);
    if (errors > 0)
        m_summary->setText(
            tr("%n error(s) must be fixed before the plan can be applied; go Back to "
               "change it.",
               "", errors));
    else if (warnings > 0)
        m_summary->setText(tr("No errors; %n warning(s) to read.", "", warnings));
    else
        m_summary->setText(tr("The plan passes every check."));
    emit completeChanged();
}

void FoldCheckPage::retranslate()
{
    setTitle(tr("Check"));
    setSubTitle(tr("What the manuals say about this plan. Errors block Next."));
    m_hasSnum->setText(tr("The PLC program already exists; the SNUM it sends:"));
    m_list->setHeaderLabels({tr("Severity"), tr("Where"), tr("Finding")});
    if (fold())
        recheck();
}

} // namespace vt::ui
