// BodePlot: gain (dB) and phase (°) of the response against the set value over a logarithmic
// frequency axis, one pair of curves per run shown. Points outside the valid band (above what the
// sample and update rates resolve, or without enough samples) are drawn as grey crosses apart
// from the data, never joined to it; the band's top is a vertical line. GUI thread.
#pragma once

#include "model/tuning/tuning_run.h"

#include <qcustomplot.h>
#include <vector>

namespace vt::ui {

class BodePlot : public QCustomPlot
{
    Q_OBJECT
public:
    explicit BodePlot(QWidget *parent = nullptr);

    // `names`, when given, name the runs in the legend instead of "run N" (one per run).
    void showRuns(const std::vector<const model::TuningRun *> &runs, const QStringList &names = {});
    QCPAxisRect *gainRect() const { return m_gain; }
    QCPAxisRect *phaseRect() const { return m_phase; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QCPAxisRect *m_gain = nullptr;
    QCPAxisRect *m_phase = nullptr;
};

} // namespace vt::ui
