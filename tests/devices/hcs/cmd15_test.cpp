// CMD 15 module counts and lengths: OPAT manual §3.1 (SNUM = slaves, master included, 8..43
// bytes) against DMA Profinet manual §4.1 (SNUM = modules 1..5, 8..28 bytes).
#include "hcs/cmd15.h"
#include "hcs/telegram.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hcs;

TEST(HcsCmd15, OpatSec3_1_SnumCountsSlavesBesidesTheMaster)
{
    for (std::uint8_t snum = 0; snum <= 7; ++snum)
        EXPECT_EQ(modulesForSnum(Family::Opat, snum), std::size_t{snum} + 1u);
    EXPECT_FALSE(modulesForSnum(Family::Opat, 8));
    EXPECT_EQ(snumForModules(Family::Opat, 1), 0);
    EXPECT_EQ(snumForModules(Family::Opat, 8), 7);
    EXPECT_FALSE(snumForModules(Family::Opat, 0));
    EXPECT_FALSE(snumForModules(Family::Opat, 9));
    EXPECT_EQ(moduleAddress(Family::Opat, 0), 0); // master
    EXPECT_EQ(moduleAddress(Family::Opat, 7), 7);
}

TEST(HcsCmd15, DmaProfinetSec4_1_SnumCountsModules)
{
    EXPECT_FALSE(modulesForSnum(Family::Dma, 0));
    for (std::uint8_t snum = 1; snum <= 5; ++snum)
        EXPECT_EQ(modulesForSnum(Family::Dma, snum), std::size_t{snum});
    EXPECT_FALSE(modulesForSnum(Family::Dma, 6));
    EXPECT_EQ(moduleAddress(Family::Dma, 0), 1); // E22 = 1
}

TEST(HcsCmd15, TelegramLengthsMatchTheTables)
{
    // OPAT manual §3.1: 8 13 18 … 43; DMA Profinet manual §4.1: 8 13 18 23 28.
    for (std::size_t n = 1; n <= 8; ++n) {
        CyclicRequest q{0x01, std::vector<ModuleSetpoints>(n)};
        auto opat = encode(q, Family::Opat);
        ASSERT_TRUE(opat.ok());
        EXPECT_EQ(opat->size(), 3 + 5 * n);
        auto dma = encode(q, Family::Dma);
        EXPECT_EQ(dma.ok(), n <= 5);
        if (!dma.ok()) {
            EXPECT_EQ(dma.error().code, DecodeErrc::BadValue);
            EXPECT_EQ(dma.error().offset, 1u);
        }
    }
    EXPECT_FALSE(encode(CyclicRequest{}, Family::Opat).ok());
    EXPECT_FALSE(encode(CyclicRequest{}, Family::Dma).ok());
}

TEST(HcsCmd15, RoundTripsEveryFieldOfEveryModule)
{
    CyclicRequest q{0xA5, {}};
    for (int i = 0; i < 8; ++i)
        q.modules.push_back({static_cast<std::uint8_t>(0x80 | i),
                             static_cast<std::int16_t>(-32768 + i),
                             static_cast<std::int16_t>(32767 - i)});
    auto bytes = encode(q, Family::Opat);
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(bytes->size(), 43u);
    auto back = decodeCyclicRequest(*bytes, {Family::Opat, false});
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(*back, q);
}

TEST(HcsCmd15, DmaProfinetSec4_5_4_PaddedProcessImage)
{
    // The Profinet node uses one 42-byte image for every fold: a 1-module telegram + 34 zero bytes.
    CyclicRequest q{0x23, {{0x00, 1000, 0}}};
    Bytes image = encode(q, Family::Dma).value();
    image.resize(42, 0);
    auto strict = decodeCyclicRequest(image, {Family::Dma, false});
    ASSERT_FALSE(strict.ok());
    EXPECT_EQ(strict.error().code, DecodeErrc::TooLong);
    EXPECT_EQ(strict.error().offset, 8u);
    auto padded = decodeCyclicRequest(image, {Family::Dma, true});
    ASSERT_TRUE(padded.ok());
    EXPECT_EQ(*padded, q);
    auto any = decodeRequest(image, {Family::Dma, true});
    ASSERT_TRUE(any.ok());
    EXPECT_EQ(std::get<CyclicRequest>(*any), q);
}

TEST(HcsCmd15, SnumOutsideTheFamilyRangeIsBadValueAtOffset1)
{
    const Bytes opatSnum8{0x01, 0x08, 0x0F};
    auto a = decodeCyclicRequest(opatSnum8, {Family::Opat, false});
    ASSERT_FALSE(a.ok());
    EXPECT_EQ(a.error().code, DecodeErrc::BadValue);
    EXPECT_EQ(a.error().offset, 1u);
    for (std::uint8_t snum : {std::uint8_t{0}, std::uint8_t{6}, std::uint8_t{255}}) {
        const Bytes dma{0x01, snum, 0x0F, 0, 0, 0, 0, 0};
        auto b = decodeCyclicRequest(dma, {Family::Dma, false});
        ASSERT_FALSE(b.ok());
        EXPECT_EQ(b.error().code, DecodeErrc::BadValue);
        EXPECT_EQ(b.error().offset, 1u);
    }
}
