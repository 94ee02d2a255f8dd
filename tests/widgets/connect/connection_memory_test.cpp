// ConnectionMemory: the last spec of each kind survives a
// round trip through a QSettings file, and the dialog reopens on the last used kind.
#include "connect_test_support.h"
#include "widgets/connect/connect_dialog.h"
#include "widgets/connect/connection_memory.h"

#include <QLineEdit>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>

namespace vt::test {
namespace {

using model::ConnectionKind;
using model::ConnectionSpec;
using ui::ConnectionMemory;

struct TempSettings
{
    QTemporaryDir dir;
    QString path() const { return dir.filePath(QStringLiteral("valvetune.ini")); }
    std::unique_ptr<QSettings> open() const
    {
        return std::make_unique<QSettings>(path(), QSettings::IniFormat);
    }
};

TEST(ConnectionMemory, EveryKindRoundTripsThroughAFile)
{
    TempSettings temp;
    ASSERT_TRUE(temp.dir.isValid());

    ConnectionSpec serial;
    serial.kind = ConnectionKind::Serial;
    serial.serial = link::SerialSettings::hcsDefault(QStringLiteral("/dev/ttyUSB1"));
    serial.serial.baudRate = 57600;
    serial.serial.setFormatText(u"8N2");
    serial.unit = 7;
    serial.product = dev::HcsProduct::DmaProfinet;

    ConnectionSpec tcp;
    tcp.kind = ConnectionKind::Tcp;
    tcp.host = QStringLiteral("192.168.0.10");
    tcp.port = 1502;
    tcp.tcpProtocol = dev::LinkProtocol::NodeImage;
    tcp.unit = 0;
    tcp.product = dev::HcsProduct::Opat;

    ConnectionSpec can;
    can.kind = ConnectionKind::Can;
    can.canInterface = QStringLiteral("vcan0");
    can.canNode = 42;
    can.canDsp408 = true;

    ConnectionSpec hart;
    hart.kind = ConnectionKind::Hart;
    hart.serial = link::SerialSettings::hart(QStringLiteral("/dev/ttyACM0"));
    hart.unit = 2;

    ConnectionSpec sim;
    sim.kind = ConnectionKind::Sim;
    sim.sim.family = "opat";
    sim.sim.modules = 3;
    sim.sim.mode = 6;
    sim.sim.protocol = dev::LinkProtocol::NodeImage;

    {
        auto settings = temp.open();
        ConnectionMemory memory(*settings);
        for (const ConnectionSpec &spec : {serial, tcp, can, hart, sim})
            memory.save(spec);
        settings->sync();
        ASSERT_EQ(settings->status(), QSettings::NoError);
    }

    auto settings = temp.open();
    ConnectionMemory memory(*settings);
    EXPECT_EQ(memory.lastKind(), ConnectionKind::Sim);

    const auto s = memory.load(ConnectionKind::Serial);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->serial, serial.serial);
    EXPECT_EQ(s->unit, 7);
    EXPECT_EQ(s->product, dev::HcsProduct::DmaProfinet);

    const auto t = memory.load(ConnectionKind::Tcp);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->host, tcp.host);
    EXPECT_EQ(t->port, tcp.port);
    EXPECT_EQ(t->tcpProtocol, dev::LinkProtocol::NodeImage);
    EXPECT_EQ(t->unit, 0);
    EXPECT_EQ(t->product, dev::HcsProduct::Opat);

    const auto c = memory.load(ConnectionKind::Can);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->canInterface, can.canInterface);
    EXPECT_EQ(c->canNode, 42);
    EXPECT_TRUE(c->canDsp408);
    EXPECT_FALSE(c->unit);

    const auto h = memory.load(ConnectionKind::Hart);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->serial, hart.serial);
    EXPECT_EQ(h->unit, 2);

    const auto m = memory.load(ConnectionKind::Sim);
    ASSERT_TRUE(m);
    EXPECT_EQ(m->sim.family, "opat");
    EXPECT_EQ(m->sim.modules, 3u);
    EXPECT_EQ(m->sim.mode, 6);
    EXPECT_EQ(m->sim.protocol, dev::LinkProtocol::NodeImage);

    // Everything lives in the "connection" group.
    EXPECT_EQ(settings->childGroups(), QStringList{QStringLiteral("connection")});
}

TEST(ConnectionMemory, NothingSavedIsNothingLoaded)
{
    TempSettings temp;
    auto settings = temp.open();
    ConnectionMemory memory(*settings);
    EXPECT_FALSE(memory.lastKind());
    EXPECT_FALSE(memory.load(ConnectionKind::Tcp));
}

TEST(ConnectionMemory, DialogReopensOnTheLastKindWithItsFields)
{
    TempSettings temp;
    {
        auto settings = temp.open();
        ui::ConnectDialog dialog(dictionaries(), settings.get());
        dialog.setKind(ConnectionKind::Tcp);
        child<QLineEdit>(dialog, "tcpHost")->setText(QStringLiteral("127.0.0.1"));
        child<QSpinBox>(dialog, "tcpPort")->setValue(15020);
        dialog.accept();
        EXPECT_EQ(dialog.result(), QDialog::Accepted);
    }
    {
        // A later connection of another kind does not lose the TCP fields.
        auto settings = temp.open();
        ui::ConnectDialog dialog(dictionaries(), settings.get());
        EXPECT_EQ(dialog.kind(), ConnectionKind::Tcp);
        dialog.setKind(ConnectionKind::Sim);
        selectData(child<QComboBox>(dialog, "simFamily"), QStringLiteral("dma-pb-v32"));
        dialog.accept();
    }
    auto settings = temp.open();
    ui::ConnectDialog dialog(dictionaries(), settings.get());
    EXPECT_EQ(dialog.kind(), ConnectionKind::Sim);
    EXPECT_EQ(dialog.spec().sim.family, "dma-pb-v32");
    dialog.setKind(ConnectionKind::Tcp);
    EXPECT_EQ(dialog.spec().host, QStringLiteral("127.0.0.1"));
    EXPECT_EQ(dialog.spec().port, 15020);
}

TEST(ConnectionMemory, RejectedDialogRemembersNothing)
{
    TempSettings temp;
    auto settings = temp.open();
    {
        ui::ConnectDialog dialog(dictionaries(), settings.get());
        dialog.setKind(ConnectionKind::Can);
        dialog.reject();
    }
    EXPECT_FALSE(ConnectionMemory(*settings).lastKind());
}

} // namespace
} // namespace vt::test
