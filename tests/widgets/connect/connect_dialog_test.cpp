// ConnectDialog: every link kind's fields make the right ConnectionSpec,
// invalid input disables OK and says why, and the simulator choice connects for real.
#include "connect_test_support.h"
#include "model/session/connection.h"
#include "widgets/connect/connect_dialog.h"
#include "widgets/connect/sim_page.h"

#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabWidget>

namespace vt::test {
namespace {

using model::ConnectionKind;
using ui::ConnectDialog;

void setEditText(QComboBox *box, const QString &text)
{
    ASSERT_NE(box, nullptr);
    box->setEditText(text);
}

QString problemShown(const ConnectDialog &dialog)
{
    auto *label = dialog.findChild<QLabel *>(QStringLiteral("problem"));
    return label && !label->isHidden() ? label->text() : QString();
}

// OK is disabled and the reason shown, and they agree.
void expectRefused(const ConnectDialog &dialog, const char *what)
{
    EXPECT_FALSE(okEnabled(dialog)) << what;
    EXPECT_FALSE(problemShown(dialog).isEmpty()) << what;
    EXPECT_EQ(problemShown(dialog), dialog.problem()) << what;
}

void expectAccepted(const ConnectDialog &dialog, const char *what)
{
    EXPECT_TRUE(okEnabled(dialog)) << what << ": " << dialog.problem().toStdString();
    EXPECT_TRUE(problemShown(dialog).isEmpty()) << what;
}

TEST(ConnectDialog, SerialFieldsMakeAModbusRtuSpec)
{
    ConnectDialog dialog(dictionaries());
    dialog.setKind(ConnectionKind::Serial);
    setEditText(child<QComboBox>(dialog, "serialPort"), QStringLiteral("/dev/ttyUSB7"));
    setEditText(child<QComboBox>(dialog, "serialBaud"), QStringLiteral("9600"));
    selectData(child<QComboBox>(dialog, "serialDataBits"), 7);
    selectData(child<QComboBox>(dialog, "serialParity"), static_cast<int>(link::Parity::Odd));
    selectData(child<QComboBox>(dialog, "serialStopBits"), 2);
    child<QSpinBox>(dialog, "serialAddress")->setValue(5);
    selectData(child<QComboBox>(dialog, "serialProduct"),
               static_cast<int>(dev::HcsProduct::DmaProfibus));

    expectAccepted(dialog, "serial");
    const model::ConnectionSpec spec = dialog.spec();
    EXPECT_EQ(spec.kind, ConnectionKind::Serial);
    EXPECT_EQ(spec.serial.portName, QStringLiteral("/dev/ttyUSB7"));
    EXPECT_EQ(spec.serial.baudRate, 9600);
    EXPECT_EQ(spec.serial.formatText(), QStringLiteral("7O2"));
    EXPECT_EQ(spec.unit, 5);
    EXPECT_EQ(spec.product, dev::HcsProduct::DmaProfibus);
}

TEST(ConnectDialog, SerialDefaultsToTheHcsLine)
{
    ConnectDialog dialog(dictionaries());
    dialog.setKind(ConnectionKind::Serial);
    setEditText(child<QComboBox>(dialog, "serialPort"), QStringLiteral("/dev/ttyS9"));
    const model::ConnectionSpec spec = dialog.spec();
    EXPECT_EQ(spec.serial.baudRate, 19200);
    EXPECT_EQ(spec.serial.formatText(), QStringLiteral("8E1"));
    EXPECT_EQ(spec.unit, 1);
}

TEST(ConnectDialog, TcpFieldsMakeATcpSpec)
{
    ConnectDialog dialog(dictionaries());
    dialog.setKind(ConnectionKind::Tcp);
    child<QLineEdit>(dialog, "tcpHost")->setText(QStringLiteral(" 127.0.0.1 "));
    child<QSpinBox>(dialog, "tcpPort")->setValue(1502);
    selectData(child<QComboBox>(dialog, "tcpProtocol"),
               static_cast<int>(dev::LinkProtocol::NodeImage));
    child<QSpinBox>(dialog, "tcpAddress")->setValue(0);
    selectData(child<QComboBox>(dialog, "tcpProduct"), static_cast<int>(dev::HcsProduct::Opat));

    expectAccepted(dialog, "tcp");
    const model::ConnectionSpec spec = dialog.spec();
    EXPECT_EQ(spec.kind, ConnectionKind::Tcp);
    EXPECT_EQ(spec.host, QStringLiteral("127.0.0.1"));
    EXPECT_EQ(spec.port, 1502);
    EXPECT_EQ(spec.tcpProtocol, dev::LinkProtocol::NodeImage);
    EXPECT_EQ(spec.unit, 0); // the OPAT master
    EXPECT_EQ(spec.product, dev::HcsProduct::Opat);
}

TEST(ConnectDialog, CanFieldsMakeACanopenSpec)
{
    ConnectDialog dialog(dictionaries());
    dialog.setKind(ConnectionKind::Can);
    child<QLineEdit>(dialog, "canInterface")->setText(QStringLiteral("vcan0"));
    child<QSpinBox>(dialog, "canNode")->setValue(12);
    selectData(child<QComboBox>(dialog, "canDevice"), true); // Wandfluh ED1 (CiA 408)

    expectAccepted(dialog, "can");
    model::ConnectionSpec spec = dialog.spec();
    EXPECT_EQ(spec.kind, ConnectionKind::Can);
    EXPECT_EQ(spec.canInterface, QStringLiteral("vcan0"));
    EXPECT_EQ(spec.canNode, 12);
    EXPECT_TRUE(spec.canDsp408);
    EXPECT_FALSE(spec.unit); // the node id addresses the module
    EXPECT_FALSE(child<QComboBox>(dialog, "canProduct")->isEnabled());

    selectData(child<QComboBox>(dialog, "canDevice"), false);
    selectData(child<QComboBox>(dialog, "canProduct"),
               static_cast<int>(dev::HcsProduct::DmaProfinet));
    spec = dialog.spec();
    EXPECT_FALSE(spec.canDsp408);
    EXPECT_EQ(spec.product, dev::HcsProduct::DmaProfinet);
}

TEST(ConnectDialog, HartFieldsMakeAFixedLineSpec)
{
    ConnectDialog dialog(dictionaries());
    dialog.setKind(ConnectionKind::Hart);
    setEditText(child<QComboBox>(dialog, "hartPort"), QStringLiteral("/dev/ttyUSB3"));
    child<QSpinBox>(dialog, "hartPollAddress")->setValue(3);

    expectAccepted(dialog, "hart");
    const model::ConnectionSpec spec = dialog.spec();
    EXPECT_EQ(spec.kind, ConnectionKind::Hart);
    EXPECT_EQ(spec.serial, link::SerialSettings::hart(QStringLiteral("/dev/ttyUSB3"))); // 1200 8O1
    EXPECT_EQ(spec.unit, 3);
    EXPECT_EQ(child<QSpinBox>(dialog, "hartPollAddress")->maximum(), 15);
}

TEST(ConnectDialog, SimulatorFieldsMakeASimSpec)
{
    ConnectDialog dialog(dictionaries());
    dialog.setKind(ConnectionKind::Sim);
    selectData(child<QComboBox>(dialog, "simFamily"), QStringLiteral("opat"));
    child<QSpinBox>(dialog, "simModules")->setValue(3);
    selectData(child<QComboBox>(dialog, "simMode"), 4);
    selectData(child<QComboBox>(dialog, "simProtocol"), QStringLiteral("node-image"));

    expectAccepted(dialog, "sim");
    const model::ConnectionSpec spec = dialog.spec();
    EXPECT_EQ(spec.kind, ConnectionKind::Sim);
    EXPECT_EQ(spec.sim.family, "opat");
    EXPECT_EQ(spec.sim.modules, 3u);
    EXPECT_EQ(spec.sim.mode, 4);
    EXPECT_EQ(spec.sim.protocol, dev::LinkProtocol::NodeImage);

    // The SD7 has one module, no start-up mode and HART only.
    selectData(child<QComboBox>(dialog, "simFamily"), QStringLiteral("wandfluh-sd7"));
    EXPECT_FALSE(child<QSpinBox>(dialog, "simModules")->isEnabled());
    EXPECT_FALSE(child<QComboBox>(dialog, "simProtocol")->isEnabled());
    const model::ConnectionSpec sd7 = dialog.spec();
    EXPECT_EQ(sd7.sim.family, "wandfluh-sd7");
    EXPECT_EQ(sd7.sim.modules, 1u);
    EXPECT_EQ(sd7.sim.protocol, dev::LinkProtocol::Hart);
}

TEST(ConnectDialog, SimulatorOffersEveryFamilyItCanServe)
{
    ConnectDialog dialog(dictionaries());
    auto *page = child<ui::SimPage>(dialog, "simPage");
    // Every concrete family, the ED1 (its PROFIBUS image, raw or behind a gateway) included.
    std::vector<std::string> expected;
    for (const std::string &family : dictionaries().families())
        if (!dictionaries().find(family)->abstract)
            expected.push_back(family);
    EXPECT_EQ(page->families(), expected);
    EXPECT_GE(expected.size(), 8u); // 5 DMA-2, OPAT, ED1, SD7
    // Each one builds a simulator, over each protocol the page offers for it.
    auto *protocol = child<QComboBox>(dialog, "simProtocol");
    for (const std::string &family : expected) {
        selectData(child<QComboBox>(dialog, "simFamily"), QString::fromStdString(family));
        for (int i = 0; i < protocol->count(); ++i) {
            protocol->setCurrentIndex(i);
            auto made = model::Connection::create(page->spec(), dictionaries());
            EXPECT_TRUE(made.ok()) << family << " " << protocol->currentText().toStdString() << ": "
                                   << (made.ok() ? "" : made.error().toStdString());
        }
    }
    selectData(child<QComboBox>(dialog, "simFamily"), QStringLiteral("wandfluh-ed1"));
    EXPECT_EQ(protocol->count(), 2);
    EXPECT_EQ(page->spec().sim.protocol, dev::LinkProtocol::Dsp408Image);
}

TEST(ConnectDialog, InvalidInputDisablesOkWithTheReason)
{
    ConnectDialog dialog(dictionaries());

    dialog.setKind(ConnectionKind::Serial);
    auto *port = child<QComboBox>(dialog, "serialPort");
    setEditText(port, QString());
    expectRefused(dialog, "no serial port");
    setEditText(port, QStringLiteral("/dev/ttyUSB0"));
    expectAccepted(dialog, "serial port typed");
    setEditText(child<QComboBox>(dialog, "serialBaud"), QStringLiteral("fast"));
    expectRefused(dialog, "baud rate not a number");
    setEditText(child<QComboBox>(dialog, "serialBaud"), QStringLiteral("19200"));
    child<QSpinBox>(dialog, "serialAddress")->setValue(0);
    expectRefused(dialog, "Modbus broadcast address");
    child<QSpinBox>(dialog, "serialAddress")->setValue(1);
    expectAccepted(dialog, "serial fixed");

    dialog.setKind(ConnectionKind::Tcp);
    auto *host = child<QLineEdit>(dialog, "tcpHost");
    host->clear();
    expectRefused(dialog, "empty host");
    host->setText(QStringLiteral("plc one"));
    expectRefused(dialog, "host with a space");
    host->setText(QStringLiteral("127.0.0.1"));
    expectAccepted(dialog, "host typed");
    child<QSpinBox>(dialog, "tcpPort")->setValue(0);
    expectRefused(dialog, "port 0");
    child<QSpinBox>(dialog, "tcpPort")->setValue(502);
    expectAccepted(dialog, "tcp fixed");

    dialog.setKind(ConnectionKind::Can);
    auto *node = child<QSpinBox>(dialog, "canNode");
    node->setValue(0);
    expectRefused(dialog, "node 0");
    node->setValue(128);
    expectRefused(dialog, "node 128");
    node->setValue(127);
    expectAccepted(dialog, "node 127");
    child<QLineEdit>(dialog, "canInterface")->clear();
    expectRefused(dialog, "no CAN interface");
    child<QLineEdit>(dialog, "canInterface")->setText(QStringLiteral("can0"));
    expectAccepted(dialog, "can fixed");

    dialog.setKind(ConnectionKind::Hart);
    setEditText(child<QComboBox>(dialog, "hartPort"), QString());
    expectRefused(dialog, "no HART port");

    dialog.setKind(ConnectionKind::Sim);
    selectData(child<QComboBox>(dialog, "simFamily"), QStringLiteral("opat"));
    child<QSpinBox>(dialog, "simModules")->setValue(3);
    selectData(child<QComboBox>(dialog, "simProtocol"), QStringLiteral("modbus-rtu"));
    expectRefused(dialog, "OPAT master behind Modbus RTU");
    selectData(child<QComboBox>(dialog, "simProtocol"), QStringLiteral("modbus-tcp"));
    expectAccepted(dialog, "OPAT node behind Modbus TCP");

    // accept() refuses while there is a problem.
    dialog.setKind(ConnectionKind::Hart);
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Rejected);
}

TEST(ConnectDialog, SimulatorChoiceConnectsForReal)
{
    for (const auto &[family, modules] : std::vector<std::pair<QString, int>>{
             {QStringLiteral("dma-pn-v51"), 1}, {QStringLiteral("opat"), 3}}) {
        ConnectDialog dialog(dictionaries());
        dialog.setKind(ConnectionKind::Sim);
        selectData(child<QComboBox>(dialog, "simFamily"), family);
        child<QSpinBox>(dialog, "simModules")->setValue(modules);
        ASSERT_TRUE(okEnabled(dialog)) << dialog.problem().toStdString();

        auto made = model::Connection::create(dialog.spec(), dictionaries());
        ASSERT_TRUE(made.ok()) << made.error().toStdString();
        std::unique_ptr<model::Connection> connection = std::move(made).value();
        QSignalSpy opened(connection.get(), &model::Connection::opened);
        connection->open();
        ASSERT_TRUE(opened.count() > 0 || opened.wait(kWaitMs)) << family.toStdString();
        EXPECT_TRUE(connection->isOpen());
        EXPECT_EQ(connection->moduleAddresses().size(), static_cast<std::size_t>(modules));
        connection->close();
    }
}

TEST(ConnectDialog, SetSpecShowsItsKind)
{
    ConnectDialog dialog(dictionaries());
    model::ConnectionSpec spec;
    spec.kind = ConnectionKind::Tcp;
    spec.host = QStringLiteral("10.0.0.7");
    spec.port = 5020;
    dialog.setSpec(spec);
    EXPECT_EQ(dialog.kind(), ConnectionKind::Tcp);
    EXPECT_EQ(dialog.spec().host, spec.host);
    EXPECT_EQ(dialog.spec().port, spec.port);
}

TEST(ConnectDialog, GermanLocaleReadsTypedNumbers)
{
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    {
        ConnectDialog dialog(dictionaries());
        dialog.setKind(ConnectionKind::Serial);
        setEditText(child<QComboBox>(dialog, "serialPort"), QStringLiteral("/dev/ttyUSB0"));
        auto *baud = child<QComboBox>(dialog, "serialBaud");
        // Rates are listed without a group separator, and typed the same way: "115.200" is
        // refused (a thousands separator is no exact number here), "115200" is taken.
        EXPECT_EQ(baud->itemText(baud->findData(19200)), QStringLiteral("19200"));
        setEditText(baud, QStringLiteral("115.200"));
        EXPECT_FALSE(dialog.problem().isEmpty());
        setEditText(baud, QStringLiteral("115200"));
        EXPECT_EQ(dialog.spec().serial.baudRate, 115200);
        setEditText(baud, QStringLiteral("9600"));
        EXPECT_EQ(dialog.spec().serial.baudRate, 9600);
    }
    QLocale::setDefault(before);
}

TEST(ConnectDialog, RetranslatesOnLanguageChange)
{
    ConnectDialog dialog(dictionaries());
    auto *tabs = child<QTabWidget>(dialog, "kinds");
    for (int i = 0; i < tabs->count(); ++i)
        tabs->setTabText(i, QString());
    QEvent change(QEvent::LanguageChange);
    QCoreApplication::sendEvent(&dialog, &change);
    for (int i = 0; i < tabs->count(); ++i)
        EXPECT_FALSE(tabs->tabText(i).isEmpty()) << i;
}

} // namespace
} // namespace vt::test
