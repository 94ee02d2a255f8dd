// The reference fingerprint's file (`.vtref`, docs/TUNING.md "Reference fingerprint"): one JSON
// text with the module's identity (family, software version, mode, address), every setting the
// device image held (raw, as shown, unit), the standard tests (each a run in the run-file format of
// run_file.h: its JSON object and its CSV text) and the figures they gave. Plain C++ so the reader
// can be fuzzed: bounded size and nesting, every field checked, a message instead of an exception.
#pragma once

#include "core/result.h"
#include "model/tuning/run_file.h"

#include <string>
#include <string_view>
#include <vector>

namespace vt::model {

struct ReferenceSetting
{
    std::string name;
    double raw = 0;
    std::string display; // as shown when it was saved ("2.00", "P-PT1-I-DT1")
    std::string unit;
};

struct ReferenceTest
{
    std::string key; // "step-up", "step-down", "sweep" (referenceTestKey)
    RunFileData run; // its spec is the test's spec
};

struct ReferenceFigure
{
    std::string test;   // a ReferenceTest's key
    std::string metric; // a DriftMetric key (reference_comparison.h)
    double value = 0;   // NaN: the test gave none
    std::string unit;
};

struct ReferenceFileData
{
    std::string saved; // ISO 8601
    std::string family;
    std::string version;
    std::string mode;
    int address = 0;
    std::string setValue; // row name
    double centre = 0;    // the set value the steps go around (display unit)
    double amplitude = 0; // the step height / the sweep's amplitude (display unit)
    std::vector<ReferenceSetting> settings;
    std::vector<ReferenceTest> tests;
    std::vector<ReferenceFigure> figures; // for readers of the file; the comparison recomputes
};

constexpr std::size_t kMaxReferenceFileBytes = 256u * 1024 * 1024;
constexpr std::size_t kMaxReferenceTests = 8;
constexpr std::size_t kMaxReferenceSettings = 4096;

std::string referenceJson(const ReferenceFileData &reference);
// A text written by referenceJson; the error names what is wrong.
dev::Result<ReferenceFileData, std::string> parseReferenceFile(std::string_view text);

} // namespace vt::model
