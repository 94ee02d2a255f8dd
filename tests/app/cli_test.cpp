// valvetune-cli conventions: usage errors exit 2 with one line on stderr;
// --help and --version exit 0; --json output is JSON.
#include "cli_run.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace {

using vt::test::cli;
using vt::test::CliRun;

} // namespace

TEST(Cli, UsageErrorsExitTwoWithOneLineOnStderr)
{
    for (const QStringList &args :
         {QStringList{}, QStringList{"--frobnicate"}, QStringList{"no-such-command"},
          QStringList{"--json", "no-such-command"}}) {
        const CliRun r = cli(args);
        EXPECT_EQ(r.code, vt::cli::kExitUsage) << args.join(' ').toStdString();
        EXPECT_EQ(r.errLines(), 1) << r.err;
        EXPECT_EQ(r.err.rfind("valvetune-cli: ", 0), 0u) << r.err;
        EXPECT_TRUE(r.out.empty());
    }
}

TEST(Cli, HelpAndVersion)
{
    const CliRun help = cli({"--help"});
    EXPECT_EQ(help.code, 0);
    EXPECT_NE(help.out.find("Exit codes: 0 ok, 1 device or protocol error, 2 usage error"),
              std::string::npos);
    const CliRun version = cli({"--version"});
    EXPECT_EQ(version.code, 0);
    EXPECT_EQ(version.out, std::string("valvetune-cli ") + VT_VERSION + "\n");
    const CliRun json = cli({"--json", "--version"});
    const auto doc = nlohmann::json::parse(json.out);
    EXPECT_EQ(doc.at("version"), VT_VERSION);
}

TEST(Cli, TheInstalledBinaryKeepsTheExitCodes)
{
    const std::string cmd = std::string(VT_CLI_PATH) + " --frobnicate 2>/dev/null";
    FILE *p = popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::array<char, 256> buf{};
    while (fgets(buf.data(), static_cast<int>(buf.size()), p)) {
    }
    const int status = pclose(p);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
}

TEST(CliDictionary, ListsTheFamilies)
{
    const CliRun r = cli({"--json", "dictionary", "list"});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    ASSERT_EQ(doc.at("families").size(), 8u);
    EXPECT_EQ(doc["families"][5]["family"], "opat");
    EXPECT_EQ(doc["families"][5]["protocol"], "hcs");
    const CliRun text = cli({"dictionary", "list"});
    EXPECT_NE(text.out.find("wandfluh-sd7"), std::string::npos);
}

TEST(CliDictionary, ShowsEveryParameterWithItsMetadata)
{
    const CliRun r = cli({"dictionary", "show", "opat", "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    const auto &rows = doc.at("parameters");
    const auto it =
        std::find_if(rows.begin(), rows.end(), [](const auto &p) { return p["name"] == "C1.07"; });
    ASSERT_NE(it, rows.end());
    for (const char *key : {"name", "id", "block", "access", "type", "min", "max", "unit", "scale",
                            "enum", "label_en", "label_de"})
        EXPECT_TRUE(it->contains(key)) << key;
    EXPECT_EQ((*it)["id"], 48);
    EXPECT_EQ((*it)["unit"], "V");
    EXPECT_EQ((*it)["max"], 9999);
    EXPECT_EQ((*it)["scale"]["factor"], 0.001);
    EXPECT_EQ((*it)["label_de"], "Totbereichkompensation A");

    const CliRun wf = cli({"--json", "dictionary", "show", "wandfluh-ed1"});
    const auto ed1 = nlohmann::json::parse(wf.out);
    EXPECT_TRUE(ed1["parameters"][0].contains("ind"));
    EXPECT_TRUE(ed1["parameters"][0].contains("pnu"));

    const CliRun de = cli({"dictionary", "show", "opat", "--lang", "de"});
    EXPECT_NE(de.out.find("Totbereichkompensation A  [0,000 V … 9,999 V]"), std::string::npos);
}

TEST(CliDictionary, UsageErrors)
{
    EXPECT_EQ(cli({"dictionary"}).code, vt::cli::kExitUsage);
    EXPECT_EQ(cli({"dictionary", "show"}).code, vt::cli::kExitUsage);
    EXPECT_EQ(cli({"dictionary", "show", "dma-pn-common"}).code, vt::cli::kExitUsage); // abstract
    const CliRun r = cli({"dictionary", "show", "nope"});
    EXPECT_EQ(r.code, vt::cli::kExitUsage);
    EXPECT_EQ(r.err, "valvetune-cli: unknown family 'nope' (see: valvetune-cli dictionary list)\n");
}
