// parseParamFile: bounded, typed reading of a .vtpar file (docs/FILE-FORMAT.md). Every problem
// becomes a FileError naming where it is; nothing here throws past the function.
#include "core/json_depth.h"
#include "param_file.h"

#include <cmath>
#include <limits>
#include <set>

namespace vt::dev::files {
namespace {

using Json = nlohmann::json;

// Beyond 2^53 a double no longer holds every integer: such a value would change on save.
constexpr std::int64_t kExactInteger = std::int64_t{1} << 53;

struct Failure
{
    FileError error;
};

[[noreturn]] void fail(FileErrc code, std::string location, LocalText message)
{
    throw Failure{{code, std::move(message), std::move(location), 0, 0}};
}

[[noreturn]] void failAt(FileErrc code, std::string_view text, std::size_t offset,
                         LocalText message)
{
    FileError e{code, std::move(message), {}, 1, 1};
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++e.line;
            e.column = 1;
        } else {
            ++e.column;
        }
    }
    throw Failure{std::move(e)};
}

// Nesting depth before the JSON parser sees the text: writing a deeply nested unknown key back
// would recurse once per level.
void checkDepth(std::string_view text)
{
    if (const auto at = jsonTooDeepAt(text, kMaxDepth))
        failAt(FileErrc::TooDeep, text, *at,
               {"nested deeper than " + std::to_string(kMaxDepth) + " levels",
                "tiefer als " + std::to_string(kMaxDepth) + " Ebenen verschachtelt"});
}

std::string typeNameDe(const Json &j)
{
    switch (j.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "Wahrheitswert";
    case Json::value_t::string: return "Text";
    case Json::value_t::array: return "Liste";
    case Json::value_t::object: return "Objekt";
    default: return "Zahl";
    }
}

[[noreturn]] void wrongType(const std::string &where, const std::string &key, const char *en,
                            const char *de, const Json &found)
{
    fail(FileErrc::WrongType, where + "/" + key,
         {"\"" + key + "\" must be " + en + ", not " + found.type_name(),
          "\"" + key + "\" muss " + de + " sein, nicht " + typeNameDe(found)});
}

// Keys the reader consumes; everything else of the object lands in `extra`.
class Fields
{
public:
    Fields(const Json &object, std::string where) : m_object(object), m_where(std::move(where)) {}

    const std::string &where() const { return m_where; }

    const Json *get(const std::string &key)
    {
        m_known.insert(key);
        const auto it = m_object.find(key);
        return it == m_object.end() ? nullptr : &*it;
    }

    const Json &require(const std::string &key)
    {
        const Json *j = get(key);
        if (!j)
            fail(FileErrc::MissingKey, m_where,
                 {"\"" + key + "\" is missing", "\"" + key + "\" fehlt"});
        return *j;
    }

    std::string text(const std::string &key, bool required = false)
    {
        const Json *j = required ? &require(key) : get(key);
        if (!j)
            return {};
        if (!j->is_string())
            wrongType(m_where, key, "a text", "ein Text", *j);
        return j->get<std::string>();
    }

    std::optional<std::int64_t> integer(const std::string &key, std::int64_t min, std::int64_t max,
                                        bool required = false)
    {
        const Json *j = required ? &require(key) : get(key);
        if (!j)
            return std::nullopt;
        if (!j->is_number_integer())
            wrongType(m_where, key, "a whole number", "eine ganze Zahl", *j);
        // The JSON parser holds every non-negative integer as unsigned.
        const bool fits =
            j->is_number_unsigned()
                ? max >= 0 && j->get<std::uint64_t>() <= static_cast<std::uint64_t>(max) &&
                      (min <= 0 || j->get<std::uint64_t>() >= static_cast<std::uint64_t>(min))
                : j->get<std::int64_t>() >= min && j->get<std::int64_t>() <= max;
        if (!fits)
            fail(
                FileErrc::BadValue, m_where + "/" + key,
                {"\"" + key + "\" must lie in " + std::to_string(min) + " … " + std::to_string(max),
                 "\"" + key + "\" muss in " + std::to_string(min) + " … " + std::to_string(max) +
                     " liegen"});
        return j->get<std::int64_t>();
    }

    std::optional<int> smallInt(const std::string &key)
    {
        const auto v =
            integer(key, std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
        return v ? std::optional<int>(static_cast<int>(*v)) : std::nullopt;
    }

    const Json &array(const std::string &key, std::size_t maxItems)
    {
        const Json &j = require(key);
        if (!j.is_array())
            wrongType(m_where, key, "a list", "eine Liste", j);
        if (j.size() > maxItems)
            fail(FileErrc::TooMany, m_where + "/" + key,
                 {"more than " + std::to_string(maxItems) + " entries in \"" + key + "\"",
                  "mehr als " + std::to_string(maxItems) + " Einträge in \"" + key + "\""});
        return j;
    }

    Json extra() const
    {
        Json out = Json::object();
        for (const auto &[key, value] : m_object.items())
            if (!m_known.count(key))
                out[key] = value;
        return out;
    }

private:
    const Json &m_object;
    std::string m_where;
    std::set<std::string> m_known;
};

RawValue readRaw(const Json &j, const std::string &where)
{
    if (j.is_string())
        return j.get<std::string>();
    if (j.is_number_integer()) {
        const bool exact =
            j.is_number_unsigned()
                ? j.get<std::uint64_t>() <= static_cast<std::uint64_t>(kExactInteger)
                : j.get<std::int64_t>() >= -kExactInteger && j.get<std::int64_t>() <= kExactInteger;
        if (!exact)
            fail(FileErrc::BadValue, where,
                 {"the whole number is too large to keep exactly",
                  "die ganze Zahl ist zu groß, um sie genau zu halten"});
        return j.get<double>();
    }
    if (j.is_number_float())
        return j.get<double>(); // the JSON parser refuses what does not fit a double
    if (j.is_object() && j.size() == 1 && j.contains("number") && j["number"].is_string()) {
        const std::string s = j["number"].get<std::string>();
        if (s == "NaN")
            return std::nan("");
        if (s == "Infinity")
            return HUGE_VAL;
        if (s == "-Infinity")
            return -HUGE_VAL;
        fail(FileErrc::BadValue, where + "/number",
             {"\"number\" must be NaN, Infinity or -Infinity",
              "\"number\" muss NaN, Infinity oder -Infinity sein"});
    }
    fail(FileErrc::WrongType, where,
         {std::string("\"raw\" must be a number or a text, not ") + j.type_name(),
          "\"raw\" muss eine Zahl oder ein Text sein, nicht " + typeNameDe(j)});
}

void requireObject(const Json &j, const std::string &where, const char *en, const char *de)
{
    if (!j.is_object())
        fail(FileErrc::WrongType, where,
             {std::string(en) + " must be an object, not " + j.type_name(),
              std::string(de) + " muss ein Objekt sein, nicht " + typeNameDe(j)});
}

ValueRow readRow(const Json &j, const std::string &where)
{
    requireObject(j, where, "a value row", "eine Wertzeile");
    Fields f(j, where);
    ValueRow row;
    row.name = f.text("name", true);
    if (row.name.empty())
        fail(FileErrc::BadValue, where + "/name",
             {"the row has no name", "die Zeile hat keinen Namen"});
    row.id = f.smallInt("id");
    row.ind = f.smallInt("ind");
    row.pnu = f.smallInt("pnu");
    row.instance = f.smallInt("instance");
    row.raw = readRaw(f.require("raw"), where + "/raw");
    row.display = f.text("display");
    row.extra = f.extra();
    return row;
}

ModuleRecord readModule(const Json &j, const std::string &where)
{
    requireObject(j, where, "a module", "ein Modul");
    Fields f(j, where);
    ModuleRecord m;
    m.address = static_cast<int>(*f.integer("address", 0, 255, true));
    m.family = f.text("family", true);
    if (m.family.empty())
        fail(FileErrc::BadValue, where + "/family",
             {"the module names no family", "das Modul nennt keine Familie"});
    m.version = f.text("version");
    m.mode = f.text("mode");
    m.label = f.text("label");
    const Json &values = f.array("values", kMaxRows);
    m.values.reserve(values.size());
    std::set<std::string> names;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::string rowWhere = where + "/values/" + std::to_string(i);
        ValueRow row = readRow(values[i], rowWhere);
        if (!names.insert(row.name).second)
            fail(FileErrc::Duplicate, rowWhere + "/name",
                 {"row " + row.name + " appears twice in module " + std::to_string(m.address),
                  "Zeile " + row.name + " steht zweimal in Modul " + std::to_string(m.address)});
        m.values.push_back(std::move(row));
    }
    m.extra = f.extra();
    return m;
}

ParamFile readFile(std::string_view text)
{
    if (text.size() > kMaxFileBytes)
        fail(
            FileErrc::TooLarge, {},
            {"the file is larger than " + std::to_string(kMaxFileBytes / (1024 * 1024)) + " MiB",
             "die Datei ist größer als " + std::to_string(kMaxFileBytes / (1024 * 1024)) + " MiB"});
    checkDepth(text);
    Json doc;
    try {
        doc = Json::parse(text.begin(), text.end());
    } catch (const Json::parse_error &e) {
        const std::size_t at = e.byte > 0 ? static_cast<std::size_t>(e.byte - 1) : 0;
        failAt(FileErrc::Syntax, text, at,
               {"not a valid JSON text (the file is damaged or truncated)",
                "kein gültiger JSON-Text (die Datei ist beschädigt oder abgeschnitten)"});
    }
    if (!doc.is_object() || !doc.contains("format") || doc["format"] != kFormatName)
        fail(
            FileErrc::NotAParamFile, {},
            {"not a ValveTune parameter file (no \"format\": \"" + std::string(kFormatName) + "\")",
             "keine ValveTune-Parameterdatei (kein \"format\": \"" + std::string(kFormatName) +
                 "\")"});
    Fields f(doc, {});
    (void)f.get("format");
    const std::int64_t version =
        *f.integer("formatVersion", 0, std::numeric_limits<std::int64_t>::max(), true);
    if (version > kFormatVersion)
        fail(FileErrc::NewerVersion, "/formatVersion",
             {"written by a newer ValveTune (file format " + std::to_string(version) +
                  "); this version reads format " + std::to_string(kFormatVersion) +
                  " — please update ValveTune",
              "von einem neueren ValveTune geschrieben (Dateiformat " + std::to_string(version) +
                  "); diese Version liest Format " + std::to_string(kFormatVersion) +
                  " — bitte ValveTune aktualisieren"});
    if (version < 1)
        fail(FileErrc::BadValue, "/formatVersion",
             {"file format 0 does not exist", "Dateiformat 0 gibt es nicht"});

    ParamFile out;
    out.formatVersion = static_cast<int>(version);
    out.tool = f.text("tool");
    out.created = f.text("created");
    out.note = f.text("note");
    const Json &modules = f.array("modules", kMaxModules);
    std::set<int> addresses;
    for (std::size_t i = 0; i < modules.size(); ++i) {
        const std::string where = "/modules/" + std::to_string(i);
        ModuleRecord m = readModule(modules[i], where);
        if (!addresses.insert(m.address).second)
            fail(FileErrc::Duplicate, where + "/address",
                 {"two modules have address " + std::to_string(m.address),
                  "zwei Module haben die Adresse " + std::to_string(m.address)});
        out.modules.push_back(std::move(m));
    }
    out.extra = f.extra();
    return out;
}

} // namespace

Result<ParamFile, FileError> parseParamFile(std::string_view text)
{
    try {
        return readFile(text);
    } catch (const Failure &f) {
        return f.error;
    } catch (const Json::exception &e) { // a JSON access the checks above missed: still typed
        return FileError{FileErrc::WrongType,
                         {std::string("unexpected JSON content: ") + e.what(),
                          std::string("unerwarteter JSON-Inhalt: ") + e.what()},
                         {},
                         0,
                         0};
    }
}

LocalText FileError::text() const
{
    if (line > 0)
        return {"line " + std::to_string(line) + ", column " + std::to_string(column) + ": " +
                    message.en,
                "Zeile " + std::to_string(line) + ", Spalte " + std::to_string(column) + ": " +
                    message.de};
    if (!location.empty())
        return {location + ": " + message.en, location + ": " + message.de};
    return message;
}

} // namespace vt::dev::files
