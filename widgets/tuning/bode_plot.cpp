#include "bode_plot.h"

#include <QEvent>
#include <QLocale>
#include <cmath>

namespace vt::ui {

namespace {

const QColor kRunColors[] = {QColor(0xd6, 0x27, 0x28), QColor(0x1f, 0x77, 0xb4),
                             QColor(0x2c, 0xa0, 0x2c), QColor(0xff, 0x7f, 0x0e)};

void logAxis(QCPAxis *axis)
{
    axis->setScaleType(QCPAxis::stLogarithmic);
    axis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
}

} // namespace

BodePlot::BodePlot(QWidget *parent) : QCustomPlot(parent)
{
    m_gain = axisRect();
    m_phase = new QCPAxisRect(this);
    plotLayout()->addElement(1, 0, m_phase);
    logAxis(m_gain->axis(QCPAxis::atBottom));
    logAxis(m_phase->axis(QCPAxis::atBottom));
    connect(m_gain->axis(QCPAxis::atBottom), qOverload<const QCPRange &>(&QCPAxis::rangeChanged),
            m_phase->axis(QCPAxis::atBottom), qOverload<const QCPRange &>(&QCPAxis::setRange));
    setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    setMinimumHeight(120);
    retranslate();
}

void BodePlot::showRuns(const std::vector<const model::TuningRun *> &runs, const QStringList &names)
{
    clearGraphs();
    clearItems();
    QCPAxis *fx = m_gain->axis(QCPAxis::atBottom);
    QCPAxis *gain = m_gain->axis(QCPAxis::atLeft);
    QCPAxis *px = m_phase->axis(QCPAxis::atBottom);
    QCPAxis *phase = m_phase->axis(QCPAxis::atLeft);
    double fMin = INFINITY, fMax = 0;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const model::RunAnalysis &a = runs[i]->analysis;
        const QColor color = kRunColors[i % std::size(kRunColors)];
        QCPGraph *g = addGraph(fx, gain);
        QCPGraph *p = addGraph(px, phase);
        QCPGraph *outG = addGraph(fx, gain);
        QCPGraph *outP = addGraph(px, phase);
        for (QCPGraph *graph : {g, p}) {
            graph->setPen(QPen(color, 1.5));
            graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 5));
        }
        for (QCPGraph *graph : {outG, outP}) {
            graph->setLineStyle(QCPGraph::lsNone);
            graph->setPen(QPen(Qt::gray));
            graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCross, 7));
        }
        const std::vector<double> unwrapped = model::unwrappedPhaseDeg(a.points);
        for (std::size_t k = 0; k < a.points.size(); ++k) {
            const model::FrequencyPoint &pt = a.points[k];
            if (!std::isfinite(pt.gainDb))
                continue;
            fMin = std::min(fMin, pt.frequencyHz);
            fMax = std::max(fMax, pt.frequencyHz);
            const double ph =
                k < unwrapped.size() && std::isfinite(unwrapped[k]) ? unwrapped[k] : pt.phaseDeg;
            (pt.valid ? g : outG)->addData(pt.frequencyHz, pt.gainDb);
            (pt.valid ? p : outP)->addData(pt.frequencyHz, ph);
        }
        g->setName(static_cast<qsizetype>(i) < names.size() ? names[static_cast<qsizetype>(i)]
                                                            : tr("run %1").arg(runs[i]->number));
        if (i == 0 && a.maxValidHz > 0) {
            for (QCPAxisRect *rect : {m_gain, m_phase}) {
                auto *line = new QCPItemStraightLine(this);
                line->setClipAxisRect(rect);
                line->point1->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
                line->point2->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
                line->point1->setCoords(a.maxValidHz, 0);
                line->point2->setCoords(a.maxValidHz, 1);
                line->setPen(QPen(Qt::gray, 0, Qt::DashLine));
            }
        }
    }
    if (fMax > 0) {
        fx->setRange(fMin / 1.3, fMax * 1.3);
        gain->rescale();
        phase->rescale();
        gain->scaleRange(1.2, gain->range().center());
        phase->scaleRange(1.2, phase->range().center());
    }
    replot();
}

void BodePlot::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QCustomPlot::changeEvent(event);
}

void BodePlot::retranslate()
{
    m_gain->axis(QCPAxis::atLeft)->setLabel(tr("gain (dB)"));
    m_phase->axis(QCPAxis::atLeft)->setLabel(tr("phase (°)"));
    m_phase->axis(QCPAxis::atBottom)->setLabel(tr("frequency (Hz)"));
    setLocale(QLocale());
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace vt::ui
