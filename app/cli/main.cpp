// valvetune-cli: ValveTune on the command line (see cli_app.h for the conventions).
#include "app/cli/cli_app.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <cstring>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace {

// The command: the first argument after the global options ("--json", "--help" …).
bool isReport(int argc, char *argv[])
{
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], "--", 2) != 0)
            return std::strcmp(argv[i], "report") == 0;
    return false;
}

} // namespace

int main(int argc, char *argv[])
{
    // The report draws its plots and lays out its pages with fonts, which need a QGuiApplication;
    // without a display it runs on the offscreen platform. Every other command stays headless.
    std::unique_ptr<QCoreApplication> app;
    if (isReport(argc, argv)) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
        app = std::make_unique<QGuiApplication>(argc, argv);
    } else {
        app = std::make_unique<QCoreApplication>(argc, argv);
    }
    QCoreApplication::setApplicationName(QStringLiteral("valvetune-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(VT_VERSION));
    // A valve-moving write asks only a person at a terminal (confirm_gate.h).
    const vt::cli::Console console{isatty(STDIN_FILENO) != 0, &std::cin};
    return vt::cli::runCli(QCoreApplication::arguments(), std::cout, std::cerr, console);
}
