// The commissioning report assembled: what a node (every module) or a parameter file holds, module
// by module, every setting with its value, range and default and where it differs from the default
// and from a reference parameter file; the write log, the chosen workbench runs, the fold/PLC
// configuration of an HCS node and the drift against a reference fingerprint. The renderers
// (report_render.h) turn it into JSON, HTML and PDF. A plain value; any thread, one at a time.
// The texts are made in `lang` when the report is rendered, through the catalogue in force.
#pragma once

#include "core/local_text.h"
#include "dict/dictionary.h"
#include "dict/raw_value.h"
#include "files/param_file.h"
#include "model/fold/fold_export.h"
#include "model/report/report_data.h"
#include "model/tuning/tuning_run.h"

#include <QDateTime>
#include <QString>
#include <map>
#include <optional>
#include <vector>

namespace vt::model {

struct ReportSetting
{
    const dev::ParamMeta *row = nullptr; // the dictionary row; outlives the report
    dev::RawValue value;
    std::optional<dev::RawValue> reference; // in the reference file; empty: none given or not there

    bool differsFromDefault() const;
    bool differsFromReference() const;
};

struct ReportModule
{
    int address = 0;
    const dev::Dictionary *dictionary = nullptr;
    std::string version;      // "51.02"
    std::string mode;         // "3"; empty when not applicable
    std::string label;        // the user's name for the module, from the file
    dev::LocalText identity;  // type code / serial as the device reports them; may be empty
    bool inReference = false; // the reference file holds this address
    std::vector<ReportSetting> settings; // dictionary order
};

struct Report
{
    ReportHeader header;
    QDateTime created;
    QString toolVersion; // "0.1.0"
    QString connection;  // "tcp 127.0.0.1:502, modbus-tcp, modules 1, 2, 3"; empty offline
    QString sourceFile;  // the parameter file reported offline; empty online
    QString referenceFile;
    std::vector<ReportModule> modules;
    std::vector<ReportWrite> writes;
    std::vector<TuningRun> runs;
    std::optional<FoldSheet> fold; // an HCS node: its PLC configuration
    ReportDrift drift;
    dev::Language lang = dev::Language::English;

    std::size_t settingCount() const;
};

struct ReportInput
{
    ReportHeader header;
    dev::files::ParamFile settings; // read from the node now, or the offline file
    QString connection;
    QString sourceFile;
    std::optional<dev::files::ParamFile> reference;
    QString referenceFile;
    std::vector<ReportWrite> writes;
    std::vector<TuningRun> runs;
    ReportDrift drift;
    std::map<int, dev::LocalText> identities; // by address: the device's identity words
    QDateTime created;
};

// Each module's settings (files/file_rows.h: no process or live values) that apply to its version
// and mode, in dictionary order, with the reference's values. Rows the file holds that the
// dictionary does not know are left out (the file keeps them); a module whose family has no
// dictionary is listed without settings.
Report assembleReport(ReportInput input, const dev::DictionarySet &dictionaries,
                      dev::Language lang);

} // namespace vt::model
