// valvetune-cli decode / encode golden tests: the manuals' worked
// examples, error exits, and every protocol surviving garbage.
#include "cli_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

namespace {

using vt::test::cli;
using vt::test::CliRun;

} // namespace

// OPAT manual §2.7: write C1.07 = 1.000 V to the OPAT master: 23 00 06 00 30 03 E8.
TEST(CliDecode, OpatWriteExampleFieldByField)
{
    const CliRun r = cli(
        {"--json", "decode", "--protocol", "gateway", "--family", "opat", "23 00 06 00 30 03 E8"});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    EXPECT_EQ(doc["protocol"], "gateway");
    EXPECT_EQ(doc["ok"], true);
    EXPECT_TRUE(doc["error"].is_null());
    const auto &f = doc["fields"];
    ASSERT_GE(f.size(), 5u);
    EXPECT_EQ(f[0]["key"], "TADR");
    EXPECT_EQ(f[0]["value"], "0x23");
    EXPECT_EQ(f[3]["offset"], 3);
    EXPECT_EQ(f[3]["length"], 2);
    EXPECT_NE(f[3]["text"].get<std::string>().find("C1.07"),
              std::string::npos); // named from the dictionary
    EXPECT_NE(f[4]["text"].get<std::string>().find("1.000 V"), std::string::npos);
    const CliRun de = cli({"decode", "--protocol", "gateway", "--family", "opat", "--lang", "de",
                           "23 00 06 00 30 03 E8"});
    EXPECT_NE(de.out.find("1,000 V"), std::string::npos);
}

TEST(CliDecode, AFrameThatDoesNotDecodeIsOkFalseExitOne)
{
    const CliRun r = cli({"--json", "decode", "--protocol", "gateway", "23 00"});
    EXPECT_EQ(r.code, vt::cli::kExitDeviceError);
    const auto doc = nlohmann::json::parse(r.out);
    EXPECT_EQ(doc["ok"], false);
    EXPECT_EQ(doc["error"]["offset"], 2);
    EXPECT_FALSE(doc["error"]["reason"].get<std::string>().empty());
    EXPECT_EQ(doc["fields"].size(), 2u); // as far as the bytes go
}

TEST(CliDecode, EveryProtocolSurvivesGarbage)
{
    for (const char *p :
         {"gateway", "modbus-rtu", "modbus-tcp", "profidrive", "pkw", "pzd", "hart", "canopen"}) {
        for (const char *hex :
             {"00", "FF FF FF FF FF FF FF FF FF FF FF FF FF FF FF FF FF FF FF FF", "83"}) {
            const CliRun r =
                cli({"--json", "decode", "--protocol", p, "--direction", "response", hex});
            EXPECT_TRUE(r.code == 0 || r.code == 1) << p << " " << hex;
            const auto doc = nlohmann::json::parse(r.out);
            EXPECT_EQ(doc["protocol"], p);
            EXPECT_EQ(doc["ok"], r.code == 0) << p << " " << hex;
        }
    }
}

TEST(CliDecode, UsageErrors)
{
    EXPECT_EQ(cli({"decode", "23 00"}).code, vt::cli::kExitUsage); // no protocol fits
    EXPECT_EQ(cli({"decode", "--protocol", "smoke-signals", "23"}).code, vt::cli::kExitUsage);
    EXPECT_EQ(cli({"decode", "--protocol", "gateway", "23 0G"}).code,
              vt::cli::kExitUsage);                                                // not hex
    EXPECT_EQ(cli({"decode", "--protocol", "gateway"}).code, vt::cli::kExitUsage); // no frame
    EXPECT_EQ(cli({"decode", "--protocol", "gateway", "--family", "xyz", "23"}).code,
              vt::cli::kExitUsage);
    EXPECT_EQ(cli({"decode", "--protocol", "gateway", "--profile", "nope", "23 00 03"}).code,
              vt::cli::kExitUsage);
}

// Without --protocol the bytes are auto-detected, as the decode box does, and the protocol chosen
// is named; a damaged Modbus RTU frame is named as RTU with a wrong CRC; --protocol still forces.
TEST(CliDecode, AutoDetectsAndNamesTheProtocol)
{
    const CliRun ok = cli({"decode", "01 03 00 07 00 01 35 CB"});
    EXPECT_EQ(ok.code, 0) << ok.err;
    EXPECT_EQ(ok.out.rfind("auto-detected: modbus-rtu, request\n", 0), 0u) << ok.out;

    const CliRun bad = cli({"--json", "decode", "01 03 00 07 00 01 35 34"});
    EXPECT_EQ(bad.code, vt::cli::kExitDeviceError);
    const auto doc = nlohmann::json::parse(bad.out);
    EXPECT_EQ(doc["protocol"], "modbus-rtu");
    EXPECT_EQ(doc["detected"], true);
    EXPECT_NE(bad.err.find("CRC"), std::string::npos) << bad.err;

    const CliRun ambiguous = cli({"decode", "20 49 03 00 00 00 01 C2"}); // PKW or SDO
    EXPECT_EQ(ambiguous.code, vt::cli::kExitUsage);
    EXPECT_NE(ambiguous.err.find("pkw"), std::string::npos) << ambiguous.err;

    const CliRun forced = cli({"--json", "decode", "--protocol", "pkw", "20 49 03 00 00 00 01 C2"});
    EXPECT_EQ(nlohmann::json::parse(forced.out)["protocol"], "pkw");
    EXPECT_EQ(nlohmann::json::parse(forced.out)["detected"], false);
}

// OPAT manual §2.7 (CMD 6) and the classic Modbus reference frame 01 03 00 00 00 01 84 0A.
TEST(CliEncode, BuildsTheManualsFrames)
{
    EXPECT_EQ(cli({"encode", "gateway", "write", "--tadr", "0x23", "--sadr", "0", "--id", "0x30",
                   "--value", "1000"})
                  .out,
              "23 00 06 00 30 03 E8\n");
    EXPECT_EQ(
        cli({"encode", "gateway", "read", "--tadr", "0x23", "--sadr", "0", "--id", "0x30"}).out,
        "23 00 03 00 30 00 01\n");
    EXPECT_EQ(cli({"encode", "modbus-rtu", "read", "--unit", "1", "--id", "0"}).out,
              "01 03 00 00 00 01 84 0A\n");
    const CliRun neg = cli({"--json", "encode", "gateway", "write", "--tadr", "1", "--sadr", "2",
                            "--id", "31", "--value", "-3000"});
    EXPECT_EQ(nlohmann::json::parse(neg.out)["hex"], "01 02 06 00 1F F4 48");
    // DMA CMD 15 for two modules: 3 + 5·2 bytes, SNUM = 2.
    const CliRun cyc = cli({"encode", "gateway", "cyclic", "--family", "dma", "--tadr", "1",
                            "--module", "0,1000,0", "--module", "0,2000,0"});
    EXPECT_EQ(cyc.out, "01 02 0F 00 03 E8 00 00 00 07 D0 00 00\n");
}

TEST(CliEncode, ImpossibleFramesAreUsageErrorsThatSayWhy)
{
    QStringList six = {"encode", "gateway", "cyclic", "--family", "dma", "--tadr", "1"};
    for (int i = 0; i < 6; ++i)
        six << "--module"
            << "0,0,0";
    const CliRun r = cli(six);
    EXPECT_EQ(r.code, vt::cli::kExitUsage);
    EXPECT_NE(r.err.find("cannot carry 6 modules"), std::string::npos) << r.err;
    const CliRun count =
        cli({"encode", "modbus-rtu", "read", "--unit", "1", "--id", "0", "--count", "9"});
    EXPECT_EQ(count.code, vt::cli::kExitUsage);
    EXPECT_NE(count.err.find("1 to 8"), std::string::npos);
    EXPECT_EQ(cli({"encode", "gateway", "write", "--tadr", "1", "--sadr", "0", "--id", "1"}).code,
              vt::cli::kExitUsage);
    EXPECT_EQ(cli({"encode", "gateway", "write", "--tadr", "256", "--sadr", "0", "--id", "1",
                   "--value", "0"})
                  .code,
              vt::cli::kExitUsage);
}
