// The report's plots: what each shows (report_plot.h draws them).
#include "report_plot.h"
#include "report_render.h"
#include "report_text.h"

namespace vt::model {

namespace {

const QColor kSetValue(110, 110, 110);
const QColor kResponse(31, 119, 180);
const QColor kReference(214, 39, 40);

PlotSpec responsePlot(const TuningRun &run)
{
    const QString unit = run.setValueRow ? reportQs(run.setValueRow->unit) : QString();
    PlotSpec spec;
    spec.title = run.spec.kind == SignalKind::Step ? ReportText::tr("Step response")
                                                   : ReportText::tr("Time response");
    spec.xLabel = ReportText::tr("time (s)");
    spec.yLabel = unit.isEmpty() ? ReportText::tr("value") : ReportText::tr("value (%1)").arg(unit);
    spec.series.push_back(
        {ReportText::tr("set value %1")
             .arg(reportQs(run.setValueRow ? run.setValueRow->name : std::string())),
         run.recording.setValue.t, run.recording.setValue.y, kSetValue, false, true});
    if (const Samples *response = run.recording.channel(run.responseRow))
        spec.series.push_back({ReportText::tr("response %1").arg(reportQs(run.responseRow->name)),
                               response->t, response->y, kResponse, false, false});
    return spec;
}

// Gain and phase over frequency, valid points only.
std::pair<PlotSpec, PlotSpec> bodePlots(const TuningRun &run)
{
    std::vector<double> f, gain, phase;
    const std::vector<double> unwrapped = unwrappedPhaseDeg(run.analysis.points);
    for (std::size_t i = 0; i < run.analysis.points.size(); ++i) {
        const FrequencyPoint &p = run.analysis.points[i];
        if (!p.valid)
            continue;
        f.push_back(p.frequencyHz);
        gain.push_back(p.gainDb);
        phase.push_back(unwrapped[i]);
    }
    PlotSpec g;
    g.title = ReportText::tr("Bode plot: gain");
    g.xLabel = ReportText::tr("frequency (Hz)");
    g.yLabel = ReportText::tr("gain (dB)");
    g.logX = true;
    g.series.push_back({ReportText::tr("gain"), f, gain, kResponse, false, false});
    PlotSpec ph = g;
    ph.title = ReportText::tr("Bode plot: phase");
    ph.yLabel = ReportText::tr("phase (°)");
    ph.series = {{ReportText::tr("phase"), f, phase, kResponse, false, false}};
    return {g, ph};
}

PlotSpec driftPlot(const ReportDriftCurve &curve)
{
    PlotSpec spec;
    spec.title = ReportText::tr("Module %1 · %2").arg(curve.module).arg(curve.test);
    spec.xLabel = ReportText::tr("time (s)");
    spec.yLabel = curve.unit.isEmpty() ? ReportText::tr("value")
                                       : ReportText::tr("value (%1)").arg(curve.unit);
    spec.series.push_back(
        {ReportText::tr("reference"), curve.time, curve.reference, kReference, true, false});
    spec.series.push_back({ReportText::tr("now"), curve.time, curve.now, kResponse, false, false});
    return spec;
}

} // namespace

std::vector<ReportFigure> reportFigures(const Report &report)
{
    std::vector<ReportFigure> figures;
    for (std::size_t i = 0; i < report.runs.size(); ++i) {
        const TuningRun &run = report.runs[i];
        const int index = static_cast<int>(i);
        const QString prefix = QStringLiteral("run-%1-").arg(i);
        if (run.spec.kind != SignalKind::Sweep)
            figures.push_back({prefix + QStringLiteral("response"), index, -1,
                               renderPlot(responsePlot(run), report.lang)});
        if (!run.analysis.points.empty()) {
            const auto [gain, phase] = bodePlots(run);
            figures.push_back(
                {prefix + QStringLiteral("gain"), index, -1, renderPlot(gain, report.lang)});
            figures.push_back(
                {prefix + QStringLiteral("phase"), index, -1, renderPlot(phase, report.lang)});
        }
    }
    for (std::size_t i = 0; i < report.drift.curves.size(); ++i)
        figures.push_back({QStringLiteral("drift-%1").arg(i), -1, static_cast<int>(i),
                           renderPlot(driftPlot(report.drift.curves[i]), report.lang)});
    return figures;
}

} // namespace vt::model
