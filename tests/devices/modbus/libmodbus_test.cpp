// Cross-check against libmodbus, a real Modbus peer: libmodbus talks to our codec over a pty (RTU)
// and a loopback socket (TCP), in both roles. Every wait is a poll() with a 2 s bound; no sleeps.
#include "modbus/deframer.h"
#include "modbus/exceptions.h"
#include "modbus/rtu.h"
#include "modbus/tcp.h"
#include "modbus_vectors.h"
#include "pty_support.h"

#include <arpa/inet.h>
#include <cerrno>
#include <cstdlib>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <string>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

using namespace vt::dev;
using namespace vt::dev::modbus;
using namespace vt::test::modbus_vectors;

namespace {

constexpr int kTimeoutMs = 2000;

using vt::test::Pty;
using vt::test::writeAll;

// Reads until `deframer` yields one frame or the bound expires.
template<typename Deframer> std::optional<Bytes> readFrame(int fd, Deframer &deframer)
{
    for (;;) {
        pollfd p{fd, POLLIN, 0};
        if (poll(&p, 1, kTimeoutMs) <= 0)
            return std::nullopt;
        std::uint8_t buf[300];
        const ssize_t n = read(fd, buf, sizeof buf);
        if (n <= 0)
            return std::nullopt;
        auto frames =
            deframer.feed(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)));
        if (!frames.empty())
            return frames.front();
    }
}

struct ModbusCtx
{
    modbus_t *ctx = nullptr;
    ~ModbusCtx()
    {
        if (ctx != nullptr) {
            modbus_close(ctx);
            modbus_free(ctx);
        }
    }
};

modbus_t *rtuContext(const Pty &pty, int unit)
{
    modbus_t *ctx = modbus_new_rtu(pty.slaveName().c_str(), 19200, 'E', 8, 1);
    if (ctx == nullptr)
        return nullptr;
    modbus_set_slave(ctx, unit);
    modbus_set_response_timeout(ctx, kTimeoutMs / 1000, 0);
    modbus_set_indication_timeout(ctx, kTimeoutMs / 1000, 0);
    if (modbus_connect(ctx) != 0) {
        modbus_free(ctx);
        return nullptr;
    }
    return ctx;
}

} // namespace

// libmodbus is the master: its FC 3 request must be our bytes, and it must accept our answer.
TEST(ModbusLibmodbus, RtuClientReadsOurResponse)
{
    Pty pty;
    ASSERT_TRUE(pty.ok());
    ModbusCtx m{rtuContext(pty, 1)};
    ASSERT_NE(m.ctx, nullptr) << modbus_strerror(errno);

    std::optional<Bytes> request;
    std::thread server([&] {
        RtuDeframer deframer(Direction::Request);
        request = readFrame(pty.fd(), deframer);
        if (request)
            writeAll(pty.fd(), kRtuReadD107Response);
    });
    std::uint16_t dest[1] = {0};
    const int rc = modbus_read_registers(m.ctx, 0x0007, 1, dest);
    server.join();
    ASSERT_TRUE(request);
    EXPECT_EQ(*request, encodeRtu(RtuRequest{1, ReadRequest{0x0007, 1}}).value());
    EXPECT_EQ(*request, kRtuReadD107);
    ASSERT_EQ(rc, 1) << modbus_strerror(errno);
    EXPECT_EQ(dest[0], 0x0133);
}

TEST(ModbusLibmodbus, RtuClientWritesAndSeesOurException)
{
    Pty pty;
    ASSERT_TRUE(pty.ok());
    ModbusCtx m{rtuContext(pty, 1)};
    ASSERT_NE(m.ctx, nullptr) << modbus_strerror(errno);

    std::optional<Bytes> request;
    std::thread server([&] {
        RtuDeframer deframer(Direction::Request);
        request = readFrame(pty.fd(), deframer);
        if (request) // HCS: writing ID 0x0030 failed → FC 6 exception 3 "wrong data value"
            writeAll(pty.fd(), encodeRtu(RtuResponse{1, ExceptionResponse{6, 3}}).value());
    });
    const int rc = modbus_write_register(m.ctx, 0x0030, 1000);
    const int err = errno;
    server.join();
    ASSERT_TRUE(request);
    EXPECT_EQ(*request, kRtuWriteC107);
    EXPECT_EQ(rc, -1);
    EXPECT_EQ(err, EMBXILVAL);
}

// libmodbus is the slave: it must accept our requests and we must decode its answers.
TEST(ModbusLibmodbus, RtuServerAnswersOurRequests)
{
    Pty pty;
    ASSERT_TRUE(pty.ok());
    ModbusCtx m{rtuContext(pty, 1)};
    ASSERT_NE(m.ctx, nullptr) << modbus_strerror(errno);
    modbus_mapping_t *map = modbus_mapping_new(0, 0, 0x40, 0);
    ASSERT_NE(map, nullptr);
    for (int i = 0; i < 0x40; ++i)
        map->tab_registers[i] = static_cast<std::uint16_t>(0x0100 + i);

    struct Case
    {
        RtuRequest request;
        RtuResponse expected;
    };
    const Case cases[] = {
        {{1, ReadRequest{0x0007, 7}},
         {1, ReadResponse{{0x0107, 0x0108, 0x0109, 0x010A, 0x010B, 0x010C, 0x010D}}}},
        {{1, WriteRequest{0x0030, 1000}}, {1, WriteResponse{0x0030, 1000}}},
        {{1, ReadRequest{0x003E, 4}},
         {1, ExceptionResponse{3, 2}}}, // past the map: illegal data address
    };
    for (const Case &c : cases) {
        ASSERT_TRUE(writeAll(pty.fd(), encodeRtu(c.request).value()));
        std::uint8_t query[MODBUS_RTU_MAX_ADU_LENGTH];
        const int len = modbus_receive(m.ctx, query);
        ASSERT_GT(len, 0) << modbus_strerror(errno);
        modbus_reply(m.ctx, query, len, map);
        RtuDeframer deframer(Direction::Response);
        auto answer = readFrame(pty.fd(), deframer);
        ASSERT_TRUE(answer);
        auto decoded = decodeRtuResponse(*answer);
        ASSERT_TRUE(decoded.ok()) << describeError(decoded.error()).en;
        EXPECT_EQ(*decoded, c.expected);
    }
    EXPECT_EQ(map->tab_registers[0x30], 1000);
    EXPECT_EQ(hcsMeaning(3, 2, hcs::Family::Dma)->en, "wrong ID");
    modbus_mapping_free(map);
}

// Modbus TCP over loopback: libmodbus client, our server side.
TEST(ModbusLibmodbus, TcpClientReadsOurResponse)
{
    const int listener = socket(AF_INET, SOCK_STREAM, 0);
    ASSERT_GE(listener, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = 0;
    ASSERT_EQ(bind(listener, reinterpret_cast<sockaddr *>(&addr), sizeof addr), 0);
    ASSERT_EQ(listen(listener, 1), 0);
    socklen_t alen = sizeof addr;
    ASSERT_EQ(getsockname(listener, reinterpret_cast<sockaddr *>(&addr), &alen), 0);

    ModbusCtx m{modbus_new_tcp("127.0.0.1", ntohs(addr.sin_port))};
    ASSERT_NE(m.ctx, nullptr);
    modbus_set_response_timeout(m.ctx, kTimeoutMs / 1000, 0);
    ASSERT_EQ(modbus_connect(m.ctx), 0) << modbus_strerror(errno);

    std::optional<TcpRequest> request;
    std::thread server([&] {
        pollfd p{listener, POLLIN, 0};
        if (poll(&p, 1, kTimeoutMs) <= 0)
            return;
        const int conn = accept(listener, nullptr, nullptr);
        if (conn < 0)
            return;
        TcpDeframer deframer;
        if (auto frame = readFrame(conn, deframer)) {
            auto q = decodeTcpRequest(*frame);
            if (q.ok()) {
                request = *q;
                writeAll(conn, encodeTcp(TcpResponse{q->transaction, q->unit,
                                                     ReadResponse{{0x0133, 0xFFFF}}})
                                   .value());
            }
        }
        close(conn);
    });
    std::uint16_t dest[2] = {0, 0};
    const int rc = modbus_read_registers(m.ctx, 0x0007, 2, dest);
    server.join();
    close(listener);
    ASSERT_TRUE(request);
    EXPECT_EQ(std::get<ReadRequest>(request->pdu), (ReadRequest{0x0007, 2}));
    ASSERT_EQ(rc, 2) << modbus_strerror(errno);
    EXPECT_EQ(dest[0], 0x0133);
    EXPECT_EQ(dest[1], 0xFFFF);
}
