// The drift between a reference fingerprint and the same tests repeated now (docs/TUNING.md
// "Reference fingerprint"): the settings that differ (reference vs now, in display units), the
// figures of each test with their change against a threshold (ok / exceeded), and the old and new
// responses on one axis for an overlay. Plain C++ over plain values (any thread); the GUI, the CLI
// and the commissioning report read the same ReferenceComparison.
#pragma once

#include "dict/dictionary.h"
#include "model/tuning/run_file.h"
#include "model/tuning/samples.h"
#include "model/tuning/step_metrics.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vt::model {

enum class DriftMetric {
    RiseTime,         // s; change in % of the reference, both ways
    Overshoot,        // %; change in percentage points, only a rise counts
    SettlingTime,     // s (±2 %); change in % of the reference, both ways
    SteadyStateError, // set value's unit; change in % of the step height, both ways
    Bandwidth,        // Hz (−3 dB); change in % of the reference, both ways
    Phase90,          // Hz (−90°); change in % of the reference, both ways
};
// "rise-time", "overshoot", "settling-time", "steady-state-error", "bandwidth", "phase-90"
std::string_view driftMetricKey(DriftMetric metric);
// English label for logs and files ("rise time 10–90 %"); the GUI translates by key.
std::string_view driftMetricLabel(DriftMetric metric);

// How far a figure may move before it counts as drift. Editable; these are the defaults.
struct DriftThresholds
{
    double riseTimePct = 20;
    double overshootPoints = 5;
    double settlingPct = 20;
    double steadyStatePctOfStep = 2;
    double bandwidthPct = 20;
    double phase90Pct = 20;

    double of(DriftMetric metric) const;
};

struct ParamDrift
{
    int module = 0;
    std::string row;  // "C1.13"
    std::string name; // its label in the language asked for ("P portion KP1"); the row if none
    std::optional<double> reference; // display units; empty: not in that snapshot
    std::optional<double> now;
    std::string unit;
    std::optional<double> referenceRaw; // the same as the device holds them (for enum labels)
    std::optional<double> nowRaw;
};

struct MetricDrift
{
    int module = 0;
    std::string test; // "step-up", "step-down", "sweep"
    DriftMetric metric = DriftMetric::RiseTime;
    std::string label;       // driftMetricLabel
    double reference = 0;    // NaN: the reference test gave none
    double now = 0;          // NaN: the repeated test gave none
    std::string unit;        // "s", "%", "Hz", or the set value's unit
    double deltaPercent = 0; // see DriftMetric (percentage points for overshoot); NaN: none
    double thresholdPercent = 0;
    bool exceeded = false; // beyond the threshold, or the figure is gone now
};

// One test's response, reference and now, on a common axis: seconds after the step (from a tenth
// of the hold before it), or Hz with the gain in dB for a sweep.
struct DriftOverlay
{
    std::string test;
    bool frequency = false;
    std::vector<double> x;
    std::vector<double> reference;
    std::vector<double> now;
};

struct ReferenceComparison
{
    std::vector<ParamDrift> params;
    std::vector<MetricDrift> metrics;
    std::vector<DriftOverlay> overlays;

    bool exceeded() const; // any metric
};

// One figure's drift. `stepHeight` (|to − from|) scales the steady-state error.
MetricDrift metricDrift(DriftMetric metric, double reference, double now,
                        const DriftThresholds &thresholds, double stepHeight = 0);

// A step test's four figures (rise, overshoot, settling 2 %, steady-state error); a missing
// metrics set counts as every figure NaN.
std::vector<MetricDrift> stepDrift(const std::optional<StepMetrics> &reference,
                                   const std::optional<StepMetrics> &now,
                                   const DriftThresholds &thresholds, const std::string &unit);
// A sweep's −3 dB and −90° frequencies (NaN: none).
std::vector<MetricDrift> sweepDrift(double referenceF3dB, double nowF3dB, double referenceF90,
                                    double nowF90, const DriftThresholds &thresholds);

// Settings that differ, or are known in only one snapshot, in dictionary order (rows the
// dictionary does not know last, with raw values and no unit).
std::vector<ParamDrift> paramDrift(int module, const dev::Dictionary &dictionary,
                                   const std::vector<RunSetting> &reference,
                                   const std::vector<RunSetting> &now, dev::Language language);

// Both responses after their steps at `points` times over the shorter hold.
DriftOverlay stepOverlay(std::string test, const Samples &reference, const StepEdge &referenceEdge,
                         const Samples &now, const StepEdge &nowEdge, std::size_t points = 200);

} // namespace vt::model
