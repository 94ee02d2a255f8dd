// Row kinds (setting / process / live) and valve-moving rows: the rule of each family, read from
// its manual (docs/DICTIONARY.md "Row kinds"), and the validation that keeps a row's kind
// consistent with its access, persistence and PZD number.
#include "dict/dictionary_loader.h"

#include <gtest/gtest.h>

using namespace vt::dev;

namespace {

const Dictionary &family(const std::string &id)
{
    static const Dictionary empty;
    const auto &set = builtinDictionaries();
    if (!set.ok()) {
        ADD_FAILURE() << set.error().front().text();
        return empty;
    }
    const Dictionary *d = set->find(id);
    if (!d) {
        ADD_FAILURE() << "no family " << id;
        return empty;
    }
    return *d;
}

struct Expected
{
    const char *name;
    RowKind kind;
    bool moves;
};

void expectRows(const std::string &id, const std::vector<Expected> &rows)
{
    const Dictionary &d = family(id);
    for (const Expected &e : rows) {
        const ParamMeta *p = d.find(e.name);
        ASSERT_NE(p, nullptr) << id << " has no " << e.name;
        EXPECT_EQ(key(p->kind), std::string(key(e.kind))) << id << " " << e.name;
        EXPECT_EQ(p->movesActuator, e.moves) << id << " " << e.name;
    }
}

std::string hcsFile(const std::string &extraHeader, const std::string &rows)
{
    return R"({"schema":1,"family":"k","title":{"en":"T","de":"T"},"vendor":"HCS",)"
           R"("protocol":"hcs","versions":["1"],"modes":["1"],)" +
           extraHeader + R"("parameters":[)" + rows + "]}";
}

std::string hcsRow(const std::string &name, int id, const std::string &block,
                   const std::string &access, const std::string &extra = {})
{
    return R"({"name":")" + name + R"(","id":)" + std::to_string(id) + R"(,"block":")" + block +
           R"(","access":")" + access +
           R"(","type":"int16","min":0,"max":100,"label":{"en":"L","de":"L"})" + extra + "}";
}

std::vector<std::string> errors(const std::string &text)
{
    std::vector<std::string> out;
    auto r = loadDictionaries({{"k.json", text}});
    if (!r.ok())
        for (const auto &e : r.error())
            out.push_back(e.text());
    return out;
}

} // namespace

TEST(RowKind, KeysRoundTrip)
{
    for (RowKind k : kRowKinds)
        EXPECT_EQ(fromKey<RowKind>(key(k)), k);
    EXPECT_STREQ(key(RowKind::Setting), "setting");
    EXPECT_STREQ(key(RowKind::Process), "process");
    EXPECT_STREQ(key(RowKind::Live), "live");
    EXPECT_EQ(fromKey<RowKind>("Process"), std::nullopt);
    EXPECT_EQ(ParamMeta{}.kind, RowKind::Setting);
    EXPECT_FALSE(ParamMeta{}.movesActuator);
}

// OPAT manual §7: "R = read only parameter"; A1.01 "This value is, when written, always active.
// … For switching off of the analogue set-value, set E17 = 2"; A1.02 "C1.09 has to be switched
// off" (the bus feedback closes the loop); B1.01 the same for the ProfiDrive set value; 0xB0
// "Enable active", "Bus Disable Card (Read/Write)"; EClr "After writing, this parameter is set
// again to 0".
TEST(RowKind, OpatFollowsItsManual)
{
    expectRows("opat", {
                           {"d1.11", RowKind::Live, false},
                           {"d2.13", RowKind::Live, false},
                           {"ERR", RowKind::Live, false},
                           {"E27", RowKind::Live, false},
                           {"A1.01", RowKind::Process, true},
                           {"A1.02", RowKind::Process, true},
                           {"A2.01", RowKind::Process, true},
                           {"B1.01", RowKind::Process, true},
                           {"B2.01", RowKind::Process, true},
                           {"0xB0", RowKind::Process, true},
                           {"EClr", RowKind::Process, true},
                           {"E17", RowKind::Setting, true},
                           {"C1.07", RowKind::Setting, false},
                           {"r1.01", RowKind::Setting, false},
                           {"Vers", RowKind::Setting, false},
                           {"E00", RowKind::Setting, false},
                           // "Reserved" in the OPAT list: not writable, so never valve-moving.
                           {"S1.01", RowKind::Setting, false},
                       });
}

// DMA Profinet manual §4.5.3: "Process Value1 = A1.01, set value input", "Process Value2 =
// A1.02, feedback value input"; §6: E17 "0 = 4 digital, 1 analogue active, 2 = only 4 digital
// active" (S1.01..S1.04 drive the valve when their input is on); So.in "Indicator for activated
// digital set values".
TEST(RowKind, DmaProfinetFollowsItsManual)
{
    for (const char *id : {"dma-pn-v13", "dma-pn-v51"})
        expectRows(id, {
                           {"d1.01", RowKind::Live, false},
                           {"So.in", RowKind::Live, false},
                           {"A1.01", RowKind::Process, true},
                           {"A2.01", RowKind::Process, true},
                           {"A2.02", RowKind::Process, true},
                           {"0xB0", RowKind::Process, true},
                           {"E17", RowKind::Setting, true},
                           {"S1.01", RowKind::Setting, true},
                           {"S2.02", RowKind::Setting, true},
                           {"E22", RowKind::Setting, false},
                           {"L1.x0", RowKind::Setting, false},
                       });
}

// DMA Profibus Anleitung §7: A1.01 "Wert ist, wenn geschrieben, immer Aktiv"; E17
// "Sollwert Aktivierungsmodus"; S1.01 "Interner Sollwert 1"; 0xB0 "Interne digitale Schalter".
TEST(RowKind, DmaProfibusFollowsItsManual)
{
    for (const char *id : {"dma-pb-v15", "dma-pb-v22", "dma-pb-v32"})
        expectRows(id, {
                           {"d1.11", RowKind::Live, false},
                           {"So.in", RowKind::Live, false},
                           {"A1.01", RowKind::Process, true},
                           {"A2.01", RowKind::Process, true},
                           {"0xB0", RowKind::Process, true},
                           {"E17", RowKind::Setting, true},
                           {"S1.04", RowKind::Setting, true},
                           {"C1.07", RowKind::Setting, false},
                           {"E23", RowKind::Setting, false},
                       });
}

// ED1/SD1 manual §4.4 (PZD-number and persistence columns), §4.5.2 "Receive data (Master →
// Slave, set values)": db_ControlWord, dpc_SetpointVal; §4.5.3 "Transmit data (Slave → Master,
// actual values)": db_StatusWord, dpc_ActualVal; §4.3.1 db_DeviceMode "Preset value setting
// through the bus (1) / locally (2)"; §4.8.6 db_Local "Specifies the source for the control
// word"; §4.8.9 db_ResetDefault "All device parameters will be set to default values".
TEST(RowKind, Ed1FollowsItsManual)
{
    expectRows("wandfluh-ed1", {
                                   {"db_ControlWord", RowKind::Process, true},
                                   {"dpc_SetpointVal", RowKind::Process, true},
                                   {"db_ResetDefault", RowKind::Process, true},
                                   {"db_StoreParameter", RowKind::Process, false},
                                   {"db_StatusWord", RowKind::Live, false},
                                   {"dpc_ActualVal", RowKind::Live, false},
                                   {"dpc_CtrlDeviationVal", RowKind::Live, false},
                                   {"db_ErrorCode", RowKind::Live, false},
                                   {"db_DeviceMode", RowKind::Setting, true},
                                   {"db_Local", RowKind::Setting, true},
                                   {"db_ControlMode", RowKind::Setting, false},
                                   {"dop_drivePos_AsideVal", RowKind::Setting, false},
                                   {"db_Capability", RowKind::Setting, false},
                               });
}

// HART-7 manual §5.2.8 "Command value … Min .. Max Bus Interface"; §6.6 "Setting the command
// value via Fieldbus … the 3 bits D, H and M from the control word … must be set"; §5.2.3 Device
// mode "1: Command value from fieldbus 2: Command value local"; §5.2.5 Device local "0: control
// word via fieldbus 1: control word local"; §5.2.58 Channel Enable; §5.2.94 "Fixed command values
// active"; commands 1–3 and 9 only read the device variables.
TEST(RowKind, Sd7FollowsItsManual)
{
    expectRows("wandfluh-sd7", {
                                   {"db_ControlWord", RowKind::Process, true},
                                   {"dpc_CommandValue", RowKind::Process, true},
                                   {"vprc_CommandValue", RowKind::Process, true},
                                   {"npc_CommandValue", RowKind::Process, true},
                                   {"db_ResetDefault", RowKind::Process, true},
                                   {"db_StatusWord", RowKind::Live, false},
                                   {"db_Temperature", RowKind::Live, false},
                                   {"dpc_ActualValue", RowKind::Live, false},
                                   {"hart_PvValue", RowKind::Live, false},
                                   {"hart_LoopCurrent", RowKind::Live, false},
                                   {"hart_ConfigChangeCounter", RowKind::Live, false},
                                   {"db_DeviceMode", RowKind::Setting, true},
                                   {"db_Local", RowKind::Setting, true},
                                   {"ch_Enable", RowKind::Setting, true},
                                   {"sol2_Enable", RowKind::Setting, true},
                                   {"fcv_Function", RowKind::Setting, true},
                                   {"fcv_Value7", RowKind::Setting, true},
                                   // A speed limit, not a set value, despite its name.
                                   {"ctrl_PosSpeedCommandValue", RowKind::Setting, false},
                                   {"hart_Tag", RowKind::Setting, false},
                                   {"sol1_Imax", RowKind::Setting, false},
                               });
}

// Every family names its set-value source and at least one set value as valve-moving, so the
// confirmation gate has something to guard in each.
TEST(RowKind, EveryFamilyMarksItsSetValuesAndItsSource)
{
    const auto &set = builtinDictionaries();
    ASSERT_TRUE(set.ok());
    for (const std::string &id : set->families()) {
        const Dictionary &d = *set->find(id);
        bool processMoves = false, settingMoves = false;
        for (const ParamMeta &p : d.params) {
            processMoves = processMoves || (p.kind == RowKind::Process && p.movesActuator);
            settingMoves = settingMoves || (p.kind == RowKind::Setting && p.movesActuator);
        }
        EXPECT_TRUE(processMoves) << id;
        EXPECT_TRUE(settingMoves) << id;
    }
}

TEST(RowKind, BlockDefaultsApplyAndRowsOverrideThem)
{
    const std::string text =
        hcsFile(R"("block_defaults":{"d":{"row_kind":"live","note":"why"},)"
                R"("A":{"row_kind":"process","moves_actuator":true}},)",
                hcsRow("d1.01", 1, "d", "r") + "," + hcsRow("A1.01", 31, "A", "rw") + "," +
                    hcsRow("A1.09", 39, "A", "rw", R"(,"moves_actuator":false)") + "," +
                    hcsRow("E17", 112, "E", "rw", R"(,"moves_actuator":true)") + "," +
                    hcsRow("0xB0", 176, "system", "rw", R"(,"row_kind":"process")") + "," +
                    hcsRow("C1.07", 48, "C", "rw"));
    auto r = loadDictionaries({{"k.json", text}});
    ASSERT_TRUE(r.ok()) << r.error().front().text();
    const Dictionary &d = *r->find("k");
    EXPECT_EQ(d.find("d1.01")->kind, RowKind::Live);
    EXPECT_EQ(d.find("A1.01")->kind, RowKind::Process);
    EXPECT_TRUE(d.find("A1.01")->movesActuator);
    EXPECT_EQ(d.find("A1.09")->kind, RowKind::Process);
    EXPECT_FALSE(d.find("A1.09")->movesActuator); // the row's own word wins
    EXPECT_EQ(d.find("E17")->kind, RowKind::Setting);
    EXPECT_TRUE(d.find("E17")->movesActuator);
    EXPECT_EQ(d.find("0xB0")->kind, RowKind::Process);
    EXPECT_EQ(d.find("C1.07")->kind, RowKind::Setting);
    EXPECT_FALSE(d.find("C1.07")->movesActuator);
    EXPECT_TRUE(d.find("d1.01")->note.empty()); // a block default's note stays with the block
}

TEST(RowKind, BlockDefaultsAreInheritedThroughExtends)
{
    const std::string base =
        R"({"schema":1,"family":"base","abstract":true,"title":{"en":"T","de":"T"},)"
        R"("vendor":"HCS","protocol":"hcs","block_defaults":{"A":{"row_kind":"process"}},)"
        R"("parameters":[)" +
        hcsRow("A1.01", 31, "A", "rw") + "]}";
    const std::string child =
        R"({"schema":1,"family":"child","extends":"base","title":{"en":"T","de":"T"},)"
        R"("block_defaults":{"A":{"row_kind":"process","moves_actuator":true}},)"
        R"("parameters":[)" +
        hcsRow("A1.02", 32, "A", "rw") + "]}";
    auto r = loadDictionaries({{"base.json", base}, {"child.json", child}});
    ASSERT_TRUE(r.ok()) << r.error().front().text();
    const Dictionary &d = *r->find("child");
    EXPECT_TRUE(d.find("A1.01")->movesActuator);
    EXPECT_EQ(d.find("A1.02")->kind, RowKind::Process);
}

TEST(RowKind, ValidationRefusesInconsistentRows)
{
    EXPECT_EQ(
        errors(hcsFile({}, hcsRow("d1.01", 1, "d", "rw", R"(,"row_kind":"live")"))),
        std::vector<std::string>{"k.json, row d1.01: a live value is read only, but access is rw"});
    EXPECT_EQ(errors(hcsFile({}, hcsRow("So.in", 154, "S", "r", R"(,"moves_actuator":true)"))),
              std::vector<std::string>{
                  "k.json, row So.in: moves_actuator on a row that cannot be written (access r)"});
    EXPECT_EQ(
        errors(hcsFile(
            {}, hcsRow("A1.01", 31, "A", "rw", R"(,"row_kind":"process","persistence":"eeprom")"))),
        std::vector<std::string>{"k.json, row A1.01: a process value is kept in EEPROM; a value "
                                 "the device keeps is a setting"});
    EXPECT_EQ(errors(hcsFile({}, hcsRow("A1.01", 31, "A", "rw", R"(,"persistence":"volatile")"))),
              std::vector<std::string>{"k.json, row A1.01: a writable volatile value is lost at "
                                       "power down: a process value, not a setting"});
    EXPECT_EQ(errors(hcsFile({}, hcsRow("EClr", 185, "E", "w"))),
              std::vector<std::string>{"k.json, row EClr: a write-only row is a command, not a "
                                       "setting: a file cannot hold what cannot be read back"});
    EXPECT_EQ(errors(hcsFile({}, hcsRow("A1.01", 31, "A", "rw", R"(,"pzd":12)"))),
              std::vector<std::string>{
                  "k.json, row A1.01: a row with a PZD number is process data, not a setting"});
    EXPECT_EQ(errors(hcsFile({}, hcsRow("d1.01", 1, "d", "r", R"(,"row_kind":"process")"))),
              std::vector<std::string>{"k.json, row d1.01: a process value is written at run "
                                       "time; a read-only run-time value is live"});
}

TEST(RowKind, LoaderRefusesUnknownWords)
{
    EXPECT_EQ(errors(hcsFile({}, hcsRow("A1.01", 31, "A", "rw", R"(,"row_kind":"proces")"))),
              std::vector<std::string>{
                  "k.json, row A1.01: \"row_kind\" must be setting, process or live"});
    EXPECT_EQ(
        errors(hcsFile({}, hcsRow("A1.01", 31, "A", "rw", R"(,"moves_actuator":1)"))),
        std::vector<std::string>{"k.json, row A1.01: \"moves_actuator\" must be true or false"});
    EXPECT_EQ(errors(hcsFile(R"("block_defaults":{"A":{"row_kind":"process","unit":"V"}},)",
                             hcsRow("A1.01", 31, "A", "rw"))),
              std::vector<std::string>{"k.json: block_defaults 'A' may set only row_kind and "
                                       "moves_actuator (and a note), not 'unit'"});
    // A misspelt block would leave its rows settings silently.
    EXPECT_EQ(errors(hcsFile(R"("block_defaults":{"a":{"row_kind":"process"}},)",
                             hcsRow("A1.01", 31, "A", "rw"))),
              std::vector<std::string>{"k.json: block_defaults names block 'a', which no row has"});
    EXPECT_EQ(errors(hcsFile(R"("block_defaults":[],)", hcsRow("A1.01", 31, "A", "rw"))),
              std::vector<std::string>{"k.json: \"block_defaults\" must be an object"});
    // A block default is checked like a row's own word.
    EXPECT_EQ(
        errors(hcsFile(R"("block_defaults":{"d":{"row_kind":"live"}},)",
                       hcsRow("d1.01", 1, "d", "rw"))),
        std::vector<std::string>{"k.json, row d1.01: a live value is read only, but access is rw"});
}
