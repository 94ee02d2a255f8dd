// The manuals' worked examples replayed against a simulated node: the request bytes from the
// manual go in; the answer must have the manual's structure, TADR, SADR sequence and status
// word, with VALUE1 / VALUE2 from the plant (OPAT manual §2.3, §2.6, §2.7, §3.3, §3.4.1, §3.4.2;
// DMA Profinet manual = DMA Profibus Anleitung §3.3, §3.6, §3.7, §4.3, §4.4.1, §4.4.2).
// Status word: the examples print 0x40 for "Hardware Enable is active"; the bit tables, ID 0xB0
// and recorded telegrams say 0x04 (docs/protocol-notes/hcs-modbus-profidrive.md §5), which the
// simulator sends: withTableStatus() makes that one repair to the manual's bytes.
#include "../hcs/worked_examples.h"
#include "hcs/telegram.h"
#include "sim/node_config.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::sim;
using namespace vt::test::hcs_examples;

namespace {

std::unique_ptr<HcsNode> node(SimClock &clock, const char *family, std::size_t modules)
{
    auto made = makeNode(clock, family, modules);
    EXPECT_TRUE(made.ok()) << (made.ok() ? "" : made.error());
    return made.ok() ? std::move(made).value() : nullptr;
}

Bytes withTadr(Bytes request, std::uint8_t tadr)
{
    request.at(0) = tadr;
    return request;
}

// The manual's 9-byte CMD 15 answer with the status high byte per the bit tables (0x40 → 0x04)
// and VALUE1 / VALUE2 as the module that answered has them now.
Bytes expectedCyclic(Bytes manual, const HcsModule &module)
{
    EXPECT_EQ(manual.at(3), 0x40) << "the examples print 0x40 for HW_ENABLE";
    manual.at(3) = 0x04;
    const CyclicValues v = module.cyclicValues();
    manual.at(5) = static_cast<std::uint8_t>(static_cast<std::uint16_t>(v.value1) >> 8);
    manual.at(6) = static_cast<std::uint8_t>(v.value1);
    manual.at(7) = static_cast<std::uint8_t>(static_cast<std::uint16_t>(v.value2) >> 8);
    manual.at(8) = static_cast<std::uint8_t>(v.value2);
    return manual;
}

std::int16_t value(const Bytes &answer, std::size_t at)
{
    return static_cast<std::int16_t>((answer.at(at) << 8) | answer.at(at + 1));
}

Bytes answer(HcsNode &n, const Bytes &request)
{
    auto a = n.process(request);
    EXPECT_TRUE(a.has_value()) << "no answer";
    return a ? a->bytes : Bytes{};
}

constexpr std::int64_t kCycleUs = 100'000; // a slow PLC cycle: the plant settles in between

} // namespace

TEST(NodeCmd15Examples, DmaProfinetSec4_4_1_SingleModule)
{
    SimClock clock;
    auto n = node(clock, "dma-pn-v13", 1);
    ASSERT_TRUE(n);
    const Bytes a = answer(*n, kDma441Request);
    EXPECT_EQ(a, expectedCyclic(kDma441Response, n->module(0)));
    EXPECT_EQ(n->module(0).storage().get("A1.01"), 1000);
    // The answer a PLC cycle later (TADR toggled to force it): 1.000 V of the 2.7 A solenoid.
    clock.advance(kCycleUs);
    const Bytes later = answer(*n, withTadr(kDma441Request, 0x24));
    EXPECT_EQ(later, expectedCyclic(withTadr(kDma441Response, 0x24), n->module(0)));
    EXPECT_NEAR(value(later, 5) + value(later, 7),
                value(kDma441Response, 5) + value(kDma441Response, 7), 3)
        << "0.270 A in total; the manual shows it on solenoid B, the plant drives A for a positive "
           "value (docs/SIMULATOR.md)";
}

TEST(NodeCmd15Examples, DmaProfinetSec4_4_2_ThreeModulesMultiplexed)
{
    SimClock clock;
    auto n = node(clock, "dma-pn-v13", 3);
    ASSERT_TRUE(n);
    // "module 1 answers first", then 2, 3 and 1 again as TADR changes 0x23 → 0x26.
    const Bytes *manual[] = {&kDma442Response1, &kDma442Response2, &kDma442Response3,
                             &kDma442Response1Again};
    const std::uint8_t sadr[] = {1, 2, 3, 1};
    for (std::size_t i = 0; i < 4; ++i) {
        const auto tadr = static_cast<std::uint8_t>(0x23 + i);
        const Bytes a = answer(*n, withTadr(kDma442Request, tadr));
        ASSERT_EQ(a.size(), 9u);
        EXPECT_EQ(a.at(1), sadr[i]);
        EXPECT_EQ(a, expectedCyclic(*manual[i], n->module(sadr[i] - 1u))) << "answer " << i;
        if (i > 0) { // the plant has had a cycle to drive the current
            EXPECT_NEAR(value(a, 5) + value(a, 7), value(*manual[i], 5) + value(*manual[i], 7), 3)
                << "answer " << i;
        }
        clock.advance(kCycleUs);
    }
    // The set values went to all three modules at once ("immediately forwarded to all slaves").
    EXPECT_EQ(n->module(0).storage().get("A1.01"), 1000);
    EXPECT_EQ(n->module(1).storage().get("A1.01"), 2000);
    EXPECT_EQ(n->module(2).storage().get("A1.01"), -3000);
}

TEST(NodeCmd15Examples, OpatSec3_4_1_MasterOnly)
{
    SimClock clock;
    auto n = node(clock, "opat", 1);
    ASSERT_TRUE(n);
    EXPECT_EQ(answer(*n, kOpat341Request), expectedCyclic(kOpat341Response, n->module(0)));
    clock.advance(kCycleUs);
    const Bytes later = answer(*n, withTadr(kOpat341Request, 0x24));
    EXPECT_EQ(later, expectedCyclic(withTadr(kOpat341Response, 0x24), n->module(0)));
    // VALUE2 = d1.10, the internal set value: 1.000 V (no ramps by default). VALUE1 = d1.11 comes
    // from A1.02 = 0 (C1.09 = 0, feedback via the bus); the manual prints 1000 and 0 the other way
    // round (docs/SIMULATOR.md).
    EXPECT_EQ(value(later, 7), 1000);
    EXPECT_EQ(value(later, 5), 0);
}

TEST(NodeCmd15Examples, OpatSec3_4_2_MasterAndTwoSlavesMultiplexed)
{
    SimClock clock;
    auto n = node(clock, "opat", 3);
    ASSERT_TRUE(n);
    // "the OPAT-master … will respond first … slave 1 … slave 2 … Than it starts again with the
    // master address 0."
    const Bytes *manual[] = {&kOpat342ResponseMaster, &kOpat342ResponseSlave1,
                             &kOpat342ResponseSlave2, &kOpat342ResponseMasterAgain};
    const std::uint8_t sadr[] = {0, 1, 2, 0};
    const std::int16_t setValue[] = {1000, 2000, -3000, 1000};
    for (std::size_t i = 0; i < 4; ++i) {
        const auto tadr = static_cast<std::uint8_t>(0x23 + i);
        const Bytes a = answer(*n, withTadr(kOpat342Request, tadr));
        ASSERT_EQ(a.size(), 9u);
        EXPECT_EQ(a.at(0), tadr);
        EXPECT_EQ(a.at(1), sadr[i]);
        EXPECT_EQ(a, expectedCyclic(*manual[i], n->module(sadr[i]))) << "answer " << i;
        if (i > 0) {
            EXPECT_EQ(value(a, 7), setValue[i]) << "d1.10 of SADR " << int(sadr[i]);
        }
        clock.advance(kCycleUs);
    }
    EXPECT_EQ(n->module(0).version(), "34");
    EXPECT_EQ(n->module(1).version(), "31");
}

TEST(NodeCmd15Examples, ErrorExamplesModuleThreeNotInstalled)
{
    SimClock clock;
    auto dma = node(clock, "dma-pn-v13", 2);
    auto opat = node(clock, "opat", 3);
    ASSERT_TRUE(dma && opat);
    // DMA Profinet manual §3.3 / §3.6: SADR 3 not installed → 0x83 / 0x86, EXCE 5.
    EXPECT_EQ(answer(*dma, hcs::encode(hcs::ReadRequest{0x23, 3, 0x0007, 1})), kDma33ReadError);
    EXPECT_EQ(answer(*dma, hcs::encode(hcs::WriteRequest{0x23, 3, 0x0030, 1000})),
              kDma36WriteError);
    // §4.3: "Module 3 is not installed and SNUM in the master telegram is set to 3" → EXCE 8.
    auto snum3 = hcs::encode(hcs::CyclicRequest{0x23, {{}, {}, {}}}, hcs::Family::Dma);
    ASSERT_TRUE(snum3.ok());
    EXPECT_EQ(answer(*dma, *snum3), kDma43CyclicError);
    // OPAT manual §2.3 / §2.6 / §3.3: the same with slave 3 of a master with slaves 1 and 2.
    EXPECT_EQ(answer(*opat, hcs::encode(hcs::ReadRequest{0x23, 3, 0x0007, 1})), kOpat23ReadError);
    EXPECT_EQ(answer(*opat, hcs::encode(hcs::WriteRequest{0x23, 3, 0x0030, 1000})),
              kOpat26WriteError);
    auto opatSnum3 = hcs::encode(hcs::CyclicRequest{0x23, {{}, {}, {}, {}}}, hcs::Family::Opat);
    ASSERT_TRUE(opatSnum3.ok());
    EXPECT_EQ(answer(*opat, *opatSnum3), kOpat33CyclicError);
}

TEST(NodeCmd15Examples, Sec3_7_WriteC107AndReadD107)
{
    for (const char *family : {"dma-pn-v51", "opat"}) {
        SimClock clock;
        auto n = node(clock, family, 1);
        ASSERT_TRUE(n);
        const bool opat = std::string(family) == "opat";
        // DMA manuals §3.7 / OPAT manual §2.7: the write is echoed.
        const Bytes &write = opat ? kOpat27Write : kDma37Write;
        EXPECT_EQ(answer(*n, write), write) << family;
        EXPECT_EQ(n->module(0).storage().get("C1.07"), 1000) << family;
        // Read d1.07: the manual's structure, the value from the plant.
        const Bytes &manual = opat ? kOpat27ReadResponse : kDma37ReadResponse;
        const Bytes a = answer(*n, opat ? kOpat27ReadRequest : kDma37ReadRequest);
        ASSERT_EQ(a.size(), manual.size()) << family;
        EXPECT_TRUE(std::equal(manual.begin(), manual.begin() + 4, a.begin())) << family;
        EXPECT_EQ(value(a, 4), n->module(0).storage().get("d1.07")) << family;
    }
}

TEST(NodeCmd15Examples, StatusWordFollowsTheHardwareEnableAndBusDisable)
{
    SimClock clock;
    auto n = node(clock, "dma-pn-v13", 1);
    ASSERT_TRUE(n);
    n->module(0).setHardwareEnable(false);
    Bytes a = answer(*n, kDma441Request);
    EXPECT_EQ(a.at(3), 0x00) << "no HW_ENABLE";
    clock.advance(kCycleUs);
    a = answer(*n, withTadr(kDma441Request, 0x24));
    EXPECT_EQ(value(a, 5) + value(a, 7), 0) << "no current without the enable";
    n->module(0).setHardwareEnable(true);
    // Control byte 0x80: BUS_DISABLE (DMA Profinet manual §4.5.2) → status 0x84 00, outputs off.
    Bytes q = withTadr(kDma441Request, 0x25);
    q.at(3) = 0x80;
    a = answer(*n, q);
    EXPECT_EQ(a.at(3), 0x84);
    EXPECT_EQ(a.at(4), 0x00);
}
