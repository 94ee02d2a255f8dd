#include "run_analysis.h"

#include <cmath>
#include <limits>

namespace vt::model {

namespace {

double recordingEnd(const TestRecording &recording, const Samples &actual)
{
    double end = actual.t.empty() ? 0 : actual.t.back();
    if (!recording.setValue.t.empty())
        end = std::max(end, recording.setValue.t.back());
    return end;
}

// The acknowledged edges that belong to the signal's measured ones: the same levels, nearest in
// time (the acknowledgement comes a link's exchange after the signal's own time).
std::vector<StepEdge> measuredEdges(const TestSignal &signal, const TestRecording &recording,
                                    double end)
{
    std::vector<StepEdge> out;
    if (signal.edges().empty())
        return out;
    double smallest = std::numeric_limits<double>::infinity();
    for (const SignalEdge &e : signal.edges())
        smallest = std::min(smallest, std::abs(e.to - e.from));
    const std::vector<StepEdge> found = findStepEdges(recording.setValue, smallest / 2, end);
    for (const SignalEdge &wanted : signal.edges()) {
        const StepEdge *best = nullptr;
        for (const StepEdge &e : found) {
            const double tolerance = (wanted.end - wanted.time) / 2;
            if (std::abs(e.time - wanted.time) > tolerance)
                continue;
            if (std::abs(e.to - wanted.to) > smallest / 2 ||
                std::abs(e.from - wanted.from) > smallest / 2)
                continue;
            if (!best || std::abs(e.time - wanted.time) < std::abs(best->time - wanted.time))
                best = &e;
        }
        if (best)
            out.push_back(*best);
    }
    return out;
}

} // namespace

RunAnalysis analyseRun(const TestSignal &signal, const TestRecording &recording,
                       const dev::ParamMeta *responseRow, const dev::ParamMeta *setValueRow)
{
    RunAnalysis out;
    const Samples *actual = recording.channel(responseRow);
    if (!actual || actual->t.empty())
        return out;
    out.hasResponse = true;
    const double end = recordingEnd(recording, *actual);
    for (const StepEdge &edge : measuredEdges(signal, recording, end)) {
        StepResult result{edge, {}, {}};
        auto metrics = stepMetrics(*actual, edge);
        if (metrics.ok()) {
            result.metrics = *metrics;
            if (setValueRow && responseRow->unit != setValueRow->unit)
                result.metrics->steadyStateError = std::numeric_limits<double>::quiet_NaN();
        } else
            result.problem = metrics.error();
        out.steps.push_back(result);
    }
    const FrequencyLimits limits{recording.sampleRateHz(), recording.updateRateHz()};
    out.maxValidHz = maxValidFrequency(limits);
    for (const SignalPoint &p : signal.points())
        out.points.push_back(frequencyPoint(recording.setValue, *actual, p.frequencyHz,
                                            p.measureStart, p.cycles, limits));
    out.f3dB = gainCrossing(out.points);
    out.f90deg = phaseCrossing(out.points);
    return out;
}

} // namespace vt::model
