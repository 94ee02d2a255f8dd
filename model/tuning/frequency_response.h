// Frequency-response analysis of the tuning workbench: gain and phase of the recorded actual value
// against the set value as written, at one frequency of a sine or stepped-sine sweep, from a
// single-bin DFT over whole cycles; the valid band the sample and update rates allow; and the
// −3 dB and −90° frequencies of a sweep. Pure functions over plain values (any thread);
// docs/TUNING.md ("Analysis") states the definitions and the tolerances the tests hold.
//
// The DFT. Over the window [t0, t0 + cycles/f] both signals are compared at ω = 2πf:
//   U = ∫ (u(t) − ū) e^{−jω(t−t0)} dt  with u the set value as a staircase (each confirmed write
//       holds until the next): integrated exactly, segment by segment, so the steps the loop
//       really saw are what the actual is compared against;
//   Y = ∫ (y(t) − ȳ) e^{−jω(t−t0)} dt  with y the sampled actual: the trapezoid rule over the
//       sample times as they are (uneven), the window's ends read by linear interpolation.
//   ū, ȳ are the window's time-weighted means. Gain = 20·log10|Y/U| dB, phase = arg(Y/U) in
//   degrees, wrapped into (−360°, 0°] (a lag reads as a negative angle; a small lead, e.g. noise
//   at low frequency, reads just above −360° — unwrappedPhaseDeg() gives the continuous curve).
//   quality = (2|Y|²/T) / ∫(y − ȳ)² dt, clamped to [0, 1]: the share of the actual's AC energy
//   in the window that a sine at f explains (1: a clean sine; noise, harmonics of a saturating
//   valve or an unsettled transient lower it).
#pragma once

#include "samples.h"

#include <optional>
#include <string_view>
#include <vector>

namespace vt::model {

struct FrequencyLimits
{
    double sampleRateHz = 0; // actual value samples per second (achieved, averageRateHz())
    double updateRateHz = 0; // confirmed set-value writes per second (achieved)
};

// Samples and set-value updates a cycle must have at least (the valid-band rule below).
constexpr double kMinPerCycle = 10;

// The highest frequency a point may have and still count as data: min(sampleRateHz,
// updateRateHz) / 10 — at least 10 actual samples and 10 set-value writes per cycle. Why 10:
// - updates: at 10 writes per cycle the staircase the loop sees is still close to a sine: its
//   fundamental is sinc(0.1) = 0.14 dB below the intended amplitude and its strongest images
//   (at update rate ± f) are 1/9 of it before the loop's low-pass; fewer writes per cycle excite
//   the loop with a signal that is mostly steps, and the valve's rate limits (not linear) with it.
// - samples: the actual's bin is a trapezoid sum over uneven sample times. Its error per sample
//   interval grows with (2π·f·Δt)² (evenly spaced samples cancel it over whole cycles, polled
//   ones only partly); at 10 samples per cycle the tests see it stay within 0.2 dB and 2°, and
//   Nyquist (2 per cycle) is the hard limit where the bin aliases.
// 0 when either rate is not positive (nothing is valid then).
double maxValidFrequency(const FrequencyLimits &limits);

enum class FrequencyProblem {
    None,
    BadRequest,       // frequency ≤ 0, fewer than one cycle, or a time that is not finite
    OutsideRecording, // the window starts before the first set value or the first actual sample,
                      // or ends after the last actual sample: no figures
    TooFewSamples,    // fewer than 2 actual samples in the window (no figures), or fewer than half
                      // of kMinPerCycle per cycle (figures computed, not valid: a gap)
    NoExcitation,     // the set value has no component at f in the window: no figures
    AboveValidBand,   // f > maxValidFrequency(): figures computed, not valid
};

struct FrequencyPoint
{
    double frequencyHz = 0;
    double gainDb = 0;   // NaN when there are no figures (see FrequencyProblem)
    double phaseDeg = 0; // (−360°, 0°]; NaN when there are no figures
    double quality = 0;  // [0, 1]
    bool valid = false;  // data to draw and to search crossings in
    FrequencyProblem problem = FrequencyProblem::None; // why not valid
};

// Gain and phase of `actual` against `setValue` at frequencyHz over `cycles` whole cycles from t0
// (the caller puts t0 after the settling cycles). A point above the valid band, or with a gap in
// the actual, keeps its figures but is not valid.
FrequencyPoint frequencyPoint(const Samples &setValue, const Samples &actual, double frequencyHz,
                              double t0, int cycles, const FrequencyLimits &limits);

// The phases of `points` unwrapped across the sweep: valid points in order of frequency, the
// lowest one's phase taken into (−180°, 180°], every next one within 180° of the one before.
// Same order as `points`; NaN for points that are not valid.
std::vector<double> unwrappedPhaseDeg(const std::vector<FrequencyPoint> &points);

// The lowest frequency at which the gain falls through gainDb (from ≥ gainDb to below it between
// two valid points neighbouring in frequency), interpolated linearly in dB over log frequency.
// None when the valid points never fall through it. The points need not be sorted.
std::optional<double> gainCrossing(const std::vector<FrequencyPoint> &points, double gainDb = -3.0);

// The same for the unwrapped phase falling through phaseDeg.
std::optional<double> phaseCrossing(const std::vector<FrequencyPoint> &points,
                                    double phaseDeg = -90.0);

// Stable English key for logs and JSON: "none", "bad-request", "outside-recording",
// "too-few-samples", "no-excitation", "above-valid-band".
std::string_view frequencyProblemKey(FrequencyProblem problem);

} // namespace vt::model
