#include "widgets/fold/fold_modules_page.h"

#include "core/version.h"
#include "dict/dictionary.h"
#include "model/session/connection.h"
#include "model/text_language.h"
#include "widgets/fold/fold_wizard.h"
#include "widgets/number_box.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace vt::ui {

namespace {

enum Column { ColModule, ColVersion, ColMode, ColName, ColCount };

} // namespace

FoldModulesPage::FoldModulesPage(QWidget *parent) : FoldPage(parent)
{
    auto *layout = new QVBoxLayout(this);
    auto *top = new QHBoxLayout;
    m_countLabel = new QLabel(this);
    m_count = new WholeNumberBox(this);
    m_count->setObjectName(QStringLiteral("moduleCount"));
    m_scan = new QPushButton(this);
    m_scan->setObjectName(QStringLiteral("scan"));
    top->addWidget(m_countLabel);
    top->addWidget(m_count);
    top->addStretch();
    top->addWidget(m_scan);
    layout->addLayout(top);
    m_table = new QTableWidget(0, ColCount, this);
    m_table->setObjectName(QStringLiteral("modules"));
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(m_table);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    m_status->setObjectName(QStringLiteral("scanStatus"));
    layout->addWidget(m_status);
    connect(m_count, &QSpinBox::valueChanged, this, [this](int value) {
        if (!m_filling)
            setCount(value);
    });
    connect(m_scan, &QPushButton::clicked, this, &FoldModulesPage::startScan);
    retranslate();
}

void FoldModulesPage::initializePage()
{
    const model::FoldPlan &plan = fold()->plan();
    m_filling = true;
    // The wizard plans more modules than CMD 15 reaches (DMA E22 up to 32); the check page says
    // what that costs.
    m_count->setRange(1, static_cast<int>(model::foldMaxModules(plan.node)));
    m_count->setValue(static_cast<int>(plan.modules.size()));
    m_filling = false;
    m_scan->setEnabled(fold()->online() && !m_scanning);
    fillTable();
}

bool FoldModulesPage::validatePage()
{
    return !m_scanning;
}

void FoldModulesPage::setCount(int count)
{
    model::FoldPlan &plan = fold()->editPlan();
    const model::FoldPlan fresh =
        model::defaultFoldPlan(plan.node, static_cast<std::size_t>(count));
    // Keep what was entered for the modules that stay; new ones get the plan's defaults.
    std::vector<model::FoldModule> modules = fresh.modules;
    for (std::size_t i = 0; i < modules.size() && i < plan.modules.size(); ++i)
        modules[i] = plan.modules[i];
    plan.modules = modules;
    fold()->setFoundAddresses({});
    fillTable();
}

void FoldModulesPage::fillTable()
{
    const model::FoldPlan &plan = fold()->plan();
    m_filling = true;
    m_table->setRowCount(static_cast<int>(plan.modules.size()));
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const auto index = static_cast<std::size_t>(row);
        QString what = tr("Module %1").arg(row + 1);
        if (plan.node == model::FoldNode::Opat)
            what += row == 0 ? tr(" (master)") : tr(" (CAN slave)");
        auto *item = new QTableWidgetItem(what);
        item->setFlags(Qt::ItemIsEnabled);
        m_table->setItem(row, ColModule, item);
        auto *version = new QComboBox(m_table);
        for (int v : model::foldVersions(plan.node, index))
            version->addItem(tr("V%1").arg(v), v);
        version->setCurrentIndex(std::max(0, version->findData(plan.modules[index].version)));
        m_table->setCellWidget(row, ColVersion, version);
        connect(version, &QComboBox::currentIndexChanged, this, [this, row] {
            if (m_filling)
                return;
            storeRow(row);
            fillModes(row);
            storeRow(row);
        });
        auto *mode = new QComboBox(m_table);
        m_table->setCellWidget(row, ColMode, mode);
        connect(mode, &QComboBox::currentIndexChanged, this, [this, row] {
            if (!m_filling)
                storeRow(row);
        });
        auto *name = new QLineEdit(QString::fromStdString(plan.modules[index].name), m_table);
        m_table->setCellWidget(row, ColName, name);
        connect(name, &QLineEdit::textEdited, this, [this, row] { storeRow(row); });
        fillModes(row);
    }
    m_filling = false;
    for (int row = 0; row < m_table->rowCount(); ++row)
        storeRow(row); // the combos may have settled on the first entry
    m_table->resizeColumnsToContents();
}

void FoldModulesPage::fillModes(int row)
{
    const model::FoldPlan &plan = fold()->plan();
    const auto index = static_cast<std::size_t>(row);
    auto *mode = qobject_cast<QComboBox *>(m_table->cellWidget(row, ColMode));
    if (!mode || index >= plan.modules.size())
        return;
    const bool filling = m_filling;
    m_filling = true;
    mode->clear();
    const dev::Dictionary *dictionary =
        model::foldDictionary(fold()->dictionaries(), plan.node, plan.modules[index]);
    const dev::ParamMeta *e00 = dictionary ? dictionary->find("E00") : nullptr;
    if (dictionary) {
        for (const std::string &m : dictionary->modes) {
            const int value = std::atoi(m.c_str());
            QString text = tr("Mode %1").arg(value);
            if (e00)
                if (const dev::EnumLabel *label = e00->findEnum(value))
                    text += QStringLiteral(" — ") + model::localText(label->text);
            mode->addItem(text, value);
        }
    }
    const int at = mode->findData(plan.modules[index].mode);
    mode->setCurrentIndex(at >= 0 ? at : 0);
    m_filling = filling;
}

void FoldModulesPage::storeRow(int row)
{
    model::FoldPlan &plan = fold()->editPlan();
    const auto index = static_cast<std::size_t>(row);
    if (index >= plan.modules.size())
        return;
    if (auto *version = qobject_cast<QComboBox *>(m_table->cellWidget(row, ColVersion)))
        if (version->currentIndex() >= 0)
            plan.modules[index].version = version->currentData().toInt();
    if (auto *mode = qobject_cast<QComboBox *>(m_table->cellWidget(row, ColMode)))
        plan.modules[index].mode = mode->currentIndex() >= 0 ? mode->currentData().toInt() : 0;
    if (auto *name = qobject_cast<QLineEdit *>(m_table->cellWidget(row, ColName)))
        plan.modules[index].name = name->text().toStdString();
}

void FoldModulesPage::startScan()
{
    model::Connection *connection = fold() ? fold()->connection() : nullptr;
    if (m_scanning || !connection || !fold()->online())
        return;
    m_scanning = true;
    ++m_scanGeneration;
    m_scanAddresses = connection->scanAddresses();
    m_scanCursor = 0;
    m_scanFound.clear();
    m_scan->setEnabled(false);
    m_count->setEnabled(false);
    m_table->setEnabled(false);
    scanNext();
}

void FoldModulesPage::scanNext()
{
    model::Connection *connection = fold() ? fold()->connection() : nullptr;
    if (!connection || m_scanCursor >= m_scanAddresses.size()) {
        m_scanning = false;
        m_scan->setEnabled(fold() && fold()->online());
        m_count->setEnabled(true);
        m_table->setEnabled(true);
        std::sort(m_scanFound.begin(), m_scanFound.end(),
                  [](const auto &a, const auto &b) { return a.address < b.address; });
        if (!m_scanFound.empty()) {
            model::FoldPlan &plan = fold()->editPlan();
            plan = model::foldPlanFromNode(plan, m_scanFound);
            std::vector<int> found;
            for (const model::FoldModule &m : plan.modules)
                found.push_back(m.address);
            fold()->setFoundAddresses(found);
            m_filling = true;
            m_count->setValue(static_cast<int>(plan.modules.size()));
            m_filling = false;
            fillTable();
        }
        QStringList where;
        for (const model::FoldNodeModule &f : m_scanFound)
            where << QString::number(f.address);
        m_status->setText(m_scanFound.empty() ? tr("Scan finished: no module answered.")
                                              : tr("Scan finished: %n module(s) at address %1.", "",
                                                   static_cast<int>(m_scanFound.size()))
                                                    .arg(where.join(QStringLiteral(", "))));
        emit scanFinished(static_cast<int>(m_scanFound.size()));
        return;
    }
    const int address = m_scanAddresses[m_scanCursor];
    m_status->setText(tr("Scanning address %1 …").arg(address));
    connection->access().identify(address, [this, address, g = m_scanGeneration,
                                            self = QPointer<FoldModulesPage>(this)](
                                               const model::IdentifyResult &r) {
        if (!self || g != m_scanGeneration)
            return;
        if (r.ok)
            m_scanFound.push_back(
                {address, dev::majorVersionNumber(r.module.identification.version), r.module.mode});
        ++m_scanCursor;
        scanNext();
    });
}

void FoldModulesPage::retranslate()
{
    setTitle(tr("Modules"));
    setSubTitle(tr("How many modules the node has and which software and mode each runs. Scan the "
                   "connected node, or enter them for offline planning."));
    m_countLabel->setText(tr("Modules on the node:"));
    m_scan->setText(tr("Scan the connected node"));
    m_scan->setToolTip(
        tr("Identifies every address of the connection and takes the modules that answer."));
    m_table->setHorizontalHeaderLabels(
        {tr("Module"), tr("Software"), tr("Mode"), tr("Name (for the PLC sheet)")});
    if (fold() && m_table->rowCount() > 0 && !m_scanning)
        fillTable();
}

} // namespace vt::ui
