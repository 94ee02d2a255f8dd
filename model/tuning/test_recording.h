// TestRecording: what a workbench test recorded — one series per channel and the set value as the
// device acknowledged it, on the test's time axis (0 = the first value of the signal was
// acknowledged), in display units. Plain C++: the analysis and the run files read it.
#pragma once

#include "dict/param_meta.h"
#include "model/tuning/samples.h"

#include <vector>

namespace vt::model {

struct TestRecording
{
    std::vector<const dev::ParamMeta *> rows; // the channels
    std::vector<Samples> channels;            // one per row
    Samples setValue;                         // at each acknowledgement
    double sessionStart = 0;                  // session seconds of t = 0
    int writes = 0;
    int cycles = 0;
    double updateRateHz() const; // acknowledged set-value writes per second
    double sampleRateHz() const; // channel reads per second
    // The channel of `row` (null when not recorded).
    const Samples *channel(const dev::ParamMeta *row) const;
};

} // namespace vt::model
