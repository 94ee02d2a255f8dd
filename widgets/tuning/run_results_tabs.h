// RunResultsTabs: the workbench's results under its plot — the current run's step figures or gain
// and phase per frequency, and the setting differences between it and the first ticked run; the
// workbench adds its guided-tuning tab after these two. GUI thread; owned by the workbench view.
#pragma once

#include "model/tuning/tuning_run.h"

#include <QTabWidget>
#include <vector>

class QTableWidget;

namespace vt::ui {

class RunResultsTabs : public QTabWidget
{
    Q_OBJECT
public:
    explicit RunResultsTabs(QWidget *parent = nullptr);

    // `runs`: the current run first, then the ticked ones (empty: nothing shown).
    void showRuns(const std::vector<const model::TuningRun *> &runs);
    QTableWidget *resultsTable() const { return m_results; }
    QTableWidget *differencesTable() const { return m_differences; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void fillResults(const model::TuningRun &run);
    void fillDifferences(const std::vector<const model::TuningRun *> &runs);
    void retranslate();

    QTableWidget *m_results = nullptr;
    QTableWidget *m_differences = nullptr;
};

} // namespace vt::ui
