#include "monitor_defaults_load.h"

#include <algorithm>
#include <optional>
#include <set>

namespace vt::dev {
namespace {

using Json = nlohmann::json;

class MonitorLoader
{
public:
    explicit MonitorLoader(const Dictionary &dict) : m_dict(dict) {}

    MonitorPlan plan;

    std::vector<DictionaryError> run(const Json &monitor)
    {
        if (!monitor.is_object()) {
            fail("\"monitor\" must be an object");
            return m_errors;
        }
        plan.all = entry(monitor, {}, true);
        if (monitor.contains("modes")) {
            const Json &modes = monitor["modes"];
            if (!modes.is_object()) {
                fail("\"monitor\".\"modes\" must be an object");
                return m_errors;
            }
            for (const auto &[mode, over] : modes.items()) {
                if (std::find(m_dict.modes.begin(), m_dict.modes.end(), mode) ==
                    m_dict.modes.end()) {
                    fail("\"monitor\" names mode '" + mode + "', which the family does not have");
                    continue;
                }
                if (!over.is_object()) {
                    fail("\"monitor\" mode '" + mode + "' must be an object");
                    continue;
                }
                // A mode entry replaces the keys it gives and keeps the others.
                Json merged = monitor;
                merged.erase("modes");
                merged.update(over);
                plan.byMode[mode] = entry(merged, mode, false);
            }
        }
        return m_errors;
    }

private:
    void fail(std::string message) { m_errors.push_back({{}, {}, std::move(message)}); }

    // The row `name` if it exists and applies to `mode` ("" = the family's rows of any mode).
    const ParamMeta *row(const std::string &name, const std::string &mode, const char *what)
    {
        const ParamMeta *p = m_dict.find(name);
        if (!p) {
            fail(std::string("\"monitor\" ") + what + " names unknown row '" + name + "'");
            return nullptr;
        }
        if (!mode.empty() && !p->modes.empty() &&
            std::find(p->modes.begin(), p->modes.end(), mode) == p->modes.end()) {
            fail(std::string("\"monitor\" ") + what + " '" + name + "' does not exist in mode " +
                 mode);
            return nullptr;
        }
        return p;
    }

    std::vector<std::string> names(const Json &j, const char *key)
    {
        std::vector<std::string> out;
        if (!j.contains(key))
            return out;
        if (!j[key].is_array()) {
            fail(std::string("\"monitor\".\"") + key + "\" must be a list of row names");
            return out;
        }
        std::set<std::string> seen;
        for (const Json &n : j[key]) {
            if (!n.is_string()) {
                fail(std::string("\"monitor\".\"") + key + "\" must be a list of row names");
                continue;
            }
            if (!seen.insert(n.get<std::string>()).second)
                fail(std::string("\"monitor\".\"") + key + "\" names '" + n.get<std::string>() +
                     "' twice");
            out.push_back(n.get<std::string>());
        }
        return out;
    }

    static LocalText text(const Json &j)
    {
        if (!j.is_object())
            return {};
        return {j.value("en", std::string()), j.value("de", std::string())};
    }

    std::optional<SetValueActivation> activation(const Json &a, const std::string &mode)
    {
        if (a.is_object() && a.contains("state"))
            return stateActivation(a, mode);
        if (!a.is_object() || !a.contains("value") || !a["value"].is_number() ||
            !a.contains("row") || !a["row"].is_string()) {
            fail("\"monitor\".\"activation\" entries need \"row\", a numeric \"value\" and "
                 "\"reason\", or a \"state\" and \"reason\"");
            return std::nullopt;
        }
        SetValueActivation act;
        act.row = a["row"].get<std::string>();
        act.value = a["value"].get<double>();
        if (!reason(a, act))
            return std::nullopt;
        const ParamMeta *p = row(act.row, mode, "activation");
        if (!p)
            return std::nullopt;
        if (!p->readable() || !p->writable() || !p->movesActuator)
            fail("\"monitor\" activation '" + act.row +
                 "' must be readable, writable and marked moves_actuator");
        if (act.value < p->min || act.value > p->max)
            fail("\"monitor\" activation value is outside the range of '" + act.row + "'");
        return act;
    }

    bool reason(const Json &a, SetValueActivation &act)
    {
        act.reason = text(a.value("reason", Json()));
        if (act.reason.complete())
            return true;
        fail("\"monitor\".\"activation\" '" + (act.row.empty() ? act.written() : act.row) +
             "' needs a \"reason\" in English and German");
        return false;
    }

    // {"state": "DEVICE_MODE_ACTIVE", "reason": …}: the DSP-408 state machine (ED1/SD1 manual
    // and HART-7 manual §4.2.2), read from db_StatusWord, commanded through db_ControlWord.
    std::optional<SetValueActivation> stateActivation(const Json &a, const std::string &mode)
    {
        static const std::set<std::string> kKeys = {"state", "reason"};
        for (const auto &[key, value] : a.items())
            if (!kKeys.count(key))
                fail("\"monitor\" state activation has an unknown key '" + key + "'");
        const auto state = a["state"].is_string()
                               ? dsp408::stateFromName(a["state"].get<std::string>())
                               : std::nullopt;
        const auto word = state ? dsp408::controlWordFor(*state) : std::nullopt;
        if (!word) {
            fail("\"monitor\" activation \"state\" must name a state a control word commands "
                 "(INIT, DISABLED, HOLD, DEVICE_MODE_ACTIVE)");
            return std::nullopt;
        }
        SetValueActivation act;
        act.state = state;
        act.row = "db_StatusWord";
        act.writeRow = "db_ControlWord";
        act.value = *word;
        if (!reason(a, act))
            return std::nullopt;
        const ParamMeta *status = row(act.row, mode, "state activation");
        const ParamMeta *control = row(act.writeRow, mode, "state activation");
        if (!status || !control)
            return std::nullopt;
        if (!status->readable() || !control->writable() || !control->movesActuator)
            fail("\"monitor\" state activation needs a readable db_StatusWord and a writable "
                 "db_ControlWord marked moves_actuator");
        return act;
    }

    MonitorDefaults entry(const Json &j, const std::string &mode, bool top)
    {
        static const std::set<std::string> kKeys = {"channels",  "set_values", "activation",
                                                    "responses", "fault",      "no_set_value",
                                                    "note",      "modes"};
        for (const auto &[key, value] : j.items())
            if (!kKeys.count(key) || (!top && key == "modes"))
                fail("\"monitor\" has an unknown key '" + key + "'");

        MonitorDefaults out;
        for (const std::string &name : names(j, "channels")) {
            const ParamMeta *p = row(name, mode, "channel");
            if (!p)
                continue;
            if (!p->readable() || p->isString())
                fail("\"monitor\" channel '" + name + "' is not a readable number");
            out.channels.push_back(name);
        }
        for (const std::string &name : names(j, "set_values")) {
            const ParamMeta *p = row(name, mode, "set value");
            if (!p)
                continue;
            // The step reads the value before it writes (the journal's old value) and passes the
            // valve-moving gate.
            if (!p->readable() || !p->writable() || p->isString() || !p->movesActuator)
                fail("\"monitor\" set value '" + name +
                     "' must be a readable, writable number marked moves_actuator");
            out.setValues.push_back(name);
        }
        if (j.contains("activation")) {
            if (!j["activation"].is_array())
                fail("\"monitor\".\"activation\" must be a list of {row, value, reason}");
            else
                for (const Json &a : j["activation"])
                    if (auto act = activation(a, mode))
                        out.activation.push_back(std::move(*act));
        }
        if (j.contains("responses")) {
            if (!j["responses"].is_object())
                fail("\"monitor\".\"responses\" must map set values to the rows that answer them");
            else
                for (const auto &[set, answer] : j["responses"].items()) {
                    if (std::find(out.setValues.begin(), out.setValues.end(), set) ==
                        out.setValues.end()) {
                        fail("\"monitor\".\"responses\" names '" + set +
                             "', which is not one of the set values");
                        continue;
                    }
                    const ParamMeta *p = answer.is_string()
                                             ? row(answer.get<std::string>(), mode, "response")
                                             : nullptr;
                    if (!p || !p->readable() || p->isString()) {
                        fail("\"monitor\" response of '" + set + "' must be a readable number");
                        continue;
                    }
                    out.responses[set] = p->name;
                }
        }
        if (j.contains("fault")) {
            const Json &f = j["fault"];
            const auto whole = [&](const char *key) {
                return f.contains(key) && f[key].is_number_unsigned() &&
                       f[key].get<std::uint64_t>() <= 0xFFFF'FFFFu;
            };
            const ParamMeta *p = f.is_object() && f.contains("row") && f["row"].is_string() &&
                                         whole("ok") && (!f.contains("mask") || whole("mask"))
                                     ? row(f["row"].get<std::string>(), mode, "fault")
                                     : nullptr;
            if (!p || !p->readable() || p->isString())
                fail("\"monitor\".\"fault\" needs a readable numeric \"row\", its \"ok\" "
                     "value and optionally a \"mask\" (whole numbers)");
            else
                out.fault =
                    FaultRow{p->name, static_cast<std::uint32_t>(f.value("mask", 0xFFFF'FFFFu)),
                             static_cast<std::uint32_t>(f["ok"].get<std::uint64_t>())};
        }
        out.noSetValue = text(j.value("no_set_value", Json()));
        if (out.setValues.empty() && !out.noSetValue.complete())
            fail("\"monitor\" without \"set_values\" needs \"no_set_value\" (why there is no "
                 "step) in English and German" +
                 (mode.empty() ? std::string() : " for mode " + mode));
        if (!out.setValues.empty() && j.contains("no_set_value"))
            fail("\"monitor\" has both \"set_values\" and \"no_set_value\"" +
                 (mode.empty() ? std::string() : std::string(" for mode ") + mode));
        return out;
    }

    const Dictionary &m_dict;
    std::vector<DictionaryError> m_errors;
};

} // namespace

MonitorPlan loadMonitorDefaults(const Json &monitor, const Dictionary &dict,
                                std::vector<DictionaryError> &errors)
{
    MonitorLoader loader(dict);
    for (DictionaryError &e : loader.run(monitor))
        errors.push_back(std::move(e));
    return std::move(loader.plan);
}

} // namespace vt::dev
