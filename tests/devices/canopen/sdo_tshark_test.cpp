// Cross-check of our SDO frames against Wireshark's CANopen dissector: frames go into a pcap of
// linktype 227 (LINKTYPE_CAN_SOCKETCAN, can_id big-endian there) and tshark decodes them as
// CANopen ("-d can.subdissector,canopen"). Skips without tshark or without that decode-as table.
#include "../hart/tshark_support.h"
#include "canopen/sdo.h"
#include "core/hex.h"

#include <gtest/gtest.h>
#include <sstream>

using namespace vt::dev;
using namespace vt::dev::canopen;
using vt::test::lower;
using vt::test::number;

namespace {

const char *kDecodeAs = "-d can.subdissector,canopen";

// One LINKTYPE_CAN_SOCKETCAN record: can_id in network byte order, len, 3 pad bytes, data[8].
Bytes socketCanRecord(const CanFrame &f)
{
    ByteWriter w;
    w.u32be(f.id).u8(f.dlc).u8(0).u8(0).u8(0).bytes(f.data);
    return w.take();
}

bool canSubdissectorAvailable()
{
    const auto r = vt::test::runCommand("tshark -G dissector-tables");
    return r.output.find("can.subdissector") != std::string::npos;
}

struct Case
{
    std::string name;
    CanFrame frame;
};

std::vector<Case> cases()
{
    Sdo segmentedInit;
    segmentedInit.command = SdoCommand::InitiateUploadResponse;
    segmentedInit.index = 0x1008;
    segmentedInit.sizeIndicated = true;
    segmentedInit.size = 20;
    return {
        {"write 0x6040 = 0x000F", *toCanFrame(expeditedDownload(0x6040, 0, 0x000F, 2), 5)},
        {"write confirmed", *toCanFrame(downloadResponse(0x6040, 0), 5)},
        {"read 0x6041", *toCanFrame(uploadRequest(0x6041, 0), 5)},
        {"read value 0x0237", *toCanFrame(expeditedUploadResponse(0x6041, 0, 0x0237, 2), 5)},
        {"write 1 byte to 0x2000/3 (HCS manufacturer area)",
         *toCanFrame(expeditedDownload(0x2003, 0, 7, 1), 127)},
        {"read 4 bytes", *toCanFrame(expeditedUploadResponse(0x604F, 1, 0x12345678, 4), 1)},
        {"segmented upload initiate", *toCanFrame(segmentedInit, 5)},
        {"server abort", *toCanFrame(abortTransfer(0x6042, 0, 0x06090030), 5, Direction::Response)},
        {"client abort", *toCanFrame(abortTransfer(0x6042, 0, 0x05040000), 5, Direction::Request)},
    };
}

const std::vector<std::string> kFields{
    "canopen.node_id",        "canopen.sdo.ccs",     "canopen.sdo.scs",
    "canopen.sdo.main_idx",   "canopen.sdo.sub_idx", "canopen.sdo.data.bytes",
    "canopen.sdo.abort_code", "canopen.sdo.e",       "canopen.sdo.s"};
enum Col { kNode, kCcs, kScs, kIndex, kSub, kData, kAbort, kE, kS };

bool flag(const std::string &s)
{
    return s == "1" || s == "True";
}

} // namespace

TEST(CanopenTshark, Cia301SdoFramesMatchWireshark)
{
    if (!vt::test::haveProgram("tshark"))
        GTEST_SKIP() << "tshark is not installed";
    if (!canSubdissectorAvailable() || !vt::test::tsharkHasField("canopen.sdo.main_idx"))
        GTEST_SKIP() << "this tshark cannot decode CAN as CANopen (no can.subdissector table)";

    const auto all = cases();
    vt::test::PcapWriter pcap(vt::test::kLinktypeSocketCan);
    for (const Case &c : all)
        pcap.add(socketCanRecord(c.frame));
    vt::test::TempFile file("vt_canopen_tshark");
    ASSERT_TRUE(pcap.write(file.path()));
    int status = 0;
    const auto rows = vt::test::tsharkFields(file.path(), kFields, kDecodeAs, &status);
    ASSERT_EQ(status, 0) << "tshark failed";
    ASSERT_EQ(rows.size(), all.size());

    for (std::size_t i = 0; i < all.size(); ++i) {
        SCOPED_TRACE(all[i].name);
        const auto &row = rows[i];
        auto ours = fromCanFrame(all[i].frame);
        ASSERT_TRUE(ours.ok());
        const Sdo &s = ours->sdo;
        EXPECT_EQ(number(row[kNode]), ours->channel.node);
        const long specifier = all[i].frame.data[0] >> 5;
        EXPECT_EQ(number(ours->channel.direction == Direction::Request ? row[kCcs] : row[kScs]),
                  specifier);
        EXPECT_EQ(number(row[kIndex]), s.index);
        EXPECT_EQ(number(row[kSub]), s.subindex);
        if (s.command == SdoCommand::Abort) {
            EXPECT_EQ(static_cast<std::uint32_t>(number(row[kAbort])), s.abortCode);
            continue;
        }
        if (s.command == SdoCommand::InitiateDownloadRequest ||
            s.command == SdoCommand::InitiateUploadResponse) {
            EXPECT_EQ(flag(row[kE]), s.expedited);
            EXPECT_EQ(flag(row[kS]), s.sizeIndicated);
        }
        if (s.expedited) {
            // tshark 4.0 shows all four data bytes; ours are the first 4 − n of them.
            EXPECT_EQ(lower(row[kData]).substr(0, 2 * s.data.size()), lower(toHex(s.data, '\0')));
        }
    }
}

// Our CiA 301 abort-code table against Wireshark's: same codes, same English wording apart from
// CiA 301's "(block mode only)" / "(download only)" notes and Wireshark's "an hardware".
TEST(CanopenTshark, Cia301AbortCodeTextsMatchWireshark)
{
    if (!vt::test::haveProgram("tshark"))
        GTEST_SKIP() << "tshark is not installed";
    if (!canSubdissectorAvailable())
        GTEST_SKIP() << "this tshark cannot decode CAN as CANopen (no can.subdissector table)";
    const std::uint32_t codes[] = {
        0x05030000, 0x05040000, 0x05040001, 0x05040002, 0x05040003, 0x05040004, 0x05040005,
        0x06010000, 0x06010001, 0x06010002, 0x06020000, 0x06040041, 0x06040042, 0x06040043,
        0x06040047, 0x06060000, 0x06070010, 0x06070012, 0x06070013, 0x06090011, 0x06090030,
        0x06090031, 0x06090032, 0x06090036, 0x060A0023, 0x08000000, 0x08000020, 0x08000021,
        0x08000022, 0x08000023, 0x08000024};
    vt::test::PcapWriter pcap(vt::test::kLinktypeSocketCan);
    for (std::uint32_t code : codes)
        pcap.add(
            socketCanRecord(*toCanFrame(abortTransfer(0x2000, 1, code), 5, Direction::Response)));
    vt::test::TempFile file("vt_canopen_abort_tshark");
    ASSERT_TRUE(pcap.write(file.path()));
    const auto r = vt::test::runCommand(vt::test::tsharkCommand() + " -n -r '" +
                                        file.path().string() + "' " + kDecodeAs + " -V");
    ASSERT_EQ(r.status, 0);
    std::vector<std::string> texts;
    std::istringstream lines(r.output);
    std::string line;
    while (std::getline(lines, line)) {
        const std::size_t at = line.find("Abort code: ");
        const std::size_t paren = line.rfind(" (0x");
        if (at != std::string::npos && paren != std::string::npos && paren > at)
            texts.push_back(line.substr(at + 12, paren - at - 12));
    }
    ASSERT_EQ(texts.size(), std::size(codes));
    for (std::size_t i = 0; i < texts.size(); ++i) {
        std::string ours = abortCodeText(codes[i]).en;
        for (const char *note : {" (block mode only)", " (download only)"})
            if (const auto p = ours.find(note); p != std::string::npos)
                ours.erase(p);
        std::string theirs = texts[i];
        if (const auto p = theirs.find("an hardware"); p != std::string::npos)
            theirs.replace(p, 11, "a hardware");
        EXPECT_EQ(ours, theirs) << std::hex << codes[i];
    }
}
