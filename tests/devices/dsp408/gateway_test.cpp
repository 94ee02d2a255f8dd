// The ED1's image in a PROFIBUS-master gateway's Modbus TCP registers (dsp408/gateway.h,
// modbus/register_image.h) and how the inspector explains those frames: the §4.6.1 example 1
// request ("dop_drivePos_AsideVal = 450", AK 2, PNU 73, IND 3) written with FC 16, an input image
// read with FC 3, the parameter a frame carries, and the state a status word reports (§4.2.2).
#include "dsp408/gateway.h"
#include "dsp408/state_machine.h"
#include "inspect/describe_any.h"
#include "inspect/frame_parameters.h"
#include "inspect/logged_frame.h"
#include "modbus/register_image.h"

#include <gtest/gtest.h>

using namespace vt::dev;

namespace {

// ED1/SD1 manual §4.6.1 example 1, request and response.
const Bytes kExample1Request{0x20, 0x49, 0x03, 0x00, 0x00, 0x00, 0x01, 0xC2};
const Bytes kExample1Response{0x10, 0x49, 0x03, 0x00, 0x00, 0x00, 0x01, 0xC2};

Bytes pkwWrite(std::uint16_t transaction, std::uint16_t start,
               dsp408::RegisterByteOrder order = dsp408::RegisterByteOrder::FirstByteHigh)
{
    const auto registers = dsp408::toRegisters(kExample1Request, order);
    const auto pdu =
        modbus::encodeRegisterPdu(modbus::RegisterRequest{modbus::RegisterWrite{start, registers}});
    return modbus::wrapAdu(transaction, 1, *pdu);
}

std::string field(const Description &d, const char *key)
{
    const FieldSpan *f = d.field(key);
    return f ? f->value : std::string("(none)");
}

} // namespace

TEST(Dsp408Gateway, RegistersHoldTheImageBytesInTheConfiguredOrder)
{
    const Bytes image{0x20, 0x49, 0x03, 0x00};
    EXPECT_EQ(dsp408::toRegisters(image, dsp408::RegisterByteOrder::FirstByteHigh),
              (std::vector<std::uint16_t>{0x2049, 0x0300}));
    EXPECT_EQ(dsp408::toRegisters(image, dsp408::RegisterByteOrder::FirstByteLow),
              (std::vector<std::uint16_t>{0x4920, 0x0003}));
    for (auto order :
         {dsp408::RegisterByteOrder::FirstByteHigh, dsp408::RegisterByteOrder::FirstByteLow})
        EXPECT_EQ(dsp408::fromRegisters(dsp408::toRegisters(image, order), order), image);
}

TEST(Dsp408Gateway, Fc16AndFc4PdusAsTheModbusSpecificationLaysThemOut)
{
    // Modbus Application Protocol §6.12: 10 start quantity byte-count values.
    const auto write = modbus::encodeRegisterPdu(
        modbus::RegisterRequest{modbus::RegisterWrite{0x0400, {0x2049, 0x0300}}});
    ASSERT_TRUE(write.ok());
    EXPECT_EQ(*write, (Bytes{0x10, 0x04, 0x00, 0x00, 0x02, 0x04, 0x20, 0x49, 0x03, 0x00}));
    // §6.4: FC 4 answer = 04 byte-count values.
    const auto answer = modbus::decodeRegisterResponse(Bytes{0x04, 0x02, 0x12, 0x34});
    ASSERT_TRUE(answer.ok());
    EXPECT_EQ(std::get<modbus::RegisterReadAnswer>(*answer).registers,
              std::vector<std::uint16_t>{0x1234});
    // A byte count that is not twice the quantity is refused.
    EXPECT_FALSE(modbus::decodeRegisterRequest(Bytes{0x10, 0, 0, 0, 1, 3, 0, 0, 0}).ok());
    EXPECT_FALSE(modbus::decodeRegisterRequest(Bytes{0x06, 0, 0, 0, 1}).ok()); // not 3, 4, 16
}

TEST(Dsp408Gateway, TheInspectorExplainsAPkwWriteAndAnInputImage)
{
    AnyOptions o;
    o.direction = Direction::Request;
    auto request = inspect::describeLogged(LinkProtocol::Dsp408Gateway, pkwWrite(7, 1024), o);
    ASSERT_TRUE(request.ok());
    ASSERT_TRUE(request->ok()) << request->summary.en;
    EXPECT_EQ(field(*request, "pdu.start"), "1024");
    EXPECT_EQ(field(*request, "pkw.ak"), "2");
    EXPECT_EQ(field(*request, "pkw.pnu"), "73");
    EXPECT_EQ(field(*request, "pkw.ind"), "3");
    EXPECT_EQ(field(*request, "pkw.value"), "450");

    Bytes image = kExample1Response;
    image.insert(image.end(), {0x00, 0x0F, 0x00, 0x00, 0x02, 0x00}); // R M H D, actual 512
    const auto registers = dsp408::toRegisters(image, dsp408::RegisterByteOrder::FirstByteHigh);
    const auto pdu = modbus::encodeRegisterPdu(
        modbus::RegisterResponse{modbus::RegisterReadAnswer{3, registers}});
    o.direction = Direction::Response;
    auto answer =
        inspect::describeLogged(LinkProtocol::Dsp408Gateway, modbus::wrapAdu(8, 1, *pdu), o);
    ASSERT_TRUE(answer.ok());
    ASSERT_TRUE(answer->ok()) << answer->summary.en;
    EXPECT_EQ(field(*answer, "pkw.ak"), "1");
    EXPECT_EQ(field(*answer, "pzd.status_word"), "0x000F");
    EXPECT_EQ(field(*answer, "pzd.actual_value"), "512");
    EXPECT_EQ(dsp408::stateOfStatusWord(0x000F), dsp408::State::DeviceModeActive);
    EXPECT_EQ(dsp408::stateOfStatusWord(0x1008), dsp408::State::Init); // target window bit 12

    // The raw image link: a type 1 telegram.
    Bytes out = kExample1Request;
    out.insert(out.end(), {0x00, 0x07, 0x00, 0x00, 0x00, 0x64});
    o.direction = Direction::Request;
    auto raw = inspect::describeLogged(LinkProtocol::Dsp408Image, out, o);
    ASSERT_TRUE(raw.ok());
    EXPECT_EQ(field(*raw, "pkw.pnu"), "73");
    EXPECT_EQ(field(*raw, "pzd.control_word"), "0x0007");
}

// A gateway that puts the first image byte into a register's low byte (--register-bytes): the
// inspector decodes the frames of such a link with the link's order, so the PKW fields are the
// §4.6.1 example's and not a byte-swapped PNU.
TEST(Dsp408Gateway, TheInspectorDecodesWithTheLinksRegisterByteOrder)
{
    const Bytes swapped = pkwWrite(9, 1024, dsp408::RegisterByteOrder::FirstByteLow);
    AnyOptions o;
    o.direction = Direction::Request;
    o.registerBytes = dsp408::RegisterByteOrder::FirstByteLow;
    const auto right = inspect::describeLogged(LinkProtocol::Dsp408Gateway, swapped, o);
    ASSERT_TRUE(right.ok());
    ASSERT_TRUE(right->ok()) << right->summary.en;
    EXPECT_EQ(field(*right, "pkw.ak"), "2");
    EXPECT_EQ(field(*right, "pkw.pnu"), "73");
    EXPECT_EQ(field(*right, "pkw.ind"), "3");
    EXPECT_EQ(field(*right, "pkw.value"), "450");
    // The default order reads other numbers from the same bytes.
    o.registerBytes = dsp408::RegisterByteOrder::FirstByteHigh;
    const auto wrong = inspect::describeLogged(LinkProtocol::Dsp408Gateway, swapped, o);
    ASSERT_TRUE(wrong.ok());
    EXPECT_NE(field(*wrong, "pkw.pnu"), "73");

    // "Go to parameter" names the parameter the device saw: PNU 73, IND 3.
    inspect::ImageLayout layout;
    layout.registerBytes = dsp408::RegisterByteOrder::FirstByteLow;
    const auto carried = inspect::carriedBy(LinkProtocol::Dsp408Gateway, swapped,
                                            Direction::Request, hcs::Family::Dma, layout);
    ASSERT_TRUE(carried.indPnu);
    EXPECT_EQ(carried.indPnu->pnu, 73);
    EXPECT_EQ(carried.indPnu->ind, 3);
    const auto unswapped =
        inspect::carriedBy(LinkProtocol::Dsp408Gateway, swapped, Direction::Request);
    EXPECT_TRUE(!unswapped.indPnu || unswapped.indPnu->pnu != 73);
}

TEST(Dsp408Gateway, AFrameNamesTheParameterItCarries)
{
    const auto viaGateway =
        inspect::carriedBy(LinkProtocol::Dsp408Gateway, pkwWrite(1, 0), Direction::Request);
    ASSERT_TRUE(viaGateway.indPnu);
    EXPECT_EQ(viaGateway.indPnu->ind, 3);
    EXPECT_EQ(viaGateway.indPnu->pnu, 73);
    Bytes out = kExample1Request;
    out.insert(out.end(), {0, 0, 0, 0, 0, 0});
    const auto viaImage = inspect::carriedBy(LinkProtocol::Dsp408Image, out, Direction::Request);
    ASSERT_TRUE(viaImage.indPnu);
    EXPECT_EQ(viaImage.indPnu->pnu, 73);
    // "No instruction" (AK 0) carries none.
    Bytes idle(14, 0);
    EXPECT_TRUE(inspect::carriedBy(LinkProtocol::Dsp408Image, idle, Direction::Request).empty());
}
