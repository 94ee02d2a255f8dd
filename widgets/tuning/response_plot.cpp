#include "response_plot.h"

#include <QEvent>
#include <QLocale>
#include <cmath>

namespace vt::ui {

namespace {

const QColor kRunColors[] = {QColor(0xd6, 0x27, 0x28), QColor(0x1f, 0x77, 0xb4),
                             QColor(0x2c, 0xa0, 0x2c), QColor(0xff, 0x7f, 0x0e),
                             QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b)};
const QColor kMarkColor(0x60, 0x60, 0x60);

QColor runColor(int index)
{
    return kRunColors[static_cast<std::size_t>(index) % std::size(kRunColors)];
}

QVector<double> vec(const std::vector<double> &v, double shift = 0)
{
    QVector<double> out;
    out.reserve(static_cast<qsizetype>(v.size()));
    for (double x : v)
        out.push_back(x - shift);
    return out;
}

} // namespace

ResponsePlot::ResponsePlot(QWidget *parent) : QCustomPlot(parent)
{
    setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    legend->setVisible(false); // shown with the first curve
    QFont small = legend->font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.85));
    legend->setFont(small);
    axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignRight);
    setMinimumHeight(120);
    retranslate();
}

double ResponsePlot::alignment(const model::TuningRun &run)
{
    return run.analysis.steps.empty() ? 0 : run.analysis.steps.front().edge.time;
}

void ResponsePlot::showRuns(const std::vector<const model::TuningRun *> &runs,
                            const QStringList &names)
{
    clearGraphs();
    clearItems();
    for (std::size_t i = 0; i < runs.size(); ++i)
        addRun(*runs[i], runs[i]->recording, static_cast<int>(i), alignment(*runs[i]), i == 0,
               static_cast<qsizetype>(i) < names.size() ? names[static_cast<qsizetype>(i)]
                                                        : QString());
    legend->setVisible(graphCount() > 0);
    rescaleAxes();
    yAxis->scaleRange(1.1, yAxis->range().center());
    replot();
}

void ResponsePlot::showLive(const model::TuningRun &run, const model::TestRecording &recording)
{
    clearGraphs();
    clearItems();
    addRun(run, recording, 0, 0, false);
    legend->setVisible(graphCount() > 0);
    rescaleAxes();
    yAxis->scaleRange(1.1, yAxis->range().center());
    replot(QCustomPlot::rpQueuedReplot);
}

void ResponsePlot::addRun(const model::TuningRun &run, const model::TestRecording &recording,
                          int index, double shift, bool marks, const QString &name)
{
    const QColor color = runColor(index);
    const QString prefix = !name.isEmpty() ? name + QStringLiteral(": ")
                           : index == 0    ? QString()
                                           : tr("run %1: ").arg(run.number);
    if (run.setValueRow) {
        QCPGraph *set = addGraph();
        set->setLineStyle(QCPGraph::lsStepLeft);
        QPen pen(color.lighter(150), 1, Qt::DashLine);
        set->setPen(pen);
        set->setName(prefix + tr("%1 written").arg(QString::fromStdString(run.setValueRow->name)));
        set->setData(vec(recording.setValue.t, shift), vec(recording.setValue.y), true);
    }
    if (const model::Samples *actual = recording.channel(run.responseRow)) {
        QCPGraph *g = addGraph();
        g->setPen(QPen(color, 1.5));
        g->setName(prefix + QString::fromStdString(run.responseRow->name));
        g->setData(vec(actual->t, shift), vec(actual->y), true);
    }
    if (marks)
        addMarks(run, shift);
}

void ResponsePlot::addMarks(const model::TuningRun &run, double shift)
{
    for (const model::StepResult &s : run.analysis.steps) {
        if (!s.metrics)
            continue;
        const model::StepMetrics &m = *s.metrics;
        const auto vertical = [&](double t, const QString &text) {
            if (!std::isfinite(t))
                return;
            auto *line = new QCPItemStraightLine(this);
            line->point1->setCoords(t - shift, 0);
            line->point2->setCoords(t - shift, 1);
            line->setPen(QPen(kMarkColor, 0, Qt::DotLine));
            auto *label = new QCPItemText(this);
            label->position->setType(QCPItemPosition::ptPlotCoords);
            label->position->setCoords(t - shift,
                                       m.startValue + 0.5 * (m.finalValue - m.startValue));
            label->setText(text);
            label->setColor(kMarkColor);
            label->setPositionAlignment(Qt::AlignLeft | Qt::AlignVCenter);
        };
        vertical(m.rise10Time, tr("10 %"));
        vertical(m.rise90Time, tr("90 %"));
        // The ±2 % band around the settled value, over the hold.
        const double band = 0.02 * std::abs(m.finalValue - m.startValue);
        for (double y : {m.finalValue - band, m.finalValue + band}) {
            auto *line = new QCPItemLine(this);
            line->start->setCoords(s.edge.time - shift, y);
            line->end->setCoords(s.edge.end - shift, y);
            line->setPen(QPen(kMarkColor, 0, Qt::DashLine));
        }
        auto *peak = new QCPItemTracer(this);
        peak->position->setCoords(s.edge.time + m.peakTime - shift, m.peakValue);
        peak->setStyle(QCPItemTracer::tsCircle);
        peak->setSize(7);
        peak->setPen(QPen(kMarkColor));
    }
}

void ResponsePlot::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QCustomPlot::changeEvent(event);
}

void ResponsePlot::retranslate()
{
    // Tick labels in the language's notation too (0,5 / 0.5).
    setLocale(QLocale());
    xAxis->setLabel(tr("time (s)"));
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace vt::ui
