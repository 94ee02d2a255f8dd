// Fold wizard page 2: how many modules the node has and which software version and mode each
// runs — read from the connected node by a scan (identify every address) or entered by hand for
// offline planning.
#pragma once

#include "model/fold/fold_node_check.h"
#include "widgets/fold/fold_page.h"

#include <vector>

class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace vt::ui {

class FoldModulesPage : public FoldPage
{
    Q_OBJECT
public:
    explicit FoldModulesPage(QWidget *parent = nullptr);
    void initializePage() override;
    bool validatePage() override;

    // Identifies every address the connection can scan and takes what answers as the plan's
    // modules (in address order). scanFinished() when done.
    void startScan();
    bool isScanning() const { return m_scanning; }

signals:
    void scanFinished(int found);

protected:
    void retranslate() override;

private:
    void setCount(int count);
    void fillTable();
    void fillModes(int row);
    void storeRow(int row);
    void scanNext();

    QSpinBox *m_count = nullptr;
    QLabel *m_countLabel = nullptr;
    QTableWidget *m_table = nullptr;
    QPushButton *m_scan = nullptr;
    QLabel *m_status = nullptr;
    bool m_filling = false;
    bool m_scanning = false;
    unsigned m_scanGeneration = 0;
    std::vector<int> m_scanAddresses;
    std::size_t m_scanCursor = 0;
    std::vector<model::FoldNodeModule> m_scanFound;
};

} // namespace vt::ui
