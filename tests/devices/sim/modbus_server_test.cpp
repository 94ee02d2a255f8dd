// The simulator's Modbus front ends byte for byte: RTU frames split anywhere or run together go
// through the de-framer (Modbus over Serial Line §2.5.1), unit id = module address, broadcast,
// silence for absent units, the HCS exceptions (ARCHITECTURE.md "Protocol decisions"), answers
// held back until the simulated clock reaches a delayed EEPROM write (DMA Profinet manual
// §3.4.1); Modbus TCP with its MBAP header and gateway answers.
#include "modbus/crc.h"
#include "modbus/rtu.h"
#include "modbus/tcp.h"
#include "sim/hcs_codes.h"
#include "sim/modbus_rtu_server.h"
#include "sim/modbus_tcp_server.h"
#include "sim/node_config.h"

#include <gtest/gtest.h>

using namespace vt::dev;
using namespace vt::dev::sim;
using namespace vt::dev::modbus;

namespace {

std::unique_ptr<HcsNode> node(SimClock &clock, const char *family, std::size_t modules,
                              EepromBusyPolicy policy = EepromBusyPolicy::Refuse)
{
    NodeConfig c;
    c.family = family;
    c.modules = modules;
    c.moduleTemplate.eepromBusy = policy;
    auto made = makeNode(clock, c);
    EXPECT_TRUE(made.ok());
    return made.ok() ? std::move(made).value() : nullptr;
}

Bytes rtu(std::uint8_t unit, RequestPdu pdu)
{
    return encodeRtu(RtuRequest{unit, std::move(pdu)}).value();
}

std::vector<RtuResponse> rtuAnswers(const Bytes &bytes)
{
    RtuDeframer deframer(Direction::Response);
    std::vector<RtuResponse> out;
    for (const Bytes &frame : deframer.feed(bytes)) {
        auto r = decodeRtuResponse(frame);
        EXPECT_TRUE(r.ok());
        if (r.ok())
            out.push_back(*r);
    }
    EXPECT_EQ(deframer.buffered(), 0u) << "a partial answer";
    return out;
}

} // namespace

TEST(ModbusServerRtu, FramesSplitAnywhereOrRunTogether)
{
    SimClock clock;
    auto n = node(clock, "dma-pn-v51", 2);
    ModbusRtuServer server(clock, *n);
    const Bytes read = rtu(1, ReadRequest{0x0000, 1});      // Vers
    const Bytes write = rtu(2, WriteRequest{0x001F, 1000}); // A1.01 of module 2
    // Byte by byte.
    for (std::uint8_t b : read)
        server.receive(std::span<const std::uint8_t>(&b, 1));
    // Two frames in one chunk, the second split after the unit id.
    Bytes chunk = write;
    chunk.insert(chunk.end(), read.begin(), read.begin() + 1);
    server.receive(chunk);
    server.receive(std::span<const std::uint8_t>(read).subspan(1));
    const auto answers = rtuAnswers(server.drain());
    ASSERT_EQ(answers.size(), 3u);
    EXPECT_EQ(answers[0], (RtuResponse{1, ReadResponse{{5100}}}));
    EXPECT_EQ(answers[1], (RtuResponse{2, WriteResponse{0x001F, 1000}}));
    EXPECT_EQ(answers[2], (RtuResponse{1, ReadResponse{{5100}}}));
    EXPECT_EQ(n->module(1).storage().get("A1.01"), 1000);
    EXPECT_EQ(server.framesHandled(), 3u);
    EXPECT_TRUE(server.drain().empty());
}

TEST(ModbusServerRtu, LineNoiseAndBadCrcAreDropped)
{
    SimClock clock;
    auto n = node(clock, "dma-pn-v13", 1);
    ModbusRtuServer server(clock, *n);
    Bytes noisy{0x00, 0xFF, 0x13};
    const Bytes read = rtu(1, ReadRequest{0x0007, 7});
    noisy.insert(noisy.end(), read.begin(), read.end());
    server.receive(noisy);
    auto answers = rtuAnswers(server.drain());
    ASSERT_EQ(answers.size(), 1u);
    EXPECT_EQ(std::get<ReadResponse>(answers[0].pdu).registers.size(), 7u);
    EXPECT_GT(server.garbageBytes(), 0u);
    Bytes corrupt = read;
    corrupt.back() ^= 0x01;
    server.receive(corrupt);
    server.silence(); // 3.5 characters of silence end the broken frame
    EXPECT_TRUE(server.drain().empty());
}

TEST(ModbusServerRtu, UnitsBroadcastAndSilence)
{
    SimClock clock;
    auto n = node(clock, "dma-pn-v51", 3);
    ModbusRtuServer server(clock, *n);
    // Broadcast (unit 0): every module takes the write, nobody answers.
    server.receive(rtu(0, WriteRequest{0x001F, 700}));
    EXPECT_TRUE(server.drain().empty());
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(n->module(i).storage().get("A1.01"), 700);
    // No module at unit 9; two modules at unit 2: silence on a serial line.
    server.receive(rtu(9, ReadRequest{0, 1}));
    n->module(2).setAddress(2);
    server.receive(rtu(2, ReadRequest{0, 1}));
    EXPECT_TRUE(server.drain().empty());
    // Point to point: only the configured unit, answered by the first module.
    ModbusRtuServer p2p(clock, *n, ModbusUnitOptions{std::uint8_t{5}, false});
    p2p.receive(rtu(1, ReadRequest{0, 1}));
    EXPECT_TRUE(p2p.drain().empty());
    p2p.receive(rtu(5, ReadRequest{0xA3, 1})); // E22 of module 1
    const auto answers = rtuAnswers(p2p.drain());
    ASSERT_EQ(answers.size(), 1u);
    EXPECT_EQ(answers[0], (RtuResponse{5, ReadResponse{{1}}}));
}

TEST(ModbusServerRtu, HcsExceptions)
{
    SimClock clock;
    auto n = node(clock, "opat", 2);
    ModbusRtuServer server(clock, *n);                   // slave 1 (DIP switch 1) = unit 1
    server.receive(rtu(1, ReadRequest{0x0000, 9}));      // more than 8 registers
    server.receive(rtu(1, WriteRequest{0x0007, 0}));     // d1.07: read only
    server.receive(rtu(1, WriteRequest{0x0030, 10000})); // C1.07 above 9.999 V
    server.receive(rtu(1, ReadRequest{0x0075, 1}));      // FB1M: not active
    server.receive(rtu(1, WriteRequest{0x0030, 1000}));
    server.receive(rtu(1, WriteRequest{0x0031, 1000})); // EEPROM still busy
    const auto a = rtuAnswers(server.drain());
    ASSERT_EQ(a.size(), 6u);
    EXPECT_EQ(a[0].pdu, ResponsePdu(ExceptionResponse{3, exce::kBadCount}));
    EXPECT_EQ(a[1].pdu, ResponsePdu(ExceptionResponse{6, exce::kWrongId}));
    EXPECT_EQ(a[2].pdu, ResponsePdu(ExceptionResponse{6, exce::kWrongData}));
    EXPECT_EQ(a[3].pdu, ResponsePdu(ExceptionResponse{3, exce::kWrongId}));
    EXPECT_EQ(a[4].pdu, ResponsePdu(WriteResponse{0x0030, 1000}));
    EXPECT_EQ(a[5].pdu, ResponsePdu(ExceptionResponse{6, exce::kWriteFailed}));
    // A quantity outside 1..125 fails in the codec: illegal data value as well.
    Bytes zero = rtu(1, ReadRequest{0, 1});
    zero[5] = 0;
    const std::uint16_t crc = crc16(std::span<const std::uint8_t>(zero).first(6));
    zero[6] = static_cast<std::uint8_t>(crc);
    zero[7] = static_cast<std::uint8_t>(crc >> 8);
    server.receive(zero);
    const auto b = rtuAnswers(server.drain());
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(b[0].pdu, ResponsePdu(ExceptionResponse{3, 3}));
}

TEST(ModbusServerRtu, DelayedEepromWriteWaitsForTheSimulatedClock)
{
    SimClock clock;
    auto n = node(clock, "dma-pn-v13", 1, EepromBusyPolicy::Delay);
    ModbusRtuServer server(clock, *n);
    server.receive(rtu(1, WriteRequest{0x0030, 1000}));
    server.receive(rtu(1, WriteRequest{0x0031, 2000}));
    server.receive(rtu(1, ReadRequest{0x0030, 2})); // queued behind the delayed write
    EXPECT_EQ(rtuAnswers(server.drain()).size(), 1u);
    ASSERT_TRUE(server.nextAnswerUs());
    EXPECT_EQ(*server.nextAnswerUs(), 25'000);
    clock.advance(24'999);
    EXPECT_TRUE(server.drain().empty());
    clock.advanceTo(*server.nextAnswerUs());
    const auto a = rtuAnswers(server.drain());
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[0].pdu, ResponsePdu(WriteResponse{0x0031, 2000}));
    EXPECT_EQ(a[1].pdu, ResponsePdu(ReadResponse{{1000, 2000}}));
}

TEST(ModbusServerTcp, MbapTransactionsGatewayAnswersAndOutOfStep)
{
    SimClock clock;
    auto n = node(clock, "opat", 3);
    ModbusTcpServer server(clock, *n);
    const auto tcp = [](std::uint16_t t, std::uint8_t unit, RequestPdu pdu) {
        return encodeTcp(TcpRequest{t, unit, std::move(pdu)}).value();
    };
    Bytes in = tcp(0x1234, 0, ReadRequest{0, 1});              // unit 0 = SADR 0, the OPAT master
    const Bytes second = tcp(0x1235, 2, ReadRequest{0xA3, 1}); // slave 2's E22
    in.insert(in.end(), second.begin(), second.begin() + 4);
    server.receive(in);
    server.receive(std::span<const std::uint8_t>(second).subspan(4));
    server.receive(tcp(0x1236, 6, ReadRequest{0, 1})); // nobody at 6: gateway answers 5
    Bytes unknownFc = tcp(0x1237, 1, ReadRequest{0, 1});
    unknownFc[7] = 0x04; // FC 4, read input registers: not an HCS function
    server.receive(unknownFc);
    TcpDeframer deframer;
    const std::vector<Bytes> frames = deframer.feed(server.drain());
    ASSERT_EQ(frames.size(), 4u);
    EXPECT_EQ(decodeTcpResponse(frames[0]).value(), (TcpResponse{0x1234, 0, ReadResponse{{3400}}}));
    EXPECT_EQ(decodeTcpResponse(frames[1]).value(), (TcpResponse{0x1235, 2, ReadResponse{{2}}}));
    EXPECT_EQ(decodeTcpResponse(frames[2]).value(),
              (TcpResponse{0x1236, 6, ExceptionResponse{3, exce::kSlaveTimeout}}));
    // FC 4 → 0x84, exception 1 "illegal function" (our codec decodes only 0x83 / 0x86).
    EXPECT_EQ(frames[3], (Bytes{0x12, 0x37, 0, 0, 0, 3, 1, 0x84, 0x01}));
    // Duplicate DIP switches behind the gateway: OPAT code 12.
    n->module(2).setAddress(1);
    server.receive(tcp(0x1238, 1, ReadRequest{0, 1}));
    for (const Bytes &frame : deframer.feed(server.drain()))
        EXPECT_EQ(decodeTcpResponse(frame)->pdu,
                  ResponsePdu(ExceptionResponse{3, exce::kDuplicateAddress}));
    // A header that cannot be right (protocol id 1): nothing more until the connection is new.
    Bytes bad = tcp(0x1239, 0, ReadRequest{0, 1});
    bad[3] = 1;
    server.receive(bad);
    server.receive(tcp(0x123A, 0, ReadRequest{0, 1}));
    EXPECT_TRUE(server.outOfStep());
    EXPECT_TRUE(server.drain().empty());
    server.reset();
    server.receive(tcp(0x123B, 0, ReadRequest{0, 1}));
    EXPECT_EQ(server.drain().size(), 9u + 2u);
}
