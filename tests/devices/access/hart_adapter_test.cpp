// HartAdapter against the simulated SD7 (devices/sim/hart_device.h, hart_server.h): command 0 in
// a short frame, then long frames to the unique id (HART-7 manual §2.3), commands 128..133 by the
// row's type (§4.4.1 table and examples), response codes and the communication-error byte
// (§4.4.1 "Status"), preambles, checksum, chunking.
#include "access/hart_adapter.h"
#include "access/hart_universal_rows.h"
#include "adapter_rig.h"
#include "dict/dictionary_loader.h"
#include "dict/identify.h"
#include "dsp408/pzd.h"
#include "hart/data_types.h"
#include "hart/texts.h"
#include "sim/dsp408_param_store.h"
#include "sim/hart_device.h"
#include "sim/hart_server.h"

#include <gtest/gtest.h>
#include <set>

using namespace vt::dev;
using namespace vt::dev::access;
using access::test::Rig;

namespace {

const Dictionary &sd7()
{
    return *builtinDictionaries()->find("wandfluh-sd7");
}

struct HartRig
{
    sim::SimClock clock;
    sim::HartDevice device;
    sim::HartServer server{device};
    HartAdapter adapter;
    Rig rig{adapter, server, clock};

    explicit HartRig(sim::HartDevice::Options options = {}, HartAdapterOptions adapterOptions = {})
        : device(sd7(), std::move(options)), adapter(adapterOptions)
    {
        clock.attach(device);
    }
    ~HartRig() { clock.detach(device); }

    void identify(int poll = 0)
    {
        ASSERT_TRUE(access::test::okReply(rig.run(adapter.planIdentify(poll).front())));
    }
    const ParamMeta &row(const char *name) { return *sd7().find(name); }
    Transaction readOf(const ParamMeta &r)
    {
        return Transaction{TransactionKind::Read, 0, {&r}, {}, 0, {}, true};
    }

    // What the device sends for `meta`: its stored value (the status word live), through the wire.
    double expected(const ParamMeta &meta)
    {
        double value = device.params().value(meta);
        if (meta.name == "db_StatusWord")
            value = device.drive().statusWord() |
                    (device.params().value("db_Local") != 0 ? dsp408::status::kLocal : 0);
        return sim::fromWireBits(meta, sim::toWireBits(meta, value));
    }

    // The ACK frame bytes the device would send to us (for crafted answers).
    Bytes response(std::uint8_t command, std::uint8_t code, Bytes data)
    {
        hart::Frame f =
            hart::makeResponse(*adapter.longAddressOf(0), command, code, 0, std::move(data));
        return hart::encodeFrame(f).value();
    }
};

} // namespace

TEST(HartAdapter, ReadsCannotBeAddressedBeforeCommand0)
{
    HartRig r;
    const auto plan = r.adapter.planRead(0, std::vector<const ParamMeta *>{&r.row("sol1_Imin")});
    ASSERT_EQ(plan.size(), 1u);
    EXPECT_FALSE(r.adapter.longAddressOf(0));
    EXPECT_TRUE(r.adapter.encode(plan.front()).empty());
    EXPECT_TRUE(r.adapter.encode(r.adapter.planWrite(0, r.row("sol1_Imin"), 450.0)).empty());
}

TEST(HartAdapter, IdentifiesByPollAddressThenUsesTheUniqueId)
{
    HartRig r;
    const auto plan = r.adapter.planIdentify(0);
    ASSERT_EQ(plan.size(), 1u);
    const auto request = hart::decodeFrame(r.adapter.encode(plan.front()));
    ASSERT_TRUE(request.ok());
    EXPECT_FALSE(request->address.isLong);
    EXPECT_EQ(request->command, 0);
    EXPECT_GE(request->preambles, 5u);
    const auto reply = access::test::okReply(r.rig.run(plan.front()));
    ASSERT_TRUE(reply);
    // HART-7 manual §3.4 / §6.4: Wandfluh 24835, SD733 58352; the simulator's device id.
    EXPECT_EQ(reply->identity.manufacturer, kWandfluhHartManufacturer);
    EXPECT_EQ(reply->identity.expandedDeviceType, 58352);
    EXPECT_EQ(reply->identity.deviceId, 2412345u);
    EXPECT_TRUE(reply->identity.text.complete()); // both languages
    EXPECT_NE(reply->identity.text.de.find("Geräte-ID"), std::string::npos);
    ASSERT_TRUE(r.adapter.longAddressOf(0));
    EXPECT_EQ(*r.adapter.longAddressOf(0), r.device.address());

    const auto read = hart::decodeFrame(r.adapter.encode(r.readOf(r.row("sol1_Imin"))));
    ASSERT_TRUE(read.ok());
    EXPECT_TRUE(read->address.isLong);
    EXPECT_EQ(read->command, hart::kReadWord);
}

TEST(HartAdapter, OtherPollAddressAndSecondaryMaster)
{
    sim::HartDevice::Options options;
    options.pollAddress = 3;
    HartRig r(options, HartAdapterOptions{false, 5, 20});
    EXPECT_FALSE(r.rig.run(r.adapter.planIdentify(0).front(), 1)); // nobody at 0
    const auto reply = access::test::okReply(r.rig.run(r.adapter.planIdentify(3).front()));
    ASSERT_TRUE(reply);
    Transaction read = r.readOf(r.row("sol1_Imin"));
    read.module = 3;
    EXPECT_TRUE(access::test::okReply(r.rig.run(read)));
    EXPECT_TRUE(r.adapter.encode(r.adapter.planIdentify(64).front()).empty());
}

TEST(HartAdapter, ReadsEveryParameterTheCommandsCanAddress)
{
    HartRig r;
    r.identify();
    std::vector<const ParamMeta *> rows;
    for (const ParamMeta &p : sd7().params)
        rows.push_back(&p);
    const auto plan = r.adapter.planRead(0, rows);
    std::vector<Transaction> byIndPnu;
    std::set<std::uint8_t> universalCommands;
    for (const Transaction &t : plan) {
        if (t.rows.front()->block == "hart") {
            // One universal command for all the fields it carries (HART-7 manual §5.1).
            const auto field = universalField(*t.rows.front());
            ASSERT_TRUE(field) << t.rows.front()->name;
            EXPECT_TRUE(universalCommands.insert(field->readCommand).second);
            for (const ParamMeta *row : t.rows)
                EXPECT_EQ(universalField(*row)->readCommand, field->readCommand) << row->name;
            continue;
        }
        ASSERT_EQ(t.rows.size(), 1u);
        EXPECT_TRUE(t.rows.front()->readable());
        EXPECT_FALSE(t.rows.front()->isString());
        EXPECT_LE(*t.rows.front()->pnu, 255);
        byIndPnu.push_back(t);
    }
    EXPECT_GT(byIndPnu.size(), 150u);
    // Commands 0, 2, 3, 7, 12, 13, 14, 15, 16, 20, 48.
    EXPECT_EQ(universalCommands, (std::set<std::uint8_t>{0, 2, 3, 7, 12, 13, 14, 15, 16, 20, 48}));
    const auto values = r.rig.readAll(byIndPnu);
    ASSERT_EQ(values.size(), byIndPnu.size());
    for (const auto &[row, value] : values)
        EXPECT_EQ(rawNumber(value), r.expected(*row)) << row->name;
    // Every universal field arrives too, the texts as texts.
    std::vector<Transaction> universal;
    for (const Transaction &t : plan)
        if (t.rows.front()->block == "hart")
            universal.push_back(t);
    for (const auto &[row, value] : r.rig.readAll(universal))
        EXPECT_EQ(isText(value), row->isString()) << row->name;
    EXPECT_EQ(std::get<std::string>(r.rig.readAll({r.readOf(r.row("hart_Tag"))}).front().second),
              "WAGSD733");
    // No readable row is left without an exchange (Read All would report it as a failure): the
    // field device status is status byte 2 of command 48's answer (HART-7 manual §4.4.1).
    std::set<const ParamMeta *> planned;
    for (const Transaction &t : plan)
        planned.insert(t.rows.begin(), t.rows.end());
    for (const ParamMeta &p : sd7().params) {
        if (p.readable()) {
            EXPECT_TRUE(planned.count(&p)) << p.name;
        }
    }
    const auto status = r.rig.readAll({r.readOf(r.row("hart_FieldDeviceStatus"))});
    ASSERT_EQ(status.size(), 1u);
    EXPECT_EQ(rawNumber(status.front().second), r.device.deviceStatus(true));
}

TEST(HartAdapter, WritesAsTheManualsExampleAndReadsBack)
{
    HartRig r;
    r.identify();
    const ParamMeta &imin = r.row("sol1_Imin");
    const Transaction write = r.adapter.planWrite(0, imin, 450.0);
    // HART-7 manual §4.4.1 example 1: command 131, FA 06 00 01 C2.
    const auto request = hart::decodeFrame(r.adapter.encode(write));
    ASSERT_TRUE(request.ok());
    EXPECT_EQ(request->command, 131);
    EXPECT_EQ(request->data, (Bytes{0xFA, 0x06, 0x00, 0x01, 0xC2}));
    const auto reply = access::test::okReply(r.rig.run(write));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->values, std::vector<RawValue>{450.0});
    EXPECT_EQ(r.device.params().value(imin), 450.0);
    const auto back = access::test::okReply(r.rig.run(r.readOf(imin)));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->values, std::vector<RawValue>{450.0});
}

TEST(HartAdapter, RefusalsAreDeviceExceptionsWithTheResponseCodeText)
{
    HartRig r;
    r.identify();
    // §4.4.1: "6 device specific error" for a value above the limit and a read-only row.
    for (const auto &[name, value] :
         {std::pair{"sol1_Imin", 20000.0}, std::pair{"db_StatusWord", 1.0}}) {
        const auto reply = r.rig.run(r.adapter.planWrite(0, r.row(name), value));
        ASSERT_TRUE(reply) << name;
        EXPECT_EQ(reply->status, ReplyStatus::DeviceException) << name;
        EXPECT_EQ(reply->exceptionCode, 6) << name;
        EXPECT_EQ(reply->exceptionText, hart::responseCodeText(6)) << name;
    }
    sim::HartDevice::Options common;
    common.commonResponseCodes = true;
    HartRig c(common);
    c.identify();
    const auto reply = c.rig.run(c.adapter.planWrite(0, c.row("sol1_Imin"), 20000.0));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->exceptionCode, 3);
    EXPECT_EQ(reply->exceptionText.en, "passed parameter too large");
    // Not representable in the row's type: not sent at all.
    EXPECT_TRUE(c.adapter.encode(c.adapter.planWrite(0, c.row("sol1_Imin"), 70000.0)).empty());
    EXPECT_TRUE(c.adapter.encode(c.adapter.planWrite(0, c.row("sol1_Imin"), 1.5)).empty());
}

TEST(HartAdapter, CommunicationErrorsWarningsAndFloats)
{
    HartRig r;
    r.identify();
    const ParamMeta &imin = r.row("sol1_Imin");
    const Transaction read = r.readOf(imin);
    // Status byte 1 with bit 7: the device saw a longitudinal parity error in our request.
    auto reply = r.adapter.feed(r.response(hart::kReadWord, 0x88, {}), read);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::DeviceException);
    EXPECT_EQ(reply->exceptionCode, 0x88);
    EXPECT_NE(reply->exceptionText.en.find("longitudinal parity error"), std::string::npos);
    EXPECT_NE(reply->exceptionText.de.find("Längsparitätsfehler"), std::string::npos);
    // Code 8 is a warning: the value is taken, the warning travels with it.
    reply = r.adapter.feed(r.response(hart::kReadWord, 8, {0xFA, 0x06, 0x00, 0x01, 0xC2}), read);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::Ok);
    EXPECT_EQ(reply->values, std::vector<RawValue>{450.0});
    EXPECT_EQ(reply->exceptionCode, 8);
    // A float row (IEEE 754, §2.3) and a signed byte.
    ParamMeta f;
    f.ind = 1;
    f.pnu = 2;
    f.type = RawType::Float32;
    const std::uint32_t bits = hart::bitsFromFloat(-1.5f);
    reply = r.adapter.feed(
        r.response(hart::kReadDoubleWord, 0,
                   {1, 2, 0, static_cast<std::uint8_t>(bits >> 24),
                    static_cast<std::uint8_t>(bits >> 16), static_cast<std::uint8_t>(bits >> 8),
                    static_cast<std::uint8_t>(bits)}),
        r.readOf(f));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->values, std::vector<RawValue>{-1.5});
    ParamMeta i8 = f;
    i8.type = RawType::Int8;
    reply = r.adapter.feed(r.response(hart::kReadByte, 0, {1, 2, 0, 0xFE}), r.readOf(i8));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->values, std::vector<RawValue>{-2.0});
    // The answer for another parameter, or from another device, does not answer this one.
    reply = r.adapter.feed(r.response(hart::kReadWord, 0, {0xFA, 0x07, 0x00, 0x01, 0xC2}), read);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::Mismatch);
    hart::Frame other = hart::makeResponse(hart::longAddress(58352, 7), hart::kReadWord, 0, 0,
                                           {0xFA, 0x06, 0, 1, 0xC2});
    reply = r.adapter.feed(hart::encodeFrame(other).value(), read);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->status, ReplyStatus::Mismatch);
}

TEST(HartAdapter, ChangedBytesAreNeverAccepted)
{
    HartRig r;
    r.identify();
    const ParamMeta &imin = r.row("sol1_Imin");
    ASSERT_TRUE(access::test::okReply(r.rig.run(r.adapter.planWrite(0, imin, 450.0))));
    const Transaction read = r.readOf(imin);
    const Bytes answer = r.rig.ask(r.adapter.encode(read));
    ASSERT_GT(answer.size(), 5u);
    // §2.3: the XOR checksum covers everything after the preambles; a changed preamble leaves
    // enough of them to synchronise on.
    for (std::uint8_t mask : {std::uint8_t{0x01}, std::uint8_t{0x80}, std::uint8_t{0xFF}})
        access::test::expectCorruptionRejected(
            r.adapter, answer, read, {450.0}, [](std::size_t i) { return i >= 5; }, {}, mask);
}

TEST(HartAdapter, SplitAndMergedFrames)
{
    HartRig r;
    r.identify();
    const ParamMeta &imin = r.row("sol1_Imin");
    const ParamMeta &imax = r.row("sol1_Imax");
    r.rig.chunk = 1;
    EXPECT_EQ(access::test::okReply(r.rig.run(r.readOf(imin)))->values.front(),
              RawValue{r.expected(imin)});
    r.rig.chunk = 3;
    EXPECT_EQ(access::test::okReply(r.rig.run(r.readOf(imax)))->values.front(),
              RawValue{r.expected(imax)});
    // Line noise, the answer for another parameter and the answer in one read.
    const Bytes other = r.rig.ask(r.adapter.encode(r.readOf(imax)));
    const Bytes answer = r.rig.ask(r.adapter.encode(r.readOf(imin)));
    Bytes merged{0x00, 0x13, 0xFF, 0x86};
    merged.insert(merged.end(), other.begin(), other.end());
    merged.insert(merged.end(), answer.begin(), answer.end());
    const auto reply = access::test::okReply(r.adapter.feed(merged, r.readOf(imin)));
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->values, std::vector<RawValue>{r.expected(imin)});
}
