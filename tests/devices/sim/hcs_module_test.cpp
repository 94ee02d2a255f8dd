// The simulated HCS module's access rules for every family, version and mode: every readable
// row reads its dictionary default, out-of-range writes get EXCE 3, writes to read-only / not
// active / unknown IDs get the family's "wrong ID" (2), reads keep the "1..8 at once" rule
// (OPAT manual §2.1 / §2.3, DMA Profinet manual §3.1 / §3.3 / §3.6).
#include "dict/param_meta.h"
#include "hcs/exceptions.h"
#include "hcs_sim_support.h"
#include "sim/hcs_codes.h"

using namespace vt::dev;
using namespace vt::dev::sim;
using namespace vt::dev::sim::test;

namespace {

// The wire word of a raw value one step outside a limit, or nullopt when the type cannot carry it.
std::optional<std::uint16_t> beyond(const ParamMeta &row, double limit, int direction)
{
    const double v = limit + direction;
    if (v < typeMin(row.type) || v > typeMax(row.type))
        return std::nullopt;
    return static_cast<std::uint16_t>(static_cast<std::int32_t>(v));
}

} // namespace

TEST(HcsSimModule, EveryReadableRowReadsItsDictionaryDefault)
{
    for (const Variant &v : allVariants()) {
        SimClock clock;
        HcsModule module(clock, configFor(v));
        const auto rows = readableRows(module);
        ASSERT_GT(rows.size(), 50u) << v.name();
        for (const ParamMeta *row : rows) {
            const ReadOutcome one = module.read(static_cast<std::uint16_t>(*row->id), 1);
            ASSERT_TRUE(one.ok()) << v.name() << " " << row->name << " EXCE " << int(one.exception);
            EXPECT_EQ(one.values.at(0), expectedFreshWord(*row, module))
                << v.name() << " " << row->name;
        }
        // The same through blocks of up to 8 consecutive IDs, as the session reads them.
        for (const hcs::ReadBlock &b : readBlocks(rows)) {
            const ReadOutcome block = module.read(b.firstId, b.count);
            ASSERT_TRUE(block.ok()) << v.name() << " block at " << b.firstId;
            ASSERT_EQ(block.values.size(), b.count);
            for (std::uint16_t i = 0; i < b.count; ++i)
                EXPECT_EQ(block.values[i],
                          expectedFreshWord(*module.storage().meta(b.firstId + i), module));
        }
    }
}

TEST(HcsSimModule, IdentityRowsCarryVersionModeAndAddress)
{
    SimClock clock;
    HcsModuleConfig c = configFor({"opat", "31", 6}, 5);
    HcsModule slave(clock, c);
    EXPECT_EQ(slave.read(0, 1).values.at(0), 3100); // Vers
    EXPECT_EQ(slave.storage().get("E00"), 6);       // mode
    EXPECT_EQ(slave.storage().get("E22"), 5);       // DIP switch (V31)
    EXPECT_EQ(slave.address(), 5);
    EXPECT_EQ(slave.profile(), hcs::Profile::OpatV34Mode6);
    c.versionRaw = 3112;
    HcsModule other(clock, c);
    EXPECT_EQ(other.read(0, 1).values.at(0), 3112);
}

TEST(HcsSimModule, OutOfRangeWritesGetWrongDataValue)
{
    for (const Variant &v : allVariants()) {
        SimClock clock;
        HcsModule module(clock, configFor(v));
        int checked = 0;
        for (const ParamMeta &row : module.dictionary().params) {
            if (!row.id || module.storage().meta(*row.id) != &row || !row.writable())
                continue;
            for (const auto &word : {beyond(row, row.min, -1), beyond(row, row.max, +1)}) {
                if (!word)
                    continue;
                const std::int32_t before = module.storage().raw(*row.id);
                const WriteOutcome out = module.write(static_cast<std::uint16_t>(*row.id), *word);
                EXPECT_EQ(out.exception, exce::kWrongData)
                    << v.name() << " " << row.name << " = " << *word;
                EXPECT_EQ(module.storage().raw(*row.id), before) << v.name() << " " << row.name;
                ++checked;
            }
        }
        EXPECT_GT(checked, 50) << v.name();
        EXPECT_EQ(hcs::exceptionText(module.family(), hcs::kCmdWrite, exce::kWrongData)->en,
                  "wrong data value");
    }
}

TEST(HcsSimModule, ReadOnlyNotActiveAndUnknownIdsGetWrongId)
{
    for (const Variant &v : allVariants()) {
        SimClock clock;
        HcsModule module(clock, configFor(v));
        int readOnly = 0, inactive = 0;
        for (const ParamMeta &row : module.dictionary().params) {
            if (!row.id)
                continue;
            const auto id = static_cast<std::uint16_t>(*row.id);
            const bool applies = module.storage().meta(*row.id) == &row;
            if (applies && row.access == Access::Read) {
                const std::int32_t before = module.storage().raw(*row.id);
                // Write the value it holds: the access rule answers before the range check.
                EXPECT_EQ(module.write(id, module.storage().word(*row.id)).exception,
                          exce::kWrongId)
                    << v.name() << " " << row.name;
                EXPECT_EQ(module.storage().raw(*row.id), before);
                ++readOnly;
            } else if (!applies || row.access == Access::Inactive ||
                       row.access == Access::NotImplemented) {
                EXPECT_EQ(module.write(id, 0).exception, exce::kWrongId)
                    << v.name() << " " << row.name;
                EXPECT_EQ(module.read(id, 1).exception, exce::kWrongId)
                    << v.name() << " " << row.name;
                ++inactive;
            }
        }
        EXPECT_GT(readOnly, 10) << v.name();
        EXPECT_EQ(module.write(0x3FF, 0).exception, exce::kWrongId);
        EXPECT_EQ(module.read(0x3FF, 1).exception, exce::kWrongId);
        EXPECT_EQ(hcs::exceptionText(module.family(), hcs::kCmdWrite, exce::kWrongId)->en,
                  "wrong ID");
        if (v.family == "opat" || v.family.rfind("dma-pn", 0) == 0) {
            EXPECT_GT(inactive, 10) << v.name();
        }
    }
}

TEST(HcsSimModule, ReadsOneToEightIdsAtOnce)
{
    SimClock clock;
    HcsModule module(clock, configFor({"dma-pn-v51", "51", 3}));
    EXPECT_EQ(module.read(7, 0).exception, exce::kBadCount);
    EXPECT_EQ(module.read(7, 9).exception, exce::kBadCount);
    EXPECT_EQ(module.read(7, 8).values.size(), 8u);
    EXPECT_EQ(hcs::exceptionText(hcs::Family::Dma, hcs::kCmdRead, exce::kBadCount)->en,
              "CNT == 0 or CNT > 16 (0x10)");
}

TEST(HcsSimModule, BlockOverAMissingIdIsRefusedUnlessLenient)
{
    SimClock clock;
    HcsModuleConfig c = configFor({"dma-pn-v51", "51", 3});
    HcsModule strict(clock, c);
    // ID 0x75 (FB1M) is "implemented, but not active": a block across it.
    ASSERT_EQ(strict.storage().meta(0x75)->access, Access::Inactive);
    EXPECT_EQ(strict.read(0x72, 8).exception, exce::kWrongId);
    c.strictBlockReads = false;
    HcsModule lenient(clock, c);
    const ReadOutcome out = lenient.read(0x72, 8);
    ASSERT_TRUE(out.ok());
    EXPECT_EQ(out.values.at(3), 0);
}

TEST(HcsSimModule, SignedAndUnsignedWordsFollowTheRowType)
{
    SimClock clock;
    HcsModule module(clock, configFor({"dma-pn-v51", "51", 3}));
    const ParamMeta *a101 = module.storage().find("A1.01");
    ASSERT_TRUE(a101);
    // DMA Profinet manual §3.8: -9.999 V = 0xD8F1.
    ASSERT_TRUE(module.write(static_cast<std::uint16_t>(*a101->id), 0xD8F1).ok());
    EXPECT_EQ(module.storage().raw(*a101->id), -9999);
    EXPECT_EQ(module.read(static_cast<std::uint16_t>(*a101->id), 1).values.at(0), 0xD8F1);
    EXPECT_EQ(module.write(static_cast<std::uint16_t>(*a101->id), 0xD8F0).exception,
              exce::kWrongData); // -10000
}
