#include "reference_file.h"

#include "core/json_depth.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace vt::model {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char *kFormat = "valvetune-reference";
constexpr int kVersion = 1;
// The reference's own three levels (file, list, entry) over a run's eight (run_file.cpp).
constexpr int kMaxDepth = 12;
constexpr std::size_t kMaxFigures = 256;
constexpr std::size_t kMaxText = 256; // names, units, shown values

// NaN and infinities as null (JSON has no such numbers).
Json numberOrNull(double v)
{
    return std::isfinite(v) ? Json(v) : Json(nullptr);
}

struct Fields
{
    const Json &j;
    std::string where;
    std::string error;

    const Json *field(const char *name)
    {
        if (!error.empty())
            return nullptr;
        if (!j.is_object() || !j.contains(name)) {
            error = where + "\"" + name + "\" is missing";
            return nullptr;
        }
        return &j[name];
    }
    std::string text(const char *name)
    {
        const Json *v = field(name);
        if (v && (!v->is_string() || v->get_ref<const std::string &>().size() > kMaxText)) {
            error = where + "\"" + name + "\" is not a short text";
            return {};
        }
        return v ? v->get<std::string>() : std::string();
    }
    // `orNull`: null reads as NaN.
    double real(const char *name, bool orNull = false)
    {
        const Json *v = field(name);
        if (!v)
            return 0;
        if (orNull && v->is_null())
            return std::numeric_limits<double>::quiet_NaN();
        if (!v->is_number() || !std::isfinite(v->get<double>())) {
            error = where + "\"" + name + "\" is not a finite number";
            return 0;
        }
        return v->get<double>();
    }
    int whole(const char *name, int min, int max)
    {
        const Json *v = field(name);
        if (!v)
            return 0;
        if (!v->is_number_integer() || v->get<std::int64_t>() < min ||
            v->get<std::int64_t>() > max) {
            error = where + "\"" + name + "\" is not a whole number in range";
            return 0;
        }
        return static_cast<int>(v->get<std::int64_t>());
    }
    const Json *list(const char *name, std::size_t max)
    {
        const Json *v = field(name);
        if (v && (!v->is_array() || v->size() > max)) {
            error = where + "\"" + name + "\" is not a list of at most " + std::to_string(max);
            return nullptr;
        }
        return v;
    }
};

} // namespace

std::string referenceJson(const ReferenceFileData &r)
{
    Json settings = Json::array();
    for (const ReferenceSetting &s : r.settings)
        settings.push_back(
            Json{{"name", s.name}, {"raw", s.raw}, {"display", s.display}, {"unit", s.unit}});
    Json tests = Json::array();
    for (const ReferenceTest &t : r.tests)
        tests.push_back(
            Json{{"test", t.key}, {"run", Json::parse(runJson(t.run))}, {"csv", runCsv(t.run)}});
    Json figures = Json::array();
    for (const ReferenceFigure &f : r.figures)
        figures.push_back(Json{{"test", f.test},
                               {"metric", f.metric},
                               {"value", numberOrNull(f.value)},
                               {"unit", f.unit}});
    const Json j{
        {"format", kFormat},
        {"format_version", kVersion},
        {"saved", r.saved},
        {"module",
         {{"family", r.family}, {"version", r.version}, {"mode", r.mode}, {"address", r.address}}},
        {"set_value", r.setValue},
        {"centre", r.centre},
        {"amplitude", r.amplitude},
        {"settings", settings},
        {"tests", tests},
        {"figures", figures}};
    return j.dump(1) + "\n";
}

dev::Result<ReferenceFileData, std::string> parseReferenceFile(std::string_view text)
{
    if (text.size() > kMaxReferenceFileBytes)
        return std::string("the file is larger than 256 MiB");
    if (dev::jsonTooDeepAt(text, kMaxDepth))
        return std::string("the JSON is nested too deeply");
    const Json j = Json::parse(text.begin(), text.end(), nullptr, false);
    if (j.is_discarded() || !j.is_object())
        return std::string("not a valid JSON text (the file is damaged or truncated)");
    if (!j.contains("format") || j["format"] != kFormat)
        return std::string("not a ValveTune reference file");
    Fields f{j, {}, {}};
    if (f.whole("format_version", 1, 1'000'000) > kVersion)
        return std::string("written by a newer ValveTune (format version ") +
               std::to_string(j["format_version"].get<std::int64_t>()) + ")";
    ReferenceFileData r;
    r.saved = f.text("saved");
    r.setValue = f.text("set_value");
    r.centre = f.real("centre");
    r.amplitude = f.real("amplitude");
    const Json *module = f.field("module");
    const Json *settings = f.list("settings", kMaxReferenceSettings);
    const Json *tests = f.list("tests", kMaxReferenceTests);
    const Json *figures = f.list("figures", kMaxFigures);
    if (!f.error.empty())
        return f.error;
    Fields m{*module, "module: ", {}};
    r.family = m.text("family");
    r.version = m.text("version");
    r.mode = m.text("mode");
    r.address = m.whole("address", 0, 255);
    if (!m.error.empty())
        return m.error;
    for (const Json &s : *settings) {
        Fields e{s, "settings: ", {}};
        ReferenceSetting setting{e.text("name"), e.real("raw"), e.text("display"), e.text("unit")};
        if (!e.error.empty())
            return e.error;
        r.settings.push_back(std::move(setting));
    }
    for (const Json &t : *tests) {
        Fields e{t, "tests: ", {}};
        ReferenceTest test;
        test.key = e.text("test");
        const Json *run = e.field("run");
        const Json *csv = e.field("csv");
        if (!e.error.empty())
            return e.error;
        if (!run->is_object() || !csv->is_string())
            return std::string("tests: \"run\" must be a run and \"csv\" its recording");
        auto parsed = parseRunFiles(run->dump(), csv->get_ref<const std::string &>());
        if (!parsed.ok())
            return "test " + test.key + ": " + parsed.error();
        test.run = std::move(parsed).value();
        r.tests.push_back(std::move(test));
    }
    for (const Json &g : *figures) {
        Fields e{g, "figures: ", {}};
        ReferenceFigure figure{e.text("test"), e.text("metric"), e.real("value", true),
                               e.text("unit")};
        if (!e.error.empty())
            return e.error;
        r.figures.push_back(std::move(figure));
    }
    return r;
}

} // namespace vt::model
