// FoldWizard: sets up a multi-module HCS node and produces its PLC configuration:
// node type, modules (scanned or planned), addresses, bus options, checks, apply to the node,
// PLC sheet with exports and the .vtfold plan file, and a CMD 15 test bench. The plan
// (model::FoldPlan) is the wizard's one state; every page reads and edits it.
// Owner: the main window (Qt parent); GUI thread. The dictionaries and the connection must
// outlive the wizard (or call setConnection(nullptr) before the connection goes).
#pragma once

#include "model/fold/fold_node_check.h"
#include "model/fold/fold_plan.h"
#include "model/session/connection.h"

#include <QPointer>
#include <QWizard>
#include <functional>
#include <optional>
#include <vector>

namespace vt::dev {
class DictionarySet;
}

namespace vt::ui {

class FoldWizard : public QWizard
{
    Q_OBJECT
public:
    enum PageId {
        NodePageId,
        ModulesPageId,
        AddressPageId,
        OptionsPageId,
        CheckPageId,
        ApplyPageId,
        PlcPageId,
        BenchPageId
    };

    // `connection`: the connected node, or nullptr for offline planning (scan, apply and test
    // bench then say what they need instead of acting).
    FoldWizard(const dev::DictionarySet &dictionaries, model::Connection *connection,
               QWidget *parent = nullptr);
    ~FoldWizard() override;

    // Opens a saved .vtfold plan and restarts the wizard on it; false with *error set (in the UI
    // language) when the file cannot be read.
    bool openPlan(const QString &path, QString *error = nullptr);
    // Replaces the plan and restarts on the node page.
    void setPlan(const model::FoldPlan &plan);
    const model::FoldPlan &plan() const { return m_plan; }
    model::FoldPlan &editPlan() { return m_plan; }
    QString planPath() const { return m_planPath; }
    void setPlanPath(const QString &path) { m_planPath = path; }

    const dev::DictionarySet &dictionaries() const { return m_dictionaries; }
    model::Connection *connection() const { return m_connection; }
    void setConnection(model::Connection *connection);
    // Connected and open: scan and apply work on the node.
    bool online() const;

    // Where each planned module answers now, as the last scan found them (same order as the
    // plan's modules); empty when the modules were entered by hand.
    const std::vector<int> &foundAddresses() const { return m_found; }
    void setFoundAddresses(std::vector<int> addresses) { m_found = std::move(addresses); }

    // Identifies every address of the connection (version and mode of each module, as a scan
    // does) and calls `done` when all have answered or not; the main window shows the wizard
    // only then, so its first page already knows the node. Unless a plan file is open, the plan
    // then becomes the node as read (type, versions, modes, addresses). Offline: `done` at once.
    void readNode(std::function<void()> done);
    // What the node reported at the last readNode(); nodeRead() false before one finished.
    const std::vector<model::FoldNodeModule> &nodeModules() const { return m_node; }
    bool nodeRead() const { return m_nodeRead; }

signals:
    void connectionChanged();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void startFromNode();

    const dev::DictionarySet &m_dictionaries;
    QPointer<model::Connection> m_connection;
    model::FoldPlan m_plan;
    QString m_planPath;
    std::vector<int> m_found;
    std::vector<model::FoldNodeModule> m_node;
    std::optional<model::FoldNode> m_nodeType; // from the first module that answered
    bool m_nodeRead = false;
    int m_readGeneration = 0;
};

} // namespace vt::ui
