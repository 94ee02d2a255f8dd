#include "model/audit/audit_record.h"

#include <nlohmann/json.hpp>

namespace vt::model {

namespace {

using Json = nlohmann::ordered_json;

constexpr int kFormat = 1; // the log's layout; a reader skips lines of a layout it does not know

Json valueJson(const AuditValue &value)
{
    if (value.text.empty() && value.raw.empty())
        return nullptr;
    return Json{{"text", value.text}, {"raw", value.raw}};
}

std::string line(const Json &json)
{
    // Invalid UTF-8 (a device's text) is replaced, never thrown about.
    return json.dump(-1, ' ', false, Json::error_handler_t::replace) + '\n';
}

// The member `key` as a string; empty when missing or of another type.
std::string text(const Json &object, const char *key)
{
    const auto it = object.find(key);
    return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}

AuditValue value(const Json &object, const char *key)
{
    const auto it = object.find(key);
    if (it == object.end() || !it->is_object())
        return {};
    return {text(*it, "text"), text(*it, "raw")};
}

bool readHeader(const Json &json, AuditHeaderRecord *header)
{
    if (!json.is_object() || text(json, "type") != "session")
        return false;
    header->program = text(json, "program");
    header->version = text(json, "version");
    const auto pid = json.find("pid");
    header->pid = pid != json.end() && pid->is_number_integer() ? pid->get<long long>() : 0;
    header->started = text(json, "started");
    header->connection = text(json, "connection");
    return true;
}

bool readWrite(const Json &json, AuditWriteRecord *write)
{
    const auto module = json.find("module");
    if (module == json.end() || !module->is_number_integer())
        return false;
    const long long address = module->get<long long>();
    if (address < 0 || address > 0xFFFF)
        return false;
    write->time = text(json, "time");
    write->module = static_cast<int>(address);
    write->row = text(json, "row");
    write->name = text(json, "name");
    write->unit = text(json, "unit");
    write->oldValue = value(json, "old");
    write->newValue = value(json, "new");
    write->status = text(json, "status");
    write->readBack = value(json, "readBack");
    const auto reason = json.find("reason");
    if (reason != json.end() && reason->is_object()) {
        write->reasonEn = text(*reason, "en");
        write->reasonDe = text(*reason, "de");
    }
    write->origin = text(json, "origin");
    return !write->status.empty();
}

} // namespace

std::string formatAuditLine(const AuditHeaderRecord &header)
{
    return line(Json{{"type", "session"},
                     {"format", kFormat},
                     {"program", header.program},
                     {"version", header.version},
                     {"pid", header.pid},
                     {"started", header.started},
                     {"connection", header.connection}});
}

std::string formatAuditLine(const AuditConnectionRecord &connection)
{
    return line(Json{
        {"type", "connection"}, {"time", connection.time}, {"connection", connection.connection}});
}

std::string formatAuditLine(const AuditWriteRecord &write)
{
    return line(Json{{"type", "write"},
                     {"time", write.time},
                     {"module", write.module},
                     {"row", write.row},
                     {"name", write.name},
                     {"unit", write.unit},
                     {"old", valueJson(write.oldValue)},
                     {"new", valueJson(write.newValue)},
                     {"status", write.status},
                     {"readBack", valueJson(write.readBack)},
                     {"reason", Json{{"en", write.reasonEn}, {"de", write.reasonDe}}},
                     {"origin", write.origin}});
}

AuditParse parseAuditLog(std::string_view log, const AuditLimits &limits)
{
    AuditParse result;
    if (log.size() > limits.maxBytes) {
        result.error =
            "the session log is larger than " + std::to_string(limits.maxBytes) + " bytes";
        return result;
    }
    bool first = true;
    std::size_t at = 0;
    while (at < log.size()) {
        const std::size_t end = log.find('\n', at);
        if (end == std::string_view::npos) {
            // Every line is written whole with its newline: one without was cut by a kill.
            result.truncatedTail = true;
            break;
        }
        const std::string_view content = log.substr(at, end - at);
        at = end + 1;
        if (content.empty())
            continue;
        const Json json = content.size() <= limits.maxLine ? Json::parse(content, nullptr, false)
                                                           : Json(Json::value_t::discarded);
        if (first) {
            first = false;
            if (json.is_discarded() || !readHeader(json, &result.header)) {
                result.error = "the first line is not a session header";
                return result;
            }
            continue;
        }
        const std::string type = json.is_object() ? text(json, "type") : std::string();
        AuditWriteRecord write;
        if (type == "write" && readWrite(json, &write))
            result.writes.push_back(std::move(write));
        else if (type == "connection")
            result.connections.push_back({text(json, "time"), text(json, "connection")});
        else
            ++result.skipped;
    }
    if (first) {
        result.error = "the session log has no complete line";
        return result;
    }
    result.ok = true;
    return result;
}

} // namespace vt::model
