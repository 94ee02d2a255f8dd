#include "fold_plan_file.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

namespace vt::model {

using dev::LocalText;
using Json = nlohmann::json;

namespace {

constexpr int kMaxDepth = 8; // the format nests 4 deep; anything deeper is not a plan

FoldFileError error(FoldFileErrc code, std::string member, LocalText message,
                    std::size_t offset = 0)
{
    return FoldFileError{code, std::move(member), offset, std::move(message)};
}

FoldFileError bad(const std::string &member, const std::string &what_en, const std::string &what_de)
{
    return error(FoldFileErrc::BadMember, member,
                 {"The fold plan file is damaged: " + member + " " + what_en + ".",
                  "Die Modulplan-Datei ist beschädigt: " + member + " " + what_de + "."});
}

FoldFileError missing(const std::string &member)
{
    return error(FoldFileErrc::MissingMember, member,
                 {"The fold plan file is incomplete: " + member + " is missing.",
                  "Die Modulplan-Datei ist unvollständig: " + member + " fehlt."});
}

// Nesting depth outside strings, so a hostile "[[[[…" never reaches the recursive parts of the
// JSON library (its destructor recurses).
bool depthWithin(std::string_view text, int limit)
{
    int depth = 0;
    bool inString = false, escaped = false;
    for (char c : text) {
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"')
            inString = true;
        else if (c == '[' || c == '{') {
            if (++depth > limit)
                return false;
        } else if (c == ']' || c == '}')
            --depth;
    }
    return true;
}

class Reader
{
public:
    std::optional<FoldFileError> err;

    std::optional<int> integer(const Json &obj, const std::string &key, const std::string &path,
                               long long min, long long max, bool required)
    {
        const auto it = obj.find(key);
        if (it == obj.end()) {
            if (required && !err)
                err = missing(path);
            return std::nullopt;
        }
        if (!it->is_number_integer()) {
            if (!err)
                err = bad(path, "is not a whole number", "ist keine ganze Zahl");
            return std::nullopt;
        }
        long long v = 0;
        if (it->is_number_unsigned()) {
            const auto u = it->get<std::uint64_t>();
            v = u > static_cast<std::uint64_t>(std::numeric_limits<long long>::max())
                    ? std::numeric_limits<long long>::max()
                    : static_cast<long long>(u);
        } else {
            v = it->get<std::int64_t>();
        }
        if (v < min || v > max) {
            if (!err)
                err = bad(path, "is outside " + std::to_string(min) + " … " + std::to_string(max),
                          "liegt außerhalb " + std::to_string(min) + " … " + std::to_string(max));
            return std::nullopt;
        }
        return static_cast<int>(v);
    }

    std::string text(const Json &obj, const std::string &key, const std::string &path)
    {
        const auto it = obj.find(key);
        if (it == obj.end())
            return {};
        if (!it->is_string()) {
            if (!err)
                err = bad(path, "is not a text", "ist kein Text");
            return {};
        }
        const auto &s = it->get_ref<const std::string &>();
        if (s.size() > kFoldPlanMaxText) {
            if (!err)
                err = bad(path, "is longer than " + std::to_string(kFoldPlanMaxText) + " bytes",
                          "ist länger als " + std::to_string(kFoldPlanMaxText) + " Byte");
            return {};
        }
        return s;
    }
};

constexpr const char *kOptionNames[] = {"E17", "E23", "E24", "E26", "E28"};

} // namespace

std::string writeFoldPlan(const FoldPlan &plan)
{
    Json root = Json::object();
    root["format"] = kFoldPlanFormat;
    root["formatVersion"] = kFoldPlanVersion;
    root["node"] = foldNodeKey(plan.node);
    root["title"] = plan.title;
    root["product_number"] = plan.productNumber;
    if (plan.plcSnum)
        root["plc_snum"] = *plan.plcSnum;
    root["notes"] = plan.notes;
    Json modules = Json::array();
    for (const FoldModule &m : plan.modules) {
        Json jm = Json::object();
        jm["name"] = m.name;
        jm["version"] = m.version;
        jm["mode"] = m.mode;
        jm["address"] = m.address;
        Json options = Json::object();
        for (const char *name : kOptionNames)
            if (const auto v = foldOption(m.options, name))
                options[name] = *v;
        jm["options"] = options;
        modules.push_back(jm);
    }
    root["modules"] = modules;
    // nlohmann::ordered_json is not used: keys come out sorted, which is stable enough for diffs.
    return root.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

dev::Result<FoldPlan, FoldFileError> parseFoldPlan(std::string_view text)
{
    if (text.size() > kFoldPlanMaxBytes)
        return error(FoldFileErrc::TooLarge, {},
                     {"The file is larger than " + std::to_string(kFoldPlanMaxBytes / 1024) +
                          " KiB; it is not a fold plan.",
                      "Die Datei ist größer als " + std::to_string(kFoldPlanMaxBytes / 1024) +
                          " KiB; sie ist kein Modulplan."});
    if (!depthWithin(text, kMaxDepth))
        return error(FoldFileErrc::WrongFormat, {},
                     {"The file is nested too deeply to be a fold plan.",
                      "Die Datei ist zu tief verschachtelt für einen Modulplan."});
    Json root;
    try {
        root = Json::parse(text.begin(), text.end());
    } catch (const Json::parse_error &e) {
        return error(FoldFileErrc::NotJson, {},
                     {"The file is not valid JSON (byte " + std::to_string(e.byte) + ").",
                      "Die Datei ist kein gültiges JSON (Byte " + std::to_string(e.byte) + ")."},
                     e.byte);
    } catch (const Json::exception &) { // e.g. out_of_range: a number beyond double ("1E999999")
        return error(
            FoldFileErrc::NotJson, {},
            {"The file is not valid JSON (a number is out of range).",
             "Die Datei ist kein gültiges JSON (eine Zahl liegt außerhalb des Bereichs)."});
    }
    if (!root.is_object())
        return error(
            FoldFileErrc::WrongFormat, {},
            {"The file is not a ValveTune fold plan.", "Die Datei ist kein ValveTune-Modulplan."});
    const auto format = root.find("format");
    if (format == root.end() || !format->is_string() ||
        format->get_ref<const std::string &>() != kFoldPlanFormat)
        return error(
            FoldFileErrc::WrongFormat, "format",
            {"The file is not a ValveTune fold plan.", "Die Datei ist kein ValveTune-Modulplan."});

    Reader r;
    const auto version =
        r.integer(root, "formatVersion", "formatVersion", 1, std::numeric_limits<int>::max(), true);
    if (r.err)
        return *r.err;
    if (*version > kFoldPlanVersion)
        return error(
            FoldFileErrc::NewerVersion, "formatVersion",
            {"The fold plan was written by a newer ValveTune (format version " +
                 std::to_string(*version) + "); this version reads format " +
                 std::to_string(kFoldPlanVersion) + ".",
             "Der Modulplan wurde von einem neueren ValveTune geschrieben (Formatversion " +
                 std::to_string(*version) + "); diese Version liest Format " +
                 std::to_string(kFoldPlanVersion) + "."});

    FoldPlan plan;
    const auto node = root.find("node");
    if (node == root.end())
        return missing("node");
    if (!node->is_string() || !foldNodeFromKey(node->get_ref<const std::string &>()))
        return bad("node", "is not opat, dma-pb or dma-pn", "ist nicht opat, dma-pb oder dma-pn");
    plan.node = *foldNodeFromKey(node->get_ref<const std::string &>());
    plan.title = r.text(root, "title", "title");
    plan.productNumber = r.text(root, "product_number", "product_number");
    plan.notes = r.text(root, "notes", "notes");
    plan.plcSnum = r.integer(root, "plc_snum", "plc_snum", 0, 255, false);
    if (r.err)
        return *r.err;

    const auto modules = root.find("modules");
    if (modules == root.end())
        return missing("modules");
    if (!modules->is_array())
        return bad("modules", "is not a list", "ist keine Liste");
    if (modules->size() > kFoldPlanMaxModules)
        return bad("modules", "has more than " + std::to_string(kFoldPlanMaxModules) + " entries",
                   "hat mehr als " + std::to_string(kFoldPlanMaxModules) + " Einträge");
    for (std::size_t i = 0; i < modules->size(); ++i) {
        const Json &jm = (*modules)[i];
        const std::string path = "modules[" + std::to_string(i) + "]";
        if (!jm.is_object())
            return bad(path, "is not an object", "ist kein Objekt");
        FoldModule m;
        m.name = r.text(jm, "name", path + ".name");
        m.version = r.integer(jm, "version", path + ".version", 0, 99, false).value_or(0);
        m.mode = r.integer(jm, "mode", path + ".mode", 0, 15, false).value_or(0);
        const auto address = r.integer(jm, "address", path + ".address", 0, 255, true);
        if (r.err)
            return *r.err;
        m.address = *address;
        const auto options = jm.find("options");
        if (options != jm.end()) {
            if (!options->is_object())
                return bad(path + ".options", "is not an object", "ist kein Objekt");
            for (const char *name : kOptionNames)
                setFoldOption(
                    m.options, name,
                    r.integer(*options, name, path + ".options." + name, -32768, 65535, false));
            if (r.err)
                return *r.err;
        }
        plan.modules.push_back(std::move(m));
    }
    return plan;
}

dev::Result<FoldPlan, FoldFileError> loadFoldPlanFile(const std::string &path)
{
    std::error_code ec;
    const auto size = std::filesystem::file_size(std::filesystem::path(path), ec);
    const LocalText ioText{"The fold plan file cannot be read: " + path,
                           "Die Modulplan-Datei kann nicht gelesen werden: " + path};
    if (ec)
        return error(FoldFileErrc::Io, {}, ioText);
    if (size > kFoldPlanMaxBytes)
        return parseFoldPlan(std::string(kFoldPlanMaxBytes + 1, ' ')); // the TooLarge error
    std::ifstream in(std::filesystem::path(path), std::ios::binary);
    if (!in)
        return error(FoldFileErrc::Io, {}, ioText);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        return error(FoldFileErrc::Io, {}, ioText);
    return parseFoldPlan(text);
}

std::optional<FoldFileError> saveFoldPlanFile(const FoldPlan &plan, const std::string &path)
{
    const auto target = std::filesystem::path(path);
    auto temp = target;
    temp += ".tmp";
    const LocalText ioText{"The fold plan file cannot be written: " + path,
                           "Die Modulplan-Datei kann nicht geschrieben werden: " + path};
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out)
            return error(FoldFileErrc::Io, {}, ioText);
        out << writeFoldPlan(plan);
        out.flush();
        if (!out)
            return error(FoldFileErrc::Io, {}, ioText);
    }
    std::error_code ec;
    std::filesystem::rename(temp, target, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        return error(FoldFileErrc::Io, {}, ioText);
    }
    return std::nullopt;
}

} // namespace vt::model
