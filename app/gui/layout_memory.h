// LayoutMemory: the sizes the user gave the main window's splitters and view columns, kept
// between runs beside the window geometry and dock state (AppSettings). Every QSplitter and every
// item view with an object name takes part; a name is the key, so a renamed widget starts afresh.
// GUI thread only.
#pragma once

class QSettings;
class QWidget;

namespace vt::app {

void saveViewLayout(const QWidget &root, QSettings &store);
// Sizes missing from the store (first start, a new column) keep the widgets' defaults.
void restoreViewLayout(QWidget &root, QSettings &store);

} // namespace vt::app
