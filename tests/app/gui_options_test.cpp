#include "app/gui/gui_options.h"

#include <gtest/gtest.h>

using vt::app::parseGuiOptions;

TEST(GuiOptions, LanguageIsValidated)
{
    auto ok = parseGuiOptions({"valvetune", "--lang", "de"});
    EXPECT_FALSE(ok.exitNow);
    EXPECT_EQ(ok.language, "de");

    auto bad = parseGuiOptions({"valvetune", "--lang", "fr"});
    EXPECT_TRUE(bad.exitNow);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_TRUE(bad.error.contains("en or de"));
}

TEST(GuiOptions, UnknownOptionsAndArgumentsAreUsageErrors)
{
    EXPECT_EQ(parseGuiOptions({"valvetune", "--frobnicate"}).exitCode, 2);
    EXPECT_EQ(parseGuiOptions({"valvetune", "stray"}).exitCode, 2);
    EXPECT_EQ(parseGuiOptions({"valvetune", "--lang"}).exitCode, 2); // missing value
}

TEST(GuiOptions, HelpAndVersionExitWithoutAWindow)
{
    EXPECT_TRUE(parseGuiOptions({"valvetune", "--help"}).exitNow);
    EXPECT_TRUE(parseGuiOptions({"valvetune", "--version"}).exitNow);
    EXPECT_FALSE(parseGuiOptions({"valvetune"}).exitNow);
}

TEST(GuiOptions, FeaturesNotBuiltYetAreRefusedClearly)
{
    for (const char *opt : {"--simulate", "--open"}) {
        auto r = parseGuiOptions({"valvetune", opt, "x"});
        EXPECT_EQ(r.exitCode, 2) << opt;
        EXPECT_TRUE(r.error.contains("not available in this version yet")) << opt;
    }
}
