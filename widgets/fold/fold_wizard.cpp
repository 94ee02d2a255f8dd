#include "widgets/fold/fold_wizard.h"

#include "core/version.h"
#include "model/fold/fold_plan_file.h"
#include "model/session/connection.h"
#include "widgets/fold/fold_address_page.h"
#include "widgets/fold/fold_apply_page.h"
#include "widgets/fold/fold_bench_page.h"
#include "widgets/fold/fold_check_page.h"
#include "widgets/fold/fold_modules_page.h"
#include "widgets/fold/fold_node_page.h"
#include "widgets/fold/fold_options_page.h"
#include "widgets/fold/fold_plc_page.h"

#include <QEvent>
#include <memory>

namespace vt::ui {

FoldWizard::FoldWizard(const dev::DictionarySet &dictionaries, model::Connection *connection,
                       QWidget *parent)
    : QWizard(parent), m_dictionaries(dictionaries), m_connection(connection),
      m_plan(model::defaultFoldPlan(model::FoldNode::DmaProfinet, 3))
{
    setObjectName(QStringLiteral("foldWizard"));
    setWizardStyle(QWizard::ClassicStyle);
    setOption(QWizard::NoBackButtonOnStartPage);
    setPage(NodePageId, new FoldNodePage(this));
    setPage(ModulesPageId, new FoldModulesPage(this));
    setPage(AddressPageId, new FoldAddressPage(this));
    setPage(OptionsPageId, new FoldOptionsPage(this));
    setPage(CheckPageId, new FoldCheckPage(this));
    setPage(ApplyPageId, new FoldApplyPage(this));
    setPage(PlcPageId, new FoldPlcPage(this));
    setPage(BenchPageId, new FoldBenchPage(this));
    setStartId(NodePageId);
    // Its tables and texts readable without resizing, on a 1366 × 768 laptop as well.
    resize(980, 640);
    if (m_connection)
        connect(m_connection, &model::Connection::lost, this, &FoldWizard::connectionChanged);
    retranslate();
}

FoldWizard::~FoldWizard()
{
    if (auto *bench = qobject_cast<FoldBenchPage *>(page(BenchPageId)))
        bench->stopBench();
}

void FoldWizard::setConnection(model::Connection *connection)
{
    if (m_connection)
        disconnect(m_connection, nullptr, this, nullptr);
    if (auto *bench = qobject_cast<FoldBenchPage *>(page(BenchPageId)))
        bench->dropBench();
    if (auto *apply = qobject_cast<FoldApplyPage *>(page(ApplyPageId)))
        apply->dropJob();
    m_connection = connection;
    if (m_connection)
        connect(m_connection, &model::Connection::lost, this, &FoldWizard::connectionChanged);
    if (auto *bench = qobject_cast<FoldBenchPage *>(page(BenchPageId)))
        bench->refresh();
    if (auto *apply = qobject_cast<FoldApplyPage *>(page(ApplyPageId)))
        apply->refresh();
    emit connectionChanged();
}

bool FoldWizard::online() const
{
    return m_connection && m_connection->isOpen();
}

void FoldWizard::readNode(std::function<void()> done)
{
    const int generation = ++m_readGeneration;
    m_node.clear();
    m_nodeType.reset();
    m_nodeRead = false;
    if (!online()) {
        done();
        return;
    }
    // One address after the other, as the node answers one request at a time.
    auto addresses = std::make_shared<std::vector<int>>(m_connection->scanAddresses());
    auto next = std::make_shared<std::function<void(std::size_t)>>();
    *next = [this, self = QPointer<FoldWizard>(this), generation, addresses, next,
             done](std::size_t i) {
        if (!self || generation != m_readGeneration)
            return;
        if (i >= addresses->size() || !online()) {
            m_nodeRead = online();
            if (m_nodeRead && !m_node.empty() && m_planPath.isEmpty())
                startFromNode();
            done();
            *next = nullptr; // ends the cycle the lambda holds on itself
            return;
        }
        const int address = (*addresses)[i];
        m_connection->access().identify(address, [self, generation, next, address, i,
                                                  this](const model::IdentifyResult &r) {
            if (!self || generation != m_readGeneration || !*next)
                return;
            if (r.ok) {
                m_node.push_back({address, dev::majorVersionNumber(r.module.identification.version),
                                  r.module.mode});
                if (!m_nodeType)
                    m_nodeType = model::foldNodeOfFamily(r.module.identification.family);
            }
            (*next)(i + 1);
        });
    };
    (*next)(0);
}

void FoldWizard::startFromNode()
{
    // The node as read, not a default plan: its type, and each module's version, mode and
    // address (issue #23). A plan file opened later is checked against it on the check page.
    model::FoldPlan base = m_plan;
    if (m_nodeType && *m_nodeType != base.node)
        base = model::defaultFoldPlan(*m_nodeType, 0);
    setPlan(model::foldPlanFromNode(base, m_node));
    std::vector<int> found;
    for (const model::FoldModule &m : m_plan.modules)
        found.push_back(m.address);
    m_found = std::move(found);
}

void FoldWizard::setPlan(const model::FoldPlan &plan)
{
    m_plan = plan;
    m_found.clear();
    restart();
}

bool FoldWizard::openPlan(const QString &path, QString *error)
{
    auto loaded = model::loadFoldPlanFile(path.toStdString());
    if (!loaded.ok()) {
        if (error)
            *error = model::foldFileErrorText(loaded.error());
        return false;
    }
    setPlan(loaded.value());
    m_planPath = path;
    return true;
}

void FoldWizard::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWizard::changeEvent(event);
}

void FoldWizard::retranslate()
{
    setWindowTitle(tr("Module fold wizard"));
    // QWizard words its buttons once, when it is made; a run-time switch needs them again.
    setButtonText(QWizard::BackButton, tr("< &Back"));
    setButtonText(QWizard::NextButton, tr("&Next >"));
    setButtonText(QWizard::CommitButton, tr("Commit"));
    setButtonText(QWizard::FinishButton, tr("&Finish"));
    setButtonText(QWizard::CancelButton, tr("Cancel"));
    setButtonText(QWizard::HelpButton, tr("&Help"));
}

} // namespace vt::ui
