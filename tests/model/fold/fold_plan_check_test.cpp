// Checks of a fold plan: duplicate E22 / SADR, CMD 15 limits, SNUM mismatch,
// ranges against the dictionaries, mixed modes (DMA Profibus Anleitung §1.5, §6; DMA Profinet
// manual §1.5, §4.1, §5; OPAT manual §1.4, §3.1, §5.7).
#include "model/fold/fold_check.h"

#include <QString>
#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::model;

namespace {

// Keeps the findings of the last call alive, so callers may pass checkFoldPlan(...) directly.
const FoldFinding *find(std::vector<FoldFinding> all, FoldCheckCode code)
{
    static std::vector<FoldFinding> kept;
    kept = std::move(all);
    const auto it = std::find_if(kept.begin(), kept.end(),
                                 [code](const FoldFinding &f) { return f.code == code; });
    return it == kept.end() ? nullptr : &*it;
}

FoldPlan dmaPlan(std::size_t n)
{
    FoldPlan plan = defaultFoldPlan(FoldNode::DmaProfibus, n);
    plan.productNumber = "5 004 123 12";
    return plan;
}

} // namespace

TEST(FoldPlanCheck, DefaultPlansAreClean)
{
    for (std::size_t n = 1; n <= 5; ++n) {
        EXPECT_TRUE(checkFoldPlan(dmaPlan(n)).empty()) << n;
        EXPECT_TRUE(checkFoldPlan(defaultFoldPlan(FoldNode::DmaProfinet, n)).empty()) << n;
    }
    for (std::size_t n = 1; n <= 8; ++n)
        EXPECT_TRUE(checkFoldPlan(defaultFoldPlan(FoldNode::Opat, n)).empty()) << n;
}

TEST(FoldPlanCheck, DuplicateE22)
{
    FoldPlan plan = dmaPlan(3);
    plan.modules[2].address = 2;
    const auto findings = checkFoldPlan(plan);
    const FoldFinding *f = find(findings, FoldCheckCode::DuplicateAddress);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->severity, FoldSeverity::Error);
    EXPECT_EQ(f->parameter, "E22");
    EXPECT_EQ(f->module, 2);
    EXPECT_NE(foldFindingText(*f).toStdString().find("Modules 2, 3 share E22 = 2"),
              std::string::npos)
        << foldFindingText(*f).toStdString();
    EXPECT_FALSE(
        foldFindingText(*f).isEmpty()); // German: ModelTextsLanguage.FoldCheckFindingInGerman
    EXPECT_TRUE(hasErrors(findings));
}

TEST(FoldPlanCheck, DuplicateOpatSlaveSwitch)
{
    FoldPlan plan = defaultFoldPlan(FoldNode::Opat, 3);
    plan.modules[2].address = 1;
    const FoldFinding *f = find(checkFoldPlan(plan), FoldCheckCode::DuplicateAddress);
    ASSERT_NE(f, nullptr);
    EXPECT_NE(foldFindingText(*f).toStdString().find("exception 12"), std::string::npos);
}

TEST(FoldPlanCheck, SixDmaModulesExceedCmd15)
{
    const auto findings = checkFoldPlan(dmaPlan(6));
    const FoldFinding *f = find(findings, FoldCheckCode::Cmd15Limit);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->severity, FoldSeverity::Error);
    EXPECT_NE(foldFindingText(*f).toStdString().find("E22 = 1 … 5"), std::string::npos);
    // The sixth module's own address is beyond CMD 15 as well.
    const FoldFinding *a = find(findings, FoldCheckCode::AddressBeyondCmd15);
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->module, 5);
}

TEST(FoldPlanCheck, NineOpatModules)
{
    const FoldFinding *f =
        find(checkFoldPlan(defaultFoldPlan(FoldNode::Opat, 9)), FoldCheckCode::TooManyModules);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->severity, FoldSeverity::Error);
}

TEST(FoldPlanCheck, SnumMismatch)
{
    FoldPlan plan = dmaPlan(3);
    plan.plcSnum = 3;
    EXPECT_EQ(find(checkFoldPlan(plan), FoldCheckCode::SnumMismatch), nullptr);
    plan.plcSnum = 4; // more than installed: exception 8
    const FoldFinding *f = find(checkFoldPlan(plan), FoldCheckCode::SnumMismatch);
    ASSERT_NE(f, nullptr);
    EXPECT_NE(foldFindingText(*f).toStdString().find("exception 8"), std::string::npos)
        << foldFindingText(*f).toStdString();
    plan.plcSnum = 9; // outside 1..5: exception 7
    f = find(checkFoldPlan(plan), FoldCheckCode::SnumMismatch);
    ASSERT_NE(f, nullptr);
    EXPECT_NE(foldFindingText(*f).toStdString().find("exception 7"), std::string::npos)
        << foldFindingText(*f).toStdString();

    // OPAT: SNUM counts the slaves only (OPAT manual §3.1); master + 2 slaves → SNUM 2.
    FoldPlan opat = defaultFoldPlan(FoldNode::Opat, 3);
    opat.plcSnum = 2;
    EXPECT_EQ(find(checkFoldPlan(opat), FoldCheckCode::SnumMismatch), nullptr);
    opat.plcSnum = 3;
    EXPECT_NE(find(checkFoldPlan(opat), FoldCheckCode::SnumMismatch), nullptr);
}

TEST(FoldPlanCheck, AddressesMustCoverOneToN)
{
    FoldPlan plan = dmaPlan(3);
    plan.modules[2].address = 5; // 1, 2, 5: module 5 is outside SNUM = 3
    const FoldFinding *f = find(checkFoldPlan(plan), FoldCheckCode::AddressOrder);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->severity, FoldSeverity::Error);

    plan = dmaPlan(3);
    std::swap(plan.modules[0].address,
              plan.modules[2].address); // 3, 2, 1: works, not as recommended
    f = find(checkFoldPlan(plan), FoldCheckCode::AddressOrder);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->severity, FoldSeverity::Warning);

    FoldPlan opat = defaultFoldPlan(FoldNode::Opat, 2);
    opat.modules[0].address = 1; // the master must be SADR 0 (OPAT manual §1.4)
    EXPECT_NE(find(checkFoldPlan(opat), FoldCheckCode::AddressOrder), nullptr);

    plan = dmaPlan(1);
    plan.modules[0].address = 0; // E22 = 0: no bus function
    EXPECT_NE(find(checkFoldPlan(plan), FoldCheckCode::AddressOutOfRange), nullptr);
}

TEST(FoldPlanCheck, MixedModesNoteTheManual)
{
    FoldPlan plan = dmaPlan(2);
    plan.modules[1].version = 22;
    plan.modules[1].mode = 2;
    const FoldFinding *f = find(checkFoldPlan(plan), FoldCheckCode::MixedModes);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->severity, FoldSeverity::Warning);
    EXPECT_NE(foldFindingText(*f).toStdString().find("own mode"), std::string::npos);
}

TEST(FoldPlanCheck, VersionAndLayout)
{
    FoldPlan plan = dmaPlan(1);
    plan.modules[0].version = 51; // a Profinet version on a Profibus node
    EXPECT_NE(find(checkFoldPlan(plan), FoldCheckCode::UnknownVersion), nullptr);
    plan.modules[0].version = 15;
    plan.modules[0].mode = 3; // V15 is open loop, mode 1 only
    EXPECT_NE(find(checkFoldPlan(plan), FoldCheckCode::UnknownLayout), nullptr);
}

TEST(FoldPlanCheck, OptionRangesComeFromTheDictionaries)
{
    FoldPlan plan = defaultFoldPlan(FoldNode::Opat, 2);
    plan.modules[0].options.e24 = 127; // opat.json E24: 0..126
    plan.modules[0].options.e28 = 3;   // 0..2
    const auto findings = checkFoldPlan(plan);
    int outOfRange = 0;
    for (const FoldFinding &f : findings)
        outOfRange += f.code == FoldCheckCode::OptionOutOfRange;
    EXPECT_EQ(outOfRange, 2);

    plan.modules[0].options = {};
    plan.modules[1].options.e24 = 5; // E24 is the master's only
    EXPECT_NE(find(checkFoldPlan(plan), FoldCheckCode::OptionNotApplicable), nullptr);

    FoldPlan dma = dmaPlan(1);
    dma.modules[0].options.e17 = 3; // dma-pb E17: 0..2
    EXPECT_NE(find(checkFoldPlan(dma), FoldCheckCode::OptionOutOfRange), nullptr);
    dma.modules[0].options.e17 = 2;
    EXPECT_TRUE(checkFoldPlan(dma).empty());
}

TEST(FoldPlanCheck, OptionConsequencesAreExplained)
{
    FoldPlan plan = defaultFoldPlan(FoldNode::Opat, 2);
    plan.modules[0].options.e24 = 126;
    auto findings = checkFoldPlan(plan);
    const FoldFinding *f = find(findings, FoldCheckCode::OptionConsequence);
    ASSERT_NE(f, nullptr);
    EXPECT_NE(foldFindingText(*f).toStdString().find("before power-up"), std::string::npos);

    plan.modules[0].options = {};
    plan.modules[0].options.e26 = 4;
    plan.modules[1].options.e26 = 6; // different CAN baud rates
    findings = checkFoldPlan(plan);
    EXPECT_TRUE(std::any_of(findings.begin(), findings.end(), [](const FoldFinding &x) {
        return x.parameter == "E26" && x.severity == FoldSeverity::Error;
    }));
}

TEST(FoldPlanCheck, ProductNumberDecidesTheGsdFile)
{
    FoldPlan plan = dmaPlan(2);
    plan.productNumber.clear();
    const FoldFinding *f = find(checkFoldPlan(plan), FoldCheckCode::ProductNumber);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->severity, FoldSeverity::Info);
    plan.productNumber = "banana";
    f = find(checkFoldPlan(plan), FoldCheckCode::ProductNumber);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->severity, FoldSeverity::Warning);
}
