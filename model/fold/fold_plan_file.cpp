#include "fold_plan_file.h"

#include "core/json_depth.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

namespace vt::model {

using Json = nlohmann::json;

namespace {

constexpr int kMaxDepth = 8; // the format nests 4 deep; anything deeper is not a plan

FoldFileError error(FoldFileErrc code, std::string member = {},
                    FoldFileProblem problem = FoldFileProblem::None)
{
    FoldFileError e;
    e.code = code;
    e.member = std::move(member);
    e.problem = problem;
    return e;
}

FoldFileError bad(const std::string &member, FoldFileProblem problem, long long low = 0,
                  long long high = 0)
{
    FoldFileError e = error(FoldFileErrc::BadMember, member, problem);
    e.low = low;
    e.high = high;
    return e;
}

FoldFileError missing(const std::string &member)
{
    return error(FoldFileErrc::MissingMember, member);
}

FoldFileError io(FoldFileProblem problem, const std::string &path)
{
    FoldFileError e = error(FoldFileErrc::Io, {}, problem);
    e.path = path;
    return e;
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
                err = bad(path, FoldFileProblem::NotWholeNumber);
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
                err = bad(path, FoldFileProblem::OutOfBounds, min, max);
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
                err = bad(path, FoldFileProblem::NotText);
            return {};
        }
        const auto &s = it->get_ref<const std::string &>();
        if (s.size() > kFoldPlanMaxText) {
            if (!err)
                err = bad(path, FoldFileProblem::TooLong, 0,
                          static_cast<long long>(kFoldPlanMaxText));
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
        return error(FoldFileErrc::TooLarge);
    if (dev::jsonTooDeepAt(text, kMaxDepth))
        return error(FoldFileErrc::WrongFormat, {}, FoldFileProblem::TooDeep);
    Json root;
    try {
        root = Json::parse(text.begin(), text.end());
    } catch (const Json::parse_error &e) {
        FoldFileError syntax = error(FoldFileErrc::NotJson);
        syntax.offset = e.byte;
        return syntax;
    } catch (const Json::exception &) { // e.g. out_of_range: a number beyond double ("1E999999")
        return error(FoldFileErrc::NotJson, {}, FoldFileProblem::NumberTooLarge);
    }
    if (!root.is_object())
        return error(FoldFileErrc::WrongFormat);
    const auto format = root.find("format");
    if (format == root.end() || !format->is_string() ||
        format->get_ref<const std::string &>() != kFoldPlanFormat)
        return error(FoldFileErrc::WrongFormat, "format");

    Reader r;
    const auto version =
        r.integer(root, "formatVersion", "formatVersion", 1, std::numeric_limits<int>::max(), true);
    if (r.err)
        return *r.err;
    if (*version > kFoldPlanVersion) {
        FoldFileError newer = error(FoldFileErrc::NewerVersion, "formatVersion");
        newer.high = *version;
        return newer;
    }

    FoldPlan plan;
    const auto node = root.find("node");
    if (node == root.end())
        return missing("node");
    if (!node->is_string() || !foldNodeFromKey(node->get_ref<const std::string &>()))
        return bad("node", FoldFileProblem::UnknownNode);
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
        return bad("modules", FoldFileProblem::NotList);
    if (modules->size() > kFoldPlanMaxModules)
        return bad("modules", FoldFileProblem::TooManyEntries, 0,
                   static_cast<long long>(kFoldPlanMaxModules));
    for (std::size_t i = 0; i < modules->size(); ++i) {
        const Json &jm = (*modules)[i];
        const std::string path = "modules[" + std::to_string(i) + "]";
        if (!jm.is_object())
            return bad(path, FoldFileProblem::NotObject);
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
                return bad(path + ".options", FoldFileProblem::NotObject);
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
    const FoldFileError ioError = io(FoldFileProblem::ReadFailed, path);
    if (ec)
        return ioError;
    if (size > kFoldPlanMaxBytes)
        return parseFoldPlan(std::string(kFoldPlanMaxBytes + 1, ' ')); // the TooLarge error
    std::ifstream in(std::filesystem::path(path), std::ios::binary);
    if (!in)
        return ioError;
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        return ioError;
    return parseFoldPlan(text);
}

std::optional<FoldFileError> saveFoldPlanFile(const FoldPlan &plan, const std::string &path)
{
    const auto target = std::filesystem::path(path);
    auto temp = target;
    temp += ".tmp";
    const FoldFileError ioError = io(FoldFileProblem::WriteFailed, path);
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out)
            return ioError;
        out << writeFoldPlan(plan);
        out.flush();
        if (!out)
            return ioError;
    }
    std::error_code ec;
    std::filesystem::rename(temp, target, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        return ioError;
    }
    return std::nullopt;
}

} // namespace vt::model
