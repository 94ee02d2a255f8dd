#include "app/gui/gui_options.h"
#include "app/gui/startup.h"

#include <QMessageBox>
#include <QProcess>
#include <gtest/gtest.h>
#include <tuple>

using vt::app::parseGuiOptions;

TEST(GuiOptions, LanguageIsValidated)
{
    auto ok = parseGuiOptions({"valvetune", "--lang", "de"});
    EXPECT_FALSE(ok.exitNow);
    EXPECT_EQ(ok.language, "de");

    auto bad = parseGuiOptions({"valvetune", "--lang", "fr"});
    EXPECT_TRUE(bad.exitNow);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_TRUE(bad.error.contains("en or de"));
}

TEST(GuiOptions, UnknownOptionsAndArgumentsAreUsageErrors)
{
    EXPECT_EQ(parseGuiOptions({"valvetune", "--frobnicate"}).exitCode, 2);
    EXPECT_EQ(parseGuiOptions({"valvetune", "a.vtpar", "b.vtpar"}).exitCode, 2);
    EXPECT_EQ(parseGuiOptions({"valvetune", "--lang"}).exitCode, 2); // missing value
}

TEST(GuiOptions, HelpAndVersionExitWithoutAWindow)
{
    EXPECT_TRUE(parseGuiOptions({"valvetune", "--help"}).exitNow);
    EXPECT_TRUE(parseGuiOptions({"valvetune", "--version"}).exitNow);
    EXPECT_FALSE(parseGuiOptions({"valvetune"}).exitNow);
}

TEST(GuiOptions, SimulateAndOpenAreTakenAndCheckedForNonsense)
{
    auto r = parseGuiOptions({"valvetune", "--simulate", "dma-pn-v51:3", "--open", "/tmp/x.vtpar"});
    EXPECT_FALSE(r.exitNow);
    EXPECT_EQ(r.simulate, "dma-pn-v51:3");
    EXPECT_EQ(r.openFile, "/tmp/x.vtpar");
    for (const char *bad : {"no-such-family", "dma-pn-v51:0", "dma-pn-v51:x"}) {
        auto e = parseGuiOptions({"valvetune", "--simulate", bad});
        EXPECT_EQ(e.exitCode, 2) << bad;
        EXPECT_TRUE(e.error.startsWith("--simulate: ")) << bad;
    }
}

// --audit-dir: where the session log goes (model/audit); empty means AuditLog's default.
TEST(GuiOptions, AuditDirIsTakenAndNamedInTheHelp)
{
    EXPECT_TRUE(parseGuiOptions({"valvetune"}).auditDir.isEmpty());
    auto r = parseGuiOptions({"valvetune", "--audit-dir", "/tmp/logs", "--simulate", "opat"});
    ASSERT_FALSE(r.exitNow) << r.error.toStdString();
    EXPECT_EQ(r.auditDir, "/tmp/logs");
    QString help;
    parseGuiOptions({"valvetune", "--help"}, &help);
    EXPECT_TRUE(help.contains("--audit-dir")) << help.toStdString();
}

// --factory: the built-in simulator from the dictionary defaults instead of the commissioned
// machine; it goes with --simulate (or with --connect --sim, the CLI's connection options).
TEST(GuiOptions, FactoryGoesWithTheSimulator)
{
    auto commissioned = parseGuiOptions({"valvetune", "--simulate", "dma-pn-v51:3"});
    EXPECT_FALSE(commissioned.factory);
    auto factory = parseGuiOptions({"valvetune", "--simulate", "dma-pn-v51:3", "--factory"});
    ASSERT_FALSE(factory.exitNow) << factory.error.toStdString();
    EXPECT_TRUE(factory.factory);
    auto alone = parseGuiOptions({"valvetune", "--factory"});
    EXPECT_EQ(alone.exitCode, 2);
    EXPECT_TRUE(alone.error.contains("--factory goes with --simulate"))
        << alone.error.toStdString();
    auto connect = parseGuiOptions({"valvetune", "--connect", "--sim", "opat", "--factory"});
    ASSERT_TRUE(connect.connection.has_value()) << connect.error.toStdString();
    EXPECT_TRUE(connect.connection->sim.factory);
    auto tcp = parseGuiOptions({"valvetune", "--connect", "--tcp", "h:1", "--factory"});
    EXPECT_EQ(tcp.exitCode, 2);
    EXPECT_TRUE(tcp.error.contains("--factory goes with --sim")) << tcp.error.toStdString();
}

// The desktop entry starts "valvetune %f": a file manager passes the file as the one argument.
TEST(GuiOptions, AFileArgumentIsOpenedAsOpenDoes)
{
    auto file = parseGuiOptions({"valvetune", "/home/me/press 1.vtpar"});
    EXPECT_FALSE(file.exitNow) << file.error.toStdString();
    EXPECT_EQ(file.openFile, "/home/me/press 1.vtpar");

    auto withLanguage = parseGuiOptions({"valvetune", "--lang", "de", "node.vtfold"});
    EXPECT_FALSE(withLanguage.exitNow) << withLanguage.error.toStdString();
    EXPECT_EQ(withLanguage.openFile, "node.vtfold");
    EXPECT_EQ(withLanguage.language, "de");

    auto both = parseGuiOptions({"valvetune", "--open", "a.vtpar", "b.vtpar"});
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_TRUE(both.error.contains("give one file")) << both.error.toStdString();
}

// --connect takes valvetune-cli's connection options, parsed by the same code (app/cmdline).
TEST(GuiOptions, ConnectTakesTheCliConnectionOptions)
{
    using vt::model::ConnectionKind;
    auto tcp = parseGuiOptions(
        {"valvetune", "--lang", "de", "--connect", "--tcp", "127.0.0.1:1502", "--unit", "2"});
    ASSERT_FALSE(tcp.exitNow) << tcp.error.toStdString();
    ASSERT_TRUE(tcp.connection.has_value());
    EXPECT_EQ(tcp.connection->kind, ConnectionKind::Tcp);
    EXPECT_EQ(tcp.connection->host, "127.0.0.1");
    EXPECT_EQ(tcp.connection->port, 1502);
    EXPECT_EQ(tcp.connection->unit, 2);
    EXPECT_EQ(tcp.language, "de"); // the GUI's own options still count

    auto gateway = parseGuiOptions({"valvetune", "--connect", "--tcp", "192.168.0.10"});
    ASSERT_TRUE(gateway.connection.has_value()) << gateway.error.toStdString();
    EXPECT_EQ(gateway.connection->port, 502); // Modbus TCP's port when none is given

    auto serial = parseGuiOptions({"valvetune", "--connect", "--port", "/dev/ttyUSB0", "--baud",
                                   "115200", "--parity", "none", "--stop", "2"});
    ASSERT_TRUE(serial.connection.has_value()) << serial.error.toStdString();
    EXPECT_EQ(serial.connection->kind, ConnectionKind::Serial);
    EXPECT_EQ(serial.connection->serial.portName, "/dev/ttyUSB0");
    EXPECT_EQ(serial.connection->serial.baudRate, 115200);
    EXPECT_EQ(serial.connection->serial.parity, vt::link::Parity::None);
    EXPECT_EQ(serial.connection->serial.stopBits, vt::link::StopBits::Two);
    // Modbus over Serial Line §2.5.1.1: the RTU line timing is on unless turned off.
    EXPECT_TRUE(serial.connection->serial.silentInterval);
    EXPECT_TRUE(serial.connection->serial.frameEndBySilence);
    auto lenient = parseGuiOptions({"valvetune", "--connect", "--port", "/dev/ttyUSB0",
                                    "--no-silent-interval", "--frame-end", "crc"});
    ASSERT_TRUE(lenient.connection.has_value()) << lenient.error.toStdString();
    EXPECT_FALSE(lenient.connection->serial.silentInterval);
    EXPECT_FALSE(lenient.connection->serial.frameEndBySilence);
    EXPECT_FALSE(
        parseGuiOptions({"valvetune", "--connect", "--port", "/dev/ttyUSB0", "--frame-end", "soon"})
            .connection.has_value());
    EXPECT_FALSE(
        parseGuiOptions({"valvetune", "--connect", "--sim", "opat", "--no-silent-interval"})
            .connection.has_value());

    auto can = parseGuiOptions({"valvetune", "--connect", "--can", "vcan0", "--node", "5"});
    ASSERT_TRUE(can.connection.has_value()) << can.error.toStdString();
    EXPECT_EQ(can.connection->kind, ConnectionKind::Can);
    EXPECT_EQ(can.connection->canInterface, "vcan0");
    EXPECT_EQ(can.connection->canNode, 5);

    auto hart = parseGuiOptions({"valvetune", "--connect", "--hart", "/dev/ttyUSB1"});
    ASSERT_TRUE(hart.connection.has_value()) << hart.error.toStdString();
    EXPECT_EQ(hart.connection->kind, ConnectionKind::Hart);
    EXPECT_EQ(hart.connection->serial.baudRate, 1200); // HART: 1200 8O1

    EXPECT_FALSE(parseGuiOptions({"valvetune"}).connection.has_value());
}

TEST(GuiOptions, ConnectMistakesAreUsageErrorsWithTheCliWording)
{
    const struct
    {
        QStringList args;
        const char *says;
    } cases[] = {
        {{"valvetune", "--connect"}, "--connect: no connection given"},
        {{"valvetune", "--connect", "--tcp", "host:99999"}, "--connect: --tcp takes HOST:PORT"},
        {{"valvetune", "--connect", "--port", "/dev/ttyS0", "--parity", "mark"},
         "--parity takes none, even or odd"},
        {{"valvetune", "--connect", "--can", "vcan0"}, "--can needs --node N"},
        {{"valvetune", "--connect", "--tcp", "h:1", "--hart", "/dev/x"}, "give one connection"},
        {{"valvetune", "--connect", "--tcp"}, "missing its value"},
        {{"valvetune", "--tcp", "127.0.0.1:502"}, "go with --connect"},
        {{"valvetune", "--simulate", "opat", "--connect", "--tcp", "h:1"},
         "give one connection: --simulate or --connect"},
    };
    for (const auto &c : cases) {
        const auto r = parseGuiOptions(c.args);
        EXPECT_TRUE(r.exitNow) << c.args.join(' ').toStdString();
        EXPECT_EQ(r.exitCode, 2) << c.args.join(' ').toStdString();
        EXPECT_TRUE(r.error.contains(c.says)) << r.error.toStdString();
        EXPECT_FALSE(r.connection.has_value());
    }
}

TEST(GuiOptions, HelpNamesConnectAndItsOptions)
{
    QString help;
    parseGuiOptions({"valvetune", "--help"}, &help);
    EXPECT_TRUE(help.contains("--connect")) << help.toStdString();
    EXPECT_TRUE(help.contains(
        "--tcp HOST:PORT [--protocol modbus-tcp|node-image|dsp408-image|dsp408-gateway]"))
        << help.toStdString();
    EXPECT_TRUE(help.contains("--port PATH [--baud B]")) << help.toStdString();
    EXPECT_TRUE(help.contains("[--out-register N] [--in-register N]")) << help.toStdString();
}

// A bad command line is said in a message box as well (a desktop shortcut has no terminal), and
// --help / a bad option answer without any display: no QGuiApplication is made for them.
TEST(GuiStartup, BadCommandLineIsShownInAMessageBox)
{
    const auto options = parseGuiOptions({"valvetune", "--simulate", "nonsense"});
    ASSERT_TRUE(options.exitNow);
    QMessageBox *box = vt::app::startupErrorBox(options.error);
    box->open();
    EXPECT_TRUE(box->isVisible());
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("--simulate")))
        << box->informativeText().toStdString();
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("nonsense")));
    box->close(); // deletes itself
}

TEST(GuiStartup, HelpAndBadOptionsNeedNoDisplay)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        env.remove(QString::fromLatin1(name));
    EXPECT_FALSE(qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")); // this test runs offscreen
    auto run = [&](const QStringList &args) {
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(VT_GUI_PATH), args);
        EXPECT_TRUE(p.waitForFinished(10000));
        return std::make_tuple(p.exitStatus(), p.exitCode(),
                               QString::fromUtf8(p.readAllStandardOutput()),
                               QString::fromUtf8(p.readAllStandardError()));
    };
    const auto [helpStatus, helpCode, helpOut, helpErr] = run({QStringLiteral("--help")});
    EXPECT_EQ(helpStatus, QProcess::NormalExit);
    EXPECT_EQ(helpCode, 0) << helpErr.toStdString();
    EXPECT_TRUE(helpOut.contains(QStringLiteral("--simulate"))) << helpOut.toStdString();
    const auto [badStatus, badCode, badOut, badErr] =
        run({QStringLiteral("--simulate"), QStringLiteral("nonsense")});
    EXPECT_EQ(badStatus, QProcess::NormalExit);
    EXPECT_EQ(badCode, 2);
    EXPECT_TRUE(badErr.contains(QStringLiteral("nonsense"))) << badErr.toStdString();
}
