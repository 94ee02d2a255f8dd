// valvetune --connect on a real link: the GUI's connection to a valvetune-sim process over
// Modbus TCP, with valvetune-cli working on the same simulated node at the same time, and a
// refused connection or a serial port the user may not open said in a message.
#include "app/gui/app_settings.h"
#include "app/gui/device_controller.h"
#include "app/gui/gui_options.h"
#include "app/gui/language.h"
#include "app/gui/main_window.h"
#include "app/gui/workspace.h"
#include "sim_process.h"
#include "test_wait.h"

#include <QMessageBox>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <linux/capability.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace vt {
namespace {

using simtest::run;
using simtest::Sim;
using test::kWaitMs;

// Root opens any file whatever its mode (CAP_DAC_OVERRIDE). While this lives, the calling thread
// and the threads it starts (a serial link's worker) do without that, so an open meets the
// file's mode as a user's would; the thread gets its capabilities back at the end.
class WithoutDacOverride
{
public:
    WithoutDacOverride()
    {
        if (::geteuid() != 0 || ::syscall(SYS_capget, &m_header, m_saved) != 0)
            return;
        __user_cap_data_struct reduced[2] = {m_saved[0], m_saved[1]};
        constexpr unsigned kDac = (1u << CAP_DAC_OVERRIDE) | (1u << CAP_DAC_READ_SEARCH);
        reduced[0].effective &= ~kDac;
        m_dropped = ::syscall(SYS_capset, &m_header, reduced) == 0;
    }
    ~WithoutDacOverride()
    {
        if (m_dropped)
            ::syscall(SYS_capset, &m_header, m_saved);
    }
    WithoutDacOverride(const WithoutDacOverride &) = delete;
    WithoutDacOverride &operator=(const WithoutDacOverride &) = delete;
    // Whether an open() of this thread now meets the file's mode.
    bool bound() const { return m_dropped || ::geteuid() != 0; }

private:
    __user_cap_header_struct m_header{_LINUX_CAPABILITY_VERSION_3, 0};
    __user_cap_data_struct m_saved[2] = {};
    bool m_dropped = false;
};

struct GuiConnect : ::testing::Test
{
    QTemporaryDir dir;
    app::AppSettings settings{dir.filePath("settings.ini")};
    app::Language language;
    std::unique_ptr<app::MainWindow> window;

    void SetUp() override
    {
        ASSERT_TRUE(language.setLanguage("en"));
        window = std::make_unique<app::MainWindow>(settings, language);
        window->show();
    }

    // What main() does with the command line.
    void start(const QStringList &arguments)
    {
        const app::GuiOptions options = app::parseGuiOptions(arguments);
        ASSERT_FALSE(options.exitNow) << options.error.toStdString();
        ASSERT_TRUE(options.connection.has_value());
        window->device().connectTo(*options.connection);
    }

    simtest::ProcessRun cli(const QStringList &args) { return run(VT_CLI_PATH, args); }
};

// A 3-fold DMA-2 behind Modbus TCP: the GUI connects to module 2 and reads all; while it stays
// connected (its live poll running), valvetune-cli reads and writes the same module; the GUI
// reads the CLI's write back.
TEST_F(GuiConnect, ConnectsOverTcpWhileTheCliWorksOnTheSameNode)
{
    Sim sim({"--device", "dma-pn-v51", "--modules", "3", "--tcp", "127.0.0.1:0"});
    const QString where = sim.listening();
    ASSERT_TRUE(where.startsWith("127.0.0.1:")) << sim.stderrText().toStdString();

    QSignalSpy read(&window->device(), &app::DeviceController::readFinished);
    start({"valvetune", "--connect", "--tcp", where, "--unit", "2"});
    ASSERT_TRUE(read.wait(kWaitMs));
    ASSERT_TRUE(read.at(0).at(0).toBool());
    app::Workspace &workspace = window->workspace();
    ASSERT_TRUE(workspace.isConnected());
    ASSERT_EQ(workspace.modules().size(), 1u);
    EXPECT_EQ(workspace.modules().front().address, 2);
    EXPECT_EQ(workspace.connection()->spec().kind, model::ConnectionKind::Tcp);

    const auto get = cli({"get", "--tcp", where, "--unit", "2", "C1.07"});
    ASSERT_TRUE(get.finished);
    EXPECT_EQ(get.code, 0) << get.err.toStdString();
    EXPECT_EQ(get.out, "C1.07          0.000 V\n");
    const auto set = cli({"set", "--tcp", where, "--unit", "2", "C1.07=1.234"});
    ASSERT_TRUE(set.finished);
    ASSERT_EQ(set.code, 0) << set.out.toStdString() << set.err.toStdString();
    EXPECT_TRUE(workspace.isConnected()); // the GUI's connection stayed

    model::ParameterDocument &doc = workspace.document();
    const int module = doc.findModule(2);
    ASSERT_GE(module, 0);
    const dev::ParamMeta *row = doc.module(module).dictionary->find("C1.07");
    ASSERT_NE(row, nullptr);
    window->device().readAll();
    ASSERT_TRUE(read.wait(kWaitMs));
    ASSERT_TRUE(read.last().at(0).toBool());
    const auto value = doc.value(module, row);
    ASSERT_TRUE(value.has_value());
    EXPECT_EQ(*value, dev::RawValue(1234.0));
}

// Nobody listens: the reason is shown in a message, not only in the status bar.
TEST_F(GuiConnect, ARefusedConnectionIsShownInAMessage)
{
    QTcpServer closed; // a port known to be free: listen, note it, stop listening
    ASSERT_TRUE(closed.listen(QHostAddress::LocalHost));
    const QString where = QStringLiteral("127.0.0.1:%1").arg(closed.serverPort());
    closed.close();

    start({"valvetune", "--connect", "--tcp", where});
    ASSERT_TRUE(test::waitUntil([&] {
        return window->device().connectFailure() && window->device().connectFailure()->isVisible();
    }));
    const QString text = window->device().connectFailure()->text();
    EXPECT_TRUE(text.startsWith("ValveTune could not connect: ")) << text.toStdString();
    EXPECT_TRUE(text.contains("refused", Qt::CaseInsensitive)) << text.toStdString();
    EXPECT_FALSE(window->workspace().isConnected());
}

// A serial port the user may not open (here the simulator's pty with mode 000): the message says
// which group to join and how.
TEST_F(GuiConnect, APortTheUserMayNotOpenSaysHowToJoinDialout)
{
    Sim sim({"--device", "dma-pn-v51", "--pty"});
    const QString pty = sim.listening();
    ASSERT_TRUE(pty.startsWith("/dev/pts/")) << sim.stderrText().toStdString();
    ASSERT_EQ(::chmod(pty.toLocal8Bit().constData(), 0), 0);

    WithoutDacOverride user;
    ASSERT_TRUE(user.bound()) << "cannot give up CAP_DAC_OVERRIDE";
    start({"valvetune", "--connect", "--port", pty});
    ASSERT_TRUE(test::waitUntil([&] {
        return window->device().connectFailure() && window->device().connectFailure()->isVisible();
    }));
    const QString text = window->device().connectFailure()->text();
    EXPECT_TRUE(text.contains(pty + ": permission denied.")) << text.toStdString();
    EXPECT_TRUE(text.contains("the group dialout: add your user to it with \"sudo usermod -aG "
                              "dialout $USER\", then log out and log in again."))
        << text.toStdString();
    EXPECT_FALSE(window->workspace().isConnected());
}

} // namespace
} // namespace vt
