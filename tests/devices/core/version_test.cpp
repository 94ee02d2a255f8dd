// majorVersion: the part of a version text that dictionaries list ("34" of "34.03").
#include "core/version.h"

#include <gtest/gtest.h>

using namespace vt::dev;

TEST(MajorVersion, LeadingDigits)
{
    EXPECT_EQ(majorVersion("34.03"), "34");
    EXPECT_EQ(majorVersion("32.10"), "32");
    EXPECT_EQ(majorVersion("22"), "22");
    EXPECT_EQ(majorVersion("5"), "5");
}

TEST(MajorVersion, NoneWithoutLeadingDigit)
{
    EXPECT_EQ(majorVersion(""), "");
    EXPECT_EQ(majorVersion("SD7 device type 58352"), "");
    EXPECT_EQ(majorVersion(".5"), "");
    EXPECT_EQ(majorVersion("V34"), "");
}

TEST(MajorVersion, AsNumber)
{
    EXPECT_EQ(majorVersionNumber("34.03"), 34);
    EXPECT_EQ(majorVersionNumber("51"), 51);
    EXPECT_EQ(majorVersionNumber(""), 0);
    EXPECT_EQ(majorVersionNumber("SD7 device type 58352"), 0);
    EXPECT_EQ(majorVersionNumber("99999999999999999999.1"), 0); // does not fit an int
}
