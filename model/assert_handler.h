// Routes failed VT_ASSERTs (core/vt_assert.h) into the Qt message log as critical messages with
// the assertion's file and line, so they land where every other message of the Qt layers goes
// (console, a message handler, a test's capture). Installed once by each main() at start-up.
#pragma once

#include "core/vt_assert.h"

#include <QMessageLogger>

namespace vt::model {

inline void qtAssertHandler(const char *condition, const char *file, int line)
{
    QMessageLogger(file, line, nullptr, "vt.assert")
        .critical("ASSERTION \"%s\" FAILED at %s:%d", condition, file, line);
}

inline void installQtAssertHandler()
{
    setAssertHandler(&qtAssertHandler);
}

} // namespace vt::model
