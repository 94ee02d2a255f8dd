// What valvetune does once its window shows, as its command line asks: open the file it names
// (--open FILE, or FILE as the desktop entry and a file manager pass it) and connect (--simulate,
// --connect). main() calls it; the tests call it on a window of their own. GUI thread.
#pragma once

#include <QString>

class QMessageBox;

namespace vt::app {

class MainWindow;
struct GuiOptions;

void startFromOptions(MainWindow &window, const GuiOptions &options);

// Whether a window can be shown: a display to draw on, and a platform that is not headless
// (offscreen, minimal). Asked before a QGuiApplication exists, so that --help never needs one.
bool displayAvailable();

// The message box that tells a bad command line to someone who started ValveTune from a
// desktop shortcut and never sees stderr. The caller shows it (exec() in main, open() in tests).
QMessageBox *startupErrorBox(const QString &error);

} // namespace vt::app
