// GuiOptions: the valvetune command line (--simulate FAMILY[:MODULES] [--factory], --connect with
// valvetune-cli's connection options, --lang en|de, --open FILE or just FILE), parsed into a
// plain struct that main() acts on (startup.h): QCommandLineParser for the GUI's own options,
// app/cmdline for the connection.
#pragma once

#include "model/session/connection.h"

#include <QString>
#include <QStringList>
#include <optional>

namespace vt::app {

struct GuiOptions
{
    QString language;     // "en", "de" or empty (settings / system locale decide)
    QString simulate;     // family id, optionally ":MODULES"
    bool factory = false; // --factory: the simulator starts from the dictionary defaults
    QString openFile;     // --open FILE or the positional FILE
    QString auditDir;     // --audit-dir DIR: where the session log goes (empty: the default)
    // --connect: the link to open at start-up (--tcp, --port, --can, --hart, --sim and their
    // settings, as valvetune-cli takes them).
    std::optional<model::ConnectionSpec> connection;
    bool exitNow = false; // --help / --version were answered
    int exitCode = 0;
    QString error; // one line for stderr when the command line is wrong
};

// arguments include the program name, as QCoreApplication::arguments() gives them.
GuiOptions parseGuiOptions(const QStringList &arguments, QString *helpText = nullptr);

} // namespace vt::app
