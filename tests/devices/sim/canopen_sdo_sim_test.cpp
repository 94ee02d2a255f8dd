// CANopen SDO server of the simulators (devices/sim/canopen_sdo_server.h) on SocketCAN frame
// images: expedited upload / download on 0x600 + node → 0x580 + node (CiA 301 §7.2.4.3,
// ARCHITECTURE.md "CAN"), the ED1's CiA 408 objects from the dictionary's canopen fields
// (0x6040 control word, 0x6041 status word, …) and the HCS manufacturer objects 0x2000 + ID, with
// the CiA 301 §7.2.4.3.17 abort codes.
#include "canopen/can_frame.h"
#include "canopen/sdo.h"
#include "sim/canopen_dsp408_objects.h"
#include "sim/canopen_hcs_objects.h"
#include "sim/canopen_sdo_server.h"
#include "sim/dsp408_device.h"
#include "sim/param_io.h"
#include "sim/sim_clock.h"
#include "sim_dictionaries.h"

#include <gtest/gtest.h>
#include <optional>

using namespace vt::dev;
using namespace vt::dev::sim;
using canopen::Sdo;
using canopen::SdoCommand;

namespace {

constexpr std::uint8_t kNode = 5;

// A client on the bus: SDO requests as SocketCAN images in, the server's answers decoded.
struct SdoClient
{
    CanopenSdoServer &server;

    std::optional<canopen::SdoMessage> transact(const Sdo &request, std::uint8_t node = kNode)
    {
        auto frame = canopen::toCanFrame(request, node);
        EXPECT_TRUE(frame.ok());
        const auto image = canopen::toSocketCan(*frame);
        server.receive(image);
        const auto out = server.drain();
        if (out.empty())
            return std::nullopt;
        EXPECT_EQ(out.size(), canopen::kSocketCanFrameSize);
        auto can = canopen::fromSocketCan(out);
        EXPECT_TRUE(can.ok());
        EXPECT_EQ(can->id, 0x580u + node); // response COB-ID
        auto msg = canopen::fromCanFrame(*can);
        EXPECT_TRUE(msg.ok());
        return msg.ok() ? std::optional<canopen::SdoMessage>(*msg) : std::nullopt;
    }

    Sdo upload(std::uint16_t index, std::uint8_t sub)
    {
        auto msg = transact(canopen::uploadRequest(index, sub));
        EXPECT_TRUE(msg.has_value());
        return msg ? msg->sdo : Sdo{};
    }

    Sdo download(std::uint16_t index, std::uint8_t sub, std::uint32_t value, std::size_t bytes)
    {
        auto msg = transact(canopen::expeditedDownload(index, sub, value, bytes));
        EXPECT_TRUE(msg.has_value());
        return msg ? msg->sdo : Sdo{};
    }

    static std::optional<std::uint32_t> abortCode(const Sdo &sdo)
    {
        return sdo.command == SdoCommand::Abort ? std::optional<std::uint32_t>(sdo.abortCode)
                                                : std::nullopt;
    }
};

struct Ed1Rig
{
    Dsp408Device device{test::family("wandfluh-ed1")};
    Dsp408Objects objects{device};
    CanopenSdoServer server{objects, kNode};
    SdoClient client{server};
    SimClock clock;

    Ed1Rig() { clock.attach(device); }
};

} // namespace

// Expedited upload of 0x6041 (db_StatusWord): 2 bytes, little-endian, size indicated; the state
// machine walked with expedited downloads of 0x6040 (db_ControlWord).
TEST(CanopenSimSdo, ExpeditedUploadOfStatusWordFollowsControlWordDownloads)
{
    Ed1Rig rig;
    Sdo rsp = rig.client.upload(0x6041, 0);
    ASSERT_EQ(rsp.command, SdoCommand::InitiateUploadResponse);
    EXPECT_TRUE(rsp.expedited);
    EXPECT_TRUE(rsp.sizeIndicated);
    EXPECT_EQ(rsp.index, 0x6041);
    EXPECT_EQ(rsp.subindex, 0);
    EXPECT_EQ(rsp.data.size(), 2u);
    EXPECT_EQ(canopen::expeditedValue(rsp), 0x0000u); // NOT_READY

    rig.clock.advance(50'000);
    EXPECT_EQ(canopen::expeditedValue(rig.client.upload(0x6041, 0)), 0x0008u); // INIT
    for (const std::uint32_t cw : {0x0001u, 0x0003u, 0x0007u}) {
        rsp = rig.client.download(0x6040, 0, cw, 2);
        ASSERT_EQ(rsp.command, SdoCommand::InitiateDownloadResponse) << cw;
        EXPECT_EQ(rsp.index, 0x6040);
    }
    EXPECT_EQ(rig.device.state(), dsp408::State::DeviceModeActive);
    EXPECT_EQ(canopen::expeditedValue(rig.client.upload(0x6041, 0)) & 0x000F, 0x000Fu);

    // The wire bytes of the upload request and response (CiA 301: little-endian index).
    auto request = canopen::toCanFrame(canopen::uploadRequest(0x6041, 0), kNode);
    ASSERT_TRUE(request.ok());
    EXPECT_EQ(canopen::formatCandump(*request), "605#4041600000000000");
}

TEST(CanopenSimSdo, DownloadToReadOnlyObjectAbortsWith06010002)
{
    Ed1Rig rig;
    const Sdo rsp = rig.client.download(0x6041, 0, 0x000F, 2);
    EXPECT_EQ(SdoClient::abortCode(rsp), 0x06010002u);
    EXPECT_EQ(rsp.index, 0x6041);
    EXPECT_EQ(SdoClient::abortCode(rig.client.download(0x6601, 1, 10, 4)),
              0x06010002u); // actual value
    EXPECT_EQ(SdoClient::abortCode(rig.client.download(0x1000, 0, 1, 4)), 0x06010002u);
}

// Value range: CiA 301 0x06090031 "value written too high" / 0x06090032 "too low" (the specific
// codes of the 0x0609003x family).
TEST(CanopenSimSdo, OutOfRangeDownloadsAbortWithValueRangeCodes)
{
    Ed1Rig rig;
    EXPECT_EQ(SdoClient::abortCode(rig.client.download(0x6600, 1, 5000, 4)),
              0x06090031u); // 0 … 4096
    EXPECT_EQ(SdoClient::abortCode(rig.client.download(0x6043, 0, 12, 1)), 0x06090031u); // 6 … 9
    EXPECT_EQ(SdoClient::abortCode(rig.client.download(0x6043, 0, 5, 1)), 0x06090032u);
    EXPECT_EQ(SdoClient::abortCode(rig.client.download(0x6042, 0, 0xFF, 1)),
              0x06090032u); // int8 −1
    EXPECT_EQ(rig.device.params().value("db_ControlMode"), 9);
    // In range and in a configurable state: accepted, and visible through PKW's storage too.
    EXPECT_EQ(rig.client.download(0x6043, 0, 6, 1).command, SdoCommand::InitiateDownloadResponse);
    EXPECT_EQ(rig.device.params().value("db_ControlMode"), 6);
    EXPECT_EQ(canopen::expeditedValue(rig.client.upload(0x6043, 0)), 6u);
}

TEST(CanopenSimSdo, ObjectSubindexLengthAndAccessAborts)
{
    Ed1Rig rig;
    EXPECT_EQ(SdoClient::abortCode(rig.client.upload(0x6044, 0)), 0x06020000u); // no object
    EXPECT_EQ(SdoClient::abortCode(rig.client.upload(0x6600, 2)), 0x06090011u); // no sub-index
    EXPECT_EQ(SdoClient::abortCode(rig.client.upload(0x6040, 0)), 0x06010001u); // write-only
    EXPECT_EQ(SdoClient::abortCode(rig.client.download(0x6040, 0, 1, 4)),
              0x06070012u); // 4 bytes to uint16
    EXPECT_EQ(SdoClient::abortCode(rig.client.download(0x6600, 1, 1, 2)),
              0x06070013u); // 2 bytes to int32
    // The device state: modes only in INIT / DISABLED.
    rig.clock.advance(50'000);
    rig.client.download(0x6040, 0, 7, 2);
    EXPECT_EQ(SdoClient::abortCode(rig.client.download(0x6043, 0, 6, 1)), 0x08000022u);
    // CiA 301 0x1000 device type: profile 408.
    EXPECT_EQ(canopen::expeditedValue(rig.client.upload(0x1000, 0)), 408u);
    // Segmented download and block transfer are not served.
    Sdo segmented;
    segmented.command = SdoCommand::InitiateDownloadRequest;
    segmented.index = 0x6043;
    segmented.sizeIndicated = true;
    segmented.size = 10;
    EXPECT_EQ(SdoClient::abortCode(rig.client.transact(segmented)->sdo), 0x06070012u);
}

TEST(CanopenSimSdo, OtherNodesAndIdsAreIgnoredAndImagesMayBeSplit)
{
    Ed1Rig rig;
    EXPECT_FALSE(rig.client.transact(canopen::uploadRequest(0x6041, 0), 6));
    // The server's own response id is not a request.
    const auto echo = canopen::toSocketCan(canopen::makeCanFrame(0x585, Bytes(8, 0)));
    rig.server.receive(echo);
    EXPECT_TRUE(rig.server.drain().empty());
    EXPECT_EQ(rig.server.framesIgnored(), 2u);
    // A client abort is not answered.
    EXPECT_FALSE(rig.client.transact(canopen::abortTransfer(0x6041, 0, 0x08000000)));

    auto frame = canopen::toCanFrame(canopen::uploadRequest(0x6041, 0), kNode);
    const auto image = canopen::toSocketCan(*frame);
    rig.server.receive(std::span<const std::uint8_t>(image).first(7));
    EXPECT_TRUE(rig.server.drain().empty());
    rig.server.receive(std::span<const std::uint8_t>(image).subspan(7));
    EXPECT_EQ(rig.server.drain().size(), canopen::kSocketCanFrameSize);
}

// HCS parameters as manufacturer objects 0x2000 + ID, sub 0 (ARCHITECTURE.md "CAN"), over any
// ParamSource/ParamSink image; here the DMA-2 PROFINET V51 dictionary with a ParamMemory.
TEST(CanopenSimHcsObjects, ManufacturerObjectsByParameterId)
{
    const Dictionary &dict = test::family("dma-pn-v51");
    ParamMemory memory(dict);
    HcsParamObjects objects(dict, memory, memory);
    CanopenSdoServer server(objects, 1);
    SdoClient client{server};
    auto transact = [&](const Sdo &sdo) { return client.transact(sdo, 1)->sdo; };

    const ParamMeta *c103 = dict.find("C1.03");
    ASSERT_NE(c103, nullptr);
    const auto index = static_cast<std::uint16_t>(0x2000 + *c103->id);
    Sdo rsp = transact(canopen::uploadRequest(index, 0));
    ASSERT_EQ(rsp.command, SdoCommand::InitiateUploadResponse);
    EXPECT_EQ(rsp.data.size(), 2u);
    EXPECT_EQ(canopen::expeditedValue(rsp), 100u); // default factor 1.00
    EXPECT_EQ(transact(canopen::expeditedDownload(index, 0, 150, 2)).command,
              SdoCommand::InitiateDownloadResponse);
    EXPECT_EQ(memory.get("C1.03"), 150);
    EXPECT_EQ(SdoClient::abortCode(transact(canopen::expeditedDownload(index, 0, 201, 2))),
              0x06090031u);
    EXPECT_EQ(SdoClient::abortCode(transact(canopen::expeditedDownload(index, 0, 1, 4))),
              0x06070012u);
    EXPECT_EQ(SdoClient::abortCode(transact(canopen::uploadRequest(index, 1))), 0x06090011u);

    const ParamMeta *d101 = dict.find("d1.01");
    ASSERT_NE(d101, nullptr);
    EXPECT_EQ(SdoClient::abortCode(transact(canopen::expeditedDownload(
                  static_cast<std::uint16_t>(0x2000 + *d101->id), 0, 1, 2))),
              0x06010002u);
    const ParamMeta *s108 = dict.find("S1.08"); // access x: not an object
    ASSERT_NE(s108, nullptr);
    EXPECT_EQ(SdoClient::abortCode(transact(
                  canopen::uploadRequest(static_cast<std::uint16_t>(0x2000 + *s108->id), 0))),
              0x06020000u);
    // Signed rows: 0xFFFF is −1; C1.05 allows −400 … .
    const ParamMeta *c105 = dict.find("C1.05");
    ASSERT_NE(c105, nullptr);
    const auto i105 = static_cast<std::uint16_t>(0x2000 + *c105->id);
    EXPECT_EQ(transact(canopen::expeditedDownload(i105, 0, 0xFFFF, 2)).command,
              SdoCommand::InitiateDownloadResponse);
    EXPECT_EQ(memory.get("C1.05"), -1);
    EXPECT_EQ(canopen::expeditedValue(transact(canopen::uploadRequest(i105, 0))), 0xFFFFu);
}
