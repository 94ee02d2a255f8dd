// Cross-check of our HART frames against Wireshark's HART-IP dissector: each frame is wrapped in
// a HART-IP pass-through message (UDP port 5094, linktype raw IPv4) and tshark's view of the
// link layer and of the typed universal payloads must equal ours. Skips without tshark.
#include "core/hex.h"
#include "hart/data_types.h"
#include "hart/frame.h"
#include "hart/universal.h"
#include "tshark_support.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::hart;
using vt::test::lower;
using vt::test::number;

namespace {

constexpr std::uint16_t kHartIpPort = 5094;

// HART-IP header (version 1, message type 0 request / 1 response, id 3 pass-through, status 0,
// sequence number, total length) + the HART PDU.
Bytes hartIp(const Bytes &pdu, bool response, std::uint16_t sequence)
{
    ByteWriter w;
    w.u8(1)
        .u8(response ? 1 : 0)
        .u8(3)
        .u8(0)
        .u16be(sequence)
        .u16be(static_cast<std::uint16_t>(8 + pdu.size()));
    w.bytes(pdu);
    return w.take();
}

Identity sd733()
{
    Identity id;
    id.expandedDeviceType = 0xE3F0;
    id.deviceRevision = 1;
    id.softwareRevision = 2;
    id.hardwareRevisionAndSignaling = 0x08;
    id.deviceId = 0x123456;
    id.maxDeviceVariables = 4;
    id.configChangeCounter = 3;
    id.manufacturerId = 24835;
    id.privateLabel = 24835;
    id.deviceProfile = 1;
    return id;
}

struct Case
{
    std::string name;
    Frame frame;
};

std::vector<Case> cases()
{
    const Address sd = longAddress(0xE3F0, 0x123456);
    DynamicVariables dv{12.0f, {{49, 250.5f}, {57, 50.0f}, {39, 4.0f}, {7, -1.25f}}};
    return {
        {"cmd0 request, short frame", makeRequest(shortAddress(0), 0)},
        {"cmd0 response", makeResponse(shortAddress(0), 0, 0, 0, encodePayload(sd733()))},
        {"§4.4.1 example 1 request", makeRequest(sd, 131, {0xFA, 0x06, 0x00, 0x01, 0xC2})},
        {"§4.4.1 example 1 response", makeResponse(sd, 131, 0, 0, {0xFA, 0x06, 0x00, 0x01, 0xC2})},
        {"§4.4.1 example 2 request", makeRequest(sd, 132, {0xEE, 0x08, 0x00})},
        {"§4.4.1 example 2 response",
         makeResponse(sd, 132, 0, 0, {0xEE, 0x08, 0x00, 0x00, 0x00, 0x00, 0x50})},
        {"cmd1 response", makeResponse(sd, 1, 0, 0x40, encodePayload(UnitValue{39, 20.0f}))},
        {"cmd3 response", makeResponse(sd, 3, 0, 0, encodePayload(dv))},
        {"cmd13 response", makeResponse(sd, 13, 0, 0,
                                        encodePayload(TagDescriptorDate{
                                            "WAGSD733", "WAG ELECTRONIC", {17, 3, 124}}))},
        {"rc 5 with status bits", makeResponse(sd, 131, 5, 0x30)},
    };
}

const std::vector<std::string> kFields{
    "hart_ip.pt.command",
    "hart_ip.pt.length",
    "hart_ip.pt.response_code",
    "hart_ip.pt.device_status",
    "hart_ip.pt.checksum",
    "hart_ip.pt.long_address",
    "hart_ip.pt.short_addr",
    "hart_ip.pt.payload",
    "hart_ip.pt.rsp.device_id",
    "hart_ip.pt.rsp.manufacturer_Id",
    "hart_ip.pt.rsp.expanded_device_type",
    "hart_ip.pt.rsp.pv_units",
    "hart_ip.pt.rsp.pv",
    "hart_ip.pt.rsp.tag",
    "hart_ip.pt.rsp.descriptor",
    "hart_ip.pt.rsp.year",
    "hart_ip.pt.rsp.qv",
    "hart_ip.pt.delimiter",
};
// Column of each field in kFields.
enum Col {
    kCommand,
    kLength,
    kRc,
    kStatus,
    kChecksum,
    kLongAddr,
    kShortAddr,
    kPayload,
    kDeviceId,
    kMfr,
    kDevType,
    kPvUnits,
    kPv,
    kTag,
    kDescriptor,
    kYear,
    kQv,
    kDelimiter
};

} // namespace

TEST(HartTshark, Section23FramesMatchWiresharkHartIp)
{
    if (!vt::test::haveProgram("tshark"))
        GTEST_SKIP() << "tshark is not installed";
    if (!vt::test::tsharkHasField("hart_ip.pt.command"))
        GTEST_SKIP() << "this tshark has no HART-IP pass-through dissector";

    const std::vector<Case> all = cases();
    vt::test::PcapWriter pcap(vt::test::kLinktypeRawIp);
    std::vector<Bytes> wires;
    std::uint16_t seq = 1;
    for (const Case &c : all) {
        auto wire = encodeFrame(c.frame);
        ASSERT_TRUE(wire.ok()) << c.name;
        wires.push_back(*wire);
        const bool response = c.frame.isResponse();
        pcap.add(vt::test::ipv4Udp(hartIp(*wire, response, seq++), response ? kHartIpPort : 40000,
                                   response ? 40000 : kHartIpPort));
    }
    vt::test::TempFile file("vt_hart_tshark");
    ASSERT_TRUE(pcap.write(file.path()));
    int status = 0;
    const auto rows = vt::test::tsharkFields(file.path(), kFields, "", &status);
    ASSERT_EQ(status, 0) << "tshark failed";
    ASSERT_EQ(rows.size(), all.size());

    for (std::size_t i = 0; i < all.size(); ++i) {
        SCOPED_TRACE(all[i].name);
        const auto &row = rows[i];
        auto ours = decodeFrame(wires[i]);
        ASSERT_TRUE(ours.ok());
        const Frame &f = *ours;
        EXPECT_EQ(number(row[kDelimiter]), delimiterOf(f));
        EXPECT_EQ(number(row[kCommand]), f.command);
        EXPECT_EQ(number(row[kLength]),
                  static_cast<long>(f.data.size() + (f.isResponse() ? 2 : 0)));
        EXPECT_EQ(number(row[kChecksum]), wires[i].back());
        if (f.isResponse()) {
            EXPECT_EQ(number(row[kRc]), f.responseCode);
            EXPECT_EQ(number(row[kStatus]), f.deviceStatus);
        }
        if (f.address.isLong) {
            const Bytes address(wires[i].begin() + 6, wires[i].begin() + 11);
            EXPECT_EQ(lower(row[kLongAddr]), lower(toHex(address, '\0')));
        } else {
            EXPECT_EQ(number(row[kShortAddr]), f.address.pollAddress);
        }
        if (f.command >= 128) {
            EXPECT_EQ(lower(row[kPayload]), lower(toHex(f.data, '\0')));
        }
        if (!f.isResponse() || f.data.empty() || f.command >= 128)
            continue;
        auto payload = decodeUniversal(f.command, true, f.data);
        ASSERT_TRUE(payload.ok());
        if (const auto *id = std::get_if<Identity>(&*payload)) {
            EXPECT_EQ(number(row[kMfr]), id->manufacturerId);
            EXPECT_EQ(number(row[kDevType]), id->expandedDeviceType);
            EXPECT_EQ(lower(row[kDeviceId]), "123456");
        } else if (const auto *pv = std::get_if<UnitValue>(&*payload)) {
            EXPECT_EQ(number(row[kPvUnits]), pv->unit);
            EXPECT_FLOAT_EQ(std::stof(row[kPv]), pv->value);
        } else if (const auto *dv = std::get_if<DynamicVariables>(&*payload)) {
            EXPECT_FLOAT_EQ(std::stof(row[kPv]), dv->variables.at(0).value);
            EXPECT_FLOAT_EQ(std::stof(row[kQv]), dv->variables.at(3).value);
        } else if (const auto *tdd = std::get_if<TagDescriptorDate>(&*payload)) {
            // Wireshark unpacks packed ASCII itself: the tag text is a check of our packer.
            EXPECT_EQ(row[kTag], tdd->tag);
            EXPECT_EQ(row[kDescriptor].substr(0, tdd->descriptor.size()), tdd->descriptor);
            EXPECT_EQ(number(row[kYear]), tdd->date.yearSince1900);
        }
    }
}
