// FaultSpec text form, as the CLI's --fault option will pass it XX: seeded fault injection).
#include "qt_printers.h"
#include "transports/fault_spec.h"

#include <gtest/gtest.h>

namespace {

using vt::link::FaultSpec;
using vt::link::parseFaultSpec;

TEST(FaultSpec, ParsesTheDocumentedExample)
{
    const auto spec = parseFaultSpec(u"drop=0.02,corrupt=0.005,delay=5,cut=120,seed=7");
    ASSERT_TRUE(spec) << spec.error().text().toStdString();
    EXPECT_DOUBLE_EQ(spec->tx.drop, 0.02);
    EXPECT_DOUBLE_EQ(spec->rx.drop, 0.02);
    EXPECT_DOUBLE_EQ(spec->tx.corrupt, 0.005);
    EXPECT_EQ(spec->rx.delayMs, 5);
    ASSERT_TRUE(spec->cutAfterFrames);
    EXPECT_EQ(*spec->cutAfterFrames, 120u);
    EXPECT_EQ(spec->seed, 7u);
}

TEST(FaultSpec, DirectionPrefixesAndWhitespace)
{
    const auto spec = parseFaultSpec(u" drop = 0.1 , rx.drop=0.5, TX.delay=20 ");
    ASSERT_TRUE(spec) << spec.error().text().toStdString();
    EXPECT_DOUBLE_EQ(spec->tx.drop, 0.1);
    EXPECT_DOUBLE_EQ(spec->rx.drop, 0.5);
    EXPECT_EQ(spec->tx.delayMs, 20);
    EXPECT_EQ(spec->rx.delayMs, 0);
    EXPECT_FALSE(spec->cutAfterFrames);
    EXPECT_EQ(spec->seed, FaultSpec::kDefaultSeed);
}

TEST(FaultSpec, BlankSpecInjectsNothing)
{
    for (const char16_t *blank : {u"", u"   "}) {
        const auto spec = parseFaultSpec(blank);
        ASSERT_TRUE(spec);
        EXPECT_TRUE(spec->isNull());
    }
}

TEST(FaultSpec, TextRoundTrips)
{
    for (const char16_t *text :
         {u"drop=0.02,corrupt=0.005,delay=5,cut=120,seed=7",
          u"tx.drop=0.25,rx.corrupt=0.125,rx.delay=3,seed=4294967295", u"seed=1"}) {
        const auto spec = parseFaultSpec(text);
        ASSERT_TRUE(spec) << spec.error().text().toStdString();
        const auto again = parseFaultSpec(spec->toString());
        ASSERT_TRUE(again) << spec->toString().toStdString();
        EXPECT_EQ(*again, *spec) << spec->toString().toStdString();
    }
    EXPECT_EQ(parseFaultSpec(u"drop=0.02,cut=120,seed=7")->toString(),
              QStringLiteral("drop=0.02,cut=120,seed=7"));
}

TEST(FaultSpec, BadSpecsSayWhichItemAndWhy)
{
    struct Case
    {
        const char16_t *text;
        const char *item;
        const char *why;
    };
    const Case cases[] = {
        {u"drop=2", "drop=2", "between 0 and 1"},
        {u"drop=-0.1", "drop=-0.1", "between 0 and 1"},
        {u"corrupt=abc", "corrupt=abc", "between 0 and 1"},
        {u"drop=nan", "drop=nan", "between 0 and 1"},
        {u"delay=-1", "delay=-1", "milliseconds"},
        {u"delay=1.5", "delay=1.5", "milliseconds"},
        {u"cut=many", "cut=many", "whole number"},
        {u"seed=-3", "seed=-3", "whole number"},
        {u"jitter=5", "jitter=5", "unknown key"},
        {u"drop", "drop", "key=value"},
        {u"drop=0.1,drop=0.2", "drop=0.2", "twice"},
        {u"tx.cut=5", "tx.cut=5", "both directions"},
        {u"drop=0.1,,seed=2", "", "empty item"},
    };
    for (const Case &c : cases) {
        const auto spec = parseFaultSpec(c.text);
        ASSERT_FALSE(spec) << QString::fromUtf16(c.text).toStdString();
        EXPECT_EQ(spec.error().item, QString::fromUtf8(c.item));
        const QString text = spec.error().text();
        EXPECT_TRUE(text.contains(QString::fromUtf8(c.why))) << text.toStdString();
        if (*c.item) {
            EXPECT_TRUE(text.contains(QString::fromUtf8(c.item))) << text.toStdString();
        }
    }
}

} // namespace
