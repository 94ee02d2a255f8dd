// The EXCE codes the simulator answers with (sim/hcs_codes.h) mean what their names say in each
// family's tables (hcs::exceptionText: OPAT manual §2.3 / §2.6 / §3.3, DMA Profinet manual §3.3 /
// §3.6 / §4.3).
#include "hcs/exceptions.h"
#include "sim/hcs_codes.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::sim;
using hcs::Family;

namespace {

std::string text(Family f, std::uint8_t cmd, std::uint8_t code)
{
    const auto t = hcs::exceptionText(f, cmd, code);
    return t ? t->en : "(none)";
}

} // namespace

TEST(HcsSimCodes, NamesMatchBothFamiliesTables)
{
    for (Family f : {Family::Opat, Family::Dma}) {
        SCOPED_TRACE(std::string(hcs::familyName(f)));
        EXPECT_EQ(text(f, 15, exce::kCommandNotSupported), "command not supported");
        EXPECT_EQ(text(f, 3, exce::kWrongId), "wrong ID");
        EXPECT_EQ(text(f, 6, exce::kWrongId), "wrong ID");
        EXPECT_EQ(text(f, 3, exce::kBadCount), "CNT == 0 or CNT > 16 (0x10)");
        EXPECT_EQ(text(f, 6, exce::kWrongData), "wrong data value");
        EXPECT_EQ(text(f, 15, exce::kWrongData), "wrong data value");
        EXPECT_EQ(text(f, 6, exce::kWriteFailed), "writing of ID failed");
        EXPECT_EQ(text(f, 3, exce::kSlaveTimeout)
                      .rfind("timeout slave, address wrong or not installed", 0),
                  0u);
        EXPECT_EQ(text(f, 15, exce::kInvalidSlaveCount), "invalid number of connected slaves");
        EXPECT_EQ(text(f, 15, exce::kCyclicSlaveTimeout),
                  "timeout slave, address wrong or not installed");
        EXPECT_NE(text(f, 15, exce::kBufferTooSmall).find("too small"), std::string::npos);
    }
    EXPECT_EQ(text(Family::Opat, 15, exce::kDuplicateAddress),
              "two or more slaves have the same slave address");
    EXPECT_EQ(text(Family::Opat, 3, exce::kDuplicateAddress),
              "two or more slaves have the same slave address");
    EXPECT_EQ(text(Family::Dma, 3, exce::kChecksum), "internal checksum error (Modbus)");
    EXPECT_EQ(text(Family::Dma, 15, exce::kChecksum), "internal checksum error (Modbus)");
}
