// valvetune-cli: ValveTune on the command line (see cli_app.h for the conventions).
#include "app/cli/cli_app.h"

#include <QCoreApplication>
#include <iostream>
#include <unistd.h>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("valvetune-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(VT_VERSION));
    // A valve-moving write asks only a person at a terminal (confirm_gate.h).
    const vt::cli::Console console{isatty(STDIN_FILENO) != 0, &std::cin};
    return vt::cli::runCli(QCoreApplication::arguments(), std::cout, std::cerr, console);
}
