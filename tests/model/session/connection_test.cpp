// Connection: one ConnectionSpec builds link, adapter, session options and
// the module addresses for the GUI and the CLI alike; opened / failed / lost arrive as signals.
#include "model/session/connection.h"
#include "sim_rig.h"

#include <QSignalSpy>

namespace vt::test {
namespace {

using model::Connection;
using model::ConnectionKind;
using model::ConnectionSpec;

std::unique_ptr<Connection> make(ConnectionSpec spec)
{
    auto made = Connection::create(std::move(spec), dictionaries());
    EXPECT_TRUE(made.ok()) << (made.ok() ? std::string() : made.error().toStdString());
    return made.ok() ? std::move(made).value() : nullptr;
}

ConnectionSpec simSpec(const std::string &family, std::size_t modules = 1)
{
    ConnectionSpec spec;
    spec.kind = ConnectionKind::Sim;
    spec.sim.family = family;
    spec.sim.modules = modules;
    return spec;
}

TEST(Connection, SimulatorModulesProtocolAndDescription)
{
    auto one = make(simSpec("dma-pn-v51"));
    ASSERT_TRUE(one);
    EXPECT_EQ(one->protocolKey(), "modbus-rtu");
    EXPECT_EQ(one->moduleAddresses(), std::vector<int>{1}); // point-to-point unit 1
    EXPECT_EQ(one->describe(), "sim dma-pn-v51 ×1, modbus-rtu, module 1");

    // A fold goes behind Modbus TCP, where unit 0 is the OPAT master and not a broadcast.
    auto fold = make(simSpec("opat", 3));
    ASSERT_TRUE(fold);
    EXPECT_EQ(fold->protocolKey(), "modbus-tcp");
    EXPECT_EQ(fold->moduleAddresses(), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(fold->scanAddresses(), (std::vector<int>{0, 1, 2}));

    ConnectionSpec hart = simSpec("wandfluh-sd7");
    auto sd7 = make(hart);
    ASSERT_TRUE(sd7);
    EXPECT_EQ(sd7->protocolKey(), "hart");
    EXPECT_EQ(sd7->moduleAddresses(), std::vector<int>{0}); // poll address 0
    EXPECT_EQ(sd7->session().options().turnaround, std::chrono::milliseconds(300));

    ConnectionSpec unknown = simSpec("no-such-family");
    EXPECT_FALSE(Connection::create(unknown, dictionaries()).ok());
}

TEST(Connection, SessionOptionsFollowTheWire)
{
    ConnectionSpec serial;
    serial.kind = ConnectionKind::Serial;
    serial.serial = link::SerialSettings::hcsDefault(QStringLiteral("/dev/ttyUSB0"));
    serial.serial.baudRate = 115200;
    serial.serial.parity = link::Parity::None;
    auto options = model::sessionOptionsFor(serial);
    EXPECT_EQ(options.baudRate, 115200);
    EXPECT_EQ(options.bitsPerCharacter, 10); // 8N1
    // Modbus over Serial Line §2.5.1.1: t3.5 is 1.75 ms above 19200 baud; the link may hold a
    // request for it and hands an answer on after it, so the timeout allows for it twice.
    EXPECT_EQ(options.lineSilence, std::chrono::microseconds(1750));
    EXPECT_EQ(options.timeout(8, 21), options.turnaround + std::chrono::milliseconds(7));
    serial.serial.silentInterval = serial.serial.frameEndBySilence = false;
    EXPECT_EQ(model::sessionOptionsFor(serial).lineSilence, std::chrono::microseconds(0));
    serial.turnaround = std::chrono::milliseconds(40);
    serial.retries = 0;
    options = model::sessionOptionsFor(serial);
    EXPECT_EQ(options.turnaround, std::chrono::milliseconds(40));
    EXPECT_EQ(options.retries, 0);

    ConnectionSpec hart;
    hart.kind = ConnectionKind::Hart;
    hart.serial = link::SerialSettings::hart(QStringLiteral("/dev/ttyUSB1"));
    EXPECT_EQ(model::sessionOptionsFor(hart).baudRate, 1200);
    EXPECT_EQ(model::sessionOptionsFor(hart).bitsPerCharacter, 11); // 8O1
    EXPECT_EQ(model::sessionOptionsFor(hart).lineSilence, std::chrono::microseconds(0));

    ConnectionSpec tcp;
    tcp.kind = ConnectionKind::Tcp;
    tcp.host = QStringLiteral("127.0.0.1");
    tcp.port = 1502;
    tcp.unit = 3;
    auto c = make(tcp);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->session().options().baudRate, 0);
    EXPECT_EQ(c->moduleAddresses(), std::vector<int>{3});
    EXPECT_EQ(c->scanAddresses().front(), 0); // Modbus TCP: no broadcast unit
    EXPECT_EQ(c->scanAddresses().back(), 32);
    EXPECT_EQ(c->describe(), "tcp 127.0.0.1:1502, modbus-tcp, module 3");
}

TEST(Connection, OpensIdentifiesAndReportsALostLink)
{
    ConnectionSpec spec = simSpec("dma-pn-v51");
    spec.fault = link::parseFaultSpec(u"cut=5").value();
    auto c = make(spec);
    ASSERT_TRUE(c);
    EXPECT_TRUE(c->faultLink());
    EXPECT_TRUE(c->describe().endsWith(" [fault cut=5,seed=1]")) << c->describe().toStdString();
    QSignalSpy opened(c.get(), &Connection::opened);
    QSignalSpy lost(c.get(), &Connection::lost);
    c->open();
    ASSERT_TRUE(opened.wait(kWaitMs));

    std::optional<model::IdentifyResult> identified;
    c->access().identify(1, [&](const model::IdentifyResult &r) { identified = r; });
    ASSERT_TRUE(waitFor(identified));
    EXPECT_TRUE(identified->ok);
    EXPECT_EQ(identified->module.identification.family, "dma-pn-v51");

    std::optional<model::ReadResult> read;
    c->access().read(1, {identified->module.dictionary->find("C1.07")}, model::Priority::User,
                     [&](const model::ReadResult &r) { read = r; });
    ASSERT_TRUE(waitFor(read));
    ASSERT_EQ(read->failures.size(), 1u); // identify took 4 frames; the cut came with the 5th
    EXPECT_EQ(read->failures.front().outcome.status, model::OutcomeStatus::LinkLost);
    ASSERT_TRUE(lost.count() > 0 || lost.wait(kWaitMs));
    EXPECT_FALSE(c->isOpen());
}

TEST(Connection, ARefusedTcpConnectionFails)
{
    ConnectionSpec spec;
    spec.kind = ConnectionKind::Tcp;
    spec.host = QStringLiteral("127.0.0.1");
    spec.port = 1; // nothing listens on loopback port 1
    auto c = make(spec);
    ASSERT_TRUE(c);
    QSignalSpy failed(c.get(), &Connection::failed);
    c->open();
    ASSERT_TRUE(failed.wait(kWaitMs));
    EXPECT_FALSE(failed.front().front().toString().isEmpty());
}

} // namespace
} // namespace vt::test
