// libmodbus, a real Modbus master, against the simulated modules: over a pseudo terminal into
// ModbusRtuServer and over loopback TCP into ModbusTcpServer it reads EVERY readable parameter of
// every HCS family, version and mode in blocks of ≤ 8 and gets the dictionary defaults; writes out
// of range get exception 3, read-only / not active rows the family's "wrong ID" (2), reads of more
// than 8 registers exception 3, a second EEPROM write within 25 ms exception 4 (ARCHITECTURE.md
// "Protocol decisions"; DMA Profinet manual §3.4.1).
// A pump thread moves bytes between the descriptor and the server with poll() and bounded
// timeouts; no sleeps.
#include "hcs_sim_support.h"
#include "pty_support.h"
#include "sim/hcs_node.h"
#include "sim/modbus_rtu_server.h"
#include "sim/modbus_tcp_server.h"

#include <arpa/inet.h>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <fcntl.h>
#include <memory>
#include <modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

using namespace vt::dev;
using namespace vt::dev::sim;
using namespace vt::dev::sim::test;

namespace {

constexpr int kTimeoutMs = 2000;
constexpr int kPumpPollMs = 20; // how often the pump looks at its stop flag

using vt::test::Pty;
using vt::test::writeAll;

// Moves bytes between `fd` and `server` on its own thread until destroyed. The server (and the
// modules behind it) belong to this thread while it runs. With a listening socket it first
// accepts one connection.
class Pump
{
public:
    Pump(int fd, ByteServer &server, bool listening = false)
        : m_fd(fd), m_server(server), m_listening(listening), m_thread([this] { run(); })
    {
    }
    ~Pump()
    {
        m_stop = true;
        m_thread.join();
        if (m_listening && m_conn >= 0)
            close(m_conn);
    }
    Pump(const Pump &) = delete;
    Pump &operator=(const Pump &) = delete;

private:
    void run()
    {
        int fd = m_fd;
        if (m_listening) {
            pollfd p{m_fd, POLLIN, 0};
            if (poll(&p, 1, kTimeoutMs) <= 0)
                return;
            m_conn = accept(m_fd, nullptr, nullptr);
            fd = m_conn;
            if (fd < 0)
                return;
        }
        while (!m_stop) {
            pollfd p{fd, POLLIN, 0};
            if (poll(&p, 1, kPumpPollMs) > 0 && (p.revents & POLLIN) != 0) {
                std::uint8_t buf[512];
                const ssize_t n = read(fd, buf, sizeof buf);
                if (n <= 0)
                    return;
                m_server.receive(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)));
            }
            const Bytes out = m_server.drain();
            if (!out.empty() && !writeAll(fd, out))
                return;
        }
    }

    int m_fd;
    ByteServer &m_server;
    bool m_listening;
    int m_conn = -1;
    std::atomic<bool> m_stop{false};
    std::thread m_thread;
};

struct Ctx
{
    modbus_t *ctx = nullptr;
    ~Ctx()
    {
        if (ctx) {
            modbus_close(ctx);
            modbus_free(ctx);
        }
    }
};

modbus_t *rtuMaster(const Pty &pty, int unit)
{
    modbus_t *ctx = modbus_new_rtu(pty.slaveName().c_str(), 19200, 'E', 8, 1);
    if (!ctx)
        return nullptr;
    modbus_set_slave(ctx, unit);
    modbus_set_response_timeout(ctx, kTimeoutMs / 1000, 0);
    if (modbus_connect(ctx) != 0) {
        modbus_free(ctx);
        return nullptr;
    }
    return ctx;
}

// One simulated module on a node, addressed as the manuals do: OPAT master SADR 0 (reached over
// the serial line point-to-point as unit 1), OPAT slave DIP switch 1, DMA E22 = 1.
struct Rig
{
    SimClock clock;
    HcsNode node;
    HcsModule *module;
    explicit Rig(const Variant &v)
        : node(clock, hcsFamilyOf(dictionary(v.family))),
          module(&node.addModule(configFor(v, v.family == "opat" && v.version == "34" ? 0 : 1)))
    {
    }
    bool isOpatMaster() const { return module->address() == 0; }
};

// Everything libmodbus should see from `module` on `ctx`; failures name the variant and row.
void checkModule(modbus_t *ctx, const HcsModule &module, const std::string &what)
{
    const auto rows = readableRows(module);
    ASSERT_GT(rows.size(), 50u) << what;
    std::size_t values = 0;
    for (const hcs::ReadBlock &b : readBlocks(rows)) {
        std::uint16_t dest[8] = {};
        const int rc = modbus_read_registers(ctx, b.firstId, b.count, dest);
        ASSERT_EQ(rc, b.count) << what << " block " << b.firstId << "+" << b.count << ": "
                               << modbus_strerror(errno);
        for (std::uint16_t i = 0; i < b.count; ++i) {
            const ParamMeta &row = *module.storage().meta(b.firstId + i);
            EXPECT_EQ(dest[i], expectedFreshWord(row, module)) << what << " " << row.name;
            ++values;
        }
    }
    EXPECT_EQ(values, rows.size()) << what;

    // More than 8 at once: the HCS rule "maximal 8 parameters readable at once" → exception 3.
    std::uint16_t dest[9] = {};
    EXPECT_EQ(modbus_read_registers(ctx, *rows.front()->id, 9, dest), -1) << what;
    EXPECT_EQ(errno, EMBXILVAL) << what;

    // Writes: a read-only row, a not-active row, out of range on both sides, then a good one.
    int readOnly = 0, inactive = 0, outOfRange = 0;
    for (const ParamMeta &row : module.dictionary().params) {
        if (!row.id || *row.id > 0xFFFF)
            continue;
        const bool applies = module.storage().meta(*row.id) == &row;
        if (applies && row.access == Access::Read && readOnly < 3) {
            EXPECT_EQ(modbus_write_register(ctx, *row.id, module.storage().word(*row.id)), -1)
                << what << " " << row.name;
            EXPECT_EQ(errno, EMBXILADD) << what << " " << row.name; // HCS 2 "wrong ID"
            ++readOnly;
        } else if (row.access == Access::Inactive && inactive < 3) {
            EXPECT_EQ(modbus_write_register(ctx, *row.id, 0), -1) << what << " " << row.name;
            EXPECT_EQ(errno, EMBXILADD) << what << " " << row.name;
            ++inactive;
        } else if (applies && row.access == Access::ReadWrite && row.type == RawType::Int16 &&
                   outOfRange < 4 && row.max < 32767 && row.min > -32768) {
            EXPECT_EQ(modbus_write_register(
                          ctx, *row.id,
                          static_cast<std::uint16_t>(static_cast<std::int32_t>(row.max) + 1)),
                      -1)
                << what << " " << row.name;
            EXPECT_EQ(errno, EMBXILVAL) << what << " " << row.name; // HCS 3 "wrong data value"
            EXPECT_EQ(modbus_write_register(
                          ctx, *row.id,
                          static_cast<std::uint16_t>(static_cast<std::int32_t>(row.min) - 1)),
                      -1)
                << what << " " << row.name;
            EXPECT_EQ(errno, EMBXILVAL) << what << " " << row.name;
            ++outOfRange;
        }
    }
    EXPECT_EQ(readOnly, 3) << what;
    EXPECT_EQ(outOfRange, 4) << what;
    // A volatile set value (A1.01, "-9.999 V = 0xD8F1", DMA Profinet manual §3.8) is taken and
    // reads back.
    const ParamMeta *a101 = module.storage().find("A1.01");
    ASSERT_TRUE(a101) << what;
    ASSERT_EQ(modbus_write_register(ctx, *a101->id, 0xD8F1), 1)
        << what << ": " << modbus_strerror(errno);
    std::uint16_t back = 0;
    ASSERT_EQ(modbus_read_registers(ctx, *a101->id, 1, &back), 1) << what;
    EXPECT_EQ(back, 0xD8F1) << what;

    // Two EEPROM writes back to back: the second comes inside the first one's 25 ms (DMA Profinet
    // manual §3.4.1; the clock does not move here) → HCS 4 "writing of ID failed".
    std::vector<const ParamMeta *> eeprom;
    for (const ParamMeta &row : module.dictionary().params)
        if (row.id && module.storage().meta(*row.id) == &row && row.access == Access::ReadWrite &&
            HcsStorage::isEeprom(row) && eeprom.size() < 2)
            eeprom.push_back(&row);
    ASSERT_EQ(eeprom.size(), 2u) << what;
    EXPECT_EQ(modbus_write_register(ctx, *eeprom[0]->id, module.storage().word(*eeprom[0]->id)), 1)
        << what;
    EXPECT_EQ(modbus_write_register(ctx, *eeprom[1]->id, module.storage().word(*eeprom[1]->id)), -1)
        << what;
    EXPECT_EQ(errno, EMBXSFAIL) << what;
}

} // namespace

TEST(ModbusServerLibmodbus, RtuMasterReadsEveryParameterOfEveryFamily)
{
    for (const Variant &v : allVariants()) {
        Pty pty;
        ASSERT_TRUE(pty.ok());
        Rig rig(v);
        ModbusUnitOptions units;
        if (rig.isOpatMaster())
            units.pointToPointUnit = 1; // SADR 0 would be the Modbus broadcast
        ModbusRtuServer server(rig.clock, rig.node, units);
        Ctx m{rtuMaster(pty, 1)};
        ASSERT_NE(m.ctx, nullptr) << modbus_strerror(errno);
        {
            Pump pump(pty.fd(), server);
            checkModule(m.ctx, *rig.module, "RTU " + v.name());
        }
        EXPECT_EQ(server.garbageBytes(), 0u) << v.name();
    }
}

TEST(ModbusServerLibmodbus, TcpMasterReadsEveryParameterOfEveryFamily)
{
    for (const Variant &v : allVariants()) {
        const int listener = socket(AF_INET, SOCK_STREAM, 0);
        ASSERT_GE(listener, 0);
        sockaddr_in addr{};
        addr.sin_family = AF_INET;
        addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        ASSERT_EQ(bind(listener, reinterpret_cast<sockaddr *>(&addr), sizeof addr), 0);
        ASSERT_EQ(listen(listener, 1), 0);
        socklen_t len = sizeof addr;
        ASSERT_EQ(getsockname(listener, reinterpret_cast<sockaddr *>(&addr), &len), 0);

        Rig rig(v);
        ModbusTcpServer server(rig.clock, rig.node); // unit = SADR: the OPAT master is unit 0
        {
            Pump pump(listener, server, true);
            Ctx m{modbus_new_tcp("127.0.0.1", ntohs(addr.sin_port))};
            ASSERT_NE(m.ctx, nullptr);
            modbus_set_response_timeout(m.ctx, kTimeoutMs / 1000, 0);
            modbus_set_slave(m.ctx, rig.module->address());
            ASSERT_EQ(modbus_connect(m.ctx), 0) << modbus_strerror(errno);
            checkModule(m.ctx, *rig.module, "TCP " + v.name());
            // A unit no module answers: the gateway says "timeout slave, address wrong or not
            // installed" (HCS 5).
            modbus_set_slave(m.ctx, 9);
            std::uint16_t dest[1];
            EXPECT_EQ(modbus_read_registers(m.ctx, 0, 1, dest), -1);
            EXPECT_EQ(errno, MODBUS_ENOBASE + 5) << v.name();
        }
        close(listener);
    }
}
