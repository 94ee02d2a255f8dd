// TuningRun: one finished workbench test as the workbench keeps it — the signal, the recording,
// the analysis, how it ended, and the module's settings at that time (from the device image: the
// values the device confirmed), so runs can be overlaid and their parameter differences listed.
// RunFile saves a run as two files, the recording as CSV and the rest as JSON beside it, and
// reads them back (bounded, refusing what it does not understand).
// Owner: the workbench's run list; GUI thread.
#pragma once

#include "model/session/device_access.h"
#include "model/session/device_image.h"
#include "model/tuning/run_analysis.h"
#include "model/tuning/run_file.h"
#include "model/tuning/test_run.h"

#include <QDateTime>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

namespace vt::model {

struct TuningRun
{
    int number = 0;
    QDateTime started;
    int module = 0;
    std::string family;
    std::string mode;
    const dev::Dictionary *dictionary = nullptr;
    const dev::ParamMeta *setValueRow = nullptr;
    const dev::ParamMeta *responseRow = nullptr; // may be null
    SignalSpec spec;
    TestRecording recording;
    RunAnalysis analysis;
    TestEnd end = TestEnd::Finished;
    bool restored = false;
    std::vector<RunSetting> settings; // settings rows with a value the device confirmed
};

// A run about to record `setup`: number, start time, module, rows, signal and the settings the
// image holds now; recording, analysis and end follow when the test is over.
std::unique_ptr<TuningRun> newRun(int number, const TestRunSetup &setup, const DeviceImage &image);

// Settings rows of the module with the value the image holds for them, in dictionary order.
std::vector<RunSetting> settingsSnapshot(const DeviceImage &image, const ModuleInfo &module);

struct SettingDifference
{
    std::string name;
    std::optional<double> a; // raw; empty: not known in that run
    std::optional<double> b;
};
// Rows whose values differ between two runs (or are known in only one), dictionary order of a.
std::vector<SettingDifference> settingDifferences(const TuningRun &a, const TuningRun &b);

// A one-line description for lists: "Run 3 · step 3.000 → 5.000 V · module 1 A1.01".
QString runTitle(const TuningRun &run);

// The run as its files hold it, and back: rows resolved in `dictionary`, the analysis computed
// again (false with why, for people, when a row or the signal does not exist).
RunFileData runFileData(const TuningRun &run);
bool runFromData(const RunFileData &data, const dev::Dictionary &dictionary, TuningRun &run,
                 QString *why);

// Saves `run` to `csvPath` and the JSON beside it (same name, ".json"). Empty on success, else
// why (for people).
QString saveRun(const TuningRun &run, const QString &csvPath);
// Reads a run saved by saveRun (either file's path) with the dictionaries to resolve the rows.
// The analysis is computed again from the recording.
std::optional<TuningRun> loadRun(const QString &path, const dev::DictionarySet &dictionaries,
                                 QString *why);

} // namespace vt::model
