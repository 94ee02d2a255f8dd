// Fold wizard page 5: the plan's checks (model::checkFoldPlan) — duplicates, ranges, CMD 15
// limits, SNUM, mixed modes — listed with the manual's reason. Errors block Next.
#pragma once

#include "model/fold/fold_check.h"
#include "widgets/fold/fold_page.h"

#include <vector>

class QCheckBox;
class QLabel;
class QSpinBox;
class QTreeWidget;

namespace vt::ui {

class FoldCheckPage : public FoldPage
{
    Q_OBJECT
public:
    explicit FoldCheckPage(QWidget *parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override { return isComplete(); }

    const std::vector<model::FoldFinding> &findings() const { return m_findings; }
    // Runs the checks on the wizard's plan again and shows the findings.
    void recheck();

protected:
    void retranslate() override;

private:
    QCheckBox *m_hasSnum = nullptr;
    QSpinBox *m_snum = nullptr;
    QTreeWidget *m_list = nullptr;
    QLabel *m_summary = nullptr;
    std::vector<model::FoldFinding> m_findings;
    bool m_filling = false;
};

} // namespace vt::ui
