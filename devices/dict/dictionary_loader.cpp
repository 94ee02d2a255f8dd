#include "dictionary_loader.h"

#include "dictionary_validate.h"
#include "monitor_defaults_load.h"

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>

namespace vt::dev {
namespace {

using Json = nlohmann::json;

struct RawFile
{
    std::string name;
    Json doc;
};

// A family with its inheritance applied, still as JSON.
struct Resolved
{
    Json header; // title, vendor, protocol, … (child keys over base keys)
    Json scales = Json::object();
    Json types = Json::object();
    Json blockDefaults = Json::object(); // block -> {"row_kind", "moves_actuator"}
    std::vector<Json> rows;
};

class Loader
{
public:
    explicit Loader(const std::vector<DictionaryFile> &files) { parseAll(files); }

    Result<DictionarySet, DictionaryErrors> run()
    {
        DictionarySet set;
        for (const auto &[family, raw] : m_raw) {
            try {
                std::set<std::string> visiting;
                const Resolved *r = resolve(family, visiting);
                if (!r)
                    continue;
                if (auto dict = build(raw.name, family, *r))
                    set.add(std::move(dict));
            } catch (const Json::exception &e) { // a family-level key of the wrong JSON type
                error(raw.name, {}, e.what());
            }
        }
        if (!m_errors.empty())
            return m_errors;
        return set;
    }

private:
    void error(const std::string &file, const std::string &row, const std::string &message)
    {
        m_errors.push_back({file, row, message});
    }

    void parseAll(const std::vector<DictionaryFile> &files)
    {
        for (const DictionaryFile &f : files) {
            try {
                parseOne(f);
            } catch (const Json::exception &e) { // a file-level key of the wrong JSON type
                error(f.name, {}, e.what());
            }
        }
    }

    void parseOne(const DictionaryFile &f)
    {
        {
            Json doc = Json::parse(f.text, nullptr, /*allow_exceptions=*/false);
            if (doc.is_discarded() || !doc.is_object()) {
                error(f.name, {}, "not a JSON object (syntax error)");
                return;
            }
            if (doc.value("schema", 0) != 1) {
                error(f.name, {}, "unsupported or missing \"schema\" (expected 1)");
                return;
            }
            const std::string family = doc.value("family", std::string());
            if (family.empty() || f.name != family + ".json") {
                error(f.name, {}, "\"family\" must equal the file name without .json");
                return;
            }
            if (!doc.contains("parameters") || !doc["parameters"].is_array()) {
                error(f.name, {}, "\"parameters\" must be an array");
                return;
            }
            m_raw[family] = RawFile{f.name, std::move(doc)};
        }
    }

    const Resolved *resolve(const std::string &family, std::set<std::string> &visiting)
    {
        if (auto it = m_resolved.find(family); it != m_resolved.end())
            return &it->second;
        const auto rawIt = m_raw.find(family);
        if (rawIt == m_raw.end())
            return nullptr;
        const RawFile &raw = rawIt->second;
        if (!visiting.insert(family).second) {
            error(raw.name, {}, "\"extends\" forms a cycle");
            return nullptr;
        }

        Resolved out;
        const std::string base = raw.doc.value("extends", std::string());
        if (!base.empty()) {
            if (!m_raw.count(base)) {
                error(raw.name, {}, "extends unknown family '" + base + "'");
                return nullptr;
            }
            const Resolved *b = resolve(base, visiting);
            if (!b)
                return nullptr;
            out = *b;
        }
        for (const char *key : {"title", "vendor", "protocol", "source", "versions", "modes",
                                "write_pacing", "monitor"})
            if (raw.doc.contains(key))
                out.header[key] = raw.doc[key];
        out.header["abstract"] = raw.doc.value("abstract", false);
        if (raw.doc.contains("scales") && raw.doc["scales"].is_object())
            out.scales.update(raw.doc["scales"]);
        if (raw.doc.contains("types") && raw.doc["types"].is_object())
            out.types.update(raw.doc["types"]);
        if (raw.doc.contains("block_defaults")) {
            if (raw.doc["block_defaults"].is_object())
                out.blockDefaults.update(raw.doc["block_defaults"]); // per block, child wins
            else
                error(raw.name, {}, "\"block_defaults\" must be an object");
        }

        std::size_t index = 0;
        for (const Json &row : raw.doc["parameters"]) {
            ++index;
            if (!row.is_object() || !row.contains("name") || !row["name"].is_string()) {
                error(raw.name, "#" + std::to_string(index), "row without a \"name\"");
                continue;
            }
            const std::string name = row["name"].get<std::string>();
            auto it = std::find_if(out.rows.begin(), out.rows.end(),
                                   [&](const Json &r) { return r["name"] == name; });
            if (it != out.rows.end() && !base.empty())
                it->update(row); // derived row overrides the inherited one key by key
            else
                out.rows.push_back(row); // duplicates inside one file are caught by validation
        }
        if (raw.doc.contains("remove") && raw.doc["remove"].is_array()) {
            for (const Json &n : raw.doc["remove"]) {
                const auto before = out.rows.size();
                std::erase_if(out.rows, [&](const Json &r) { return r["name"] == n; });
                if (out.rows.size() == before)
                    error(raw.name, n.is_string() ? n.get<std::string>() : "?",
                          "\"remove\" names no inherited row");
            }
        }
        visiting.erase(family);
        return &m_resolved.emplace(family, std::move(out)).first->second;
    }

    static LocalText localText(const Json &j)
    {
        if (!j.is_object())
            return {};
        return {j.value("en", std::string()), j.value("de", std::string())};
    }

    std::shared_ptr<Dictionary> build(const std::string &file, const std::string &family,
                                      const Resolved &r)
    {
        auto dict = std::make_shared<Dictionary>();
        dict->family = family;
        dict->abstract = r.header.value("abstract", false);
        dict->title = localText(r.header.value("title", Json::object()));
        dict->vendor = r.header.value("vendor", std::string());
        dict->source = r.header.value("source", std::string());
        dict->versions = r.header.value("versions", std::vector<std::string>());
        dict->modes = r.header.value("modes", std::vector<std::string>());
        if (r.header.contains("write_pacing")) {
            const Json &pacing = r.header["write_pacing"];
            const Json ms = pacing.is_object() ? pacing.value("ms", Json()) : Json();
            if (ms.is_number_integer() && ms.get<int>() >= 0 && ms.get<int>() <= 10'000) {
                dict->writePacingMs = ms.get<int>();
                dict->writePacingAssumed = pacing.value("assumed", false);
            } else {
                error(file, {}, "\"write_pacing\" needs \"ms\": 0..10000");
            }
        }
        const std::string protocol = r.header.value("protocol", std::string());
        if (const auto known = fromKey<DeviceProtocol>(protocol))
            dict->protocol = *known;
        else
            error(file, {}, "unknown \"protocol\" '" + protocol + "'");

        const std::size_t errorsBefore = m_errors.size();
        checkBlockDefaults(file, r);
        for (const Json &row : r.rows) {
            Json merged = row;
            const std::string name = row["name"].get<std::string>();
            if (row.contains("kind")) {
                const std::string kind = row.value("kind", std::string());
                if (!r.types.contains(kind)) {
                    error(file, name, "unknown kind '" + kind + "'");
                    continue;
                }
                merged = r.types[kind];
                merged.update(row);
            }
            try {
                applyBlockDefaults(merged, r.blockDefaults);
                if (auto meta = toMeta(file, name, merged, r.scales))
                    dict->params.push_back(std::move(*meta));
            } catch (const Json::exception &e) { // a key of the wrong JSON type
                error(file, name, e.what());
            }
        }
        dict->buildIndex();
        for (DictionaryError &e : validateDictionary(*dict))
            m_errors.push_back({file, e.row, e.message});
        // An abstract base may name rows its families remove; only concrete families are checked.
        if (r.header.contains("monitor") && !dict->abstract) {
            std::vector<DictionaryError> monitorErrors;
            dict->monitor = loadMonitorDefaults(r.header["monitor"], *dict, monitorErrors);
            for (DictionaryError &e : monitorErrors)
                m_errors.push_back({file, e.row, e.message});
        }
        if (m_errors.size() != errorsBefore)
            return nullptr;
        return dict;
    }

    // A block default is a key the rows of that block take unless the row (or its named type)
    // gives it; docs/DICTIONARY.md "Row kinds" records the rule of each family.
    static void applyBlockDefaults(Json &row, const Json &blockDefaults)
    {
        const Json block = row.value("block", Json());
        if (!block.is_string() || !blockDefaults.contains(block.get<std::string>()))
            return;
        const Json &defaults = blockDefaults[block.get<std::string>()];
        if (!defaults.is_object())
            return; // reported by checkBlockDefaults
        for (const auto &[key, value] : defaults.items())
            if (key != "note" && !row.contains(key))
                row[key] = value;
    }

    // Only row kinds are block defaults, and each names a block that exists: a misspelt block
    // would otherwise leave its rows settings without a word.
    void checkBlockDefaults(const std::string &file, const Resolved &r)
    {
        std::set<std::string> blocks;
        for (const Json &row : r.rows)
            if (row.contains("block") && row["block"].is_string())
                blocks.insert(row["block"].get<std::string>());
        for (const auto &[block, defaults] : r.blockDefaults.items()) {
            if (!defaults.is_object()) {
                error(file, {}, "block_defaults '" + block + "' must be an object");
                continue;
            }
            for (const auto &[key, value] : defaults.items())
                if (key != "row_kind" && key != "moves_actuator" && key != "note")
                    error(file, {},
                          "block_defaults '" + block + "' may set only " +
                              "row_kind and moves_actuator (and a note), not '" + key + "'");
            if (!blocks.count(block))
                error(file, {}, "block_defaults names block '" + block + "', which no row has");
        }
    }

    std::optional<ParamMeta> toMeta(const std::string &file, const std::string &name, const Json &j,
                                    const Json &scales)
    {
        ParamMeta p;
        p.name = name;
        auto optInt = [&](const char *key) -> std::optional<int> {
            if (!j.contains(key))
                return std::nullopt;
            if (!j[key].is_number_integer()) {
                error(file, name, std::string("\"") + key + "\" must be an integer");
                return std::nullopt;
            }
            return j[key].get<int>();
        };
        auto number = [&](const char *key, double fallback) {
            if (!j.contains(key))
                return fallback;
            if (!j[key].is_number()) {
                error(file, name, std::string("\"") + key + "\" must be a number");
                return fallback;
            }
            return j[key].get<double>();
        };
        p.id = optInt("id");
        p.ind = optInt("ind");
        p.pnu = optInt("pnu");
        p.instance = optInt("instance").value_or(0);
        p.pzd = optInt("pzd");
        p.branch = optInt("branch").value_or(0);
        p.length = optInt("length").value_or(0);
        p.block = j.value("block", std::string());

        const auto access = parseAccess(j.value("access", std::string()));
        if (!access) {
            error(file, name, "missing or unknown \"access\"");
            return std::nullopt;
        }
        p.access = *access;
        if (j.contains("row_kind")) {
            const Json &k = j["row_kind"];
            const auto kind = k.is_string() ? fromKey<RowKind>(k.get<std::string>()) : std::nullopt;
            if (!kind) {
                error(file, name, "\"row_kind\" must be setting, process or live");
                return std::nullopt;
            }
            p.kind = *kind;
        }
        if (j.contains("moves_actuator")) {
            if (!j["moves_actuator"].is_boolean()) {
                error(file, name, "\"moves_actuator\" must be true or false");
                return std::nullopt;
            }
            p.movesActuator = j["moves_actuator"].get<bool>();
        }
        const auto type = parseRawType(j.value("type", std::string()));
        if (!type) {
            error(file, name, "missing or unknown \"type\"");
            return std::nullopt;
        }
        p.type = *type;
        p.min = number("min", typeMin(p.type));
        p.max = number("max", typeMax(p.type));
        p.step = number("step", 1);
        p.minParam = j.value("min_param", std::string());
        p.maxParam = j.value("max_param", std::string());
        if (j.contains("default"))
            p.defaultValue = number("default", 0);
        p.defaultAssumed = j.value("default_assumed", false);
        p.unit = j.value("unit", std::string());

        if (j.contains("scale")) {
            const std::string s = j.value("scale", std::string());
            if (!scales.contains(s)) {
                error(file, name, "unknown scale '" + s + "'");
                return std::nullopt;
            }
            const Json &sj = scales[s];
            p.scale.name = s;
            p.scale.factor = sj.value("factor", 0.0);
            p.scale.decimals = sj.value("decimals", 0);
            p.scale.rounding = sj.value("rounding", std::string("nearest")) == "truncate"
                                   ? Rounding::Truncate
                                   : Rounding::Nearest;
            p.scale.assumed = sj.value("assumed", false);
            p.scale.note = sj.value("note", std::string());
            if (!(p.scale.factor > 0) || !std::isfinite(p.scale.factor) || p.scale.decimals < 0 ||
                p.scale.decimals > 9) {
                error(file, name, "scale '" + s + "' needs a positive factor and 0..9 decimals");
                return std::nullopt;
            }
            // Every raw step must show as its own display value, or editing loses precision
            // silently (and display -> raw no longer round-trips).
            if (std::pow(10.0, -p.scale.decimals) > p.scale.factor * (1 + 1e-9)) {
                error(file, name, "scale '" + s + "' shows too few decimals for one raw step");
                return std::nullopt;
            }
        }
        if (j.contains("enum")) {
            for (const Json &e : j["enum"]) {
                if (!e.contains("value") || !e["value"].is_number_integer()) {
                    error(file, name, "enum entry without an integer \"value\"");
                    continue;
                }
                p.enums.push_back({e["value"].get<std::int64_t>(), localText(e)});
            }
        }
        if (j.contains("bits")) {
            for (const Json &b : j["bits"]) {
                if (!b.contains("bit") || !b["bit"].is_number_integer()) {
                    error(file, name, "bit entry without an integer \"bit\"");
                    continue;
                }
                p.bits.push_back({b["bit"].get<int>(), localText(b)});
            }
        }
        p.modes = j.value("modes", std::vector<std::string>());
        p.versions = j.value("versions", std::vector<std::string>());
        const std::string persistence = j.value("persistence", std::string());
        p.persistence = persistence == "eeprom"     ? Persistence::Eeprom
                        : persistence == "volatile" ? Persistence::Volatile
                                                    : Persistence::Unspecified;
        if (j.contains("canopen")) {
            const Json &c = j["canopen"];
            p.canopen = CanObject{static_cast<std::uint16_t>(c.value("index", 0)),
                                  static_cast<std::uint8_t>(c.value("sub", 0))};
        } else if (p.id) {
            // ARCHITECTURE.md "CAN": HCS parameters live at the manufacturer object 0x2000 + ID.
            p.canopen = CanObject{static_cast<std::uint16_t>(0x2000 + *p.id), 0};
        }
        p.label = localText(j.value("label", Json::object()));
        p.description = localText(j.value("description", Json::object()));
        p.note = j.value("note", std::string());
        return p;
    }

    std::map<std::string, RawFile> m_raw;
    std::map<std::string, Resolved> m_resolved;
    DictionaryErrors m_errors;
};

} // namespace

Result<DictionarySet, DictionaryErrors> loadDictionaries(const std::vector<DictionaryFile> &files)
{
    return Loader(files).run();
}

const Result<DictionarySet, DictionaryErrors> &builtinDictionaries()
{
    static const Result<DictionarySet, DictionaryErrors> set =
        loadDictionaries(embeddedDictionaryFiles());
    return set;
}

} // namespace vt::dev
