// writeParamFile and the small helpers of the document: a stable, diff-friendly text (one value
// row per line) that parseParamFile reads back to the same document.
#include "dict/cooking.h"
#include "param_file.h"
#include "param_file_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace vt::dev::files {
namespace {

using Json = nlohmann::json;

// Beyond this the display text would lose digits (and enum lookup casts to an integer).
constexpr double kDisplayLimit = 1e15;

std::string dump(const Json &j)
{
    // Strings held in memory may come from a device; never throw on invalid UTF-8.
    return j.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string quoted(const std::string &s)
{
    return dump(Json(s));
}

std::string rawJson(const RawValue &raw)
{
    if (isText(raw))
        return quoted(std::get<std::string>(raw));
    const double v = rawNumber(raw);
    if (!std::isfinite(v))
        return "{\"number\": " + quoted(rawNumberText(v)) + "}";
    return rawNumberText(v);
}

// Unknown keys, minus any that would collide with the ones written explicitly.
template<std::size_t N>
std::vector<std::pair<std::string, std::string>>
extraFields(const Json &extra, const std::array<const char *, N> &known)
{
    std::vector<std::pair<std::string, std::string>> out;
    if (!extra.is_object())
        return out;
    for (auto it = extra.begin(); it != extra.end(); ++it) {
        const std::string &key = it.key(); // (clang 14 cannot capture a structured binding)
        if (std::find_if(known.begin(), known.end(), [&](const char *k) { return key == k; }) ==
            known.end())
            out.emplace_back(quoted(key), dump(*it));
    }
    return out;
}

constexpr std::array<const char *, 6> kFileKeys{"format",  "formatVersion", "tool",
                                                "created", "note",          "modules"};
constexpr std::array<const char *, 6> kModuleKeys{"address", "family", "version",
                                                  "mode",    "label",  "values"};
constexpr std::array<const char *, 7> kRowKeys{"name",     "id",  "ind",    "pnu",
                                               "instance", "raw", "display"};

std::string displayFor(const Dictionary *dict, const ValueRow &row, Language lang)
{
    if (!dict)
        return row.display;
    const ParamMeta *meta = findMeta(*dict, row);
    if (!meta || meta->isString() || isText(row.raw))
        return row.display;
    const double v = rawNumber(row.raw);
    if (!std::isfinite(v) || std::fabs(v) > kDisplayLimit)
        return {};
    std::string out = formatValue(*meta, v, lang);
    if (!meta->bits.empty() && v >= 0 && v <= 4294967295.0 && v == std::floor(v)) {
        const std::string bits = formatBits(*meta, static_cast<std::uint32_t>(v), lang);
        if (!bits.empty())
            out += " (" + bits + ")";
    }
    return out;
}

std::string rowLine(const ValueRow &row, const Dictionary *dict, Language lang)
{
    std::string s = "{\"name\": " + quoted(row.name);
    const auto number = [&](const char *key, const std::optional<int> &v) {
        if (v)
            s += ", \"" + std::string(key) + "\": " + std::to_string(*v);
    };
    number("id", row.id);
    number("ind", row.ind);
    number("pnu", row.pnu);
    number("instance", row.instance);
    s += ", \"raw\": " + rawJson(row.raw);
    if (const std::string display = displayFor(dict, row, lang); !display.empty())
        s += ", \"display\": " + quoted(display);
    for (const auto &[key, value] : extraFields(row.extra, kRowKeys))
        s += ", " + key + ": " + value;
    return s + "}";
}

void writeModule(std::string &out, const ModuleRecord &m, const DictionarySet *set, Language lang)
{
    const std::string in = "      ";
    out += "    {\n";
    out += in + "\"address\": " + std::to_string(m.address) + ",\n";
    out += in + "\"family\": " + quoted(m.family) + ",\n";
    out += in + "\"version\": " + quoted(m.version) + ",\n";
    out += in + "\"mode\": " + quoted(m.mode) + ",\n";
    if (!m.label.empty())
        out += in + "\"label\": " + quoted(m.label) + ",\n";
    for (const auto &[key, value] : extraFields(m.extra, kModuleKeys))
        out += in + key + ": " + value + ",\n";
    const Dictionary *dict = set ? set->find(m.family) : nullptr;
    if (m.values.empty()) {
        out += in + "\"values\": []\n";
    } else {
        out += in + "\"values\": [\n";
        for (std::size_t i = 0; i < m.values.size(); ++i)
            out += in + "  " + rowLine(m.values[i], dict, lang) +
                   (i + 1 < m.values.size() ? ",\n" : "\n");
        out += in + "]\n";
    }
    out += "    }";
}

} // namespace

std::string rawNumberText(double v)
{
    if (std::isnan(v))
        return "NaN";
    if (std::isinf(v))
        return v > 0 ? "Infinity" : "-Infinity";
    // Whole numbers as integers (-0.0 keeps its sign as a float); the rest shortest-exact.
    if (v == std::floor(v) && std::fabs(v) <= 9007199254740992.0 && !(v == 0 && std::signbit(v)))
        return std::to_string(static_cast<std::int64_t>(v));
    return dump(Json(v));
}

std::string writeParamFile(const ParamFile &file, const DictionarySet *forDisplay, Language lang)
{
    std::string out = "{\n";
    out += "  \"format\": " + quoted(kFormatName) + ",\n";
    out += "  \"formatVersion\": " + std::to_string(kFormatVersion) + ",\n";
    out += "  \"tool\": " + quoted(file.tool) + ",\n";
    out += "  \"created\": " + quoted(file.created) + ",\n";
    if (!file.note.empty())
        out += "  \"note\": " + quoted(file.note) + ",\n";
    for (const auto &[key, value] : extraFields(file.extra, kFileKeys))
        out += "  " + key + ": " + value + ",\n";
    if (file.modules.empty()) {
        out += "  \"modules\": []\n";
    } else {
        out += "  \"modules\": [\n";
        for (std::size_t i = 0; i < file.modules.size(); ++i) {
            writeModule(out, file.modules[i], forDisplay, lang);
            out += i + 1 < file.modules.size() ? ",\n" : "\n";
        }
        out += "  ]\n";
    }
    return out + "}\n";
}

const ValueRow *ModuleRecord::find(const std::string &name) const
{
    const auto it = std::find_if(values.begin(), values.end(),
                                 [&](const ValueRow &r) { return r.name == name; });
    return it == values.end() ? nullptr : &*it;
}

const ModuleRecord *ParamFile::findModule(int address) const
{
    const auto it = std::find_if(modules.begin(), modules.end(),
                                 [&](const ModuleRecord &m) { return m.address == address; });
    return it == modules.end() ? nullptr : &*it;
}

ValueRow makeValueRow(const ParamMeta &meta, RawValue raw)
{
    ValueRow row;
    row.name = meta.name;
    row.id = meta.id;
    row.ind = meta.ind;
    row.pnu = meta.pnu;
    if (meta.ind && meta.pnu && meta.instance != 0)
        row.instance = meta.instance;
    row.raw = std::move(raw);
    return row;
}

std::string isoUtc(std::chrono::system_clock::time_point when)
{
    using namespace std::chrono;
    const auto day = floor<days>(when);
    const year_month_day ymd{day};
    const hh_mm_ss<seconds> t{floor<seconds>(when - day)};
    char buf[32];
    std::snprintf(buf, sizeof buf, "%04d-%02u-%02uT%02d:%02d:%02dZ", static_cast<int>(ymd.year()),
                  static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()),
                  static_cast<int>(t.hours().count()), static_cast<int>(t.minutes().count()),
                  static_cast<int>(t.seconds().count()));
    return buf;
}

} // namespace vt::dev::files
