// The one number parser and formatter of the GUI (model/number_text.h): exact in the UI language
// or refused with a sentence that names the notation — never truncated, rounded or read another
// way (ARCHITECTURE.md, trust rules: numbers).
#include "model/number_text.h"

#include <gtest/gtest.h>

namespace vt::model {
namespace {

using dev::Language;

NumberRules volts()
{
    NumberRules r;
    r.decimals = 3;
    r.minimum = -10;
    r.maximum = 10;
    r.unit = QStringLiteral("V");
    return r;
}

TEST(NumberText, TheLanguagesOwnNotationIsExact)
{
    EXPECT_EQ(parseNumber("1,5", Language::German, volts()).value, 1.5);
    EXPECT_EQ(parseNumber("1.5", Language::English, volts()).value, 1.5);
    EXPECT_EQ(parseNumber(" -2,25 V ", Language::German, volts()).value, -2.25);
    EXPECT_EQ(parseNumber("+3", Language::English, volts()).value, 3.0);
    EXPECT_EQ(parseNumber("1,500000", Language::German, volts()).value, 1.5); // zeros lose nothing
}

TEST(NumberText, EverythingElseIsRefusedWithTheNotationNamed)
{
    for (Language lang : {Language::English, Language::German}) {
        const QString own = lang == Language::German ? "1,5" : "1.5";
        const QString other = lang == Language::German ? "1.5" : "1,5";
        for (const QString &text :
             {other, QString("1.500,25"), QString("1,500.25"), QString("1e3"), QString("abc"),
              QString(""), QString("1,"), QString(",5"), QString("0x10"), QString("1 5")}) {
            const NumberParse p = parseNumber(text, lang, volts());
            EXPECT_FALSE(p.ok()) << text.toStdString() << " became " << p.value.value_or(0);
            EXPECT_FALSE(p.refusal.isEmpty()) << text.toStdString();
            if (!text.isEmpty()) {
                EXPECT_TRUE(p.refusal.contains(text)) << p.refusal.toStdString();
            }
            // The example shows the notation: "1,50" in German, "1.50" in English.
            EXPECT_TRUE(p.refusal.contains(own)) << p.refusal.toStdString();
        }
    }
}

TEST(NumberText, MoreDigitsThanTheFieldKeepsAreRefusedNotRounded)
{
    const NumberParse p = parseNumber("1.2345", Language::English, volts());
    EXPECT_FALSE(p.ok());
    EXPECT_TRUE(p.refusal.contains("3")) << p.refusal.toStdString();
    NumberRules whole;
    EXPECT_FALSE(parseNumber("1.5", Language::English, whole).ok());
    EXPECT_FALSE(parseNumber("1,5", Language::German, whole).ok());
    EXPECT_EQ(parseNumber("15", Language::German, whole).value, 15.0);
    EXPECT_EQ(parseNumber("15,0", Language::German, whole).value, 15.0);
}

TEST(NumberText, OutOfRangeNamesTheRangeInTheLanguage)
{
    const NumberParse de = parseNumber("10,5", Language::German, volts());
    EXPECT_FALSE(de.ok());
    EXPECT_TRUE(de.refusal.contains("-10,000 V")) << de.refusal.toStdString();
    EXPECT_TRUE(de.refusal.contains("10,000 V")) << de.refusal.toStdString();
    const NumberParse en = parseNumber("-10.001", Language::English, volts());
    EXPECT_FALSE(en.ok());
    EXPECT_TRUE(en.refusal.contains("-10.000 V")) << en.refusal.toStdString();
}

TEST(NumberText, FormatReadsBack)
{
    EXPECT_EQ(formatNumber(1.5, 3, Language::German), "1,500");
    EXPECT_EQ(formatNumber(1500.25, 2, Language::English), "1500.25"); // no thousands separator
    EXPECT_EQ(formatNumber(-0.0001, 2, Language::German), "0,00");
    for (Language lang : {Language::English, Language::German})
        for (double v : {0.0, 1.5, -9.999, 1234.5})
            EXPECT_EQ(
                parseNumber(formatNumber(v, 3, lang), lang, NumberRules{3, -1e6, 1e6, {}}).value,
                v);
}

} // namespace
} // namespace vt::model
