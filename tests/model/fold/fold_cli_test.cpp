// valvetune-cli fold plan: golden text and JSON, and the usage errors for
// impossible plans (six DMA modules for CMD 15, nine OPAT modules), exit codes from exit_codes.h.
#include "cli_run.h"

#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace {

using vt::test::cli;
using vt::test::CliRun;

std::string golden(const char *name)
{
    std::ifstream in(std::string(VT_FOLD_TEST_DIR) + "/" + name, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

TEST(FoldCli, GoldenText)
{
    const CliRun dma = cli({"fold", "plan", "--node", "dma-pb", "--modules", "3"});
    EXPECT_EQ(dma.code, 0) << dma.err;
    EXPECT_TRUE(dma.err.empty());
    EXPECT_EQ(dma.out, golden("fold_plan_cli_dma-pb_3.txt"));

    const CliRun opat = cli({"fold", "plan", "--node", "opat", "--modules", "2", "--lang", "de"});
    EXPECT_EQ(opat.code, 0) << opat.err;
    EXPECT_EQ(opat.out, golden("fold_plan_cli_opat_2_de.txt"));
}

TEST(FoldCli, JsonForEveryAllowedCount)
{
    struct Case
    {
        const char *node;
        int max;
        int firstSadr;
    };
    for (const Case &c : {Case{"opat", 8, 0}, Case{"dma-pb", 5, 1}, Case{"dma-pn", 5, 1}}) {
        for (int n = 1; n <= c.max; ++n) {
            const CliRun r =
                cli({"--json", "fold", "plan", "--node", c.node, "--modules", QString::number(n)});
            ASSERT_EQ(r.code, 0) << r.err;
            const auto j = nlohmann::json::parse(r.out);
            EXPECT_EQ(j["node"], c.node);
            EXPECT_EQ(j["modules"], n);
            EXPECT_EQ(j["output_bytes"], 3 + 5 * n); // 8..43 OPAT, 8..28 DMA
            EXPECT_EQ(j["input_bytes"], 9);
            ASSERT_EQ(j["map"].size(), static_cast<std::size_t>(n));
            EXPECT_EQ(j["map"][0]["sadr"], c.firstSadr);
            EXPECT_EQ(j["map"][static_cast<std::size_t>(n - 1)]["output_last"], 3 + 5 * n - 1);
            EXPECT_EQ(j["map"][0]["output"].size(), 5u);
            EXPECT_TRUE(j["gsd_file"].is_string());
            EXPECT_TRUE(j["gsd_module"].is_string());
        }
    }
    const CliRun r = cli({"fold", "plan", "--node", "opat", "--modules", "5", "--json"});
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["gsd_file"], "HCS0D68.GSD");
    EXPECT_EQ(j["gsd_module"], "CMD15 1M 4S IN/OUT 9/28");
    EXPECT_EQ(j["map"][1]["output"][0]["field"], "DAT1.1");
    EXPECT_EQ(j["map"][1]["output"][0]["byte"], 8);
}

TEST(FoldCli, ImpossiblePlansAreUsageErrorsThatSayWhy)
{
    const CliRun six = cli({"fold", "plan", "--node", "dma-pb", "--modules", "6"});
    EXPECT_EQ(six.code, vt::cli::kExitUsage);
    EXPECT_EQ(six.errLines(), 1);
    EXPECT_NE(six.err.find("CMD 15 reaches E22 = 1 … 5 only"), std::string::npos) << six.err;
    EXPECT_TRUE(six.out.empty());

    const CliRun nine = cli({"fold", "plan", "--node", "opat", "--modules", "9", "--json"});
    EXPECT_EQ(nine.code, vt::cli::kExitUsage);
    EXPECT_NE(nine.err.find("at most 7 CAN slaves"), std::string::npos) << nine.err;
    EXPECT_TRUE(nine.out.empty());

    for (const QStringList &args :
         {QStringList{"fold"}, QStringList{"fold", "frobnicate"},
          QStringList{"fold", "plan", "--modules", "2"},
          QStringList{"fold", "plan", "--node", "canopen", "--modules", "2"},
          QStringList{"fold", "plan", "--node", "opat"},
          QStringList{"fold", "plan", "--node", "opat", "--modules", "0"},
          QStringList{"fold", "plan", "--node", "opat", "--modules", "x"},
          QStringList{"fold", "plan", "--node", "opat", "--modules", "2", "--lang", "fr"},
          QStringList{"fold", "plan", "--node", "opat", "--modules", "2", "extra"},
          QStringList{"fold", "plan", "--node", "opat", "--modules"}}) {
        const CliRun r = cli(args);
        EXPECT_EQ(r.code, vt::cli::kExitUsage) << args.join(' ').toStdString();
        EXPECT_EQ(r.errLines(), 1) << r.err;
        EXPECT_EQ(r.err.rfind("valvetune-cli: ", 0), 0u) << r.err;
    }
    const CliRun help = cli({"fold", "--help"});
    EXPECT_EQ(help.code, 0);
    EXPECT_NE(help.out.find("--node opat|dma-pb|dma-pn"), std::string::npos);
}

TEST(FoldCli, ListedInHelp)
{
    const CliRun help = cli({"--help"});
    EXPECT_NE(help.out.find("  fold "), std::string::npos);
}
