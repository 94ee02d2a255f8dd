// Fold wizard page 8: the PLC test bench — CMD 15 sent cyclically over the node image link with
// a set value pair and control byte per module and a toggling TADR, each module's multiplexed
// answer shown decoded (status bits of its mode, VALUE1/VALUE2 with their meaning).
#pragma once

#include "model/fold/plc_test_bench.h"
#include "widgets/fold/fold_page.h"

#include <QPointer>

class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace vt::ui {

class FoldBenchPage : public FoldPage
{
    Q_OBJECT
public:
    explicit FoldBenchPage(QWidget *parent = nullptr);
    ~FoldBenchPage() override;
    void initializePage() override;
    void cleanupPage() override;

    // False (with the reason shown) when there is no node image link or the plan does not fit
    // one CMD 15 telegram.
    bool startBench();
    void stopBench();
    model::PlcTestBench *bench() const { return m_bench; }
    // The connection changes or goes: the bench (which uses its session) is dropped first.
    void dropBench();
    // Shows what the current connection allows.
    void refresh() { updateState(); }

protected:
    void retranslate() override;

private:
    void buildTable();
    void pushSetpoints();
    void showAnswer(int index);
    void showCounters();
    QString unavailableText() const;
    void updateState();

    QLabel *m_intro = nullptr;
    QTableWidget *m_table = nullptr;
    QPushButton *m_start = nullptr;
    QPushButton *m_stop = nullptr;
    QSpinBox *m_interval = nullptr;
    QLabel *m_intervalLabel = nullptr;
    QLabel *m_counters = nullptr;
    QPointer<model::PlcTestBench> m_bench;
};

} // namespace vt::ui
