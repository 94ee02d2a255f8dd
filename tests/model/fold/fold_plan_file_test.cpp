// The fold plan file (.vtfold): round trip, versioning and typed errors for
// malformed files (STYLE.md rule 12: never crash on a bad file).
#include "model/fold/fold_plan_file.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace vt::model;

namespace {

FoldPlan samplePlan()
{
    FoldPlan plan = defaultFoldPlan(FoldNode::Opat, 3);
    plan.title = "Presse 4 – Zylinder";
    plan.notes = "line 1\nline \"2\"";
    plan.plcSnum = 2;
    plan.modules[0].name = "Master";
    plan.modules[0].options.e24 = 126;
    plan.modules[0].options.e28 = 1;
    plan.modules[1].options.e26 = 6;
    plan.modules[2].mode = 8;
    return plan;
}

FoldFileErrc errc(std::string_view text)
{
    const auto r = parseFoldPlan(text);
    EXPECT_FALSE(r.ok()) << text;
    return r.ok() ? FoldFileErrc::Io : r.error().code;
}

} // namespace

TEST(FoldPlanFile, RoundTrip)
{
    const FoldPlan plan = samplePlan();
    const std::string text = writeFoldPlan(plan);
    EXPECT_NE(text.find("\"format\": \"valvetune-fold-plan\""), std::string::npos) << text;
    const auto back = parseFoldPlan(text);
    ASSERT_TRUE(back.ok()) << foldFileErrorText(back.error()).toStdString();
    EXPECT_EQ(*back, plan);
    EXPECT_EQ(writeFoldPlan(*back), text); // stable text: saving again changes nothing

    FoldPlan dma = defaultFoldPlan(FoldNode::DmaProfinet, 5);
    dma.productNumber = "5 004 000 01";
    const auto dmaBack = parseFoldPlan(writeFoldPlan(dma));
    ASSERT_TRUE(dmaBack.ok());
    EXPECT_EQ(*dmaBack, dma);
}

TEST(FoldPlanFile, SaveAndLoadFile)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::string path = dir.filePath("plan.vtfold").toStdString();
    EXPECT_FALSE(saveFoldPlanFile(samplePlan(), path).has_value());
    const auto loaded = loadFoldPlanFile(path);
    ASSERT_TRUE(loaded.ok());
    EXPECT_EQ(*loaded, samplePlan());

    const auto none = loadFoldPlanFile(dir.filePath("missing.vtfold").toStdString());
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().code, FoldFileErrc::Io);
    const auto unwritable =
        saveFoldPlanFile(samplePlan(), dir.filePath("no/such/dir/plan.vtfold").toStdString());
    ASSERT_TRUE(unwritable.has_value());
    EXPECT_EQ(unwritable->code, FoldFileErrc::Io);
}

TEST(FoldPlanFile, MalformedFilesGiveTypedErrors)
{
    EXPECT_EQ(errc(""), FoldFileErrc::NotJson);
    EXPECT_EQ(errc("{\"format\": "), FoldFileErrc::NotJson);
    EXPECT_EQ(errc("[1, 2]"), FoldFileErrc::WrongFormat);
    EXPECT_EQ(errc("{\"format\": \"something-else\", \"formatVersion\": 1}"),
              FoldFileErrc::WrongFormat);
    EXPECT_EQ(errc(std::string(300, '[') + std::string(300, ']')), FoldFileErrc::WrongFormat);
    EXPECT_EQ(errc(std::string(kFoldPlanMaxBytes + 1, ' ')), FoldFileErrc::TooLarge);
    const std::string head = "{\"format\": \"valvetune-fold-plan\", ";
    // Found by fuzz_fold_plan: a number beyond double made the JSON library throw out_of_range.
    EXPECT_EQ(errc(head + "\"formatVersion\": 1E999999}"), FoldFileErrc::NotJson);
    EXPECT_EQ(errc(head + "\"formatVersion\": 2, \"node\": \"opat\", \"modules\": []}"),
              FoldFileErrc::NewerVersion);
    EXPECT_EQ(errc(head + "\"node\": \"opat\", \"modules\": []}"), FoldFileErrc::MissingMember);
    EXPECT_EQ(errc(head + "\"formatVersion\": 1, \"modules\": []}"), FoldFileErrc::MissingMember);
    EXPECT_EQ(errc(head + "\"formatVersion\": 1, \"node\": \"canopen\", \"modules\": []}"),
              FoldFileErrc::BadMember);
    EXPECT_EQ(errc(head + "\"formatVersion\": 1, \"node\": \"opat\"}"),
              FoldFileErrc::MissingMember);
    EXPECT_EQ(errc(head + "\"formatVersion\": 1, \"node\": \"opat\", \"modules\": {}}"),
              FoldFileErrc::BadMember);
    EXPECT_EQ(
        errc(head + "\"formatVersion\": 1, \"node\": \"opat\", \"modules\": [{\"version\": 34}]}"),
        FoldFileErrc::MissingMember);

    const auto r =
        parseFoldPlan(head + "\"formatVersion\": 1, \"node\": \"opat\", \"modules\": "
                             "[{\"address\": 0}, {\"address\": 1, \"options\": {\"E26\": 1e3}}]}");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, FoldFileErrc::BadMember);
    EXPECT_EQ(r.error().member, "modules[1].options.E26");
    EXPECT_EQ(r.error().problem, FoldFileProblem::NotWholeNumber);
    EXPECT_EQ(foldFileErrorText(r.error()),
              "The fold plan file is damaged: modules[1].options.E26 is not a whole number.");

    std::string many = head + "\"formatVersion\": 1, \"node\": \"dma-pb\", \"modules\": [";
    for (int i = 0; i < 33; ++i)
        many += std::string(i ? "," : "") + "{\"address\": 1}";
    EXPECT_EQ(errc(many + "]}"), FoldFileErrc::BadMember);
    EXPECT_EQ(errc(head + "\"formatVersion\": 1, \"node\": \"opat\", \"modules\": [{\"address\": "
                          "99999999999999999999}]}"),
              FoldFileErrc::BadMember);
    EXPECT_EQ(errc(head + "\"formatVersion\": 1, \"node\": \"opat\", \"title\": \"" +
                   std::string(5000, 'x') + "\", \"modules\": []}"),
              FoldFileErrc::BadMember);
}

TEST(FoldPlanFile, UnknownMembersOfTheSameVersionAreIgnored)
{
    const auto r = parseFoldPlan(
        "{\"format\": \"valvetune-fold-plan\", \"formatVersion\": 1, \"node\": \"dma-pn\", "
        "\"future\": {\"x\": 1}, \"modules\": [{\"address\": 1, \"colour\": \"red\"}]}");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->node, FoldNode::DmaProfinet);
    ASSERT_EQ(r->modules.size(), 1u);
    EXPECT_EQ(r->modules[0].address, 1);
    EXPECT_EQ(r->modules[0].version, 0);
}
