#include "widgets/fold/fold_apply_page.h"

#include "model/fold/fold_apply.h"
#include "model/fold/module_guide.h"
#include "model/session/connection.h"
#include "model/text_language.h"
#include "widgets/actuator_confirm.h"
#include "widgets/fold/fold_wizard.h"

#include <QCheckBox>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPointer>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace vt::ui {

namespace {

enum Column { ColModule, ColAddress, ColState, ColNotes, ColCount };

} // namespace

FoldApplyPage::FoldApplyPage(QWidget *parent) : FoldPage(parent)
{
    auto *layout = new QVBoxLayout(this);
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    m_intro->setObjectName(QStringLiteral("intro"));
    layout->addWidget(m_intro);
    m_p2p = new QCheckBox(this);
    m_p2p->setObjectName(QStringLiteral("pointToPoint"));
    layout->addWidget(m_p2p);
    m_guide = new QLabel(this);
    m_guide->setWordWrap(true);
    m_guide->setObjectName(QStringLiteral("guide"));
    layout->addWidget(m_guide);
    m_apply = new QPushButton(this);
    m_apply->setObjectName(QStringLiteral("apply"));
    layout->addWidget(m_apply, 0, Qt::AlignLeft);
    m_table = new QTableWidget(0, ColCount, this);
    m_table->setObjectName(QStringLiteral("applyResults"));
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(m_table);
    m_log = new QPlainTextEdit(this);
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(500);
    layout->addWidget(m_log);
    connect(m_apply, &QPushButton::clicked, this, &FoldApplyPage::startApply);
    connect(m_p2p, &QCheckBox::toggled, this, [this] {
        m_guided = 0;
        m_guidedComplete = false;
        updateState();
    });
    retranslate();
}

void FoldApplyPage::initializePage()
{
    model::Connection *connection = fold()->connection();
    // A serial line is usually the service cable to one module; RS485 users untick it.
    m_p2p->setChecked(connection && connection->spec().kind == model::ConnectionKind::Serial);
    m_guided = 0;
    m_guidedComplete = false;
    delete m_job;
    m_log->clear();
    showModules();
    updateState();
}

void FoldApplyPage::cleanupPage()
{
    if (m_job)
        m_job->cancel();
}

void FoldApplyPage::dropJob()
{
    delete m_job;
    showModules();
    updateState();
    emit completeChanged();
}

bool FoldApplyPage::isComplete() const
{
    return !isRunning();
}

bool FoldApplyPage::validatePage()
{
    // Point-to-point: "connect the cable to module 2, then Next" — Next applies to the module
    // the guide names until every module had its turn.
    if (isRunning())
        return false;
    if (fold()->online() && pointToPoint() && !m_guidedComplete) {
        startApply();
        return false;
    }
    return true;
}

bool FoldApplyPage::isRunning() const
{
    return m_job && m_job->isRunning();
}

bool FoldApplyPage::pointToPoint() const
{
    return m_p2p->isChecked();
}

void FoldApplyPage::startApply()
{
    FoldWizard *wizard = fold();
    if (!wizard || !wizard->online() || isRunning())
        return;
    const model::FoldPlan &plan = wizard->plan();
    if (plan.modules.empty())
        return;
    std::vector<int> current;
    if (pointToPoint()) {
        // Only one module on the line: it answers at the connection's unit whatever its E22.
        const std::vector<int> units = wizard->connection()->moduleAddresses();
        current.assign(plan.modules.size(), units.empty() ? 1 : units.front());
    } else if (wizard->foundAddresses().size() == plan.modules.size()) {
        current = wizard->foundAddresses();
    } else {
        for (const model::FoldModule &m : plan.modules)
            current.push_back(m.address);
    }
    // The apply rewrites the modules' options and addresses on a live node: asked once, naming
    // each module.
    QStringList lines;
    for (std::size_t i = 0; i < plan.modules.size(); ++i) {
        if (pointToPoint() && static_cast<int>(i) != m_guided)
            continue;
        lines << tr("Module at address %1: the plan's options, then address %2")
                     .arg(current[i])
                     .arg(plan.modules[i].address);
    }
    confirmActuatorWrites(
        this, lines, [this, guard = QPointer<FoldApplyPage>(this), current = std::move(current)] {
            if (guard && fold() && fold()->online() && !isRunning())
                runApply(current);
        });
}

void FoldApplyPage::runApply(const std::vector<int> &current)
{
    FoldWizard *wizard = fold();
    const model::FoldPlan &plan = wizard->plan();
    // A new job per run keeps the previous modules' results only when guiding module by module.
    if (!m_job || !pointToPoint()) {
        delete m_job;
        m_job = new model::FoldApply(wizard->connection()->access(), plan, current, this);
        connect(m_job, &model::FoldApply::message, this,
                [this](const QString &text) { m_log->appendPlainText(text); });
        connect(m_job, &model::FoldApply::moduleChanged, this, &FoldApplyPage::showModules);
        connect(m_job, &model::FoldApply::finished, this, [this](bool ok) {
            if (pointToPoint()) {
                if (m_guided + 1 < static_cast<int>(fold()->plan().modules.size()))
                    ++m_guided;
                else
                    m_guidedComplete = true;
            }
            showModules();
            updateState();
            emit completeChanged();
            emit applyFinished(ok);
        });
    }
    if (pointToPoint())
        m_job->applyModule(static_cast<std::size_t>(m_guided));
    else
        m_job->start();
    updateState();
    emit completeChanged();
}

void FoldApplyPage::showModules()
{
    const model::FoldPlan &plan = fold()->plan();
    m_table->setRowCount(static_cast<int>(plan.modules.size()));
    for (int row = 0; row < m_table->rowCount(); ++row) {
        const auto index = static_cast<std::size_t>(row);
        QString address = model::foldAddressText(plan.node, plan.modules[index]);
        QString state = tr("not applied");
        QString notes;
        if (m_job && index < m_job->modules().size()) {
            const model::FoldApplyModule &m = m_job->modules()[index];
            if (m.current != m.target)
                address = tr("%1 → %2").arg(m.current).arg(m.target);
            switch (m.state) {
            case model::FoldApplyState::Pending: state = tr("not applied"); break;
            case model::FoldApplyState::Running: state = tr("running …"); break;
            case model::FoldApplyState::Done: state = tr("done, found by the scan"); break;
            case model::FoldApplyState::Failed: state = tr("failed"); break;
            }
            QStringList written;
            for (const model::WriteItem &item : m.writes)
                if (item.row)
                    written << QStringLiteral("%1: %2").arg(QString::fromStdString(item.row->name),
                                                            model::writeStatusText(item.status));
            notes = (written + m.noteTexts()).join(QStringLiteral("; "));
        }
        const QString cells[ColCount] = {tr("Module %1").arg(row + 1), address, state, notes};
        for (int c = 0; c < ColCount; ++c) {
            auto *item = new QTableWidgetItem(cells[c]);
            item->setFlags(Qt::ItemIsEnabled);
            item->setToolTip(cells[c]);
            m_table->setItem(row, c, item);
        }
    }
    m_table->resizeColumnsToContents();
}

void FoldApplyPage::updateState()
{
    FoldWizard *wizard = fold();
    if (!wizard)
        return;
    const bool online = wizard->online();
    m_p2p->setVisible(online);
    m_apply->setVisible(online);
    m_table->setVisible(online);
    m_log->setVisible(online);
    m_guide->setVisible(online && pointToPoint());
    m_apply->setEnabled(online && !isRunning());
    if (!online) {
        m_intro->setText(tr("Offline planning: no node is connected, so nothing is written. Next "
                            "continues to the PLC configuration."));
        return;
    }
    m_intro->setText(tr("Writes each module's address and options (range-checked, read back), then "
                        "identifies every planned address. Connection: %1")
                         .arg(wizard->connection()->displayText()));
    if (pointToPoint()) {
        m_guide->setText(model::cableGuide(wizard->plan(), static_cast<std::size_t>(m_guided)));
        m_apply->setText(tr("Apply to module %1").arg(m_guided + 1));
    } else {
        m_apply->setText(tr("Apply to the node"));
    }
}

void FoldApplyPage::retranslate()
{
    setTitle(tr("Apply"));
    setSubTitle(
        tr("Write the addresses and options to the modules and check that every module answers."));
    m_p2p->setText(tr("Point-to-point cable: one module at a time"));
    m_table->setHorizontalHeaderLabels(
        {tr("Module"), tr("Address"), tr("State"), tr("Writes and notes")});
    if (fold()) {
        updateState();
        showModules();
    }
}

} // namespace vt::ui
