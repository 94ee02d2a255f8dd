// PLC configuration of a fold: telegram lengths, byte maps and GSD choice equal
// the manuals — OPAT manual §3.1 (master + 0..7 slaves: 8..43 bytes out, 9 in), DMA Profinet
// manual §4.1 / DMA Profibus Anleitung §4.1 (1..5 modules: 8/13/18/23/28 out, 9 in).
#include "hcs/cmd15.h"
#include "model/fold/plc_config.h"

#include <QString>
#include <gtest/gtest.h>

using namespace vt::model;
using vt::dev::Language;
namespace hcs = vt::dev::hcs;

namespace {

PlcConfig config(FoldNode node, std::size_t modules, const std::string &product = {})
{
    FoldPlan plan = defaultFoldPlan(node, modules);
    plan.productNumber = product;
    auto c = buildPlcConfig(plan);
    EXPECT_TRUE(c.ok()) << (c.ok() ? "" : plcText(c.error(), Language::English).toStdString());
    return c.ok() ? *c : PlcConfig{};
}

} // namespace

TEST(FoldPlanLayout, DmaLengthsFollowTheManualTable)
{
    // DMA Profinet manual §4.1 "Overall telegram length in bytes": 8 13 18 23 28.
    const int expected[] = {8, 13, 18, 23, 28};
    for (FoldNode node : {FoldNode::DmaProfibus, FoldNode::DmaProfinet}) {
        for (std::size_t n = 1; n <= 5; ++n) {
            const PlcConfig c = config(node, n);
            EXPECT_EQ(c.outputBytes, expected[n - 1]) << n;
            EXPECT_EQ(c.inputBytes, 9) << n;
            EXPECT_EQ(c.snum, static_cast<int>(n)); // DMA: SNUM = number of modules
            EXPECT_EQ(c.output.size(), static_cast<std::size_t>(expected[n - 1]));
            EXPECT_EQ(c.input.size(), 9u);
            EXPECT_EQ(c.exampleRequestBytes.size(), static_cast<std::size_t>(expected[n - 1]));
            EXPECT_GE(c.moduleOutputBytes, c.outputBytes); // else exception 9
            EXPECT_GE(c.moduleInputBytes, c.inputBytes);
        }
    }
}

TEST(FoldPlanLayout, OpatMasterPlusSlavesLengths)
{
    // OPAT manual §3.1: SNUM 0..7 slaves, lengths 8 13 18 23 28 33 38 43.
    for (std::size_t slaves = 0; slaves <= 7; ++slaves) {
        const PlcConfig c = config(FoldNode::Opat, slaves + 1);
        EXPECT_EQ(c.outputBytes, static_cast<int>(8 + 5 * slaves));
        EXPECT_EQ(c.inputBytes, 9);
        EXPECT_EQ(c.snum, static_cast<int>(slaves)); // the master is always included
        EXPECT_EQ(c.sections.front().sadr, 0);
        EXPECT_EQ(c.sections.back().sadr, static_cast<int>(slaves));
        EXPECT_EQ(c.gsdFile, "HCS0D68.GSD");
    }
    EXPECT_EQ(config(FoldNode::Opat, 1).gsdModule, "CMD15 1M IN/OUT 9/8");
    // OPAT manual §4.1: "with 4 slaves (modules) and 1 master … Chose … CMD15 1M 4S IN/OUT 9/28".
    EXPECT_EQ(config(FoldNode::Opat, 5).gsdModule, "CMD15 1M 4S IN/OUT 9/28");
    EXPECT_EQ(config(FoldNode::Opat, 8).gsdModule, "CMD15 1M 7S IN/OUT 9/43");
}

TEST(FoldPlanLayout, OutputMapByteByByte)
{
    // DMA Profinet manual §4.1 table: DAT3.1 at 13, DAT3.2H 14, DAT3.2L 15, DAT3.3H 16, DAT3.3L 17.
    const PlcConfig c = config(FoldNode::DmaProfibus, 3);
    ASSERT_EQ(c.output.size(), 18u);
    const char *fields[] = {"TADR",    "SNUM",    "CMD",     "DAT1.1",  "DAT1.2H", "DAT1.2L",
                            "DAT1.3H", "DAT1.3L", "DAT2.1",  "DAT2.2H", "DAT2.2L", "DAT2.3H",
                            "DAT2.3L", "DAT3.1",  "DAT3.2H", "DAT3.2L", "DAT3.3H", "DAT3.3L"};
    for (std::size_t i = 0; i < 18; ++i) {
        EXPECT_EQ(c.output[i].offset, static_cast<int>(i));
        EXPECT_EQ(c.output[i].field, fields[i]) << i;
        EXPECT_EQ(c.output[i].module, i < 3 ? -1 : static_cast<int>((i - 3) / 5)) << i;
    }
    // V15 mode 1 (DMA Profibus Anleitung §4.5.2): VALUE1 = A1.01, VALUE2 = A2.01.
    const auto english = [](const PlcText &t) { return plcText(t, Language::English); };
    EXPECT_TRUE(english(c.output[4].text).contains("VALUE1 high byte: A1.01"))
        << english(c.output[4].text).toStdString();
    EXPECT_TRUE(english(c.output[7].text).contains("VALUE2 low byte: A2.01"))
        << english(c.output[7].text).toStdString();
    EXPECT_FALSE(plcText(c.output[4].text, Language::German).isEmpty());
    // OPAT numbers its blocks by SADR from 0 (OPAT manual §3.1: DAT0.1 at byte 3, DAT7.3L at 42).
    const PlcConfig o = config(FoldNode::Opat, 8);
    EXPECT_EQ(o.output[3].field, "DAT0.1");
    EXPECT_EQ(o.output[42].field, "DAT7.3L");
    // Response (OPAT manual §3.2): TADR SADR CMD DAT.1H DAT.1L DAT.2H DAT.2L DAT.3H DAT.3L.
    const char *in[] = {"TADR",   "SADR",   "CMD",    "DAT.1H", "DAT.1L",
                        "DAT.2H", "DAT.2L", "DAT.3H", "DAT.3L"};
    for (std::size_t i = 0; i < 9; ++i)
        EXPECT_EQ(o.input[i].field, in[i]);
}

TEST(FoldPlanLayout, ExampleTelegramIsTheCodecsAndDecodesBack)
{
    const PlcConfig c = config(FoldNode::DmaProfinet, 2);
    const auto decoded = hcs::decodeCyclicRequest(c.exampleRequestBytes, {hcs::Family::Dma});
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(*decoded, c.exampleRequest);
    // TADR 01, SNUM 02, CMD 0F, then 00 03E8 0000 per module (1.000 V on VALUE1).
    const vt::dev::Bytes expected{0x01, 0x02, 0x0F, 0x00, 0x03, 0xE8, 0x00,
                                  0x00, 0x00, 0x03, 0xE8, 0x00, 0x00};
    EXPECT_EQ(c.exampleRequestBytes, expected);
}

TEST(FoldPlanLayout, GsdChoiceFollowsNodeAndProductNumber)
{
    // DMA Profibus Anleitung §5.1: "CMD15 3fold 9B-I 18B-O (kons)".
    EXPECT_EQ(config(FoldNode::DmaProfibus, 3).gsdModule, "CMD15 3fold 9B-I 18B-O (kons)");
    EXPECT_EQ(config(FoldNode::DmaProfibus, 5).gsdModule, "CMD15 5fold 9B-I 28B-O (kons)");
    EXPECT_EQ(config(FoldNode::DmaProfibus, 3).gsdFile, "HCS0220.GSD");
    // §6.1.1: last digit 1..4 → hcs0220.gsd, "5 005 xxx x5" → hcs0ea7.gsd.
    EXPECT_TRUE(chooseGsd(FoldNode::DmaProfibus, 3, "5 004 123 12").productNumberDecided);
    EXPECT_FALSE(chooseGsd(FoldNode::DmaProfibus, 3, "").productNumberDecided);
    const PlcConfig ea7 = config(FoldNode::DmaProfibus, 2, "5 005 123 15");
    EXPECT_EQ(ea7.gsdFile, "hcs0ea7.gsd");
    EXPECT_EQ(ea7.moduleOutputBytes, 28);
    EXPECT_EQ(ea7.outputBytes, 13);
    // DMA Profinet manual §4.5.4: one 42-byte IN/OUT module for every fold.
    const PlcConfig pn = config(FoldNode::DmaProfinet, 4);
    EXPECT_EQ(pn.gsdFile.rfind("GSDML-V2.2-HCS-DMA", 0), 0u);
    EXPECT_EQ(pn.moduleOutputBytes, 42);
    EXPECT_EQ(pn.outputBytes, 23);
}

TEST(FoldPlanLayout, ImpossiblePlansSayWhy)
{
    auto six = buildPlcConfig(defaultFoldPlan(FoldNode::DmaProfibus, 6));
    ASSERT_FALSE(six.ok());
    const QString sixWhy = plcText(six.error(), Language::English);
    EXPECT_TRUE(sixWhy.contains("E22 = 1 … 5")) << sixWhy.toStdString();
    EXPECT_TRUE(sixWhy.startsWith("6 DMA modules")) << sixWhy.toStdString();
    auto nine = buildPlcConfig(defaultFoldPlan(FoldNode::Opat, 9));
    ASSERT_FALSE(nine.ok());
    EXPECT_TRUE(plcText(nine.error(), Language::English).contains("7 CAN slaves"));
    EXPECT_FALSE(buildPlcConfig(defaultFoldPlan(FoldNode::DmaProfinet, 0)).ok());
}

TEST(FoldPlanLayout, BitsFollowEachModulesOwnMode)
{
    FoldPlan plan = defaultFoldPlan(FoldNode::DmaProfibus, 2);
    plan.modules[1].version = 32;
    plan.modules[1].mode = 3;
    const auto c = buildPlcConfig(plan);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c->sections[0].profile, hcs::Profile::DmaV15Mode1);
    EXPECT_EQ(c->sections[1].profile, hcs::Profile::DmaV32Mode34);
    // Open loop V15 uses only BUS_DISABLE; closed loop V32 adds Din_1 (0x01).
    EXPECT_FALSE(c->sections[0].controlBits[0].used);
    EXPECT_TRUE(c->sections[1].controlBits[0].used);
    EXPECT_TRUE(c->sections[0].controlBits[7].used);
    // Per-module meanings differ: V32 mode 3/4 VALUE1 out = A1.01 branch 1, VALUE2 = A1.02.
    EXPECT_TRUE(plcText(c->output[11].text, Language::English).contains("A1.02"));
}
