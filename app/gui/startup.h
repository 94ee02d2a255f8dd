// What valvetune does once its window shows, as its command line asks: open the file it names
// (--open FILE, or FILE as the desktop entry and a file manager pass it) and connect (--simulate,
// --connect). main() calls it; the tests call it on a window of their own. GUI thread.
#pragma once

namespace vt::app {

class MainWindow;
struct GuiOptions;

void startFromOptions(MainWindow &window, const GuiOptions &options);

} // namespace vt::app
