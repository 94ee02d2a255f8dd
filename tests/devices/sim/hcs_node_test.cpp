// The simulated node's rules: answers only to changed request bytes (OPAT manual §1.5, DMA
// Profinet manual §1.4), CMD 15 multiplexing, its exceptions (missing module 5 / 8, duplicate
// addresses 12 (OPAT) / 6 (DMA, assumed), SNUM mismatch 7, output buffer too small 9, unknown
// command 1), CMD 3/6 to DMA modules beyond SADR 5, and makeNode.
#include "dict/dictionary_loader.h"
#include "hcs/telegram.h"
#include "sim/hcs_codes.h"
#include "sim/node_config.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::sim;

namespace {

std::unique_ptr<HcsNode> node(SimClock &clock, const char *family, std::size_t modules)
{
    auto made = makeNode(clock, family, modules);
    EXPECT_TRUE(made.ok()) << (made.ok() ? "" : made.error());
    return made.ok() ? std::move(made).value() : nullptr;
}

Bytes cyclic(hcs::Family family, std::uint8_t tadr, std::size_t modules, std::int16_t value = 0)
{
    hcs::CyclicRequest q{
        tadr, std::vector<hcs::ModuleSetpoints>(modules, hcs::ModuleSetpoints{0, value, 0})};
    return hcs::encode(q, family).value();
}

hcs::ExceptionResponse exceptionOf(const std::optional<TimedBytes> &answer, hcs::Family family)
{
    EXPECT_TRUE(answer);
    if (!answer)
        return {};
    auto decoded = hcs::decodeExceptionResponse(answer->bytes, {family, false});
    EXPECT_TRUE(decoded.ok()) << "not an exception response";
    return decoded.ok() ? *decoded : hcs::ExceptionResponse{};
}

} // namespace

TEST(NodeRules, AnswersOnlyWhenTheRequestBytesChanged)
{
    SimClock clock;
    auto n = node(clock, "dma-pn-v13", 2);
    const Bytes q = cyclic(hcs::Family::Dma, 0x23, 2, 1000);
    ASSERT_TRUE(n->process(q));
    EXPECT_FALSE(n->process(q)) << "same bytes: no answer";
    EXPECT_FALSE(n->process(q));
    EXPECT_EQ(n->nextCyclicAddress(2), 2) << "silence does not advance the multiplexer";
    auto a = n->process(cyclic(hcs::Family::Dma, 0x24, 2, 1000)); // TADR toggled
    ASSERT_TRUE(a);
    EXPECT_EQ(a->bytes.at(1), 2);
    auto b = n->process(cyclic(hcs::Family::Dma, 0x24, 2, 1500)); // data changed, same TADR
    ASSERT_TRUE(b);
    EXPECT_EQ(b->bytes.at(1), 1);
    // CMD 3 follows the same rule; another command in between counts as a change.
    const Bytes read = hcs::encode(hcs::ReadRequest{0x30, 1, 0, 1});
    EXPECT_TRUE(n->process(read));
    EXPECT_FALSE(n->process(read));
    n->resetChangeDetection();
    EXPECT_TRUE(n->process(read));
    // Configurable off, for a master that repeats on purpose.
    HcsNodeOptions o = n->options();
    o.answerOnlyOnChange = false;
    n->setOptions(o);
    EXPECT_TRUE(n->process(read));
}

TEST(NodeRules, Cmd15AddressesAndNodeExceptions)
{
    SimClock clock;
    auto dma = node(clock, "dma-pn-v51", 3);
    // SNUM 2 with three modules connected: "the number of present slaves has to be set properly".
    EXPECT_EQ(exceptionOf(dma->process(cyclic(hcs::Family::Dma, 1, 2)), hcs::Family::Dma),
              (hcs::ExceptionResponse{1, 0, 15, exce::kInvalidSlaveCount}));
    // SNUM 6: more than the DMA node's 5.
    Bytes six = cyclic(hcs::Family::Dma, 2, 5);
    six[1] = 6;
    six.resize(3 + 5 * 6, 0);
    EXPECT_EQ(exceptionOf(dma->process(six), hcs::Family::Dma).code, exce::kInvalidSlaveCount);
    // A telegram cut short: "output buffer too small", SADR 0 (DMA Profinet manual §4.3 code 9).
    Bytes cut = cyclic(hcs::Family::Dma, 3, 3);
    cut.resize(13);
    EXPECT_EQ(exceptionOf(dma->process(cut), hcs::Family::Dma),
              (hcs::ExceptionResponse{3, 0, 15, exce::kBufferTooSmall}));
    // The same with a configured output image of 13 bytes ("CMD15 2fold 9B-I 13B-O").
    HcsNodeOptions o;
    o.outputBufferBytes = 13;
    dma->setOptions(o);
    EXPECT_EQ(exceptionOf(dma->process(cyclic(hcs::Family::Dma, 4, 3)), hcs::Family::Dma).code,
              exce::kBufferTooSmall);
    dma->setOptions({});
    // Duplicate E22: modules 2 and 3 both at 2 → the DMA node's internal Modbus answers collide.
    dma->module(2).setAddress(2);
    EXPECT_EQ(exceptionOf(dma->process(cyclic(hcs::Family::Dma, 5, 3)), hcs::Family::Dma),
              (hcs::ExceptionResponse{5, 2, 15, exce::kChecksum}));
    EXPECT_EQ(
        exceptionOf(dma->process(hcs::encode(hcs::ReadRequest{6, 2, 0, 1})), hcs::Family::Dma).code,
        exce::kChecksum);
    dma->module(2).setAddress(3);
    EXPECT_EQ(exceptionOf(dma->process(cyclic(hcs::Family::Dma, 7, 2)), hcs::Family::Dma).code,
              exce::kInvalidSlaveCount);
    EXPECT_EQ(dma->process(cyclic(hcs::Family::Dma, 8, 3))->bytes.size(), 9u);
    // A module switched off is missing: "all slaves must be active (connected to the power
    // supply) … Otherwise … the node-module will respond with a timeout error" (§1.3).
    dma->module(1).setPowered(false);
    EXPECT_EQ(exceptionOf(dma->process(cyclic(hcs::Family::Dma, 9, 3)), hcs::Family::Dma),
              (hcs::ExceptionResponse{9, 2, 15, exce::kCyclicSlaveTimeout}));
    EXPECT_EQ(
        exceptionOf(dma->process(hcs::encode(hcs::ReadRequest{10, 2, 0, 1})), hcs::Family::Dma)
            .code,
        exce::kSlaveTimeout);
}

TEST(NodeRules, OpatDuplicateSlaveAddressesGet12)
{
    SimClock clock;
    auto opat = node(clock, "opat", 3);
    opat->module(2).setAddress(1); // two slaves on DIP switch 1
    EXPECT_EQ(exceptionOf(opat->process(cyclic(hcs::Family::Opat, 1, 3)), hcs::Family::Opat),
              (hcs::ExceptionResponse{1, 1, 15, exce::kDuplicateAddress}));
    EXPECT_EQ(
        exceptionOf(opat->process(hcs::encode(hcs::ReadRequest{2, 1, 0, 1})), hcs::Family::Opat),
        (hcs::ExceptionResponse{2, 1, 3, exce::kDuplicateAddress}));
    EXPECT_EQ(
        exceptionOf(opat->process(hcs::encode(hcs::WriteRequest{3, 1, 0x30, 1})), hcs::Family::Opat)
            .code,
        exce::kDuplicateAddress);
    // The master is not affected for CMD 3.
    EXPECT_EQ(opat->process(hcs::encode(hcs::ReadRequest{4, 0, 0, 1}))->bytes.size(), 6u);
}

TEST(NodeRules, ModuleExceptionsReachTheTelegram)
{
    SimClock clock;
    auto n = node(clock, "dma-pn-v51", 1);
    // CMD 3 with N = 9: "maximal 8 parameters readable at once" → 0x83 EXCE 3.
    EXPECT_EQ(exceptionOf(n->process(hcs::encode(hcs::ReadRequest{1, 1, 0, 9})), hcs::Family::Dma),
              (hcs::ExceptionResponse{1, 1, 3, exce::kBadCount}));
    // CMD 6 to d1.07 (read only) → 0x86 EXCE 2; C1.07 = 10.000 V (max 9.999 V) → EXCE 3.
    EXPECT_EQ(
        exceptionOf(n->process(hcs::encode(hcs::WriteRequest{2, 1, 0x07, 0})), hcs::Family::Dma)
            .code,
        exce::kWrongId);
    EXPECT_EQ(
        exceptionOf(n->process(hcs::encode(hcs::WriteRequest{3, 1, 0x30, 10000})), hcs::Family::Dma)
            .code,
        exce::kWrongData);
    // CMD 15 VALUE1 out of range → 0x8F EXCE 3 from that module.
    EXPECT_EQ(exceptionOf(n->process(cyclic(hcs::Family::Dma, 4, 1, 12000)), hcs::Family::Dma),
              (hcs::ExceptionResponse{4, 1, 15, exce::kWrongData}));
    // An unknown command → EXCE 1 "command not supported"; an all-zero image → silence.
    EXPECT_EQ(n->process(Bytes{5, 1, 0x10, 0, 0, 0, 0})->bytes,
              (Bytes{5, 1, 0x90, exce::kCommandNotSupported}));
    EXPECT_FALSE(n->process(Bytes(42, 0)));
    EXPECT_FALSE(n->process(Bytes{1, 2}));
}

TEST(NodeRules, DmaModulesBeyondFiveOnlyByCmd3And6)
{
    SimClock clock;
    auto n = node(clock, "dma-pn-v51", 1);
    HcsModuleConfig c = n->module(0).config();
    c.address = 7; // "another slave (module) with address E22 greater than 5 is only actuated
                   // either by CMD = 3 or CMD = 6" (DMA Profinet manual §1.5)
    n->addModule(c);
    EXPECT_EQ(n->process(hcs::encode(hcs::ReadRequest{1, 7, 0, 1}))->bytes.size(), 6u);
    EXPECT_EQ(n->process(hcs::encode(hcs::WriteRequest{2, 7, 0x1F, 500}))->bytes.size(), 7u);
    EXPECT_EQ(n->module(1).storage().get("A1.01"), 500);
    // CMD 15 for module 1 alone is complete: module 7 does not count.
    EXPECT_EQ(n->process(cyclic(hcs::Family::Dma, 3, 1))->bytes.size(), 9u);
    // E22 written over the bus moves the module.
    ASSERT_EQ(n->process(hcs::encode(hcs::WriteRequest{4, 7, 0xA3, 9}))->bytes.size(), 7u);
    EXPECT_EQ(n->module(1).address(), 9);
    EXPECT_EQ(
        exceptionOf(n->process(hcs::encode(hcs::ReadRequest{5, 7, 0, 1})), hcs::Family::Dma).code,
        exce::kSlaveTimeout);
}

TEST(NodeRules, DelayedEepromWriteIsAnsweredLater)
{
    SimClock clock;
    NodeConfig config;
    config.family = "dma-pn-v51";
    config.moduleTemplate.eepromBusy = EepromBusyPolicy::Delay;
    auto made = makeNode(clock, config);
    ASSERT_TRUE(made.ok());
    HcsNode &n = **made;
    EXPECT_EQ(n.process(hcs::encode(hcs::WriteRequest{1, 1, 0x30, 1000}))->readyAtUs, 0);
    EXPECT_EQ(n.process(hcs::encode(hcs::WriteRequest{2, 1, 0x31, 1000}))->readyAtUs, 25'000);
}

TEST(NodeRules, MakeNodeByFamily)
{
    SimClock clock;
    auto opat = node(clock, "opat", 8);
    ASSERT_TRUE(opat);
    EXPECT_EQ(opat->family(), hcs::Family::Opat);
    EXPECT_EQ(opat->module(0).address(), 0);
    EXPECT_EQ(opat->module(7).address(), 7);
    EXPECT_EQ(opat->module(7).storage().get("E22"), 7);
    auto pb = node(clock, "dma-pb-v32", 32);
    ASSERT_TRUE(pb);
    EXPECT_EQ(pb->module(31).address(), 32);
    EXPECT_EQ(pb->module(0).version(), "32");
    EXPECT_EQ(pb->module(0).mode(), 3);
    EXPECT_EQ(pb->module(0).profile(), hcs::Profile::DmaV32Mode34);
    auto v22 = node(clock, "dma-pb-v22", 1);
    ASSERT_TRUE(v22);
    EXPECT_EQ(v22->module(0).profile(), hcs::Profile::DmaV22Mode2);
    EXPECT_TRUE(v22->module(0).openLoop(2));

    // Duplicate addresses configured from the start: the node's fault, not a refusal to build.
    NodeConfig dup;
    dup.family = "dma-pn-v13";
    dup.modules = 3;
    dup.addresses = {1, 2, 2};
    auto faulty = makeNode(clock, dup);
    ASSERT_TRUE(faulty.ok());
    EXPECT_EQ((*faulty)->modulesAt(2).size(), 2u);
    auto answer = (*faulty)->process(cyclic(hcs::Family::Dma, 1, 3));
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->bytes, (Bytes{1, 2, 0x8F, exce::kChecksum}));
    dup.addresses = {1, 2};
    EXPECT_FALSE(makeNode(clock, dup).ok());

    EXPECT_FALSE(makeNode(clock, "opat", 9).ok());
    EXPECT_FALSE(makeNode(clock, "dma-pn-v51", 0).ok());
    EXPECT_FALSE(makeNode(clock, "wandfluh-ed1", 1).ok());
    EXPECT_FALSE(makeNode(clock, "dma-pn-common", 1).ok());
    NodeConfig bad;
    bad.family = "dma-pn-v51";
    bad.mode = 1;
    EXPECT_FALSE(makeNode(clock, bad).ok());
    const auto &set = builtinDictionaries();
    ASSERT_TRUE(set.ok());
    EXPECT_EQ(simulatedFamilies(*set),
              (std::vector<std::string>{"dma-pb-v15", "dma-pb-v22", "dma-pb-v32", "dma-pn-v13",
                                        "dma-pn-v51", "opat"}));
}
