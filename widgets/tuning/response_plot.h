// ResponsePlot: the workbench's time plot — for each run shown, the set value as acknowledged
// (a staircase) and the response row, overlaid with the runs' first measured step at t = 0; for
// the current run the step figures are drawn on it (10 % and 90 % marks, the ±2 % settling band
// around the final value, the peak). GUI thread.
#pragma once

#include "model/tuning/tuning_run.h"

#include <qcustomplot.h>
#include <vector>

namespace vt::ui {

class ResponsePlot : public QCustomPlot
{
    Q_OBJECT
public:
    explicit ResponsePlot(QWidget *parent = nullptr);

    // `runs` must outlive the next call; the first is the current one (its marks are drawn).
    // `names`, when given, name the runs in the legend instead of "run N" (one per run).
    void showRuns(const std::vector<const model::TuningRun *> &runs, const QStringList &names = {});
    // The live run while it records (no marks, not aligned): `run` names the rows, `recording`
    // is the test's own, read in place.
    void showLive(const model::TuningRun &run, const model::TestRecording &recording);
    // Shift of `run`'s time axis in the overlay (its first measured step's time).
    static double alignment(const model::TuningRun &run);

protected:
    void changeEvent(QEvent *event) override;

private:
    void addRun(const model::TuningRun &run, const model::TestRecording &recording, int index,
                double shift, bool marks, const QString &name = {});
    void addMarks(const model::TuningRun &run, double shift);
    void retranslate();
};

} // namespace vt::ui
