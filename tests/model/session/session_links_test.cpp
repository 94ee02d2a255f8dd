// End to end against the simulator over every link: the session engine through a real
// SerialLink on a pseudo-terminal (opened as a user's is, with no test-only workaround), a TcpLink
// on loopback (Modbus TCP and the node image) and a CanLink on a SOCK_SEQPACKET socketpair, each
// against a valvetune-sim process: identify, read all, write + verify. (The in-process SimLink is
// covered by session_test.cpp / write_job_test.cpp.)
#include "../../app/sim_process.h"
#include "access/transaction.h"
#include "dict/dictionary_loader.h"
#include "model/session/adapter_factory.h"
#include "model/session/device_access.h"
#include "model/session/session.h"
#include "model/session/write_job.h"
#include "sim_rig.h"
#include "transports/can_link.h"
#include "transports/serial_link.h"
#include "transports/serial_settings.h"
#include "transports/tcp_link.h"

#include <QSignalSpy>
#include <QTest>
#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

namespace vt::test {
namespace {

using simtest::Sim;

struct Endpoint
{
    std::unique_ptr<link::Link> link;
    std::unique_ptr<model::Session> session;
    std::unique_ptr<model::DeviceAccess> access;

    bool open(std::unique_ptr<link::Link> l, dev::LinkProtocol kind, const std::string &family,
              model::SessionOptions options = {},
              dev::DeviceProtocol device = dev::DeviceProtocol::Hcs)
    {
        link = std::move(l);
        session = std::make_unique<model::Session>(
            link.get(), model::makeAdapter(kind, family, device), options);
        access = std::make_unique<model::DeviceAccess>(*session, dictionaries());
        link->open();
        return waitForState(*link, link::LinkState::Open);
    }

    model::IdentifyResult identify(int module)
    {
        std::optional<model::IdentifyResult> result;
        access->identify(module, [&](const model::IdentifyResult &r) { result = r; });
        EXPECT_TRUE(waitFor(result));
        return result.value_or(model::IdentifyResult{});
    }

    model::ReadResult readAll(int module, const model::ModuleInfo &info)
    {
        const auto rows = model::readableRows(*info.dictionary, info.identification.version,
                                              info.identification.mode);
        std::optional<model::ReadResult> result;
        access->read(module, rows, model::Priority::User,
                     [&](const model::ReadResult &r) { result = r; });
        EXPECT_TRUE(waitFor(result, 120'000));
        EXPECT_EQ(result ? result->values.size() : 0u, rows.size());
        return result.value_or(model::ReadResult{});
    }

    model::WriteStatus writeOne(int module, const dev::Dictionary &dict, const char *name,
                                double raw)
    {
        std::vector<model::WriteItem> items(1);
        items[0].row = dict.find(name);
        items[0].value = raw;
        model::WriteJob job(*access, module, dict, items, model::AuditOrigin::Editor);
        QSignalSpy finished(&job, &model::WriteJob::finished);
        job.start();
        EXPECT_TRUE(finished.wait(kWaitMs));
        EXPECT_EQ(job.items()[0].status, model::WriteStatus::Verified)
            << job.items()[0].reason.text().toStdString();
        return job.items()[0].status;
    }
};

// The simulators here run with --factory: every setting reads its dictionary default.
void expectDefaults(const model::ReadResult &result, const std::string &family, std::size_t modules,
                    std::size_t index)
{
    ASSERT_TRUE(result.complete());
    for (const model::RowValue &v : result.values) {
        if (v.row->block == "d" || !v.row->id)
            continue; // live values move with the plant
        const std::uint16_t word = simtest::freshWord(family, modules, index, *v.row->id);
        const double expected =
            v.row->type == dev::RawType::Int16 ? static_cast<std::int16_t>(word) : word;
        EXPECT_EQ(dev::rawNumber(v.value), expected) << family << " " << v.row->name;
    }
}

TEST(SessionLinks, ModbusRtuOverAPseudoTerminal)
{
    Sim sim({"--device", "dma-pn-v51", "--factory", "--pty"});
    const QString pty = sim.listening();
    ASSERT_FALSE(pty.isEmpty()) << sim.stderrText().toStdString();
    model::SessionOptions options;
    options.baudRate = 19200;
    Endpoint e;
    ASSERT_TRUE(e.open(std::make_unique<link::SerialLink>(link::SerialSettings::hcsDefault(pty)),
                       dev::LinkProtocol::ModbusRtu, "dma-pn-v51", options));
    const auto id = e.identify(1);
    ASSERT_TRUE(id.ok) << id.message.toStdString();
    EXPECT_EQ(id.module.dictionary->family, "dma-pn-v51");
    expectDefaults(e.readAll(1, id.module), "dma-pn-v51", 1, 0);
    e.writeOne(1, *id.module.dictionary, "C1.07", 1000);
}

TEST(SessionLinks, ModbusTcpOnLoopbackToAThreeModuleNode)
{
    Sim sim({"--device", "dma-pb-v32", "--factory", "--modules", "3", "--tcp", "127.0.0.1:0"});
    const QString where = sim.listening();
    ASSERT_FALSE(where.isEmpty()) << sim.stderrText().toStdString();
    const quint16 port = static_cast<quint16>(where.section(QLatin1Char(':'), -1).toUInt());
    Endpoint e;
    ASSERT_TRUE(e.open(std::make_unique<link::TcpLink>(QStringLiteral("127.0.0.1"), port),
                       dev::LinkProtocol::ModbusTcp, "dma-pb-v32"));
    for (int address = 1; address <= 3; ++address) {
        const auto id = e.identify(address);
        ASSERT_TRUE(id.ok) << address << ": " << id.message.toStdString();
        EXPECT_EQ(id.module.dictionary->family, "dma-pb-v32");
    }
    const auto id = e.identify(2);
    expectDefaults(e.readAll(2, id.module), "dma-pb-v32", 3, 1);
    e.writeOne(2, *id.module.dictionary, "C1.07", 1500);
}

TEST(SessionLinks, NodeImageOnLoopback)
{
    Sim sim({"--device", "dma-pn-v13", "--factory", "--modules", "2", "--tcp", "127.0.0.1:0",
             "--protocol", "node-image"});
    const QString where = sim.listening();
    ASSERT_FALSE(where.isEmpty()) << sim.stderrText().toStdString();
    const quint16 port = static_cast<quint16>(where.section(QLatin1Char(':'), -1).toUInt());
    Endpoint e;
    ASSERT_TRUE(e.open(std::make_unique<link::TcpLink>(QStringLiteral("127.0.0.1"), port),
                       dev::LinkProtocol::NodeImage, "dma-pn-v13"));
    const auto id = e.identify(2);
    ASSERT_TRUE(id.ok) << id.message.toStdString();
    EXPECT_EQ(id.module.dictionary->family, "dma-pn-v13");
    expectDefaults(e.readAll(2, id.module), "dma-pn-v13", 2, 1);
    e.writeOne(2, *id.module.dictionary, "C1.07", 250);
}

TEST(SessionLinks, CanopenSdoThroughASocketpair)
{
    int fds[2] = {-1, -1};
    ASSERT_EQ(::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, fds), 0);
    const int child = fds[1];
    Sim sim(
        {"--device", "dma-pn-v51", "--factory", "--can-fd", QString::number(child), "--node", "5"},
        [child] { ::fcntl(child, F_SETFD, 0); });
    ::close(child);
    ASSERT_FALSE(sim.listening().isEmpty()) << sim.stderrText().toStdString();
    Endpoint e;
    ASSERT_TRUE(e.open(std::make_unique<link::CanLink>(link::CanLink::AdoptedFd{fds[0]},
                                                       QStringLiteral("socketpair")),
                       dev::LinkProtocol::Canopen, "dma-pn-v51"));
    const auto id = e.identify(5);
    ASSERT_TRUE(id.ok) << id.message.toStdString();
    EXPECT_EQ(id.module.dictionary->family, "dma-pn-v51");
    expectDefaults(e.readAll(5, id.module), "dma-pn-v51", 1, 0);
    e.writeOne(5, *id.module.dictionary, "C1.07", 1234);
}

// The Wandfluh ED1 over CANopen (CiA 408 objects): device type 408 identifies it; the manual
// gives no object for db_Capability, so its value is named from the manual, with a warning.
TEST(SessionLinks, Ed1OverCanopenIdentifiesByDeviceTypeAndNamesTheCapability)
{
    int fds[2] = {-1, -1};
    ASSERT_EQ(::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, fds), 0);
    const int child = fds[1];
    Sim sim({"--device", "wandfluh-ed1", "--can-fd", QString::number(child), "--node", "7"},
            [child] { ::fcntl(child, F_SETFD, 0); });
    ::close(child);
    ASSERT_FALSE(sim.listening().isEmpty()) << sim.stderrText().toStdString();
    Endpoint e;
    ASSERT_TRUE(e.open(std::make_unique<link::CanLink>(link::CanLink::AdoptedFd{fds[0]},
                                                       QStringLiteral("socketpair")),
                       dev::LinkProtocol::Canopen, "", {}, dev::DeviceProtocol::Dsp408));
    const auto id = e.identify(7);
    ASSERT_TRUE(id.ok) << id.message.toStdString();
    EXPECT_EQ(id.module.dictionary->family, "wandfluh-ed1");
    EXPECT_NE(id.module.identification.version.find("0x00130000"), std::string::npos);
    EXPECT_NE(id.deviceText.en.find("profile 408"), std::string::npos) << id.deviceText.en;
    EXPECT_TRUE(
        QString::fromStdString(id.module.identityText.en).contains(QStringLiteral("profile 408")));
}

// The ED1's PROFIBUS image over loopback TCP, both mappings: identify by db_Capability, read all
// by IND/PNU, a write read back (ED1/SD1 manual §4.6, §4.8.7).
TEST(SessionLinks, Ed1ImageAndGatewayOnLoopback)
{
    for (const char *protocol : {"dsp408-image", "dsp408-gateway"}) {
        SCOPED_TRACE(protocol);
        Sim sim({"--device", "wandfluh-ed1", "--tcp", "127.0.0.1:0", "--protocol", protocol});
        const QString where = sim.listening();
        ASSERT_FALSE(where.isEmpty()) << sim.stderrText().toStdString();
        const quint16 port = static_cast<quint16>(where.section(QLatin1Char(':'), -1).toUInt());
        Endpoint e;
        ASSERT_TRUE(e.open(std::make_unique<link::TcpLink>(QStringLiteral("127.0.0.1"), port),
                           *dev::fromKey<dev::LinkProtocol>(protocol), ""));
        const auto id = e.identify(1);
        ASSERT_TRUE(id.ok) << id.message.toStdString();
        EXPECT_EQ(id.module.dictionary->family, "wandfluh-ed1");
        EXPECT_EQ(id.module.identification.version, "capability 0x00130000");
        EXPECT_TRUE(e.readAll(1, id.module).complete());
        e.writeOne(1, *id.module.dictionary, "dpc_PropFact1", 25);
    }
}

TEST(SessionLinks, HartOverAPseudoTerminal)
{
    Sim sim({"--device", "wandfluh-sd7", "--pty"});
    const QString pty = sim.listening();
    ASSERT_FALSE(pty.isEmpty()) << sim.stderrText().toStdString();
    const auto settings = link::SerialSettings::hart(pty);
    model::SessionOptions options;
    options.baudRate = settings.baudRate;
    options.bitsPerCharacter = settings.bitsPerCharacter();
    Endpoint e;
    ASSERT_TRUE(
        e.open(std::make_unique<link::SerialLink>(settings), dev::LinkProtocol::Hart, {}, options));
    const auto id = e.identify(0);
    ASSERT_TRUE(id.ok) << id.message.toStdString();
    EXPECT_EQ(id.module.dictionary->family, "wandfluh-sd7");
    // A handful of rows (1200 baud): every answer arrives and decodes.
    std::vector<const dev::ParamMeta *> rows;
    for (const dev::ParamMeta &row : id.module.dictionary->params) {
        if (row.readable() && !row.isString() && rows.size() < 12)
            rows.push_back(&row);
    }
    std::optional<model::ReadResult> result;
    e.access->read(0, rows, model::Priority::User, [&](const model::ReadResult &r) { result = r; });
    ASSERT_TRUE(waitFor(result, 120'000));
    EXPECT_TRUE(result->complete())
        << (result->failures.empty() ? std::string()
                                     : result->failures.front().outcome.reason.toStdString());
}

} // namespace
} // namespace vt::test
