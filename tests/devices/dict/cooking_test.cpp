// Cooking against the manuals' own numbers: "1000 == 1.000 V" (OPAT manual §7, C1.07), the
// German notation (DMA Profibus Anleitung: "1000 == 1,000 V"), and the DSP-408 truncation
// example (ED1/SD1 manual §4.7: 60 mA / 1.78 = 33.7 -> 33, read back 58.74 mA).
#include "dict/cooking.h"
#include "dict/dictionary_loader.h"

#include <gtest/gtest.h>

using namespace vt::dev;

namespace {

const ParamMeta &param(const std::string &family, const std::string &name)
{
    const ParamMeta *p = builtinDictionaries()->find(family)->find(name);
    if (!p)
        throw std::runtime_error(family + " " + name + " missing");
    return *p;
}

} // namespace

TEST(Cooking, HcsVoltsInBothLanguages)
{
    const ParamMeta &c107 = param("opat", "C1.07");
    EXPECT_EQ(formatValue(c107, 1000, Language::English), "1.000 V");
    EXPECT_EQ(formatValue(c107, 1000, Language::German), "1,000 V");
    EXPECT_EQ(*parseValue(c107, "1,5", Language::German), 1500);
    EXPECT_EQ(*parseValue(c107, " 1.5 V ", Language::English), 1500);
    EXPECT_EQ(*parseValue(c107, "1,000 v", Language::German), 1000); // unit in any case
    EXPECT_EQ(*parseValue(c107, "9.999", Language::English), 9999);
}

TEST(Cooking, TheOtherDecimalSignIsRefusedNotGuessed)
{
    const ParamMeta &c107 = param("opat", "C1.07");
    auto r = parseValue(c107, "1.5", Language::German);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().kind, CookError::Kind::WrongDecimalSign);
    EXPECT_EQ(r.error().message.de, "Dezimalzeichen ist ','");
    EXPECT_FALSE(parseValue(c107, "1,5", Language::English).ok());
    EXPECT_EQ(parseValue(c107, "abc", Language::English).error().kind, CookError::Kind::NotANumber);
    EXPECT_EQ(parseValue(c107, "  ", Language::English).error().kind, CookError::Kind::Empty);
}

TEST(Cooking, OutOfRangeNamesTheLimitsInDisplayUnits)
{
    const ParamMeta &c107 = param("opat", "C1.07");
    auto r = parseValue(c107, "12", Language::English);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().kind, CookError::Kind::AboveMax);
    EXPECT_EQ(r.error().message.en, "C1.07: above the maximum 9.999 V (range 0.000 V … 9.999 V)");
    auto de = parseValue(c107, "-1", Language::German);
    EXPECT_EQ(de.error().message.de,
              "C1.07: unter dem Minimum 0,000 V (Bereich 0,000 V … 9,999 V)");
}

TEST(Cooking, EnumLabelsInEitherLanguage)
{
    const ParamMeta &mode = param("wandfluh-ed1", "db_DeviceMode");
    EXPECT_EQ(formatValue(mode, 1, Language::English), "Preset value via bus");
    EXPECT_EQ(formatValue(mode, 2, Language::German), "Sollwertvorgabe lokal");
    EXPECT_EQ(*parseValue(mode, "sollwertvorgabe lokal", Language::English), 2);
    EXPECT_EQ(*parseValue(mode, "1", Language::German), 1);
    EXPECT_EQ(parseValue(mode, "maybe", Language::English).error().kind,
              CookError::Kind::UnknownLabel);
}

TEST(Cooking, Dsp408ScalingTruncatesAsTheManualShows)
{
    const ParamMeta &aside = param("wandfluh-ed1", "dop_drivePos_AsideVal");
    ASSERT_EQ(aside.scale.rounding, Rounding::Truncate);
    EXPECT_EQ(*parseValue(aside, "60", Language::English), 33);       // 60 / 1.78 = 33.7 -> 33
    EXPECT_EQ(formatValue(aside, 33, Language::English), "58.74 mA"); // what the card holds
    EXPECT_EQ(*parseValue(aside, "58.74 mA", Language::English), 33); // and back
    EXPECT_EQ(*parseValue(aside, "58,74", Language::German), 33);
}

TEST(Cooking, WritesNeedAWritableRowInRange)
{
    const ParamMeta &d111 = param("opat", "d1.11");
    ASSERT_TRUE(checkWrite(d111, 0).has_value());
    EXPECT_EQ(checkWrite(d111, 0)->kind, CookError::Kind::NotWritable);
    EXPECT_FALSE(checkRange(d111, 0).has_value());
    const ParamMeta &c107 = param("opat", "C1.07");
    EXPECT_FALSE(checkWrite(c107, 1000).has_value());
    EXPECT_EQ(checkWrite(c107, 10000)->kind, CookError::Kind::AboveMax);
    EXPECT_EQ(checkWrite(c107, 500, Limits{0, 400})->kind,
              CookError::Kind::AboveMax); // narrowed limits
}

TEST(Cooking, BitFieldsListTheirSetBits)
{
    const ParamMeta &b0 = param("opat", "0xB0");
    EXPECT_EQ(formatBits(b0, (1u << 10) | (1u << 11), Language::English), "Enable active, Error");
    EXPECT_EQ(formatBits(b0, (1u << 10) | (1u << 9), Language::German), "Bit 9, Freigabe aktiv");
    EXPECT_EQ(formatBits(b0, 0, Language::English), "");
}
