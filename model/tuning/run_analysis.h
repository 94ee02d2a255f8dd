// RunAnalysis: what a workbench test measured — the step figures of each step edge the signal
// made (step, square) and gain and phase at each frequency (square, triangle, sine: the signal's
// frequency; sweep: every point), from the recording of the set value as acknowledged and of the
// response row (workbench_rows.h). Plain C++; the definitions are step_metrics.h's and
// frequency_response.h's (docs/TUNING.md "Analysis").
#pragma once

#include "core/result.h"
#include "model/tuning/frequency_response.h"
#include "model/tuning/step_metrics.h"
#include "model/tuning/test_recording.h"
#include "model/tuning/test_signal.h"

#include <optional>
#include <vector>

namespace vt::model {

struct StepResult
{
    StepEdge edge; // on the recording's time axis
    std::optional<StepMetrics> metrics;
    std::optional<StepProblem> problem; // why there are no metrics
};

struct RunAnalysis
{
    bool hasResponse = false; // the response row was recorded; without it nothing is analysed
    std::vector<StepResult> steps;
    std::vector<FrequencyPoint> points;
    std::optional<double> f3dB;   // Hz, first −3 dB crossing of the valid points
    std::optional<double> f90deg; // Hz, first −90° crossing of the valid points
    double maxValidHz = 0;        // the valid band's top for these sample and update rates
};

// `setValueRow` names the set value's unit: a response in another unit (a solenoid current in
// open loop) has no steady-state error against it (NaN).
RunAnalysis analyseRun(const TestSignal &signal, const TestRecording &recording,
                       const dev::ParamMeta *responseRow, const dev::ParamMeta *setValueRow);

} // namespace vt::model
