// valvetune-sim: a simulated HCS node or Wandfluh device on a pty, serial port, TCP port or CAN,
// for ValveTune, the CLI, mbpoll or a PLC test rig (README "Simulator"). Prints "listening on …"
// once ready, serves until SIGINT / SIGTERM (exit 0).
#include "app/cli/exit_codes.h"
#include "app/sim/sim_host.h"
#include "app/sim/sim_options.h"

#include <QCoreApplication>
#include <QSocketNotifier>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <unistd.h>

namespace {

int g_signalPipe[2] = {-1, -1};

// Async-signal-safe: one byte into the self-pipe; the event loop does the rest.
void onSignal(int)
{
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = ::write(g_signalPipe[1], &byte, 1);
}

bool installSignalHandlers()
{
    if (pipe2(g_signalPipe, O_CLOEXEC | O_NONBLOCK) != 0)
        return false;
    struct sigaction action
    {
    };
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    std::signal(SIGPIPE, SIG_IGN); // a client vanishing is handled where the write fails
    return sigaction(SIGINT, &action, nullptr) == 0 && sigaction(SIGTERM, &action, nullptr) == 0;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("valvetune-sim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(VT_VERSION));

    auto options = vt::simapp::parseSimOptions(QCoreApplication::arguments());
    if (!options.ok()) {
        const vt::simapp::OptionsExit &e = options.error();
        std::ostream &out = e.exitCode == vt::cli::kExitOk ? std::cout : std::cerr;
        out << e.text << (e.text.empty() || e.text.back() != '\n' ? "\n" : "");
        return e.exitCode;
    }
    if (!installSignalHandlers()) {
        std::cerr << "valvetune-sim: cannot install signal handlers: " << std::strerror(errno)
                  << '\n';
        return vt::cli::kExitDeviceError;
    }
    QSocketNotifier signalNotifier(g_signalPipe[0], QSocketNotifier::Read);
    QObject::connect(&signalNotifier, &QSocketNotifier::activated, &app, [] {
        char byte = 0;
        while (::read(g_signalPipe[0], &byte, 1) > 0) {
        }
        QCoreApplication::quit();
    });

    vt::simapp::SimHost host(std::move(options).value());
    auto where = host.start();
    if (!where.ok()) {
        std::cerr << "valvetune-sim: " << where.error().message << '\n';
        return where.error().exitCode;
    }
    QObject::connect(&host, &vt::simapp::SimHost::finished, &app,
                     [](int code) { QCoreApplication::exit(code); });
    std::cout << "listening on " << where->toStdString() << std::endl;
    return QCoreApplication::exec();
}
