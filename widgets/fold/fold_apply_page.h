// Fold wizard page 6: writes the plan's addresses and options to the connected node
// (model::FoldApply: range check, paced writes, read back) and verifies by a scan. Over a
// point-to-point cable it guides the technician module by module; offline it is skipped.
#pragma once

#include "model/fold/fold_apply.h"
#include "widgets/fold/fold_page.h"

#include <QPointer>

class QCheckBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QTableWidget;

namespace vt::ui {

class FoldApplyPage : public FoldPage
{
    Q_OBJECT
public:
    explicit FoldApplyPage(QWidget *parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override;
    void cleanupPage() override;

    // Bus: the whole node. Point-to-point: the module the guide names now.
    void startApply();
    void runApply(const std::vector<int> &current); // after the person agreed
    bool isRunning() const;
    model::FoldApply *job() const { return m_job; }
    // The connection changes or goes: the apply job (which uses its access) is dropped first.
    void dropJob();
    // Shows what the current connection allows.
    void refresh() { updateState(); }
    // Point-to-point: the module the technician should connect now (index into the plan).
    int guidedModule() const { return m_guided; }

signals:
    void applyFinished(bool ok);

protected:
    void retranslate() override;

private:
    bool pointToPoint() const;
    void updateState();
    void showModules();

    QLabel *m_intro = nullptr;
    QCheckBox *m_p2p = nullptr;
    QLabel *m_guide = nullptr;
    QPushButton *m_apply = nullptr;
    QTableWidget *m_table = nullptr;
    QPlainTextEdit *m_log = nullptr;
    QPointer<model::FoldApply> m_job;
    int m_guided = 0;
    bool m_guidedComplete = false;
};

} // namespace vt::ui
