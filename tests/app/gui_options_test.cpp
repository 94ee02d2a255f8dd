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

TEST(GuiOptions, SimulateAndOpenAreTakenAndCheckedForNonsense)
{
    auto r = parseGuiOptions({"valvetune", "--simulate", "dma-pn-v51:3", "--open", "/tmp/x.vtpar"});
    EXPECT_FALSE(r.exitNow);
    EXPECT_EQ(r.simulate, "dma-pn-v51:3");
    EXPECT_EQ(r.openFile, "/tmp/x.vtpar");
    for (const char *bad : {"no-such-family", "dma-pn-v51:0", "dma-pn-v51:x"}) {
        auto e = parseGuiOptions({"valvetune", "--simulate", bad});
        EXPECT_EQ(e.exitCode, 2) << bad;
        EXPECT_TRUE(e.error.startsWith("--simulate: ")) << bad;
    }
}
