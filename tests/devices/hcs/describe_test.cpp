// hcs::describe(): the worked examples' fields named as the manuals name them, in both languages,
// with the CMD 15 meaning that belongs to the software version and mode.
#include "hcs/describe.h"
#include "worked_examples.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hcs;
using namespace vt::test::hcs_examples;

namespace {

bool contains(const std::string &text, const std::string &part)
{
    return text.find(part) != std::string::npos;
}

DescribeOptions opts(Family family, Direction direction)
{
    DescribeOptions o;
    o.family = family;
    o.direction = direction;
    return o;
}

} // namespace

TEST(HcsDescribe, OpatSec2_7_WriteC107NamesEveryField)
{
    DescribeOptions o = opts(Family::Opat, Direction::Request);
    o.parameters.name = [](std::uint16_t id) -> std::optional<LocalText> {
        if (id == 0x0030)
            return LocalText{"C1.07 dead band compensation A", "C1.07 Totbereichkompensation A"};
        return std::nullopt;
    };
    o.parameters.cook = [](std::uint16_t, std::uint16_t raw) -> std::optional<LocalText> {
        return LocalText{std::to_string(raw / 1000) + ".000 V",
                         std::to_string(raw / 1000) + ",000 V"};
    };
    const Description d = describe(kOpat27Write, o);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d.protocol, "gateway");
    ASSERT_EQ(d.fields.size(), 5u);
    EXPECT_EQ(d.fields[0].key, "TADR");
    EXPECT_EQ(d.fields[0].value, "0x23");
    EXPECT_EQ(d.fields[1].key, "SADR");
    EXPECT_TRUE(contains(d.fields[1].text.en, "OPAT master"));
    EXPECT_TRUE(contains(d.fields[1].text.de, "OPAT-Master"));
    EXPECT_EQ(d.fields[2].key, "CMD");
    EXPECT_EQ(d.fields[2].value, "0x06");
    EXPECT_TRUE(contains(d.fields[2].text.de, "Schreiben eines einzelnen Parameters"));
    const FieldSpan *id = d.field("ID");
    ASSERT_NE(id, nullptr);
    EXPECT_EQ(id->offset, 3u);
    EXPECT_EQ(id->length, 2u);
    EXPECT_EQ(id->value, "0x0030");
    EXPECT_TRUE(contains(id->text.en, "C1.07"));
    const FieldSpan *dat = d.field("DAT");
    ASSERT_NE(dat, nullptr);
    EXPECT_EQ(dat->value, "1000");
    EXPECT_TRUE(contains(dat->text.en, "1.000 V"));
    EXPECT_TRUE(contains(dat->text.de, "1,000 V"));
    EXPECT_TRUE(contains(d.summary.en, "CMD 6"));
}

TEST(HcsDescribe, DmaSec3_7_ReadResponseNamesDataByFirstId)
{
    DescribeOptions o = opts(Family::Dma, Direction::Response);
    o.firstId = 0x0007;
    const Description d = describe(kDma37ReadResponse, o);
    ASSERT_TRUE(d.ok());
    const FieldSpan *cnt = d.field("CNT");
    ASSERT_NE(cnt, nullptr);
    EXPECT_EQ(cnt->value, "2");
    const FieldSpan *dat = d.field("DAT1");
    ASSERT_NE(dat, nullptr);
    EXPECT_EQ(dat->offset, 4u);
    EXPECT_EQ(dat->value, "307");
    EXPECT_TRUE(contains(dat->text.en, "ID 0x0007"));
    EXPECT_TRUE(contains(dat->text.en, "0x0133"));
}

TEST(HcsDescribe, OpatSec2_3_ResponseRecognisesErrorFrameByBit7)
{
    const Description d = describe(kOpat23ReadError, opts(Family::Opat, Direction::Response));
    ASSERT_TRUE(d.ok());
    const FieldSpan *err = d.field("ERR");
    ASSERT_NE(err, nullptr);
    EXPECT_EQ(err->value, "0x83");
    EXPECT_TRUE(contains(err->text.en, "read failed"));
    const FieldSpan *exce = d.field("EXCE");
    ASSERT_NE(exce, nullptr);
    EXPECT_EQ(exce->value, "5");
    EXPECT_TRUE(contains(exce->text.en, "timeout slave"));
    EXPECT_TRUE(contains(exce->text.de, "Timeout Slave"));
    // The same bytes read as a request are an unknown command.
    const Description q = describe(kOpat23ReadError, opts(Family::Opat, Direction::Request));
    ASSERT_FALSE(q.ok());
    EXPECT_EQ(q.error->code, DecodeErrc::UnexpectedCommand);
}

TEST(HcsDescribe, OpatSec3_3_CyclicErrorUsesTheCmd15Table)
{
    const Description d = describe(kOpat33CyclicError, opts(Family::Opat, Direction::Response));
    const FieldSpan *exce = d.field("EXCE");
    ASSERT_NE(exce, nullptr);
    EXPECT_TRUE(contains(exce->text.en, "timeout slave, address wrong or not installed"));
    const Description dma = describe(kDma43CyclicError, opts(Family::Dma, Direction::Response));
    EXPECT_TRUE(contains(dma.field("EXCE")->text.de,
                         "Timeout Slave, Adresse falsch oder nicht installiert"));
}

TEST(HcsDescribe, OpatSec3_4_1_DefaultProfileIsStatedAndNamesD111)
{
    const Description d = describe(kOpat341Response, opts(Family::Opat, Direction::Response));
    ASSERT_TRUE(d.ok());
    const FieldSpan *profile = d.field("profile");
    ASSERT_NE(profile, nullptr);
    EXPECT_EQ(profile->value, "opat-v34-mode34");
    EXPECT_TRUE(contains(profile->text.en, "assumed"));
    EXPECT_TRUE(contains(profile->text.de, "angenommen"));
    const FieldSpan *v1 = d.field("DAT.2");
    ASSERT_NE(v1, nullptr);
    EXPECT_EQ(v1->value, "1000");
    EXPECT_TRUE(
        contains(v1->text.en, "VALUE1 = d1.11 actual value, feedback value (branch 1): 1.000 V"));
    EXPECT_TRUE(contains(v1->text.de, "d1.11 Aktueller Istwert (Zweig 1): 1,000 V"));
    const FieldSpan *v2 = d.field("DAT.3");
    ASSERT_NE(v2, nullptr);
    EXPECT_TRUE(contains(v2->text.en, "d1.10 set value (internal value)"));
    // 0x40: the example's "hardware enable active" is STAT_5 in every bit table.
    const FieldSpan *stat5 = d.field("DAT.1H.STAT_5");
    ASSERT_NE(stat5, nullptr);
    EXPECT_TRUE(contains(stat5->text.en, "0x04"));
    EXPECT_EQ(d.field("DAT.1H.HW_ENABLE"), nullptr);
}

TEST(HcsDescribe, OpatSec3_4_2_RequestNamesModulesBySadr)
{
    const Description d = describe(kOpat342Request, opts(Family::Opat, Direction::Request));
    ASSERT_TRUE(d.ok());
    const FieldSpan *snum = d.field("SNUM");
    ASSERT_NE(snum, nullptr);
    EXPECT_EQ(snum->value, "2");
    EXPECT_TRUE(contains(snum->text.en, "master"));
    // OPAT numbers the module data DAT0.x (master) … DAT2.x.
    ASSERT_NE(d.field("DAT0.1"), nullptr);
    const FieldSpan *slave2 = d.field("DAT2.2");
    ASSERT_NE(slave2, nullptr);
    EXPECT_EQ(slave2->offset, 14u);
    EXPECT_EQ(slave2->value, "-3000");
    EXPECT_TRUE(contains(slave2->text.en, "A1.01 set value input (bus) for branch 1: -3.000 V"));
    EXPECT_TRUE(contains(d.field("DAT1.3")->text.en, "A1.02 feedback value input"));
    EXPECT_TRUE(contains(d.field("DAT0.1")->text.de, "kein Bit gesetzt"));
}

TEST(HcsDescribe, DmaSec4_4_1_V15Mode1ResponseIsCurrentsInAmpere)
{
    const Description d = describe(kDma441Response, opts(Family::Dma, Direction::Response));
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d.field("profile")->value, "dma-v15-mode1");
    EXPECT_TRUE(contains(d.field("DAT.2")->text.en, "d1.07 actual current A: 0.000 A"));
    EXPECT_TRUE(contains(d.field("DAT.3")->text.en, "d1.08 actual current B: 0.270 A"));
    EXPECT_TRUE(contains(d.field("DAT.3")->text.de, "Aktueller Strom B: 0,270 A"));
    EXPECT_TRUE(contains(d.field("SADR")->text.en, "E22 = 1"));
}

TEST(HcsDescribe, DmaSec4_4_2_RequestUsesA101AndA201)
{
    const Description d = describe(kDma442Request, opts(Family::Dma, Direction::Request));
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d.field("DAT3.2")->value, "-3000");
    // DMA Profibus Anleitung R2.9: VALUE2 of mode 1 is A2.01 (not A1.02 as the Profinet example
    // prints).
    EXPECT_TRUE(contains(d.field("DAT1.3")->text.en, "A2.01"));
}

TEST(HcsDescribe, VersionAndModeChangeWhatTheValuesMean)
{
    DescribeOptions o = opts(Family::Opat, Direction::Response);
    o.profile = Profile::OpatV34Mode6;
    Description d = describe(kOpat341Response, o);
    EXPECT_TRUE(contains(d.field("DAT.3")->text.en,
                         "VALUE2 = d2.11 actual value, feedback value (branch 2)"));
    EXPECT_FALSE(contains(d.field("profile")->text.en, "assumed"));
    o.family = Family::Dma;
    o.profile = profileFor(Family::Dma, 32, 8);
    d = describe(kDma441Request, DescribeOptions{o.family, Direction::Request, o.profile});
    EXPECT_TRUE(contains(d.field("DAT1.3")->text.en, "A2.01 set value input (bus) for branch 2"));
    d = describe(kDma441Request,
                 DescribeOptions{Family::Dma, Direction::Request, Profile::DmaV32Mode6});
    EXPECT_TRUE(contains(d.field("DAT1.3")->text.de, "A2.02 Istwert Eingang (Bus) für Zweig 2"));
}

TEST(HcsDescribe, ControlBitsPerVersion)
{
    // Control 0x91 = BUS_DISABLE + Din_2 + Din_1.
    const Bytes q{0x10, 0x01, 0x0F, 0x91, 0x00, 0x00, 0x00, 0x00};
    Description d =
        describe(q, DescribeOptions{Family::Dma, Direction::Request, Profile::DmaV32Mode34});
    ASSERT_NE(d.field("DAT1.1.Din_1"), nullptr);
    ASSERT_NE(d.field("DAT1.1.Din_2"), nullptr);
    EXPECT_FALSE(contains(d.field("DAT1.1.Din_2")->text.en, "reserved"));
    EXPECT_TRUE(contains(d.field("DAT1.1.BUS_DISABLE")->text.de, "Freigabe via Bus sperren"));
    // DMA Profinet manual §4.5.3: V51 reserves Din_2; §4.5.2: V13 uses only BUS_DISABLE.
    d = describe(q, DescribeOptions{Family::Dma, Direction::Request, Profile::DmaV51Mode34});
    EXPECT_TRUE(contains(d.field("DAT1.1.Din_2")->text.en, "reserved"));
    EXPECT_FALSE(contains(d.field("DAT1.1.Din_1")->text.en, "reserved"));
    d = describe(q, DescribeOptions{Family::Dma, Direction::Request, Profile::DmaV13Mode1});
    EXPECT_TRUE(contains(d.field("DAT1.1.Din_1")->text.de, "reserviert"));
    EXPECT_FALSE(contains(d.field("DAT1.1.BUS_DISABLE")->text.en, "reserved"));
}

TEST(HcsDescribe, StatusWordErrorNumberPerFamily)
{
    // DMA Profinet manual §4.5.1.1: status 0x0C 0x02 = error 2, wire break at set point S1.06.
    const Bytes dma{0x30, 0x02, 0x0F, 0x0C, 0x02, 0x00, 0x00, 0x00, 0x00};
    Description d = describe(dma, opts(Family::Dma, Direction::Response));
    ASSERT_NE(d.field("DAT.1H.HW_ENABLE"), nullptr);
    ASSERT_NE(d.field("DAT.1H.ERROR"), nullptr);
    const FieldSpan *e = d.field("DAT.1L.error");
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->value, "2");
    EXPECT_TRUE(contains(e->text.de, "Drahtbruch des Analog-Einganges S1.06"));
    // OPAT: error 2 = wire break sensor 1 (ID 0x102; §5.6 "cable fracture at FB1").
    d = describe(dma, opts(Family::Opat, Direction::Response));
    EXPECT_TRUE(contains(d.field("DAT.1L.error")->text.en, "wire break sensor 1"));
}

TEST(HcsDescribe, StatusLowSignalsAndTheOpatPrintedOrder)
{
    const Bytes a{0x30, 0x00, 0x0F, 0x04, 0x02, 0x00, 0x00, 0x00, 0x00};
    DescribeOptions o = opts(Family::Opat, Direction::Response);
    Description d = describe(a, o);
    ASSERT_NE(d.field("DAT.1L.Dout_1"), nullptr); // parameter 0xB0: 0x02 = Dout_1
    o.opatPrintedStatusOrder = true;
    d = describe(a, o);
    ASSERT_NE(d.field("DAT.1L.DKOMP_1"), nullptr); // OPAT manual §3.5.2 table: 0x02 = DKOMP_1
}

TEST(HcsDescribe, TruncatedFrameDescribesWhatIsThere)
{
    const Bytes cut(kOpat342Request.begin(), kOpat342Request.begin() + 11);
    const Description d = describe(cut, opts(Family::Opat, Direction::Request));
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error->code, DecodeErrc::Truncated);
    EXPECT_EQ(d.error->offset, 11u);
    ASSERT_NE(d.field("DAT1.2"), nullptr);
    EXPECT_EQ(d.field("DAT1.3"), nullptr);
    EXPECT_TRUE(contains(d.summary.en, "truncated at byte 11"));
    EXPECT_TRUE(contains(d.summary.de, "unvollständig bei Byte 11"));
}

TEST(HcsDescribe, PaddingAndExtraBytes)
{
    Bytes padded = kDma441Request;
    padded.resize(42, 0);
    DescribeOptions o = opts(Family::Dma, Direction::Request);
    Description d = describe(padded, o);
    EXPECT_FALSE(d.ok());
    ASSERT_NE(d.field("extra"), nullptr);
    EXPECT_EQ(d.field("extra")->length, 34u);
    o.allowPadding = true;
    d = describe(padded, o);
    EXPECT_TRUE(d.ok());
    ASSERT_NE(d.field("padding"), nullptr);
}

TEST(HcsDescribe, NodeRuleNotes)
{
    const Bytes nineParams{0x01, 0x01, 0x03, 0x00, 0x07, 0x00, 0x09};
    const Description d = describe(nineParams, opts(Family::Dma, Direction::Request));
    EXPECT_TRUE(d.ok()); // well-formed; the node would refuse it
    const FieldSpan *note = d.field("note");
    ASSERT_NE(note, nullptr);
    EXPECT_TRUE(contains(note->text.en, "exception 3"));
}

TEST(HcsDescribe, EveryWorkedExampleIsDescribedCompletelyInBothLanguages)
{
    for (const Example &ex : allExamples()) {
        DescribeOptions o = opts(ex.family, ex.direction);
        const Description d = describe(ex.bytes, o);
        EXPECT_TRUE(d.ok()) << ex.name;
        EXPECT_TRUE(d.summary.complete()) << ex.name;
        std::size_t covered = 0;
        for (const FieldSpan &f : d.fields) {
            EXPECT_TRUE(f.text.complete()) << ex.name << " " << f.key;
            EXPECT_LE(f.offset + f.length, ex.bytes.size()) << ex.name << " " << f.key;
            if (f.depth == 0)
                covered += f.length;
        }
        EXPECT_EQ(covered, ex.bytes.size()) << ex.name; // top-level rows tile the frame
    }
}
