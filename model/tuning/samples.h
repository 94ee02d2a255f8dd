// Samples: one recorded channel as the tuning analysis reads it, and the few ways the analysis
// reads a value between samples. Times are seconds and never decrease; samples are not uniform
// in time (the monitor polls channels in turn), so nothing here assumes a fixed rate.
// Plain values: the caller owns them; the functions only read them (any thread).
#pragma once

#include <cstddef>
#include <vector>

namespace vt::model {

struct Samples
{
    std::vector<double> t; // seconds, non-decreasing
    std::vector<double> y; // one value per time, same length as t
};

// Index of the first sample later than `time`; s.t.size() when there is none (binary search).
std::size_t firstAfter(const Samples &s, double time);

// The value at `time` read as a straight line between the neighbouring samples; before the first
// sample the first value, after the last the last value. NaN for an empty channel.
double valueAt(const Samples &s, double time);

// The value at `time` read as a staircase (zero-order hold: each sample holds until the next),
// which is how a written set value behaves; before the first sample the first value.
// NaN for an empty channel.
double heldValueAt(const Samples &s, double time);

// Time-weighted mean of the straight-line reading over [from, to] (the trapezoid rule, so uneven
// sample spacing does not bias it), with the interval clipped to the recording; the value at the
// clipped end when nothing of the interval is left. NaN for an empty channel.
double meanOver(const Samples &s, double from, double to);

// Samples per second over the whole channel: (n − 1) / (last − first); 0 with fewer than two
// samples or no time between them. The figure FrequencyLimits wants for a recorded channel.
double averageRateHz(const Samples &s);

} // namespace vt::model
