// valvetune-cli: ValveTune on the command line (see cli_app.h for the conventions).
#include "app/cli/cli_app.h"

#include <QCoreApplication>
#include <iostream>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("valvetune-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(VT_VERSION));
    return vt::cli::runCli(QCoreApplication::arguments(), std::cout, std::cerr);
}
