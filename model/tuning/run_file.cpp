#include "run_file.h"

#include "core/json_depth.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace vt::model {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char *kFormat = "valvetune-run";
constexpr int kVersion = 1;
constexpr int kMaxDepth = 8;
constexpr std::size_t kMaxChannels = 64;

std::string number(double v)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

Json specJson(const SignalSpec &s)
{
    return Json{{"kind", key(s.kind)},
                {"from", s.from},
                {"to", s.to},
                {"hold_s", s.hold},
                {"repeats", s.repeats},
                {"direction", key(s.direction)},
                {"amplitude", s.amplitude},
                {"offset", s.offset},
                {"frequency_hz", s.frequencyHz},
                {"cycles", s.cycles},
                {"from_hz", s.fromHz},
                {"to_hz", s.toHz},
                {"points_per_decade", s.pointsPerDecade},
                {"settling_cycles", s.settlingCycles}};
}

struct Reader
{
    const Json &j;
    std::string error;

    const Json *field(const char *name, bool (Json::*is)() const noexcept)
    {
        if (!error.empty())
            return nullptr;
        if (!j.contains(name) || !(j[name].*is)()) {
            error = std::string("\"") + name + "\" is missing or of the wrong type";
            return nullptr;
        }
        return &j[name];
    }
    std::string text(const char *name)
    {
        const Json *v = field(name, &Json::is_string);
        return v ? v->get<std::string>() : std::string();
    }
    double real(const char *name)
    {
        const Json *v = field(name, &Json::is_number);
        const double d = v ? v->get<double>() : 0;
        if (v && !std::isfinite(d))
            error = std::string("\"") + name + "\" is not a finite number";
        return d;
    }
    int whole(const char *name, int min, int max)
    {
        const Json *v = field(name, &Json::is_number_integer);
        if (!v)
            return 0;
        const auto i = v->get<std::int64_t>();
        if (i < min || i > max) {
            error = std::string("\"") + name + "\" is out of range";
            return 0;
        }
        return static_cast<int>(i);
    }
    bool flag(const char *name)
    {
        const Json *v = field(name, &Json::is_boolean);
        return v && v->get<bool>();
    }
};

std::string readSpec(const Json &j, SignalSpec &s)
{
    Reader r{j, {}};
    const auto kind = dev::fromKey<SignalKind>(r.text("kind"));
    const auto direction = dev::fromKey<StepDirection>(r.text("direction"));
    s.from = r.real("from");
    s.to = r.real("to");
    s.hold = r.real("hold_s");
    s.repeats = r.whole("repeats", 0, 1'000'000);
    s.amplitude = r.real("amplitude");
    s.offset = r.real("offset");
    s.frequencyHz = r.real("frequency_hz");
    s.cycles = r.whole("cycles", 0, 1'000'000);
    s.fromHz = r.real("from_hz");
    s.toHz = r.real("to_hz");
    s.pointsPerDecade = r.whole("points_per_decade", 0, 1000);
    s.settlingCycles = r.whole("settling_cycles", 0, 1'000'000);
    if (!r.error.empty())
        return "signal: " + r.error;
    if (!kind || !direction)
        return "signal: unknown kind or direction";
    s.kind = *kind;
    s.direction = *direction;
    return {};
}

std::string readSamples(const Json &j, Samples &out)
{
    if (!j.is_object() || !j.contains("t") || !j.contains("y") || !j["t"].is_array() ||
        !j["y"].is_array() || j["t"].size() != j["y"].size())
        return "\"set_value_samples\" needs the lists \"t\" and \"y\" of one length";
    for (std::size_t i = 0; i < j["t"].size(); ++i) {
        const Json &t = j["t"][i];
        const Json &y = j["y"][i];
        if (!t.is_number() || !y.is_number())
            return "\"set_value_samples\" holds something that is not a number";
        out.t.push_back(t.get<double>());
        out.y.push_back(y.get<double>());
        if (!std::isfinite(out.t.back()) || !std::isfinite(out.y.back()) ||
            (i > 0 && out.t[i] < out.t[i - 1]))
            return "\"set_value_samples\" times must be finite and ascending";
    }
    return {};
}

std::vector<std::string_view> split(std::string_view line)
{
    std::vector<std::string_view> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        out.push_back(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
        if (comma == std::string_view::npos || out.size() > kMaxChannels + 2)
            return out;
        start = comma + 1;
    }
}

bool parseDouble(std::string_view text, double &v)
{
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    return ec == std::errc() && end == text.data() + text.size() && std::isfinite(v);
}

// The CSV's channel columns (after time and the set value) into `run.channels`.
std::string readCsv(std::string_view csv, RunFileData &run)
{
    std::size_t pos = 0;
    std::size_t lineNo = 0;
    std::size_t columns = 0;
    while (pos < csv.size()) {
        std::size_t end = csv.find('\n', pos);
        if (end == std::string_view::npos)
            end = csv.size();
        std::string_view line = csv.substr(pos, end - pos);
        pos = end + 1;
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        ++lineNo;
        if (line.empty())
            continue;
        const auto cells = split(line);
        if (lineNo == 1) {
            columns = cells.size();
            if (columns != run.channelNames.size() + 2 || cells[0] != "time_s")
                return "the CSV's header does not match the channels of the JSON";
            continue;
        }
        if (cells.size() != columns)
            return "CSV line " + std::to_string(lineNo) + " has " + std::to_string(cells.size()) +
                   " cells, not " + std::to_string(columns);
        double t = 0;
        if (!parseDouble(cells[0], t))
            return "CSV line " + std::to_string(lineNo) + ": the time is not a number";
        for (std::size_t c = 0; c < run.channels.size(); ++c) {
            double y = 0;
            if (!parseDouble(cells[c + 2], y))
                return "CSV line " + std::to_string(lineNo) + ": a value is not a number";
            Samples &s = run.channels[c];
            if (!s.t.empty() && t < s.t.back())
                return "CSV line " + std::to_string(lineNo) + ": the time goes back";
            s.t.push_back(t);
            s.y.push_back(y);
        }
    }
    if (columns == 0)
        return "the CSV is empty";
    return {};
}

} // namespace

std::string runJson(const RunFileData &run)
{
    Json settings = Json::object();
    for (const RunSetting &s : run.settings)
        settings[s.name] = s.raw;
    const Json j{
        {"format", kFormat},
        {"format_version", kVersion},
        {"number", run.number},
        {"started", run.started},
        {"module", run.module},
        {"family", run.family},
        {"mode", run.mode},
        {"set_value", run.setValue},
        {"response", run.response},
        {"signal", specJson(run.spec)},
        {"end", run.end},
        {"restored", run.restored},
        {"writes", run.writes},
        {"cycles", run.cycles},
        {"channels", run.channelNames},
        {"set_value_samples", {{"t", run.setValueSamples.t}, {"y", run.setValueSamples.y}}},
        {"settings", settings}};
    return j.dump(1) + "\n";
}

std::string runCsv(const RunFileData &run)
{
    std::string out = "time_s," + run.setValue + " written";
    for (const std::string &name : run.channelNames)
        out += "," + name;
    out += "\n";
    const std::size_t n = run.channels.empty() ? 0 : run.channels.front().t.size();
    std::size_t k = 0;
    const Samples &set = run.setValueSamples;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = run.channels.front().t[i];
        while (k + 1 < set.t.size() && set.t[k + 1] <= t)
            ++k;
        char time[32];
        std::snprintf(time, sizeof time, "%.6f", t);
        out += time;
        out += ",";
        out += set.y.empty() ? std::string("0") : number(set.y[k]);
        for (const Samples &c : run.channels)
            out += "," + (i < c.y.size() ? number(c.y[i]) : std::string("0"));
        out += "\n";
    }
    return out;
}

dev::Result<RunFileData, std::string> parseRunFiles(std::string_view json, std::string_view csv)
{
    if (json.size() > kMaxRunFileBytes || csv.size() > kMaxRunFileBytes)
        return std::string("the file is larger than 256 MiB");
    if (dev::jsonTooDeepAt(json, kMaxDepth))
        return std::string("the JSON is nested too deeply");
    Json j = Json::parse(json.begin(), json.end(), nullptr, false);
    if (j.is_discarded() || !j.is_object())
        return std::string("not a valid JSON text (the file is damaged or truncated)");
    if (!j.contains("format") || j["format"] != kFormat)
        return std::string("not a ValveTune run file");
    RunFileData run;
    Reader r{j, {}};
    if (r.whole("format_version", 1, 1'000'000) > kVersion)
        return std::string("written by a newer ValveTune (format version ") +
               std::to_string(j["format_version"].get<std::int64_t>()) + ")";
    run.number = r.whole("number", 0, 1'000'000);
    run.started = r.text("started");
    run.module = r.whole("module", 0, 255);
    run.family = r.text("family");
    run.mode = r.text("mode");
    run.setValue = r.text("set_value");
    run.response = r.text("response");
    run.end = r.text("end");
    run.restored = r.flag("restored");
    run.writes = r.whole("writes", 0, 1'000'000'000);
    run.cycles = r.whole("cycles", 0, 1'000'000'000);
    const Json *signal = r.field("signal", &Json::is_object);
    const Json *channels = r.field("channels", &Json::is_array);
    const Json *samples = r.field("set_value_samples", &Json::is_object);
    const Json *settings = r.field("settings", &Json::is_object);
    if (!r.error.empty())
        return r.error;
    if (std::string e = readSpec(*signal, run.spec); !e.empty())
        return e;
    if (channels->size() > kMaxChannels)
        return std::string("more than 64 channels");
    // Names go into the CSV's header: no separators in them.
    const auto plainName = [](const std::string &name) {
        return !name.empty() && name.find_first_of(",\r\n") == std::string::npos;
    };
    if (!plainName(run.setValue))
        return std::string("\"set_value\" is not a row name");
    for (const Json &c : *channels) {
        if (!c.is_string() || !plainName(c.get<std::string>()))
            return std::string("\"channels\" must be a list of row names");
        run.channelNames.push_back(c.get<std::string>());
    }
    run.channels.resize(run.channelNames.size());
    if (std::string e = readSamples(*samples, run.setValueSamples); !e.empty())
        return e;
    for (const auto &[name, value] : settings->items()) {
        if (!value.is_number() || !std::isfinite(value.get<double>()))
            return "setting " + name + " is not a number";
        run.settings.push_back({name, value.get<double>()});
    }
    if (std::string e = readCsv(csv, run); !e.empty())
        return e;
    return run;
}

} // namespace vt::model
