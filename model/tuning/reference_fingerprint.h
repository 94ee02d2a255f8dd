// The reference fingerprint (issue #19, docs/TUNING.md "Reference fingerprint"): a module's
// settings and its responses to a standard test set — a step up and a step down around a set value
// and, if asked for, a stepped-sine sweep — kept in one file, and later compared with the same
// tests repeated on the module: which settings changed, which figures drifted beyond their
// thresholds, and the old and new responses overlaid. The tests themselves run through
// ReferenceSession (reference_session.h) on the workbench's test engine; this file holds the plan,
// the file's reading and writing, the check that a file fits a module and the comparison. Plain
// values; GUI thread for the file functions (Qt file access).
#pragma once

#include "model/session/device_access.h"
#include "model/tuning/reference_comparison.h"
#include "model/tuning/reference_file.h"
#include "model/tuning/tuning_run.h"

#include <QString>
#include <memory>
#include <optional>
#include <vector>

namespace vt::model {

// The standard tests: the set value moves between centre − amplitude and centre + amplitude.
struct ReferencePlan
{
    double centre = 0;    // display unit of the set value
    double amplitude = 0; // > 0
    double hold = 1;      // s each level of the steps is held (several settling times)
    bool sweep = false;
    double fromHz = 0.5;
    double toHz = 10;
    int pointsPerDecade = 5;
};

// One test of the set: "steps" (from centre − amplitude up to centre + amplitude and back down,
// each level held; its edges are the tests "step-up" and "step-down") or "sweep".
struct ReferenceTestSpec
{
    std::string key;
    SignalSpec spec;
};
std::vector<ReferenceTestSpec> referenceTests(const ReferencePlan &plan);

// A reference as saved or loaded: the file's data, and each test as a run (rows resolved in the
// family's dictionary, analysed), in the file's order.
struct Reference
{
    ReferenceFileData file;
    std::vector<std::shared_ptr<TuningRun>> runs;

    std::vector<ReferenceTestSpec> tests() const; // the specs to repeat
};

// A reference from a finished test set: identity of `module`, `settings` (raw, with their display
// text and unit in `language`), the runs and their figures.
Reference makeReference(const ModuleInfo &module, const dev::ParamMeta &setValue,
                        const ReferencePlan &plan, const std::vector<RunSetting> &settings,
                        std::vector<std::shared_ptr<TuningRun>> runs, dev::Language language);

// Writes `reference` to `path` (empty on success, else why, for people).
QString saveReference(const Reference &reference, const QString &path);
// Reads a file saved by saveReference; rows resolved in `dictionaries`, the runs analysed again.
std::optional<Reference> loadReference(const QString &path, const dev::DictionarySet &dictionaries,
                                       QString *why);

// Why `reference` does not fit `module` (another family, another mode, a set value the mode does
// not test); empty when it fits. Another software version or address only differs (noteworthy,
// not a reason to refuse): see referenceNotes.
QString referenceFitProblem(const ReferenceFileData &reference, const ModuleInfo &module);
QStringList referenceNotes(const ReferenceFileData &reference, const ModuleInfo &module);

// The drift: settings of the reference against `settings` now, the figures of each reference run
// against the run of the same test in `now` (the runs of reference.tests(), in that order; a test
// missing there has no figures now), with the overlays.
ReferenceComparison compareWithReference(const Reference &reference,
                                         const std::vector<std::shared_ptr<TuningRun>> &now,
                                         const std::vector<RunSetting> &settings,
                                         const DriftThresholds &thresholds, dev::Language language);

} // namespace vt::model
