// valvetune-cli device commands, golden tests: info, scan, read, get, set and
// monitor against the built-in simulator (dma-pn-v51, opat:3, dma-pb-v32) in text and --json,
// the error exits (usage 2, device 1, connection 3), and one run over a real valvetune-sim --tcp.
// Files (read --out, diff, write): cli_device_file_test.cpp.
#include "app/cli/device_output.h"
#include "app/cli/exit_codes.h"
#include "cli_device_fixture.h"
#include "dict/dictionary_loader.h"
#include "sim_process.h"

#include <QCoreApplication>
#include <regex>

namespace vt::clitest {
namespace {

using cli::kExitConnection;
using cli::kExitDeviceError;
using cli::kExitOk;
using cli::kExitUsage;

TEST_F(CliDevice, InfoIdentifiesEveryModuleInTextAndJson)
{
    const CliRun text = cli({"info", "--sim", "dma-pn-v51"});
    ASSERT_EQ(text.code, kExitOk) << what(text);
    EXPECT_TRUE(text.says("connection: sim dma-pn-v51 ×1, modbus-rtu, module 1\n")) << text.out;
    EXPECT_TRUE(text.says("module 1: dma-pn-v51 V51.00, mode 3 — ")) << text.out;

    const CliRun opat = cli({"--json", "info", "--sim", "opat:3"});
    ASSERT_EQ(opat.code, kExitOk) << what(opat);
    const auto doc = opat.json();
    ASSERT_EQ(doc["modules"].size(), 3u);
    // OPAT master (V34, SADR 0) with two CAN slaves (V31, DIP switches 1 and 2).
    const int addresses[] = {0, 1, 2};
    const char *versions[] = {"34.00", "31.00", "31.00"};
    for (std::size_t i = 0; i < 3; ++i) {
        const auto &m = doc["modules"][i];
        EXPECT_EQ(m["address"], addresses[i]);
        EXPECT_EQ(m["ok"], true);
        EXPECT_EQ(m["family"], "opat");
        EXPECT_EQ(m["version"], versions[i]);
        EXPECT_EQ(m["mode"], "3");
    }

    const CliRun pb = cli({"info", "--sim", "dma-pb-v32", "--json"});
    ASSERT_EQ(pb.code, kExitOk) << what(pb);
    EXPECT_EQ(pb.json()["modules"][0]["family"], "dma-pb-v32");
    EXPECT_EQ(pb.json()["modules"][0]["version"], "32.00");
}

TEST_F(CliDevice, ScanListsTheAddressesThatAnswer)
{
    const CliRun text = cli({"scan", "--sim", "opat:3"});
    ASSERT_EQ(text.code, kExitOk) << what(text);
    EXPECT_TRUE(text.says("address 0: opat V34.00, mode 3\n")) << text.out;
    EXPECT_TRUE(text.says("address 2: opat V31.00, mode 3\n")) << text.out;
    EXPECT_TRUE(text.says("3 of 3 addresses answered\n")) << text.out;

    const CliRun json = cli({"--json", "scan", "--sim", "dma-pb-v32"});
    ASSERT_EQ(json.code, kExitOk) << what(json);
    EXPECT_EQ(json.json()["tried"], nlohmann::json::array({1}));
    EXPECT_EQ(json.json()["found"][0]["family"], "dma-pb-v32");
}

TEST_F(CliDevice, ReadPrintsEveryReadableRowOfEveryModule)
{
    const CliRun text = cli({"read", "--sim", "dma-pn-v51"});
    ASSERT_EQ(text.code, kExitOk) << what(text);
    EXPECT_TRUE(text.says("module 1: dma-pn-v51 V51.00, mode 3\n")) << text.out;
    EXPECT_TRUE(text.says("  Vers           51.00\n")) << text.out;
    EXPECT_TRUE(text.says("  C1.07          0.000 V\n")) << text.out;

    const CliRun json = cli({"--json", "read", "--sim", "opat:3"});
    ASSERT_EQ(json.code, kExitOk) << what(json);
    const auto doc = json.json();
    ASSERT_EQ(doc["modules"].size(), 3u);
    for (const auto &m : doc["modules"]) {
        EXPECT_GT(m["count"].get<int>(), 50);
        EXPECT_EQ(m["values"].size(), m["count"].get<std::size_t>());
        EXPECT_TRUE(m["failures"].empty()) << m["failures"].dump();
    }
    EXPECT_EQ(
        doc["modules"][0]["values"][0],
        (nlohmann::json{{"name", "Vers"}, {"raw", 3400}, {"display", "34.00"}, {"unit", ""}}));

    const CliRun one = cli({"--json", "read", "--sim", "opat:3", "--module", "2"});
    ASSERT_EQ(one.code, kExitOk) << what(one);
    ASSERT_EQ(one.json()["modules"].size(), 1u);
    EXPECT_EQ(one.json()["modules"][0]["address"], 2);
}

// The editor's scenario on the command line: C1.07 = 1.000 V, read back the same.
TEST_F(CliDevice, SetThenGetShowsTheValueInDisplayUnits)
{
    const CliRun set = cli({"set", "--sim", "dma-pn-v51", "C1.07=1.000"});
    ASSERT_EQ(set.code, kExitOk) << what(set);
    EXPECT_EQ(set.out, "C1.07          0.000 V -> 1.000 V  verified\n");
    const CliRun get = cli({"get", "--sim", "dma-pn-v51", "C1.07"});
    ASSERT_EQ(get.code, kExitOk) << what(get);
    EXPECT_EQ(get.out, "C1.07          1.000 V\n");

    const CliRun json = cli({"--json", "get", "--sim", "dma-pn-v51", "C1.07", "E00"});
    ASSERT_EQ(json.code, kExitOk) << what(json);
    const auto values = json.json()["values"];
    EXPECT_EQ(
        values[0],
        (nlohmann::json{{"name", "C1.07"}, {"raw", 1000}, {"display", "1.000 V"}, {"unit", "V"}}));
    EXPECT_EQ(values[1]["name"], "E00");
    EXPECT_EQ(values[1]["raw"], 3);
}

// `--sim` starts a commissioned machine (docs/SIMULATOR.md "Commissioned preset": bus set values
// only, a 0 … 10 V position sensor, KP1 2.00); `--factory` the dictionary defaults.
TEST_F(CliDevice, SimStartsCommissionedUnlessFactory)
{
    const CliRun commissioned =
        cli({"--json", "get", "--sim", "dma-pn-v51", "E17", "C1.09", "C1.13"});
    ASSERT_EQ(commissioned.code, kExitOk) << what(commissioned);
    const auto c = commissioned.json()["values"];
    EXPECT_EQ(c[0]["raw"], 2);
    EXPECT_EQ(c[1]["raw"], 4);
    EXPECT_EQ(c[2]["raw"], 200);

    const CliRun factory =
        cli({"--json", "get", "--sim", "dma-pn-v51", "--factory", "E17", "C1.09", "C1.13"});
    ASSERT_EQ(factory.code, kExitOk) << what(factory);
    const auto f = factory.json()["values"];
    const dev::Dictionary &dict = *dev::builtinDictionaries()->find("dma-pn-v51");
    for (std::size_t i = 0; i < 3; ++i) {
        const dev::ParamMeta *row = dict.find(f[i]["name"].get<std::string>());
        ASSERT_TRUE(row && row->defaultValue);
        EXPECT_EQ(f[i]["raw"], *row->defaultValue) << row->name;
    }

    const CliRun alone = cli({"get", "--tcp", "127.0.0.1:1", "--factory", "E17"});
    EXPECT_EQ(alone.code, kExitUsage) << what(alone);
    EXPECT_NE(alone.err.find("--factory goes with --sim"), std::string::npos) << alone.err;
}

TEST_F(CliDevice, SetJsonRecordsEveryParameterAndSkipsUnchangedValues)
{
    const CliRun first = cli({"--json", "set", "--sim", "dma-pb-v32", "C1.07=2.5", "r1.01=120"});
    ASSERT_EQ(first.code, kExitOk) << what(first);
    const auto doc = first.json();
    EXPECT_EQ(doc["module"]["family"], "dma-pb-v32");
    EXPECT_EQ(doc["complete"], true);
    ASSERT_EQ(doc["results"].size(), 2u);
    EXPECT_EQ(doc["results"][0]["status"], "verified");
    EXPECT_EQ(doc["results"][0]["value"]["raw"], 2500);
    EXPECT_EQ(doc["results"][0]["read_back"]["display"], "2.500 V");
    EXPECT_EQ(doc["results"][1]["name"], "r1.01");

    const CliRun again = cli({"--json", "set", "--sim", "dma-pb-v32", "C1.07=2.500"});
    ASSERT_EQ(again.code, kExitOk) << what(again);
    EXPECT_EQ(again.json()["results"][0]["status"], "unchanged");
}

// German input and output: "1,500" is 1.5 V; a point is refused rather than guessed.
TEST_F(CliDevice, GermanDecimalSign)
{
    const CliRun set = cli({"set", "--sim", "dma-pn-v51", "--lang", "de", "C1.07=1,500"});
    ASSERT_EQ(set.code, kExitOk) << what(set);
    EXPECT_TRUE(set.says("-> 1,500 V  verified")) << set.out;
    const CliRun get = cli({"get", "--sim", "dma-pn-v51", "C1.07", "--lang", "de"});
    EXPECT_EQ(get.out, "C1.07          1,500 V\n");
    EXPECT_EQ(cli({"get", "--sim", "dma-pn-v51", "C1.07"}).out, "C1.07          1.500 V\n");

    const CliRun point = cli({"set", "--sim", "dma-pn-v51", "--lang", "de", "C1.07=2.000"});
    EXPECT_EQ(point.code, kExitUsage) << what(point);
    EXPECT_EQ(cli({"get", "--sim", "dma-pn-v51", "C1.07"}).out, "C1.07          1.500 V\n");
}

// Decision: a value the dictionary refuses (out of range, read-only row, unknown name) is a usage
// error, exit 2, detected before anything is sent; exit 1 is kept for the device's refusals.
TEST_F(CliDevice, RefusedValuesExitTwoAndAreNeverSent)
{
    const CliRun range = cli({"set", "--sim", "dma-pn-v51", "C1.07=10"});
    EXPECT_EQ(range.code, kExitUsage) << what(range);
    EXPECT_EQ(range.errLines(), 1) << range.err;
    EXPECT_TRUE(range.complains("C1.07: above the maximum 9.999 V")) << range.err;
    EXPECT_TRUE(range.out.empty());
    // Together with a valid value: nothing of the command is sent.
    const CliRun mixed = cli({"--json", "set", "--sim", "dma-pn-v51", "r1.01=100", "C1.07=-1"});
    EXPECT_EQ(mixed.code, kExitUsage) << what(mixed);
    EXPECT_TRUE(mixed.out.empty());
    const auto unchanged =
        cli({"--json", "get", "--sim", "dma-pn-v51", "r1.01", "C1.07"}).json()["values"];
    EXPECT_EQ(unchanged[0]["raw"], 0);
    EXPECT_EQ(unchanged[1]["raw"], 0);

    const CliRun readOnly = cli({"set", "--sim", "dma-pn-v51", "d1.07=1"});
    EXPECT_EQ(readOnly.code, kExitUsage) << what(readOnly);
    EXPECT_TRUE(readOnly.complains("d1.07 cannot be written")) << readOnly.err;

    for (const char *command : {"get", "set", "monitor"}) {
        const CliRun unknown = cli(
            {command, "--sim", "dma-pn-v51", std::string(command) == "set" ? "X9.99=1" : "X9.99"});
        EXPECT_EQ(unknown.code, kExitUsage) << command << what(unknown);
        EXPECT_EQ(unknown.errLines(), 1) << unknown.err;
        EXPECT_TRUE(unknown.complains("unknown parameter 'X9.99' for dma-pn-v51")) << unknown.err;
    }
}

// r2.01 (ramp of branch 2) exists in OPAT modes 6 and 8 only: the module in mode 3 refuses it.
TEST_F(CliDevice, TheDeviceRefusingExitsOne)
{
    const CliRun r = cli({"--json", "set", "--sim", "opat:3", "r2.01=100"});
    EXPECT_EQ(r.code, kExitDeviceError) << what(r);
    const auto doc = r.json();
    EXPECT_EQ(doc["complete"], false);
    EXPECT_EQ(doc["results"][0]["status"], "refused");
    EXPECT_NE(doc["results"][0]["reason"].get<std::string>().find("wrong ID"), std::string::npos)
        << r.out;
}

// The device's refusal is printed in the language --lang chose, as every device text is.
TEST_F(CliDevice, TheDeviceRefusalInTheChosenLanguage)
{
    model::Outcome refused;
    refused.status = model::OutcomeStatus::DeviceException;
    refused.reply.exceptionText = {"wrong ID", "Falsche ID"};
    EXPECT_EQ(cli::outcomeText(refused, dev::Language::German),
              "refused by the device: Falsche ID");
    EXPECT_EQ(cli::outcomeText(refused, dev::Language::English), "refused by the device: wrong ID");

    const CliRun de = cli({"get", "--sim", "opat:3", "--lang", "de", "r2.01"});
    EXPECT_EQ(de.code, kExitDeviceError) << what(de);
    EXPECT_TRUE(de.complains("Falsche ID")) << de.err;
    const CliRun en = cli({"get", "--sim", "opat:3", "r2.01"});
    EXPECT_EQ(en.code, kExitDeviceError) << what(en);
    EXPECT_TRUE(en.complains("wrong ID")) << en.err;
}

TEST_F(CliDevice, ALinkCutExitsThree)
{
    for (const QStringList &args :
         {QStringList{"get", "C1.07", "--fault", "cut=2"}, QStringList{"read", "--fault", "cut=12"},
          QStringList{"set", "C1.07=1.000", "--fault", "cut=4"},
          QStringList{"monitor", "--rate", "0", "--duration", "5", "--fault", "cut=40"}}) {
        const CliRun r = cli(QStringList{args.front(), "--sim", "dma-pn-v51"} + args.mid(1));
        EXPECT_EQ(r.code, kExitConnection) << args.join(' ').toStdString() << '\n' << what(r);
        EXPECT_TRUE(r.complains("Fault injection cut the link") || r.complains("was lost"))
            << r.err;
    }
    // The write cut after the request: the record says the value may or may not be there.
    const CliRun set =
        cli({"--json", "set", "--sim", "dma-pn-v51", "C1.07=1.000", "--fault", "cut=7"});
    EXPECT_EQ(set.code, kExitConnection) << what(set);
    EXPECT_EQ(set.json()["results"][0]["status"], "uncertain") << set.out;
}

TEST_F(CliDevice, MonitorPrintsSamplesAndReportsTheAchievedRate)
{
    const CliRun text =
        cli({"monitor", "--sim", "dma-pn-v51", "--rate", "20", "--duration", "0.3"});
    ASSERT_EQ(text.code, kExitOk) << what(text);
    // Every sample line names each channel with its value and unit. The values themselves follow
    // the commissioned plant (the cylinder settles from mid-stroke), so only the shape is fixed.
    const std::regex sample(
        R"((?:^|\n) +\d+\.\d{3} s  d1\.10 -?\d+\.\d{3} V  d1\.11 -?\d+\.\d{3} V  )"
        R"(d1\.07 -?\d+\.\d{3} A  d1\.08 -?\d+\.\d{3} A  d1\.09 -?\d+\.\d{3} A\n)");
    EXPECT_TRUE(std::regex_search(text.out, sample)) << text.out;
    EXPECT_TRUE(text.says("requested 20.0 Hz, achieved ")) << text.out;

    const CliRun csv = cli({"monitor", "--sim", "opat:3", "--module", "1", "d1.07", "d1.10",
                            "--rate", "20", "--duration", "0.3", "--csv"});
    ASSERT_EQ(csv.code, kExitOk) << what(csv);
    EXPECT_EQ(csv.out.rfind("time_s,d1.07 [A],d1.10 [V]\n0.0000,", 0), 0u) << csv.out;
    EXPECT_TRUE(csv.complains("# requested 20.0 Hz")) << csv.err;

    const CliRun json =
        cli({"--json", "monitor", "--sim", "dma-pb-v32", "--rate", "50", "--duration", "0.4"});
    ASSERT_EQ(json.code, kExitOk) << what(json);
    const auto doc = json.json();
    EXPECT_EQ(doc["requested_hz"], 50.0);
    // The family's default channels (dictionary "monitor"): d1.10, d1.11, d1.07, d1.08, d1.09.
    ASSERT_EQ(doc["rows"].size(), 5u);
    EXPECT_EQ(doc["rows"][0]["name"], "d1.10");
    EXPECT_GE(doc["samples"].get<int>(), 5);
    EXPECT_EQ(doc["data"].size(), doc["samples"].get<std::size_t>());
    EXPECT_GT(doc["achieved_hz"].get<double>(), 10.0);
    EXPECT_LT(doc["achieved_hz"].get<double>(), 60.0);
}

TEST_F(CliDevice, ConnectionUsageErrors)
{
    const QStringList bad[] = {
        {"info"},                                                  // no connection
        {"info", "--sim", "dma-pn-v51", "--tcp", "127.0.0.1:502"}, // two
        {"info", "--sim", "no-such-family"},
        {"info", "--sim", "opat:99"},
        {"info", "--sim", "opat", "--fault", "drop=2"},
        {"info", "--sim", "opat", "--baud", "9600"},
        {"info", "--can", "vcan0"}, // no --node
        {"info", "--sim", "opat", "--frobnicate"},
        {"get", "--sim", "opat:3", "--module", "7", "C1.07"},
        {"get", "--sim", "opat"},          // no name
        {"set", "--sim", "opat", "C1.07"}, // no value
        {"write", "--sim", "opat"},        // no file
        {"monitor", "--sim", "opat", "--rate", "fast"},
    };
    for (const QStringList &args : bad) {
        const CliRun r = cli(args);
        EXPECT_EQ(r.code, kExitUsage) << args.join(' ').toStdString() << '\n' << what(r);
        EXPECT_EQ(r.errLines(), 1) << args.join(' ').toStdString() << '\n' << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
    for (const char *command : {"info", "scan", "read", "get", "set", "write", "diff", "monitor"}) {
        const CliRun help = cli({command, "--help"});
        EXPECT_EQ(help.code, kExitOk);
        EXPECT_EQ(help.out.rfind(std::string("usage: valvetune-cli ") + command + " CONNECTION", 0),
                  0u)
            << help.out;
        EXPECT_TRUE(help.says("--sim FAMILY[:MODULES]")) << help.out;
        EXPECT_TRUE(help.says("[--factory]")) << help.out;
    }
    const CliRun refused = cli({"info", "--tcp", "127.0.0.1:1"});
    EXPECT_EQ(refused.code, kExitConnection) << what(refused);
    EXPECT_EQ(refused.errLines(), 1) << refused.err;
}

// --lang de puts the German catalogue in force for the run: the link's own words (tr()) come out
// in German; the next run without --lang is English again (runCli removes what it installed).
TEST_F(CliDevice, LangDeWordsTheLinksTextsInGermanForThatRunOnly)
{
    const CliRun german = cli({"info", "--tcp", "127.0.0.1:1", "--lang", "de"});
    EXPECT_EQ(german.code, kExitConnection) << what(german);
    EXPECT_TRUE(german.complains("Verbindung zu 127.0.0.1:1 fehlgeschlagen")) << german.err;
    const CliRun english = cli({"info", "--tcp", "127.0.0.1:1"});
    EXPECT_EQ(english.code, kExitConnection) << what(english);
    EXPECT_TRUE(english.complains("Connection to 127.0.0.1:1 failed")) << english.err;
    EXPECT_EQ(QCoreApplication::translate("vt::link::TcpLink", "Connection to %1 failed: %2"),
              "Connection to %1 failed: %2");
}

// End to end over a real valvetune-sim process on loopback: a 3-fold DMA-2 behind Modbus TCP.
TEST_F(CliDevice, OverTcpToTheSimulatorProcess)
{
    simtest::Sim sim({"--device", "dma-pn-v51", "--modules", "3", "--tcp", "127.0.0.1:0"});
    const QString where = sim.listening();
    ASSERT_TRUE(where.startsWith("127.0.0.1:")) << sim.stderrText().toStdString();
    const QString tcp = where;

    const CliRun scan = cli({"--json", "scan", "--tcp", tcp});
    ASSERT_EQ(scan.code, kExitOk) << what(scan);
    const auto found = scan.json()["found"];
    ASSERT_EQ(found.size(), 3u) << scan.out;
    EXPECT_EQ(found[2]["address"], 3);

    const CliRun set = cli({"set", "--tcp", tcp, "--unit", "2", "C1.07=1.234"});
    ASSERT_EQ(set.code, kExitOk) << what(set);
    EXPECT_EQ(cli({"get", "--tcp", tcp, "--unit", "2", "C1.07"}).out, "C1.07          1.234 V\n");
    EXPECT_EQ(cli({"get", "--tcp", tcp, "C1.07"}).out,
              "C1.07          0.000 V\n"); // unit 1 untouched

    const CliRun info = cli({"info", "--tcp", tcp, "--unit", "3"});
    ASSERT_EQ(info.code, kExitOk) << what(info);
    EXPECT_TRUE(info.says(", modbus-tcp, module 3\nmodule 3: dma-pn-v51 V51.00, mode 3"))
        << info.out;
}

// The SD7's own texts (HART-7 manual §5.1.10, §5.1.11, §5.1.18; delivery state §6.4) in info.
TEST_F(CliDevice, InfoShowsTheSd7Texts)
{
    const CliRun text = cli({"info", "--sim", "wandfluh-sd7"});
    ASSERT_EQ(text.code, kExitOk) << what(text);
    EXPECT_TRUE(text.says("  Tag: WAGSD733\n")) << text.out;
    EXPECT_TRUE(text.says("  Long tag: Wandfluh AG - SD733\n")) << text.out;
    EXPECT_TRUE(text.says("  Descriptor: WAG ELECTRONIC\n")) << text.out;
    EXPECT_TRUE(text.says("  Date: 2024-03-15\n")) << text.out;
    EXPECT_TRUE(text.says("  Message: ")) << text.out;

    // Commands 18 and 17 write them, each read back (HART-7 manual §5.1.15, §5.1.16).
    const CliRun set =
        cli({"set", "--sim", "wandfluh-sd7", "--yes", "hart_Tag=PUMP 7", "hart_Message=CHECKED"});
    ASSERT_EQ(set.code, kExitOk) << what(set);
    EXPECT_TRUE(set.says("hart_Tag       \"WAGSD733\" -> \"PUMP 7\"  verified\n")) << set.out;
    EXPECT_TRUE(set.says("hart_Message   \"\" -> \"CHECKED\"  verified\n")) << set.out;

    // The next command finds what the set left (the simulator is a bench device).
    const CliRun json = cli({"--json", "info", "--sim", "wandfluh-sd7"});
    ASSERT_EQ(json.code, kExitOk) << what(json);
    const auto doc = json.json();
    const auto &texts = doc["modules"][0]["texts"];
    EXPECT_EQ(texts["tag"], "PUMP 7");
    EXPECT_EQ(texts["message"], "CHECKED");
    EXPECT_EQ(texts["descriptor"], "WAG ELECTRONIC");
    EXPECT_EQ(texts["date"], "2024-03-15");
    EXPECT_EQ(texts["long_tag"], "Wandfluh AG - SD733");
}

// The built-in simulator is a bench device for every family: what one command set, the next
// command's connection to the same simulator reads — the SD7's IND/PNU rows and its HART texts
// (HART-7 manual §5.1.15, §5.2) and the ED1/SD1's rows, as for the HCS modules above.
TEST_F(CliDevice, TheWandfluhSimulatorsKeepWhatASetWroteForTheNextCommand)
{
    const CliRun set =
        cli({"set", "--sim", "wandfluh-sd7", "--yes", "dcol_RampAUp=250", "hart_Tag=PUMP 7"});
    ASSERT_EQ(set.code, kExitOk) << what(set);
    const CliRun get = cli({"get", "--sim", "wandfluh-sd7", "dcol_RampAUp", "hart_Tag"});
    ASSERT_EQ(get.code, kExitOk) << what(get);
    EXPECT_TRUE(get.says("dcol_RampAUp   250 ms\n")) << get.out;
    EXPECT_TRUE(get.says("hart_Tag       \"PUMP 7\"\n")) << get.out;

    const CliRun ed1 = cli({"set", "--sim", "wandfluh-ed1", "--yes", "dpc_PropFact1=25"});
    ASSERT_EQ(ed1.code, kExitOk) << what(ed1);
    const CliRun back = cli({"get", "--sim", "wandfluh-ed1", "dpc_PropFact1"});
    ASSERT_EQ(back.code, kExitOk) << what(back);
    EXPECT_TRUE(back.says("dpc_PropFact1  25\n")) << back.out;

    // Another test's simulator starts fresh.
    cli::forgetSimulators();
    const CliRun fresh = cli({"get", "--sim", "wandfluh-sd7", "dcol_RampAUp"});
    ASSERT_EQ(fresh.code, kExitOk) << what(fresh);
    EXPECT_TRUE(fresh.says("dcol_RampAUp   0 ms\n")) << fresh.out;
}

} // namespace
} // namespace vt::clitest
