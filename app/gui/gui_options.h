// GuiOptions: the valvetune command line (--simulate FAMILY[:MODULES], --lang en|de,
// --open FILE), parsed with QCommandLineParser into a plain struct that main() acts on.
#pragma once

#include <QString>
#include <QStringList>

namespace vt::app {

struct GuiOptions
{
    QString language; // "en", "de" or empty (settings / system locale decide)
    QString simulate; // family id, optionally ":MODULES"
    QString openFile;
    bool exitNow = false; // --help / --version were answered
    int exitCode = 0;
    QString error; // one line for stderr when the command line is wrong
};

// arguments include the program name, as QCoreApplication::arguments() gives them.
GuiOptions parseGuiOptions(const QStringList &arguments, QString *helpText = nullptr);

} // namespace vt::app
