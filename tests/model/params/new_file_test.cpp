// newParamFile: a new file holds the chosen
// modules with the dictionary's factory defaults, only for rows of that version and mode, and
// survives the .vtpar codec unchanged.
#include "dict/dictionary_loader.h"
#include "model/params/new_file.h"

#include <gtest/gtest.h>

namespace vt::test {
namespace {

const dev::Dictionary &dict(const std::string &family)
{
    return *dev::builtinDictionaries()->find(family);
}

TEST(NewFile, HoldsTheDictionaryDefaultsOfVersionAndMode)
{
    model::NewFileChoice choice;
    choice.dictionary = &dict("dma-pn-v51");
    choice.version = "51";
    choice.mode = "3";
    choice.modeRaw = 3;
    choice.modules = 2;
    ASSERT_TRUE(choice.valid());

    const auto created =
        std::chrono::system_clock::time_point{} + std::chrono::hours(24 * 365 * 55);
    const dev::files::ParamFile file = model::newParamFile(choice, "ValveTune test", created);
    EXPECT_EQ(file.tool, "ValveTune test");
    EXPECT_EQ(file.created, dev::files::isoUtc(created));
    ASSERT_EQ(file.modules.size(), 2u);
    EXPECT_EQ(file.modules[0].address, 1);
    EXPECT_EQ(file.modules[1].address, 2);
    for (const dev::files::ModuleRecord &module : file.modules) {
        EXPECT_EQ(module.family, "dma-pn-v51");
        EXPECT_EQ(module.version, "51");
        EXPECT_EQ(module.mode, "3");
        ASSERT_FALSE(module.values.empty());
        for (const dev::files::ValueRow &row : module.values) {
            const dev::ParamMeta *meta = choice.dictionary->find(row.name);
            ASSERT_NE(meta, nullptr) << row.name;
            EXPECT_TRUE(meta->writable()) << row.name;
            ASSERT_TRUE(meta->defaultValue) << row.name;
            EXPECT_EQ(dev::rawNumber(row.raw), *meta->defaultValue) << row.name;
            EXPECT_TRUE(meta->appliesTo("51", "3")) << row.name;
        }
    }
    // Every writable default of the mode is there.
    std::size_t expected = 0;
    for (const dev::ParamMeta &meta : choice.dictionary->params)
        expected += meta.writable() && meta.defaultValue && meta.appliesTo("51", "3") ? 1u : 0u;
    EXPECT_EQ(file.modules[0].values.size(), expected);

    const auto parsed = dev::files::parseParamFile(dev::files::writeParamFile(file));
    ASSERT_TRUE(parsed.ok());
    EXPECT_EQ(*parsed, file);
}

TEST(NewFile, ModeDecidesTheRows)
{
    // Rows limited to some modes appear only in files of those modes.
    const dev::Dictionary &opat = dict("opat");
    std::size_t differing = 0;
    for (const dev::ParamMeta &meta : opat.params)
        differing += meta.writable() && meta.defaultValue && !meta.modes.empty() ? 1u : 0u;
    ASSERT_GT(differing, 0u) << "no mode-specific rows with defaults to tell modes apart";

    model::NewFileChoice three{&opat, "34", "3", 3, 1};
    model::NewFileChoice eight{&opat, "34", "8", 8, 1};
    const auto a = model::newParamFile(three, "t", {});
    const auto b = model::newParamFile(eight, "t", {});
    ASSERT_EQ(a.modules.size(), 1u);
    ASSERT_EQ(b.modules.size(), 1u);
    EXPECT_NE(a.modules[0].values, b.modules[0].values);
}

TEST(NewFile, InvalidChoicesMakeNoModules)
{
    model::NewFileChoice none;
    EXPECT_FALSE(none.valid());
    EXPECT_TRUE(model::newParamFile(none, "t", {}).modules.empty());

    model::NewFileChoice badMode{&dict("dma-pn-v51"), "51", "8", 8, 1};
    EXPECT_FALSE(badMode.valid());
    model::NewFileChoice tooMany{&dict("dma-pn-v51"), "51", "3", 3, 6};
    EXPECT_FALSE(tooMany.valid());
    model::NewFileChoice slaveNode{&dict("opat"), "31", "3", 3, 2};
    EXPECT_FALSE(slaveNode.valid());
}

} // namespace
} // namespace vt::test
