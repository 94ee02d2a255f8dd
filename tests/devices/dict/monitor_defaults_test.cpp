// The "monitor" key of the dictionaries (docs/DICTIONARY.md "Monitor defaults"): the built-in
// families name the channels and set values their manuals give, per mode where they differ, and a
// name that is not a fitting row of the family is a load error.
#include "dict/dictionary_loader.h"

#include <gtest/gtest.h>

using namespace vt::dev;

namespace {

// A family with a live value d1.01, a setting C1.01, a valve-moving set value A1.01, the
// activation row E17 and a text row T; `monitor` is the value of the "monitor" key.
std::string family(const std::string &monitor)
{
    return R"({"schema":1,"family":"f","title":{"en":"T","de":"T"},"vendor":"HCS","protocol":"hcs",)"
           R"("versions":["1"],"modes":["1","2"],"monitor":)" +
           monitor +
           R"(,"parameters":[)"
           R"({"name":"d1.01","id":1,"block":"d","access":"r","row_kind":"live","type":"int16","label":{"en":"L","de":"L"}},)"
           R"({"name":"C1.01","id":2,"block":"C","access":"rw","type":"int16","label":{"en":"L","de":"L"}},)"
           R"({"name":"A1.01","id":3,"block":"A","access":"rw","row_kind":"process","moves_actuator":true,"type":"int16","label":{"en":"L","de":"L"}},)"
           R"({"name":"E17","id":4,"block":"E","access":"rw","moves_actuator":true,"type":"uint8","min":0,"max":2,"label":{"en":"L","de":"L"}},)"
           R"({"name":"d2.01","id":5,"block":"d","access":"r","row_kind":"live","modes":["2"],"type":"int16","label":{"en":"L","de":"L"}},)"
           R"({"name":"T","id":6,"block":"E","access":"rw","type":"string","length":4,"label":{"en":"L","de":"L"}}]})";
}

const char kActivation[] =
    R"("activation":[{"row":"E17","value":2,"reason":{"en":"manual","de":"Handbuch"}}])";

std::vector<std::string> errors(const std::string &monitor)
{
    std::vector<std::string> out;
    auto r = loadDictionaries({{"f.json", family(monitor)}});
    if (!r.ok())
        for (const auto &e : r.error())
            out.push_back(e.text());
    return out;
}

bool mentions(const std::vector<std::string> &errors, const std::string &part)
{
    for (const std::string &e : errors)
        if (e.find(part) != std::string::npos)
            return true;
    return false;
}

std::vector<std::string> channels(const char *family, const std::string &mode)
{
    return builtinDictionaries()->find(family)->monitor.forMode(mode).channels;
}

} // namespace

TEST(MonitorDefaults, AValidPlanLoadsWithItsModeOverride)
{
    auto r = loadDictionaries(
        {{"f.json", family(std::string(R"({"channels":["d1.01"],)") + R"("set_values":["A1.01"],)" +
                           kActivation + R"(,"modes":{"2":{"channels":["d2.01"]}}})")}});
    ASSERT_TRUE(r.ok()) << r.error().front().text();
    const MonitorPlan &plan = r->find("f")->monitor;
    EXPECT_EQ(plan.forMode("1").channels, std::vector<std::string>{"d1.01"});
    EXPECT_EQ(plan.forMode("2").channels, std::vector<std::string>{"d2.01"});
    EXPECT_EQ(plan.forMode("2").setValues, std::vector<std::string>{"A1.01"}); // kept
    ASSERT_EQ(plan.forMode("2").activation.size(), 1u);
    EXPECT_EQ(plan.forMode("2").activation.front().row, "E17");
    EXPECT_EQ(plan.forMode("2").activation.front().value, 2);
}

TEST(MonitorDefaults, NamesThatAreNotFittingRowsAreLoadErrors)
{
    EXPECT_TRUE(mentions(errors(R"({"channels":["d9.99"],"no_set_value":{"en":"x","de":"x"}})"),
                         "f.json: \"monitor\" channel names unknown row 'd9.99'"));
    EXPECT_TRUE(mentions(errors(R"({"channels":["T"],"no_set_value":{"en":"x","de":"x"}})"),
                         "channel 'T' is not a readable number"));
    EXPECT_TRUE(mentions(
        errors(std::string(R"({"channels":["d1.01"],"set_values":["C1.01"],)") + kActivation + "}"),
        "set value 'C1.01' must be a readable, writable number marked "
        "moves_actuator"));
    EXPECT_TRUE(mentions(
        errors(std::string(R"({"channels":["d1.01"],"set_values":["Z"],)") + kActivation + "}"),
        "set value names unknown row 'Z'"));
    EXPECT_TRUE(mentions(
        errors(R"({"channels":["d1.01"],"set_values":["A1.01"],"activation":[{"row":"E17",)"
               R"("value":7,"reason":{"en":"m","de":"H"}}]})"),
        "activation value is outside the range of 'E17'"));
    EXPECT_TRUE(mentions(errors(R"({"channels":["d1.01"]})"), "needs \"no_set_value\""));
    EXPECT_TRUE(mentions(
        errors(R"({"channels":["d1.01"],"no_set_value":{"en":"x","de":"x"},"chanels":[]})"),
        "unknown key 'chanels'"));
    EXPECT_TRUE(mentions(errors(R"({"channels":["d1.01"],"no_set_value":{"en":"x","de":"x"},)"
                                R"("modes":{"9":{"channels":["d1.01"]}}})"),
                         "names mode '9', which the family does not have"));
    EXPECT_TRUE(mentions(errors(R"({"channels":["d1.01"],"no_set_value":{"en":"x","de":"x"},)"
                                R"("modes":{"1":{"channels":["d2.01"]}}})"),
                         "channel 'd2.01' does not exist in mode 1"));
    EXPECT_TRUE(mentions(errors(R"({"channels":["d1.01","d1.01"],)"
                                R"("no_set_value":{"en":"x","de":"x"}})"),
                         "names 'd1.01' twice"));
}

// Closed loop: desired, actual value and the solenoid currents; open loop (V13, V15 mode 1, V22
// mode 2): the set value after the ramps and the currents, since d1.10 / d1.11 stay 0 there.
TEST(MonitorDefaults, EachBuiltinFamilyNamesItsManualsChannels)
{
    const std::vector<std::string> closed = {"d1.10", "d1.11", "d1.07", "d1.08", "d1.09"};
    EXPECT_EQ(channels("dma-pn-v51", "3"), closed);
    EXPECT_EQ(channels("dma-pb-v32", "4"), closed);
    EXPECT_EQ(channels("opat", "3"), closed);
    const std::vector<std::string> oneValve = {"d1.02", "d1.07", "d1.08", "d1.09"};
    EXPECT_EQ(channels("dma-pn-v13", "1"), oneValve);
    EXPECT_EQ(channels("dma-pb-v15", "1"), oneValve);
    EXPECT_EQ(channels("dma-pb-v22", "2"),
              (std::vector<std::string>{"d1.02", "d2.02", "d1.07", "d1.08"}));
    EXPECT_EQ(
        channels("wandfluh-sd7", ""),
        (std::vector<std::string>{"hart_TvValue", "hart_PvValue", "hart_SvValue", "hart_QvValue"}));
    EXPECT_EQ(
        channels("wandfluh-ed1", "6"),
        (std::vector<std::string>{"dpc_SetpointVal", "dpc_ActualVal", "dpc_CtrlDeviationVal"}));
    for (const std::string &name : builtinDictionaries()->families()) {
        const Dictionary &d = *builtinDictionaries()->find(name);
        EXPECT_FALSE(d.monitor.all.channels.empty()) << name;
        const auto &sd7 = d.monitor.forMode("");
        if (name == "wandfluh-sd7" || name == "wandfluh-ed1") {
            ASSERT_EQ(sd7.activation.size(), 3u) << name;
            EXPECT_EQ(sd7.activation[0].row, "db_Local");      // §4.2.1 bus mode "Remote"
            EXPECT_EQ(sd7.activation[1].row, "db_DeviceMode"); // "1: Command value from fieldbus"
            EXPECT_EQ(sd7.activation[1].value, 1);
            // §4.2.2: only DEVICE_MODE_ACTIVE enables the device functions; D, H, M lead there.
            const SetValueActivation &state = sd7.activation[2];
            EXPECT_EQ(state.state, dsp408::State::DeviceModeActive) << name;
            EXPECT_EQ(state.row, "db_StatusWord");
            EXPECT_EQ(state.written(), "db_ControlWord");
            EXPECT_EQ(state.value, dsp408::kControlActive);
            EXPECT_TRUE(state.holds(0x000F));  // R M H D
            EXPECT_TRUE(state.holds(0x001F));  // and "local control": bits 4.. do not matter
            EXPECT_FALSE(state.holds(0x0008)); // INIT
            EXPECT_FALSE(state.holds(0x000B)); // HOLD
        }
    }
}

// A state rule names a state a control word commands, in a family with the DSP-408 words.
TEST(MonitorDefaults, AStateRuleNeedsACommandableStateAndTheStatusAndControlWords)
{
    const auto rule = [](const char *state) {
        return std::string(R"({"channels":["d1.01"],"set_values":["A1.01"],"activation":[)"
                           R"({"state":")") +
               state + R"(","reason":{"en":"m","de":"H"}}]})";
    };
    EXPECT_TRUE(mentions(errors(rule("FAULT")), "must name a state a control word commands"));
    EXPECT_TRUE(mentions(errors(rule("ACTIVE")), "must name a state a control word commands"));
    // This HCS-like family has neither db_StatusWord nor db_ControlWord.
    EXPECT_TRUE(mentions(errors(rule("DEVICE_MODE_ACTIVE")), "unknown row 'db_StatusWord'"));
}
