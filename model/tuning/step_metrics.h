// Step-response analysis of the tuning workbench: the steps of a recorded set value and, per step,
// the figures MATLAB's `stepinfo` defines (dead time, rise time 10–90 %, overshoot, peak time,
// settling times to ±2 % and ±5 %) plus the steady-state error, from the recorded actual value.
// Pure functions over plain values (any thread); docs/TUNING.md ("Analysis") states the
// definitions and the tolerances the tests hold.
//
// Every figure is taken relative to the step's start value and its settled final value:
//   startValue  the actual's time-weighted mean over the last 10 % of the previous hold
//               (StepEdge::holdBefore), or the last actual sample before the step when
//               holdBefore is 0;
//   finalValue  the actual's time-weighted mean over the last 10 % of this hold;
//   (both read the samples of their own hold only, never a line to a sample across a step)
//   s(t)        (actual(t) − startValue) / (finalValue − startValue), the normalised response,
//               so down steps and up steps read alike.
// Crossing times are interpolated linearly between the two samples around the crossing; the
// response before the first sample after the step is taken as the last sample before it (the
// actual cannot move before the set value does).
//   deadTime        first time after the step at which s(t) reaches 0.02, minus the step time.
//                   A pure lag with time constant τ shows τ·ln(1/0.98) ≈ 0.02·τ here; a
//                   transport delay L adds L.
//   rise10Time/rise90Time  first times s(t) reaches 0.1 / 0.9 (absolute, for plot marks);
//   riseTime        rise90Time − rise10Time.
//   peakValue/peakTime  the sample with the largest s(t) in the hold, its value and its time
//                   after the step (without overshoot that is simply the highest sample).
//   overshootPct    (max s − 1) · 100, 0 when s never exceeds 1.
//   settlingTime2/5 time after the step from which |s(t) − 1| stays ≤ 0.02 / 0.05 until the end
//                   of the hold; NaN when the last sample of the hold is outside that band (noise
//                   larger than the band).
//   steadyStateError  set value (`to`) − finalValue, in the channels' unit.
// Refused (StepProblem):
//   ZeroStep        to == from.
//   TooShort        the hold has no length, the actual starts after the step, or the actual's
//                   recording ends before the final-value window (the last 10 % of the hold)
//                   begins.
//   TooFewSamples   fewer than kMinHoldSamples actual samples in the hold, or fewer than
//                   kMinFinalSamples in the final-value window.
//   NoResponse      |finalValue − startValue| is not larger than the actual's peak-to-peak
//                   spread in the final-value window: the step is lost in the noise.
//   NotSettled      the final-value window still drifts: across it, the least-squares line
//                   through its samples changes by more than 2 % of |finalValue − startValue|
//                   (noise averages out of the line, a trend does not). This refuses a lag held
//                   for less than about 3 time constants; ringing that averages out is not
//                   refused, the settling times show it. Hold a step for several settling times.
//                   The checks run in the order listed.
#pragma once

#include "core/result.h"
#include "samples.h"

#include <cstddef>
#include <string_view>
#include <vector>

namespace vt::model {

// A step of the set value: it jumps from `from` to `to` at `time` and holds `to` until `end`.
struct StepEdge
{
    double time = 0; // s, when the device confirmed the new set value
    double from = 0;
    double to = 0;
    double end = 0;        // s, the next step or the end of the recording
    double holdBefore = 0; // s the set value had held `from` before `time`; 0: not known
};

// The steps of a set-value channel read as a staircase (zero-order hold between samples): every
// change between consecutive samples larger than `minJump` (in the channel's unit), in time order.
// Each step holds until the next one; the last until `recordingEnd` (or its own time if that is
// earlier). holdBefore is the time since the previous step, for the first step since the first
// sample. Changes of at most minJump leave the staircase as it is (they are not steps).
std::vector<StepEdge> findStepEdges(const Samples &setValue, double minJump, double recordingEnd);

enum class StepProblem { TooFewSamples, TooShort, ZeroStep, NoResponse, NotSettled };

constexpr std::size_t kMinHoldSamples = 20; // actual samples in the hold
constexpr std::size_t kMinFinalSamples = 4; // actual samples in the final-value window

struct StepMetrics
{
    bool up = true;              // the set value rose
    double from = 0;             // set value before the step
    double to = 0;               // set value after it
    double stepTime = 0;         // s, absolute (StepEdge::time)
    double startValue = 0;       // actual, see the header comment
    double finalValue = 0;       // actual, see the header comment
    double deadTime = 0;         // s
    double riseTime = 0;         // s
    double overshootPct = 0;     // %
    double peakTime = 0;         // s after the step
    double settlingTime2 = 0;    // s after the step; NaN: not inside ±2 % at the end of the hold
    double settlingTime5 = 0;    // s after the step; NaN: not inside ±5 % at the end of the hold
    double steadyStateError = 0; // set value's unit
    double peakValue = 0;        // actual at the peak
    double rise10Time = 0;       // s, absolute, for the plot's 10 % mark
    double rise90Time = 0;       // s, absolute, for the plot's 90 % mark
};

// The step's figures from the recorded actual value (same time axis and unit as the set value).
dev::Result<StepMetrics, StepProblem> stepMetrics(const Samples &actual, const StepEdge &edge);

// Stable English key for logs and JSON: "too-few-samples", "too-short", "zero-step",
// "no-response", "not-settled".
std::string_view stepProblemKey(StepProblem problem);

} // namespace vt::model
