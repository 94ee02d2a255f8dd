// The workbench's run files: a finished test saved as its recording in CSV (time_s, the set value
// as acknowledged, each channel; what a spreadsheet opens) and everything else in JSON beside it
// (the signal, the module, how it ended, the settings at that time and the set value's own
// acknowledgement times). Plain C++ so the reader can be fuzzed: bounded sizes, bounded nesting,
// every field checked, a message instead of an exception. docs/TUNING.md "Run files".
#pragma once

#include "core/result.h"
#include "model/tuning/samples.h"
#include "model/tuning/test_signal.h"

#include <string>
#include <string_view>
#include <vector>

namespace vt::model {

struct RunSetting
{
    std::string name;
    double raw = 0;
};

struct RunFileData
{
    int number = 0;
    std::string started; // ISO 8601
    int module = 0;
    std::string family;
    std::string mode;
    std::string setValue; // row names
    std::string response; // empty: none
    SignalSpec spec;
    std::string end; // TestEnd key
    bool restored = false;
    int writes = 0;
    int cycles = 0;
    Samples setValueSamples;
    std::vector<std::string> channelNames;
    std::vector<Samples> channels; // one per name, sharing the CSV's times
    std::vector<RunSetting> settings;
};

constexpr std::size_t kMaxRunFileBytes = 256u * 1024 * 1024;

std::string runJson(const RunFileData &run);
std::string runCsv(const RunFileData &run);
// Both texts as written by runJson/runCsv; the error names what is wrong.
dev::Result<RunFileData, std::string> parseRunFiles(std::string_view json, std::string_view csv);

} // namespace vt::model
