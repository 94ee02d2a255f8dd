// The report as JSON (docs/REPORT.md "JSON"): stable snake_case keys in a fixed order, raw values
// beside the texts the pages show, numbers as numbers (null when not finite).
#include "model/fold/plc_config.h"
#include "model/params/parameter_tree_model.h"
#include "report_render.h"
#include "report_text.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace vt::model {

namespace {

using Json = nlohmann::ordered_json;
using dev::Language;

std::string s(const QString &text)
{
    return text.toStdString();
}

Json number(double value)
{
    return std::isfinite(value) ? Json(value) : Json(nullptr);
}

Json raw(const dev::RawValue &value)
{
    if (dev::isText(value))
        return std::get<std::string>(value);
    return number(dev::rawNumber(value));
}

Json settingJson(const ReportSetting &setting, Language lang)
{
    const dev::ParamMeta &row = *setting.row;
    Json j{{"name", row.name},
           {"label", row.label.in(lang)},
           {"description", row.description.in(lang)},
           {"raw", raw(setting.value)},
           {"value", s(reportValueText(row, setting.value, lang))},
           {"unit", row.unit},
           {"range", s(ParameterTreeModel::rangeText(row, lang))}};
    j["default_raw"] = row.defaultValue ? number(*row.defaultValue) : Json(nullptr);
    j["default"] = row.defaultValue ? Json(s(reportDefaultText(row, lang))) : Json(nullptr);
    j["differs_from_default"] = setting.differsFromDefault();
    j["reference_raw"] = setting.reference ? raw(*setting.reference) : Json(nullptr);
    j["differs_from_reference"] = setting.differsFromReference();
    return j;
}

Json moduleJson(const ReportModule &m, Language lang)
{
    Json settings = Json::array();
    for (const ReportSetting &setting : m.settings)
        settings.push_back(settingJson(setting, lang));
    return Json{{"address", m.address},
                {"family", m.dictionary ? m.dictionary->family : std::string()},
                {"title", m.dictionary ? m.dictionary->title.in(lang) : std::string()},
                {"version", m.version},
                {"mode", m.mode},
                {"label", m.label},
                {"identity", m.identity.in(lang)},
                {"in_reference", m.inReference},
                {"settings", settings}};
}

Json writeJson(const ReportWrite &w, Language lang)
{
    return Json{{"time", s(w.time.toString(Qt::ISODateWithMs))},
                {"module", w.module},
                {"row", s(w.row)},
                {"name", s(w.name)},
                {"unit", s(w.unit)},
                {"old", s(w.oldText)},
                {"new", s(w.newText)},
                {"status", s(w.status)},
                {"status_text", s(reportWriteStatusText(w.status))},
                {"reason", s(reportWriteReason(w, lang))}};
}

Json runJson(const TuningRun &run)
{
    Json steps = Json::array();
    for (const StepResult &step : run.analysis.steps) {
        Json j{{"time_s", number(step.edge.time)},
               {"from", number(step.edge.from)},
               {"to", number(step.edge.to)}};
        if (step.metrics) {
            const StepMetrics &m = *step.metrics;
            j["dead_time_s"] = number(m.deadTime);
            j["rise_time_s"] = number(m.riseTime);
            j["overshoot_pct"] = number(m.overshootPct);
            j["peak_time_s"] = number(m.peakTime);
            j["settling_time_2_s"] = number(m.settlingTime2);
            j["settling_time_5_s"] = number(m.settlingTime5);
            j["steady_state_error"] = number(m.steadyStateError);
        } else if (step.problem) {
            j["problem"] = std::string(stepProblemKey(*step.problem));
        }
        steps.push_back(j);
    }
    Json points = Json::array();
    for (const FrequencyPoint &p : run.analysis.points)
        points.push_back(Json{{"frequency_hz", number(p.frequencyHz)},
                              {"gain_db", number(p.gainDb)},
                              {"phase_deg", number(p.phaseDeg)},
                              {"valid", p.valid}});
    return Json{{"number", run.number},
                {"title", s(runTitle(run))},
                {"started", s(run.started.toString(Qt::ISODate))},
                {"module", run.module},
                {"family", run.family},
                {"signal", key(run.spec.kind)},
                {"set_value", run.setValueRow ? run.setValueRow->name : std::string()},
                {"response", run.responseRow ? run.responseRow->name : std::string()},
                {"unit", run.setValueRow ? run.setValueRow->unit : std::string()},
                {"steps", steps},
                {"points", points},
                {"f3db_hz", run.analysis.f3dB ? number(*run.analysis.f3dB) : Json(nullptr)},
                {"f90deg_hz", run.analysis.f90deg ? number(*run.analysis.f90deg) : Json(nullptr)}};
}

Json foldJson(const FoldSheet &fold)
{
    const PlcConfig &c = fold.config;
    Json modules = Json::array();
    for (const PlcModuleSection &section : c.sections)
        modules.push_back(
            Json{{"module", section.module + 1},
                 {"address", fold.plan.modules[static_cast<std::size_t>(section.module)].address},
                 {"sadr", section.sadr},
                 {"layout", std::string(dev::hcs::profileInfo(section.profile).key)},
                 {"output_first", section.outputFirst},
                 {"output_last", section.outputFirst + section.outputLength - 1}});
    return Json{{"node", std::string(foldNodeKey(c.node))},
                {"gsd_file", c.gsdFile},
                {"gsd_device", c.gsdDevice},
                {"gsd_module", c.gsdModule},
                {"output_bytes", c.outputBytes},
                {"input_bytes", c.inputBytes},
                {"modules", modules}};
}

Json driftJson(const ReportDrift &d)
{
    Json params = Json::array();
    for (const ReportDriftParam &p : d.params)
        params.push_back(Json{{"module", p.module},
                              {"row", s(p.row)},
                              {"name", s(p.name)},
                              {"reference", s(p.reference)},
                              {"now", s(p.now)},
                              {"unit", s(p.unit)}});
    Json metrics = Json::array();
    for (const ReportDriftMetric &m : d.metrics)
        metrics.push_back(Json{{"module", m.module},
                               {"test", s(m.test)},
                               {"metric", s(m.metric)},
                               {"reference", number(m.reference)},
                               {"now", number(m.now)},
                               {"unit", s(m.unit)},
                               {"delta_pct", number(m.deltaPercent)},
                               {"threshold_pct", number(m.thresholdPercent)},
                               {"exceeded", m.exceeded}});
    Json curves = Json::array();
    for (const ReportDriftCurve &c : d.curves)
        curves.push_back(Json{{"module", c.module},
                              {"test", s(c.test)},
                              {"unit", s(c.unit)},
                              {"points", c.time.size()}});
    return Json{{"reference_file", s(d.referenceFile)},
                {"taken_at", s(d.takenAt.toString(Qt::ISODate))},
                {"params", params},
                {"metrics", metrics},
                {"curves", curves}};
}

} // namespace

std::string reportJson(const Report &r)
{
    Json modules = Json::array();
    for (const ReportModule &m : r.modules)
        modules.push_back(moduleJson(m, r.lang));
    Json writes = Json::array();
    for (const ReportWrite &w : r.writes)
        writes.push_back(writeJson(w, r.lang));
    Json runs = Json::array();
    for (const TuningRun &run : r.runs)
        runs.push_back(runJson(run));
    Json doc{{"format", "valvetune-report"},
             {"format_version", 1},
             {"language", r.lang == Language::German ? "de" : "en"},
             {"created", s(r.created.toString(Qt::ISODate))},
             {"tool", s(QStringLiteral("ValveTune ") + r.toolVersion)},
             {"connection", s(r.connection)},
             {"file", s(r.sourceFile)},
             {"reference_file", s(r.referenceFile)},
             {"header", Json{{"customer", s(r.header.customer)},
                             {"machine", s(r.header.machine)},
                             {"axis", s(r.header.axis)},
                             {"operator", s(r.header.operatorName)},
                             {"comment", s(r.header.comment)}}},
             {"modules", modules},
             {"writes", writes},
             {"runs", runs}};
    doc["fold"] = r.fold ? foldJson(*r.fold) : Json(nullptr);
    doc["drift"] = r.drift.empty() ? Json(nullptr) : driftJson(r.drift);
    return doc.dump(2) + '\n';
}

} // namespace vt::model
