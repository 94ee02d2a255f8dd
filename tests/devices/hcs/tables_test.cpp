// The manuals' tables as data: exception codes per family and command, error numbers, CMD 15
// profiles and their bits — complete in both languages.
#include "hcs/exceptions.h"
#include "hcs/profiles.h"
#include "hcs/status_bits.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hcs;

TEST(HcsTables, OpatSec2_3_Sec2_6_Sec3_3_ExceptionCodes1To12)
{
    for (std::uint8_t cmd : {kCmdRead, kCmdWrite, kCmdCyclic}) {
        EXPECT_EQ(maxExceptionCode(Family::Opat, cmd), 12);
        EXPECT_FALSE(exceptionText(Family::Opat, cmd, 0));
        EXPECT_FALSE(exceptionText(Family::Opat, cmd, 13));
        for (std::uint8_t code = 1; code <= 12; ++code) {
            auto t = exceptionText(Family::Opat, cmd, code);
            ASSERT_TRUE(t) << int(cmd) << "/" << int(code);
            EXPECT_TRUE(t->complete());
        }
    }
    EXPECT_EQ(exceptionText(Family::Opat, kCmdRead, 3)->en, "CNT == 0 or CNT > 16 (0x10)");
    EXPECT_EQ(exceptionText(Family::Opat, kCmdWrite, 3)->en, "wrong data value");
    EXPECT_EQ(exceptionText(Family::Opat, kCmdRead, 6)->en,
              "internal checksum error (CAN connection)");
    // §3.3 differs in 5 and 6.
    EXPECT_EQ(exceptionText(Family::Opat, kCmdCyclic, 5)->en, "timeout (CAN connection)");
    EXPECT_EQ(exceptionText(Family::Opat, kCmdCyclic, 6)->en, "internal checksum error (Modbus)");
    EXPECT_EQ(exceptionText(Family::Opat, kCmdCyclic, 12)->en,
              "two or more slaves have the same slave address");
}

TEST(HcsTables, DmaProfinetSec3_3_Sec3_6_Sec4_3_ExceptionCodes)
{
    EXPECT_EQ(maxExceptionCode(Family::Dma, kCmdRead), 6);
    EXPECT_EQ(maxExceptionCode(Family::Dma, kCmdWrite), 6);
    EXPECT_EQ(maxExceptionCode(Family::Dma, kCmdCyclic), 9);
    EXPECT_FALSE(exceptionText(Family::Dma, kCmdRead, 7));
    EXPECT_FALSE(exceptionText(Family::Dma, kCmdCyclic, 10));
    // German wording of the DMA Profibus Anleitung §3.3.
    EXPECT_EQ(exceptionText(Family::Dma, kCmdRead, 4)->de, "Lesen der ID fehlgeschlagen");
    EXPECT_EQ(exceptionText(Family::Dma, kCmdRead, 6)->de, "Interner Checksum Fehler (Modbus)");
    EXPECT_EQ(exceptionText(Family::Dma, kCmdWrite, 4)->en, "writing of ID failed");
    EXPECT_EQ(exceptionText(Family::Dma, kCmdCyclic, 5)->en, "timeout (Modbus)");
    EXPECT_NE(exceptionText(Family::Dma, kCmdCyclic, 9)->en.find("GSD"), std::string::npos);
    EXPECT_EQ(exceptionTextOrUnknown(Family::Dma, kCmdRead, 42).en, "unknown exception 42");
    EXPECT_FALSE(exceptionText(Family::Dma, 4, 1));
}

TEST(HcsTables, DmaProfinetSec4_5_1_1_ErrorNumbers)
{
    for (std::uint8_t n = 1; n <= 10; ++n) {
        auto t = errorNumberText(Family::Dma, n);
        ASSERT_TRUE(t) << int(n);
        EXPECT_TRUE(t->complete());
    }
    EXPECT_FALSE(errorNumberText(Family::Dma, 0));
    EXPECT_FALSE(errorNumberText(Family::Dma, 11));
    EXPECT_EQ(errorNumberText(Family::Dma, 1)->de, "Allgemeiner Fehler");
}

TEST(HcsTables, OpatSec7_Id0x102_ErrorCodes)
{
    for (int n : {2, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 23})
        ASSERT_TRUE(errorNumberText(Family::Opat, static_cast<std::uint8_t>(n))) << n;
    for (int n : {0, 1, 3, 14, 22, 24})
        EXPECT_FALSE(errorNumberText(Family::Opat, static_cast<std::uint8_t>(n))) << n;
    EXPECT_EQ(errorNumberText(Family::Opat, 7)->en, "CAN error, no connection to slave or master");
}

TEST(HcsTables, ProfilesCoverEveryDocumentedVersionAndMode)
{
    EXPECT_EQ(profileFor(Family::Dma, 13, 1), Profile::DmaV13Mode1);
    EXPECT_EQ(profileFor(Family::Dma, 15, 0), Profile::DmaV15Mode1);
    EXPECT_EQ(profileFor(Family::Dma, 22, 2), Profile::DmaV22Mode2);
    EXPECT_EQ(profileFor(Family::Dma, 32, 3), Profile::DmaV32Mode34);
    EXPECT_EQ(profileFor(Family::Dma, 32, 4), Profile::DmaV32Mode34);
    EXPECT_EQ(profileFor(Family::Dma, 32, 6), Profile::DmaV32Mode6);
    EXPECT_EQ(profileFor(Family::Dma, 31, 8), Profile::DmaV32Mode8);
    EXPECT_EQ(profileFor(Family::Dma, 51, 4), Profile::DmaV51Mode34);
    EXPECT_EQ(profileFor(Family::Opat, 34, 0), Profile::OpatV34Mode34);
    EXPECT_EQ(profileFor(Family::Opat, 31, 6), Profile::OpatV34Mode6);
    EXPECT_EQ(profileFor(Family::Opat, 34, 8), Profile::OpatV34Mode8);
    EXPECT_FALSE(profileFor(Family::Dma, 13, 3));
    EXPECT_FALSE(profileFor(Family::Dma, 51, 6));
    EXPECT_FALSE(profileFor(Family::Opat, 34, 1));
    EXPECT_FALSE(profileFor(Family::Opat, 15, 1));
    EXPECT_EQ(defaultProfile(Family::Opat), Profile::OpatV34Mode34);
    EXPECT_EQ(defaultProfile(Family::Dma), Profile::DmaV15Mode1);
    for (const ProfileInfo &p : allProfiles()) {
        EXPECT_EQ(profileByKey(p.key), p.profile);
        EXPECT_EQ(&profileInfo(p.profile), &p);
        for (const LocalText *t :
             {&p.title, &p.request1.text, &p.request2.text, &p.response1.text, &p.response2.text})
            EXPECT_TRUE(t->complete()) << p.key;
        for (const auto &bits : {controlBits(p.profile), statusHighBits(p.profile),
                                 statusLowBits(p.profile), statusLowBits(p.profile, true)})
            for (const BitMeaning &b : bits)
                EXPECT_TRUE(b.text.complete()) << p.key << " " << b.name;
    }
    EXPECT_FALSE(profileByKey("dma-v99"));
    EXPECT_EQ(familyFromName(familyName(Family::Opat)), Family::Opat);
    EXPECT_EQ(familyFromName(familyName(Family::Dma)), Family::Dma);
    EXPECT_FALSE(familyFromName("wandfluh"));
}

TEST(HcsTables, BitsPerVersion)
{
    auto used = [](const std::array<BitMeaning, 8> &bits) {
        std::uint8_t mask = 0;
        for (const BitMeaning &b : bits)
            if (b.used)
                mask = static_cast<std::uint8_t>(mask | b.mask);
        return mask;
    };
    // DMA Profibus Anleitung §4.5.2 (V15): only BUS_DISABLE; §4.5.4 (V32): Din_1, TST_CMP, Din_2,
    // BUS_DISABLE; DMA Profinet manual §4.5.3 (V51): Din_2 reserved.
    EXPECT_EQ(used(controlBits(Profile::DmaV15Mode1)), 0x80);
    EXPECT_EQ(used(controlBits(Profile::DmaV32Mode34)), 0x95);
    EXPECT_EQ(used(controlBits(Profile::DmaV51Mode34)), 0x85);
    EXPECT_EQ(used(statusHighBits(Profile::DmaV15Mode1)), 0x8C);
    EXPECT_EQ(used(statusLowBits(Profile::DmaV15Mode1)), 0x00);
    EXPECT_EQ(used(statusLowBits(Profile::DmaV51Mode34)), 0x0F);
    EXPECT_EQ(used(statusLowBits(Profile::OpatV34Mode8)), 0xFF);
    EXPECT_EQ(statusLowBits(Profile::OpatV34Mode34)[1].name, "Dout_1");
    EXPECT_EQ(statusLowBits(Profile::OpatV34Mode34, true)[1].name, "DKOMP_1");
    EXPECT_EQ(statusLowBits(Profile::OpatV34Mode34, true)[6].name, "Dout_2");
    EXPECT_EQ(statusLowBits(Profile::DmaV32Mode34, true)[1].name,
              "Dout_1"); // DMA: no alternative order
}

TEST(HcsTables, DecodeStatusSplitsErrorNumberAndSignals)
{
    ModuleStatus s = decodeStatus(0x0C02);
    EXPECT_TRUE(s.hwEnable);
    EXPECT_TRUE(s.error);
    EXPECT_FALSE(s.busDisable);
    EXPECT_EQ(s.errorNumber, 2);
    EXPECT_EQ(s.signalBits, 0);
    s = decodeStatus(0x8411);
    EXPECT_TRUE(s.busDisable);
    EXPECT_FALSE(s.error);
    EXPECT_EQ(s.signalBits, 0x11);
}
